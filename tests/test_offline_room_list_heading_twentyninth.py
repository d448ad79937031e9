"""A room heading before a list of the things it holds ("In the kitchen - the rubbish bin, the
recycling bin and the fridge. In the living room - her sofa and the coffee table."), from the
twenty-ninth session (dev 50's good neighbours visit card): it says where the listed things are,
as a place heading does, and asks nothing of the thing named before it (the recycling bin was
asked to be in the living room) (`analysis._room_list_heading`). Rows written here in other
registers before the rule and measured then: 0 of 6; after: 6 of 6. Near misses: a room heading
before an instruction or a condition still reads as before."""

from __future__ import annotations

import pytest
from reading import factors, placed

#: (text, rooms, the thing named before the heading, a placement the list states)
LISTS = [
    ("In the kitchen - the kettle, the toaster and the fridge. In the lounge - his sofa and the TV.",
     ("kitchen", "lounge"), "toaster", "in_room(sofa, lounge)"),
    ("Where it is: in the study - the desk, the lamp and the bookshelf. In the hall - her coat rack and the "
     "shoe rack.", ("study", "hall"), "desk_lamp", "in_room(shoe_rack, hall)"),
    ("Upstairs, the bed, the wardrobe and the dresser. In the bathroom - our hamper and the mirror.",
     ("bedroom", "bathroom"), "bed", "in_room(mirror, bathroom)"),
    ("In the cabin - the bunk, the chair and the lamp. In the galley - the stove and the kettle.",
     ("cabin", "galley"), "chair", "in_room(stove, galley)"),
    ("Garden room: the armchair. In the conservatory - the plant and the watering can.",
     ("garden_room", "conservatory"), "armchair", "in_room(watering_can, conservatory)"),
    ("In the office - the printer, the desk and the chair. In the kitchenette - my kettle and the fridge.",
     ("office", "kitchenette"), "desk", "in_room(fridge, kitchenette)"),
]


@pytest.mark.parametrize(("text", "rooms", "before", "fact"), LISTS)
def test_a_room_heading_before_a_list_asks_nothing_of_the_thing_before(
        text: str, rooms: tuple[str, ...], before: str, fact: str) -> None:
    got = factors(text, rooms)
    assert not any(f"in_room({before}" in v for values in got.values() for v in values), got
    assert fact in placed(text, rooms), placed(text, rooms)


def test_a_room_heading_before_a_condition_reads_as_before() -> None:
    got = factors("The mug is on the desk. In the kitchen: if it's dirty, wash it.", ("study", "kitchen"))
    assert set(got) == {"mug_dirty"}, got
