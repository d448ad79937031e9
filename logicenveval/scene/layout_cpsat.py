"""OR-Tools CP-SAT layout backend: the same contract as `layout_z3`, with CP-SAT's global constraints.

Non-overlap is one `NoOverlap2D` over (optional) interval variables instead of pairwise
disjunctions: an enrichment object's interval is present iff its tracked literal is, a rotation
changes an interval's size through a single `odd` literal. Each task object is packed together with
its walkway strip as one rectangle whose corner is linear in the four orientation literals, so the
strip keeps clear of every other box, strip and door square in the floor's `NoOverlap2D`. Relations are reified on the tracked literal (and those of their enrichment objects).
Relaxation uses assumptions and `sufficient_assumptions_for_infeasibility` as the core. One worker
and the run's seed keep the search deterministic. Large packings (`STRONG_NO_OVERLAP_FROM` boxes)
switch on NoOverlap2D timetabling and try-edge reasoning: the weak default propagation was where
a dense 40-box floor spent its time (two full searches of ~0.6-1.4 s each).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from ortools.sat.python import cp_model

from logicenveval.errors import LogicEnvEvalError
from logicenveval.scene.layout import (
    FAR,
    FLOOR_RELATIONS,
    IN_FRONT_GAP,
    NEAR_AXIS,
    STRONG_NO_OVERLAP_FROM,
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
from logicenveval.scene.relax import Dropped, Status, Tracked, object_literals, relax, wall_cap

Lit = Any  # a CP-SAT Boolean literal (IntVar or its negation)

#: CP-SAT deterministic time per second of a room's budget: the median ratio of deterministic to
#: wall time over the layout solves of a 25-task offline run (0.19) on the calibrating machine
#: (2 cores, load 5, 2026-11-30), rounded; a budget is so much deterministic work on any machine
DET_PER_SECOND = 0.2


class _Model(cp_model.CpModel):
    """A CP-SAT model without the camelCase aliases `CpModel` binds to every new instance: this
    module never calls them, and binding them (~60 bound methods, each a reference cycle back to
    the model) cost more than building the layout model itself (measured: 0.6 of 3.2 s layout
    over the 25 tasks, docs/scene.md). The model proto, hence every solve, is unchanged."""

    def _add_pre_pep8_methods(self) -> None:
        return None


class _Solve:
    """The relaxation `Check` for one model; keeps the last solver to read the solution from.

    CP-SAT's `sufficient_assumptions_for_infeasibility` is often not minimal (it may name a
    relation that conflicts with nothing), and relaxation drops a core's lowest-priority member,
    so the core is shrunk by deletion, lowest priority first, before it is returned. Each deletion
    probe is capped in deterministic time (`PROBE_DET_TIME`), and the loop stops when the call's
    deterministic work reaches its budget, so the core does not depend on the machine's speed; a
    probe that runs out keeps its item. Every solve after the first feasible
    one is hinted with the last feasible assignment (probes of a core differ in one assumption, so
    it is often one repair away; measured: the second probe of a dense 60-object floor 1.4 s ->
    0.02 s).
    """

    PROBE_DET_TIME = 1.0

    def __init__(self, m: cp_model.CpModel, seed: int, strong: bool = False) -> None:
        self.m = m
        self.seed = seed
        #: stronger NoOverlap2D propagation (large floors, `layout.STRONG_NO_OVERLAP_FROM`)
        self.strong = strong
        self.solver = cp_model.CpSolver()
        #: the last feasible assignment of this model (every variable), the hint of the next solve
        self._last: list[int] | None = None

    def __call__(self, active: list[Tracked], budget: float) -> tuple[Status, list[Tracked], float]:
        status = self._solve(active, budget)
        spent = self._spent()
        if status != "unsat":
            return status, [], spent
        core = self._core(active)
        for t in sorted(core, key=lambda t: t.rank):
            if len(core) == 1 or spent >= budget:
                break
            trial = [c for c in core if c is not t]
            probe = self._solve(trial, budget - spent, self.PROBE_DET_TIME)
            spent += self._spent()
            if probe == "unsat":
                core = self._core(trial)
        return "unsat", core, spent  # in `active` order: every core is filtered from it in order

    def _spent(self) -> float:
        """The last solve's deterministic work, in calibrated seconds (`DET_PER_SECOND`)."""
        return float(self.solver.response_proto.deterministic_time) / DET_PER_SECOND

    def _solve(self, assumed: list[Tracked], budget: float, det_time: float | None = None) -> Status:
        self.m.clear_assumptions()
        self.m.add_assumptions([t.lit for t in assumed])
        self.solver = cp_model.CpSolver()
        p = self.solver.parameters
        p.num_workers = 1
        p.random_seed = self.seed % 2**31
        det = max(1e-3, budget) * DET_PER_SECOND
        p.max_deterministic_time = det if det_time is None else min(det, det_time)
        p.max_time_in_seconds = wall_cap(budget)
        # measured on benchmarks/layout.py floors: presolve and LP relaxation cost more than they
        # prune on these small feasibility models (3-6x faster without them, docs/scene.md)
        p.cp_model_presolve = False
        p.linearization_level = 0
        if self.strong:
            p.use_timetabling_in_no_overlap_2d = True
            p.use_try_edge_reasoning_in_no_overlap_2d = True
        if self._last is not None:  # warm start: the last layout found under other assumptions
            self.m.clear_hints()  # type: ignore[no-untyped-call]
            hint = self.m.proto.solution_hint
            hint.vars.extend(range(len(self._last)))
            hint.values.extend(self._last)
        status = self.solver.solve(self.m)
        if status in (cp_model.OPTIMAL, cp_model.FEASIBLE):
            self._last = list(self.solver.response_proto.solution)
            return "sat"
        if status == cp_model.INFEASIBLE:
            return "unsat"
        if status == cp_model.MODEL_INVALID:
            raise LogicEnvEvalError(f"the CP-SAT layout model is invalid: {self.m.validate()}",
                                    hint="report this as a bug; use solver='z3' meanwhile")
        ran_out = self.solver.response_proto.deterministic_time >= p.max_deterministic_time * 0.999
        # the deterministic budget ran out (the same on every machine), else the wall-clock cap did
        return "capped" if not ran_out and self.solver.wall_time >= p.max_time_in_seconds else "unknown"

    def _core(self, assumed: list[Tracked]) -> list[Tracked]:
        core = set(self.solver.sufficient_assumptions_for_infeasibility())
        return [t for t in assumed if t.lit.index in core]


class _Vars:
    """Corner, far corner, orientation literals and the x/z intervals of one box."""

    def __init__(self, m: cp_model.CpModel, b: Box, tag: str, frame: tuple[int, int], free_rotation: bool,
                 present: Lit | None) -> None:
        W, D = frame
        c0, c1 = b.cells
        self.x = m.new_int_var(0, W, f"x_{tag}")
        self.z = m.new_int_var(0, D, f"z_{tag}")
        self.ex = m.new_int_var(0, W, f"ex_{tag}")  # x + wx: in the frame by its domain
        self.ez = m.new_int_var(0, D, f"ez_{tag}")
        self.o = [m.new_bool_var(f"o{k}_{tag}") for k in range(4)]
        m.add_exactly_one(self.o)
        if not free_rotation:
            m.add(self.o[0] == 1)
        self.odd = m.new_bool_var(f"odd_{tag}")
        m.add(self.odd == self.o[1] + self.o[3])
        self.wx = c0 + (c1 - c0) * self.odd
        self.wz = c1 + (c0 - c1) * self.odd
        self.cx2 = self.x + self.ex
        self.cz2 = self.z + self.ez
        if present is None:
            self.ix = m.new_interval_var(self.x, self.wx, self.ex, f"ix_{tag}")
            self.iz = m.new_interval_var(self.z, self.wz, self.ez, f"iz_{tag}")
        else:
            self.ix = m.new_optional_interval_var(self.x, self.wx, self.ex, present, f"ix_{tag}")
            self.iz = m.new_optional_interval_var(self.z, self.wz, self.ez, present, f"iz_{tag}")


def _solid(ob: Obstacle) -> bool:
    """A rectangle of positive area (a fixed interval of zero size would block nothing)."""
    return ob[2] > ob[0] and ob[3] > ob[1]


def _fixed(m: cp_model.CpModel, ob: Obstacle, tag: str) -> tuple[Any, Any]:
    x0, z0, x1, z1 = ob
    return (m.new_fixed_size_interval_var(x0, x1 - x0, f"obx_{tag}"),
            m.new_fixed_size_interval_var(z0, z1 - z0, f"obz_{tag}"))


def _outside(m: cp_model.CpModel, ix: Any, iz: Any, ob: Obstacle, en: list[Lit]) -> None:
    """The rectangle of intervals `ix` x `iz` does not meet `ob` (for degenerate or mutually
    overlapping obstacles, which are not in the NoOverlap2D)."""
    x0, z0, x1, z1 = ob
    side = [m.new_bool_var("") for _ in range(4)]
    m.add_bool_or(side).only_enforce_if(en)
    m.add(ix.end_expr() <= x0).only_enforce_if(side[0])
    m.add(ix.start_expr() >= x1).only_enforce_if(side[1])
    m.add(iz.end_expr() <= z0).only_enforce_if(side[2])
    m.add(iz.start_expr() >= z1).only_enforce_if(side[3])


def pack(frame: tuple[int, int], boxes: Sequence[Box], *, seed: int, timeout_s: float,
         obstacles: Sequence[Obstacle] = (), tall: Sequence[tuple[Obstacle, float]] = (),
         walkway: int = 0, rels: Sequence[FloorRel] = (), grid: float = 0.05,
         free_rotation: bool = True, openings: Sequence[Opening] = ()) -> tuple[dict[str, Placed], list[Dropped]]:
    """See `scene.layout.Backend.pack`."""
    W, D = frame
    m = _Model()
    ops = [_OpeningVars(m, op, frame, str(k)) for k, op in enumerate(openings)]
    doors = [o for o in ops if o.op.sill is None]
    lit, tracked = object_literals(boxes, m.new_bool_var, "obj")
    vs = {b.id: _Vars(m, b, str(k), frame, free_rotation, lit.get(b.id)) for k, b in enumerate(boxes)}

    def guard(ids: Sequence[str]) -> list[Lit]:
        return [lit[i] for i in ids if i in lit]

    ext = {b.id: _extended(m, vs[b.id], b, walkway, frame, str(k)) for k, b in enumerate(boxes)
           if walkway and b.task}
    xs = [ext[b.id][0] if b.id in ext else vs[b.id].ix for b in boxes]
    zs = [ext[b.id][1] if b.id in ext else vs[b.id].iz for b in boxes]
    fixed_x: list[Any] = []
    fixed_z: list[Any] = []
    kept: list[Obstacle] = []
    for k, ob in enumerate(obstacles):
        if _solid(ob) and not any(_meet(ob, o) for o in kept):
            kept.append(ob)
            ix, iz = _fixed(m, ob, str(k))
            fixed_x.append(ix)
            fixed_z.append(iz)
        else:  # outside the NoOverlap2D: each box, with its strip when `ob` is solid (as in Z3)
            for b, ix, iz in zip(boxes, xs, zs, strict=True):
                if b.id in ext and not _solid(ob):
                    ix, iz = vs[b.id].ix, vs[b.id].iz
                _outside(m, ix, iz, ob, guard([b.id]))
            for d in doors:
                _outside(m, d.ix, d.iz, ob, [])
    m.add_no_overlap_2d(xs + fixed_x + [d.ix for d in doors], zs + fixed_z + [d.iz for d in doors])
    for w in ops:
        if w.op.sill is not None:
            taller = [b for b in boxes if b.size[1] > w.op.sill]
            if taller:
                m.add_no_overlap_2d([w.ix] + [vs[b.id].ix for b in taller], [w.iz] + [vs[b.id].iz for b in taller])
    for side in "snwe":
        line = [o.line for o in ops if o.op.side == side]
        if len(line) > 1:
            m.add_no_overlap(line)
    for k, (ob, min_h) in enumerate(tall):
        taller = [b for b in boxes if b.size[1] > min_h]
        if not taller:
            continue
        if _solid(ob):
            ix, iz = _fixed(m, ob, f"t{k}")
            m.add_no_overlap_2d([ix] + [vs[b.id].ix for b in taller], [iz] + [vs[b.id].iz for b in taller])
        else:
            for b in taller:
                _outside(m, vs[b.id].ix, vs[b.id].iz, ob, guard([b.id]))
    for k, fr in enumerate(rels):
        if fr.rel.type not in FLOOR_RELATIONS:
            continue
        p = m.new_bool_var(f"rel_{k}")
        tracked.append(Tracked(p, "relation", fr.rel.text(), fr.task, tuple(fr.rel.args)))
        _encode(m, fr, vs, frame, grid, [p, *guard(fr.args)])
    solve = _Solve(m, seed, strong=len(boxes) >= STRONG_NO_OVERLAP_FROM)
    ok, dropped = relax(solve, tracked, timeout_s)
    if not ok:
        return {}, dropped
    gone = {d.tracked.item for d in dropped if d.tracked.kind == "object"}
    val = solve.solver.value
    out = {o.op.id: opening_start(o.op, val(o.t), frame, grid) for o in ops}
    for b in boxes:
        if b.id in gone:
            continue
        v = vs[b.id]
        o = next(k for k in range(4) if solve.solver.boolean_value(v.o[k]))
        out[b.id] = Placed(val(v.x) * grid, val(v.z) * grid, o)
    return out, dropped


class _OpeningVars:
    """An opening's start cell, its clearance as x/z intervals and its stretch along the side
    extended by the gap (one `NoOverlap` per side keeps openings apart)."""

    def __init__(self, m: cp_model.CpModel, op: Opening, frame: tuple[int, int], tag: str) -> None:
        self.op = op
        self.t = m.new_int_var_from_domain(cp_model.Domain.from_intervals([list(r) for r in op.starts]),
                                           f"op_{tag}")
        x0, z0, x1, z1 = opening_rect(op, self.t, frame)
        self.ix = m.new_interval_var(x0, x1 - x0, x1, f"opx_{tag}")
        self.iz = m.new_interval_var(z0, z1 - z0, z1, f"opz_{tag}")
        self.line = m.new_interval_var(self.t, op.width + op.gap, self.t + op.width + op.gap, f"opl_{tag}")


def _meet(a: Obstacle, b: Obstacle) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _extended(m: cp_model.CpModel, v: _Vars, b: Box, A: int, frame: tuple[int, int],
              tag: str) -> tuple[Any, Any]:
    """The box together with its walkway strip `A` cells deep in front (+z, +x, -z, -x for
    orientations 0..3): one rectangle whose corner is linear in the literals and whose size is
    affine in `odd` (= o1 + o3: the strip adds A along x when odd, along z otherwise)."""
    W, D = frame
    c0, c1 = b.cells
    o = v.o
    x0, x1 = m.new_int_var(0, W, f"ex0_{tag}"), m.new_int_var(0, W, f"ex1_{tag}")
    z0, z1 = m.new_int_var(0, D, f"ez0_{tag}"), m.new_int_var(0, D, f"ez1_{tag}")
    m.add(x0 == v.x - A * o[3])
    m.add(z0 == v.z - A * o[2])
    return (m.new_interval_var(x0, c0 + (c1 - c0 + A) * v.odd, x1, f"exi_{tag}"),
            m.new_interval_var(z0, c1 + A + (c0 - c1 - A) * v.odd, z1, f"ezi_{tag}"))


def _abs_le(m: cp_model.CpModel, e: Any, k: int, en: list[Lit]) -> None:
    m.add(e <= k).only_enforce_if(en)
    m.add(-e <= k).only_enforce_if(en)


def _any_of(m: cp_model.CpModel, n: int, en: list[Lit]) -> list[Lit]:
    """`n` case literals of which at least one holds when all of `en` do."""
    cases = [m.new_bool_var("") for _ in range(n)]
    m.add_bool_or(cases).only_enforce_if(en)
    return cases


def _encode(m: cp_model.CpModel, fr: FloorRel, vs: dict[str, _Vars], frame: tuple[int, int], grid: float,
            en: list[Lit]) -> None:
    """`fr` holds when every literal of `en` does (the same geometry as `layout_z3._encode`)."""
    W, D = frame
    t = fr.rel.type
    if t == "edge":  # back against the wall it faces away from; exactly one orientation holds
        v = vs[fr.args[0]]
        m.add(v.z == 0).only_enforce_if([v.o[0], *en])
        m.add(v.x == 0).only_enforce_if([v.o[1], *en])
        m.add(v.ez == D).only_enforce_if([v.o[2], *en])
        m.add(v.ex == W).only_enforce_if([v.o[3], *en])
        return
    if t == "center":
        v = vs[fr.args[0]]
        _abs_le(m, v.cx2 - W, 2, en)
        _abs_le(m, v.cz2 - D, 2, en)
        return
    a, b = vs[fr.args[0]], vs[fr.args[1]]
    if t == "near":
        n = int(math.floor((NEAR_AXIS - sum(fr.slack)) / grid))
        for e in (b.x - a.ex, a.x - b.ex, b.z - a.ez, a.z - b.ez):
            m.add(e <= n).only_enforce_if(en)
        return
    if t == "far":
        f2 = 2 * cells(FAR + sum(fr.slack) + grid, grid)
        dx, dz = a.cx2 - b.cx2, a.cz2 - b.cz2
        for case, e in zip(_any_of(m, 4, en), (dx, -dx, dz, -dz), strict=True):
            m.add(e >= f2).only_enforce_if(case)
        return
    if t == "center_aligned":
        cx, cz = _any_of(m, 2, en)
        _abs_le(m, a.cx2 - b.cx2, 1, [cx])
        _abs_le(m, a.cz2 - b.cz2, 1, [cz])
        return
    near = int(math.floor(IN_FRONT_GAP / grid))
    if t in ("in_front_of", "face_to"):
        # `front` lies on the front axis of `back` (centres aligned within half a cell)
        front, back = (a, b) if t == "in_front_of" else (b, a)
        gaps = [front.z - back.ez, back.z - front.ez, front.x - back.ex, back.x - front.ex]  # o = 0, 2, 1, 3
        for k, gap, cross in ((0, gaps[0], front.cx2 - back.cx2), (2, gaps[1], front.cx2 - back.cx2),
                              (1, gaps[2], front.cz2 - back.cz2), (3, gaps[3], front.cz2 - back.cz2)):
            when = [back.o[k], *en]
            m.add(gap >= 0).only_enforce_if(when)
            if t == "in_front_of":
                m.add(gap <= near).only_enforce_if(when)
            _abs_le(m, cross, 1, when)
        return
    # side_of: beside `b` along its own left-right axis
    for odd, lo_gap, hi_gap, cross in ((b.odd.Not(), b.x - a.ex, a.x - b.ex, a.cz2 - b.cz2),
                                       (b.odd, b.z - a.ez, a.z - b.ez, a.cx2 - b.cx2)):
        when = [odd, *en]
        for case, gap in zip(_any_of(m, 2, when), (lo_gap, hi_gap), strict=True):
            m.add(gap >= 0).only_enforce_if(case)
            m.add(gap <= near).only_enforce_if(case)
        _abs_le(m, cross, 1, when)


def pack_walls(walls: Sequence[WallSegment], boxes: Sequence[WallBox], *, seed: int,
               timeout_s: float) -> tuple[dict[str, tuple[int, int]], list[Dropped]]:
    """See `scene.layout.Backend.pack_walls`: one optional interval per (box, wall), one NoOverlap per wall."""
    m = _Model()
    lit, tracked = object_literals(boxes, m.new_bool_var, "wobj")
    longest = max((length for length, _ in walls), default=0)
    on: dict[str, list[Lit]] = {}
    start: dict[str, Any] = {}
    per_wall: list[list[Any]] = [[] for _ in walls]
    for i, b in enumerate(boxes):
        present = lit.get(b.id)
        start[b.id] = t = m.new_int_var(0, max(0, longest), f"t_{i}")
        on[b.id] = [m.new_bool_var(f"w{k}_{i}") for k in range(len(walls))]
        m.add_exactly_one(on[b.id])
        for k, (length, blocked) in enumerate(walls):
            here = on[b.id][k]
            if present is not None:  # placed on wall k: on it and kept
                here = m.new_bool_var(f"p{k}_{i}")
                m.add_implication(here, on[b.id][k])
                m.add_implication(here, present)
                m.add_bool_or([on[b.id][k].Not(), present.Not(), here])
            free = _free_starts(length, b, blocked)
            if free:
                m.add_linear_expression_in_domain(t, cp_model.Domain.from_intervals(free)).only_enforce_if(here)
            else:
                m.add_bool_or([here.Not()])
            per_wall[k].append(m.new_optional_fixed_size_interval_var(t, b.length, here, f"i{k}_{i}"))
    for intervals in per_wall:
        m.add_no_overlap(intervals)
    solve = _Solve(m, seed)
    ok, dropped = relax(solve, tracked, timeout_s)
    if not ok:
        return {}, dropped
    gone = {d.tracked.item for d in dropped}
    s = solve.solver
    return ({b.id: (next(k for k, w in enumerate(on[b.id]) if s.boolean_value(w)), s.value(start[b.id]))
             for b in boxes if b.id not in gone}, dropped)


def _free_starts(length: int, b: WallBox, blocked: list[tuple[int, int, float, float]]) -> list[list[int]]:
    """Start cells of `b` on a wall of `length` clear of the stretches that reach its height."""
    free = [[0, length - b.length]] if length >= b.length else []
    for lo, hi, bot, top in blocked:
        if not (bot < b.bottom + b.height and top > b.bottom):
            continue
        cut_lo, cut_hi = lo - b.length + 1, hi - 1  # starts that overlap [lo, hi)
        nxt = []
        for a, z in free:
            if cut_hi < a or z < cut_lo:
                nxt.append([a, z])
                continue
            if a < cut_lo:
                nxt.append([a, cut_lo - 1])
            if cut_hi < z:
                nxt.append([cut_hi + 1, z])
        free = nxt
    return free
