"""A head word several kinds share is read as the kind that can stand where its own phrase puts it,
from the twenty-fifth session: "The lamp lives on the shelf" is a desk or table lamp (the catalog
stands those on a surface), never the floor lamp or ceiling lamp the reader named before; "a clock
on the shelf" an alarm clock, no wall clock; "the dryer sits on the shelf" a hair dryer, no
tumble dryer. The reader already read "on the floor" so ("the bowl on the floor": a pet's bowl);
`naming._Reader.stood_on` now gives the support too, when the catalog gives it a top
(`Category.surface`), and reads the verb of standing as written ("lives", whose singular noun
"life" the lemmatised words hold, so "lives on the floor" was missed too). Found on dev 40's signal
box (its hand lamp "lives on the shelf" was named a ceiling lamp); the rows were written here in
other registers (a handover line, a dash list, a notice, a note) before the rule and measured then
(the counts in each test's docstring)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from reading import named

CATALOG = json.loads((Path(__file__).resolve().parents[1] / "benchmark_data" / "catalog.json").read_text())["categories"]

#: (text, rooms, the head word the kind is named by)
ON_A_SURFACE = [
    ("The lamp lives on the shelf. Still lit? Switch it off.", ("signal_box",), "lamp"),
    ("Old lamp on the bookshelf - if it's on, switch it off.", ("workshop",), "lamp"),
    ("There's a clock on the shelf; if it's ringing, silence it.", ("garage",), "clock"),
    ("The dryer sits on the shelf by the mirror. If it's on, switch it off.", ("changing_room",), "dryer"),
    ("A can is on the shelf in the shed - if it is open, tip it out in the sink.", ("shed",), "can"),
    # read before the rule too
    ("The board is on the counter. If it's dirty, wash it in the sink.", ("galley",), "board"),
    ("The rack stands on the counter by the sink. If it's full, empty it.", ("galley",), "rack"),
]


def _kinds_named_by(text: str, rooms: tuple[str, ...], word: str) -> list[str]:
    return [kind for kind, _ in named(text, rooms).values()
            if word in " ".join([kind.replace("_", " "), *CATALOG[kind].get("synonyms", [])]).split()]


@pytest.mark.parametrize(("text", "rooms", "word"), ON_A_SURFACE)
def test_a_thing_on_a_surface_is_a_kind_that_stands_on_one(text: str, rooms: tuple[str, ...], word: str) -> None:
    """Measured before the rule: 2 of 7; after: 7 of 7."""
    kinds = _kinds_named_by(text, rooms, word)
    assert kinds and all("surface" in CATALOG[k]["placement"] for k in kinds), kinds


@pytest.mark.parametrize(("text", "rooms", "kind"), [
    ("The lamp lives on the floor by the sofa; if it's on, switch it off.", ("living_room",), "floor_lamp"),
    # near misses, the same before and after: the floor, a wall, a ceiling
    ("The bowl on the floor by the door is empty; fill it.", ("hallway",), "pet_bowl"),
    ("The dryer is on the floor by the washing machine; if it's running, stop it.", ("laundry_room",), "dryer"),
    ("The clock on the wall is wrong.", ("kitchen",), "wall_clock"),
    ("The lamp on the ceiling is on; switch it off.", ("hallway",), "ceiling_lamp"),
])
def test_the_floor_wall_and_ceiling_keep_their_kinds(text: str, rooms: tuple[str, ...], kind: str) -> None:
    """The first row was a table lamp before the rule ("lives" unread); the others are as before."""
    assert kind in named(text, rooms)
