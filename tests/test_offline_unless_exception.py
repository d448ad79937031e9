"""A sentence opening with "Unless" after an instruction (issue 47, the fourteenth session's second
round, kept in the fifteenth): the exception to that instruction, so its thing's state is asked in the
instruction's subtask. A composed table written here (several registers and kinds), with a near miss
that must stay apart."""

from __future__ import annotations

import pytest
from reading import CATALOG
from reading import brief as _brief

from logicenveval.offline.analysis import analyse

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
