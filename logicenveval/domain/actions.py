"""The action and condition library of DESIGN.md §5: ports, preconditions and effects.

Each action's `check` returns the reason its precondition fails (or None) and `apply` performs
the effect; the simulator calls `check` before `apply`, so `apply` trusts its inputs. The world
is any object with the `ActWorld` interface (the simulator's `World`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol


class _Caps(Protocol):
    @property
    def pickable(self) -> bool: ...
    @property
    def surface(self) -> bool: ...
    @property
    def container(self) -> bool: ...
    @property
    def openable(self) -> bool: ...
    @property
    def toggleable(self) -> bool: ...


class ActWorld(Protocol):
    support: dict[str, str | None]
    container: dict[str, str | None]
    room: dict[str, str]
    flags: set[tuple[str, str]]
    holding: str | None
    near: str | None
    agent_room: str

    def obj(self, name: str) -> str | None: ...
    def is_unbound_role(self, name: str) -> bool: ...
    def rooms_named(self, name: str) -> frozenset[str]: ...
    def caps(self, oid: str) -> _Caps: ...
    def room_of(self, oid: str) -> str: ...
    def reachable(self, room: str) -> bool: ...
    def holds(self, name: str, args: tuple[str, ...]) -> bool: ...


Args = dict[str, str]
Check = Callable[[ActWorld, Args], "str | None"]
Apply = Callable[[ActWorld, Args], None]


@dataclass(frozen=True, slots=True)
class ActionSpec:
    name: str
    ports: tuple[str, ...]
    optional: tuple[str, ...]
    check: Check
    apply: Apply
    doc: str


@dataclass(frozen=True, slots=True)
class ConditionSpec:
    name: str
    ports: tuple[str, ...]
    predicate: str  # the condition-language predicate it mirrors, args in port order
    doc: str


def _need(w: ActWorld, name: str, port: str) -> tuple[str | None, str | None]:
    """Resolve an object argument: (object id, None) or (None, violation message)."""
    oid = w.obj(name)
    if oid is not None:
        return oid, None
    if w.is_unbound_role(name):
        return None, f"{port}={name!r}: role is not bound to any object in this environment"
    return None, f"{port}={name!r}: no such object in this environment"


def _near(w: ActWorld, oid: str) -> bool:
    return w.near == oid


def _enclosed_by_closed(w: ActWorld, oid: str) -> str | None:
    """The first closed openable container enclosing `oid` (through supports too), if any."""
    seen: set[str] = set()
    cur: str | None = oid
    while cur is not None and cur not in seen:
        seen.add(cur)
        c = w.container.get(cur)
        if c is not None:
            if w.caps(c).openable and (c, "open") not in w.flags:
                return c
            cur = c
        else:
            s = w.support.get(cur)
            cur = s if s not in (None, "floor", "wall", "ceiling") else None
    return None


# ----- Walk ------------------------------------------------------------------------------
def _walk_target(w: ActWorld, target: str) -> tuple[str | None, str | None, str | None]:
    """(near token, room, violation) for a Walk target: an object or a room."""
    oid = w.obj(target)
    if oid is not None:
        return oid, w.room_of(oid), None
    rooms = w.rooms_named(target)
    if rooms:
        room = sorted(rooms)[0]
        return room, room, None
    _, why = _need(w, target, "target")
    return None, None, why


def _walk_check(w: ActWorld, a: Args) -> str | None:
    _, room, why = _walk_target(w, a["target"])
    if why is not None:
        return why
    assert room is not None
    if not w.reachable(room):
        return f"target={a['target']!r} is in room {room!r}, not reachable through doors from {w.agent_room!r}"
    return None


def _walk_apply(w: ActWorld, a: Args) -> None:
    token, room, _ = _walk_target(w, a["target"])
    assert room is not None
    w.near = token
    w.agent_room = room


# ----- Pick / Place / PutIn --------------------------------------------------------------
def _pick_check(w: ActWorld, a: Args) -> str | None:
    oid, why = _need(w, a["obj"], "obj")
    if oid is None:
        return why
    if not _near(w, oid):
        return f"agent is not near obj={a['obj']!r} (Walk to it first)"
    if w.holding is not None:
        return f"hand is not empty (holding {w.holding!r})"
    if not w.caps(oid).pickable:
        return f"obj={a['obj']!r} is not pickable"
    closed = _enclosed_by_closed(w, oid)
    if closed is not None:
        return f"obj={a['obj']!r} is inside closed container {closed!r} (Open it first)"
    return None


def _pick_apply(w: ActWorld, a: Args) -> None:
    oid = w.obj(a["obj"])
    assert oid is not None
    w.holding = oid
    w.support[oid] = None
    w.container[oid] = None


def _held(w: ActWorld, a: Args) -> tuple[str | None, str | None]:
    oid, why = _need(w, a["obj"], "obj")
    if oid is None:
        return None, why
    if w.holding != oid:
        return None, f"agent is not holding obj={a['obj']!r}"
    return oid, None


def _place_check(w: ActWorld, a: Args) -> str | None:
    oid, why = _held(w, a)
    if oid is None:
        return why
    if a["target"] == "floor":
        return None
    tid, why = _need(w, a["target"], "target")
    if tid is None:
        return why
    if tid == oid:
        return "cannot place an object on itself"
    if not _near(w, tid):
        return f"agent is not near target={a['target']!r} (Walk to it first)"
    if not w.caps(tid).surface:
        return f"target={a['target']!r} is not a surface"
    return None


def _place_apply(w: ActWorld, a: Args) -> None:
    oid = w.obj(a["obj"])
    assert oid is not None
    target = a["target"]
    w.holding = None
    w.container[oid] = None
    if target == "floor":
        w.support[oid] = "floor"
        w.room[oid] = w.agent_room
    else:
        tid = w.obj(target)
        assert tid is not None
        w.support[oid] = tid
        w.room[oid] = w.room_of(tid)


def _putin_check(w: ActWorld, a: Args) -> str | None:
    oid, why = _held(w, a)
    if oid is None:
        return why
    tid, why = _need(w, a["target"], "target")
    if tid is None:
        return why
    if tid == oid:
        return "cannot put an object into itself"
    if not _near(w, tid):
        return f"agent is not near target={a['target']!r} (Walk to it first)"
    caps = w.caps(tid)
    if not caps.container:
        return f"target={a['target']!r} is not a container"
    if caps.openable and (tid, "open") not in w.flags:
        return f"target={a['target']!r} is closed (Open it first)"
    return None


def _putin_apply(w: ActWorld, a: Args) -> None:
    oid, tid = w.obj(a["obj"]), w.obj(a["target"])
    assert oid is not None and tid is not None
    w.holding = None
    w.support[oid] = None
    w.container[oid] = tid
    w.room[oid] = w.room_of(tid)


# ----- state-changing actions ------------------------------------------------------------
def _afford_check(cap: str) -> Check:
    def check(w: ActWorld, a: Args) -> str | None:
        oid, why = _need(w, a["obj"], "obj")
        if oid is None:
            return why
        if not _near(w, oid):
            return f"agent is not near obj={a['obj']!r} (Walk to it first)"
        if not getattr(w.caps(oid), cap):
            return f"obj={a['obj']!r} is not {cap}"
        return None

    return check


def _set_flag(flag: str, value: bool) -> Apply:
    def apply(w: ActWorld, a: Args) -> None:
        oid = w.obj(a["obj"])
        assert oid is not None
        if value:
            w.flags.add((oid, flag))
        else:
            w.flags.discard((oid, flag))

    return apply


def _clean_check(w: ActWorld, a: Args) -> str | None:
    oid, why = _need(w, a["obj"], "obj")
    if oid is None:
        return why
    if not _near(w, oid) and w.holding != oid:
        return f"agent is not near obj={a['obj']!r} (Walk to it first)"
    tool = a.get("tool")
    if tool is not None:
        tid, why = _need(w, tool, "tool")
        if tid is None:
            return why
        if w.holding != tid:
            return f"agent is not holding tool={tool!r} (Pick it first)"
    return None


def _fill_check(w: ActWorld, a: Args) -> str | None:
    oid, why = _held(w, a)
    if oid is None:
        return why
    sid, why = _need(w, a["source"], "source")
    if sid is None:
        return why
    if not _near(w, sid):
        return f"agent is not near source={a['source']!r} (Walk to it first)"
    return None


ACTIONS: dict[str, ActionSpec] = {
    s.name: s
    for s in (
        ActionSpec("Walk", ("target",), (), _walk_check, _walk_apply,
                   "go next to an object or into a room reachable through doors"),
        ActionSpec("Pick", ("obj",), (), _pick_check, _pick_apply,
                   "pick up a pickable object you are near, hand empty"),
        ActionSpec("Place", ("obj", "target"), (), _place_check, _place_apply,
                   "put the held object on a surface you are near, or on the floor"),
        ActionSpec("PutIn", ("obj", "target"), (), _putin_check, _putin_apply,
                   "put the held object into a container you are near (open if openable)"),
        ActionSpec("Open", ("obj",), (), _afford_check("openable"), _set_flag("open", True),
                   "open an openable object you are near"),
        ActionSpec("Close", ("obj",), (), _afford_check("openable"), _set_flag("open", False),
                   "close an openable object you are near"),
        ActionSpec("ToggleOn", ("obj",), (), _afford_check("toggleable"),
                   _set_flag("toggled_on", True), "switch on a toggleable object you are near"),
        ActionSpec("ToggleOff", ("obj",), (), _afford_check("toggleable"),
                   _set_flag("toggled_on", False), "switch off a toggleable object you are near"),
        ActionSpec("Clean", ("obj",), ("tool",), _clean_check, _set_flag("dirty", False),
                   "clean an object you are near (or hold), with a held tool if given"),
        ActionSpec("Fill", ("obj", "source"), (), _fill_check, _set_flag("filled", True),
                   "fill the held object at a source you are near"),
    )
}

CONDITIONS: dict[str, ConditionSpec] = {
    s.name: s
    for s in (
        ConditionSpec("Exists", ("obj",), "exists", "the role is bound to an object"),
        ConditionSpec("On", ("obj", "target"), "on", "obj rests directly on target (or floor)"),
        ConditionSpec("Inside", ("obj", "target"), "inside", "obj is directly inside target"),
        ConditionSpec("InRoom", ("obj", "room"), "in_room", "obj is in the room (id or type)"),
        ConditionSpec("Attr", ("obj", "key", "value"), "attr", "attribute key of obj equals value"),
        ConditionSpec("State", ("obj", "flag"), "state", "state flag of obj is true"),
        ConditionSpec("Holding", ("obj",), "holding", "the agent holds obj"),
        ConditionSpec("Near", ("obj",), "near", "the agent stands next to obj"),
        ConditionSpec("AgentIn", ("room",), "agent_in", "the agent is in the room"),
    )
}

#: ports whose value names an object (a role), checked against the task's roles when given
OBJECT_PORTS = frozenset({"obj", "target", "tool", "source"})
