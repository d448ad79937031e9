"""Layout solver benchmark: decomposed Z3 and CP-SAT (per floor / surface / wall) vs one monolithic Z3 model.

Rooms of 10, 20, 30, 40 objects: half on the floor (some of them surfaces), a third of the rest
on surfaces, the rest wall-mounted; a third are task objects; near/edge/far relations and one
conflicting enrichment pair. Two densities: `normal` (14 m² + 1 m² per object) and `dense` (35 % of
that area: 40-50 % of the floor covered by 20+ objects). For each density, size and backend: median
and max time of `construct_environment`, relaxations, physics pass rate (`physics.check_env`);
for `normal` also the median of a naive monolithic single Z3 model of the same objects (world frame,
no decomposition, no relaxation; timeout counts as the limit). Then which backend is faster on
dense rooms, against the package default. Last line (default backend, normal rooms):
`objects=30 median_s=<float> monolithic_median_s=<float> phypr=<float>`.

`--objects N --dense` measures dense rooms instead: a growth table (median of `--growth-rooms`
rooms per size of `--growth`, every backend incl. `auto`, Z3 only up to `--z3-max` objects because
it takes minutes beyond), the fitted growth exponent per backend (slope of log time over log
objects), then `--rooms` dense rooms of N objects with the default backend. Last line:
`objects=<N> dense_median_s=<float> phypr=<float>`.

`--crossover` measures what the `auto` backend's rule is taken from: every floor packing of rooms
of `--crossover-sizes` objects (`--rooms` each) at each area factor of `--crossover-factors`,
solved by Z3 and by CP-SAT (best of 3 each); per area factor and floor box count the median times,
the median and range of the Z3/CP-SAT ratio, the share of the floor covered, and which backend
`auto` picks there.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from typing import Any

import numpy as np
import z3

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.errors import LogicEnvEvalError
from logicenveval.model.envspec import EnvSpec
from logicenveval.scene.construct import construct_environment
from logicenveval.scene.layout import DEFAULT_SOLVER, SOLVERS, Solver
from logicenveval.scene.spec import (
    ObjectRequest,
    RelationRequest,
    RoomRequest,
    SceneSpec,
    WindowRequest,
)
from logicenveval.scene.verify import geometric_failures

FLOOR = ["armchair", "side_table", "ottoman", "floor_lamp", "bookshelf", "toy_box", "trash_can", "stool",
         "potted_plant", "pet_bed", "chair", "cabinet"]
SURFACES = ["coffee_table", "dining_table", "desk", "console_table", "tv_stand"]
ON_TOP = ["book", "mug", "remote_control", "candle", "apple", "cup", "tissue_box", "cell_phone"]
WALL = ["painting", "wall_clock", "mirror", "bulletin_board", "light_switch"]


DENSE = 0.35  # area factor of the dense setting


def room_spec(n: int, seed: int, area_factor: float = 1.0) -> SceneSpec:
    rng = np.random.default_rng(seed)
    n_floor = n // 2
    n_surf = max(1, n_floor // 4)
    n_on = (n - n_floor) * 2 // 3
    n_wall = n - n_floor - n_on
    objs: list[ObjectRequest] = []
    for i in range(n_surf):
        objs.append(ObjectRequest(id=f"s{i}", category=SURFACES[i % len(SURFACES)], room="r", task=i % 3 == 0))
    for i in range(n_floor - n_surf):
        objs.append(ObjectRequest(id=f"f{i}", category=str(rng.choice(FLOOR)), room="r", task=i % 3 == 0))
    for i in range(n_on):
        objs.append(ObjectRequest(id=f"o{i}", category=str(rng.choice(ON_TOP)), room="r",
                                  placement=f"on:s{i % n_surf}", task=i % 3 == 0))
    for i in range(n_wall):
        objs.append(ObjectRequest(id=f"w{i}", category=WALL[i % len(WALL)], room="r", placement="wall",
                                  task=i % 3 == 0))
    floor_ids = [o.id for o in objs if o.placement == "floor"]
    rels = [RelationRequest(type="near", args=(floor_ids[0], floor_ids[1])),
            RelationRequest(type="edge", args=(floor_ids[-1],)),
            RelationRequest(type="far", args=(floor_ids[0], floor_ids[-2]))]
    extra = next(o.id for o in objs if o.placement == "floor" and not o.is_task)
    rels += [RelationRequest(type="edge", args=(extra,)),  # an LLM-style conflict: relaxation must drop one
             RelationRequest(type="center", args=(extra,))]
    for k in range(2, min(len(floor_ids) - 1, 2 + n // 10)):
        rels.append(RelationRequest(type="near", args=(floor_ids[k], floor_ids[k + 1])))
    area = (14.0 + 1.0 * n) * area_factor
    room = RoomRequest(id="r", type="LivingRoom", area=area, windows=[WindowRequest(wall="n")])
    return SceneSpec(task_id="bench", env_id=f"n{n}_{seed}", rooms=[room], objects=objs, relations=rels,
                     room_timeout_s=30.0)


def physics_passes(env: EnvSpec, catalog: Catalog) -> tuple[bool, str]:
    try:
        from logicenveval.physics import check_env
    except ImportError:
        return (not geometric_failures(env, catalog)), "scene self-check"
    report: Any = check_env(env, catalog)
    return bool(report.floor_plan.passed and report.entity.passed and report.relation.passed), "physics.check_env"


def monolithic(spec: SceneSpec, catalog: Catalog, timeout_s: float) -> float:
    """One Z3 model over every object in world cells; returns the solve time (timeout = limit)."""
    rng = np.random.default_rng(0)
    g = spec.grid
    side = spec.rooms[0].area ** 0.5
    W = D = int(side / g)
    s = z3.Solver()
    s.set("timeout", int(timeout_s * 1000))
    v: dict[str, tuple[Any, Any, Any, Any, Any, int]] = {}
    for o in spec.objects:
        c = catalog.categories[o.category]
        size = [float(rng.uniform(a, b)) for a, b in zip(c.size_min, c.size_max, strict=True)]
        cx, cz, h = int(np.ceil(size[0] / g)), int(np.ceil(size[2] / g)), int(np.ceil(size[1] / g))
        x, z, r = z3.Int(f"x_{o.id}"), z3.Int(f"z_{o.id}"), z3.Int(f"r_{o.id}")
        odd = z3.Or(r == 1, r == 3)
        wx, wz = z3.If(odd, cz, cx), z3.If(odd, cx, cz)
        s.add(r >= 0, r <= 3, x >= 0, z >= 0, x + wx <= W, z + wz <= D)
        v[o.id] = (x, z, wx, wz, r, h)
        if o.placement == "wall":
            s.add(z3.Or(x == 0, z == 0, x + wx == W, z + wz == D))
    by_id = {o.id: o for o in spec.objects}
    for o in spec.objects:
        if o.placement.startswith("on:"):
            x, z, wx, wz, _, _ = v[o.id]
            px, pz, pwx, pwz, _, _ = v[o.placement[3:]]
            s.add(x >= px, z >= pz, x + wx <= px + pwx, z + wz <= pz + pwz)
    ids = list(v)
    for i, a in enumerate(ids):
        for b in ids[i + 1:]:
            pa, pb = by_id[a].placement, by_id[b].placement
            same_level = pa == pb or (pa in ("floor", "wall") and pb in ("floor", "wall"))
            if not same_level:
                continue
            xa, za, wxa, wza, _, _ = v[a]
            xb, zb, wxb, wzb, _, _ = v[b]
            s.add(z3.Or(xa + wxa <= xb, xb + wxb <= xa, za + wza <= zb, zb + wzb <= za))
    n = int(0.7 / g)
    for rel in spec.relations:
        if rel.type == "near":
            xa, za, wxa, wza, _, _ = v[rel.args[0]]
            xb, zb, wxb, wzb, _, _ = v[rel.args[1]]
            s.add(xb - (xa + wxa) <= n, xa - (xb + wxb) <= n, zb - (za + wza) <= n, za - (zb + wzb) <= n)
    t0 = time.perf_counter()
    s.check()
    return min(time.perf_counter() - t0, timeout_s)


def measure(n: int, rooms: int, factor: float, solver: Solver, catalog: Catalog
            ) -> tuple[list[float], list[int], list[bool], str]:
    times, relax, passed = [], [], []
    how = ""
    for k in range(rooms):
        spec = room_spec(n, 1000 * n + k, factor)
        t0 = time.perf_counter()
        res = construct_environment(spec, catalog=catalog, rng=np.random.default_rng(k), solver=solver)
        times.append(time.perf_counter() - t0)
        relax.append(len(res.relaxation_log))
        ok, how = physics_passes(res.env, catalog)
        passed.append(ok)
    return times, relax, passed, how


def _load() -> str:
    return "load (1, 5, 15 min): " + " ".join(f"{x:.2f}" for x in os.getloadavg())


def growth(args: argparse.Namespace, catalog: Catalog) -> None:
    print(_load())
    sizes = [int(x) for x in args.growth.split(",")]
    print(f"{'objects':>8} " + " ".join(f"{s + '_s':>10}" for s in SOLVERS)
          + f"  (dense, median of {args.growth_rooms} rooms; ! = a room failed physics)")
    fits: dict[str, list[tuple[float, float]]] = {s: [] for s in SOLVERS}
    for n in sizes:
        cols = []
        for solver in SOLVERS:
            if solver == "z3" and n > args.z3_max:
                cols.append(f"{'skipped':>10}")
                continue
            times, _, passed, _ = measure(n, args.growth_rooms, DENSE, solver, catalog)
            med = statistics.median(times)
            fits[solver].append((n, med))
            cols.append(f"{med:>9.3f}{'' if all(passed) else '!'}")
        print(f"{n:>8} " + " ".join(cols), flush=True)
    for solver, pts in fits.items():
        if len(pts) >= 2:
            slope = float(np.polyfit(np.log([p[0] for p in pts]), np.log([p[1] for p in pts]), 1)[0])
            print(f"growth exponent {solver}: {slope:.2f} over {[p[0] for p in pts]} objects")
    times, relax, passed, how = measure(args.objects, args.rooms, DENSE, DEFAULT_SOLVER, catalog)
    print(f"dense objects={args.objects} solver={DEFAULT_SOLVER} rooms={args.rooms} "
          f"times_s={[round(t, 3) for t in times]} relaxations={statistics.mean(relax):.1f} ({how})")
    print(_load())
    print(f"objects={args.objects} dense_median_s={statistics.median(times):.3f} "
          f"phypr={sum(passed) / len(passed):.2f}")


def crossover(args: argparse.Namespace, catalog: Catalog) -> None:
    """Z3 vs CP-SAT on the very floor packings `construct_environment` hands to a backend."""
    from logicenveval.scene import layout_auto, layout_cpsat, layout_z3

    print(_load())
    floors: list[tuple[str, tuple[Any, ...], dict[str, Any]]] = []
    real = layout_cpsat.pack
    current = [""]  # the density being recorded

    def record(*a: Any, **kw: Any) -> Any:
        if kw.get("walkway"):
            floors.append((current[0], a, kw))
        return real(*a, **kw)

    layout_cpsat.pack = record
    try:
        for factor in (float(x) for x in args.crossover_factors.split(",")):
            current[0] = f"{factor:g}"
            for n in (int(x) for x in args.crossover_sizes.split(",")):
                try:
                    measure(n, args.rooms, factor, "cpsat", catalog)
                except LogicEnvEvalError as e:  # too small a room for this many objects
                    print(f"area factor {factor:g}, {n} objects: skipped ({e})")
    finally:
        layout_cpsat.pack = real

    def best(f: Any, a: tuple[Any, ...], kw: dict[str, Any]) -> float:
        out = []
        for _ in range(3):
            t0 = time.perf_counter()
            f(*a, **kw)
            out.append(time.perf_counter() - t0)
        return min(out)

    rows: dict[tuple[str, int], list[tuple[float, float, float, str]]] = {}
    for where, a, kw in floors:
        frame, boxes = a
        fill = sum(b.cells[0] * b.cells[1] for b in boxes) / (frame[0] * frame[1])
        rows.setdefault((where, len(boxes)), []).append(
            (best(layout_z3.pack, a, kw), best(real, a, kw), fill, layout_auto.choose(frame, boxes, kw["walkway"])))
    print(f"{'area':>7} {'boxes':>5} {'floors':>6} {'z3_ms':>7} {'cpsat_ms':>8} {'z3/cpsat':>8} {'range':>11} "
          f"{'fill':>5} auto")
    for (where, nb), rs in sorted(rows.items()):
        ratios = [z / c for z, c, _, _ in rs]
        print(f"{where:>7} {nb:>5} {len(rs):>6} {statistics.median(r[0] for r in rs) * 1e3:>7.1f} "
              f"{statistics.median(r[1] for r in rs) * 1e3:>8.1f} {statistics.median(ratios):>8.2f} "
              f"{min(ratios):>5.2f}-{max(ratios):<5.2f} {statistics.median(r[2] for r in rs):>5.2f} "
              f"{'/'.join(sorted({r[3] for r in rs}))}", flush=True)
    print(_load())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--rooms", type=int, default=3, help="rooms per size")
    ap.add_argument("--sizes", default="10,20,30,40")
    ap.add_argument("--mono-timeout", type=float, default=20.0)
    ap.add_argument("--objects", type=int, default=None, help="dense-room mode with this many objects")
    ap.add_argument("--dense", action="store_true", help="with --objects: dense rooms (the only mode)")
    ap.add_argument("--growth", default="20,40,60,80", help="sizes of the dense growth table")
    ap.add_argument("--growth-rooms", type=int, default=3, help="dense rooms per size of the growth table")
    ap.add_argument("--z3-max", type=int, default=40,
                    help="largest dense room given to Z3 in the table (Z3 takes ~2 min at 60)")
    ap.add_argument("--crossover", action="store_true", help="Z3 vs CP-SAT per floor size (the `auto` rule)")
    ap.add_argument("--crossover-sizes", default="6,8,10,12,14,16,18,20,24")
    ap.add_argument("--crossover-factors", default=f"1,{DENSE},0.25",
                    help="room area factors of the crossover (1 = normal; 0.25 crowds 4-7-box floors)")
    ap.add_argument("--smoke", action="store_true", help="seconds, not minutes: a small case of the same code path (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = ap.parse_args()
    if args.smoke:  # one 6-object room per setting and backend; 10 objects in the dense table
        args.rooms, args.sizes, args.mono_timeout = 1, "6", 5.0
        args.growth, args.growth_rooms, args.z3_max = "10", 1, 10
        args.crossover_sizes, args.crossover_factors = "6", "1"
    catalog = load_catalog()
    construct_environment(room_spec(10, 0), catalog=catalog, rng=np.random.default_rng(0), solver="cpsat")  # warm-up
    if args.crossover:
        crossover(args, catalog)
        return
    if args.objects is not None:
        growth(args, catalog)
        return
    last = ""
    dense_wins: dict[str, int] = {s: 0 for s in SOLVERS}
    for setting, factor in (("normal", 1.0), ("dense", DENSE)):
        for n in (int(x) for x in args.sizes.split(",")):
            medians: dict[str, float] = {}
            mono = ([monolithic(room_spec(n, 1000 * n + k), catalog, args.mono_timeout) for k in range(args.rooms)]
                    if setting == "normal" else [])
            for solver in SOLVERS:
                times, relax, passed, how = measure(n, args.rooms, factor, solver, catalog)
                med = medians[solver] = statistics.median(times)
                rate = sum(passed) / len(passed)
                line = (f"{setting:6s} objects={n:2d} solver={solver:5s} rooms={args.rooms} median_s={med:.3f} "
                        f"max_s={max(times):.3f} relaxations={statistics.mean(relax):.1f} phypr={rate:.2f} ({how})")
                if mono:
                    mmed = statistics.median(mono)
                    line += f" monolithic_median_s={mmed:.3f} speedup={mmed / med:.1f}x"
                    if n == 30 and solver == DEFAULT_SOLVER:
                        last = f"objects=30 median_s={med:.3f} monolithic_median_s={mmed:.3f} phypr={rate:.2f}"
                print(line, flush=True)
            if setting == "dense":
                dense_wins[min(medians, key=lambda s: medians[s])] += 1
    best = max(dense_wins, key=lambda s: dense_wins[s])
    print(f"dense rooms: fastest backend per size {dense_wins}; package default DEFAULT_SOLVER={DEFAULT_SOLVER!r} "
          f"({'agrees' if best == DEFAULT_SOLVER else 'DISAGREES: revisit scene/layout.py'})")
    if last:
        print(last)


if __name__ == "__main__":
    main()
