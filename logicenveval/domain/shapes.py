"""Shapes, not only boxes: where objects rest on a receptacle and which parts of its box are solid.

`benchmark_data/support_shapes.json` is derived by `tools/derive_shapes.py` from AI2-THOR's own
scene metadata (settled bounding boxes of every object in its hand-built scenes, shipped in
ProcTHOR's databases): per AI2-THOR type, the `levels` where objects rest (sofa and armchair
seats, shelf bands of TV stands and shelving units, tops) and the `solid` parts of the box (a
seat below its seat height plus a back strip; a table, desk or coffee table only above the free
space under its top; a TV only above the free space in front of its foot). A catalog category takes the shape of its AI2-THOR type (`categories`).
Entity PhyPR uses them for every environment, whoever wrote it, and the layout solver places
objects on them (docs/physics.md "Shapes").
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from logicenveval.errors import ConfigError
from logicenveval.limits import parse_json, read_text

SHAPES_FILE = Path(__file__).resolve().parents[2] / "benchmark_data" / "support_shapes.json"


@dataclass(frozen=True)
class Part:
    """A solid part of a box, as fractions: y of its height (0 = bottom), z of its depth (0 = back)."""

    y: tuple[float, float]
    z: tuple[float, float]

    def local_box(self, half: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(centre, half extents) of the part in the body's local frame."""
        lo = np.array([-half[0], -half[1] + 2 * half[1] * self.y[0], -half[2] + 2 * half[2] * self.z[0]])
        hi = np.array([half[0], -half[1] + 2 * half[1] * self.y[1], -half[2] + 2 * half[2] * self.z[1]])
        return (lo + hi) / 2, np.maximum((hi - lo) / 2, 1e-6)


@dataclass(frozen=True)
class Shape:
    otype: str
    levels: tuple[tuple[float, float], ...]  # where objects rest, fractions of the height
    solid: tuple[Part, ...] | None  # None: the whole box is solid
    open_top: bool = False  # what it holds may stand out of its top (a sink, not a fridge)
    seat: float | None = None  # a seat's surface (fraction of the height): where things are put on it

    def surface(self) -> tuple[float, float]:
        """Where a layout puts things on it: (height fraction, depth fraction from the back where
        the usable area starts) — a seat in front of its back strip, else the whole top."""
        if self.seat is None:
            return 1.0, 0.0
        back = max((p.z[1] for p in self.solid or () if p.z[0] == 0.0 and p.z[1] < 1.0), default=0.0)
        return self.seat, back


@dataclass(frozen=True)
class Shapes:
    types: dict[str, Shape]
    categories: dict[str, str]

    def of(self, category: str) -> Shape | None:
        otype = self.categories.get(category)
        return self.types.get(otype) if otype is not None else None


def _shape(otype: str, entry: dict[str, Any]) -> Shape:
    levels = tuple((float(lo), float(hi)) for lo, hi in entry["levels"])
    solid = entry.get("solid")
    parts = tuple(Part((float(p["y"][0]), float(p["y"][1])), (float(p["z"][0]), float(p["z"][1])))
                  for p in solid) if solid else None
    seat = entry.get("seat")
    return Shape(otype, levels, parts, bool(entry.get("open_top", False)),
                 float(seat) if seat is not None else None)


@lru_cache(maxsize=4)
def load_shapes(path: str | None = None) -> Shapes:
    """The derived shapes (benchmark_data/support_shapes.json unless `path`)."""
    p = Path(path) if path else SHAPES_FILE
    text = read_text(p, what="support shapes file", error=ConfigError, max_bytes="max_env_bytes",
                     hint="regenerate it with python tools/derive_shapes.py")
    data = parse_json(text, file=str(p), error=ConfigError)
    try:
        types = {t: _shape(t, e) for t, e in data["types"].items()}
        return Shapes(types, {str(k): str(v) for k, v in data["categories"].items()})
    except (KeyError, TypeError, ValueError, IndexError) as exc:
        raise ConfigError(f"not a support shapes file ({type(exc).__name__}: {str(exc)[:200]})", file=str(p),
                          hint="regenerate it with python tools/derive_shapes.py") from None


def support_gap(bottom: float, s_bottom: float, s_top: float, shape: Shape | None) -> float:
    """Signed distance (m) from `bottom` to the nearest height where the receptacle holds objects:
    > 0 above it, < 0 below it, 0 on it. Without a shape that height is the top of the box."""
    height = s_top - s_bottom
    bands = shape.levels if shape is not None else ((1.0, 1.0),)
    best = None
    for lo, hi in bands:
        a, b = s_bottom + lo * height, s_bottom + hi * height
        gap = bottom - b if bottom > b else (bottom - a if bottom < a else 0.0)
        if best is None or abs(gap) < abs(best):
            best = gap
    assert best is not None
    return best


__all__ = ["SHAPES_FILE", "Part", "Shape", "Shapes", "load_shapes", "support_gap"]
