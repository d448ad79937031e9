"""Condition forms people use widely that the offline reader did not read, found while composing
test sentences (docs/reader.md "What it still misreads"), from the seventeenth session. Each
structure is a table of sentences written here, in several registers, rooms, kinds and states,
with near misses that must stay as they are; each table was measured before its rule (the counts
in each test's docstring).

- a modal doubt said with its own negation ("A tape roll may or may not be on the cart. If
  present, ...", "may or may not lie on the floor. If it does, ..."): read as the modal alone;
- a bracketed appositive of "one" between a thing and its place ("left a mug (the blue one) on
  the desk. If so, ..."): read as between commas;
- a condition typed without its comma before an instruction to report to the speaker ("If the
  mug is missing let me know", "if the heater's on tell us"): the speaker ("me", "us") is the
  instruction's object, so the condition ends before the verb;
- a plural pronoun in a time clause after a thing named in the singular in the same clause ("If
  the lamp is still on when they've gone"): the people the time is told by, not the thing."""

from __future__ import annotations

import pytest
from reading import asks, factors, instruction_under

from logicenveval.offline.sentences import unquote

#: a thing, a modal doubt with its negation, then an elliptical condition taking the clause up:
#: (text, rooms, the condition asked). Before the rule 1 of 10 was asked
MODAL_DOUBT = [
    # a warehouse pick note: "If present" after a place on a cart
    ("Shift brief. A roll of tape may or may not be on the trolley. If present, put it in the cardboard box.",
     ("garage",), "on(tape, cart)"),
    # a house-sitter's note: a lexical verb taken up by "If it does"
    ("The cat's bowl might or might not sit on the floor by now. If it does, pop it in the sink.",
     ("kitchen",), "on(pet_bowl, floor)"),
    # a formal checklist: the doubt between commas, a device's state, "If so"
    ("The desk lamp may, or may not, have been left on. If so, switch it off.",
     ("office",), "state(desk_lamp, toggled_on)"),
    # a chat message: mixed modals, an opening state, "if it is"
    ("the fridge may or might not be open again lol. if it is, shut it pls", ("kitchen",),
     "state(fridge, open)"),
    # a caretaker's log: inside a container, "If so"
    ("Note: a mug may or may not be in the sink this morning. If so, wash it and put it on the shelf.",
     ("kitchen",), "inside(mug, sink)"),
    # a parent's note: a pronoun's thing named the sentence before
    ("Check on the teddy bear. It might or might not be lying on the floor. If it is, put it on the bed.",
     ("bedroom",), "on(teddy_bear, floor)"),
    # a manual's register: "could or could not", an elided "If so"
    ("The towel could or could not be hanging on the rail. If so, leave it; otherwise fetch it.",
     ("bathroom",), "on(towel, towel_rack)"),
    # a housemate's text: dirty, "if it is"
    ("ur plate may or may not be dirty still. if it is, rinse it", ("kitchen",), "state(plate, dirty)"),
    # a lab bench rule: switched on, "If so"
    ("The kettle may or may not still be switched on. If so, turn it off before you leave.",
     ("kitchen",), "state(kettle, toggled_on)"),
    # a cleaner's note: a covering's opening, plural, with "If they are"
    ("The curtains might or might not be open. If they are, close them.", ("bedroom",), "state(curtain, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), MODAL_DOUBT)
def test_modal_doubt_with_its_negation_is_asked(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"A tape roll may or may not be on the cart. If present, ..." (dev 31 despatch_bay_pick_list):
    the negation of "may or may not" only says the doubt runs both ways, as "may" alone does
    (`sentences._MODAL_DOUBT`)."""
    assert asks(text, rooms, condition), factors(text, rooms)


def test_modal_doubt_near_misses_stay_apart() -> None:
    """An existential "there may or may not be" still asks whether there is one at all; an
    agent's "may or may not want to" or "may or may not stay" names no thing's state."""
    assert asks("There may or may not be a mug on the desk. If so, take it to the kitchen.", ("office",),
                "exists(mug)")
    assert not factors("You may or may not want to sweep the floor first. Then wash up.", ("kitchen",))
    assert not factors("The guests may or may not stay for dinner. If so, wipe the table.", ("kitchen",))


#: a thing, a bracketed "(the ... one)" telling it apart, then its place, and a condition taking
#: the clause up: (text, rooms, the condition asked). Before the rule 2 of 6 were asked (the
#: bracket after a subject, where the verb group that follows carries the place, and "If it is
#: still there" after a container, which asks the place named last)
ONE_APPOSITIVE = [
    # a colleague's note: "I left", "If so"
    ("I left a mug (the blue one) on the desk. If so, take it to the kitchen.", ("office",), "on(mug, desk)"),
    # a housekeeping card: a longer appositive, a guest as the agent
    ("Housekeeping: a guest may have left a towel (the big white one) on the bed. If so, hang it on the rack.",
     ("bedroom",), "on(towel, bed)"),
    # a family message: a plural "ones", a possessive
    ("Grandad may have left his glasses (the reading ones) on the armchair. If so, put them on the shelf.",
     ("living_room",), "on(glasses, armchair)"),
    # a chat message: small letters, a suspension before "if so"
    ("we might have left a laptop (the work one) on the sofa... if so can u put it on the desk",
     ("living_room",), "on(laptop, sofa)"),
    # a lab note: inside a container, "still there"
    ("Lab note: someone left a kettle (the old steel one) in the sink. If it is still there, put it on the counter.",
     ("kitchen",), "inside(kettle, sink)"),
    # a formal register: the bracket after a subject (already read)
    ("The remote (the old silver one) might be lying on the armchair. If it is, put it on the coffee table.",
     ("living_room",), "on(remote_control, armchair)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), ONE_APPOSITIVE)
def test_bracketed_one_appositive_keeps_the_place(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"left a mug (the blue one) on the desk. If so, ..." (docs/reader.md "What it still
    misreads"): a bracket cuts the clause, so the appositive is read between commas
    (`sentences._ONE_APPOSITIVE`)."""
    assert asks(text, rooms, condition), factors(text, rooms)


def test_bracketed_gloss_stays_a_bracket() -> None:
    """A bracketed noun is a gloss or a fuller name, not an appositive of "one": it is left to
    naming (`naming.glossed`), and a bracket of "one" before no place is left as it is."""
    assert unquote("left the headset (headphones) on the table") == "left the headset (headphones) on the table"
    assert unquote("Take the mug (the blue one). Then wash up.") == "Take the mug (the blue one). Then wash up."
    assert "(" not in unquote("left a mug (the blue one) on the desk")


#: a condition without its comma, then an instruction whose object is the speaker: (text, rooms,
#: the condition, the value the instruction falls under, the instruction's first words). Before
#: the rule 0 of 8 put the instruction under its value (the condition ran on to the sentence's
#: end, so neither answer held an instruction)
REPORT_BACK = [
    # a flatmate's note: an absence, "let me know"
    ("If the mug is missing let me know.", ("kitchen",), "exists(mug)", "no", "let me know"),
    # a landlord's message: a device's state, "tell us"
    ("If the heater is still on tell us and we will sort it.", ("living_room",), "state(radiator, toggled_on)",
     "yes", "tell us"),
    # a parent's text in small letters: wet, "text me"
    ("if the towel is wet phone me pls", ("bathroom",), "state(towel, wet)", "yes", "phone me"),
    # a dislocated subject: a negated presence, "let us know"
    ("The laptop - if it isn't there let us know.", ("office",), "exists(laptop)", "no", "let us know"),
    # an office rule: open, "call me" and an adverbial
    ("If the fridge is open call me straight away.", ("kitchen",), "state(fridge, open)", "yes", "call me"),
    # a formal register: "inform us"
    ("Should the kettle be dirty inform us at once.", ("kitchen",), "state(kettle, dirty)", "yes", "inform us"),
    # a carer's note: on the floor, "call me"
    ("If the blanket is on the floor call me.", ("bedroom",), "on(blanket, floor)", "yes", "call me"),
    # a chat message: "give me a shout"
    ("if the lamp's on give me a shout", ("bedroom",), "state(table_lamp, toggled_on)", "yes", "give me"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "value", "words"), REPORT_BACK)
def test_report_back_without_comma_is_the_instruction(text: str, rooms: tuple[str, ...], condition: str,
                                                      value: str, words: str) -> None:
    """"If the mug is missing let me know" (`benchmarks/condition_forms.py`, "if, no comma"): the
    speaker as a verb's object makes it an instruction (`clauses.OBJECT_STARTS`), which ends a
    condition typed without its comma (`clauses._imperative_cut`)."""
    under = instruction_under(text, rooms, condition)
    other = "no" if value == "yes" else "yes"
    assert words in under.get(value, "") and words not in under.get(other, ""), under


def test_speaker_after_a_preposition_stays_in_the_condition() -> None:
    """"next to me": the speaker after a preposition is no instruction's object, and the
    condition runs on to the instruction after it."""
    under = instruction_under("If the lamp is on next to me switch it off.", ("bedroom",),
                               "state(table_lamp, toggled_on)")
    assert "switch it off" in under.get("yes", ""), under


#: a condition on a thing named in the singular, then a time clause whose subject is "they" (the
#: people): (text, rooms, the condition asked, the presence that must not be asked). Before the
#: rule 3 of 6 were read without asking the thing's presence (the other three asked it too: "gone"
#: read of the thing)
TIME_CLAUSE_PEOPLE = [
    # a party host's note
    ("If the lamp is still on when they've gone, switch it off.", ("living_room",),
     "state(table_lamp, toggled_on)", "exists(table_lamp)"),
    # an office closing rule: "once they have left", a device
    ("Unless the heater is off once they have left, turn it off.", ("office",),
     "state(radiator, toggled_on)", "exists(radiator)"),
    # a holiday-let card: "after they've gone", a place
    ("If the towel is on the floor after they've gone, hang it up.", ("bathroom",), "on(towel, floor)", "exists(towel)"),
    # a B&B owner's text in small letters: "when the last of them's gone"
    ("if the kettle is still on when the last of them's gone switch it off", ("kitchen",),
     "state(kettle, toggled_on)", "exists(kettle)"),
    # a caretaker's rota: "once they've all gone", open
    ("If the fridge is open once they've all gone, shut it.", ("kitchen",), "state(fridge, open)", "exists(fridge)"),
    # a formal register: an inverted "should", "when the last of them has gone"
    ("Should the desk lamp still be on when the last of them has gone, switch it off.", ("office",),
     "state(desk_lamp, toggled_on)", "exists(desk_lamp)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "not_asked"), TIME_CLAUSE_PEOPLE)
def test_they_in_a_time_clause_are_people(text: str, rooms: tuple[str, ...], condition: str,
                                          not_asked: str) -> None:
    """"If the lamp is still on when they've gone" (docs/reader.md "What it still misreads"): the
    time clause's "they" is no mention of the lamp (`analysis._in_time_clause`)."""
    assert asks(text, rooms, condition), factors(text, rooms)
    assert not asks(text, rooms, not_asked), factors(text, rooms)


def test_they_of_a_plural_thing_in_a_time_clause_stays_the_thing() -> None:
    """A plural thing named before the time clause is what "they" take up ("the cups ... when
    they have dried")."""
    assert asks("If the cups are still on the table when they have dried, put them away.", ("living_room",),
                "on(cup, coffee_table)")
