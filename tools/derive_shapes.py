"""Derive support surfaces and free space under tops from AI2-THOR's own scene data.

Reads ProcTHOR's `ai2thor-object-metadata.json` (every object of AI2-THOR's hand-built iTHOR and
RoboTHOR scenes, with its settled axis-aligned bounding box and `parentReceptacles`) and
writes `benchmark_data/support_shapes.json`, which entity PhyPR (`domain.shapes`) and the layout
solver read. Run:

    python tools/derive_shapes.py [--db DIR]   # DIR: ProcTHOR's procthor/databases (default: found)

What is derived, per AI2-THOR object type, all as fractions of the receptacle's height (0 = its
bottom, 1 = its top) or depth (0 = its back, 1 = its front):

* `levels`: the heights where objects rest on it (the bottoms of objects whose parent receptacle
  it is), clustered; a cluster needs >= 3 observations and >= 5 % of the type's observations.
  A seat's levels run from its lowest cluster above 0.2 (the seat) to its highest; any other type
  with objects resting below 0.9 of its height or `Shelf` objects inside its box (together >= 3
  and >= 1 % of its observations) has shelves, and is given the band
  from the lowest of them to its top, since shelf heights differ between assets of one type;
  the rest hold objects on their top, over the spread of their highest cluster (a sink's rim).
* `solid`: the parts of its bounding box that are solid. Seats (chair, armchair, sofa, bed): the
  box below the seat (`seat`: the median height things rest at on it) plus a back strip whose depth is what the data leaves behind tucked chairs
  (1 - the 95th percentile of how far chairs reach under tables and desks). Tops (tables, desks,
  counters) with >= 3 things found tucked under them: a slab above the highest solid part of
  those (a tucked seat's solid part ends at its seat). A television (its box includes its foot;
  the screen above is thin): the box above the free space in front of its foot, i.e. above the
  90th percentile of the tops of the objects that rest on the TV's own receptacle inside its box
  (by > 1 cm on every axis, the collision tolerance; tops below the TV's top; >= 3 of them) — the
  highest tenth are boxes that overhang (a houseplant's leaves) or stand beside the screen.
  Everything else: the whole box.
* `open_top`: whether objects held inside it stand out of its top in the scenes (>= 2 and >= 5 %
  of them by more than 1 cm): a sink, a bin or a box is open, a fridge or a drawer is not.
* `floor_spread`: how far settled floor objects' boxes dip below the floor (5th percentile) — the
  penetration into floors and walls that is not a collision.

Output is deterministic (sorted keys, rounded to 3 decimals).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections import defaultdict
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmark_data" / "support_shapes.json"
SEATS = ("Chair", "ArmChair", "Sofa", "Bed", "Stool", "Ottoman")
TOPS = ("DiningTable", "Desk", "CounterTop", "CoffeeTable", "SideTable")
#: objects seen tucked under tops (the others overlapping a top are its own drawers and shelves)
TUCKED = ("Chair", "Stool", "Ottoman", "Footstool", "GarbageCan", "Box", "LaundryHamper")
#: objects whose box includes a deep foot under a thin solid part
FOOTED = ("Television",)


def _box(o: dict[str, Any]) -> tuple[list[float], list[float]]:
    bb = o["axisAlignedBoundingBox"]
    c, s = bb["center"], bb["size"]
    return [c[k] - s[k] / 2 for k in "xyz"], [c[k] + s[k] / 2 for k in "xyz"]


def _quantile(values: list[float], q: float) -> float:
    v = sorted(values)
    return v[min(len(v) - 1, max(0, math.ceil(q * len(v)) - 1))]


def clusters(levels: list[float], gap: float = 0.08) -> list[tuple[float, float, int]]:
    """Sorted levels split where consecutive ones are more than `gap` apart: (lo, hi, count)."""
    out: list[tuple[float, float, int]] = []
    for v in sorted(levels):
        if out and v - out[-1][1] <= gap:
            lo, _, n = out[-1]
            out[-1] = (lo, v, n + 1)
        else:
            out.append((v, v, 1))
    keep = max(3, math.ceil(0.05 * len(levels)))
    return [c for c in out if c[2] >= keep]


def _axis_aligned(o: dict[str, Any]) -> bool:
    r = o["rotation"]["y"] % 90
    return min(r, 90 - r) < 2


def beside_foot(scenes: list[list[dict[str, Any]]], otype: str) -> tuple[int, list[float]]:
    """(how many `otype` objects, the tops of the objects resting on their receptacles inside their
    boxes, as fractions of their height): the free space in front of a TV's foot."""
    count, tops = 0, []
    for scene in scenes:
        for tv in scene:
            if tv["objectType"] != otype:
                continue
            count += 1
            parents = set(tv.get("parentReceptacles") or [])
            tlo, thi = _box(tv)
            for o in scene:
                if o is tv or not parents & set(o.get("parentReceptacles") or []):
                    continue
                olo, ohi = _box(o)
                if min(min(ohi[k], thi[k]) - max(olo[k], tlo[k]) for k in range(3)) <= 0.01:
                    continue
                if ohi[1] < thi[1]:
                    tops.append((ohi[1] - tlo[1]) / (thi[1] - tlo[1]))
    return count, tops


def derive(meta: dict[str, Any]) -> dict[str, Any]:
    levels: dict[str, list[float]] = defaultdict(list)
    above: dict[str, list[bool]] = defaultdict(list)
    floor_gaps: list[float] = []
    scenes = [scene for group in meta.values() for scene in group]
    for scene in scenes:
        by_id = {o["objectId"]: o for o in scene}
        for o in scene:
            lo, _ = _box(o)
            for pid in o.get("parentReceptacles") or []:
                r = by_id.get(pid)
                if r is None:
                    continue
                rlo, rhi = _box(r)
                if r["objectType"] == "Floor":
                    floor_gaps.append(lo[1] - rhi[1])
                    continue
                height = rhi[1] - rlo[1]
                frac = (lo[1] - rlo[1]) / height if height > 0 else math.nan
                if -0.05 <= frac <= 1.05:
                    levels[r["objectType"]].append(frac)
                    if frac < 0.9:  # held inside: does it stand out of the top?
                        above[r["objectType"]].append(_box(o)[1][1] - rhi[1] > 0.01)
    # AI2-THOR models a receptacle's open shelves as `Shelf` objects inside its box: their
    # bottoms are shelf heights too (drawers are closed: what lies in them is contained)
    shelves: dict[str, list[float]] = defaultdict(list)
    for scene in scenes:
        inner = [s for s in scene if s["objectType"] == "Shelf"]
        for r in scene:
            if r["objectType"] in ("Shelf", "Floor") or r["objectType"] not in levels:
                continue
            rlo, rhi = _box(r)
            for s in inner:
                c = s["axisAlignedBoundingBox"]["center"]
                if all(rlo[i] <= c[k] <= rhi[i] for i, k in enumerate("xyz")):
                    frac = (_box(s)[0][1] - rlo[1]) / (rhi[1] - rlo[1])
                    if 0.0 <= frac < 0.9:
                        shelves[r["objectType"]].append(frac)
    types: dict[str, dict[str, Any]] = {}
    for otype, vals in sorted(levels.items()):
        cl = clusters(vals)
        if not cl:
            continue
        entry: dict[str, Any] = {"observations": len(vals),
                                 "clusters": [[round(a, 3), round(b, 3), n] for a, b, n in cl]}
        if otype in SEATS:
            seat = [c for c in cl if c[0] > 0.2] or cl
            entry["levels"] = [[round(seat[0][0], 3), round(max(c[1] for c in seat), 3)]]
            # the seat surface: the median height where things rest on it
            entry["seat"] = round(_quantile([v for v in vals if seat[0][0] <= v <= seat[-1][1]], 0.5), 3)
        else:
            inside = [v for v in vals if v < 0.9] + shelves.get(otype, [])
            shelved = len(inside) >= max(3, math.ceil(0.01 * len(vals)))
            entry["shelves"] = len(shelves.get(otype, []))
            top = min(cl[-1][0], 1.0)
            entry["levels"] = [[round(max(min(inside), 0.0), 3), 1.0]] if shelved else [[round(top, 3), 1.0]]
        out_top = sum(above.get(otype, []))
        entry["open_top"] = out_top >= max(2, math.ceil(0.05 * len(above.get(otype, []))))
        types[otype] = entry
    # how far chairs reach under tops, and the highest solid thing tucked under each top type
    reach: list[float] = []
    under: dict[str, list[float]] = defaultdict(list)
    for scene in scenes:
        tops = [o for o in scene if o["objectType"] in TOPS]
        for o in scene:
            if o["objectType"] not in TUCKED or not _axis_aligned(o):
                continue
            olo, ohi = _box(o)
            for t in tops:
                tlo, thi = _box(t)
                ov = [min(ohi[k], thi[k]) - max(olo[k], tlo[k]) for k in range(3)]
                if min(ov) <= 0.03:
                    continue
                axis = 0 if ov[0] < ov[2] else 2
                if o["objectType"] == "Chair":
                    reach.append(ov[axis] / (ohi[axis] - olo[axis]))
                seat = types.get(o["objectType"], {}).get("seat", 1.0)
                solid_top = olo[1] + seat * (ohi[1] - olo[1])
                under[t["objectType"]].append((solid_top - tlo[1]) / (thi[1] - tlo[1]))
    back = round(1.0 - _quantile(reach, 0.95), 3) if reach else 0.25
    for otype in SEATS:
        if otype in types:
            s = types[otype]["seat"]
            types[otype]["solid"] = [{"y": [0.0, s], "z": [0.0, 1.0]}, {"y": [0.0, 1.0], "z": [0.0, back]}]
    for otype in TOPS:
        mine = [v for v in under.get(otype, []) if v < 1.0]
        if otype in types and len(mine) >= 3:  # a top is solid above the highest thing tucked under it
            types[otype]["solid"] = [{"y": [round(max(mine), 3), 1.0], "z": [0.0, 1.0]}]
            types[otype]["tucked"] = len(mine)
    for otype in FOOTED:
        count, tops = beside_foot(scenes, otype)
        if len(tops) >= 3:  # not a receptacle: nothing rests on it, objects rest beside its foot
            types[otype] = {"beside_foot": len(tops), "levels": [[1.0, 1.0]], "objects": count,
                            "open_top": False,
                            "solid": [{"y": [round(_quantile(tops, 0.9), 3), 1.0], "z": [0.0, 1.0]}]}
    return {
        "source": "ProcTHOR procthor/databases/ai2thor-object-metadata.json (Apache-2.0), "
                  f"{len(scenes)} AI2-THOR scenes; derived by tools/derive_shapes.py",
        "chair_reach_under_tops": {"observations": len(reach),
                                   "p95": round(_quantile(reach, 0.95), 3) if reach else None},
        "floor_spread": round(-_quantile(floor_gaps, 0.05), 3) if floor_gaps else 0.0,
        "floor_observations": len(floor_gaps),
        "types": types,
    }


def category_types(catalog_path: Path) -> dict[str, str]:
    """Catalog category -> the AI2-THOR type whose shape it takes: its own `ai2thor_type`, else
    the type that stands in for it in our ProcTHOR mapping (`scene.procthor.STAND_IN_TYPES`)."""
    from logicenveval.scene.procthor import STAND_IN_TYPES

    cats = json.loads(catalog_path.read_text(encoding="utf-8"))["categories"]
    out = {name: c.get("ai2thor_type") or STAND_IN_TYPES.get(name) for name, c in cats.items()}
    return {k: v for k, v in sorted(out.items()) if v}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--db", default=None, help="ProcTHOR's procthor/databases folder (default: found)")
    parser.add_argument("--out", default=str(OUT))
    args = parser.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    from logicenveval.scene.procthor import find_procthor_db

    db = Path(args.db) if args.db else find_procthor_db()
    if db is None:
        print("ProcTHOR's databases not found: pip install 'logicenveval[procthor]' or pass --db",
              file=sys.stderr)
        return 2
    meta = json.loads((db / "ai2thor-object-metadata.json").read_text(encoding="utf-8"))
    data = derive(meta)
    data["categories"] = {k: v for k, v in category_types(ROOT / "benchmark_data" / "catalog.json").items()
                          if v in data["types"]}
    Path(args.out).write_text(json.dumps(data, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    print(f"wrote {args.out}: {len(data['types'])} types (receptacles, seats, tops, footed)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
