"""Object selection helpers: category lookup, sizes, enrichment by room type, trajectory facts."""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np

from logicenveval.domain.catalog import Catalog, Category
from logicenveval.domain.categories import singular, snake, vocabulary
from logicenveval.errors import CatalogError
from logicenveval.model.rooms import room_type_of
from logicenveval.scene.spec import ObjectRequest


def resolve_category(text: str, catalog: Catalog) -> tuple[str, str | None]:
    """Catalog category for free text (an LLM's reply): the one vocabulary
    (`domain.categories`: key, synonym, AI2-THOR type, any spelling or plural), else the
    lexically closest category, with a warning."""
    known = vocabulary(catalog).canonical(text)
    if known is not None:
        return known, None
    sing = singular(text)
    tokens = set(sing.split("_"))
    best, score = "", -1.0
    for name, cat in sorted(catalog.categories.items()):
        for cand in [name, *(snake(s) for s in cat.synonyms)]:
            ctoks = set(cand.split("_"))
            overlap = len(tokens & ctoks) / len(tokens | ctoks)
            s = overlap + difflib.SequenceMatcher(None, sing, cand).ratio()
            if s > score:
                best, score = name, s
    return best, f"unknown category {text!r}: using the closest catalog category {best!r}"


def category(catalog: Catalog, name: str) -> Category:
    cat = catalog.get(name)
    if cat is None:
        raise CatalogError(f"unknown category {name!r}", field="categories",
                           hint="resolve free text with scene.objects.resolve_category first")
    return cat


def sample_size(cat: Category, rng: np.random.Generator) -> tuple[float, float, float]:
    """A size within the category's range, on a 1 cm grid (rounded inwards)."""
    out = []
    for lo, hi in zip(cat.size_min, cat.size_max, strict=True):
        v = float(rng.uniform(lo, hi))
        out.append(min(max(round(v, 2), lo), hi))
    return (out[0], out[1], out[2])


def fits_room(cat: Category, room_type: str) -> bool:
    return not cat.rooms or room_type in cat.rooms or room_type_of(room_type) in cat.rooms


def enrichment_objects(room_type: str, rng: np.random.Generator, n: int, catalog: Catalog, *,
                       room: str, exclude: Iterable[str] = (), prefix: str = "extra") -> list[ObjectRequest]:
    """`n` enrichment objects that belong in `room_type` (catalog `rooms`), none of `exclude`.

    Only categories whose typical placement is the floor, a wall or the ceiling are offered:
    objects on surfaces need a surface the caller chooses.
    """
    rtype = room_type_of(room_type)
    banned = set(exclude)
    pool = sorted(name for name, c in catalog.categories.items()
                  if name not in banned and c.rooms and rtype in c.rooms
                  and c.placement[0] in ("floor", "wall", "ceiling"))
    if not pool or n <= 0:
        return []
    picks = rng.choice(len(pool), size=min(n, len(pool)), replace=False)
    out = []
    for k, i in enumerate(sorted(int(p) for p in picks)):
        name = pool[i]
        out.append(ObjectRequest(id=f"{prefix}_{name}_{k}", category=name, room=room,
                                 placement=catalog.categories[name].placement[0], task=False))
    return out


def apply_trajectory_states(objects: list[ObjectRequest], facts: Mapping[str, Mapping[str, Any]],
                            catalog: Catalog) -> list[ObjectRequest]:
    """Apply symbolic facts per role: `{role: {support, container, room, attributes, states}}`.

    Catalog default states come first, then the facts; `support` is `floor`, `wall` or an object
    id, `container` an object id. Roles not among the objects raise, so no fact is silently lost.
    """
    by_role = {o.role: i for i, o in enumerate(objects) if o.role}
    out = list(objects)
    for role, f in facts.items():
        if role not in by_role:
            raise CatalogError(f"fact about role {role!r}, which no object plays", field=f"facts.{role}",
                               hint=f"bind the role to one of the objects (roles: {sorted(by_role)})")
        o = out[by_role[role]]
        cat = catalog.get(o.category)
        states = {**(cat.default_states if cat else {}), **o.states, **dict(f.get("states", {}))}
        attrs = {**o.attributes, **dict(f.get("attributes", {}))}
        placement = o.placement
        if f.get("container"):
            placement = f"inside:{f['container']}"
        elif f.get("support"):
            s = str(f["support"])
            placement = s if s in ("floor", "wall", "ceiling") else f"on:{s}"
        out[by_role[role]] = o.model_copy(update={
            "states": states, "attributes": attrs, "placement": placement,
            "room": str(f.get("room", o.room))})
    return out
