"""Add the household categories AI2-THOR has and our catalog lacked, sized from ProcTHOR's assets.

Every AI2-THOR object type in ProcTHOR's databases must map to a catalog category or to a stated
obstacle class (`scene.procthor.OBSTACLE_CLASSES`). The types below are household things a task
may name; each becomes a category whose size range is the range of its ProcTHOR assets' bounding
boxes (rounded outwards to 1 cm; a type without assets: its objects in AI2-THOR's scenes), with no `rooms` so that generators never add them as
enrichment (the benchmark's generated environments stay as they were). Idempotent:

    python tools/add_ai2thor_categories.py [--db DIR]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
CATALOG = ROOT / "benchmark_data" / "catalog.json"
#: AI2-THOR type -> (category, placement, flags, synonyms)
NEW: dict[str, tuple[str, list[str], dict[str, bool], list[str]]] = {
    "ButterKnife": ("butter_knife", ["surface", "inside"], {"pickable": True}, []),
    "CreditCard": ("credit_card", ["surface", "inside"], {"pickable": True}, ["bank card"]),
    "Ladle": ("ladle", ["surface", "inside"], {"pickable": True}, []),
    "SaltShaker": ("salt_shaker", ["surface", "inside"], {"pickable": True}, []),
    "PepperShaker": ("pepper_shaker", ["surface", "inside"], {"pickable": True}, []),
    "Spatula": ("spatula", ["surface", "inside"], {"pickable": True}, []),
    "Statue": ("statue", ["surface", "floor"], {"pickable": True}, ["figurine", "sculpture"]),
    "TableTopDecor": ("table_decor", ["surface"], {"pickable": True}, ["tabletop decor"]),
    "Watch": ("watch", ["surface", "inside"], {"pickable": True}, ["wristwatch"]),
    "BaseballBat": ("baseball_bat", ["floor", "surface"], {"pickable": True}, []),
    "TennisRacket": ("tennis_racket", ["floor", "surface"], {"pickable": True}, []),
    "Dumbbell": ("dumbbell", ["floor", "surface"], {"pickable": True}, []),
    "CD": ("cd", ["surface", "inside"], {"pickable": True}, ["compact disc"]),
    "AluminumFoil": ("aluminum_foil", ["surface", "inside"], {"pickable": True}, ["tin foil"]),
    "ScrubBrush": ("scrub_brush", ["floor", "surface"], {"pickable": True}, []),
    "Plunger": ("plunger", ["floor"], {"pickable": True}, []),
    "ShelvingUnit": ("shelving_unit", ["floor"], {"surface": True}, ["open shelves"]),
    "Cart": ("cart", ["floor"], {"surface": True}, ["trolley"]),
    "Desktop": ("desktop_computer", ["surface"], {"toggleable": True}, ["desktop"]),
    "Safe": ("safe", ["floor"], {"container": True, "openable": True}, []),
    "RoomDecor": ("room_decor", ["floor"], {}, ["floor decor"]),
    "Poster": ("poster", ["wall"], {}, []),
}


def _size_range(assets: list[dict[str, Any]]) -> tuple[list[float], list[float]]:
    boxes = [[a["boundingBox"][k] for k in "xyz"] for a in assets]
    lo = [max(0.01, math.floor(min(b[k] for b in boxes) * 100) / 100) for k in range(3)]
    hi = [math.ceil(max(b[k] for b in boxes) * 100) / 100 for k in range(3)]
    return lo, hi


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--db", default=None, help="ProcTHOR's procthor/databases folder (default: found)")
    args = parser.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    from logicenveval.scene.procthor import find_procthor_db

    db = Path(args.db) if args.db else find_procthor_db()
    if db is None:
        print("ProcTHOR's databases not found: pip install 'logicenveval[procthor]' or pass --db", file=sys.stderr)
        return 2
    assets = json.loads((db / "asset-database.json").read_text(encoding="utf-8"))
    # types only AI2-THOR's hand-built scenes have (a poster): sized from those scenes' objects
    meta = json.loads((db / "ai2thor-object-metadata.json").read_text(encoding="utf-8"))
    for o in (o for group in meta.values() for scene in group for o in scene):
        if o["objectType"] in NEW and o["objectType"] not in assets:
            assets.setdefault(f"scene:{o['objectType']}", []).append(
                {"boundingBox": o["axisAlignedBoundingBox"]["size"]})
    for key in [k for k in assets if k.startswith("scene:")]:
        assets[key.removeprefix("scene:")] = assets.pop(key)
    catalog = json.loads(CATALOG.read_text(encoding="utf-8"))
    added = 0
    for otype, (name, placement, flags, synonyms) in NEW.items():
        if name in catalog["categories"] or otype not in assets:
            continue
        lo, hi = _size_range(assets[otype])
        catalog["categories"][name] = {"size_min": lo, "size_max": hi, "placement": placement, **flags,
                                       "rooms": [], "synonyms": synonyms, "ai2thor_type": otype}
        added += 1
    CATALOG.write_text(json.dumps(catalog, indent=1) + "\n", encoding="utf-8")
    print(f"added {added} categories to {CATALOG}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
