"""Near-twin reader helpers consolidated in the eighteenth session (issue 47, docs/reader.md "Near
twins consolidated"), behaviour kept: the time words of `analysis` as one table, the two branches
that read a plural pronoun in a time clause as the people the time is told by as one test
(`_Reader._time_people`), the verbs whose particle sets a state as one table for `_undone` and
`_elided`, the closing quotation marks as one table for `sentences._QUOTED_WHOLE` and
`clauses.ends_asking`; and the pairs that stay apart (`COMMENT_ASIDES` / `_aside_end`,
`meaning._Literals` / `axioms.Axioms`) pinned on what tells them apart. Sentences written here, in
two registers or more each (none from the task sets), with near misses."""

from __future__ import annotations

import pytest
from reading import factors

from logicenveval.llm.meaning import factor_problem
from logicenveval.logic.axioms import Axioms
from logicenveval.model.conditions import parse
from logicenveval.model.task import Role
from logicenveval.offline.analysis import (
    _PARTICLE_VERBS,
    _SETTERS,
    _TIME_CUES,
    _TIME_OPENERS,
    _before_time_clause,
    _in_time_clause,
)
from logicenveval.offline.clauses import ends_asking
from logicenveval.offline.sentences import _QUOTED_WHOLE, CLOSING_QUOTES, COMMENT_ASIDES


def _asked(text: str, rooms: tuple[str, ...]) -> set[str]:
    return {c for values in factors(text, rooms).values() for c in values}


# -- (a) the time words: one table, the narrower use a part of it ------------------------------

def test_the_time_cues_are_the_time_openers_that_tell_the_time_of_asking() -> None:
    assert _TIME_CUES < _TIME_OPENERS
    assert {"when", "whenever", "once"} == _TIME_CUES
    assert {"after", "until", "till", "before"} == _TIME_OPENERS - _TIME_CUES


@pytest.mark.parametrize(("words", "i"), [
    (["if", "the", "lamp", "is", "still", "on", "when", "they've", "gone"], 7),    # a house note
    (["unless", "the", "heater", "is", "off", "once", "they", "have", "left"], 6),  # a shift handover
    (["switch", "it", "off", "after", "they", "leave"], 4),                 # an instruction, a wider opener
    (["if", "it", "is", "still", "on", "when", "the", "last", "of", "them", "is", "gone"], 9),  # "the last of" them
])
def test_a_pronoun_after_a_time_opener_is_in_a_time_clause(words: list[str], i: int) -> None:
    assert _in_time_clause(words, i)


@pytest.mark.parametrize(("words", "i"), [
    (["if", "they", "are", "dirty", "wash", "them"], 1),    # a condition's own subject
    (["put", "them", "back", "when", "dry"], 1),          # an object, no opener before it
])
def test_a_pronoun_with_no_time_opener_before_it_is_not(words: list[str], i: int) -> None:
    assert not _in_time_clause(words, i)


@pytest.mark.parametrize(("words", "core"), [
    (["spinning", "when", "you", "come", "in"], ["spinning"]),       # a text message
    (["still", "on", "once", "we", "have", "left"], ["still", "on"]),   # a chat line
    # near miss: "until" with the reader as subject is no time of asking, nothing is cut
    (["on", "until", "you", "leave"], ["on", "until", "you", "leave"]),
])
def test_only_the_narrower_time_cues_cut_a_question_before_the_agents_time(words: list[str],
                                                                           core: list[str]) -> None:
    assert _before_time_clause(words) == core


# -- (b) a plural pronoun in a time clause: one test for both cases -----------------------------

@pytest.mark.parametrize(("text", "rooms", "asked", "thing"), [
    # the thing named in the same clause, a house note
    ("If the lamp is still on when they've gone, switch it off.", ("living_room",),
     "state(table_lamp, toggled_on)", "table_lamp"),
    # the thing named in the same clause, a shift handover with "unless ... once"
    ("Night shift note: unless the heater is off once they have left, turn it off.", ("office",),
     "state(radiator, toggled_on)", "radiator"),
    # the thing only the topic, "the last of them"
    ("Desk fan. If it's still on when the last of them's gone, switch it off.", ("office",),
     "state(ceiling_fan, toggled_on)", "ceiling_fan"),
    # the thing only the topic, a terse label
    ("Heater: if it's on when they leave, turn it off.", ("office",), "state(radiator, toggled_on)", "radiator"),
])
def test_a_plural_pronoun_in_a_time_clause_after_a_singular_thing_is_the_people(
        text: str, rooms: tuple[str, ...], asked: str, thing: str) -> None:
    conditions = _asked(text, rooms)
    assert asked in conditions
    assert not any(c.endswith(f"exists({thing})") for c in conditions)  # not "has the thing gone?"


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # near miss: the thing is plural, the pronoun is the thing ("when they are dry")
    ("Towels on the rail: when they are dry, fold them.", ("bathroom",), "state(towel, wet)"),
    # near miss: a group the sentence takes up, with no time clause
    ("The cabinet has two drawers: one for forks, one for spoons. If they're open, shut them.", ("kitchen",),
     "state(spoon_drawer, open)"),
])
def test_a_plural_pronoun_that_may_mean_a_plural_thing_means_it(text: str, rooms: tuple[str, ...],
                                                                asked: str) -> None:
    assert asked in _asked(text, rooms)


# -- (c) the verbs that set a state by their particle: one table ------------------------------

def test_the_setters_are_the_particle_verbs_and_put() -> None:
    assert _PARTICLE_VERBS | {"put"} == _SETTERS
    assert "put" not in _PARTICLE_VERBS  # "put the kettle on" may be a place's "on" to `_elided`


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # `_elided`: "already" with only the pronoun, the state from the instruction's verb
    ("Close the microwave if it isn't already.", ("kitchen",), "state(microwave, open)"),
    # `_elided`: "unless ... already are", the state from the particle of "turn ... off"
    ("Per the checklist: unless they already are, turn the lights off.", ("hallway",),
     "state(ceiling_lamp, toggled_on)"),
    # `_undone`: an unreadable condition answered by "open them"
    ("Curtains: if they've been drawn, open them right up.", ("bedroom",), "state(curtain, open)"),
    # `_undone`: an unreadable condition answered by "switch it off"
    ("Kettle - if it's been left like that, switch it off.", ("kitchen",), "state(kettle, toggled_on)"),
])
def test_a_condition_without_its_own_state_asks_the_state_its_instruction_sets(
        text: str, rooms: tuple[str, ...], asked: str) -> None:
    assert asked in _asked(text, rooms)


# -- (d) comment asides: a named list everywhere, any short aside before a place ---------------

def test_the_named_comment_asides_are_dropped_from_a_condition_too() -> None:
    assert "as ever" in COMMENT_ASIDES and "i think" not in COMMENT_ASIDES
    # a condition's aside (only the named list reaches a condition)
    assert "state(table_lamp, toggled_on)" in _asked(
        "If the lamp is, as usual, still on, switch it off.", ("living_room",))


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # a named comment aside, a house manual
    ("The remote, as ever, belongs on the stand. If it is on the sofa, put it back.", ("living_room",),
     "on(remote_control, sofa)"),
    # an aside no list names, between the subject and its place (`_aside_end`), a chatty note
    ("The key, I think, is in the drawer. If it is on the floor, put it in the drawer.", ("hallway",),
     "inside(keys, drawer)"),
])
def test_an_aside_between_a_subject_and_its_place_hides_nothing(text: str, rooms: tuple[str, ...],
                                                                asked: str) -> None:
    assert asked in _asked(text, rooms)


# -- (e) closing quotation marks: one table ---------------------------------------------------

def test_the_quote_marks_that_close_a_question_are_one_table() -> None:
    assert set(CLOSING_QUOTES) == {'"', "\u201d"}
    for mark in CLOSING_QUOTES:
        assert ends_asking(f"is it on?{mark}")
        assert _QUOTED_WHOLE.sub(r"\1", f"Ask: \u201cIs it on?{mark} YES") == "Ask: Is it on? YES"


@pytest.mark.parametrize("text", [
    '"is the kettle on?"',   # lower case: `_QUOTED_WHOLE` leaves its marks, the clause still asks
    "she asked \u201cis the fridge open?\u201d ",
])
def test_a_question_the_text_keeps_quoted_still_asks(text: str) -> None:
    assert _QUOTED_WHOLE.sub(r"\1", text) == text
    assert ends_asking(text)


@pytest.mark.parametrize("text", [
    'the "good" towel',          # near miss: quoted words ending no question
    '"The cauldron." she said',  # near miss: a quoted statement
])
def test_quoted_words_that_ask_nothing_do_not_ask(text: str) -> None:
    assert not ends_asking(text)
    assert _QUOTED_WHOLE.sub(r"\1", text) == text


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    ('Ask: "Is the kettle on the counter?" YES: put it in the cupboard.', ("kitchen",),
     "on(kettle, kitchen_counter)"),                           # a call script
    ("She asked, \u201cIs the fridge open?\u201d If so, shut it.", ("kitchen",), "state(fridge, open)"),  # a story
])
def test_a_quoted_whole_question_asks_as_it_would_unquoted(text: str, rooms: tuple[str, ...], asked: str) -> None:
    assert asked in _asked(text, rooms)


# -- (f) the meaning checks' literals and the physical axioms stay apart -----------------------

def _lit(predicate: str, obj: str, negated: bool = False, **args: str) -> dict[str, object]:
    return {"predicate": predicate, "object": obj, "negated": negated, **args}


def test_a_reply_names_rooms_by_id_where_the_axioms_take_their_type() -> None:
    # a reply's factor: the mug in kitchen_1 or in kitchen_2 exclude each other (one room at a time)
    responses = [("k1", [_lit("in_room", "mug", room="kitchen_1")]),
                 ("k2", [_lit("in_room", "mug", room="kitchen_2"), _lit("in_room", "mug", True, room="kitchen_1")]),
                 ("else", [_lit("in_room", "mug", True, room="kitchen_1"),
                           _lit("in_room", "mug", True, room="kitchen_2")])]
    assert factor_problem("mug_room", responses) is None
    # the axioms read both as "in a kitchen", which can hold together
    axioms = Axioms({"mug": Role(category="mug")}, [parse("in_room(mug, kitchen_1)"), parse("in_room(mug, kitchen_2)")])
    assert axioms.possible(parse("in_room(mug, kitchen_1)"), parse("in_room(mug, kitchen_2)"))


def test_the_axioms_rule_out_a_thing_on_itself_which_a_reply_check_leaves_to_placement() -> None:
    axioms = Axioms({"box": Role(category="box")}, [parse("on(box, box)")])
    assert not axioms.possible(parse("on(box, box)"))
    responses = [("yes", [_lit("on", "box", support="box")]), ("no", [_lit("on", "box", True, support="box")])]
    assert factor_problem("box_on_box", responses) is None
