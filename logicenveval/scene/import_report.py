"""A room-level account of an imported house: what was typed, sized, settled and judged, and why.

`import_house` says where each object's type and size came from; this joins that with the PhyPR
judgement of the imported environment (`physics.check_env`), per room: how many objects got a
catalog category, which were kept as obstacles (and of which class: `scene.procthor.
OBSTACLE_CLASSES`) or as unknown types, where sizes came from, which objects rest a short drop
above their support and settle onto it (`Tolerances.settle_drop`), and the entity failures left.
`import-house` prints it; `benchmarks/real_scenes.py` sums it per house.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from logicenveval.domain.catalog import Catalog
from logicenveval.domain.shapes import load_shapes, support_gap
from logicenveval.physics.check import check_env
from logicenveval.physics.geometry import build_bodies
from logicenveval.physics.report import DEFAULT_TOLERANCES, PhysicsReport, Tolerances
from logicenveval.scene.house_import import ImportReport


@dataclass
class RoomImport:
    room: str
    source_id: str
    objects: int = 0
    typed: int = 0  # with a catalog category
    obstacles: Counter[str] = field(default_factory=Counter)  # obstacle class -> count
    unknown: list[str] = field(default_factory=list)  # objects of a type with neither
    sizes: Counter[str] = field(default_factory=Counter)  # size source -> count
    settled: list[str] = field(default_factory=list)  # a short drop above their support
    failed: dict[str, list[str]] = field(default_factory=dict)  # object -> entity failure codes


@dataclass
class HouseImport:
    rooms: list[RoomImport]
    physics: PhysicsReport

    @property
    def objects(self) -> int:
        return sum(r.objects for r in self.rooms)

    @property
    def entity_failed(self) -> int:
        return sum(len(r.failed) for r in self.rooms)


def _settled(report: ImportReport, tol: Tolerances) -> set[str]:
    """Objects whose bottom is above their support by more than `support_gap` and at most
    `settle_drop`: AI2-THOR's physics drops them onto it on load."""
    env = report.env
    bodies = build_bodies(env)
    out = set()
    for b in bodies.values():
        sup = b.obj.support
        if sup == "floor":
            gap = b.bottom
        elif sup in bodies:
            s = bodies[sup]
            gap = support_gap(b.bottom, s.bottom, s.top, load_shapes().of(s.obj.category))
        else:
            continue
        if tol.support_gap < gap <= tol.settle_drop:
            out.add(b.id)
    return out


def house_report(report: ImportReport, catalog: Catalog, *, tolerances: Tolerances = DEFAULT_TOLERANCES
                 ) -> HouseImport:
    env = report.env
    physics = check_env(env, catalog, tolerances=tolerances)
    rooms = {r.id: RoomImport(r.id, report.room_sources.get(r.id, r.id)) for r in env.rooms}
    settled = _settled(report, tolerances)
    failed: dict[str, list[str]] = {}
    for f in physics.entity.failures:
        for oid in f.objects[:1] if f.code != "interpenetration" else f.objects:
            failed.setdefault(oid, []).append(f.code)
    for o in env.objects:
        r = rooms.get(o.room)
        if r is None:
            continue
        r.objects += 1
        if o.id in report.obstacles:
            r.obstacles[report.obstacles[o.id]] += 1
        elif o.category in catalog:
            r.typed += 1
        else:
            r.unknown.append(o.id)
        r.sizes[report.size_of.get(o.id, "none")] += 1
        if o.id in settled:
            r.settled.append(o.id)
        if o.id in failed:
            r.failed[o.id] = sorted(set(failed[o.id]))
    return HouseImport(list(rooms.values()), physics)


def format_rooms(house: HouseImport) -> list[str]:
    """One line per room, for the terminal."""
    lines = []
    for r in house.rooms:
        obst = ", ".join(f"{n} {c}" for c, n in sorted(r.obstacles.items()))
        sizes = ", ".join(f"{n} {s}" for s, n in sorted(r.sizes.items()))
        lines.append(f"  {r.room} ({r.source_id}): {r.objects} object(s), {r.typed} typed"
                     + (f", obstacles: {obst}" if obst else "")
                     + (f", unknown: {', '.join(r.unknown)}" if r.unknown else "")
                     + (f"; sizes from {sizes}" if sizes else "")
                     + (f"; {len(r.settled)} settle onto their support" if r.settled else "")
                     + ("; entity failures: " + ", ".join(f"{k} ({'/'.join(v)})" for k, v in r.failed.items())
                        if r.failed else ""))
    return lines


__all__ = ["HouseImport", "RoomImport", "format_rooms", "house_report"]
