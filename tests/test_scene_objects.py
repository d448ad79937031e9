"""Object selection helpers: category resolution, sizes, enrichment, trajectory facts."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from logicenveval.domain.catalog import load_catalog
from logicenveval.errors import CatalogError
from logicenveval.scene.objects import (
    apply_trajectory_states,
    enrichment_objects,
    resolve_category,
    sample_size,
)
from logicenveval.scene.spec import ObjectRequest

CAT = load_catalog()


def test_resolve_exact_synonym_plural_and_unknown() -> None:
    assert resolve_category("sofa", CAT) == ("sofa", None)
    assert resolve_category("Coffee Table", CAT) == ("coffee_table", None)
    assert resolve_category("sofas", CAT) == ("sofa", None)
    syn = next((n, c.synonyms[0]) for n, c in CAT.categories.items() if c.synonyms)
    assert resolve_category(syn[1], CAT)[0] == syn[0]
    name, warning = resolve_category("big comfy sofa thing", CAT)
    assert name in CAT.categories and warning is not None and "sofa" in name


@given(st.text(max_size=30))
def test_resolve_never_crashes(text: str) -> None:
    name, _ = resolve_category(text, CAT)
    assert name in CAT.categories


@given(st.sampled_from(sorted(CAT.categories)), st.integers(0, 2**32 - 1))
def test_sample_size_within_range(name: str, seed: int) -> None:
    cat = CAT.categories[name]
    size = sample_size(cat, np.random.default_rng(seed))
    assert all(lo <= v <= hi for lo, v, hi in zip(cat.size_min, size, cat.size_max, strict=True))


def test_enrichment_by_room_type() -> None:
    bed = enrichment_objects("Bedroom", np.random.default_rng(0), 40, CAT, room="bedroom")
    kitchen = enrichment_objects("Kitchen", np.random.default_rng(0), 40, CAT, room="kitchen", exclude=["fridge"])
    assert "bed" in {o.category for o in bed}
    assert "bed" not in {o.category for o in kitchen} and "fridge" not in {o.category for o in kitchen}
    assert all(not o.is_task and o.room == "kitchen" for o in kitchen)
    again = enrichment_objects("Kitchen", np.random.default_rng(0), 40, CAT, room="kitchen", exclude=["fridge"])
    assert kitchen == again


def test_apply_trajectory_states() -> None:
    objs = [ObjectRequest(id="toy_1", category="toy", room="r", role="toy"),
            ObjectRequest(id="fridge_1", category="fridge", room="r", role="fridge"),
            ObjectRequest(id="table_1", category="coffee_table", room="r", role="table"),
            ObjectRequest(id="box_1", category="toy_box", room="r", role="box")]
    out = apply_trajectory_states(objs, {
        "toy": {"attributes": {"kind": "doll"}, "container": "box_1"},
        "fridge": {"states": {"open": False}},
        "table": {"states": {"dirty": True}}}, CAT)
    by = {o.id: o for o in out}
    assert by["toy_1"].attributes == {"kind": "doll"} and by["toy_1"].container == "box_1"
    assert by["fridge_1"].states["open"] is False and by["table_1"].states["dirty"] is True
    with pytest.raises(CatalogError, match="ghost"):
        apply_trajectory_states(objs, {"ghost": {}}, CAT)
