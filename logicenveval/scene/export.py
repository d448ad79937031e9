"""Exporters: EnvSpec → ProcTHOR house JSON (loadable by AI2-THOR) and → GLB (any 3D viewer).

House JSON follows ProcTHOR's schema 1.0.0 layout (its generation code: house.py, doors.py,
wall_objects.py) and the fields AI2-THOR reads (`ProceduralData.cs`: `HouseObject`,
`HouseMetadata.agentPoses`, `Door`, `Window`, `PolygonWall`, `RoomHierarchy`): `rooms` with `floorPolygon` and one of ProcTHOR's four `roomType`s, one
`walls` entry per room side and per stretch (a room edge is split wherever another room's edge
starts or ends, so a shared stretch is one wall on each side), `doors`/`windows` with
`room0/room1`, `wall0/wall1`, a real wall-hole `assetId` and its `holePolygon`/`assetPosition`
placed as ProcTHOR places them, and `objects` with a real `assetId`/`objectType` (our recorded
choice per category, `scene/procthor.py`), `position`, `rotation`, `room`, `openness`, `isOn`,
`isDirty`; an object on or inside another is listed among that object's `children`. What
AI2-THOR has no field for stays in `logicenveval*` side fields (original room type and
category, other state flags, size and hole-size differences to the chosen assets).
"""

from __future__ import annotations

import hashlib
import math
from typing import Any

import numpy as np
import shapely
from shapely import STRtree
from shapely.geometry import Polygon

from logicenveval.domain.catalog import Catalog
from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import EnvObject, EnvSpec
from logicenveval.scene.procthor import (
    AI2THOR_ROOM_TYPES,
    ROOM_TYPE_MAP,
    load_mapping,
    opening_asset,
)

Seg = tuple[tuple[float, float], tuple[float, float]]


#: largest magnitude of a coordinate, size or angle an export writes (a house is metres wide)
MAX_MAGNITUDE = 1e6


def check_exportable(env: EnvSpec, *, positions: bool) -> None:
    """Refuse what no house or scene can hold: a non-finite number anywhere in the geometry, a
    number beyond `MAX_MAGNITUDE` (finite, but a GLB stores float32, where 1e300 is infinite, and
    sums and products of it overflow), a room without a polygon, and (`positions`) an object
    without a position."""
    def finite(values: tuple[float, ...] | list[float], where: str) -> None:
        bad = next((v for v in values if not math.isfinite(v) or abs(v) > MAX_MAGNITUDE), None)
        if bad is not None:
            what = "non-finite number" if not math.isfinite(bad) else \
                f"number {bad:.3g} beyond +-{MAX_MAGNITUDE:g} (metres or degrees)"
            raise EnvSpecError(f"{what} in the geometry", field=where,
                               hint="geometry is finite numbers in metres and degrees; fix or "
                               "re-generate the environment (`check-env` lists the problems)")

    finite([env.wall_height], "wall_height")
    for r in env.rooms:
        if r.polygon is None:
            raise EnvSpecError(f"room {r.id} has no polygon", field=f"rooms.{r.id}.polygon",
                               hint="export only constructed environments (with geometry)")
        finite([v for p in r.polygon for v in p], f"rooms.{r.id}.polygon")
    for d in env.doors:
        finite([d.height, *(v for p in d.segment or () for v in p)], f"doors.{d.id}")
    for w in env.windows:
        finite([w.sill, w.height, *(v for p in w.segment or () for v in p)], f"windows.{w.id}")
    for o in env.objects:
        if positions and o.position is None:
            raise EnvSpecError(f"object {o.id} has no position", field=f"objects.{o.id}.position",
                               hint="give every object a position (its bounding-box centre, metres); "
                               "AI2-THOR places each object where the house says")
        finite([o.yaw, *(o.position or ()), *(o.size or ())], f"objects.{o.id}")


def _p(x: float, y: float, z: float) -> dict[str, float]:
    return {"x": round(x, 4), "y": round(y, 4), "z": round(z, 4)}


def _poly(env: EnvSpec, rid: str) -> list[tuple[float, float]]:
    room = next(r for r in env.rooms if r.id == rid)
    if room.polygon is None:
        raise EnvSpecError(f"room {rid} has no polygon", field=f"rooms.{rid}.polygon",
                           hint="export only constructed environments (with geometry)")
    return [(float(x), float(z)) for x, z in room.polygon]


def _edges(poly: list[tuple[float, float]]) -> list[Seg]:
    """The polygon's sides, without zero-length ones (repeated points)."""
    sides = [(poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly))]
    return [(a, b) for a, b in sides if math.dist(a, b) > 1e-9]


class _Segments:
    """Segments with a spatial index: the candidates near a segment in O(log n + k)."""

    def __init__(self, segs: list[Seg]) -> None:
        self.segs = segs
        self._tree = STRtree(shapely.linestrings(np.asarray(segs, float))) if segs else None

    def near(self, seg: Seg, pad: float = 1e-4) -> list[int]:
        return self.near_all([seg], pad)[0]

    def near_all(self, segs: list[Seg], pad: float = 1e-4) -> list[list[int]]:
        """For each of `segs`, the indexed segments within `pad` of it (one bulk query)."""
        out: list[list[int]] = [[] for _ in segs]
        if self._tree is None or not segs:
            return out
        pairs = self._tree.query(shapely.linestrings(np.asarray(segs, float)), predicate="dwithin",
                                 distance=pad)
        for q, i in sorted(zip(pairs[0].tolist(), pairs[1].tolist(), strict=True)):
            out[q].append(i)
        return out


def _along(seg: Seg, a: tuple[float, float], b: tuple[float, float], tol: float) -> list[float] | None:
    """Offsets of `seg`'s ends along the line a→b, or None when an end lies off that line."""
    length = math.dist(a, b)
    ux, uz = (b[0] - a[0]) / length, (b[1] - a[1]) / length
    ts = []
    for px, pz in seg:
        if abs((px - a[0]) * uz - (pz - a[1]) * ux) > tol:
            return None
        ts.append((px - a[0]) * ux + (pz - a[1]) * uz)
    return ts


def _wall_id(rid: str, a: tuple[float, float], b: tuple[float, float]) -> str:
    return f"wall|{rid}|{a[0]:.2f}|{a[1]:.2f}|{b[0]:.2f}|{b[1]:.2f}"


def _stretches(env: EnvSpec) -> list[tuple[str, tuple[float, float], tuple[float, float]]]:
    """(room, start, end) of every wall stretch: each room side cut wherever another room's
    side starts or ends on it (found through a spatial index, so near-linear in the sides)."""
    owners: list[str] = []
    segs: list[Seg] = []
    for r in env.rooms:
        for seg in _edges(_poly(env, r.id)):
            owners.append(r.id)
            segs.append(seg)
    near = _Segments(segs).near_all(segs, pad=1e-6)
    out = []
    for rid, seg, close in zip(owners, segs, near, strict=True):
        (ax, az), (bx, bz) = seg
        length = math.dist(seg[0], seg[1])
        cuts = {0.0, length}
        for j in close:
            if owners[j] == rid:
                continue
            for t in _along(segs[j], seg[0], seg[1], 1e-6) or ():
                if 1e-6 < t < length - 1e-6:
                    cuts.add(round(t, 6))
        ordered = sorted(cuts)
        for t0, t1 in zip(ordered, ordered[1:], strict=False):
            p0 = (round(ax + (bx - ax) * t0 / length, 4), round(az + (bz - az) * t0 / length, 4))
            p1 = (round(ax + (bx - ax) * t1 / length, 4), round(az + (bz - az) * t1 / length, 4))
            if p0 != p1:
                out.append((rid, p0, p1))
    return out


def _walls(env: EnvSpec, material: str = "Drywall") -> list[dict[str, Any]]:
    """ProcTHOR walls: one per room stretch, plus the exterior side of every stretch that no
    other room shares."""
    h = round(env.wall_height, 4)

    def wall(rid: str, a: tuple[float, float], b: tuple[float, float]) -> dict[str, Any]:
        # the stretch ends are rounded already (`_stretches`): no rounding per point
        return {"id": _wall_id(rid, a, b), "roomId": rid, "material": {"name": material},
                "polygon": [{"x": a[0], "y": 0, "z": a[1]}, {"x": b[0], "y": 0, "z": b[1]},
                            {"x": b[0], "y": h, "z": b[1]}, {"x": a[0], "y": h, "z": a[1]}]}

    stretches = _stretches(env)
    pieces = {(a, b) for _, a, b in stretches}
    return ([wall(rid, a, b) for rid, a, b in stretches]
            + [wall("exterior", b, a) for _, a, b in stretches if (b, a) not in pieces])


def _base(w: dict[str, Any]) -> Seg:
    return ((w["polygon"][0]["x"], w["polygon"][0]["z"]), (w["polygon"][1]["x"], w["polygon"][1]["z"]))


class _Walls:
    """The walls of a house, indexed to find the one holding an opening."""

    def __init__(self, walls: list[dict[str, Any]]) -> None:
        self.walls = walls
        self._index = _Segments([_base(w) for w in walls])

    def host(self, rid: str, seg: Seg) -> tuple[dict[str, Any], float, float]:
        """The wall of room `rid` holding `seg`, and the opening's offsets along it."""
        for i in self._index.near(seg):
            w = self.walls[i]
            if w["roomId"] != rid:
                continue
            a, b = _base(w)
            ts = _along(seg, a, b, 1e-4)
            if ts is not None and min(ts) >= -1e-4 and max(ts) <= math.dist(a, b) + 1e-4:
                return w, min(ts), max(ts)
        raise EnvSpecError(f"opening {seg} lies on no wall of room {rid}", field="doors/windows",
                           hint="check the environment with `check-env` first")


#: our state flags that AI2-THOR house JSON names (ProcTHOR's object_states.py / objects.py);
#: `open` becomes `openness`, the others stay in `logicenvevalStates`
_AI2THOR_STATES = {"toggled_on": "isOn", "dirty": "isDirty"}


def _opening(walls: _Walls, rid: str, seg: Seg, mapping: dict[str, Any], kind: str,
             y0: float, height: float) -> tuple[dict[str, Any], dict[str, Any]]:
    """ProcTHOR's hole and asset placement (doors.py / wall_objects.py) of the mapping's asset
    closest in size, centred on our opening: (fields of the door/window, its host wall)."""
    wall, t0, t1 = walls.host(rid, seg)
    asset_id, hole = opening_asset(mapping, kind, t1 - t0, height)
    asset_w, asset_h = mapping["openings"][kind][asset_id]["assetSize"]
    a = wall["polygon"][0]
    b = wall["polygon"][1]
    length = math.dist((a["x"], a["z"]), (b["x"], b["z"]))
    w, h = hole.size
    start = min(max((t0 + t1) / 2 - w / 2, 0.0), max(length - w, 0.0))
    ox, oy = hole.offset
    lo = _p(start - ox, y0, 0)
    hi = _p(start + w - ox, y0 + h - oy, 0)
    fields = {"assetId": asset_id, "holePolygon": [lo, hi],
              "assetPosition": _p(lo["x"] + ox + asset_w / 2, y0 + oy + asset_h / 2, 0),
              "logicenvevalOpening": {"start": round(t0, 4), "width": round(t1 - t0, 4), "height": round(height, 4),
                                      "holeSizeDifference": [round(w - (t1 - t0), 4), round(h - height, 4)]}}
    return fields, wall


def _agent_xz(env: EnvSpec) -> tuple[float, float]:
    """The agent's floor position, else the centre of its room's polygon (AI2-THOR needs one)."""
    if env.agent.position is not None:
        return env.agent.position[0], env.agent.position[1]
    rid = next((r.id for r in env.rooms if r.id == env.agent.room), env.rooms[0].id)
    poly = _poly(env, rid)
    return sum(x for x, _ in poly) / len(poly), sum(z for _, z in poly) / len(poly)


def to_procthor(env: EnvSpec, catalog: Catalog, mapping: dict[str, Any] | None = None) -> dict[str, Any]:
    """A ProcTHOR house dict for `env` that AI2-THOR can load: real asset ids, wall holes and
    materials from `mapping` (default: benchmark_data/procthor_assets.json)."""
    check_exportable(env, positions=True)
    m = mapping or load_mapping()
    mats = m["materials"]
    walls = _walls(env, mats["wall"])
    hosts = _Walls(walls)
    rooms = []
    for r in env.rooms:
        room = {"id": r.id, "roomType": r.type if r.type in AI2THOR_ROOM_TYPES else
                ROOM_TYPE_MAP.get(r.type, "LivingRoom"),
                "floorPolygon": [_p(x, 0, z) for x, z in _poly(env, r.id)],
                "floorMaterial": {"name": mats["floor"]}, "children": [], "ceilings": []}
        if room["roomType"] != r.type:
            room["logicenvevalRoomType"] = r.type
        rooms.append(room)
    doors = []
    for d in env.doors:
        if d.segment is None:
            continue
        r0, r1 = d.rooms
        if r0 == "exterior":
            r0, r1 = r1, r0
        kind = "doorway" if d.type in ("doorway", "open") else "door"  # an open boundary: a doorway
        fields, w0 = _opening(hosts, r0, d.segment, m, kind, 0.0, d.height)
        w1, _, _ = hosts.host(r1, d.segment)
        doors.append({"id": d.id, **fields, "room0": r0, "room1": r1 if r1 != "exterior" else r0,
                      "wall0": w0["id"], "wall1": w1["id"],
                      "openable": d.type not in ("doorway", "open") and r1 != "exterior",
                      "openness": 1 if d.state == "open" else 0, "logicenvevalDoorType": d.type})
    windows = []
    for w in env.windows:
        if w.segment is None:
            continue
        fields, w0 = _opening(hosts, w.room, w.segment, m, "window", w.sill, w.height)
        w1, _, _ = hosts.host("exterior", w.segment)
        windows.append({"id": w.id, **fields, "room0": w.room, "room1": w.room,
                        "wall0": w0["id"], "wall1": w1["id"], "openness": 1 if w.state == "open" else 0})
    by_parent: dict[str | None, list[EnvObject]] = {}
    for o in env.objects:
        parent = o.container or (o.support if o.support not in (None, "floor", "wall", "ceiling") else None)
        by_parent.setdefault(parent, []).append(o)

    def obj(o: EnvObject) -> dict[str, Any]:
        cat = catalog.get(o.category)
        chosen = m["categories"].get(o.category)
        extra = o.model_extra or {}
        if chosen is None and isinstance(extra.get("asset_id"), str):  # an imported obstacle keeps its asset
            chosen = {"assetId": extra["asset_id"], "objectType": str(extra.get("object_type") or o.category),
                      "size": None}
        if chosen is None:
            raise EnvSpecError(f"object {o.id}: category {o.category!r} has no ProcTHOR asset in "
                               "our mapping", field=f"objects.{o.id}.category",
                               hint="use a catalog category (benchmark_data/catalog.json)")
        assert o.position is not None  # check_exportable
        pos = o.position
        out: dict[str, Any] = {
            "id": o.id, "assetId": chosen["assetId"], "objectType": chosen["objectType"],
            "position": _p(*pos), "rotation": _p(0, o.yaw % 360, 0),
            "kinematic": not (cat.pickable if cat else False), "room": o.room,
            "openness": 1 if o.states.get("open") else 0,
            **{key: bool(o.states.get(flag)) for flag, key in _AI2THOR_STATES.items()},
            "children": [obj(c) for c in by_parent.get(o.id, [])],
            "logicenvevalCategory": o.category,
            "logicenvevalStates": {k: v for k, v in sorted(o.states.items())
                                   if k not in _AI2THOR_STATES and k != "open"}}
        if o.size is not None and chosen["size"] is not None:
            out["logicenvevalSizeDifference"] = [round(a - b, 4) for a, b in zip(chosen["size"], o.size, strict=True)]
        return out

    x, z = _agent_xz(env)
    agent: dict[str, Any] = {"horizon": 30, "standing": True, "rotation": _p(0, 0, 0),
                             "position": _p(x, 0.95, z)}
    return {"metadata": {"schema": "1.0.0", "agent": agent, "agentPoses": {"default": agent},
                         "source": f"logicenveval:{env.env_id}"},
            "proceduralParameters": {"floorColliderThickness": 1.0, "lights": [], "reflections": [],
                                     "ceilingMaterial": {"name": mats["ceiling"]}, "skyboxId": "SkyAlbany"},
            "rooms": rooms, "walls": walls, "doors": doors, "windows": windows,
            "objects": [obj(o) for o in by_parent.get(None, [])]}


def _colour(category: str) -> list[int]:
    h = hashlib.sha256(category.encode()).digest()
    return [60 + h[0] % 170, 60 + h[1] % 170, 60 + h[2] % 170, 255]


#: polygons with more vertices are cut by a grid before triangulating (GEOS's triangulation
#: is quadratic in one polygon's vertices: 40k take ~10 s whole, 0.2 s in 12 x 12 pieces)
_PIECE_VERTICES = 500


def _triangles(poly: list[tuple[float, float]]) -> tuple[np.ndarray, np.ndarray]:
    """A floor polygon as (vertices (m, 2), triangles (k, 3) counter-clockwise in (x, z)):
    GEOS's constrained Delaunay triangulation, of grid pieces when the polygon is large."""
    shape = shapely.make_valid(Polygon(poly))
    parts = [g for part in shapely.get_parts(shape) for g in shapely.get_parts(part)
             if g.geom_type == "Polygon"]
    if len(poly) > _PIECE_VERTICES:
        minx, minz, maxx, maxz = shape.bounds
        cells = math.ceil(math.sqrt(len(poly) / _PIECE_VERTICES))
        xs, zs = np.linspace(minx, maxx, cells + 1), np.linspace(minz, maxz, cells + 1)
        clipped = [shapely.clip_by_rect(g, xs[i], zs[j], xs[i + 1], zs[j + 1])
                   for g in parts for i in range(cells) for j in range(cells)]
        parts = [g for c in clipped for part in shapely.get_parts(c) for g in shapely.get_parts(part)
                 if g.geom_type == "Polygon" and not g.is_empty]
    if not parts:
        return np.empty((0, 2)), np.empty((0, 3), int)
    cdt = shapely.constrained_delaunay_triangles(shapely.MultiPolygon(parts))
    corners = shapely.get_coordinates(shapely.get_parts(cdt)).reshape(-1, 4, 2)[:, :3]
    verts, faces = np.unique(corners.reshape(-1, 2), axis=0, return_inverse=True)
    faces = faces.reshape(-1, 3)
    a, b, c = (verts[faces[:, k]] for k in range(3))
    area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    faces = np.where((area < 0)[:, None], faces[:, [0, 2, 1]], faces)
    return verts, faces[area != 0]


WALL_THICKNESS = 0.05
_WALL_COLOUR = [235, 232, 225, 255]


def _wall_pieces(env: EnvSpec) -> list[tuple[Seg, float, float]]:
    """Solid parts of the walls as (segment on the floor, bottom, top): every room edge once
    (a shared stretch only from one side), cut around the doors and windows on it."""
    done: set[tuple[tuple[float, float], tuple[float, float]]] = set()
    openings = [(d.segment, 0.0, d.height) for d in env.doors if d.segment is not None]
    openings += [(w.segment, w.sill, w.sill + w.height) for w in env.windows if w.segment is not None]
    walls = [(a, b) for _, a, b in _stretches(env)]
    near = _Segments([seg for seg, _, _ in openings]).near_all(walls)
    pieces: list[tuple[Seg, float, float]] = []
    for (a, b), close in zip(walls, near, strict=True):
        if (b, a) in done:
            continue
        done.add((a, b))
        length = math.dist(a, b)
        holes = []
        for i in close:
            seg, lo, hi = openings[i]
            ts = _along(seg, a, b, 1e-4)
            if ts is not None and min(ts) > -1e-4 and max(ts) < length + 1e-4:
                holes.append((max(min(ts), 0.0), min(max(ts), length), lo, hi))
        cuts = sorted({0.0, length, *(t for h in holes for t in h[:2])})
        ux, uz = (b[0] - a[0]) / length, (b[1] - a[1]) / length
        for t0, t1 in zip(cuts, cuts[1:], strict=False):
            if t1 - t0 < 1e-4:
                continue
            mid = (t0 + t1) / 2
            gap = next(((lo, hi) for h0, h1, lo, hi in holes if h0 <= mid <= h1), None)
            spans = [(0.0, env.wall_height)] if gap is None else [(0.0, gap[0]), (gap[1], env.wall_height)]
            seg = ((a[0] + ux * t0, a[1] + uz * t0), (a[0] + ux * t1, a[1] + uz * t1))
            pieces += [(seg, y0, y1) for y0, y1 in spans if y1 - y0 > 1e-4]
    return pieces


#: the 12 outward triangles of a box whose corners are numbered as in `_boxes`
_BOX_FACES = np.array([[0, 1, 2], [0, 2, 3], [4, 6, 5], [4, 7, 6], [0, 4, 5], [0, 5, 1],
                       [1, 5, 6], [1, 6, 2], [2, 6, 7], [2, 7, 3], [3, 7, 4], [3, 4, 0]])


def _boxes(pieces: list[tuple[Seg, float, float]], thickness: float) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces of one wall slab per piece, built at once (no mesh per piece)."""
    ends = np.array([[p0[0], p0[1], p1[0], p1[1], y0, y1] for (p0, p1), y0, y1 in pieces], float)
    p0, p1, y0, y1 = ends[:, 0:2], ends[:, 2:4], ends[:, 4], ends[:, 5]
    d = p1 - p0
    n = np.stack([-d[:, 1], d[:, 0]], axis=1) / np.linalg.norm(d, axis=1, keepdims=True) * thickness / 2
    corners2 = np.stack([p0 - n, p1 - n, p1 + n, p0 + n], axis=1)  # (k, 4, 2) around the base
    verts = np.empty((len(pieces), 8, 3))
    for level, ys in ((0, y0), (4, y1)):
        verts[:, level:level + 4, 0] = corners2[:, :, 0]
        verts[:, level:level + 4, 1] = ys[:, None]
        verts[:, level:level + 4, 2] = corners2[:, :, 1]
    faces = (_BOX_FACES[None, :, :] + 8 * np.arange(len(pieces))[:, None, None]).reshape(-1, 3)
    return verts.reshape(-1, 3), faces


def to_glb(env: EnvSpec) -> bytes:
    """A GLB scene: floor slabs per room, walls with door/window openings, and one box per
    object coloured by category."""
    import trimesh as _trimesh

    trimesh: Any = _trimesh  # trimesh is only partly typed
    check_exportable(env, positions=False)
    scene = trimesh.Scene()
    for r in env.rooms:
        flat, tris = _triangles(_poly(env, r.id))
        verts = np.column_stack([flat[:, 0], np.zeros(len(flat)), flat[:, 1]])
        slab = trimesh.Trimesh(vertices=verts, faces=tris[:, [0, 2, 1]], process=False)
        slab.visual.face_colors = [200, 200, 190, 255]
        scene.add_geometry(slab, node_name=f"floor_{r.id}")
    pieces = _wall_pieces(env)
    if pieces:  # one mesh for all walls: a mesh per piece costs ~0.4 ms each
        verts, faces = _boxes(pieces, WALL_THICKNESS)
        walls = trimesh.Trimesh(vertices=verts, faces=faces, process=False)
        walls.visual.face_colors = _WALL_COLOUR
        scene.add_geometry(walls, node_name="walls")
    for o in env.objects:
        if o.position is None or o.size is None:
            continue
        box = trimesh.creation.box(extents=o.size)
        yaw = math.radians(o.yaw)
        tf = trimesh.transformations.rotation_matrix(yaw, [0, 1, 0])
        tf[:3, 3] = o.position
        box.apply_transform(tf)
        box.visual.face_colors = _colour(o.category)
        scene.add_geometry(box, node_name=o.id)
    data = scene.export(file_type="glb")
    return bytes(data)
