"""A negated statement states no place (issue 47). Two rules read a negation as a placement:
the locative statement when the negation came before its verb group ("the mug never stands on
the table", "does not sit on"), and the possessive when the holder "has no" thing on it. Found by
the ninth session's structural-fallback round on sentences of its own; tested here on sentences
of several registers, with the affirmative near misses that must still place."""

from __future__ import annotations

import pytest
from reading import placed

ROOMS = ("study",)


@pytest.mark.parametrize("text", [
    "The mug never stands on the table. If the mug is dirty, wash it.",
    "The mug does not sit on the table. If the mug is dirty, wash it.",
    "that mug never ever really sits on the table tbh. if the mug is dirty wash it",
    "NB: the mug doesn't stand on the table. Should the mug be dirty, wash it.",
])
def test_a_negated_resting_verb_states_no_place(text: str) -> None:
    assert not {f for f in placed(text, ROOMS) if f.startswith("on(mug")}


@pytest.mark.parametrize("text", [
    "The shelf has no book on it. If the book is on the floor, pick it up.",
    "The shelf hasn't got a book on it. If the book is on the floor, pick it up.",
    "Alas, the shelf doth not have a book upon it. If the book be on the floor, pick it up.",
    "shelf doesnt have a book on it lol. if the book is on the floor pick it up",
])
def test_a_holder_that_has_no_thing_holds_none(text: str) -> None:
    assert not {f for f in placed(text, ROOMS) if f.startswith("on(book")}


@pytest.mark.parametrize("text,fact", [
    ("The mug stands on the table. If the mug is dirty, wash it.", "on(mug,"),
    ("The mug is on the table, not in the sink. If the mug is dirty, wash it.", "on(mug,"),
    ("The shelf has a book on it. If the book is dirty, wipe it.", "on(book,"),
    ("Now the shelf has a book on it, not a mug. If the book is dirty, wipe it.", "on(book,"),
])
def test_the_affirmative_still_places(text: str, fact: str) -> None:
    assert {f for f in placed(text, ROOMS) if f.startswith(fact)}


@pytest.mark.parametrize("text,kept,gone", [
    ("The mug, not the cup, is on the table. If the mug is dirty, wash it.", "on(mug,", "on(cup,"),
    ("the mug not the cup is on the table lol. if the mug is dirty wash it", "on(mug,", "on(cup,"),
    ("Note: the mug, and not the cup, is on the table. If the mug is dirty, wash it.", "on(mug,", "on(cup,"),
    ("The shelf has a mug on it and no cup. If the mug is dirty, wash it.", "on(mug,", "on(cup,"),
])
def test_a_thing_contrasted_away_in_a_subject_list_is_not_placed(text: str, kept: str, gone: str) -> None:
    facts = placed(text, ROOMS)
    assert {f for f in facts if f.startswith(kept)} and not {f for f in facts if f.startswith(gone)}
