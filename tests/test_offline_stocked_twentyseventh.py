"""Supplies "are stocked in" a place, as a shop or a store room says where they are kept, from the
twenty-seventh session (dev 45's sleeper train card): "stock" joins the verbs of keeping
(`placement.KEEP_VERBS`). Rows written here in other registers before the rule and measured
then: 2 of 6; after: 6 of 6. Near misses: a condition ("if the cabinet is stocked") places nothing,
and "stock the fridge with milk" reads as before."""

from __future__ import annotations

import pytest
from reading import placed

#: (text, rooms, the placement read)
KEPT = [
    ('Spare rolls are stocked in the vanity unit under the basin.', ('bathroom',), 'inside(spare_roll, bathroom_vanity)'),
    ('Spare bulbs are stocked in the hall cupboard.', ('hall',), 'inside(spare_bulb, cabinet)'),
    ('The tins are stocked in the pantry cupboard, top shelf.', ('kitchen',), 'inside(food_can, cabinet)'),
    ('We stock the spare candles in the desk drawer.', ('office',), 'inside(spare_candle, drawer)'),
    ('Spare candles are stocked on the wall shelf above the altar.', ('chapel',), 'on(spare_candle, wall_shelf)'),
    ('The first aid kit is always kept stocked and lives in the cabinet.', ('office',), 'inside(first_aid_kit, cabinet)'),
]

#: near misses: None when nothing is placed
NEAR = [
    ('If the cabinet is stocked, close it.', ('kitchen',), None),
    ('Stock the fridge with milk.', ('kitchen',), 'inside(milk_carton, fridge)'),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), KEPT)
def test_the_place_is_read(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), NEAR)
def test_near_misses_read_as_before(text: str, rooms: tuple[str, ...], fact: str | None) -> None:
    got = placed(text, rooms)
    assert fact in got if fact is not None else not got
