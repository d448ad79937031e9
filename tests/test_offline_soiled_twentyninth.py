"""Soil said to be on a thing ("Has it got marks on it?", "if it's got grease on it", "any mud on
them?", "if there's a mark on it"), from the twenty-ninth session (dev 48's charity shop day book:
"The navy wool coat ... Has it got marks on it? Then it goes in the wash basket"; dev 49's
cheesemaker's make sheet: "My white coat's on the hook ... Has it got whey on it? Laundry basket
then"): the thing is dirty, as "is it dirty?" asks, never a floor stain of its own; water on it
wets it (`analysis._soiled`). The soil is a stain's name in any number ("a mark", "marks") or a
bare noun that names no kind ("whey", "grease"). Rows written here in other registers before the
rule and measured then: 0 of 6; after: 6 of 6. Near misses: a stain on the floor or the carpet is
still a floor stain; a thing's part with its article ("a lid on it") soils nothing; water in a
thing still fills it."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the condition asked)
SOILED = [
    ("The chef's jacket hangs on the hook. Has it got sauce on it? Into the laundry basket with it.", ("pass",),
     "state(jacket, dirty)"),
    ("Towel on the rail - any mud on it? Put it in the laundry basket.", ("changing_room",), "state(towel, dirty)"),
    ("The shirt is on the chair. If it's got grease on it, put it in the washing machine.", ("workshop",),
     "state(shirt, dirty)"),
    ("Check the plate on the table: if there's a mark on it, wash it in the sink.", ("canteen",),
     "state(plate, dirty)"),
    ("Dad's shoes are by the door. If they have mud on them, leave them on the mat outside.", ("porch",),
     "state(shoe, dirty)"),
    ("The mug's on the desk. Coffee on it? Rinse it in the sink.", ("studio",), "state(mug, dirty)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), SOILED)
def test_soil_on_a_thing_asks_whether_it_is_dirty(text: str, rooms: tuple[str, ...], condition: str) -> None:
    got = factors(text, rooms)
    assert any({condition, f"not {condition}"} <= values for values in got.values()), got
    assert not any("floor_stain" in v for values in got.values() for v in values), got


@pytest.mark.parametrize("text", [
    "There's a stain on the carpet. If so, scrub it.",
    "The floor has a stain on it? Then scrub it with the brush.",
])
def test_a_stain_on_the_floor_is_still_a_floor_stain(text: str) -> None:
    got = factors(text, ("hall",))
    assert any("exists(floor_stain)" in values for values in got.values()), got


def test_a_part_with_its_article_soils_nothing() -> None:
    got = factors("The pot is on the stove. Has it got a lid on it? If not, cover it.", ("kitchen",))
    assert not any("dirty" in v for values in got.values() for v in values), got


def test_water_in_a_thing_still_fills_it() -> None:
    got = factors("The kettle is on the counter. Has it got water in it? If not, fill it.", ("kitchen",))
    assert any("state(kettle, filled)" in values for values in got.values()), got


def test_a_thing_lying_on_a_thing_soils_nothing() -> None:
    """"one" stands for a thing (found when "One on the sofa, put it back" was read as its
    existential case)."""
    got = factors("Books. If there is one on the sofa, put it back on the bookshelf.", ("snug",))
    assert not any("dirty" in v for values in got.values() for v in values), got
