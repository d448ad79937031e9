"""Paths the planner must combine (issue 47, the fourteenth session's second round): every value
of the task is set somewhere, but a factor asked in a subtask of its own is paired with the other
subtasks' values as the trajectory cover pleases, so a combination the text nests is never built.
Each structure below is a composed table written here (several registers and kinds), with near
misses that must keep their factors apart."""

from __future__ import annotations

import pytest
from reading import CATALOG
from reading import brief as _brief

from logicenveval.offline.analysis import analyse


def _nested(text: str, rooms: tuple[str, ...]) -> set[tuple[str, str]]:
    """(factor, factor it is asked under) pairs of the reading of `text`."""
    return {(f.id, dep) for f in analyse(_brief(text, rooms), CATALOG).factors for dep, _ in f.context}


# ----- a tool's availability, said after the instruction it serves ----------------------------------
# "Wipe the table if it's dirty. Use the sponge to wipe it, if there is one." (an instruction and
# the tool's availability in one sentence) and "... wipe it down. Use the sponge and leave it on the
# counter. If there is no sponge, use a paper towel." (the tool's absence opening the sentence after
# the one using it): the tool is only asked for when the instruction it serves is carried out.

TOOL_AFTER_INSTRUCTION = [
    # an instruction, then the tool with "if there is one" in a sentence of its own
    ("Clean the stove if it is dirty. Use the scrubbing brush to do it, if there is one. "
     "If there is no brush, use a sponge.", ("kitchen",), ("scrub_brush_present", "stove_dirty")),
    ("fridge dirty? clean it. use the sponge if there is one. no sponge? just use a cloth.",
     ("kitchen",), ("sponge_present", "fridge_dirty")),
    ("Please wipe the desk if it is dirty. Use the cloth for it, if there is one; put it in the drawer "
     "afterwards.", ("office",), ("cloth_present", "desk_dirty")),
    # an instruction using the tool, then a sentence opening with the tool's absence
    ("If the mirror is dirty, clean it. Use the cloth and hang it on the rail afterwards. "
     "If there is no cloth, use a tissue.", ("bathroom",), ("cloth_present", "mirror_dirty")),
    ("bathtub dirty? scrub it. grab the brush and rinse it under the tap after. "
     "if theres no brush use the sponge.", ("bathroom",), ("scrub_brush_present", "bathtub_dirty")),
    ("If the desk is dirty, it must be wiped. The cloth is to be used for this and put back in the "
     "drawer afterwards. If there is no cloth, a tissue will do.", ("office",), ("cloth_present", "desk_dirty")),
]

TOOL_NEAR_MISSES = [
    # the absence is of something the instruction before never spoke of
    ("Wipe the table if it is dirty. Feed the cat. If there is no cat food, buy some.", ("kitchen",)),
    ("Clean the mirror if it is dirty. Put the towel on the rail. If there is no soap, tell me.", ("bathroom",)),
    # an uncertain remark of its own, no instruction: a situation, not the instruction's tool
    ("Wipe the table if it is dirty. There may be a sponge in the sink.", ("kitchen",)),
    # a topic with "if there is one", no instruction: it carries nothing on
    ("Put the mug in the sink if it is dirty. Towel, if there is one: hang it on the rail.", ("kitchen",)),
    # a state of the thing acted on "with" a tool, not where a tool is
    ("If the mug is dirty, wash it with the sponge. Then clean the stove with a cloth when it is dirty.",
     ("kitchen",)),
]


@pytest.mark.parametrize(("text", "rooms", "pair"), TOOL_AFTER_INSTRUCTION)
def test_a_tool_said_after_its_instruction_is_asked_under_its_conditions(
        text: str, rooms: tuple[str, ...], pair: tuple[str, str]) -> None:
    """The tool's presence is asked only under the conditions of the instruction it serves, so the
    planner builds the table dirty both with and without a sponge."""
    assert pair in _nested(text, rooms)


@pytest.mark.parametrize(("text", "rooms"), TOOL_NEAR_MISSES)
def test_an_unrelated_absence_stays_a_question_of_its_own(text: str, rooms: tuple[str, ...]) -> None:
    assert not _nested(text, rooms)


# ----- where a tool is, said right after the instruction naming it as the tool ----------------------
# "Should it be dirty - I wipe it down! - With the sponge, if the sponge is lying on the counter!":
# the tool's place is its availability, asked under the instruction's conditions like "if there is one".

TOOL_PLACED = [
    ("Scrub the bathtub if it is dirty. Use the brush if it is on the shelf; if it is not, use the sponge.",
     ("bathroom",), ("scrub_brush_on_wall_shelf", "bathtub_dirty")),
    ("desk dirty? wipe it. with the cloth if the cloth is in the drawer. if not, a tissue.",
     ("office",), ("cloth_inside_drawer", "desk_dirty")),
    ("MUM: And the stove, should it be dirty -\nKID: I clean it!\nMUM: With the sponge, if the sponge is "
     "lying in the sink!", ("kitchen",), ("sponge_inside_sink", "stove_dirty")),
]

TOOL_PLACED_NEAR_MISSES = [
    # the condition is on where the thing acted on is, not the tool
    ("Wipe the table if it is dirty. Put the cup in the sink if it is on the table.", ("kitchen",)),
    ("Clean the mirror if it is dirty. Take the towel to the laundry basket if it is on the floor.", ("bathroom",)),
]


@pytest.mark.parametrize(("text", "rooms", "pair"), TOOL_PLACED)
def test_where_a_tool_is_is_asked_under_its_instructions_conditions(
        text: str, rooms: tuple[str, ...], pair: tuple[str, str]) -> None:
    assert pair in _nested(text, rooms)


@pytest.mark.parametrize(("text", "rooms"), TOOL_PLACED_NEAR_MISSES)
def test_where_the_thing_acted_on_is_stays_a_question_of_its_own(text: str, rooms: tuple[str, ...]) -> None:
    assert not _nested(text, rooms)


# ----- a leading condition with no comma before a main clause with a subject of its own -------------
# "so if it is off the helper switches it on - unless its bulb is broken": without the comma the
# condition ran on into its main clause, read "on" (of "switches it on") as the condition's state,
# and the bulb's question was nested under the lamp being on.

SUBJECT_AFTER_CONDITION = [
    # a house helper's duties (third person)
    ("If the desk lamp is off the helper switches it on.", ("study",), "if the desk lamp is off",
     ("desk_lamp", "toggled_on", True)),
    # a chatty note ("you")
    ("if the fridge is open you close it pls", ("kitchen",), "if the fridge is open",
     ("fridge", "open", False)),
    # a porter's rota
    ("If the trash can is full the porter empties it before six.", ("hallway",), "if the trash can is full",
     ("trash_can", "filled", False)),
]

SUBJECT_NEAR_MISSES = [
    # a place after the state: "off the table", no subject and verb of a main clause
    ("If the cup is off the table the helper puts it back.", ("kitchen",), "if the cup is off the table"),
    # the condition's own subject and verb ("you find ..."), no predicate before them
    ("If you find the lamp on switch it off.", ("study",), "if you find the lamp on"),
    # a place after the state, then an imperative: the imperative ends the condition
    ("if the book is off the shelf put it back", ("study",), "if the book is off the shelf"),
]


def _condition(text: str, rooms: tuple[str, ...]) -> tuple[str, list[tuple[str, str, bool]]]:
    """The first condition clause of `text`: its words and its facts (subject, key, negated)."""
    for c in analyse(_brief(text, rooms), CATALOG).clauses:
        if c.role == "condition":
            return (" ".join(f"{c.cue} {c.text}".lower().strip(" .").split()),
                    [(f.subject, f.key, f.negated) for f in c.facts if not f.goal])
    return "", []


@pytest.mark.parametrize(("text", "rooms", "said", "fact"), SUBJECT_AFTER_CONDITION)
def test_a_condition_without_its_comma_ends_before_a_subject_and_its_verb(
        text: str, rooms: tuple[str, ...], said: str, fact: tuple[str, str, bool]) -> None:
    words, facts = _condition(text, rooms)
    assert words == said
    assert facts == [fact]


@pytest.mark.parametrize(("text", "rooms", "said"), SUBJECT_NEAR_MISSES)
def test_a_place_or_the_conditions_own_subject_is_no_main_clause(text: str, rooms: tuple[str, ...],
                                                                 said: str) -> None:
    assert _condition(text, rooms)[0].startswith(said)


# ----- a sentence opening with "Unless", after an instruction that names its thing ------------------
# "If it is dirty, into the dishwasher it goes! Unless - ah, unless! - the dishwasher is already
# running: then into the sink": the exception to the instruction before, so the dishwasher's state
# is asked in the plate's subtask (where the plate goes depends on both).

UNLESS_AFTER_INSTRUCTION = [
    ("If the mug is dirty, it goes in the dishwasher. Unless the dishwasher is running: then in the sink.",
     ("kitchen",), ("mug", "dishwasher")),
    ("if the shirt is dirty chuck it in the washing machine. unless the washing machine is already "
     "running - then the hamper.", ("laundry_room",), ("shirt", "washing_machine")),
    ("Should the towel be wet, it is to be dried in the dryer. Unless the dryer is running, in which "
     "case it goes on the rack.", ("laundry_room",), ("towel", "dryer")),
]

UNLESS_NEAR_MISSES = [
    # the instruction before names nothing the exception speaks of
    ("If the plant is dry, water it. Unless the window is open, switch on the heater.", ("living_room",),
     ("plant", "window")),
]


def _together(text: str, rooms: tuple[str, ...], pair: tuple[str, str]) -> bool:
    a = analyse(_brief(text, rooms), CATALOG)
    subject = {f.id: f.subject for f in a.factors}
    return any(set(pair) <= {subject[i] for i in g} for g in a.groups)


@pytest.mark.parametrize(("text", "rooms", "pair"), UNLESS_AFTER_INSTRUCTION)
def test_a_sentence_opening_with_unless_is_the_exception_to_the_instruction_before(
        text: str, rooms: tuple[str, ...], pair: tuple[str, str]) -> None:
    assert _together(text, rooms, pair)


@pytest.mark.parametrize(("text", "rooms", "pair"), UNLESS_NEAR_MISSES)
def test_an_unless_on_something_the_instruction_never_named_stays_apart(
        text: str, rooms: tuple[str, ...], pair: tuple[str, str]) -> None:
    assert not _together(text, rooms, pair)
