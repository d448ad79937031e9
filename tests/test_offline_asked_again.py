"""Conditions the reader read and then threw away, or never saw (issue 47, the thirteenth session):
a placement the text states and then asks again ("Ned left his book on the floor ... Is it on the
floor now?", a stage direction's "a counter with a plate upon it" and "if there is no plate on the
counter at all?", a habit said in an aside, "(it is always found lying on the floor)"), and an
aside between dashes straight after a connective ("Unless - ah, unless! - the dishwasher is
running"). Each rule on sentences written here in two registers or more (none from the task sets),
with near misses that must not be read."""

from __future__ import annotations

import pytest
from reading import asks, factors

from logicenveval.offline.sentences import unquote


def _no_factor_of(text: str, rooms: tuple[str, ...], fact: str) -> bool:
    return not any(fact in values or f"not {fact}" in values for values in factors(text, rooms).values())


# -- a placement stated, then asked again (`analysis._asked_again`) ---------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a parent's note: a past statement, then a question with "now"
    ("Mia dropped her towel on the floor this morning. Is it on the floor now? Then hang it up.",
     ("bathroom",), "on(towel, floor)"),
    # a play's stage direction, then a line asking the thing's absence
    ("SCENE: an office. A desk with a mug upon it. CLERK: And if there is no mug on the desk at all? "
     "MANAGER: Then fetch one.", ("office",), "exists(mug)|on(mug, desk)"),
    # a house rule, a habit said in a bracketed aside inside the condition
    ("My scarf belongs on the hook by the door. Should it be found lying on the floor (it is always "
     "found lying on the floor), hang it back up.", ("hallway",), "on(scarf, floor)"),
    # a family chat: "still" after a past statement
    ("Dad left the remote on the sofa last night. Is it still on the sofa? If so, put it on the TV stand.",
     ("living_room",), "on(remote_control, sofa)"),
])
def test_a_placement_stated_and_then_asked_stays_a_question(text: str, rooms: tuple[str, ...],
                                                            condition: str) -> None:
    assert any(asks(text, rooms, c) for c in condition.split("|"))


@pytest.mark.parametrize(("text", "rooms", "fact"), [
    # a statement and an instruction: nothing is asked
    ("Mia dropped her towel on the floor this morning. Pick it up and hang it on the rail.", ("bathroom",),
     "on(towel, floor)"),
    # "already" asks whether the instruction is done; the statement answers it
    ("The book is on the shelf. Put the book on the shelf unless it is already there.", ("study",),
     "on(book, shelf)"),
    # the place names the thing, the state is asked
    ("There's a desk with a mug on it. If the mug on the desk is dirty, wash it.", ("office",), "on(mug, desk)"),
    # a check the reader implies ("examine X on Y"), not the writer's question
    ("A bench with a towel on it. Examine the towel on the bench. Is it wet? Then hang it up.", ("bathroom",),
     "on(towel, bench)"),
    # a verb of seeing asks no place
    ("Right, team: the water bottle is on the bench. See that water bottle on the bench? Bin it.", ("mudroom",),
     "on(water_bottle, bench)"),
])
def test_a_placement_stated_and_not_asked_is_no_question(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert _no_factor_of(text, rooms, fact)


# -- an aside between dashes after a connective (`sentences.DASHED_ASIDE_CONNECTIVES`) ---------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a libretto's exclamation
    ("Put the bowl in the dishwasher. Unless - ah, unless! - the dishwasher is already running: then "
     "into the sink with it.", ("kitchen",), "state(dishwasher, toggled_on)"),
    # a chatty email, "if - and it does happen -"
    ("Before you leave: if - and it does happen - the kettle is still on, switch it off.", ("kitchen",),
     "state(kettle, toggled_on)"),
    # a kitchen rota, "whenever"
    ("Whenever - and it is often - the bin is full, empty it into the wheelie bin.", ("kitchen",),
     "state(trash_can, filled)"),
])
def test_a_dashed_aside_after_a_connective_hides_no_condition(text: str, rooms: tuple[str, ...],
                                                             condition: str) -> None:
    assert asks(text, rooms, condition)


@pytest.mark.parametrize("text", [
    "If it is dirty - sink - then dry it.",  # a dash after the condition
    "The mug - if dirty - goes in the sink.",  # the condition itself between dashes
    "Then - wait - dry it.",  # no connective
])
def test_dashes_not_after_a_connective_are_left(text: str) -> None:
    assert unquote(text) == text


# -- a presence asked in the forms writers ask it (`clauses.presence_asked`) --------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a flatmate's note, a question with its finite word first
    ("Can you pop into the living room? Is the remote there? If so, put it on the TV stand.", ("living_room",),
     "exists(remote_control)"),
    # a negative question asks the same
    ("Before bed: isn't my laptop here? If so, plug it in.", ("office",), "exists(laptop)"),
    # a porter's round, a modal before "be"
    ("Night round: if the kettle might still be there, unplug it and leave it on the counter.", ("kitchen",),
     "exists(kettle)"),
    # a formal notice, "should" inverted
    ("Should the hair dryer be there, it is to be unplugged.", ("bathroom",), "exists(hair_dryer)"),
    # a house-sitter's note: a modifier the reader guesses an attribute from blocks no presence
    ("Is the right remote there? If so, put it on the TV stand.", ("living_room",), "exists(remote_control)"),
])
def test_a_presence_asked_as_a_question_or_with_a_modal_asks_whether_the_thing_is_there(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "fact"), [
    # a place of its own: where it is, not whether
    ("Is the remote on the sofa? If so, put it on the TV stand.", ("living_room",), "exists(remote_control)"),
    # a state, not a presence
    ("Is the kettle on right now? If so, switch it off.", ("kitchen",), "exists(kettle)"),
])
def test_a_question_of_place_or_state_is_no_presence(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert _no_factor_of(text, rooms, fact)


@pytest.mark.parametrize("words", [
    "it is there already",  # "already" asks whether an instruction is done
    "is the mug dirty",
    "the mug is on the table",
])
def test_presence_asked_leaves_other_conditions(words: str) -> None:
    from logicenveval.offline.clauses import presence_asked
    assert presence_asked(words.split()) is None


# -- a condition typed without its comma (`sentences.predicate_state`, `clauses._imperative_cut`) --

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a text message: a result participle ends the condition, no mark after it
    ("if the bowl's been rinsed stick it on the rack", ("kitchen",), "state(bowl, dirty)"),
    # a care note: a verb of the state in progress
    ("Care note: if the bath towel is still dripping hang it over the radiator.", ("bathroom",),
     "state(towel, wet)"),
    # a memo: a state, then when, then the instruction
    ("Memo to night staff: if the microwave was left open this morning close it before you go.", ("kitchen",),
     "state(microwave, open)"),
])
def test_a_condition_without_its_comma_keeps_its_predicate(text: str, rooms: tuple[str, ...],
                                                           condition: str) -> None:
    assert asks(text, rooms, condition)


def test_a_participle_describing_a_thing_asks_nothing() -> None:
    # "washed" before its noun describes the plates; no condition
    assert _no_factor_of("Washed plates go on the shelf.", ("kitchen",), "state(plate, dirty)")



def test_a_room_said_in_a_time_clause_is_not_asked_again() -> None:
    from logicenveval.offline.analysis import Fact, _asked_again
    # an advice column: "when" opens an aside about the house, not a question of where the sink is
    sink = Fact("sink", "in_room(sink, kitchen)", "location", "kitchen")
    assert _asked_again(", as in your house, the nearest sink is in the kitchen next door.", [sink]) == set()
    # a diary: where a thing is, asked of a holder
    towel = Fact("towel", "on(towel, floor)", "location", "floor")
    assert _asked_again("Is it on the floor now?", [towel]) == {"on(towel, floor)"}
