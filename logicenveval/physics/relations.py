"""Relation dimension: every declared relation must hold on the geometry (docs/physics.md
defines each one precisely)."""

from __future__ import annotations

import math

import numpy as np
from shapely.geometry import Point, Polygon

from logicenveval.model.envspec import EnvSpec, Relation
from logicenveval.physics.entity import contained_excess, rests_on, settles, wall_distance
from logicenveval.physics.geometry import Body
from logicenveval.physics.report import PhysicsFailure, Tolerances


def _angle(direction: np.ndarray, vec: np.ndarray) -> float:
    """Angle (degrees) between a unit direction and a vector; 180 for a zero vector."""
    n = float(np.linalg.norm(vec))
    if n == 0:
        return 180.0
    return math.degrees(math.acos(max(-1.0, min(1.0, float(direction @ vec) / n))))


def _gap(a: Body, b: Body) -> float:
    return float(a.footprint.distance(b.footprint))


def _holds(rel: Relation, bs: list[Body], env: EnvSpec, polys: dict[str, Polygon],
           tol: Tolerances) -> tuple[bool, float | None, float | None, str]:
    """(holds, measured, tolerance, explanation) for a relation whose arguments are bodies."""
    t = rel.type
    a = bs[0]
    poly = polys.get(a.obj.room)
    if t in ("edge", "center") and poly is None:
        return False, None, None, f"room {a.obj.room} has no valid polygon"
    if t == "edge":
        assert poly is not None
        d = float(poly.exterior.distance(a.footprint))
        return d <= tol.edge_gap, d, tol.edge_gap, f"footprint is {d:.2f} m from the nearest wall"
    if t == "center":
        assert poly is not None
        x0, z0, x1, z1 = poly.bounds
        limit = tol.center_ratio * min(x1 - x0, z1 - z0)
        d = float(Point(a.xz).distance(poly.centroid))
        return d <= limit, d, limit, f"centre is {d:.2f} m from the room centroid"
    if t == "wall_mounted":
        if a.obj.support != "wall":
            return False, None, None, f"support is {a.obj.support!r}, not 'wall'"
        d = wall_distance(a, poly) if poly is not None else math.inf
        ok = d <= tol.wall_gap and a.bottom > tol.support_gap
        return ok, d, tol.wall_gap, f"back face {d:.2f} m from a wall, bottom at {a.bottom:.2f} m"
    b = bs[1]
    if t == "on":
        if a.obj.support != b.id:
            return False, None, None, f"support is {a.obj.support!r}, not {b.id!r}"
        ok, _, m = rests_on(a, b, tol)
        return ok, m, tol.support_gap, "does not rest on a surface of it with its centre over it"
    if t == "inside":
        if a.obj.container != b.id:
            return False, None, None, f"container is {a.obj.container!r}, not {b.id!r}"
        e = contained_excess(a, b)
        return e <= tol.containment, e, tol.containment, f"sticks {e:.3f} m out of the container box"
    if t == "near":
        g = _gap(a, b)
        return g <= tol.near_gap, g, tol.near_gap, f"footprint gap is {g:.2f} m"
    if t == "far":
        d = float(np.linalg.norm(a.xz - b.xz))
        return d >= tol.far_distance, d, tol.far_distance, f"centre distance is {d:.2f} m"
    if t == "above":
        over = a.footprint.intersection(b.footprint).area > 0
        ok = over and a.bottom >= b.top - tol.support_gap
        return ok, a.bottom - b.top, tol.support_gap, "not over the other's footprint and above its top"
    if t == "in_front_of":
        ang = _angle(b.front(), a.xz - b.xz)
        g = _gap(a, b)
        ok = ang <= tol.facing_angle and g <= tol.near_gap
        return ok, ang, tol.facing_angle, f"{ang:.0f}° off the front axis of {b.id}, gap {g:.2f} m"
    if t == "face_to":
        ang = _angle(a.front(), b.xz - a.xz)
        return ang <= tol.facing_angle, ang, tol.facing_angle, f"front points {ang:.0f}° away from {b.id}"
    if t == "side_of":
        ang = min(_angle(b.right(), a.xz - b.xz), _angle(-b.right(), a.xz - b.xz))
        g = _gap(a, b)
        ok = ang <= tol.facing_angle and g <= tol.near_gap
        return ok, ang, tol.facing_angle, f"{ang:.0f}° off the side axis of {b.id}, gap {g:.2f} m"
    if t == "center_aligned":
        off = a.xz - b.xz
        lateral = min(abs(float(off @ b.right())), abs(float(off @ b.front())))
        return lateral <= tol.align_offset, lateral, tol.align_offset, f"centres are {lateral:.2f} m off either axis of {b.id}"
    raise ValueError(f"unhandled relation type {t!r}")


def _fail(code: str, rel: Relation, message: str, measured: float | None = None,
          tolerance: float | None = None) -> PhysicsFailure:
    return PhysicsFailure(dimension="relation", code=code, objects=list(rel.args), measured=measured,
                          tolerance=tolerance, message=f"{rel.type}({', '.join(rel.args)}): {message}")


def _resolve(arg: str, env: EnvSpec, ids: set[str]) -> str | None:
    if arg in ids:
        return arg
    oid = env.roles.get(arg)
    return oid if oid in ids else None


def check_relations(env: EnvSpec, bodies: dict[str, Body], polys: dict[str, Polygon],
                    tol: Tolerances) -> list[PhysicsFailure]:
    ids = {o.id for o in env.objects}
    fails: list[PhysicsFailure] = []
    for rel in env.relations:
        if rel.type == "on" and rel.args[1] == "floor":
            oid = _resolve(rel.args[0], env, ids)
            body = bodies.get(oid) if oid else None
            if oid is None or body is None or env.obj(oid).support != "floor" or not settles(body.bottom, tol):
                fails.append(_fail("relation_violated", rel, "not resting on the floor"))
            continue
        resolved = [_resolve(x, env, ids) for x in rel.args]
        missing = [x for x, r in zip(rel.args, resolved, strict=True) if r is None]
        if missing:
            fails.append(_fail("unknown_object", rel, f"{missing[0]} is not an object id or bound role"))
            continue
        bs = [bodies.get(r) for r in resolved if r is not None]
        present = [b for b in bs if b is not None]
        if len(present) != len(bs):
            fails.append(_fail("missing_geometry", rel, "an argument has no position or size"))
            continue
        ok, measured, limit, why = _holds(rel, present, env, polys, tol)
        if not ok:
            fails.append(_fail("relation_violated", rel, why, measured, limit))
    return fails
