"""The symbolic world a BT acts on: objects, rooms, doors, the agent (DESIGN.md §3, §5).

A `World` splits into an immutable part shared by all copies (roles, categories, affordances,
attributes, room connectivity) and a small mutable part (support, container, room, true state
flags, agent). `copy()` duplicates only the mutable part, so resetting per episode is cheap.
"""

from __future__ import annotations

import json
from collections import deque
from dataclasses import dataclass

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.domain.categories import vocabulary
from logicenveval.model.conditions import Holds
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.rooms import room_type_of

#: containers that are never openable whatever the catalog says (DESIGN.md §5)
OPEN_TOP_CONTAINERS = frozenset({"trash_can", "laundry_basket", "toy_box"})


@dataclass(frozen=True, slots=True)
class Caps:
    """Affordances of one object, read from its catalog category."""

    pickable: bool = False
    surface: bool = False
    container: bool = False
    openable: bool = False
    toggleable: bool = False


#: an unknown category is a non-pickable, non-container obstacle
OBSTACLE = Caps()


def caps_of(category: str, catalog: Catalog) -> Caps:
    cat = catalog.get(category)
    if cat is None:
        return OBSTACLE
    openable = cat.openable and category not in OPEN_TOP_CONTAINERS
    container = cat.container or category in OPEN_TOP_CONTAINERS
    return Caps(cat.pickable, cat.surface, container, openable, cat.toggleable)


class _Static:
    """The parts of a world that no action changes."""

    __slots__ = ("roles", "object_ids", "category", "caps", "attributes", "room_ids",
                 "room_alias", "adjacent", "start_room", "_reach")

    def __init__(self, env: EnvSpec, catalog: Catalog) -> None:
        self.roles: dict[str, str | None] = dict(env.roles)
        self.object_ids: frozenset[str] = frozenset(o.id for o in env.objects)
        # the catalog key each object's category names (domain.categories); unknown: as written
        vocab = vocabulary(catalog)
        self.category = {o.id: vocab.canonical(o.category) or o.category for o in env.objects}
        self.caps = {oid: caps_of(c, catalog) for oid, c in self.category.items()}
        self.attributes = {o.id: dict(o.attributes) for o in env.objects}
        self.room_ids: tuple[str, ...] = tuple(r.id for r in env.rooms)
        # a name -> room ids it denotes: the id itself, its EnvSpec type and its derived type
        alias: dict[str, set[str]] = {}
        for r in env.rooms:
            for name in (r.id, r.type, room_type_of(r.id)):
                alias.setdefault(name, set()).add(r.id)
        self.room_alias = {k: frozenset(v) for k, v in alias.items()}
        adj: dict[str, set[str]] = {r: set() for r in self.room_ids}
        for d in env.doors:
            a, b = d.rooms
            if a in adj and b in adj:  # doors to "exterior" lead nowhere the agent needs
                adj[a].add(b)
                adj[b].add(a)
        self.adjacent = {k: frozenset(v) for k, v in adj.items()}
        self.start_room = env.agent.room or self.room_ids[0]
        self._reach: dict[str, frozenset[str]] = {}

    def reachable_from(self, room: str) -> frozenset[str]:
        """Rooms connected to `room` through doors (open or closed: the agent opens doors)."""
        got = self._reach.get(room)
        if got is None:
            seen = {room}
            todo = deque([room])
            while todo:
                for nxt in self.adjacent[todo.popleft()]:
                    if nxt not in seen:
                        seen.add(nxt)
                        todo.append(nxt)
            got = self._reach[room] = frozenset(seen)
        return got


class World:
    """Mutable symbolic state; `holds(name, args)` answers the predicates of DESIGN.md §3."""

    __slots__ = ("_s", "support", "container", "room", "flags", "holding", "near", "agent_room")

    def __init__(self, static: _Static, support: dict[str, str | None],
                 container: dict[str, str | None], room: dict[str, str],
                 flags: set[tuple[str, str]], holding: str | None, near: str | None,
                 agent_room: str) -> None:
        self._s = static
        self.support = support
        self.container = container
        self.room = room
        self.flags = flags
        self.holding = holding
        self.near = near
        self.agent_room = agent_room

    @classmethod
    def from_env(cls, env: EnvSpec, catalog: Catalog | None = None) -> World:
        """Build the initial world of an EnvSpec; catalog defaults to the benchmark's."""
        cat = catalog if catalog is not None else load_catalog()
        static = _Static(env, cat)
        flags: set[tuple[str, str]] = set()
        for o in env.objects:
            known = cat.get(static.category[o.id])
            merged = {**(known.default_states if known else {}), **o.states}
            flags.update((o.id, f) for f, v in merged.items() if v)
        return cls(
            static,
            {o.id: (o.support if o.container is None else None) for o in env.objects},
            {o.id: o.container for o in env.objects},
            {o.id: o.room for o in env.objects},
            flags,
            None,
            None,
            static.start_room,
        )

    def copy(self) -> World:
        return World(self._s, dict(self.support), dict(self.container), dict(self.room),
                     set(self.flags), self.holding, self.near, self.agent_room)

    # ----- name resolution -------------------------------------------------------------
    def obj(self, name: str) -> str | None:
        """Object id a role name or object id denotes; None when unbound or unknown."""
        s = self._s
        if name in s.roles:
            return s.roles[name]
        return name if name in s.object_ids else None

    def is_unbound_role(self, name: str) -> bool:
        return name in self._s.roles and self._s.roles[name] is None

    def rooms_named(self, name: str) -> frozenset[str]:
        return self._s.room_alias.get(name, frozenset())

    def caps(self, oid: str) -> Caps:
        return self._s.caps[oid]

    def category(self, oid: str) -> str:
        return self._s.category[oid]

    def room_of(self, oid: str) -> str:
        return self.agent_room if self.holding == oid else self.room[oid]

    def reachable(self, room: str) -> bool:
        return room in self._s.reachable_from(self.agent_room)

    @property
    def roles(self) -> dict[str, str | None]:
        return self._s.roles

    # ----- predicates ------------------------------------------------------------------
    def holds(self, name: str, args: tuple[str, ...]) -> bool:
        """Truth of one atomic predicate; every predicate about an unbound role is false."""
        if name == "agent_in":
            return self.agent_room in self.rooms_named(args[0])
        if name == "near":
            a = args[0]
            if a == "floor":
                return True
            target = self.obj(a)
            if target is None:
                rooms = self.rooms_named(a)
                return self.near in rooms
            return self.near == target
        o = self.obj(args[0])
        if o is None:
            return False
        if name == "exists":
            return True
        if name == "on":
            t = args[1]
            sup = self.support[o]
            if t == "floor":
                return sup == "floor"
            return sup is not None and sup == self.obj(t)
        if name == "inside":
            c = self.container[o]
            return c is not None and c == self.obj(args[1])
        if name == "in_room":
            return self.room_of(o) in self.rooms_named(args[1])
        if name == "attr":
            return self._s.attributes[o].get(args[1]) == args[2]
        if name == "state":
            return (o, args[1]) in self.flags
        if name == "holding":
            return self.holding == o
        return False

    def summary(self) -> dict[str, object]:
        """Final-state digest for verdicts: agent, hand and where each role ended up."""
        roles: dict[str, object] = {}
        for role, oid in sorted(self._s.roles.items()):
            if oid is None:
                roles[role] = None
                continue
            roles[role] = {
                "room": self.room_of(oid),
                "support": self.support[oid],
                "container": self.container[oid],
                "states": sorted(f for (i, f) in self.flags if i == oid),
            }
        return {"agent_room": self.agent_room, "holding": self.holding, "near": self.near,
                "roles": roles}


def symbolic_key(env: EnvSpec) -> str:
    """Everything `World.from_env` reads from an EnvSpec, in order: two environments with the same
    key start every episode in the same symbolic world (geometry and ids of the file aside)."""
    return json.dumps([
        list(env.roles.items()),
        [(o.id, o.category, list(o.attributes.items()), list(o.states.items()), o.support,
          o.container, o.room) for o in env.objects],
        [(r.id, r.type) for r in env.rooms],
        [list(d.rooms) for d in env.doors],
        env.agent.room,
    ], default=str)


def holds_initial(env: EnvSpec, catalog: Catalog | None = None) -> Holds:
    """`holds` of an EnvSpec's initial state, for GT-tree evaluation."""
    return World.from_env(env, catalog).holds
