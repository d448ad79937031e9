"""A leading condition typed without its comma (issue 47, the fourteenth session's second round,
kept alone in the fifteenth): the condition ends before a main clause with a subject of its own.
Each structure below is a composed table written here (several registers and kinds), with near
misses that must keep their words in the condition."""

from __future__ import annotations

import pytest
from reading import CATALOG
from reading import brief as _brief

from logicenveval.offline.analysis import analyse

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
