"""A heading over a list of its own is no quality of the thing last spoken of (issue 47,
thirteenth session): "Included: all walking between rooms. Not included: meals" after an
instruction about a backpack made a factor `attr(backpack, includedness, included)` that decided
nothing and made every environment ill-formed (a key no task reads). A heading answered by a
case of the thing ("Ripe: fridge. Not ripe yet: fruit bowl") stays a quality. Texts written here
in several registers (a tour itinerary, a gym's price list, a recipe card, a chat)."""

from __future__ import annotations

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.analysis import analyse


def _factors(text: str, roles: dict[str, str], rooms: list[str]) -> dict[str, dict[str, str]]:
    brief = {"id": "t", "description": text, "rooms": rooms,
             "roles": {name: {"category": kind} for name, kind in roles.items()}}
    return {f.id: f.values for f in analyse(brief, load_catalog()).factors}


@pytest.mark.parametrize("text, roles, rooms", [
    # a tour itinerary
    ("Stop 3: the umbrella stand. If the umbrella is on the floor, put it in the stand.\n\n"
     "Included: all transfers and a packed lunch. Not included: tips, drinks.",
     {"umbrella": "umbrella", "stand": "umbrella_stand"}, ["hallway"]),
    # a gym's price list under an instruction
    ("Before you leave, if the towel is on the bench, drop it in the laundry basket.\n"
     "Refundable: the locker deposit. Non-refundable: the joining fee, classes.",
     {"towel": "towel", "laundry_basket": "laundry_basket", "bench": "bench"}, ["laundry_room"]),
    # a swimming pool's changing-room notice
    ("Last job: if the towel is on the bench, drop it in the laundry basket.\n\n"
     "Provided: soap and shampoo. Not provided: flip-flops, padlocks.",
     {"towel": "towel", "laundry_basket": "laundry_basket", "bench": "bench"}, ["laundry_room"]),
    # a recipe card
    ("If the bowl is dirty, wash it in the sink. Optional: a pinch of smoked paprika. Essential: patience.",
     {"bowl": "bowl", "sink": "sink"}, ["kitchen"]),
])
def test_a_list_heading_is_no_quality_of_the_last_thing(text: str, roles: dict[str, str], rooms: list[str]) -> None:
    factors = _factors(text, roles, rooms)
    assert not any("attr(" in v for values in factors.values() for v in values.values()), factors
    assert factors  # the instruction's own condition is still read


@pytest.mark.parametrize("text, roles, rooms, key", [
    # a chat: the headings answer with a place
    ("Tomato on the counter? Ripe: into the fridge. Not ripe yet: into the fruit bowl.",
     {"tomato": "tomato", "counter": "kitchen_counter", "fridge": "fridge", "fruit_bowl": "fruit_bowl"},
     ["kitchen"], "ripeness"),
    # a kitchen whiteboard: the headings answer with an instruction
    ("Tomato on the counter. Ripe: put it in the fridge. Unripe: put it in the fruit bowl.",
     {"tomato": "tomato", "counter": "kitchen_counter", "fridge": "fridge", "fruit_bowl": "fruit_bowl"},
     ["kitchen"], "ripeness"),
    # a pottery studio's note
    ("The clay pot on the shelf. Glazed: put it in the cabinet. Not glazed: leave it on the shelf.",
     {"pot": "pot", "shelf": "shelf", "cabinet": "cabinet"}, ["garage"], "glazedness"),
])
def test_a_heading_answered_by_a_case_of_the_thing_stays_a_quality(text: str, roles: dict[str, str],
                                                                   rooms: list[str], key: str) -> None:
    factors = _factors(text, roles, rooms)
    assert any(f", {key}, " in v for values in factors.values() for v in values.values()), factors
