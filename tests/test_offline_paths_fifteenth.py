"""Paths combined, fifteenth session (docs/reader.md, "Paths combined: a question answered by an
elided existential (fifteenth session)"): a factor asked under another's answer is asked in that
factor's subtask, so the planner combines their values on one path. The structure is written as
composed sentences in several registers and kinds (`ELLIPTICAL`), with near misses that must stay
apart (`APART`); every sentence is written for the test, none copied from a development set."""

from __future__ import annotations

import pytest
from reading import CATALOG, brief

from logicenveval.offline.analysis import analyse


def _groups(text: str, rooms: tuple[str, ...]) -> list[list[str]]:
    return analyse(brief(text, rooms), CATALOG).groups


# -- a question answered by an elided existential ("Is there a towel in it? If there is, ...") ----
#
# "If there is" / "if there are" / "if there isn't" opening the sentence after a question about a
# thing's place says no thing of its own: the "there is" of the question is elided (as "if so"
# says it), so the condition is the question's. Joined by "and" to a condition on another object,
# both decide one instruction, and the question's factor and the other's are one subtask.

#: (text, rooms, the subtask that must hold both factors)
ELLIPTICAL: list[tuple[str, tuple[str, ...], list[str]]] = [
    # a driving examiner's spoken directions
    ("Now the dryer. Is there a towel inside the dryer? If there is, and the dryer has stopped, take the "
     "towel out and put it on the shelf.", ("laundry_room",), ["towel_inside_dryer", "dryer_toggled_on"]),
    # a plural thing, a chat message, another room and holder
    ("ok so the fridge - are there any apples in the fridge? if there are, and the fridge door is open, "
     "put them on the counter pls", ("kitchen",), ["apple_inside_fridge", "fridge_open"]),
    # a formal manual, a past tense question
    ("Was there a mug in the sink? If there was, and the dishwasher is not running, the mug is to be "
     "placed in the dishwasher.", ("kitchen",), ["mug_inside_sink", "dishwasher_toggled_on"]),
]


@pytest.mark.parametrize(("text", "rooms", "group"), ELLIPTICAL)
def test_an_elided_existential_after_a_question_asks_the_question(text: str, rooms: tuple[str, ...],
                                                                  group: list[str]) -> None:
    assert group in _groups(text, rooms)


def test_an_elided_negative_existential_answers_the_question_too() -> None:
    # "If there isn't" is the question's other answer, no availability of its own
    groups = _groups("Is there a towel inside the dryer? If there is, take it out. If there isn't, leave the "
                     "dryer alone.", ("laundry_room",))
    assert groups == [["towel_inside_dryer"]]


#: near misses that must stay apart: an existential with its noun or "any" is read as before (the
#: tool's availability of the instruction it follows), and a condition on another object that no
#: elided existential joins stays its own subtask
APART: list[tuple[str, tuple[str, ...], list[list[str]]]] = [
    ("Is there a towel inside the dryer? If the lamp is on, switch it off.", ("laundry_room",),
     [["towel_inside_dryer"], ["ceiling_lamp_toggled_on"]]),
    ("Are there apples in the fridge? Put them on the counter. If the fridge is open, close it.", ("kitchen",),
     [["apple_inside_fridge"], ["fridge_open"]]),
]


@pytest.mark.parametrize(("text", "rooms", "groups"), APART)
def test_conditions_no_elided_existential_joins_stay_apart(text: str, rooms: tuple[str, ...],
                                                          groups: list[list[str]]) -> None:
    assert _groups(text, rooms) == groups


#: an elided existential after its instruction ("wipe it with the sponge if there is") asks for
#: the instruction's tool, not the question before: (text, rooms, the tool's factor, its subtask)
TOOL: list[tuple[str, tuple[str, ...], str, list[list[str]]]] = [
    # (the answer to the question is asked under it since the seventeenth session's framing rule,
    # tests/test_offline_paths_seventeenth.py: the sponge only where the mug is dirty)
    ("Is the mug dirty? Wash it with the sponge if there is.", ("kitchen",), "sponge_present",
     [["mug_dirty", "sponge_present"]]),
    ("If the table is dirty, wipe it with the sponge if there is, otherwise with a cloth.", ("kitchen",),
     "sponge_present", [["dining_table_dirty", "sponge_present"]]),
]


@pytest.mark.parametrize(("text", "rooms", "tool", "groups"), TOOL)
def test_an_elided_existential_after_its_instruction_asks_for_the_tool(text: str, rooms: tuple[str, ...], tool: str,
                                                                      groups: list[list[str]]) -> None:
    a = analyse(brief(text, rooms), CATALOG)
    assert tool in {f.id for f in a.factors}
    assert a.groups == groups


# -- an exception opening with "unless" after a label, to an instruction read from a modifier ------
#
# "A clean lunch box goes in the cupboard, a dirty one in the dishwasher. Advisory: unless the
# dishwasher is running - then leave it on the counter": the sentence opening with "unless" is the
# exception to the instruction before (`_relates`), whatever label ("Note:", "NB:", "Caution -")
# opens it, and the thing its instruction moves ("leave it on the counter") is the thing of the
# factor before, though that factor, read from a modifier ("a dirty one"), has no instruction of its
# own naming the machine.

#: (text, rooms, the subtask that must hold both factors)
EXCEPTION: list[tuple[str, tuple[str, ...], list[str]]] = [
    # a work sheet: a label before the exception, the thing's factor from an instruction
    ("If the mug is dirty, it goes into the dishwasher. Note: unless the dishwasher is already running - in "
     "which case leave it in the sink.", ("kitchen",), ["mug_dirty", "dishwasher_toggled_on"]),
    # a house rule: the thing's factor from a modifier, no label
    ("A dirty mug goes into the dishwasher. Unless the dishwasher is already running - in which case leave it "
     "in the sink.", ("kitchen",), ["mug_dirty", "dishwasher_toggled_on"]),
    # a terse checklist: both, another room, thing and machine
    ("A wet towel goes in the dryer. NB: unless the dryer is running, in which case hang it on the towel rack.",
     ("laundry_room",), ["towel_wet", "dryer_toggled_on"]),
    # a formal notice, a dash after the label
    ("Soiled shirts are to be placed in the washing machine. Caution - unless the washing machine is running, in "
     "which case the shirt is to be put in the hamper.", ("laundry_room",),
     ["shirt_dirty", "washing_machine_toggled_on"]),
]


@pytest.mark.parametrize(("text", "rooms", "group"), EXCEPTION)
def test_an_exception_after_a_label_joins_the_instruction_it_excepts(text: str, rooms: tuple[str, ...],
                                                                     group: list[str]) -> None:
    assert group in _groups(text, rooms)


#: near misses: a label before a condition that is no exception ("if"), an exception whose
#: instruction moves nothing and names neither thing, a label that is a statement of its own
EXCEPTION_APART: list[tuple[str, tuple[str, ...], list[list[str]]]] = [
    ("A dirty mug goes into the dishwasher. Note: if the kettle is on, switch it off.", ("kitchen",),
     [["mug_dirty"], ["kettle_toggled_on"]]),
    ("A wet towel goes in the dryer. NB: unless the lamp is off, switch it off.", ("laundry_room",),
     [["towel_wet"], ["ceiling_lamp_toggled_on"]]),
]


@pytest.mark.parametrize(("text", "rooms", "groups"), EXCEPTION_APART)
def test_a_label_before_no_exception_joins_nothing(text: str, rooms: tuple[str, ...],
                                                   groups: list[list[str]]) -> None:
    assert _groups(text, rooms) == groups
