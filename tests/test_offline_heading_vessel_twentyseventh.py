"""An item's heading that names a thing by its contents, then its vessel in the next sentence,
after a subordinator at most ("2. DETERGENT. If the bottle has ended up on the floor", "Shampoo.
When the bottle is empty", "Board game. The box lives on the shelf"), from the twenty-seventh
session (dev 46's boarding house matron's notice): the vessel is the heading's thing, not a second,
plain bottle or box (`naming._Reader.heading_vessel`). A thing's vessel is the word its name ends
in ("milk carton") or the last word of its AI2-THOR type (a laundry detergent is a "SoapBottle",
a board game a "Box": data made by the simulator's authors, `vessel_word`). Rows written here in
other registers before the rule and measured then: 0 of 6 (near misses held); after: 6 of 6.
Near misses: a kind whose vessel is not said ("Plate. The bottle ...") and a heading that is a
whole statement still name the bottle."""

from __future__ import annotations

import pytest
from reading import named

#: (text, rooms, the heading's kind, the vessel's own kind that must not be named)
VESSELS = [
    ('2. DETERGENT. If the bottle has ended up on the floor, put it back on the shelf.', ('laundry_room',), 'laundry_detergent', 'bottle'),
    ("Washing-up liquid. The bottle is by the sink; if it's empty, bin it.", ('kitchen',), 'dish_soap', 'bottle'),
    ('Shampoo. When the bottle is empty, put it in the recycling.', ('bathroom',), 'shampoo', 'bottle'),
    ("Board game. The box lives on the shelf; if it's open, close it.", ('den',), 'board_game', 'cardboard_box'),
    ('Plant mister. If the bottle is empty, fill it at the sink.', ('conservatory',), 'plant_mister', 'bottle'),
    ("- Detergent. Once the bottle is back on the shelf, you're done.", ('utility_room',), 'laundry_detergent', 'bottle'),
]
#: near misses: (text, rooms, a kind that must still be named)
NEAR = [
    ('Milk. The carton is on the counter.', ('kitchen',), 'milk_carton'),
    ('Plate. The bottle is on the table.', ('kitchen',), 'bottle'),
    ('Shampoo is on the shelf. The bottle is on the floor.', ('bathroom',), 'bottle'),
]


@pytest.mark.parametrize(("text", "rooms", "kind", "vessel"), VESSELS)
def test_the_vessel_is_the_headings_thing(text: str, rooms: tuple[str, ...], kind: str, vessel: str) -> None:
    kinds = {category for category, _ in named(text, rooms).values()}
    assert kind in kinds and vessel not in kinds, kinds


@pytest.mark.parametrize(("text", "rooms", "kind"), NEAR)
def test_near_misses_still_name_the_vessel(text: str, rooms: tuple[str, ...], kind: str) -> None:
    assert kind in {category for category, _ in named(text, rooms).values()}
