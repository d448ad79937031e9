"""A kind's two-word name with its head said by a synonym that names the head's kind outright:
"the wall cupboard" is the wall cabinet, as "cupboard" is a name of the cabinet ("the bedside
cupboard", "the TV cupboard", "the medicine cupboard", "the filing cupboard", "the upper
cupboard"), from the thirtieth session (the sibling kinds development texts lost most on:
cupboards and cabinets; `naming._Reader.head_by_synonym`). Rows written here in other registers
before the rule and measured then: 0 of 6; after: 6 of 6. Near misses: a modifier that makes no
name with the head's kind ("the kitchen cupboard", "the cupboard under the sink") leaves a
cupboard."""

from __future__ import annotations

import pytest
from reading import kinds

#: (text, rooms, the kind named)
BY_SYNONYM = [
    ("Put the glasses back in the wall cupboard and shut it.", ("kitchen",), "wall_cabinet"),
    ("The bedside cupboard: if its door is open, shut it.", ("bedroom",), "nightstand"),
    ("The remote goes in the TV cupboard.", ("lounge",), "tv_stand"),
    ("Plasters are kept in the medicine cupboard.", ("bathroom",), "medicine_cabinet"),
    ("File the letter in the filing cupboard.", ("office",), "filing_cabinet"),
    ("The mugs live in the upper cupboard, left of the window.", ("kitchen",), "wall_cabinet"),
]


@pytest.mark.parametrize(("text", "rooms", "kind"), BY_SYNONYM)
def test_a_name_with_its_head_said_by_a_synonym_names_its_kind(text: str, rooms: tuple[str, ...],
                                                              kind: str) -> None:
    assert kind in kinds(text, rooms)


@pytest.mark.parametrize("text", ["The kitchen cupboard is open; close it.", "Put it in the cupboard under the sink."])
def test_a_modifier_that_makes_no_name_leaves_a_cupboard(text: str) -> None:
    got = kinds(text, ("kitchen",))
    assert "cabinet" in got and "wall_cabinet" not in got, got
