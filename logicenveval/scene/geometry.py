"""Axis-aligned rectangles and wall edges in the x–z floor plane (metres)."""

from __future__ import annotations

from dataclasses import dataclass

EPS = 1e-6


@dataclass(frozen=True)
class Rect:
    x0: float
    z0: float
    x1: float
    z1: float

    @property
    def w(self) -> float:
        return self.x1 - self.x0

    @property
    def d(self) -> float:
        return self.z1 - self.z0

    @property
    def area(self) -> float:
        return self.w * self.d

    def polygon(self) -> list[tuple[float, float]]:
        return [(self.x0, self.z0), (self.x1, self.z0), (self.x1, self.z1), (self.x0, self.z1)]

    def overlaps(self, o: Rect) -> bool:
        return self.x0 < o.x1 - EPS and o.x0 < self.x1 - EPS and self.z0 < o.z1 - EPS and o.z0 < self.z1 - EPS


@dataclass(frozen=True)
class Edge:
    """A wall edge of a room: `axis` 'x' runs along x at z=`at`; `inward` is ±1 into the room."""

    side: str  # n/s/e/w
    axis: str
    at: float
    lo: float
    hi: float
    inward: int

    def point(self, t: float) -> tuple[float, float]:
        return (t, self.at) if self.axis == "x" else (self.at, t)


def edges(r: Rect) -> dict[str, Edge]:
    """n = max z, s = min z, e = max x, w = min x."""
    return {
        "s": Edge("s", "x", r.z0, r.x0, r.x1, 1),
        "n": Edge("n", "x", r.z1, r.x0, r.x1, -1),
        "w": Edge("w", "z", r.x0, r.z0, r.z1, 1),
        "e": Edge("e", "z", r.x1, r.z0, r.z1, -1),
    }


def subtract(lo: float, hi: float, cuts: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The parts of [lo, hi] not covered by `cuts`."""
    out = [(lo, hi)]
    for a, b in cuts:
        nxt = []
        for u, v in out:
            if b <= u + EPS or a >= v - EPS:
                nxt.append((u, v))
                continue
            if a > u + EPS:
                nxt.append((u, a))
            if b < v - EPS:
                nxt.append((b, v))
        out = nxt
    return out


def shared(a: Edge, b: Edge) -> tuple[float, float] | None:
    """The common stretch of two collinear edges facing each other, or None."""
    if a.axis != b.axis or abs(a.at - b.at) > EPS or a.inward == b.inward:
        return None
    lo, hi = max(a.lo, b.lo), min(a.hi, b.hi)
    return (lo, hi) if hi - lo > EPS else None
