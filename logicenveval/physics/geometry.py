"""Geometry of an EnvSpec: room polygons, walls, and objects as oriented boxes (or meshes).

Convention (AI2-THOR): y is up, the floor is the x–z plane. `position` is the bounding-box
centre, `size` the extents along x, y, z before the rotation `yaw` (degrees) about y. A positive
yaw maps the local front +z to (sin yaw, 0, cos yaw), so yaw 0 faces +z and yaw 90 faces +x.
Collision shapes are python-fcl objects built once per object; the broad phase is a
sort-and-sweep over axis-aligned bounds so that only overlapping candidates reach fcl.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import fcl
import numpy as np
import shapely
from shapely.geometry import LineString, Polygon
from shapely.geometry.base import BaseGeometry

from logicenveval.domain.shapes import load_shapes
from logicenveval.model.envspec import EnvObject, EnvSpec

_SIGNS = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
_BOX_FOOTPRINT = [0, 4, 5, 1]  # indices of _SIGNS at y = -1 going round the x–z rectangle


def yaw_matrix(yaw_deg: float) -> np.ndarray:
    """Rotation about +y by `yaw_deg` (local +z → (sin, 0, cos))."""
    t = math.radians(yaw_deg)
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


@dataclass(frozen=True)
class Body:
    """One object with geometry: oriented box frame, footprint and fcl collision object.

    The fcl objects (`collision`, `parts`) are built on first use: only the pairs the broad
    phase cannot call apart reach fcl, a few of an environment's objects."""

    obj: EnvObject
    center: np.ndarray      # (3,)
    half: np.ndarray        # (3,) half extents in the local frame
    rot: np.ndarray         # (3, 3) local → world
    footprint: Polygon      # x–z projection
    bottom: float
    top: float
    aabb_min: np.ndarray
    aabb_max: np.ndarray
    #: the convex hull of the mesh file (None: the box is the shape)
    hull: fcl.CollisionGeometry | None = None

    @property
    def is_box(self) -> bool:
        """False: the convex hull of a mesh file."""
        return self.hull is None

    @cached_property
    def collision(self) -> fcl.CollisionObject:
        geom = self.hull if self.hull is not None else fcl.Box(*(2.0 * self.half))
        return fcl.CollisionObject(geom, fcl.Transform(self.rot, self.center))

    @cached_property
    def parts(self) -> tuple[fcl.CollisionObject, ...] | None:
        """The solid parts of the box where its shape says only parts are solid (domain.shapes)."""
        return _solid_parts(self.obj, self.center, self.half, self.rot) if self.hull is None else None

    @property
    def id(self) -> str:
        return self.obj.id

    @property
    def xz(self) -> np.ndarray:
        return np.array([self.center[0], self.center[2]])

    def front(self) -> np.ndarray:
        """Unit front direction (local +z) in the x–z plane."""
        return np.array([self.rot[0, 2], self.rot[2, 2]])

    def right(self) -> np.ndarray:
        """Unit local +x direction in the x–z plane."""
        return np.array([self.rot[0, 0], self.rot[2, 0]])

    def to_local(self, points: np.ndarray) -> np.ndarray:
        local: np.ndarray = (points - self.center) @ self.rot
        return local

    def corners(self) -> np.ndarray:
        world: np.ndarray = self.center + (_SIGNS * self.half) @ self.rot.T
        return world

    def back_face_segment(self) -> LineString:
        """The floor projection of the local −z face (what a wall-mounted object hangs by)."""
        hx, hz = self.half[0], self.half[2]
        pts = [self.center + self.rot @ np.array([sx * hx, 0.0, -hz]) for sx in (-1.0, 1.0)]
        return LineString([(p[0], p[2]) for p in pts])


def mesh_path(obj: EnvObject, base_dir: Path | None) -> Path | None:
    """Where the object's mesh file is expected, or None when it names none."""
    if not obj.mesh:
        return None
    path = Path(obj.mesh)
    return base_dir / path if not path.is_absolute() and base_dir is not None else path


def _mesh_vertices(obj: EnvObject, base_dir: Path | None) -> np.ndarray | None:
    """Local-frame vertices (centred on the bounding box) of the object's mesh, if it exists."""
    path = mesh_path(obj, base_dir)
    if path is None or not path.is_file():
        return None  # reported as `mesh_not_found` by the entity check; the box stands in
    import trimesh  # only for mesh files: importing it (and SciPy) costs a second per process

    mesh = trimesh.load(str(path), force="mesh")
    assert isinstance(mesh, trimesh.Trimesh)
    verts = np.asarray(mesh.vertices, dtype=np.float64)
    centred: np.ndarray = verts - (verts.min(axis=0) + verts.max(axis=0)) / 2.0
    return centred


def build_body(obj: EnvObject, mesh_dir: Path | None = None) -> Body:
    """Geometry of one object; the caller ensures `position` and `size` are set."""
    return _build([obj], mesh_dir)[0]


def _build(objects: list[EnvObject], mesh_dir: Path | None) -> list[Body]:
    """`build_body` of each object: per object its frame and corners, then the footprints and
    bounds of all boxes in one vectorised step each (the same numbers, fewer calls)."""
    frames = []
    for obj in objects:
        assert obj.position is not None and obj.size is not None
        center = np.asarray(obj.position, float)
        half = np.asarray(obj.size, float) / 2.0
        rot = yaw_matrix(obj.yaw)
        verts = _mesh_vertices(obj, mesh_dir)
        local = _SIGNS * half if verts is None else verts
        frames.append((obj, center, half, rot, verts, center + local @ rot.T))
    boxes = [k for k, f in enumerate(frames) if f[4] is None]
    footprints: list[Polygon] = [Polygon()] * len(frames)
    lo: list[np.ndarray] = [np.zeros(3)] * len(frames)
    hi = list(lo)
    if boxes:
        corners = np.stack([frames[k][5] for k in boxes])
        rects = shapely.polygons(corners[:, _BOX_FOOTPRINT][:, :, ::2])  # x, z of the bottom
        lows, highs = corners.min(axis=1), corners.max(axis=1)
        for n, k in enumerate(boxes):
            footprints[k], lo[k], hi[k] = rects[n], lows[n], highs[n]
    out = []
    for k, (obj, center, half, rot, verts, world) in enumerate(frames):
        hull_geom: fcl.CollisionGeometry | None = None
        if verts is not None:
            import trimesh

            hull = trimesh.Trimesh(vertices=verts).convex_hull
            model = fcl.BVHModel()
            model.beginModel(len(hull.vertices), len(hull.faces))
            model.addSubModel(np.asarray(hull.vertices, float), np.asarray(hull.faces, np.int32))
            model.endModel()
            hull_geom = model
            outline = Polygon(world[:, [0, 2]]).convex_hull
            footprints[k] = outline if isinstance(outline, Polygon) else Polygon()
            lo[k], hi[k] = world.min(axis=0), world.max(axis=0)
        out.append(Body(obj=obj, center=center, half=half, rot=rot, footprint=footprints[k],
                        bottom=float(lo[k][1]), top=float(hi[k][1]), aabb_min=lo[k],
                        aabb_max=hi[k], hull=hull_geom))
    return out


def _solid_parts(obj: EnvObject, center: np.ndarray, half: np.ndarray, rot: np.ndarray
                 ) -> tuple[fcl.CollisionObject, ...] | None:
    """fcl boxes of the solid parts of the object's category shape (None: the box is solid)."""
    shape = load_shapes().of(obj.category)
    if shape is None or shape.solid is None:
        return None
    out = []
    for part in shape.solid:
        c, h = part.local_box(half)
        out.append(fcl.CollisionObject(fcl.Box(*(2.0 * h)), fcl.Transform(rot, center + rot @ c)))
    return tuple(out)


def room_polygon(points: list[tuple[float, float]] | None) -> Polygon | None:
    if points is None or len(points) < 3:
        return None
    return Polygon(points)


def _depth(a: fcl.CollisionObject, b: fcl.CollisionObject) -> float:
    request = fcl.CollisionRequest(num_max_contacts=8, enable_contact=True)
    result = fcl.CollisionResult()
    if fcl.collide(a, b, request, result) == 0:
        return 0.0
    return max((float(c.penetration_depth) for c in result.contacts), default=0.0)


def penetration_depth(a: Body, b: Body) -> float:
    """Deepest contact between two bodies according to fcl (0 when they do not collide), between
    their solid parts where their shapes have parts (a chair's seat under a table's top is free)."""
    if a.parts is None and b.parts is None:
        return _depth(a.collision, b.collision)
    return max(_depth(pa, pb) for pa in (a.parts or (a.collision,)) for pb in (b.parts or (b.collision,)))


def candidate_pairs(bodies: list[Body], margin: float = 0.0) -> list[tuple[int, int]]:
    """Pairs (i < j, sorted) whose axis-aligned bounds meet: `candidate_array` as tuples."""
    return [(int(i), int(j)) for i, j in candidate_array(bodies, margin)]


def candidate_array(bodies: list[Body], margin: float = 0.0) -> np.ndarray:
    """Sort-and-sweep broad phase: an (P, 2) array of the pairs (i < j) whose axis-aligned bounds
    meet (closed intervals on x, y and z), sorted by i then j.

    Bodies are sorted by their lower x bound once; the bodies that can meet body k on x are then
    the contiguous run after it up to k's upper bound (binary search), and all runs are tested on
    y and z in one vectorised step. Time and memory are O(n log n + X) array work, X the pairs
    that meet on x — no Python loop over objects or pairs.
    """
    n = len(bodies)
    if n < 2:
        return np.zeros((0, 2), dtype=np.int64)
    lo = np.array([b.aabb_min for b in bodies]) - margin
    hi = np.array([b.aabb_max for b in bodies]) + margin
    order = np.argsort(lo[:, 0], kind="stable")
    lo_s, hi_s = lo[order], hi[order]
    ends = np.searchsorted(lo_s[:, 0], hi_s[:, 0], side="right")
    counts = np.maximum(ends - np.arange(n) - 1, 0)
    k = np.repeat(np.arange(n), counts)
    m = k + 1 + np.arange(int(counts.sum())) - np.repeat(np.cumsum(counts) - counts, counts)
    meet = ((lo_s[m, 0] <= hi_s[k, 0]) & (lo_s[m, 1] <= hi_s[k, 1]) & (lo_s[k, 1] <= hi_s[m, 1])
            & (lo_s[m, 2] <= hi_s[k, 2]) & (lo_s[k, 2] <= hi_s[m, 2]))
    pairs = np.sort(np.stack([order[k[meet]], order[m[meet]]], axis=1), axis=1)
    out: np.ndarray = pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]
    return out


def separated(bodies: list[Body], pairs: np.ndarray, eps: float = 1e-6) -> np.ndarray:
    """For each pair of boxes, whether a separating axis keeps them more than `eps` apart: the
    vertical axis or one of the four footprint edge normals (objects turn about y only, so these
    are all the candidate axes of two such boxes). Such a pair cannot collide (a property test
    checks fcl agrees); pairs with a mesh body are never called separated here. Vectorised."""
    out = np.zeros(len(pairs), dtype=bool)
    if not len(pairs):
        return out
    cen = np.array([b.center for b in bodies])[:, ::2]                 # x, z (`Body.xz`)
    rot = np.array([b.rot for b in bodies])
    ax = rot[:, ::2, ::2].transpose(0, 2, 1)  # (n, 2 axes, 2): `Body.right()`, `Body.front()`
    half = np.array([b.half for b in bodies])[:, ::2]                  # (n, 2)
    bot = np.array([b.bottom for b in bodies])
    top = np.array([b.top for b in bodies])
    box = np.array([b.is_box for b in bodies])
    for s in range(0, len(pairs), 65536):  # bounded memory on huge candidate sets
        with np.errstate(all="ignore"):  # absurd coordinates give inf/NaN: not called separated
            out[s:s + 65536] = _apart(pairs[s:s + 65536], cen, ax, half, bot, top, box, eps)
    return out


def _apart(pairs: np.ndarray, cen: np.ndarray, ax: np.ndarray, half: np.ndarray, bot: np.ndarray,
           top: np.ndarray, box: np.ndarray, eps: float) -> np.ndarray:
    """`separated` on one chunk of pairs: the largest gap over the five axes, > eps."""
    i, j = pairs[:, 0], pairs[:, 1]
    gap = np.maximum(bot[i], bot[j]) - np.minimum(top[i], top[j])  # > 0: apart vertically
    d = cen[j] - cen[i]
    for normals in (ax[i, 0], ax[i, 1], ax[j, 0], ax[j, 1]):
        reach = sum(half[k, a] * np.abs(np.einsum("pb,pb->p", ax[k, a], normals)) for k in (i, j) for a in (0, 1))
        gap = np.maximum(gap, np.abs(np.einsum("pb,pb->p", d, normals)) - reach)
    apart: np.ndarray = (gap > eps) & box[i] & box[j]
    return apart


def rect_pairs(a: list[tuple[float, float, float, float]],
               b: list[tuple[float, float, float, float]]) -> list[tuple[int, int]]:
    """(i, j) with rectangle a[i] meeting b[j] (x0, z0, x1, z1): one sort-and-sweep over x of both
    sets, an interval test on z. Used to pair door squares with object footprints; a rectangle with
    a non-finite bound (an empty shape) meets nothing."""
    events = sorted([(r[0], 0, i) for i, r in enumerate(a) if finite(*r)]
                    + [(r[0], 1, j) for j, r in enumerate(b) if finite(*r)])
    active: tuple[list[int], list[int]] = ([], [])
    rects = (a, b)
    pairs: list[tuple[int, int]] = []
    for x0, side, k in events:
        other = 1 - side
        active_other = [m for m in active[other] if rects[other][m][2] >= x0]
        active[other][:] = active_other
        r = rects[side][k]
        for m in active_other:
            q = rects[other][m]
            if r[1] <= q[3] and q[1] <= r[3]:
                pairs.append((k, m) if side == 0 else (m, k))
        active[side].append(k)
    return sorted(pairs)


def point_to_boundary(geom: BaseGeometry, poly: Polygon) -> float:
    return float(poly.exterior.distance(geom))


def finite(*values: float) -> bool:
    return all(map(math.isfinite, values))


def has_geometry(obj: EnvObject) -> bool:
    """Position and size given, finite, with positive extents (else the entity check reports it)."""
    return (obj.position is not None and obj.size is not None and finite(*obj.position, *obj.size, obj.yaw)
            and min(obj.size) > 0)


#: the last bodies built and what they were built from: checking and then rendering one
#: environment builds them once
_LAST: list[tuple[Path | None, list[EnvObject], dict[str, Body]]] = []


def clear_body_cache() -> None:
    """Forget the memoised bodies (benchmarks time cold checks of one environment)."""
    _LAST.clear()


def build_bodies(env: EnvSpec, mesh_dir: Path | None = None) -> dict[str, Body]:
    """Bodies of all objects that have geometry, keyed by id, in EnvSpec order (read-only)."""
    objects = [o for o in env.objects if has_geometry(o)]
    if _LAST and _LAST[0][0] == mesh_dir and _LAST[0][1] == objects:
        return _LAST[0][2]
    bodies = {b.id: b for b in _build(objects, mesh_dir)}
    _LAST[:] = [(mesh_dir, objects, bodies)]
    return bodies
