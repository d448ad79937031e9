"""Rule-based spatial relation compatibility (paper §3.3), with reasons an LLM can act on.

Objects and relations are taken structurally (`id/category/room/placement`, `type/args`), so
both LLM drafts and `scene.spec` requests can be checked. Each `Incompatibility` keeps the very
relation objects involved, so a caller can drop exactly those.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

from logicenveval.domain.catalog import Catalog, Category


class ObjectLike(Protocol):
    @property
    def id(self) -> str: ...
    @property
    def category(self) -> str: ...
    @property
    def room(self) -> str: ...
    @property
    def placement(self) -> str: ...


class RelationLike(Protocol):
    @property
    def type(self) -> str: ...
    @property
    def args(self) -> Sequence[str]: ...


@dataclass(frozen=True)
class Incompatibility:
    code: str
    reason: str
    objects: tuple[str, ...]
    relations: tuple[Any, ...] = field(default=())


def _fits(inner: tuple[float, float, float], outer: tuple[float, float, float], *, with_height: bool) -> bool:
    a = sorted(inner[::2]) if not with_height else sorted(inner)
    b = sorted(outer[::2]) if not with_height else sorted(outer)
    return all(x <= y + 1e-9 for x, y in zip(a, b, strict=True))


def _vol(s: tuple[float, float, float]) -> float:
    return s[0] * s[1] * s[2]


def can_hold(item: Category, holder: Category, relation: str) -> bool:
    """Whether an `item` of its category can be `on` or `inside` a `holder` of its category at
    all (a surface / a container it fits in, its smallest size against the holder's largest):
    the same tests `check_relations` applies, for a reader that must not propose what it rules out."""
    if relation == "on":
        return holder.surface and _fits(item.size_min, holder.size_max, with_height=False) \
            and _vol(item.size_min) <= _vol(holder.size_max)
    return holder.container and _fits(item.size_min, holder.size_max, with_height=True)


def check_relations(objects: Sequence[ObjectLike], relations: Sequence[RelationLike],
                    catalog: Catalog) -> list[Incompatibility]:
    """Every contradiction among placements and relations; empty when compatible."""
    out: list[Incompatibility] = []
    objs = {o.id: o for o in objects}
    cats: dict[str, Category | None] = {o.id: catalog.get(o.category) for o in objects}
    on: dict[str, list[tuple[str, Any]]] = {}
    inside: dict[str, list[tuple[str, Any]]] = {}
    for o in objects:
        c_o = cats[o.id]
        if c_o is not None and c_o.placement == ["inside"] and not o.placement.startswith("inside:"):
            out.append(Incompatibility("needs_a_container", f"{o.id} ({o.category}) is part of a piece of "
                                       f"furniture and cannot be placed {o.placement}; put it inside a "
                                       "container such as a cabinet or dresser", (o.id,)))
        if o.placement.startswith("on:"):
            on.setdefault(o.id, []).append((o.placement[3:], None))
        elif o.placement.startswith("inside:"):
            inside.setdefault(o.id, []).append((o.placement[7:], None))
        elif o.placement == "wall":
            c = cats[o.id]
            if c is not None and "wall" not in c.placement:
                out.append(Incompatibility("wall_mounted_floor_object",
                                           f"{o.id} ({o.category}) cannot be mounted on a wall; place it on the floor",
                                           (o.id,)))
    good: list[RelationLike] = []
    for r in relations:
        unknown = [a for a in r.args if a not in objs]
        if unknown:
            out.append(Incompatibility("unknown_object", f"{r.type}({', '.join(r.args)}) names unknown "
                                       f"object(s) {unknown}; use the ids of the selected objects",
                                       tuple(unknown), (r,)))
            continue
        good.append(r)
        if r.type == "on":
            on.setdefault(r.args[0], []).append((r.args[1], r))
        elif r.type == "inside":
            inside.setdefault(r.args[0], []).append((r.args[1], r))
        elif r.type == "wall_mounted":
            c = cats[r.args[0]]
            if c is not None and "wall" not in c.placement:
                out.append(Incompatibility("wall_mounted_floor_object",
                                           f"{r.args[0]} ({objs[r.args[0]].category}) is floor furniture and cannot "
                                           "be wall-mounted; drop wall_mounted", (r.args[0],), (r,)))
    for a, targets in on.items():
        for b, rel in targets:
            rels = tuple(x for x in (rel,) if x is not None)
            if b not in objs:
                out.append(Incompatibility("unknown_object", f"{a} is placed on unknown object {b}", (a, b), rels))
                continue
            cb, ca = cats[b], cats[a]
            if cb is not None and not cb.surface:
                out.append(Incompatibility("not_a_surface", f"{a} cannot rest on {b} ({objs[b].category}), "
                                           "which is not a surface", (a, b), rels))
            if ca is not None and cb is not None:
                if not _fits(ca.size_min, cb.size_max, with_height=False):
                    out.append(Incompatibility("too_big_for_surface", f"{a} ({objs[a].category}) is larger than "
                                               f"the top of {b} ({objs[b].category}); put it on the floor",
                                               (a, b), rels))
                elif _vol(ca.size_min) > _vol(cb.size_max):
                    out.append(Incompatibility("large_on_small", f"{a} ({objs[a].category}) is much bigger than "
                                               f"{b} ({objs[b].category}) and cannot stand on it", (a, b), rels))
            for back, rel2 in on.get(b, []):
                if back == a and a < b:
                    out.append(Incompatibility("mutual_on", f"{a} on {b} and {b} on {a} contradict each other; "
                                               "keep one", (a, b), tuple(x for x in (rel, rel2) if x is not None)))
    for a, targets in inside.items():
        for b, rel in targets:
            rels = tuple(x for x in (rel,) if x is not None)
            if b not in objs:
                out.append(Incompatibility("unknown_object", f"{a} is inside unknown object {b}", (a, b), rels))
                continue
            ca, cb = cats[a], cats[b]
            if cb is not None and not cb.container:
                out.append(Incompatibility("not_a_container", f"{a} cannot be inside {b} ({objs[b].category}), "
                                           "which is not a container", (a, b), rels))
            elif ca is not None and cb is not None and not _fits(ca.size_min, cb.size_max, with_height=True):
                out.append(Incompatibility("too_big_for_container", f"{a} ({objs[a].category}) does not fit "
                                           f"inside {b} ({objs[b].category})", (a, b), rels))
        if a in on:
            rels = tuple(x for _, x in [*targets, *on[a]] if x is not None)
            out.append(Incompatibility("on_and_inside", f"{a} cannot be both on {on[a][0][0]} and inside "
                                       f"{targets[0][0]}; choose one", (a,), rels))
    out += _cycles(on, inside)
    pairs: dict[frozenset[str], dict[str, RelationLike]] = {}
    for r in good:
        if r.type in ("near", "far") and len(set(r.args)) == 2:
            pairs.setdefault(frozenset(r.args), {})[r.type] = r
            ra, rb = objs[r.args[0]].room, objs[r.args[1]].room
            if r.type == "near" and ra != rb:
                out.append(Incompatibility("different_rooms", f"near({', '.join(r.args)}): the objects are in "
                                           f"different rooms ({ra}, {rb})", tuple(r.args), (r,)))
    for pair, kinds in pairs.items():
        if {"near", "far"} <= kinds.keys():
            out.append(Incompatibility("near_and_far", f"{' and '.join(sorted(pair))} cannot be both near and "
                                       "far; keep one", tuple(sorted(pair)), (kinds["near"], kinds["far"])))
    return out


def _cycles(on: dict[str, list[tuple[str, Any]]], inside: dict[str, list[tuple[str, Any]]]) -> list[Incompatibility]:
    graph: dict[str, list[tuple[str, Any]]] = {}
    for src in (on, inside):
        for a, ts in src.items():
            graph.setdefault(a, []).extend(ts)
    out: list[Incompatibility] = []
    seen: set[frozenset[str]] = set()
    for start in sorted(graph):
        stack: list[tuple[str, list[str], list[Any]]] = [(start, [start], [])]
        while stack:
            node, path, rels = stack.pop()
            for nxt, rel in graph.get(node, []):
                nrels = [*rels, rel] if rel is not None else rels
                if nxt == start and len(path) > 2 and frozenset(path) not in seen:
                    seen.add(frozenset(path))
                    out.append(Incompatibility("cycle", "support/containment cycle " + " -> ".join([*path, start])
                                               + "; break it by putting one of them on the floor",
                                               tuple(path), tuple(nrels)))
                elif nxt not in path and len(path) < 16:
                    stack.append((nxt, [*path, nxt], nrels))
    return out
