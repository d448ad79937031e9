"""A participle of finding or leaving fronted before its main clause ("Found on the floor, it goes
back on its hook", "Left on the desk, it goes in the sink", "Found dirty, ...") is the case the main
clause acts in, as "if found on the floor, ..." is (`sentences._FRONTED_FINDING`, then
`_ELIDED_SUBJECT`). From the thirty-first session (a stained glass class card in development set
54: "Found on the floor, it goes back on its hook under the cupboard; anywhere else, leave it").
Rows written here in other registers before the rule and measured then: 0 of 6; after: 4 of 6
(left: a subject said only in the main clause, "Spotted on the sofa, the remote goes ...", and a
quantified heading, "Any toy.", which the pronoun does not take up: "Any toy. If discovered in the
bath, ..." reads nothing either). Near miss: "Found it!" with
no place asks nothing."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the condition asked)
FRONTED = [
    ("The dustpan. Found on the floor, it goes back on its hook.", ("studio",), "on(dustpan, floor)"),
    ("The mug. Left on the desk, it goes in the sink.", ("office",), "on(mug, desk)"),
    ("Wet towels: found on the floor, they go in the basket.", ("bathroom",), "on(towel, floor)"),
    pytest.param("Spotted on the sofa, the remote goes back on the stand.", ("lounge",), "on(remote_control, sofa)",
                 marks=pytest.mark.xfail(strict=True, reason="subject said only in the main clause")),
    ("Found dirty, the cup goes in the sink.", ("kitchen",), "state(cup, dirty)"),
    pytest.param("Any toy. Discovered in the bath, it goes in the toy box.", ("bathroom",), "toy",
                 marks=pytest.mark.xfail(strict=True, reason="'Any toy.' heading not taken up by 'it'")),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), FRONTED)
def test_a_fronted_finding_is_a_case(text: str, rooms: tuple[str, ...], condition: str) -> None:
    asked = set().union(set(), *factors(text, rooms).values())
    assert condition in asked or "(" not in condition and any(condition in c for c in asked)


def test_found_it_asks_nothing() -> None:
    assert factors("Found it! The remote was on the sofa all along.", ("lounge",)) == {}


def test_a_participle_describing_where_a_thing_is_stays_a_statement() -> None:
    """"Left on the counter, by the kettle, as usual." has no main clause after its comma: it says
    where the mug is (a first form of the rule read it as a case and broke a development task)."""
    text = "Your mug. Left on the counter, by the kettle, as usual. If it's dirty, wash it."
    assert "on(mug, kitchen_counter)" not in set().union(set(), *factors(text, ("kitchen",)).values())
