"""The asset catalog (`benchmark_data/catalog.json`): categories with sizes and affordances.

The simulator reads `pickable`, `surface`, `container`, `openable`, `toggleable` and
`default_states`; the physics checker reads sizes and placement; scene construction reads rooms,
synonyms and attribute domains.
"""

from __future__ import annotations

import functools
import json
from collections.abc import Callable
from functools import lru_cache
from pathlib import Path
from typing import Literal, TypeVar

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from logicenveval.errors import CatalogError
from logicenveval.limits import read_text
from logicenveval.validation import first_error

Placement = Literal["floor", "surface", "wall", "ceiling", "inside"]

DEFAULT_CATALOG = Path(__file__).resolve().parents[2] / "benchmark_data" / "catalog.json"


class Category(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")
    size_min: tuple[float, float, float]  # width (x), height (y), depth (z) in metres
    size_max: tuple[float, float, float]
    placement: list[Placement] = Field(min_length=1)  # allowed placements, the first is typical
    pickable: bool = False
    surface: bool = False
    container: bool = False
    openable: bool = False
    toggleable: bool = False
    fillable: bool = False
    attributes: dict[str, list[str]] = Field(default_factory=dict)
    default_states: dict[str, bool] = Field(default_factory=dict)
    rooms: list[str] = Field(default_factory=list)
    synonyms: list[str] = Field(default_factory=list)
    ai2thor_type: str | None = None

    @model_validator(mode="after")
    def _sizes(self) -> Category:
        for lo, hi in zip(self.size_min, self.size_max, strict=True):
            if not 0 < lo <= hi:
                raise ValueError(f"need 0 < size_min <= size_max, got {self.size_min} / {self.size_max}")
        return self


class Catalog(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid", populate_by_name=True)
    schema_: Literal["logicenveval.catalog/1"] = Field("logicenveval.catalog/1", alias="schema")
    categories: dict[str, Category] = Field(min_length=1)

    def get(self, name: str) -> Category | None:
        return self.categories.get(name)

    def __contains__(self, name: object) -> bool:
        return name in self.categories

    def generator_categories(self) -> list[str]:
        """The categories a generator is offered (sorted): those with rooms to stand in. A
        category without rooms is known only to read environments made elsewhere (AI2-THOR types
        of imported houses, docs/catalog.md); offering it would change every prompt's vocabulary
        and with it every recorded request."""
        return sorted(name for name, cat in self.categories.items() if cat.rooms)


@lru_cache(maxsize=8)
def _load(path: str) -> Catalog:
    p = Path(path)
    text = read_text(p, what="catalog file", error=CatalogError, max_bytes="max_env_bytes",
                     hint="pass an existing catalog.json")
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise CatalogError(f"invalid JSON: {exc.msg}", file=path, line=exc.lineno, column=exc.colno,
                           hint="fix the JSON syntax") from None
    try:
        return Catalog.model_validate(data)
    except ValidationError as exc:
        loc, msg = first_error(exc)
        raise CatalogError(msg, file=path, field=loc, hint="see docs/catalog.md for the fields") from None


def load_catalog(path: str | Path | None = None) -> Catalog:
    """Load (and cache) a catalog; the default is the benchmark's `catalog.json`."""
    return _load(str(Path(path) if path else DEFAULT_CATALOG))


def reload_catalogs() -> None:
    """Forget every loaded catalog, so the next `load_catalog` reads its file again (the runner
    restores a catalog that a generator changed in place)."""
    _load.cache_clear()


_T = TypeVar("_T")


def per_catalog(build: Callable[[Catalog], _T]) -> Callable[[Catalog], _T]:
    """`build(catalog)` done once per catalog object (by identity: a catalog is a pydantic model,
    costly to hash and equal to its copies); the last 8 catalogs of the process are kept."""
    built: list[tuple[Catalog, _T]] = []

    @functools.wraps(build)
    def once(catalog: Catalog) -> _T:
        for cat, value in built:
            if cat is catalog:
                return value
        value = build(catalog)
        built.insert(0, (catalog, value))
        del built[8:]
        return value

    return once
