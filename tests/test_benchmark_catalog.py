"""The shipped catalog: schema, required categories, affordances of DESIGN.md §5, JSON round trip."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from logicenveval.domain.catalog import DEFAULT_CATALOG, Catalog, load_catalog
from logicenveval.errors import CatalogError
from logicenveval.model.rooms import ROOM_TYPES

REQUIRED = (Path(__file__).parent / "fixtures" / "benchmark_catalog_required.txt").read_text(
    encoding="utf-8").split()  # every category name the task authors may use


def test_catalog_is_large_and_complete() -> None:
    cat = load_catalog()
    assert len(cat.categories) >= 150
    assert [n for n in REQUIRED if n not in cat] == []


def test_affordances_follow_design() -> None:
    cat = load_catalog()
    for name in ("trash_can", "laundry_basket", "toy_box"):
        c = cat.categories[name]
        assert c.container and not c.openable, name
    for name in ("fridge", "cabinet", "wardrobe", "dresser", "microwave", "oven", "dishwasher",
                 "washing_machine", "dryer", "nightstand"):
        c = cat.categories[name]
        assert c.container and c.openable and c.default_states.get("open") is False, name
    for name in ("coffee_table", "dining_table", "kitchen_counter", "wall_shelf", "bed", "sofa", "desk"):
        assert cat.categories[name].surface, name
    for name in ("desk_lamp", "floor_lamp", "television", "stove"):
        c = cat.categories[name]
        assert c.toggleable and c.default_states.get("toggled_on") is False, name
    assert cat.categories["floor_stain"].default_states == {"dirty": True}
    assert cat.categories["water_puddle"].default_states == {"dirty": True, "wet": True}
    assert set(cat.categories["toy"].attributes["kind"]) == {"doll", "car", "ball", "puzzle", "teddy", "blocks"}
    assert "novel" in cat.categories["book"].attributes["kind"]
    assert "toy chest" in cat.categories["toy_box"].synonyms
    assert cat.categories["fridge"].ai2thor_type == "Fridge"


def _import_only() -> set[str]:
    """The categories added for AI2-THOR types (tools/add_ai2thor_categories.py): no rooms, so that
    generators never add them as enrichment; they type imported houses."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
    import add_ai2thor_categories

    # and the kinds added for issue 47's sentences (docs/catalog.md "A drawer is part of its
    # furniture"): read wherever a text names them, offered to no generator unasked
    return {entry[0] for entry in add_ai2thor_categories.NEW.values()} | {"drawer", "fuse"}


def test_rooms_and_sizes_are_plausible() -> None:
    cat = load_catalog()
    import_only = _import_only()
    for name, c in cat.categories.items():
        assert (not c.rooms if name in import_only else c.rooms) and set(c.rooms) <= set(ROOM_TYPES), name
        if c.pickable:
            assert max(c.size_max) <= 2.5, name
    sofa = cat.categories["sofa"]
    assert sofa.size_min[0] >= 1.5 and sofa.size_max[0] <= 2.5


def test_catalog_json_round_trip() -> None:
    cat = load_catalog()
    again = Catalog.model_validate(json.loads(cat.model_dump_json(by_alias=True)))
    assert again == cat
    raw = json.loads(DEFAULT_CATALOG.read_text(encoding="utf-8"))
    assert Catalog.model_validate(raw) == cat


def test_bad_catalog_names_field(tmp_path: Path) -> None:
    raw = json.loads(DEFAULT_CATALOG.read_text(encoding="utf-8"))
    raw["categories"]["sofa"]["size_min"] = [3.0, 0.8, 0.9]
    bad = tmp_path / "catalog.json"
    bad.write_text(json.dumps(raw), encoding="utf-8")
    with pytest.raises(CatalogError) as err:
        load_catalog(bad)
    assert "sofa" in str(err.value) and str(bad) in str(err.value)


def test_generators_are_offered_only_categories_with_rooms() -> None:
    """Categories kept only to read imported houses (no rooms) stay out of every prompt's
    vocabulary, so adding one changes no recorded request."""
    from logicenveval.domain.catalog import load_catalog

    catalog = load_catalog()
    offered = catalog.generator_categories()
    assert offered == sorted(offered) and offered
    assert all(catalog.categories[c].rooms for c in offered)
    assert any(not c.rooms for c in catalog.categories.values())  # the import-only ones exist
    assert set(offered) == {n for n, c in catalog.categories.items() if c.rooms}
