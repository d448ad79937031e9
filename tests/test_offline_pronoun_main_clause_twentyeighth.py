"""A condition typed without its comma, then a main clause whose subject is the thing itself ("If
it's dirty it goes in the dishwasher", "If it's still there it goes in the lost property box"),
from the twenty-eighth session (dev 46's Scout kit store returns): the pronoun and a verb agreeing
with it (its "-s" form) open the main clause, as "you" and an imperative do ("if the window is open
you close it"), after a state word or "there" (`clauses._main_clause`, `THING_SUBJECTS`). Never
after a state word that is also a preposition: "if the lamp is on it ..." may be "on it", a place.
Rows written here in other registers before the rule and measured then: 0 of 6; after: 6 of 6
(the blankets' row first ran on into a muddled second sentence, cut after the first run; "they"
takes the verb's base form, added then).
Near misses: a comma-less condition with no second subject, and "on it" as a place."""

from __future__ import annotations

import pytest
from reading import CATALOG, brief

from logicenveval.offline.analysis import analyse

#: (text, rooms, the condition's words, the main clause's first words)
CUT = [
    ("Mug on the desk. If it's dirty it goes in the dishwasher.", ("study",), "it's dirty", "it goes"),
    ("if the towel's wet it needs hanging on the drying rack", ("box_room",), "the towel's wet", "it needs"),
    ("When the bin is full it gets emptied into the wheelie bin outside.", ("back_kitchen",), "the bin is full",
     "it gets"),
    ("There's a scarf on the coat hook. If it's still there it goes in the storage box.", ("hall",),
     "it's still there", "it goes"),
    ("If the kettle is empty it wants filling at the sink.", ("galley",), "the kettle is empty", "it wants"),
    ("Should the blankets be dirty they go straight in the laundry basket.", ("lounge",), "the blankets be dirty",
     "they go"),
]
#: near misses: (text, rooms, the condition's words, which run on)
WHOLE = [
    ("If the lamp is on it gets hot, so switch it off.", ("study",), "the lamp is on it gets hot"),
    ("If there is a book on it put it on the shelf.", ("study",), "there is a book on it"),
]


def _clauses(text: str, rooms: tuple[str, ...]) -> list[tuple[str, str]]:
    return [(c.role, c.text.strip(" .,")) for c in analyse(brief(text, rooms), CATALOG).clauses]


@pytest.mark.parametrize(("text", "rooms", "condition", "main"), CUT)
def test_the_thing_as_subject_opens_the_main_clause(text: str, rooms: tuple[str, ...], condition: str,
                                                     main: str) -> None:
    got = _clauses(text, rooms)
    assert ("condition", condition) in got, got
    assert any(role != "condition" and said.startswith(main) for role, said in got), got


@pytest.mark.parametrize(("text", "rooms", "condition"), WHOLE)
def test_a_place_or_a_run_on_condition_is_not_cut(text: str, rooms: tuple[str, ...], condition: str) -> None:
    got = _clauses(text, rooms)
    assert any(role == "condition" and said.startswith(condition) for role, said in got), got
