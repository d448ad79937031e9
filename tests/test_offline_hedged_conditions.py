"""Conditions said without the benchmark's "If the X is Y, ...", from the seventh development set's
new tasks (`tests/data/reader_dev7/tasks_new/`): a check with its "that" left out, "make sure it's
off" after "but do", an obligation to a state, "if need be" after an instruction, a bare state
ending an instruction ("power off if still on"), "any on the floor" after a plural heading, "if
found there" and "if you find one there" after a habit. Each is tried on the development sentence
and on one written here in another room with other objects."""

from __future__ import annotations

import pytest
from reading import asks as _asks
from reading import factors as _factors
from reading import placed as _placed

from logicenveval.offline.analysis import _ensured
from logicenveval.offline.implied import any_at, implied
from logicenveval.offline.sentences import unquote


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 annex_host_review_reply (a host's reply to a review)
    ("On the checkout points you raised: please check the hair dryer is off before you go, it has been "
     "left running more than once.", ("annex",), "state(hair_dryer, toggled_on)"),
    # written here: a study, "double-check", a plural
    ("Before you lock up, double-check the desk lamp is switched off.", ("study",), "state(desk_lamp, toggled_on)"),
])
def test_a_check_with_its_that_left_out_asks_the_state(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"check the X is off" is "check that the X is off" (`analysis._ENSURE`): whether it is off is
    in doubt."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 caravan_visitors_book_letter (a caravan's visitors' book)
    ("The gas fireplace is lovely of an evening but do make sure it's turned off before you leave.",
     ("caravan",), "state(fireplace, toggled_on)"),
    # written here: "and", a door left open
    ("The fridge is new and please do make sure it's closed after use.", ("kitchen",), "state(fridge, open)"),
])
def test_make_sure_after_but_or_and_with_an_emphatic_do_asks_the_state(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"... but do make sure it's turned off": a clause about the thing, then "make sure" after a
    conjunction and an emphatic "do", speaking of it by a pronoun (`analysis._ENSURE`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize("text", [
    # built-in kitchen_breakfast_prep
    "in case a loaf of bread is on the counter, put it on the plate and make sure the toaster is switched on.",
    # written here
    "If the kids are home, feed the cat and make sure the fan is off.",
])
def test_make_sure_after_and_in_a_conditions_instruction_is_left_to_it(text: str) -> None:
    """After a condition earlier in its sentence, "and make sure ..." is part of that condition's
    instruction, not a condition of its own (`analysis._IN_CONDITION`)."""
    assert _ensured(text) == text


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 treehouse_secret_club_rules (a children's secret-club rules, spelling kept)
    ("3. The torch has to be turnd off when you go or the batterys run out (AGAIN).", ("treehouse",),
     "state(flashlight, toggled_on)"),
    # written here: "must", a bedroom lamp
    ("The lamp must be switched off when you leave.", ("bedroom",), "state(table_lamp, toggled_on)"),
    # written here: "need to", a state of opening
    ("The curtains need to be closed before dark.", ("bedroom",), "state(curtain, open)"),
])
def test_an_obligation_to_a_state_asks_it(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"The torch has to be turned off when you go": the state the thing must be in may not hold
    yet (`implied._OBLIGED`), as with "make sure"."""
    assert _asks(text, rooms, condition)


def test_an_obligation_the_text_answers_itself_is_left_to_its_condition() -> None:
    """With a condition of its own after it ("must be off - if it's on, switch it off"), the
    obligation is left as it is: the condition says it."""
    text = "The heater must be off when you go - if it's on, switch it off."
    assert implied(text) == text
    assert implied("The shelf must be on the wall.") == "The shelf must be on the wall."  # a place, no state


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 vestry_choir_secretary_email (a choir secretary's email)
    ("The kettle has been left on twice this month, so do check it and switch it off at the wall if need be.",
     ("vestry",), "state(kettle, toggled_on)"),
    # written here: "if necessary", a bare verb of closing
    ("The wardrobe sticks; close it if necessary.", ("bedroom",), "state(wardrobe, open)"),
    # written here: "if needed", the thing named in the instruction
    ("On your way out, turn the television off if needed.", ("living_room",), "state(television, toggled_on)"),
])
def test_if_need_be_after_an_instruction_asks_whether_its_result_holds(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"switch it off at the wall if need be": the instruction holds only when the state it sets
    does not yet (`implied._IF_NEED_BE`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 gallery_invigilator_checklist (a tick-box checklist)
    ("[ ] Tablet on the plinth by the entrance (interactive map): power off if still on. Do NOT unplug",
     ("gallery",), "state(tablet, toggled_on)"),
    # written here
    ("The tablet is on the desk: power off if still on.", ("office",), "state(tablet, toggled_on)"),
    ("Fan by the door: switch off if running.", ("office",), "state(ceiling_fan, toggled_on)"),
])
def test_a_bare_state_ending_an_instruction_is_said_of_the_thing_it_acts_on(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"power off if still on": the instruction's condition with its subject and copula elided
    (`sentences._ELIDED_END_STATE`), "if it is still on"."""
    assert "if it is still on" in unquote("Lamp: power off if still on.")
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 bunkhouse_counselor_duty_list (a camp counselor's list)
    ("* Ceiling fan - if it's running, turn it off.\n"
     "* Tennis rackets: any on the floor go in the gear bin (the blue storage box by the door).\n"
     "* Flashlights are fine.", ("bunkhouse",), "on(tennis_racket, floor)"),
    # written here: books, "back on"
    ("Books: any on the floor go back on the shelf.", ("living_room",), "on(book, floor)"),
    # written here: a dash, "left"
    ("Towels - any left on the floor go in the laundry basket.", ("bathroom",), "on(towel, floor)"),
])
def test_any_at_a_place_after_a_plural_heading_asks_where_the_things_are(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"Tennis rackets: any on the floor go in the box": "any" is any of the heading's things,
    and the place after it the condition (`implied._ANY_AT`)."""
    assert any_at("Books: any on the floor go back.") == "Books: any books on the floor go back."
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 darkroom_risk_assessment (a risk-assessment row)
    ("Scissors not to be left out on the counter. If found there, return them to the drawer under the sink.",
     ("darkroom",), "on(scissors, kitchen_counter)"),
    # written here
    ("The remote is not to be left on the sofa. If found there, put it back on the shelf.", ("living_room",),
     "on(remote_control, sofa)"),
])
def test_if_found_there_is_the_place_named_before(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"If found there": a participle of finding with its subject elided; "there" is the place the
    sentence before named (`analysis._there_named`, `_THERE_SUBJECTS`)."""
    assert _asks(text, rooms, condition)


def test_if_theyre_already_there_is_not_the_place_named_before() -> None:
    """"if they're already there" after two goals asks each thing about its own goal, not about
    the place named last (dev3 `sunroom_note_from_roommate`)."""
    text = ("my bat and my racket go in the storage bin and on the bench, respectively. if they're already "
            "there, don't sweat it")
    assert _asks(text, ("sunroom",), "inside(baseball_bat, storage_box)")


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 vestry_choir_secretary_email
    ("The black music folders do tend to end up on the floor under the chairs - if you find one there, "
     "would you put it back in the cardboard box?", ("vestry",), "on(black_folder, floor)"),
    # written here: "tend", cushions, a sofa
    ("The cushions tend to end up on the floor - if you find one there, put it on the sofa.", ("living_room",),
     "on(sofa_pillow, floor)"),
    # written here: an emphatic "do", a request after the condition's comma
    ("Mugs do tend to end up on the desk - if you find one there, could you take it to the sink?", ("office",),
     "on(mug, desk)"),
    ("The red dog toys tend to end up on the sofa - if you find one there, could you put it in the basket?",
     ("living_room",), "on(red_toy, sofa)"),
])
def test_finding_one_there_after_a_habit_asks_the_habits_place(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"if you find one there" points back to the things the habit before says may be there
    (`analysis.FOUND_ONE`), not to whether one exists; an emphatic "do" before "tend" keeps the
    habit (`sentences._EMPHATIC_DO`); a request after the condition's comma is its instruction."""
    found = _factors(text, rooms)
    assert _asks(text, rooms, condition)
    assert not any(v.startswith("exists(") for values in found.values() for v in values)


# ----- from dev 7's rewordings -------------------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 study_desk_cleanup_d7 (a Scottish note)
    ("Ma mug might be on the desk an aw. Take it through tae the kitchen: a dirty mug in the kitchen sink, "
     "a clean yin on the kitchen counter.", ("study", "kitchen"), "state(mug, dirty)"),
    # written here: "bring", a towel's wetness
    ("Bring the towel down to the laundry room: a wet towel on the drying rack, a dry one in the hamper.",
     ("laundry_room",), "state(towel, wet)"),
])
def test_a_verbless_list_after_taking_a_thing_asks_which_case_it_is(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"Take it to the kitchen: a dirty mug in the sink, a clean one on the counter": after a verb
    of carrying (`analysis._TAKING`) the list says where each case goes (`_elaborates`), so its
    places are goals, and the state that tells the cases apart is asked (`_moved`), not stated."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 hallway_coat_and_bag_d7 (an Irish granny's note)
    ("A clean lunch box goes in the kitchen cabinet, a dirty one in the dishwasher - but if the dishwasher's "
     "going already, just leave it on the kitchen counter, sure.", ("hallway", "kitchen"),
     "state(dishwasher, toggled_on)"),
    # written here
    ("If the washing machine's going still, put the shirt in the basket.", ("laundry_room",),
     "state(washing_machine, toggled_on)"),
])
def test_going_before_already_or_still_is_running(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"the dishwasher's going already": "going" as a predicate (`sentences.PREDICATE_STATES`)
    with "already" / "still" after it, as before it."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "conditions"), [
    # dev7 living_room_toy_boxes_d7 (a babysitting job sheet)
    ("Notes: the floor has a stain on it. A sofa pillow and/or a toy may be on the floor.", ("living_room",),
     ("on(sofa_pillow, floor)", "on(toy, floor)")),
    # written here
    ("A book and/or a mug may have been left on the desk.", ("study",), ("on(book, desk)", "on(mug, desk)")),
])
def test_and_or_between_things_in_doubt_asks_each(text: str, rooms: tuple[str, ...],
                                                 conditions: tuple[str, ...]) -> None:
    """"A sofa pillow and/or a toy may be on the floor" is read as "a sofa pillow or a toy"
    (`sentences._AND_OR`): each may be there."""
    for condition in conditions:
        assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 living_room_toy_boxes_d7 (a babysitting job sheet)
    ("Tasks:\n1. Pillow on the floor -> back on the sofa.\n2. Toy on the floor -> into the right toy box.",
     ("living_room",), "on(pillow, floor)"),
    # written here
    ("Mug on the desk -> back in the cupboard.", ("office",), "on(mug, desk)"),
])
def test_a_heading_answered_after_an_arrow_is_a_condition_not_a_placement(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"Pillow on the floor -> back on the sofa": the arrow cuts as a colon does
    (`placement._THEN_ARROW`), so the heading is the instruction's condition: asked, not placed."""
    assert _asks(text, rooms, condition)
    assert condition not in _placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev7 study_desk_cleanup_d7 (a Scottish note)
    ("If there's a document on the desk an it's a bill, file it in the filing cabinet - the drawer might be "
     "pulled oot already, if no open it - an shut the drawer efter.", ("study",), "state(filing_cabinet, open)"),
    # written here: a bedroom
    ("The nightstand drawer might be pulled oot; if it is, push it in efter.", ("bedroom",),
     "state(nightstand, open)"),
])
def test_scots_spellings_read_as_their_english_words(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"pulled oot" is "pulled out" (open) in a text with two Scots spellings or more
    (`sentences.SCOTS`); one such word alone is left as written."""
    assert _asks(text, rooms, condition)
    assert unquote("Balance, yin and yang.") == "Balance, yin and yang."


@pytest.mark.parametrize(("text", "rooms", "table"), [
    # dev7 cabin_yacht_logbook (a yacht's logbook)
    ("- Desk lamp over chart table left on last night - batteries low. Check, OFF if on.\n"
     "- Torch found on the port bunk again. Belongs in the chart table drawer; if on bunk, stow it there.",
     ("cabin",), "coffee_table"),
    # written here: a television over a dresser
    ("Television over the dresser left on last night - check it, off if on.", ("bedroom",), "dresser"),
])
def test_a_state_said_next_to_a_thing_that_cannot_take_it_is_not_asked_of_it(
        text: str, rooms: tuple[str, ...], table: str) -> None:
    """"Desk lamp over chart table left on": the piece of furniture beside the lamp, which the
    catalog says cannot be switched on, is asked nothing when the clause says the state of a thing
    that can take it (`FITTED`, `_capabilities`); the lamp still is."""
    found = _factors(text, rooms)
    assert not any(f"state({table}, toggled_on)" in v for values in found.values() for v in values)
    lamp = "desk_lamp" if "lamp" in text else "television"
    assert _asks(text, rooms, f"state({lamp}, toggled_on)")


@pytest.mark.parametrize(("text", "rooms", "thing"), [
    # dev7 vestry_choir_secretary_email
    ("If you find one there, would you put it back in the cardboard box that lives on top of the piano?",
     ("vestry",), "cardboard_box"),
    # written here
    ("If you find one there, could you put it back in the basket that sits on top of the wardrobe?", ("bedroom",),
     "basket"),
])
def test_on_top_of_is_a_place_not_the_state_on(text: str, rooms: tuple[str, ...], thing: str) -> None:
    """"on top of" is read as "on" (`sentences._ON_TOP`): its "on" is no switched-on state of the
    thing it is said with."""
    found = _factors(text, rooms)
    assert not any(f"state({thing}, toggled_on)" in v for values in found.values() for v in values)
