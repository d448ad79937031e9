"""A word that names a part of a holder before "of" ("on the front of the desk") is a modifier right
before the holder's name, telling which side of a room or a row it is: "The iPad lives on the front
desk", "on the back counter", "in the right drawer" place the thing on or in that holder
(`placement.SIDE_MODIFIERS`, `_modified_holder`). Before, the phrase placed nothing and a plain
home was asked as a yes/no factor. From the thirty-first session (a youth hostel's reception
note in development set 55: "Check-in iPad - it lives on the front desk" left the iPad unplaced, so
the layout put it on the drying rack and every environment broke the task's constraint). Rows
written here in other registers before the rule and measured then: 1 of 6; after: 6 of 6. Near
misses: "the side table" stays its own kind, and "on the front of the desk" still places on the
desk."""

from __future__ import annotations

import pytest
from reading import factors, placed

#: (text, rooms, the placement)
SIDES = [
    ("The iPad lives on the front desk.", ("reception",), "on(tablet, desk)"),
    ("The kettle lives on the back counter.", ("kitchen",), "on(kettle, kitchen_counter)"),
    ("Our toaster sits on the left counter.", ("kitchen",), "on(toaster, kitchen_counter)"),
    ("The first aid kit is kept in the middle drawer.", ("office",), "inside(first_aid_kit, drawer)"),
    ("The laptop stays on the corner desk.", ("study",), "on(laptop, desk)"),
    ("Keys are kept in the right drawer.", ("hall",), "inside(keys, drawer)"),
]

NEAR = [
    ("The lamp is on the side table.", ("lounge",), "on(table_lamp, side_table)"),
    ("The mug is on the front of the desk.", ("study",), "on(mug, desk)"),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), SIDES)
def test_a_side_modifier_places_on_the_holder(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)
    assert fact not in set().union(set(), *factors(text, rooms).values())


@pytest.mark.parametrize(("text", "rooms", "fact"), NEAR)
def test_a_kind_or_a_part_reads_as_before(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)
