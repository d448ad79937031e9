"""Room geometry and the offline models' guessed coordinates (no solver)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from logicenveval.baselines.geometry import layout_rooms, room_dims
from logicenveval.domain.catalog import Catalog
from logicenveval.offline.analysis import Factor
from logicenveval.offline.baseline_answers import (
    door_stretches,
    flat_situations,
    written_floor_plan,
)
from logicenveval.scene.guessed_layout import footprint, guess_coordinates, typical_size

CAT = Catalog.model_validate({"categories": {
    "sofa": {"size_min": [2.0, 0.8, 0.9], "size_max": [2.0, 0.8, 0.9], "placement": ["floor"], "surface": True},
    "table": {"size_min": [1.0, 0.5, 0.6], "size_max": [1.0, 0.5, 0.6], "placement": ["floor"], "surface": True},
    "book": {"size_min": [0.2, 0.04, 0.3], "size_max": [0.2, 0.04, 0.3], "placement": ["surface"], "pickable": True},
    "toy": {"size_min": [0.2, 0.2, 0.2], "size_max": [0.2, 0.2, 0.2], "placement": ["floor"], "pickable": True},
    "clock": {"size_min": [0.3, 0.3, 0.05], "size_max": [0.3, 0.3, 0.05], "placement": ["wall"]},
}})


@given(st.floats(3.0, 80.0))
def test_room_dims_keep_the_area(area: float) -> None:
    w, d = room_dims(area)
    assert w * d == pytest.approx(area, rel=0.08)


def test_rooms_side_by_side() -> None:
    a, b = layout_rooms([("a", 20.0), ("b", 10.0)])
    assert a.x0 == 0.0 and b.x0 == pytest.approx(a.width)
    assert typical_size("unknown", CAT) == (0.4, 0.4, 0.4)
    assert footprint((2.0, 1.0, 0.5), 90.0) == (0.5, 2.0)


def test_guessed_coordinates() -> None:
    objects = [
        {"id": "sofa", "category": "sofa", "room": "r", "placement": "floor"},
        {"id": "table", "category": "table", "room": "r", "placement": "floor"},
        {"id": "book", "category": "book", "room": "r", "placement": "on:table"},
        {"id": "toy", "category": "toy", "room": "r", "placement": "floor"},
        {"id": "clock", "category": "clock", "room": "r", "placement": "wall"},
    ]
    doors = {"r": {"s": [(0.0, 1.5)]}}
    placed = {o["id"]: o for o in guess_coordinates(objects, {"r": (5.0, 4.0)}, CAT, doors=doors)}
    sofa, table, book = placed["sofa"], placed["table"], placed["book"]
    assert sofa["position"][0] - 1.0 >= 1.5  # the door stretch of the south wall is skipped
    assert sofa["position"][1] == pytest.approx(0.4) and sofa["position"][2] == pytest.approx(0.45 + 0.05)
    assert book["position"][1] - 0.02 == pytest.approx(table["position"][1] + 0.25)
    assert placed["toy"]["position"][2] == pytest.approx(2.0)
    assert placed["clock"]["position"][1] == pytest.approx(1.5)


def test_sampled_wall_gap_is_seeded() -> None:
    objects = [{"id": "sofa", "category": "sofa", "room": "r", "placement": "floor"}]
    one = guess_coordinates(objects, {"r": (5.0, 4.0)}, CAT, rng=np.random.default_rng(3), wall_gap=0.5)
    two = guess_coordinates(objects, {"r": (5.0, 4.0)}, CAT, rng=np.random.default_rng(3), wall_gap=0.5)
    assert one == two and 0.45 <= one[0]["position"][2] <= 0.95


def test_door_stretches_of_the_written_floor_plan() -> None:
    spans = door_stretches(written_floor_plan({"rooms": ["hallway", "kitchen"]}))
    assert "s" in spans["hallway"] and "e" in spans["hallway"] and "w" in spans["kitchen"]
    assert spans["hallway"]["s"] == [pytest.approx((1.25 - 0.9, 2.15 + 0.9))]  # the entrance and its swing


def test_flat_situations_vary_one_factor_at_a_time() -> None:
    f1 = Factor("a", "x", "A?", {"yes": "on(x, floor)", "no": "not on(x, floor)"}, "location", 0)
    f2 = Factor("b", "y", "B?", {"doll": "attr(y, kind, doll)", "other": "not attr(y, kind, doll)"}, "attr", 1)
    situations = [facts for _, facts in flat_situations([f1, f2])]
    assert situations == [["on(x, floor)", "attr(y, kind, doll)"], ["not on(x, floor)", "attr(y, kind, doll)"],
                          ["on(x, floor)", "not attr(y, kind, doll)"]]
