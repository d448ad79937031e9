"""Z3 layout backend: pairwise disjunctions over integer cells, tracked literals as assumptions.

The contract (frames, boxes, relations, orientation convention) is `scene.layout`'s.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import z3

from logicenveval.scene.layout import (
    FAR,
    IN_FRONT_GAP,
    NEAR_AXIS,
    Box,
    FloorRel,
    Obstacle,
    Opening,
    Placed,
    WallBox,
    WallSegment,
    cells,
    opening_rect,
    opening_start,
)
from logicenveval.scene.relax import (
    Check,
    Dropped,
    Status,
    Tracked,
    object_literals,
    relax,
    wall_cap,
)

#: Z3 resource units per second of a room's budget: the median ratio of `rlimit count` to wall
#: time over the checks of a five-task offline run (2.1 M) on the calibrating machine (2 cores,
#: load 5, 2026-11-30), rounded
RLIMIT_PER_SECOND = 2_000_000


class _Guard:
    """One tracked literal per enrichment box; `guard(ids, c)` asserts `c` for when all of `ids` are kept."""

    def __init__(self, s: z3.Solver, boxes: Sequence[Box | WallBox], ctx: z3.Context, prefix: str) -> None:
        self.s = s
        self.lit, self.tracked = object_literals(boxes, lambda name: z3.Bool(name, ctx), prefix)

    def __call__(self, ids: Sequence[str], c: z3.BoolRef) -> None:
        conds = [self.lit[i] for i in ids if i in self.lit]
        self.s.add(z3.Implies(z3.And(*conds), c) if conds else c)


class _Vars:
    def __init__(self, b: Box, tag: str, ctx: z3.Context) -> None:
        self.x = z3.Int(f"x_{tag}", ctx)
        self.z = z3.Int(f"z_{tag}", ctx)
        self.o = z3.Int(f"o_{tag}", ctx)
        odd = z3.Or(self.o == 1, self.o == 3)
        self.wx = z3.If(odd, b.cells[1], b.cells[0])
        self.wz = z3.If(odd, b.cells[0], b.cells[1])
        self.cx2 = 2 * self.x + self.wx
        self.cz2 = 2 * self.z + self.wz

    def disjoint(self, x0: z3.ArithRef | int, z0: z3.ArithRef | int, x1: z3.ArithRef | int,
                 z1: z3.ArithRef | int) -> z3.BoolRef:
        return z3.Or(self.x + self.wx <= x0, x1 <= self.x, self.z + self.wz <= z0, z1 <= self.z)

    def apart(self, v: _Vars) -> z3.BoolRef:
        return self.disjoint(v.x, v.z, v.x + v.wx, v.z + v.wz)


def pack(frame: tuple[int, int], boxes: Sequence[Box], *, seed: int, timeout_s: float,
         obstacles: Sequence[Obstacle] = (), tall: Sequence[tuple[Obstacle, float]] = (),
         walkway: int = 0, rels: Sequence[FloorRel] = (), grid: float = 0.05,
         free_rotation: bool = True, openings: Sequence[Opening] = ()) -> tuple[dict[str, Placed], list[Dropped]]:
    """See `scene.layout.Backend.pack`."""
    W, D = frame
    ctx = z3.Context()  # a fresh context per solve: results do not depend on earlier solves
    s = z3.Solver(ctx=ctx)
    s.set("random_seed", seed)
    s.set("core.minimize", False)
    vs = {b.id: _Vars(b, f"{k}", ctx) for k, b in enumerate(boxes)}
    guard = _Guard(s, boxes, ctx, "obj")
    tracked = guard.tracked

    for b in boxes:
        v = vs[b.id]
        s.add(v.o >= 0, v.o <= (3 if free_rotation else 0), v.x >= 0, v.z >= 0)
        guard([b.id], z3.And(v.x + v.wx <= W, v.z + v.wz <= D))
        for ob in obstacles:
            guard([b.id], v.disjoint(*ob))
        for ob, min_h in tall:
            if b.size[1] > min_h:
                guard([b.id], v.disjoint(*ob))
    for i, a in enumerate(boxes):
        for bb in boxes[i + 1:]:
            guard([a.id, bb.id], vs[a.id].apart(vs[bb.id]))
    ts = [z3.Int(f"op_{k}", ctx) for k in range(len(openings))]
    door_rects: list[tuple[Any, Any, Any, Any]] = []
    for k, (op, t) in enumerate(zip(openings, ts, strict=True)):
        s.add(z3.Or(*[z3.And(t >= lo, t <= hi) for lo, hi in op.starts]))
        rect = opening_rect(op, t, frame)
        for b in boxes:
            if op.sill is None or b.size[1] > op.sill:
                guard([b.id], vs[b.id].disjoint(*rect))
        for later, u in zip(openings[k + 1:], ts[k + 1:], strict=True):
            if later.side == op.side:
                s.add(z3.Or(t + op.width + op.gap <= u, u + later.width + later.gap <= t))
        if op.sill is None:
            for ob in obstacles:
                s.add(_apart(rect, ob))
            for other_rect in door_rects:
                s.add(_apart(rect, other_rect))
            door_rects.append(rect)
    strips: list[tuple[Any, Any, Any, Any]] = []
    if walkway:
        for b in boxes:
            if not b.task:
                continue
            v = vs[b.id]
            A = walkway
            sx0 = z3.If(v.o == 1, v.x + v.wx, z3.If(v.o == 3, v.x - A, v.x))
            sx1 = z3.If(v.o == 1, v.x + v.wx + A, z3.If(v.o == 3, v.x, v.x + v.wx))
            sz0 = z3.If(v.o == 0, v.z + v.wz, z3.If(v.o == 2, v.z - A, v.z))
            sz1 = z3.If(v.o == 0, v.z + v.wz + A, z3.If(v.o == 2, v.z, v.z + v.wz))
            s.add(sx0 >= 0, sz0 >= 0, sx1 <= W, sz1 <= D)
            for other in boxes:
                if other.id != b.id:
                    guard([other.id], vs[other.id].disjoint(sx0, sz0, sx1, sz1))
            # as CP-SAT's extended boxes: clear of solid obstacles, door squares and other strips
            for ob in obstacles:
                if ob[2] > ob[0] and ob[3] > ob[1]:
                    s.add(z3.Or(sx1 <= ob[0], sx0 >= ob[2], sz1 <= ob[1], sz0 >= ob[3]))
            for rect in door_rects:
                s.add(_apart((sx0, sz0, sx1, sz1), rect))
            for tx0, tz0, tx1, tz1 in strips:
                s.add(z3.Or(sx1 <= tx0, tx1 <= sx0, sz1 <= tz0, tz1 <= sz0))
            strips.append((sx0, sz0, sx1, sz1))
    for k, fr in enumerate(rels):
        c = _encode(fr, vs, (W, D), grid)
        if c is None:
            continue
        p = z3.Bool(f"rel_{k}", ctx)
        tracked.append(Tracked(p, "relation", fr.rel.text(), fr.task, tuple(fr.rel.args)))
        guard(fr.args, z3.Implies(p, c))
    ok, dropped = relax(_check(s), tracked, timeout_s)
    if not ok:
        return {}, dropped
    gone = {d.tracked.item for d in dropped if d.tracked.kind == "object"}
    ev = s.model().eval
    out = {op.id: opening_start(op, ev(t).as_long(), frame, grid) for op, t in zip(openings, ts, strict=True)}
    for b in boxes:
        if b.id in gone:
            continue
        v = vs[b.id]
        out[b.id] = Placed(ev(v.x).as_long() * grid, ev(v.z).as_long() * grid, ev(v.o).as_long())
    return out, dropped


def _apart(a: tuple[Any, Any, Any, Any], b: tuple[Any, Any, Any, Any]) -> z3.BoolRef:
    """Two rectangles (x0, z0, x1, z1) of cells do not overlap (touching is fine)."""
    return z3.Or(a[2] <= b[0], b[2] <= a[0], a[3] <= b[1], b[3] <= a[1])


def _check(s: z3.Solver) -> Check:
    """Z3's check under assumptions within a resource limit (`RLIMIT_PER_SECOND` per second of
    budget: deterministic, unlike Z3's `timeout`); the core is read by literal name."""
    def check(active: list[Tracked], budget: float) -> tuple[Status, list[Tracked], float]:
        limit = max(1, int(max(1e-3, budget) * RLIMIT_PER_SECOND))
        s.set("rlimit", limit)  # counted from this check's start
        s.set("timeout", max(1, int(wall_cap(budget) * 1000)))
        before = _rlimit_count(s)
        res = s.check(*[t.lit for t in active])
        used = _rlimit_count(s) - before
        spent = used / RLIMIT_PER_SECOND
        if res == z3.sat:
            return "sat", [], spent
        if res == z3.unsat:
            core = {str(c) for c in s.unsat_core()}
            return "unsat", [t for t in active if str(t.lit) in core], spent
        return ("unknown" if used >= limit else "capped"), [], spent  # both say "canceled"
    return check


def _rlimit_count(s: z3.Solver) -> float:
    """The resource units the solver has counted so far, over all its checks (0 before any)."""
    try:
        return float(s.statistics().get_key_value("rlimit count"))
    except z3.Z3Exception:
        return 0.0


def _abs_le(e: z3.ArithRef, k: int) -> z3.BoolRef:
    return z3.And(e <= k, -e <= k)


def _encode(fr: FloorRel, vs: dict[str, _Vars], frame: tuple[int, int], grid: float) -> z3.BoolRef | None:
    W, D = frame
    t = fr.rel.type
    if t == "edge":
        v = vs[fr.args[0]]
        return z3.Or(z3.And(v.x == 0, v.o == 1), z3.And(v.x + v.wx == W, v.o == 3),
                     z3.And(v.z == 0, v.o == 0), z3.And(v.z + v.wz == D, v.o == 2))
    if t == "center":
        v = vs[fr.args[0]]
        return z3.And(_abs_le(v.cx2 - W, 2), _abs_le(v.cz2 - D, 2))
    a, b = vs[fr.args[0]], vs[fr.args[1]]
    if t == "near":
        n = int(math.floor((NEAR_AXIS - sum(fr.slack)) / grid))
        return z3.And(b.x - (a.x + a.wx) <= n, a.x - (b.x + b.wx) <= n,
                      b.z - (a.z + a.wz) <= n, a.z - (b.z + b.wz) <= n)
    if t == "far":
        f2 = 2 * cells(FAR + sum(fr.slack) + grid, grid)
        dx, dz = a.cx2 - b.cx2, a.cz2 - b.cz2
        return z3.Or(dx >= f2, -dx >= f2, dz >= f2, -dz >= f2)
    if t == "center_aligned":
        return z3.Or(_abs_le(a.cx2 - b.cx2, 1), _abs_le(a.cz2 - b.cz2, 1))
    near = int(math.floor(IN_FRONT_GAP / grid))
    if t in ("in_front_of", "face_to"):
        # `front` lies on the front axis of `back` (centres aligned within half a cell)
        front, back = (a, b) if t == "in_front_of" else (b, a)
        gap = near if t == "in_front_of" else 10**6
        return z3.Or(
            z3.And(back.o == 0, front.z >= back.z + back.wz, front.z - (back.z + back.wz) <= gap,
                   _abs_le(front.cx2 - back.cx2, 1)),
            z3.And(back.o == 2, front.z + front.wz <= back.z, back.z - (front.z + front.wz) <= gap,
                   _abs_le(front.cx2 - back.cx2, 1)),
            z3.And(back.o == 1, front.x >= back.x + back.wx, front.x - (back.x + back.wx) <= gap,
                   _abs_le(front.cz2 - back.cz2, 1)),
            z3.And(back.o == 3, front.x + front.wx <= back.x, back.x - (front.x + front.wx) <= gap,
                   _abs_le(front.cz2 - back.cz2, 1)))
    if t == "side_of":
        along_x = z3.And(z3.Or(z3.And(a.x + a.wx <= b.x, b.x - (a.x + a.wx) <= near),
                               z3.And(a.x >= b.x + b.wx, a.x - (b.x + b.wx) <= near)), _abs_le(a.cz2 - b.cz2, 1))
        along_z = z3.And(z3.Or(z3.And(a.z + a.wz <= b.z, b.z - (a.z + a.wz) <= near),
                               z3.And(a.z >= b.z + b.wz, a.z - (b.z + b.wz) <= near)), _abs_le(a.cx2 - b.cx2, 1))
        return z3.If(z3.Or(b.o == 0, b.o == 2), along_x, along_z)
    return None


def pack_walls(walls: Sequence[WallSegment], boxes: Sequence[WallBox], *,
               seed: int, timeout_s: float) -> tuple[dict[str, tuple[int, int]], list[Dropped]]:
    """See `scene.layout.Backend.pack_walls`."""
    ctx = z3.Context()
    s = z3.Solver(ctx=ctx)
    s.set("random_seed", seed)
    w = {b.id: z3.Int(f"w_{k}", ctx) for k, b in enumerate(boxes)}
    t = {b.id: z3.Int(f"t_{k}", ctx) for k, b in enumerate(boxes)}
    guard = _Guard(s, boxes, ctx, "wobj")
    tracked = guard.tracked

    for b in boxes:
        s.add(w[b.id] >= 0, w[b.id] < len(walls), t[b.id] >= 0)
        for k, (length, blocked) in enumerate(walls):
            cons = [t[b.id] + b.length <= length]
            cons += [z3.Or(t[b.id] + b.length <= lo, t[b.id] >= hi)
                     for lo, hi, bot, top in blocked if bot < b.bottom + b.height and top > b.bottom]
            guard([b.id], z3.Implies(w[b.id] == k, z3.And(*cons)))
    for i, a in enumerate(boxes):
        for c in boxes[i + 1:]:
            guard([a.id, c.id], z3.Or(w[a.id] != w[c.id], t[a.id] + a.length <= t[c.id], t[c.id] + c.length <= t[a.id]))
    ok, dropped = relax(_check(s), tracked, timeout_s)
    if not ok:
        return {}, dropped
    model = s.model()
    gone = {d.tracked.item for d in dropped}
    return ({b.id: (model.eval(w[b.id]).as_long(), model.eval(t[b.id]).as_long())
             for b in boxes if b.id not in gone}, dropped)
