"""Throughput and scaling of the PhyPR checker (one core).

1. A 40-object, 4-room valid environment built deterministically from a seeded numpy Generator:
   checks per second with the broad phase and with the naive all-pairs fcl baseline.
2. Scaling (issue 27 item 13), each case in a fresh subprocess so that its peak RSS is its own:
   `spread` (n/2 tables with an item on each, a valid room) and `pile` (n copies of one object in
   one place: n²/2 colliding pairs, the hostile case) at 500 and 2,000 objects — seconds of
   `check_env` and peak RSS of the process — and the all-pairs path as the in-run baseline where
   it is cheap (up to 500 objects; at 2,000 in a pile it takes minutes and GBs). `import_only`
   is the RSS of a process that only imported the checker.
Last line: `objects=2000 pile_s=<float> pile_peak_mb=<float> spread_s=<float> checks_per_s=<float>`.
`--smoke` (tests/test_benchmarks_smoke.py): the same code paths in seconds — 0.2 s rates and
scaling at 20 and 100 objects; its last line names 100 objects.
"""

from __future__ import annotations

import math
import time
from typing import Any

import numpy as np
from shapely.geometry import box as shp_box

from logicenveval.domain.catalog import load_catalog
from logicenveval.domain.shapes import load_shapes
from logicenveval.envfiles import env_from_dict
from logicenveval.model.envspec import EnvSpec
from logicenveval.physics import check_env
from logicenveval.physics.entity import swing_areas
from logicenveval.physics.geometry import clear_body_cache

ROOMS = {"living_room": (0, 0), "kitchen": (6, 0), "bedroom": (0, 5), "bathroom": (6, 5)}
DOORS = [("d_ext", ("living_room", "exterior"), ((1, 0), (2, 0))),
         ("d_lk", ("living_room", "kitchen"), ((6, 2), (6, 3))),
         ("d_lb", ("living_room", "bedroom"), ((2.5, 5), (3.5, 5))),
         ("d_bb", ("bedroom", "bathroom"), ((6, 7), (6, 8)))]


def build_env(rng: np.random.Generator, per_room: int = 10) -> EnvSpec:
    cat = load_catalog()
    floor = sorted(n for n, c in cat.categories.items()
                   if c.placement[0] == "floor" and c.size_max[0] <= 1.1 and c.size_max[2] <= 0.9
                   and c.size_max[1] < 2.5)
    tables = [n for n in floor if cat.categories[n].surface]
    small = sorted(n for n, c in cat.categories.items() if "surface" in c.placement and max(c.size_max) <= 0.3)
    doors = [{"id": i, "rooms": list(r), "segment": [list(p) for p in s], "height": 2.1} for i, r, s in DOORS]
    rooms = [{"id": rid, "type": "LivingRoom", "polygon": [[x, z], [x + 6, z], [x + 6, z + 5], [x, z + 5]]}
             for rid, (x, z) in ROOMS.items()]
    draft = env_from_dict({"task_id": "bench", "env_id": "bench", "rooms": rooms, "doors": doors})
    blocked = [area.buffer(0.05) for _, area in swing_areas(draft)]
    objects: list[dict[str, Any]] = []
    relations: list[dict[str, Any]] = []
    for rid, (x0, z0) in ROOMS.items():
        cells = [(x0 + 0.75 + 1.5 * i, z0 + 0.625 + 1.25 * j) for i in range(4) for j in range(4)]
        free = [c for c in cells if not any(a.intersects(shp_box(c[0] - 0.7, c[1] - 0.6, c[0] + 0.7, c[1] + 0.6))
                                            for a in blocked)]
        n_floor = per_room - 2
        chosen = [free[k] for k in sorted(rng.choice(len(free), size=n_floor, replace=False))]
        for k, (cx, cz) in enumerate(chosen):
            name = str(rng.choice(tables)) if k < 2 else str(rng.choice(floor))
            c = cat.categories[name]
            size = [float(rng.uniform(lo, hi)) for lo, hi in zip(c.size_min, c.size_max, strict=True)]
            size[0], size[2] = min(size[0], 1.3), min(size[2], 1.1)
            jx, jz = (1.4 - size[0]) / 2, (1.2 - size[2]) / 2
            px, pz = cx + float(rng.uniform(-jx, jx)), cz + float(rng.uniform(-jz, jz))
            oid = f"{rid}_{name}_{k}"
            yaw = float(rng.choice([0.0, 180.0]))
            objects.append({"id": oid, "category": name, "room": rid, "position": [px, size[1] / 2, pz],
                            "size": size, "yaw": yaw})
            if k < 2:
                sname = str(rng.choice(small))
                s = cat.categories[sname]
                ssize = [float(rng.uniform(lo, hi)) for lo, hi in zip(s.size_min, s.size_max, strict=True)]
                sid = f"{rid}_{sname}_on{k}"
                # things rest where the support holds them: a chair's seat, in front of its back
                # strip, not the top of its box (the backrest; docs/physics.md "Shapes")
                shape = load_shapes().of(name)
                level, back = shape.surface() if shape is not None else (1.0, 0.0)
                local_z = -size[2] / 2 + size[2] * (back + 1.0) / 2  # the usable area's centre
                sz = pz + (local_z if yaw == 0.0 else -local_z)  # yaw 180 turns the back round
                objects.append({"id": sid, "category": sname, "room": rid, "support": oid,
                                "position": [px, level * size[1] + ssize[1] / 2, sz], "size": ssize})
                relations.append({"type": "on", "args": [sid, oid]})
                relations.append({"type": "near", "args": [sid, oid]})
    return env_from_dict({"task_id": "bench", "env_id": "bench40", "rooms": rooms, "doors": doors,
                          "windows": [{"id": "w0", "room": "kitchen", "segment": [[12, 1], [12, 2]]}],
                          "objects": objects, "relations": relations})


def _rate(env: EnvSpec, broad_phase: bool, seconds: float = 3.0) -> float:
    """Checks per second, each cold: the bodies memoised for the render are forgotten first."""
    check_env(env, broad_phase=broad_phase)
    n, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        clear_body_cache()
        check_env(env, broad_phase=broad_phase)
        n += 1
    return n / (time.perf_counter() - start)


def scaled_env(kind: str, n: int) -> EnvSpec:
    """`spread`: n/2 coffee tables on a grid in one square room, a book on each; `pile`: n sofas at
    one position."""
    if kind == "pile":
        sofa = {"category": "sofa", "room": "r", "position": [2.0, 0.425, 2.0], "size": [2.0, 0.85, 0.9]}
        objects = [{"id": f"o{i}", **sofa} for i in range(n)]
        side = 5.0
    else:
        per_row = math.ceil(math.sqrt(n / 2))
        side = 1.0 + 1.5 * per_row
        objects = []
        for k in range(n // 2):
            x, z = 1.0 + 1.5 * (k % per_row), 1.0 + 1.5 * (k // per_row)
            objects.append({"id": f"t{k}", "category": "coffee_table", "room": "r", "position": [x, 0.225, z],
                            "size": [1.0, 0.45, 0.6]})
            objects.append({"id": f"b{k}", "category": "book", "room": "r", "support": f"t{k}",
                            "position": [x, 0.47, z], "size": [0.2, 0.04, 0.25]})
    room = {"id": "r", "type": "LivingRoom", "polygon": [[0, 0], [side, 0], [side, side], [0, side]]}
    return env_from_dict({"task_id": "bench", "env_id": f"{kind}{n}", "rooms": [room], "objects": objects})


def _one(kind: str, n: int, path: str) -> None:
    """Child process: time one check, print seconds, peak RSS (MB) and failures as JSON."""
    import json
    import resource

    if kind == "import_only":
        print(json.dumps({"s": 0.0, "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                          "failures": 0}))
        return
    env = scaled_env(kind, n)
    start = time.perf_counter()
    report = check_env(env, broad_phase=path == "broad")
    seconds = time.perf_counter() - start
    print(json.dumps({"s": seconds, "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                      "failures": len(report.failures()), "passed": report.passed}))


def _measure(kind: str, n: int, path: str) -> dict[str, Any]:
    import json
    import subprocess
    import sys

    out = subprocess.run([sys.executable, __file__, "--one", kind, str(n), path], check=True,
                         capture_output=True, text=True).stdout
    result: dict[str, Any] = json.loads(out.strip().splitlines()[-1])
    return result


def scaling(sizes: tuple[int, int] = (500, 2000)) -> dict[tuple[str, int, str], dict[str, Any]]:
    """Seconds and peak RSS per case; the all-pairs baseline only at the smaller size."""
    small, _ = sizes
    base = _measure("import_only", 0, "broad")
    print(f"import_only peak_mb={base['peak_mb']:.0f}")
    print(f"{'case':<8} {'objects':>7} {'path':<9} {'seconds':>8} {'peak MB':>8} {'failures':>9} passed")
    results = {}
    for kind in ("spread", "pile"):
        for n in sizes:
            for path in ("broad", "allpairs"):
                if path == "allpairs" and n > small:
                    continue  # the old quadratic path: minutes and GBs on the 2,000-object pile
                r = results[kind, n, path] = _measure(kind, n, path)
                print(f"{kind:<8} {n:>7} {path:<9} {r['s']:>8.2f} {r['peak_mb']:>8.0f} {r['failures']:>9} "
                      f"{r['passed']}")
    for kind in ("spread", "pile"):
        b, a = results[kind, small, "broad"], results[kind, small, "allpairs"]
        print(f"{kind} {small}: all-pairs / broad phase time {a['s'] / b['s']:.1f}x")
    return results


def main() -> None:
    import os
    import sys

    if len(sys.argv) == 5 and sys.argv[1] == "--one":
        _one(sys.argv[2], int(sys.argv[3]), sys.argv[4])
        return
    smoke = sys.argv[1:] == ["--smoke"]
    if sys.argv[1:] and not smoke:
        raise SystemExit("usage: physics_check.py [--smoke]")
    seconds, sizes = (0.2, (20, 100)) if smoke else (3.0, (500, 2000))
    print("load (1, 5, 15 min): " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
    env = build_env(np.random.default_rng(20261123))
    report = check_env(env)
    if not report.passed:  # the benchmark's own environment must be valid, or the rate means nothing
        raise SystemExit("the 40-object environment fails PhyPR: "
                         + "; ".join(f.message for f in report.failures()))
    naive = _rate(env, broad_phase=False, seconds=seconds)
    fast = _rate(env, broad_phase=True, seconds=seconds)
    print(f"rooms={len(env.rooms)} objects={len(env.objects)} passed={report.passed}")
    print(f"naive_all_pairs_checks_per_s={naive:.1f}")
    print(f"broad_phase_speedup={fast / naive:.2f}x")
    scaled = scaling(sizes)
    big = sizes[1]
    pile, spread = scaled["pile", big, "broad"], scaled["spread", big, "broad"]
    print(f"objects={big} pile_s={pile['s']:.2f} pile_peak_mb={pile['peak_mb']:.0f} spread_s={spread['s']:.2f} "
          f"checks_per_s={fast:.1f}")


if __name__ == "__main__":
    main()
