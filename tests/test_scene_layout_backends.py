"""Z3 and CP-SAT layout backends: the same contract, checked against each other and against geometry."""

from __future__ import annotations

import numpy as np
import pytest
import z3
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from ortools.sat.python import cp_model

from logicenveval.domain.catalog import load_catalog
from logicenveval.errors import EnvSpecError
from logicenveval.physics import check_env
from logicenveval.scene import layout_cpsat, layout_z3
from logicenveval.scene.construct import construct_environment
from logicenveval.scene.layout import (
    SOLVERS,
    Box,
    FloorRel,
    Obstacle,
    Opening,
    Placed,
    Solver,
    WallBox,
    backend,
    opening_rect,
)
from logicenveval.scene.spec import ObjectRequest, RelationRequest, RoomRequest, SceneSpec

CAT = load_catalog()
PAIRS = {"near": ("armchair", "sofa"), "far": ("armchair", "sofa"), "center_aligned": ("armchair", "sofa"),
         "in_front_of": ("coffee_table", "sofa"), "face_to": ("armchair", "tv_stand"),
         "side_of": ("side_table", "sofa"), "edge": ("sofa", "armchair"), "center": ("coffee_table", "sofa")}


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("rel", sorted(PAIRS))
def test_each_relation_holds_geometrically(rel: str, solver: Solver) -> None:
    a, b = PAIRS[rel]
    objs = [ObjectRequest(id="a", category=a, room="r", role="a"), ObjectRequest(id="b", category=b, room="r", role="b")]
    args = ("a",) if rel in ("edge", "center") else ("a", "b")
    spec = SceneSpec(task_id="t", env_id="e", rooms=[RoomRequest(id="r", type="LivingRoom", area=30)], objects=objs,
                     relations=[RelationRequest(type=rel, args=args)])  # type: ignore[arg-type]
    res = construct_environment(spec, catalog=CAT, rng=np.random.default_rng(5), solver=solver)
    assert res.relaxation_log == []
    assert [(r.type, r.args) for r in res.env.relations] == [(rel, args)]
    report = check_env(res.env, CAT)
    assert report.relation.passed, [f.message for f in report.relation.failures]
    assert report.entity.passed and report.floor_plan.passed


def test_unknown_backend_names_the_valid_ones() -> None:
    with pytest.raises(EnvSpecError, match="z3, cpsat, auto"):
        backend("gurobi")
    spec = SceneSpec(task_id="t", env_id="e", rooms=[RoomRequest(id="r", type="LivingRoom")], objects=[])
    with pytest.raises(EnvSpecError, match="unknown layout solver 'ortools'"):
        construct_environment(spec, catalog=CAT, rng=np.random.default_rng(0), solver="ortools")  # type: ignore[arg-type]


def _extent(b: Box, p: Placed, grid: float) -> tuple[int, int, int, int]:
    wx, wz = (b.cells[1], b.cells[0]) if p.o % 2 else b.cells
    x, z = round(p.x0 / grid), round(p.z0 / grid)
    return x, z, x + wx, z + wz


def _meet(a: tuple[int, int, int, int], b: Obstacle) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _strip(r: tuple[int, int, int, int], o: int, depth: int) -> tuple[int, int, int, int]:
    x0, z0, x1, z1 = r
    return [(x0, z1, x1, z1 + depth), (x1, z0, x1 + depth, z1), (x0, z0 - depth, x1, z0), (x0 - depth, z0, x0, z1)][o]


rects = st.tuples(st.integers(0, 30), st.integers(0, 30), st.integers(1, 12), st.integers(1, 12)).map(
    lambda t: (t[0], t[1], t[0] + t[2], t[1] + t[3]))


@st.composite
def packings(draw: st.DrawFn) -> tuple[tuple[int, int], list[Box], list[Obstacle], list[tuple[Obstacle, float]], int]:
    frame = (draw(st.integers(8, 36)), draw(st.integers(8, 36)))
    boxes = [Box(f"b{k}", (0.5, draw(st.floats(0.1, 2.0)), 0.5), (draw(st.integers(1, 12)), draw(st.integers(1, 12))),
                 task=draw(st.booleans())) for k in range(draw(st.integers(1, 7)))]
    obstacles = draw(st.lists(rects, max_size=3))
    tall = [(r, draw(st.floats(0.0, 1.5))) for r in draw(st.lists(rects, max_size=2))]
    return frame, boxes, obstacles, tall, draw(st.sampled_from([0, 3]))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(packings(), st.integers(0, 1000))
def test_property_backends_agree_on_feasibility_and_return_valid_packings(
        case: tuple[tuple[int, int], list[Box], list[Obstacle], list[tuple[Obstacle, float]], int], seed: int) -> None:
    frame, boxes, obstacles, tall, walkway = case
    results = {}
    for name in SOLVERS:
        placed, dropped = backend(name).pack(frame, boxes, seed=seed, timeout_s=30.0, obstacles=obstacles, tall=tall,
                                             walkway=walkway, grid=0.05)
        results[name] = placed
        assert all(not d.tracked.task and d.tracked.kind == "object" for d in dropped)
        if not placed:
            continue
        assert {b.id for b in boxes if b.task} <= set(placed)
        kept = [b for b in boxes if b.id in placed]
        ext = {b.id: _extent(b, placed[b.id], 0.05) for b in kept}
        for b in kept:
            r = ext[b.id]
            assert r[0] >= 0 and r[1] >= 0 and r[2] <= frame[0] and r[3] <= frame[1], (name, b, r)
            assert not any(_meet(r, ob) for ob in obstacles), (name, b.id, r)
            assert not any(_meet(r, ob) for ob, h in tall if b.size[1] > h), (name, b.id, r)
            assert not any(_meet(r, ext[c.id]) for c in kept if c.id != b.id), (name, b.id)
            if walkway and b.task:
                s = _strip(r, placed[b.id].o, walkway)
                assert s[0] >= 0 and s[1] >= 0 and s[2] <= frame[0] and s[3] <= frame[1], (name, b.id, s)
                assert not any(_meet(s, ext[c.id]) for c in kept if c.id != b.id), (name, b.id, s)
    if all(b.task for b in boxes):  # no relaxation freedom: both complete solvers must agree
        assert bool(results["z3"]) == bool(results["cpsat"])


@st.composite
def opening_packings(draw: st.DrawFn) -> tuple[tuple[int, int], list[Box], list[Obstacle], list[Opening], int]:
    frame = (draw(st.integers(12, 40)), draw(st.integers(12, 40)))
    boxes = [Box(f"b{k}", (0.5, draw(st.floats(0.1, 2.0)), 0.5), (draw(st.integers(1, 10)), draw(st.integers(1, 10))),
                 task=draw(st.booleans())) for k in range(draw(st.integers(0, 5)))]
    openings = []
    for k in range(draw(st.integers(1, 4))):
        side = draw(st.sampled_from(["s", "n", "w", "e"]))
        length = frame[0] if side in "sn" else frame[1]
        width = draw(st.integers(2, 10))
        lo = draw(st.integers(0, length - width))
        hi = draw(st.integers(lo, length - width))
        door = draw(st.booleans())
        openings.append(Opening(f"op{k}", side, ((lo, hi),), width, width if door else 6,
                                sill=None if door else draw(st.floats(0.2, 1.2))))
    return frame, boxes, draw(st.lists(rects, max_size=2)), openings, draw(st.sampled_from([0, 3]))


def _opening_cells(op: Opening, p: Placed, frame: tuple[int, int]) -> tuple[int, tuple[int, int, int, int]]:
    t = round((p.x0 if op.side in "sn" else p.z0) / 0.05)
    return t, tuple(int(v) for v in opening_rect(op, t, frame))  # type: ignore[return-value]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(opening_packings(), st.integers(0, 1000))
def test_property_backends_place_doors_and_windows_validly_and_agree(
        case: tuple[tuple[int, int], list[Box], list[Obstacle], list[Opening], int], seed: int) -> None:
    """Doors and windows are solver variables (paper §3.3): each lies in its allowed starts on its
    side, keeps the gap to the other openings of that side, a door's clearance is free of every
    box, of the obstacles and of the other doors' clearances, a window's of the boxes taller than
    its sill; both backends agree on feasibility."""
    frame, boxes, obstacles, openings, walkway = case
    results = {}
    for name in SOLVERS:
        placed, _ = backend(name).pack(frame, boxes, seed=seed, timeout_s=30.0, obstacles=obstacles,
                                       walkway=walkway, grid=0.05, openings=openings)
        results[name] = bool(placed)
        if not placed:
            continue
        kept = {b.id: _extent(b, placed[b.id], 0.05) for b in boxes if b.id in placed}
        at = {op.id: _opening_cells(op, placed[op.id], frame) for op in openings}
        for op in openings:
            t, r = at[op.id]
            assert any(lo <= t <= hi for lo, hi in op.starts), (name, op, t)
            assert r[0] >= 0 and r[1] >= 0 and r[2] <= frame[0] and r[3] <= frame[1]
            blocked = [kept[b.id] for b in boxes if b.id in kept and (op.sill is None or b.size[1] > op.sill)]
            assert not any(_meet(r, e) for e in blocked), (name, op.id)
            for other in openings:
                if other.id == op.id:
                    continue
                u, q = at[other.id]
                if other.side == op.side:
                    assert t + op.width + op.gap <= u or u + other.width + other.gap <= t, (name, op, other)
                if op.sill is None and other.sill is None:
                    assert not _meet(r, q), (name, op.id, other.id)
            if op.sill is None:
                assert not any(_meet(r, ob) for ob in obstacles), (name, op.id)
    if all(b.task for b in boxes):
        assert results["z3"] == results["cpsat"]


@st.composite
def wall_cases(draw: st.DrawFn) -> tuple[list[tuple[int, list[tuple[int, int, float, float]]]], list[WallBox]]:
    walls = []
    for _ in range(draw(st.integers(1, 4))):
        length = draw(st.integers(5, 60))
        blocked = [(lo, lo + draw(st.integers(1, 20)), bot, bot + draw(st.floats(0.1, 2.0)))
                   for lo, bot in draw(st.lists(st.tuples(st.integers(-2, 60), st.floats(0.0, 2.0)), max_size=4))]
        walls.append((length, blocked))
    boxes = [WallBox(f"w{k}", draw(st.integers(1, 25)), draw(st.floats(0.3, 1.8)), draw(st.floats(0.1, 1.0)),
                     task=draw(st.booleans())) for k in range(draw(st.integers(1, 5)))]
    return walls, boxes


@settings(max_examples=40, deadline=None)
@given(wall_cases(), st.integers(0, 1000))
def test_property_wall_backends_agree_and_respect_blocked_stretches(
        case: tuple[list[tuple[int, list[tuple[int, int, float, float]]]], list[WallBox]], seed: int) -> None:
    walls, boxes = case
    results = {}
    for name in SOLVERS:
        placed, dropped = backend(name).pack_walls(walls, boxes, seed=seed, timeout_s=30.0)
        results[name] = placed
        assert all(not d.tracked.task for d in dropped)
        for b in boxes:
            if b.id not in placed:
                continue
            k, t = placed[b.id]
            length, blocked = walls[k]
            assert t >= 0 and t + b.length <= length
            for lo, hi, bot, top in blocked:
                if bot < b.bottom + b.height and top > b.bottom:
                    assert t + b.length <= lo or t >= hi, (name, b, (lo, hi))
            for c in boxes:
                if c.id != b.id and c.id in placed and placed[c.id][0] == k:
                    tc = placed[c.id][1]
                    assert t + b.length <= tc or tc + c.length <= t
    if all(b.task for b in boxes):
        assert bool(results["z3"]) == bool(results["cpsat"])


@given(st.integers(0, 40), st.integers(1, 12),
       st.lists(st.tuples(st.integers(-3, 45), st.integers(1, 10)), max_size=5))
def test_property_free_starts_are_exactly_the_clear_positions(length: int, size: int,
                                                              cuts: list[tuple[int, int]]) -> None:
    box = WallBox("w", size, 1.0, 0.5, True)
    blocked = [(lo, lo + w, 0.0, 3.0) for lo, w in cuts]
    free = {t for a, z in layout_cpsat._free_starts(length, box, blocked) for t in range(a, z + 1)}
    brute = {t for t in range(0, length - size + 1)
             if all(t + size <= lo or t >= hi for lo, hi, _, _ in blocked)}
    assert free == brute


FRONT = [(0, 1), (1, 0), (0, -1), (-1, 0)]  # +z after yaw 90*o
SIDE = 80  # cells: 4 m, room for `far`


def _solve_forced(solver: str, rel: str, ref: str, o: int) -> dict[str, tuple[int, int, int, int, int]]:
    """Boxes a, b in an 80x80 frame with `rel`, the orientation of `ref` forced to `o`; (x0, z0, x1, z1, o) each."""
    W = D = SIDE
    boxes = {"a": Box("a", (0.3, 0.5, 0.2), (6, 4), True), "b": Box("b", (0.4, 0.5, 0.2), (8, 4), True)}
    args = ("a",) if rel in ("edge", "center") else ("a", "b")
    fr = FloorRel(RelationRequest(type=rel, args=args), True, args, (0.0,) * len(args))  # type: ignore[arg-type]
    if solver == "z3":
        ctx = z3.Context()
        s = z3.Solver(ctx=ctx)
        zv = {k: layout_z3._Vars(b, k, ctx) for k, b in boxes.items()}
        for v in zv.values():
            s.add(v.o >= 0, v.o <= 3, v.x >= 0, v.z >= 0, v.x + v.wx <= W, v.z + v.wz <= D)
        s.add(zv["a"].apart(zv["b"]), zv[ref].o == o, layout_z3._encode(fr, zv, (W, D), 0.05))
        assert s.check() == z3.sat
        mdl = s.model()
        out = {}
        for k, v in zv.items():
            x, z = mdl.eval(v.x).as_long(), mdl.eval(v.z).as_long()
            out[k] = (x, z, x + mdl.eval(v.wx).as_long(), z + mdl.eval(v.wz).as_long(), mdl.eval(v.o).as_long())
        return out
    m = cp_model.CpModel()
    cv = {k: layout_cpsat._Vars(m, b, k, (W, D), True, None) for k, b in boxes.items()}
    m.add_no_overlap_2d([v.ix for v in cv.values()], [v.iz for v in cv.values()])
    m.add(cv[ref].o[o] == 1)
    layout_cpsat._encode(m, fr, cv, (W, D), 0.05, [])
    solver_ = cp_model.CpSolver()
    solver_.parameters.num_workers = 1
    assert solver_.solve(m) in (cp_model.OPTIMAL, cp_model.FEASIBLE)
    return {k: (solver_.value(v.x), solver_.value(v.z), solver_.value(v.ex), solver_.value(v.ez),
                next(i for i in range(4) if solver_.boolean_value(v.o[i]))) for k, v in cv.items()}


def _on_front_axis(front: tuple[int, int, int, int, int], back: tuple[int, int, int, int, int], max_gap: int) -> bool:
    fx, fz = FRONT[back[4]]
    if fx:  # front axis along x: gap beyond back's front face, centres aligned in z
        gap = front[0] - back[2] if fx > 0 else back[0] - front[2]
        cross = abs((front[1] + front[3]) - (back[1] + back[3]))
    else:
        gap = front[1] - back[3] if fz > 0 else back[1] - front[3]
        cross = abs((front[0] + front[2]) - (back[0] + back[2]))
    return 0 <= gap <= max_gap and cross <= 1


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("rel", ["edge", "center", "near", "far", "center_aligned", "in_front_of", "face_to", "side_of"])
@pytest.mark.parametrize("o", range(4))
def test_every_relation_encoding_means_the_same_in_every_orientation(solver: str, rel: str, o: int) -> None:
    ref = "a" if rel in ("edge", "center", "face_to") else "b"
    p = _solve_forced(solver, rel, ref, o)
    a, b = p["a"], p["b"]
    assert p[ref][4] == o
    near_gap = 19  # IN_FRONT_GAP / grid
    if rel == "edge":
        assert [a[1] == 0, a[0] == 0, a[3] == SIDE, a[2] == SIDE][o]  # back against the wall behind it
    elif rel == "center":
        assert abs(a[0] + a[2] - SIDE) <= 2 and abs(a[1] + a[3] - SIDE) <= 2
    elif rel == "near":
        assert max(b[0] - a[2], a[0] - b[2]) <= 14 and max(b[1] - a[3], a[1] - b[3]) <= 14
    elif rel == "far":
        assert max(abs(a[0] + a[2] - b[0] - b[2]), abs(a[1] + a[3] - b[1] - b[3])) >= 2 * 51  # (FAR + one cell) / grid, doubled centres
    elif rel == "center_aligned":
        assert abs(a[0] + a[2] - b[0] - b[2]) <= 1 or abs(a[1] + a[3] - b[1] - b[3]) <= 1
    elif rel == "in_front_of":
        assert _on_front_axis(a, b, near_gap)
    elif rel == "face_to":
        assert _on_front_axis(b, a, 10**6)
    else:  # side_of: on b's left-right axis, i.e. a front axis of b turned by 90 degrees either way
        assert any(_on_front_axis(a, (*b[:4], (b[4] + t) % 4), near_gap) for t in (1, 3))


@pytest.mark.parametrize(("seed", "n_boxes"), [(0, 18), (1, 18), (2, 18), (0, 4), (1, 7), (2, 11)])
def test_walkways_are_exclusive_in_both_backends(seed: int, n_boxes: int) -> None:
    """On every floor, small or large, a walkway strip is clear of the other boxes, of the other
    strips and of door squares (CP-SAT packs box + strip as one rectangle)."""
    rng = np.random.default_rng(seed)
    frame, walkway = (70, 70), 9
    boxes = [Box(f"b{k}", (0.5, 0.8, 0.5), (int(rng.integers(3, 9)), int(rng.integers(3, 9))), task=k % 3 == 0)
             for k in range(n_boxes)]
    door: Obstacle = (30, 0, 42, 12)
    feasible = {}
    for name in SOLVERS:
        placed, _ = backend(name).pack(frame, boxes, seed=seed, timeout_s=30.0, obstacles=[door],
                                       walkway=walkway, grid=0.05)
        feasible[name] = bool(placed)
        ext = {b.id: _extent(b, placed[b.id], 0.05) for b in boxes if b.id in placed}
        strips = {b.id: _strip(ext[b.id], placed[b.id].o, walkway) for b in boxes if b.task and b.id in placed}
        for bid, s in strips.items():
            assert s[0] >= 0 and s[1] >= 0 and s[2] <= frame[0] and s[3] <= frame[1], (name, bid)
            assert not _meet(s, door), (name, bid)
            assert not any(_meet(s, r) for c, r in ext.items() if c != bid), (name, bid)
            assert not any(_meet(s, t) for c, t in strips.items() if c != bid), (name, bid)
    assert feasible == {name: True for name in SOLVERS}


@pytest.mark.parametrize(("seed", "n_boxes"), [(0, 18), (1, 18), (0, 5)])
def test_exclusive_walkways_keep_clear_of_doors_the_solver_places(seed: int, n_boxes: int) -> None:
    """As above with the door a solver variable on the south side: its square is also kept clear."""
    rng = np.random.default_rng(seed)
    frame, walkway = (70, 70), 9
    boxes = [Box(f"b{k}", (0.5, 0.8, 0.5), (int(rng.integers(3, 9)), int(rng.integers(3, 9))), task=k % 3 == 0)
             for k in range(n_boxes)]
    door = Opening("d0", "s", ((3, 55),), 12, 12)
    for name in SOLVERS:
        placed, _ = backend(name).pack(frame, boxes, seed=seed, timeout_s=30.0, walkway=walkway, grid=0.05,
                                       openings=[door])
        assert placed, name
        _, square = _opening_cells(door, placed["d0"], frame)
        ext = {b.id: _extent(b, placed[b.id], 0.05) for b in boxes if b.id in placed}
        for b in boxes:
            if b.task and b.id in placed:
                assert not _meet(_strip(ext[b.id], placed[b.id].o, walkway), square), (name, b.id)
            if b.id in placed:
                assert not _meet(ext[b.id], square), (name, b.id)


def test_two_task_objects_on_a_small_floor_do_not_share_a_walkway() -> None:
    """A floor exactly two boxes and one walkway deep: the boxes could face each other across one
    shared strip (what floors under 16 boxes allowed before issue 38); with exclusive strips both
    cannot be placed, so neither backend finds a layout."""
    boxes = [Box(f"t{k}", (0.5, 0.8, 0.5), (10, 10), task=True) for k in range(2)]
    for name in SOLVERS:
        placed, _ = backend(name).pack((10, 29), boxes, seed=0, timeout_s=30.0, walkway=9, grid=0.05)
        assert placed == {}, name
        roomier, _ = backend(name).pack((10, 38), boxes, seed=0, timeout_s=30.0, walkway=9, grid=0.05)
        assert set(roomier) == {"t0", "t1"}, name


def _valid_packing(frame: tuple[int, int], boxes: list[Box], placed: dict[str, Placed], obstacles: list[Obstacle],
                   walkway: int) -> None:
    """Every kept box in the frame, clear of the obstacles and the other boxes; exclusive walkway strips."""
    assert {b.id for b in boxes if b.task} <= set(placed)
    ext = {b.id: _extent(b, placed[b.id], 0.05) for b in boxes if b.id in placed}
    strips = {b.id: _strip(ext[b.id], placed[b.id].o, walkway) for b in boxes if b.task and b.id in placed}
    for bid, r in ext.items():
        assert r[0] >= 0 and r[1] >= 0 and r[2] <= frame[0] and r[3] <= frame[1], (bid, r)
        assert not any(_meet(r, ob) for ob in obstacles), bid
        assert not any(_meet(r, o) for c, o in ext.items() if c != bid), bid
    for bid, s in strips.items():
        assert s[0] >= 0 and s[1] >= 0 and s[2] <= frame[0] and s[3] <= frame[1], bid
        assert not any(_meet(s, ob) for ob in obstacles), bid
        assert not any(_meet(s, r) for c, r in ext.items() if c != bid), bid
        assert not any(_meet(s, t) for c, t in strips.items() if c != bid), bid


@st.composite
def large_floors(draw: st.DrawFn) -> tuple[tuple[int, int], list[Box], list[Obstacle]]:
    from logicenveval.scene.layout import STRONG_NO_OVERLAP_FROM

    frame = (draw(st.integers(60, 90)), draw(st.integers(60, 90)))
    n = draw(st.integers(STRONG_NO_OVERLAP_FROM, STRONG_NO_OVERLAP_FROM + 8))
    all_task = draw(st.booleans())
    boxes = [Box(f"b{k}", (0.5, 0.8, 0.5), (draw(st.integers(2, 12)), draw(st.integers(2, 12))),
                 task=all_task or draw(st.booleans())) for k in range(n)]
    return frame, boxes, draw(st.lists(rects, max_size=3))


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(large_floors(), st.integers(0, 1000))
def test_property_large_floors_with_strong_no_overlap_reasoning_are_valid_and_agree_with_the_weak_one(
        case: tuple[tuple[int, int], list[Box], list[Obstacle]], seed: int) -> None:
    """The stronger NoOverlap2D propagation of large CP-SAT packings only prunes: every packing it
    returns is valid, and with only task boxes (nothing to relax) it finds one iff the default
    propagation does."""
    frame, boxes, obstacles = case
    placed, dropped = layout_cpsat.pack(frame, boxes, seed=seed, timeout_s=30.0, obstacles=obstacles, walkway=5)
    assert all(not d.tracked.task for d in dropped)
    if placed:
        _valid_packing(frame, boxes, placed, obstacles, 5)
    if all(b.task for b in boxes):
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(layout_cpsat, "STRONG_NO_OVERLAP_FROM", 10**6)
            weak, _ = layout_cpsat.pack(frame, boxes, seed=seed, timeout_s=30.0, obstacles=obstacles, walkway=5)
        assert bool(placed) == bool(weak)
        if weak:
            _valid_packing(frame, boxes, weak, obstacles, 5)


def test_strong_reasoning_is_switched_on_from_the_threshold(monkeypatch: pytest.MonkeyPatch) -> None:
    from logicenveval.scene.layout import STRONG_NO_OVERLAP_FROM

    seen: list[bool] = []
    real = layout_cpsat._Solve.__init__

    def spy(self: layout_cpsat._Solve, m: cp_model.CpModel, seed: int, strong: bool = False) -> None:
        seen.append(strong)
        real(self, m, seed, strong)

    monkeypatch.setattr(layout_cpsat._Solve, "__init__", spy)
    for n in (STRONG_NO_OVERLAP_FROM - 1, STRONG_NO_OVERLAP_FROM):
        boxes = [Box(f"b{k}", (0.2, 0.2, 0.2), (2, 2), True) for k in range(n)]
        placed, _ = layout_cpsat.pack((40, 40), boxes, seed=0, timeout_s=10.0)
        assert len(placed) == n
    assert seen == [False, True]


def test_auto_sends_every_packing_to_cpsat_as_measured() -> None:
    """Re-measured on an idle machine (layout_auto's docstring): Z3 slower on every floor size
    and fill, the small sparse floors it once won included, and on every other sub-problem."""
    from logicenveval.scene import layout_auto

    def boxes(n: int, side: int) -> list[Box]:
        return [Box(f"b{k}", (0.5, 0.5, 0.5), (side, side), True) for k in range(n)]

    frame = (100, 100)  # 10 000 cells
    for n, side, walkway in ((4, 10, 9), (7, 10, 9), (3, 10, 9), (8, 10, 9), (5, 20, 9), (5, 10, 0)):
        assert layout_auto.choose(frame, boxes(n, side), walkway=walkway) == "cpsat"


def test_auto_returns_what_cpsat_returns(monkeypatch: pytest.MonkeyPatch) -> None:
    from logicenveval.scene import layout_auto

    boxes = [Box(f"b{k}", (0.5, 0.5, 0.5), (10, 10), k % 2 == 0) for k in range(5)]
    calls: list[str] = []
    for name, mod in (("z3", layout_z3), ("cpsat", layout_cpsat)):
        real = mod.pack

        def spy(*a: object, _real: object = real, _name: str = name, **kw: object) -> object:
            calls.append(_name)
            return _real(*a, **kw)  # type: ignore[operator]

        monkeypatch.setattr(mod, "pack", spy)
    sparse = layout_auto.pack((100, 100), boxes, seed=3, timeout_s=10.0, walkway=9)
    assert calls == ["cpsat"]
    assert sparse == layout_cpsat.pack((100, 100), boxes, seed=3, timeout_s=10.0, walkway=9)
    walls = [(60, [])]
    wall_boxes = [WallBox("w", 10, 1.0, 0.5, True)]
    assert layout_auto.pack_walls(walls, wall_boxes, seed=1, timeout_s=5.0) == \
        layout_cpsat.pack_walls(walls, wall_boxes, seed=1, timeout_s=5.0)


@pytest.mark.parametrize("seed", [0, 1])
def test_cpsat_models_skip_the_camelcase_aliases_and_solve_the_same(seed: int,
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """The layout models are built without `CpModel`'s per-instance camelCase aliases (their cost
    exceeded the model's own), and that changes no packing: the same floor and walls packed with
    plain `CpModel`s give the same placements and drops."""
    models: list[cp_model.CpModel] = []
    init = layout_cpsat._Solve.__init__

    def spy(self: layout_cpsat._Solve, m: cp_model.CpModel, *args: object, **kwargs: object) -> None:
        models.append(m)
        init(self, m, *args, **kwargs)  # type: ignore[arg-type]

    rng = np.random.default_rng(seed)
    boxes = [Box(f"b{k}", (0.5, 0.8, 0.5), (int(rng.integers(3, 9)), int(rng.integers(3, 9))), task=k % 2 == 0)
             for k in range(9)]
    rels = [FloorRel(RelationRequest(type="near", args=("b0", "b1")), True, ("b0", "b1"), (0.0, 0.0))]
    walls = [(40, [(5, 12, 0.0, 2.1)]), (25, [])]
    wboxes = [WallBox(f"w{k}", 6 + k, 1.0, 0.5, task=k == 0) for k in range(4)]

    def both() -> tuple[object, object]:
        return (layout_cpsat.pack((30, 30), boxes, seed=seed, timeout_s=30.0, walkway=4, rels=rels,
                                  obstacles=[(10, 0, 16, 6)]),
                layout_cpsat.pack_walls(walls, wboxes, seed=seed, timeout_s=30.0))

    monkeypatch.setattr(layout_cpsat._Solve, "__init__", spy)
    fast = both()
    assert len(models) == 2 and all("NewIntVar" not in vars(m) for m in models)
    monkeypatch.setattr(layout_cpsat, "_Model", cp_model.CpModel)
    assert both() == fast
