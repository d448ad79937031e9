"""Structures behind dev 35's losses (issue 47, docs/reader.md "Numbered headings, observed
places, verbs of state, afterthoughts and colour classes (nineteenth session)"), each written
here as composed sentences in several registers, rooms, things and states (none from the task
sets), with near misses that must stay apart:

- (a) a numbered heading: "Finding 2 - Filing cabinet (risk rating: high)", the numbering of
  reports, tickets, checklists and minutes; a numeral followed by a dash or a colon labels the
  entry, it counts nothing, so the bracket after the name is no list of several things
  (`naming._Reader.numbered_heading`);
- (b) a place reported as observed: "a cup was noted on the desk", the past or perfect passive of
  a verb of observing or recording in inspections, audits and logs, states where the thing was
  (`placement.OBSERVED`); a present one after "where"/"if" stays a condition;
- (c) a device's activity said as the finite verb of a condition ("if it still burns", "if the
  fan no longer runs", a learner's "if it already not burns"), the eighteenth session's sounding
  devices widened to burning, running, glowing, spinning and playing, with an adverb of time or a
  negation before the verb (`sentences.SOUNDS`, `_SOUNDING`);
- (d) an afterthought after a dash renaming the thing the sentence opens with ("The table lamp
  stands on the desk - my reading lamp"): the writer's own name for the thing just placed, of the
  same head noun, no second lamp (`naming._Reader.subject_renamed`);
- (e) a colour sorted against its complement ("a white shirt goes in the washing machine, a
  coloured shirt in the hamper", "a towel of any other colour"): an indefinite thing's colour is
  then a condition on any one thing of the kind, no particular white shirt
  (`naming._Reader.color_class`).

Measured on the tables below on the tree before the rules: (a) 8 of 10 named once, (b) 0 of 8
read as stated, (c) 1 of 8 asked, (d) 1 of 4 named once, (e) 0 of 6 asked; after: all of
them, and every near miss as before."""

from __future__ import annotations

import pytest
from reading import asks, factors, named, placed

from logicenveval.offline.sentences import _SOUNDING, _sounding

# -- (a) a numbered heading names one thing ---------------------------------------------------

NUMBERED_HEADINGS = [
    # (register, room, text, the kind named once)
    ("audit", "office", "Finding 4 - Fridge (risk rating: high). Close it before you leave.", "fridge"),
    ("ticket", "office", "Ticket 14 – Desk lamp (reported by: Ann). If it is on, switch it off.", "desk_lamp"),
    ("recipe", "kitchen", "Step 4 - Kettle (allow: five minutes). If it is on, switch it off.", "kettle"),
    ("minutes", "office", "Action 7: Laptop (owner: Sam). Please shut it.", "laptop"),
    ("chore list", "bedroom", "Task 2 — Wardrobe (deadline: tonight). If the wardrobe is open, close it.", "wardrobe"),
    ("inspection", "bathroom", "Defect 3 - Towel (category: hygiene). Hang it up if it is wet.", "towel"),
    ("puzzle", "living room", "Clue 6 - Television (answer: switch off). If it is on, switch it off.", "television"),
    ("incident log", "kitchen", "Issue 9: Dishwasher (impact: medium). If the dishwasher is open, shut it.",
     "dishwasher"),
    ("handover", "studio", "Note 2 - Laptop (battery: low). If the laptop is open, close it.", "laptop"),
    ("lesson plan", "classroom", "Section 5 - Desk lamp (teacher: Mr Brown). If the lamp is on, turn it off.",
     "desk_lamp"),
]


@pytest.mark.parametrize(("register", "room", "text", "kind"), NUMBERED_HEADINGS)
def test_a_numbered_heading_names_one_thing(register: str, room: str, text: str, kind: str) -> None:
    names = [name for name, (category, _) in named(text, (room,)).items() if category == kind]
    assert names == [kind], register


@pytest.mark.parametrize(("room", "text", "names"), [
    # a count runs into its noun, or stands alone after the plural it counts: still a count
    ("kitchen", "2 mugs: a red one and a blue one. Put them in the sink.", {"red_mug", "blue_mug"}),
    ("kitchen", "Mugs - 2 - a red one and a blue one. Put them in the sink.", {"red_mug", "blue_mug"}),
    ("kitchen", "Bowls: 2 - a food bowl and a water bowl.", {"food_bowl", "water_bowl"}),
    ("kitchen", "2 bowls - a food bowl and a water bowl.", {"food_bowl", "water_bowl"}),
    ("bathroom", "Towels: 2 (a green one and a white one).", {"green_towel", "white_towel"}),
])
def test_a_count_still_counts(room: str, text: str, names: set[str]) -> None:
    assert names <= set(named(text, (room,)))


# -- (b) a place reported as observed ---------------------------------------------------------

OBSERVED = [
    # (register, room, text, the placement stated)
    ("audit", "office", "Observation: a cup was noted on the desk during the walk-round. Should the cup be "
     "dirty, place it on the cart.", "on(cup, desk)"),
    ("memo", "office", "A cup was noted on the desk. If it is dirty, put it in the sink.", "on(cup, desk)"),
    ("lab report", "office", "A cup was observed on the desk. If it is dirty, put it in the sink.", "on(cup, desk)"),
    ("house-sitter", "kitchen", "A mug was spotted on the counter this morning. If it is dirty, wash it.",
     "on(mug, kitchen_counter)"),
    ("hotel inspection", "bedroom", "A towel was recorded on the bed during the inspection. If it is wet, hang "
     "it on the towel rail.", "on(towel, bed)"),
    ("logbook", "living room", "Inspector's note: a book has been logged on the sofa since 9am. Put it on "
     "the bookshelf.", "on(book, sofa)"),
    ("police", "office", "A cup was reported on the desk by the cleaner. If it is dirty, put it in the sink.",
     "on(cup, desk)"),
    ("survey", "bedroom", "A towel was photographed on the bed. If it is wet, hang it on the towel rail.",
     "on(towel, bed)"),
]


@pytest.mark.parametrize(("register", "room", "text", "fact"), OBSERVED)
def test_a_place_reported_as_observed_is_stated(register: str, room: str, text: str, fact: str) -> None:
    assert fact in placed(text, (room,)), register


@pytest.mark.parametrize("text", [
    "If a cup is spotted on the desk, put it in the sink.",
    "Any cup noted on the desk must be washed.",
    "Should a cup be observed on the desk, wash it.",
    "Where a cup is recorded on the desk, wash it.",   # a present passive: the condition's
    "Where a cup is noted on the desk, wash it.",
    "Nothing was noted on the desk. If a cup is there, wash it.",
    "A cup was not observed on the desk, so check the shelf too.",
])
def test_an_observation_asked_or_denied_states_nothing(text: str) -> None:
    assert "on(cup, desk)" not in placed(text, ("office",))


# -- (c) a device's activity said as a condition's finite verb ---------------------------------

ACTIVITY_VERBS = [
    # (register, room, text, condition asked)
    ("note", "living room", "The candle on the coffee table: if it still burns, blow it out.",
     "state(candle, toggled_on)"),
    ("house rules", "bedroom", "If the ceiling fan still runs, switch it off.", "state(ceiling_fan, toggled_on)"),
    ("laundry card", "laundry room", "Dryer: if it no longer runs, take the towels out; if it runs, leave it alone.",
     "state(dryer, toggled_on)"),
    ("parent's text", "living room", "If the television still plays, turn it off please.",
     "state(television, toggled_on)"),
    ("learner (Slavic)", "living room", "Fireplace. If it already not burns, it is OK; if it burns, put it out.",
     "state(fireplace, toggled_on)"),
    ("cabin rules", "bedroom", "Candle by the bed - if it doesn't burn any more, leave it; if it still burns, "
     "blow it out.", "state(candle, toggled_on)"),
    ("caretaker", "living room", "If the floor lamp still glows, switch it off.", "state(floor_lamp, toggled_on)"),
    ("study rules", "bedroom", "When the ceiling fan spins, the papers fly; if it spins, turn it off.",
     "state(ceiling_fan, toggled_on)"),
]


@pytest.mark.parametrize(("register", "room", "text", "condition"), ACTIVITY_VERBS)
def test_an_activity_as_a_finite_verb_asks_the_state(register: str, room: str, text: str, condition: str) -> None:
    assert asks(text, (room,), condition), register


@pytest.mark.parametrize(("clause", "read"), [
    ("if it no longer runs, take", "if it is no longer running, take"),
    ("If it already not burns, it is OK", "If it is already not burning, it is OK"),
    ("if it doesn't burn any more, leave it", "if it is not burning any more, leave it"),
    ("if they still run", "if they are still running"),
])
def test_the_activity_is_read_as_its_state_word(clause: str, read: str) -> None:
    assert _SOUNDING.sub(_sounding, clause) == read


@pytest.mark.parametrize(("room", "text"), [
    ("office", "If the printer runs out of paper, put more paper in the tray."),  # a particle: another verb
    ("living room", "If the candle burns down, throw it away."),
    ("living room", "If the television plays up again, unplug it."),
    ("kitchen", "If the tap runs over, call me."),
    ("bedroom", "Let the candle burn for an hour."),                               # no condition
    ("kitchen", "If you run the dishwasher, add a tablet."),                       # a person's act
])
def test_another_verb_asks_no_state(room: str, text: str) -> None:
    assert not any("toggled_on" in c for values in factors(text, (room,)).values() for c in values)


# -- (d) an afterthought renaming the sentence's subject ---------------------------------------

RENAMED_SUBJECTS = [
    # (register, room, text, the one kind named, the kind not named)
    ("diary", "study", "The table lamp stands on the desk - my reading lamp. If it is on, switch it off.",
     "table_lamp", "desk_lamp"),
    ("carer's note", "bedroom", "The floor lamp is beside the bed – her reading lamp. If it is on, turn it off.",
     "floor_lamp", "desk_lamp"),
    ("tidy list", "bedroom", "The laundry basket sits on the floor – the wicker basket. If it is full, empty it.",
     "laundry_basket", "basket"),
    ("lodger's rules", "office", "The desk lamp is next to the printer — our study lamp. Switch it off at night.",
     "desk_lamp", "floor_lamp"),
]


@pytest.mark.parametrize(("register", "room", "text", "kind", "other"), RENAMED_SUBJECTS)
def test_an_afterthought_renames_the_subject(register: str, room: str, text: str, kind: str, other: str) -> None:
    kinds = {category for category, _ in named(text, (room,)).values()}
    assert kind in kinds and other not in kinds, register


def test_the_renamed_subject_is_the_one_asked() -> None:
    text = "The table lamp stands on the desk - my reading lamp. If it is on, switch it off."
    assert asks(text, ("study",), "state(table_lamp, toggled_on)")


@pytest.mark.parametrize(("room", "text", "names"), [
    ("study", "The table lamp is on the desk - my floor lamp is by the sofa.", {"table_lamp", "floor_lamp"}),
    ("study", "The table lamp is on the desk - the floor lamp too.", {"table_lamp", "floor_lamp"}),
    ("study", "Put the table lamp on the desk - the floor lamp.", {"table_lamp", "floor_lamp"}),
    ("study", "The table lamp is on the desk – and my floor lamp.", {"table_lamp", "floor_lamp"}),
    ("kitchen", "The mug is on the counter - my cup. Wash both.", {"mug", "cup"}),  # another head noun
])
def test_another_thing_after_a_dash_is_still_named(room: str, text: str, names: set[str]) -> None:
    assert names <= set(named(text, (room,)))


# -- (e) a colour sorted against its complement -------------------------------------------------

COLOR_CLASSES = [
    # (register, room, text, the one kind named, the colour asked)
    ("laundry card", "laundry room", "A white shirt goes in the washing machine. A coloured shirt goes in the hamper.",
     "shirt", "attr(shirt, color, white)"),
    ("kitchen rota", "kitchen", "Dishes: a white plate goes in the dishwasher; a coloured plate is washed by hand "
     "in the sink.", "plate", "attr(plate, color, white)"),
    ("hotel rules", "bathroom", "Bathroom rules: a white towel goes in the laundry basket, a towel of any other "
     "colour goes on the towel rail.", "towel", "attr(towel, color, white)"),
    ("text message", "bedroom", "Sock on the floor? A white sock goes in the hamper, a colored sock in the "
     "laundry basket.", "sock", "attr(sock, color, white)"),
    ("office kitchen sign", "kitchen", "If you find a dirty white mug, put it in the dishwasher; a dirty coloured "
     "mug goes in the sink.", "mug", "attr(mug, color, white)"),
    ("cleaner's brief", "living room", "Cushion on the floor: a white cushion must be put on the sofa, a coloured "
     "cushion is to be placed on the armchair.", "sofa_pillow", "attr(sofa_pillow, color, white)"),
]


@pytest.mark.parametrize(("register", "room", "text", "kind", "condition"), COLOR_CLASSES)
def test_a_colour_sorted_against_its_complement_is_asked(register: str, room: str, text: str, kind: str,
                                                          condition: str) -> None:
    names = [name for name, (category, _) in named(text, (room,)).items() if category == kind]
    assert names == [kind], register
    assert asks(text, (room,), condition), register


@pytest.mark.parametrize(("room", "text", "names"), [
    # colours that tell particular things apart: still two things, or the one coloured thing
    ("kitchen", "The white mug is on the shelf and the blue mug is in the sink. Wash the blue mug.",
     {"white_mug", "blue_mug"}),
    ("kitchen", "A white mug and a blue mug are on the table. Put both in the sink.", {"white_mug", "blue_mug"}),
    ("bedroom", "My white shirt is on the bed. Put it in the wardrobe; the coloured cushions stay on the sofa.",
     {"white_shirt"}),
    ("kitchen", "A white plate is on the counter. Put it in the sink.", {"white_plate"}),
])
def test_colours_of_particular_things_still_name_them(room: str, text: str, names: set[str]) -> None:
    assert names <= set(named(text, (room,)))
