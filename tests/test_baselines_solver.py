"""Holodeck's DFS grid solver: properties over random rooms and objects."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.baselines.holodeck_solver import (
    EDGE_GAP,
    NEAR_GAP,
    Box,
    FloorItem,
    candidates,
    solve_floor,
    surface_spot,
    wall_spots,
)

sizes = st.tuples(st.floats(0.2, 2.0), st.floats(0.1, 2.0), st.floats(0.2, 2.0))


@st.composite
def rooms(draw: st.DrawFn) -> tuple[float, float, list[FloorItem], list[Box], int]:
    width, depth = draw(st.floats(2.0, 7.0)), draw(st.floats(2.0, 6.0))
    n = draw(st.integers(1, 7))
    items = [FloorItem(f"o{i}", draw(sizes), edge=draw(st.booleans())) for i in range(n)]
    for i, it in enumerate(items[1:], start=1):
        if draw(st.booleans()):
            it.near.append(items[draw(st.integers(0, i - 1))].id)
    door = Box(draw(st.floats(0.5, width - 0.5)), 0.0, 0.9, 1.8)
    return width, depth, items, [door], draw(st.integers(0, 1000))


@settings(max_examples=40, deadline=None)
@given(rooms())
def test_placed_objects_inside_room_without_overlap(case: tuple[float, float, list[FloorItem], list[Box], int]) -> None:
    width, depth, items, obstacles, seed = case
    layout = solve_floor(items, width, depth, obstacles, np.random.default_rng(seed), max_nodes=500)
    assert set(layout.poses) | set(layout.dropped) == {it.id for it in items}
    assert not set(layout.poses) & set(layout.dropped)
    boxes = list(layout.poses.items())
    by_id = {it.id: it for it in items}
    for i, (oid, pose) in enumerate(boxes):
        b = pose.box
        assert b.x - b.fx / 2 >= -1e-6 and b.x + b.fx / 2 <= width + 1e-6
        assert b.z - b.fz / 2 >= -1e-6 and b.z + b.fz / 2 <= depth + 1e-6
        assert not any(b.overlaps(o, 0.0) for o in obstacles)
        assert not any(b.overlaps(other.box, 0.0) for _, other in boxes[i + 1:])
        if by_id[oid].edge:  # flush against some wall
            gaps = [b.x - b.fx / 2, width - b.x - b.fx / 2, b.z - b.fz / 2, depth - b.z - b.fz / 2]
            assert min(gaps) <= EDGE_GAP + 1e-6
        if not layout.relaxed:
            for n in by_id[oid].near:
                if n in layout.poses:
                    assert b.gap(layout.poses[n].box) <= NEAR_GAP + 1e-9


def test_backtracking_finds_the_only_packing() -> None:
    """Two 1 m wide objects in a 2.05 m room fit only side by side: DFS must find it."""
    items = [FloorItem("a", (1.0, 0.5, 1.0)), FloorItem("b", (1.0, 0.5, 1.0))]
    layout = solve_floor(items, 2.1, 1.1, [], np.random.default_rng(0), grid=0.05)
    assert not layout.dropped
    a, b = layout.poses["a"].box, layout.poses["b"].box
    assert not a.overlaps(b, 0.0)


def test_unplaceable_object_is_dropped() -> None:
    layout = solve_floor([FloorItem("huge", (5.0, 1.0, 5.0))], 3.0, 3.0, [], np.random.default_rng(0))
    assert layout.dropped == ["huge"] and not layout.poses


def test_near_is_relaxed_only_when_impossible() -> None:
    items = [FloorItem("a", (0.5, 0.5, 0.5)), FloorItem("b", (0.5, 0.5, 0.5), near=["a"])]
    layout = solve_floor(items, 6.0, 6.0, [], np.random.default_rng(1))
    assert not layout.relaxed and layout.poses["b"].box.gap(layout.poses["a"].box) <= NEAR_GAP


def test_edge_candidates_face_into_room() -> None:
    poses = candidates(FloorItem("sofa", (2.0, 0.8, 0.9), edge=True), 4.0, 3.0, 0.5)
    assert poses and all(p.yaw in (0.0, 90.0, 180.0, 270.0) for p in poses)
    south = [p for p in poses if p.yaw == 0.0]
    assert all(abs(p.box.z - (0.45 + EDGE_GAP)) < 1e-9 for p in south)


def test_surface_spot_and_wall_spots() -> None:
    top = Box(1.0, 1.0, 0.6, 0.4)
    first = surface_spot(top, (0.25, 0.1, 0.3), [])
    assert first is not None
    second = surface_spot(top, (0.25, 0.1, 0.3), [first])
    assert second is not None and not second.overlaps(first, 0.0)
    assert surface_spot(top, (0.25, 0.1, 0.3), [first, second]) is None
    spots = wall_spots(3.0, 3.0, {"n": [(0.0, 3.0)]}, 0.8)
    assert spots and all(w != "n" for w, _ in spots)
