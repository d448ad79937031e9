"""Values never set and paths not combined in the rewordings, sixteenth session (docs/reader.md,
"Question-and-answer layouts (sixteenth session)"). Each structure is written first as a table of
composed texts in several registers (measured before its rule and after), with near misses that
must not be misread; every text is written for the test, none copied from a development set."""

from __future__ import annotations

from typing import Any

import pytest
from reading import CATALOG, brief

from logicenveval.offline.analysis import analyse, nest
from logicenveval.offline.sentences import answered_questions


def _nested(text: str, rooms: tuple[str, ...], inner: str, outer: str) -> bool:
    """Whether the factor asking `inner` is asked under the factor asking `outer` (its context)."""
    fs = analyse(brief(text, rooms), CATALOG).factors
    outer_ids = {f.id for f in fs if outer in f.values.values()}
    return any(inner in f.values.values() and any(c in outer_ids for c, _ in f.context) for f in fs)


def _asked(text: str, rooms: tuple[str, ...]) -> dict[str, set[str]]:
    return {f.id: set(f.values.values()) for f in analyse(brief(text, rooms), CATALOG).factors}


# -- a question-and-answer layout: the answer's conditions under its question's ---------------------
#
# A catechism, an FAQ, a quiz, a training sheet: "Q. What must you do if there is a mug on the desk?
# A. If it is dirty, I take it to the sink." The question states the case ("what ... if X?", "and
# if X?"); its answer is the instruction for that case, so a condition the answer asks is asked
# under X, as a reader nests it. A follow-up question on the answer's own condition ("But what if
# it is not dirty? A. Then ...") is that condition's other branch, under X as well.

#: (text, rooms, the inner condition, the outer condition it is asked under)
ANSWERED: list[tuple[str, tuple[str, ...], str, str]] = [
    # a catechism, numbered questions, a follow-up on the answer's condition
    ("Q. 1. What must you do if there is a mug on the desk?\nA. If the mug is dirty, I take it to the sink.\n"
     "Q. 2. But what if the mug is not dirty?\nA. Then I put it in the cupboard.",
     ("study", "kitchen"), "state(mug, dirty)", "on(mug, desk)"),
    # a holiday let's FAQ, "Q:"/"A:" labels, the answer with its own "otherwise"
    ("Q: What do I do if the towel is on the floor?\nA: If it is wet, hang it on the towel rack; otherwise "
     "put it in the hamper.", ("bathroom",), "state(towel, wet)", "on(towel, floor)"),
    # a quiz sheet, "Question 3:" and "Answer:", "when" for the case
    ("Question 3: What should the robot do when the laptop is on the bed?\nAnswer: If the laptop is open, "
     "it closes it first, then it puts it on the desk.", ("bedroom",), "state(laptop, open)",
     "on(laptop, bed)"),
    # a chat-like FAQ in small letters, "and if" with no "what"
    ("q: and if there is a book on the floor?\na: if it is open, close it, then put it on the shelf.",
     ("living_room",), "state(book, open)", "on(book, floor)"),
    # a training handout, a case of a state, the answer's "when"
    ("Question: What happens if the fridge is open?\nAnswer: When the milk is on the counter, put the "
     "milk in the fridge first, then close the fridge.", ("kitchen",), "on(milk_carton, kitchen_counter)",
     "state(fridge, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), ANSWERED)
def test_an_answers_condition_is_asked_under_its_questions(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    """`sentences.answered_questions`: "Q. ... if X? A. If Y, ..." is "If X: if Y, ..."."""
    assert _nested(text, rooms, inner, outer), _asked(text, rooms)


@pytest.mark.parametrize("text", [
    # an indirect question asks no case: "know if" is "whether"
    "Q: Do you know if the mug is clean?\nA: Yes, it is clean.",
    # a question with no case: its answer's condition stays where it is
    "Question 2: Where does the book go?\nAnswer: If it is a novel, on the shelf.",
    # no labels: prose's own question and answer are read as they were
    "What if the mug is dirty? Then wash it in the sink.",
    # a question with a case and no answer after it
    "Q. What do you do if the lamp is on?\nThe lamp is in the study.",
])
def test_a_layout_that_states_no_answered_case_is_left_as_it_is(text: str) -> None:
    assert answered_questions(text) == text


def test_a_follow_up_on_another_thing_is_a_case_of_its_own() -> None:
    """"And what if the lamp is on?" after an answer about the mug shares no word with the
    answer's condition: not that condition's other branch, so not asked under the mug's case."""
    text = ("Q: What should I do if there is a mug on the desk?\nA: If it is dirty, take it to the sink.\n"
            "Q: And what if the desk lamp is on?\nA: Switch it off.")
    assert "If the desk lamp is on: Switch it off." in answered_questions(text)
    assert not _nested(text, ("study", "kitchen"), "state(desk_lamp, toggled_on)", "on(mug, desk)")
    assert _nested(text, ("study", "kitchen"), "state(mug, dirty)", "on(mug, desk)")


def _under(text: str, rooms: tuple[str, ...], inner: str, outer: str) -> bool:
    """Whether the factor asking `inner` is asked only where `outer` (one of a factor's values'
    conditions, "not ..." for its other branch) holds."""
    fs = analyse(brief(text, rooms), CATALOG).factors
    by_id = {f.id: f for f in fs}
    return any(inner in f.values.values() and any(
        c in by_id and {by_id[c].values[v] for v in vs} == {outer} for c, vs in f.context) for f in fs)


# -- an arrow flowchart: a question answered by "YES ->" / "NO ->", a question after an arrow ------
#
# A decision tree typed as text ("Clean? YES -> fold it. / NO -> Machine running? / YES -> ...") puts
# each answer's label under the question it answers (the same column) and a further question after
# an arrow: that question is asked only on its arrow's branch, and its answers, one indentation
# deeper, under it. Read as the nested conditional it draws ("if it is not clean: if the machine
# is running, ...").

#: (text, rooms, the inner condition, the outer condition (branch) it is asked under)
FLOWCHARTS: list[tuple[str, tuple[str, ...], str, str]] = [
    # a kitchen card, three levels, a topic line before the chart
    ("The plates:\n  Dirty? YES -> Dishwasher open?\n                YES -> load them.\n"
     "                NO -> open it, then load them.\n         NO -> put them in the cupboard.",
     ("kitchen",), "state(dishwasher, open)", "state(plate, dirty)"),
    # a tea-making card, the NO branch first, "already"
    ("Kettle:\n  Full? NO -> fill it at the sink.\n        YES -> Stove already on?\n"
     "                 YES -> put the kettle on the stove.\n                 NO -> switch it on first.",
     ("kitchen",), "state(stove, toggled_on)", "state(kettle, filled)"),
    # a bedtime chart in small letters, a typographic arrow
    ("the desk lamp\n  on? yes \u2192 Book open?\n           yes \u2192 close the book.\n"
     "           no \u2192 leave it.\n      no \u2192 nothing to do.", ("bedroom",), "state(book, open)",
     "state(desk_lamp, toggled_on)"),
    # an office flowchart, the inner question after the NO arrow of a state's antonym
    ("Mug on the desk:\n  Clean? YES -> put it in the cupboard.\n         NO -> Sink empty?\n"
     "                 YES -> put it in the sink.\n                 NO -> leave it on the counter.",
     ("office", "kitchen"), "state(sink, filled)", "state(mug, dirty)"),
    # a laundry-room sign, "dry" for the towel's wetness, the question on its NO branch
    ("Bath towel\n  Dry? YES -> fold it.\n       NO -> Dryer already running?\n"
     "               YES -> hang it on the towel rack.\n               NO -> put it in the dryer.",
     ("bathroom", "laundry_room"), "state(dryer, toggled_on)", "state(towel, wet)"),
    # a caretaker's card, "empty" for a fill, the YES branch of the opposite word
    ("KETTLE\n  Empty? YES -> Sink full of dishes?\n                YES -> fill it in the bathroom.\n"
     "                NO -> fill it at the sink.\n         NO -> switch it on.", ("kitchen", "bathroom"),
     "state(sink, filled)", "not state(kettle, filled)"),
    # a call script's colon labels, a question in "closed" on the NO label's line
    ("Is the laptop closed?\nNO: Is the desk lamp on? If it is, switch it off, then close the laptop.\n"
     "YES: put it in the drawer.", ("study",), "state(desk_lamp, toggled_on)", "state(laptop, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), FLOWCHARTS)
def test_a_question_after_an_arrow_is_asked_on_that_branch(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    """`sentences.unflowchart`: "Q? YES -> ... / NO -> Q2? / YES -> ..." asks Q2 on Q's branch."""
    assert _under(text, rooms, inner, outer), _asked(text, rooms)


# -- a flowchart's question within an answer has answers of its own --------------------------------
#
# "NO -> Dishwasher running?" on an indented line, and under it, one indentation deeper, "NO -> ..."
# / "YES -> Sink full?": the deeper labels answer the question within the answer (the nearest one on
# a line indented less than the label), not the chart's first question; and a question asked only
# under that inner question's answer is not asked on a branch where the inner question is not.

#: (text, rooms, the innermost condition, the middle condition (branch) it is asked under)
DEEP_FLOWCHARTS: list[tuple[str, tuple[str, ...], str, str]] = [
    # a kitchen poster, the inner question on the NO branch of an opposite word
    ("Mug:\n  Clean? YES -> cupboard.\n         NO -> Dishwasher running?\n"
     "                 NO -> load it in the dishwasher.\n                 YES -> Sink full?\n"
     "                          NO -> put it in the sink.\n                          YES -> leave it on the counter.",
     ("kitchen",), "state(sink, filled)", "state(dishwasher, toggled_on)"),
    # a study's bedtime chart in small letters, the inner question on the "no" of a second one
    ("the desk lamp\n  on? no -> nothing to do.\n      yes -> Wardrobe open?\n"
     "              yes -> close the wardrobe first.\n              no -> Laptop open?\n"
     "                      yes -> close the laptop, then switch the lamp off.\n"
     "                      no -> switch the lamp off.", ("study", "bedroom"), "state(laptop, open)",
     "not state(wardrobe, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), DEEP_FLOWCHARTS)
def test_a_deeper_label_answers_the_question_within_the_answer(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    """`analysis._answered`: an indented label answers the nearest question on a line indented less."""
    assert _under(text, rooms, inner, outer), _asked(text, rooms)


def _vars(tree: dict[str, Any]) -> set[str]:
    return {tree["var"]} | set().union(*(_vars(b) for b in tree["branches"].values())) if "var" in tree else set()


def test_a_question_under_an_inner_answer_is_not_asked_where_the_inner_question_is_not() -> None:
    """`analysis.nest`: the sink's question, asked under the dishwasher's "YES", is not asked where
    the mug is clean (the dishwasher's question is not asked there)."""
    text, rooms = DEEP_FLOWCHARTS[0][:2]
    result = analyse(brief(text, rooms), CATALOG)
    by_id = {f.id: f for f in result.factors}
    mug = next(f for f in result.factors if f.values["yes"] == "state(mug, dirty)")
    group = next(g for g in result.groups if mug.id in g)
    tree = nest([by_id[i] for i in group])
    assert tree["var"] == mug.id
    sink = next(f.id for f in result.factors if f.values["yes"] == "state(sink, filled)")
    assert sink not in _vars(tree["branches"]["no"]) and sink in _vars(tree["branches"]["yes"])
