"""Conditions and factors from the ninth development set (`tests/data/reader_dev9/`) and the
eighth set's tasks that still lost a factor (`tests/data/reader_dev8/`): "wound up" for "ended
up", "ain't got" and "we haven't got one", an inverted "should" after its main clause with no
comma, a verb of becoming in the perfect before a state ("has run empty"), a participle clause set
off by a dash, a bare state before a closing aside in brackets, and "if you find it / one" after a
clause that only says the thing was left. Each is tried on the development sentence and on one
written here in another room with other objects."""

from __future__ import annotations

import pytest
from reading import asks as _asks


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev9 laundry_sorting_d9 (a Southern US note)
    ("If that detergent bottle has wound up on the floor, put it back on the shelf.", ("laundry_room",),
     "on(laundry_detergent, floor)"),
    # written here: a hallway, a present tense
    ("If the umbrella winds up on the floor again, stand it back in the umbrella stand.", ("hallway",),
     "on(umbrella, floor)"),
])
def test_wound_up_is_ended_up(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"wind up" is "end up" (`analysis.DESCRIPTIVE`, `SITUATION_PARTICIPLES`): where the thing
    wound up is the situation asked."""
    assert _asks(text, rooms, condition)
