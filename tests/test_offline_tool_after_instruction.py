"""A tool's availability said after the instruction it serves (docs/reader.md, "A tool said after
the instruction it serves (fifteenth session)"): the tool is asked under the instruction's
conditions when the instruction's structure says the tool sentence goes on with it, not wherever
a tool's availability is said. Three structures, each written as composed sentences in several
registers and kinds before its rule, with near misses that must stay apart; every sentence is
written for the test, none copied from a development set."""

from __future__ import annotations

import pytest
from reading import CATALOG, brief

from logicenveval.offline.analysis import Clause, analyse


def _groups(text: str, rooms: tuple[str, ...]) -> list[list[str]]:
    return analyse(brief(text, rooms), CATALOG).groups


def _clauses(text: str, rooms: tuple[str, ...]) -> list[Clause]:
    return analyse(brief(text, rooms), CATALOG).clauses


# -- (a) "Use/Take/Grab X to <verb> it", the verb taken up from the instruction before ------------
#
# "You only need to wipe the table if it's dirty. Use the sponge to wipe it, if there is one.": the
# tool sentence's purpose is the instruction before (its verb again, or "do", with a pronoun
# object), so it says how that instruction is done and its tool is asked under its conditions.

#: (text, rooms, the subtask that must hold the instruction's factor and the tool's)
PURPOSE: list[tuple[str, tuple[str, ...], list[str]]] = [
    # a plain house note
    ("Wipe the table if it's dirty. Use the sponge to wipe it, if there is one.", ("kitchen",),
     ["dining_table_dirty", "sponge_present"]),
    # a formal rule, a passive instruction, another room, tool and verb
    ("The mirror is to be cleaned only if it is dirty. Use the cloth to clean it, if there is one.", ("bathroom",),
     ["mirror_dirty", "cloth_present"]),
    # a gerund instruction ("needs wiping") taken up by the infinitive
    ("The table only needs wiping if it's dirty. Grab the sponge to wipe it, if there is one.", ("kitchen",),
     ["dining_table_dirty", "sponge_present"]),
    # the pro-verb "do it" stands for the instruction before
    ("Clean the mirror if it is dirty. Take the cloth to do it, if there is one.", ("bathroom",),
     ["mirror_dirty", "cloth_present"]),
]


@pytest.mark.parametrize(("text", "rooms", "group"), PURPOSE)
def test_a_tool_whose_purpose_takes_up_the_instruction_is_asked_under_it(text: str, rooms: tuple[str, ...],
                                                                         group: list[str]) -> None:
    assert group in _groups(text, rooms)


#: near misses: a tool sentence with a verb or an object of its own, or with no purpose at all, is
#: an instruction of its own, read as before
PURPOSE_APART: list[tuple[str, tuple[str, ...], str]] = [
    # a verb of its own
    ("Clean the mirror if it is dirty. Use the cloth to dry the towel, if there is one.", ("bathroom",),
     "cloth_present"),
    # the verb again, but an object of its own
    ("Wipe the table if it's dirty. Use the sponge to wipe the sink, if there is one.", ("kitchen",),
     "sponge_present"),
]


@pytest.mark.parametrize(("text", "rooms", "tool"), PURPOSE_APART)
def test_a_tool_sentence_with_its_own_verb_or_object_stays_apart(text: str, rooms: tuple[str, ...],
                                                                 tool: str) -> None:
    assert not any(tool in g and len(g) > 1 for g in _groups(text, rooms))


# -- (b) a verbless "with X" phrase going on with the instruction before ---------------------------
#
# "If the counter is dirty, wipe it down. With the sponge, if the sponge is on the counter!": a
# sentence that is only a tool phrase (after a speaker's name at most) has no instruction of its
# own; it finishes the one before, so its condition on the tool, of any kind (where the tool lies,
# not only whether there is one), is asked under that instruction's conditions.

#: (text, rooms, the subtask that must hold both factors)
WITH: list[tuple[str, tuple[str, ...], list[str]]] = [
    # an exclamation, a place asked of the tool
    ("If the counter is dirty, wipe it down. With the sponge, if the sponge is on the counter!", ("kitchen",),
     ["kitchen_counter_dirty", "sponge_on_kitchen_counter"]),
    # a dialogue: speakers' names before the lines, the tool phrase answering a question
    ("GRAN: If the mirror is dirty, you clean it. BOY: With the towel? GRAN: With the towel, if the towel is on "
     "the rack.", ("bathroom",), ["mirror_dirty", "towel_on_towel_rack"]),
    # an inverted condition, "And with" going on
    ("Should the table be dirty, wipe it. And with the cloth, if the cloth is in the drawer.", ("kitchen",),
     ["dining_table_dirty", "cloth_inside_drawer"]),
]


@pytest.mark.parametrize(("text", "rooms", "group"), WITH)
def test_a_verbless_with_phrase_goes_on_with_the_instruction_before(text: str, rooms: tuple[str, ...],
                                                                    group: list[str]) -> None:
    assert group in _groups(text, rooms)


#: near misses: a "with" phrase opening an instruction of its own, and a condition on the tool
#: with no "with" phrase, are asked apart as before
WITH_APART: list[tuple[str, tuple[str, ...], list[list[str]]]] = [
    ("If the counter is dirty, wipe it down. With the sponge, wipe the sink if the sponge is on the counter.",
     ("kitchen",), [["kitchen_counter_dirty"], ["sponge_on_kitchen_counter"]]),
    ("If the counter is dirty, wipe it down. If the sponge is on the counter, put it in the sink.", ("kitchen",),
     [["kitchen_counter_dirty"], ["sponge_on_kitchen_counter"]]),
]


@pytest.mark.parametrize(("text", "rooms", "groups"), WITH_APART)
def test_a_with_phrase_opening_its_own_instruction_stays_apart(text: str, rooms: tuple[str, ...],
                                                               groups: list[list[str]]) -> None:
    assert _groups(text, rooms) == groups


# -- (c) "it" right after a thing said to be absent skips that thing ------------------------------
#
# "If the bowl is dirty, scrub it with the sponge. No sponge? Then wipe it out with a paper towel.":
# a clause saying only that a thing is absent makes it no topic; a later "it" is the thing spoken
# of before (a thing just said not to be there is not wiped, rinsed or put away).

#: (text, rooms, what the last clause must speak of, what it must not)
ABSENT: list[tuple[str, tuple[str, ...], str, str]] = [
    # a verbless question, "Then" answering it
    ("If the bowl is dirty, scrub it with the sponge. No sponge? Then wipe it out with a paper towel.", ("kitchen",),
     "bowl", "sponge"),
    # an existential condition in a labelled note
    ("The mug: if it's dirty, wash it with the sponge. If there's no sponge, rinse it under the tap.", ("kitchen",),
     "mug", "sponge"),
    # a lower-case chat message, a place for the thing, not a tool
    ("towel on the floor? hang it on the hook. no hook? then put it on the chair", ("bathroom",), "towel",
     "coat_hook"),
    # "we have no", after a statement
    ("The pan is dirty. Scrub it with the brush; if we have no brush, soak it in the sink.", ("kitchen",), "pan",
     "broom"),
]


@pytest.mark.parametrize(("text", "rooms", "meant", "absent"), ABSENT)
def test_it_after_an_absence_skips_the_absent_thing(text: str, rooms: tuple[str, ...], meant: str,
                                                    absent: str) -> None:
    last = _clauses(text, rooms)[-1]
    assert meant in last.mentions
    assert absent not in last.mentions


#: near misses: a thing missing from a place names the place too, and "it" is the missing thing
#: put there, as before: (text, rooms, what the last clause must speak of)
ABSENT_FROM_A_PLACE: list[tuple[str, tuple[str, ...], str]] = [
    ("No sponge on the counter? Put it there.", ("kitchen",), "sponge"),
    ("The mug is clean. If there is no towel on the rack, hang it there.", ("bathroom",), "towel"),
]


@pytest.mark.parametrize(("text", "rooms", "meant"), ABSENT_FROM_A_PLACE)
def test_a_thing_missing_from_a_place_is_still_what_it_speaks_of(text: str, rooms: tuple[str, ...],
                                                                 meant: str) -> None:
    assert meant in _clauses(text, rooms)[-1].mentions
