"""A state said after a noun phrase whose modifier opens with "next to", "against", "alongside" or
"opposite" ("If the mug next to the kettle is dirty", "If the mop against the fridge is wet") is
the head's, as after "on", "under" or "over" (`analysis.BESIDE_PREPS` in the state's subject and
`_Reader._pp_at`, "next to" read as one preposition; only right after its head, so a place in an aside further on keeps carrying the state as before: "the lamp in the hall (by the door, next to the coats) is on"), from the thirtieth session (found while
testing the wall cabinet: "the cupboard over the kettle"). Rows written here in other registers
before the rule and measured then: 3 of 6; after: 6 of 6. Near miss: "next" without "to" ("the bin
next week") opens no place."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the state asked, the place's kind that must not be asked)
BESIDE = [
    ("If the mug next to the kettle is dirty, wash it.", ("kitchen",), "state(mug, dirty)", "kettle"),
    ("If the lamp opposite the sofa is on, switch it off.", ("lounge",), "toggled_on", "sofa"),
    ("If the mop against the fridge is wet, hang it up.", ("kitchen",), "state(mop, wet)", "fridge"),
    ("If the towel alongside the sink is wet, hang it on the rail.", ("bathroom",), "state(towel, wet)", "sink"),
    ("Is the cup next to the laptop empty? Fill it at the sink.", ("office",), "state(cup, filled)", "laptop"),
    ("When the fan next to the bed is running, turn it off.", ("bedroom",), "toggled_on", "bed"),
]


@pytest.mark.parametrize(("text", "rooms", "state", "place"), BESIDE)
def test_the_state_after_a_place_modifier_is_the_heads(text: str, rooms: tuple[str, ...], state: str,
                                                        place: str) -> None:
    conditions = set().union(*factors(text, rooms).values())
    assert any(state in c for c in conditions), conditions
    assert not any(f"({place}," in c for c in conditions), conditions


def test_next_without_to_opens_no_place() -> None:
    conditions = set().union(*factors("If the bin is full, empty it; the bin next week goes out on Tuesday.",
                                      ("kitchen",)).values())
    assert any("trash_can" in c or "bin" in c for c in conditions), conditions
