"""ProcTHOR databases and our mapping onto them: real asset ids, wall holes and materials.

A house JSON only loads in AI2-THOR if every `assetId` is one of its assets, every door/window
asset has a wall hole and every material exists. `ProcthorDB` reads the three files of
ProcTHOR's `procthor/databases/` folder that say so (`asset-database.json`: objectType ->
assets with `assetId`, `objectType`, `boundingBox`, `primaryProperty`; `material-database.json`:
group -> material names; `wall-holes.json`: asset id -> hole `min`/`max`/`offset`).

We do not ship those databases: the `[procthor]` extra installs ProcTHOR's wheel, whose
databases `find_procthor_db` locates (Apache-2.0; read as data, its code is never imported).
`benchmark_data/procthor_assets.json` is *our choice*: one ProcTHOR asset id per catalog
category (the asset of the category's AI2-THOR type, else a stand-in of the same pickability,
whose size is closest to the category's mean size), the door, doorway and window ids with the
hole sizes we place, and the floor/wall/ceiling materials; `choose_assets` made it from the real
databases and `check_house` verifies houses against the real databases when given, else against
that mapping.
"""

from __future__ import annotations

import importlib.util
import math
from dataclasses import dataclass
from functools import lru_cache, partial
from pathlib import Path
from typing import Any

from logicenveval.domain.catalog import Catalog
from logicenveval.errors import ConfigError
from logicenveval.limits import parse_json, read_text

Size = tuple[float, float, float]
MAPPING_FILE = Path(__file__).resolve().parents[2] / "benchmark_data" / "procthor_assets.json"
#: the four room types ProcTHOR/AI2-THOR houses know, and where ours go (the original is kept
#: as `logicenvevalRoomType`)
AI2THOR_ROOM_TYPES = ("Kitchen", "LivingRoom", "Bedroom", "Bathroom")
ROOM_TYPE_MAP = {"Study": "Bedroom", "Hallway": "LivingRoom", "LaundryRoom": "Bathroom",
                 "DiningRoom": "Kitchen", "KidsRoom": "Bedroom", "Garage": "LivingRoom",
                 "Balcony": "LivingRoom", "Office": "Bedroom", "Pantry": "Kitchen",
                 "Entryway": "LivingRoom"}


#: stand-ins for wall-mounted categories without an AI2-THOR type
WALL_TYPES = frozenset({"Painting", "Mirror"})
#: our choice of the ProcTHOR type that stands in for a category AI2-THOR has no type for (the
#: closest-size asset of that type is taken); categories not listed get the closest-size asset
#: of the same pickability (wall-mounted: a Painting/Mirror)
STAND_IN_TYPES = {
    "bookshelf": "ShelvingUnit", "pantry_shelf": "ShelvingUnit", "utility_shelf": "ShelvingUnit",
    "shoe_rack": "ShelvingUnit", "cabinet": "Dresser", "bathroom_vanity": "Dresser",
    "wardrobe": "Dresser", "filing_cabinet": "Dresser", "changing_table": "Dresser",
    "washing_machine": "WashingMachine", "dryer": "ClothesDryer", "crib": "Bed",
    "bench": "Ottoman", "step_stool": "Stool", "toy_box": "Box", "basket": "LaundryHamper",
    "curtain": "Blinds", "shower_stall": "ShowerCurtain", "toy": "TeddyBear", "doll": "TeddyBear",
    "toy_car": "TeddyBear", "shoe": "Boots", "sock": "Cloth", "shirt": "Cloth", "jacket": "Cloth",
    "coat": "Cloth", "hat": "Cloth", "scarf": "Cloth", "blanket": "Cloth", "diaper": "Cloth",
    "bath_mat": "Towel", "wet_wipe": "TissueBox", "headphones": "RemoteControl",
    "game_controller": "RemoteControl", "calculator": "CellPhone", "phone_charger": "CellPhone",
    "wallet": "CreditCard", "document": "Newspaper", "folder": "Newspaper",
    "photo_frame": "TableTopDecor", "medicine_bottle": "SoapBottle", "sunscreen": "SoapBottle",
    "toothpaste": "SoapBottle", "baby_bottle": "Bottle", "milk_carton": "Bottle",
    "banana": "Potato", "orange": "Apple", "onion": "Potato", "cheese": "Bread",
    "food_can": "Cup", "pet_food": "Bowl", "cutting_board": "Plate", "blender": "CoffeeMachine",
    "flower": "Vase", "first_aid_kit": "Box", "mop": "Plunger", "broom": "Plunger",
    "dustpan": "ScrubBrush", "bucket": "GarbageCan", "umbrella_stand": "GarbageCan",
    # AI2-THOR's Drawer is a part of its furniture, with no asset of its own in ProcTHOR: a Box
    # (an openable receptacle of a drawer's size) stands in for one exported on its own
    "drawer": "Box",
}
#: AI2-THOR object types that are not household things a task names: the obstacle class an
#: imported one is kept as (category = its snake-case type, judged for collisions and support
#: but not sized against the catalog) and why. Every other type in ProcTHOR's databases maps to
#: a catalog category (tests/test_real_houses.py checks both against the installed databases).
OBSTACLE_CLASSES: dict[str, tuple[str, str]] = {
    "Doorframe": ("opening", "a door's frame: houses give it as a door (imported as a door), not an object"),
    "Doorway": ("opening", "a doorway: imported as a door of type doorway, not an object"),
    "Window": ("opening", "a window: imported as a window, not an object"),
    "Floor": ("structure", "the floor itself (AI2-THOR's scenes list it as an object)"),
    "SinkBasin": ("part", "the basin of a sink: part of the sink"),
    "BathtubBasin": ("part", "the basin of a bathtub: part of the bathtub"),
    "Faucet": ("fixture", "mounted on a sink or bathtub; never moved"),
    "ShowerHead": ("fixture", "mounted on a wall; never moved"),
    "StoveKnob": ("fixture", "part of a stove's front"),
    "HandTowelHolder": ("fixture", "a rail on a wall; holds a towel"),
    "ToiletPaperHanger": ("fixture", "a holder on a wall; holds toilet paper"),
    "ShowerDoor": ("fixture", "a glass door of a shower stall"),
    "ShowerCurtain": ("fixture", "hangs from a rail of a shower"),
    "Blinds": ("fixture", "hang in a window"),
}
#: the opening sizes (width, height) we choose one wall-hole asset for
OPENING_TARGETS = {"door": ((0.9, 2.1), (1.6, 2.1)), "doorway": ((0.9, 2.1), (1.6, 2.1)),
                   "window": ((0.9, 1.2), (1.5, 1.2), (2.4, 1.2))}


@dataclass(frozen=True)
class Asset:
    asset_id: str
    object_type: str
    size: Size  # bounding box x, y, z in metres
    pickable: bool


@dataclass(frozen=True)
class Hole:
    """A wall hole: its size (x along the wall, y up) and the asset's offset in it."""

    size: tuple[float, float]
    offset: tuple[float, float]


@dataclass(frozen=True)
class ProcthorDB:
    assets: dict[str, Asset]
    materials: frozenset[str]
    holes: dict[str, Hole]
    source: str


_DB_HINT = "--procthor-db is ProcTHOR's procthor/databases folder"


def _read(path: Path) -> Any:
    """One database file, read as untrusted input (size limit, UTF-8, JSON) with one message."""
    text = read_text(path, what=f"ProcTHOR database file {path.name}", error=ConfigError,
                     max_bytes="max_env_bytes", hint=_DB_HINT)
    return parse_json(text, file=str(path), error=ConfigError)


def _hole(entry: dict[str, Any]) -> Hole:
    return Hole((entry["max"]["x"] - entry["min"]["x"], entry["max"]["y"] - entry["min"]["y"]),
                (entry["offset"]["x"], entry["offset"]["y"]))


def load_procthor_db(folder: str | Path) -> ProcthorDB:
    """Read ProcTHOR's asset, material and wall-hole databases from `folder`."""
    d = Path(folder)
    if not d.is_dir():
        raise ConfigError("not a folder" if d.exists() else "folder not found", file=str(d),
                          field="--procthor-db", hint=_DB_HINT)
    raw_assets, raw_mats, raw_holes = (_read(d / n) for n in (
        "asset-database.json", "material-database.json", "wall-holes.json"))
    try:
        assets = {a["assetId"]: Asset(a["assetId"], a["objectType"],
                                      (a["boundingBox"]["x"], a["boundingBox"]["y"], a["boundingBox"]["z"]),
                                      a.get("primaryProperty") == "CanPickup")
                  for group in raw_assets.values() for a in group}
        materials = frozenset(m for group in raw_mats.values() for m in group)
        holes = {k: _hole(v) for k, v in raw_holes.items()}
    except (KeyError, TypeError, AttributeError, ValueError, IndexError) as exc:
        raise ConfigError(f"not in ProcTHOR's database format ({type(exc).__name__}: "
                          f"{str(exc)[:200]})", file=str(d), hint=_DB_HINT) from None
    return ProcthorDB(assets, materials, holes, str(d))


def find_procthor_db() -> Path | None:
    """ProcTHOR's `procthor/databases` folder of the installed `procthor` package (the
    `[procthor]` extra), found without importing it (its import pulls heavy dependencies)."""
    try:
        spec = importlib.util.find_spec("procthor")
    except (ImportError, ValueError):
        return None
    for loc in (spec.submodule_search_locations or []) if spec is not None else []:
        folder = Path(loc) / "databases"
        if (folder / "asset-database.json").is_file():
            return folder
    return None


@lru_cache(maxsize=1)
def installed_procthor_db() -> ProcthorDB | None:
    """The installed ProcTHOR databases, read once, or None when the extra is not installed."""
    folder = find_procthor_db()
    return load_procthor_db(folder) if folder is not None else None


def _distance(a: Size, b: Size) -> float:
    """Size mismatch, rotation-free on the floor: |log ratio| of height, long and short side."""
    fa, fb = sorted((a[0], a[2])), sorted((b[0], b[2]))
    pairs = ((a[1], b[1]), (fa[1], fb[1]), (fa[0], fb[0]))
    return sum(abs(math.log(max(x, 1e-3) / max(y, 1e-3))) for x, y in pairs)


def closest(size: Size, candidates: list[Asset]) -> Asset:
    return min(candidates, key=lambda a: (_distance(size, a.size), a.asset_id))


def choose_assets(catalog: Catalog, db: ProcthorDB) -> dict[str, Any]:
    """Our mapping (the content of `procthor_assets.json`) chosen from the real databases."""
    by_type: dict[str, list[Asset]] = {}
    for a in db.assets.values():
        by_type.setdefault(a.object_type, []).append(a)
    structural = {"Doorway", "Doorframe", "Window"}
    loose = [a for a in db.assets.values() if a.object_type not in structural]
    on_wall = [a for a in loose if a.object_type in WALL_TYPES]
    categories = {}
    for name, cat in sorted(catalog.categories.items()):
        mean = tuple((lo + hi) / 2 for lo, hi in zip(cat.size_min, cat.size_max, strict=True))
        size: Size = (mean[0], mean[1], mean[2])
        own = by_type.get(cat.ai2thor_type or "", [])
        pool = own or by_type.get(STAND_IN_TYPES.get(name, ""), []) or (
            on_wall if cat.placement[0] == "wall" else [a for a in loose if a.pickable == cat.pickable])
        a = closest(size, pool)
        categories[name] = {"assetId": a.asset_id, "objectType": a.object_type,
                            "size": [round(v, 4) for v in a.size], "standIn": not own}
    openings: dict[str, dict[str, Any]] = {}
    for kind, otype in (("door", "Doorframe"), ("doorway", "Doorway"), ("window", "Window")):
        holes = {a.asset_id: (a, db.holes[a.asset_id.replace("Doorframe", "Doorway")])
                 for a in by_type.get(otype, [])
                 if a.asset_id.replace("Doorframe", "Doorway") in db.holes}
        for w, h in OPENING_TARGETS[kind]:
            aid = min(sorted(holes), key=partial(_fit, holes=holes, width=w, height=h))
            a, hole = holes[aid]
            openings.setdefault(kind, {})[aid] = {
                "hole": [round(v, 4) for v in hole.size], "offset": [round(v, 4) for v in hole.offset],
                "assetSize": [round(a.size[0], 4), round(a.size[1], 4)]}
    return {"categories": categories, "openings": openings}


def _fit(aid: str, holes: dict[str, tuple[Asset, Hole]], width: float, height: float) -> float:
    return _hole_distance(holes[aid][1], width, height)


def _hole_distance(hole: Hole, width: float, height: float) -> float:
    return (abs(math.log(hole.size[0] / max(width, 1e-3)))
            + abs(math.log(hole.size[1] / max(height, 1e-3))))


@lru_cache(maxsize=4)
def load_mapping(path: str | None = None) -> dict[str, Any]:
    """Our recorded choice of ProcTHOR ids (benchmark_data/procthor_assets.json)."""
    p = Path(path) if path else MAPPING_FILE
    data: dict[str, Any] = _read(p)
    return data


def mapping_db(mapping: dict[str, Any]) -> ProcthorDB:
    """The part of ProcTHOR our mapping names, as a database (for checks without the real one)."""
    assets = {c["assetId"]: Asset(c["assetId"], c["objectType"], (c["size"][0], c["size"][1], c["size"][2]), False)
              for c in mapping["categories"].values()}
    holes = {}
    for kind, ids in mapping["openings"].items():
        for aid, o in ids.items():
            otype = {"door": "Doorframe", "doorway": "Doorway", "window": "Window"}[kind]
            assets[aid] = Asset(aid, otype, (o["assetSize"][0], o["assetSize"][1], 0.1), False)
            holes[aid.replace("Doorframe", "Doorway")] = Hole((o["hole"][0], o["hole"][1]),
                                                              (o["offset"][0], o["offset"][1]))
    materials = frozenset(mapping["materials"].values())
    return ProcthorDB(assets, materials, holes, f"our mapping ({MAPPING_FILE.name})")


@lru_cache(maxsize=1)
def our_assets() -> ProcthorDB:
    """The assets our recorded mapping names, as a database (what we know without ProcTHOR's)."""
    return mapping_db(load_mapping())


def opening_asset(mapping: dict[str, Any], kind: str, width: float, height: float) -> tuple[str, Hole]:
    """The door/doorway/window asset of the mapping whose hole is closest to width x height."""
    ids = mapping["openings"][kind]
    holes = {k: Hole((o["hole"][0], o["hole"][1]), (o["offset"][0], o["offset"][1]))
             for k, o in ids.items()}
    best = min(sorted(holes), key=lambda k: _hole_distance(holes[k], width, height))
    return best, holes[best]
