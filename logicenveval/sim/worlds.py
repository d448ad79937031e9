"""Several worlds per situation: the freedom a task leaves, explored deterministically (issue 22).

`situation_env` builds one minimal world per logical trajectory, with every unpinned object in
its most natural place. A policy can pass there and still fail in another valid world of the same
situation (a backpack holding the lunch box put away in a closed wardrobe). `situation_worlds`
starts from that world and varies what the trajectory leaves free, one *deviation* at a time:

- every placement the catalog allows for a pickable object: the floor of its room or of another
  room, each surface, and each container it fits in (catalog sizes) — openable ones both closed
  and open;
- furniture in another room (its contents move with it);
- every state flag of an object flipped;
- an optional role's object left out (the description lets it be absent: "may", "if available"),
  when nothing rests on or in it.

A deviation is kept only when the GT trees still reach exactly the same leaves (so it changes
nothing the situation pins), every explicit task constraint still holds, and the result obeys the physical axioms (holders are surfaces or
containers, no holder cycles, contents share their holder's room). Deviations are then packed
greedily into at most `limit` worlds, riskiest first (closed containers, other rooms, other
supports, states), so a small bound still covers most of them.
"""

from __future__ import annotations

from dataclasses import dataclass

from logicenveval.domain.catalog import Catalog, Category, load_catalog
from logicenveval.model.envspec import EnvObject, EnvSpec
from logicenveval.model.task import Task
from logicenveval.model.tree import Trajectory, evaluate_task
from logicenveval.sim.situations import situation_env
from logicenveval.sim.world import caps_of, holds_initial

#: default bound on the worlds built per situation (the base world included)
DEFAULT_WORLDS = 12


@dataclass(frozen=True, slots=True)
class Deviation:
    """One change to the base world: where `obj` goes and which states it sets."""

    obj: str
    room: str | None = None  # None: keep (or follow the holder's room)
    support: str | None = None
    container: str | None = None
    states: tuple[tuple[str, str, bool], ...] = ()  # (object, flag, value)
    priority: int = 3
    label: str = ""
    absent: bool = False  # the object is left out (an optional role)




_State = dict[str, "_Obj"]


def situation_worlds(task: Task, trajectory: Trajectory, catalog: Catalog | None = None, *,
                     limit: int = DEFAULT_WORLDS) -> list[EnvSpec]:
    """The base world of `trajectory` followed by up to `limit - 1` varied worlds.

    Raises `TrajectoryError` like `situation_env` when the trajectory cannot be realised.
    """
    cat = catalog if catalog is not None else load_catalog()
    base = situation_env(task, trajectory, cat)
    if limit <= 1:
        return [base]
    key = (task.model_dump_json(), trajectory.key, id(cat), limit)
    hit = _CACHE.get(key)
    if hit is not None and hit[0] is cat:
        return hit[1]
    worlds = [base, *_variants(task, trajectory, base, cat, limit - 1)]
    if len(_CACHE) > 4096:
        _CACHE.clear()
    _CACHE[key] = (cat, worlds)
    return worlds


_CACHE: dict[tuple[str, str, int, int], tuple[Catalog, list[EnvSpec]]] = {}


def _variants(task: Task, trajectory: Trajectory, base: EnvSpec, cat: Catalog,
              budget: int) -> list[EnvSpec]:
    want = [p.key for p in trajectory.paths]
    start = _state_of(base)
    deviations = [*_absences(task, base), *_deviations(base, cat)]
    single = [d for d in deviations if _realises(task, base, _apply(start, d), want, cat)]
    single.sort(key=lambda d: d.priority)
    out: list[EnvSpec] = []
    todo = single
    while todo and len(out) < budget:
        state = _copy(start)
        moved: set[str] = set()
        fixed: dict[tuple[str, str], bool] = {}
        left: list[Deviation] = []
        took = False
        for d in todo:
            moves = bool(d.support or d.container or d.room)
            clash = (moves and d.obj in moved) or any(fixed.get((o, f), v) != v for o, f, v in d.states)
            trial = None if clash else _apply(state, d)
            if trial is not None and _realises(task, base, trial, want, cat):
                state = trial
                took = True
                if moves:
                    moved.add(d.obj)
                for o, f, v in d.states:
                    fixed[(o, f)] = v
            else:
                left.append(d)
        if not took:
            break
        out.append(_env_of(base, state, len(out) + 1))
        todo = left
    return out


def _absences(task: Task, env: EnvSpec) -> list[Deviation]:
    """Leave out each optional role's object (riskiest first: policies must cope with absence)."""
    ids = {o.id for o in env.objects}
    return [Deviation(oid, absent=True, priority=0, label=f"{role} absent")
            for role, spec in task.roles.items()
            if spec.optional and (oid := env.roles.get(role)) is not None and oid in ids]


def _deviations(env: EnvSpec, cat: Catalog) -> list[Deviation]:
    rooms = [r.id for r in env.rooms]
    out: list[Deviation] = []
    for o in env.objects:
        category = cat.get(o.category)
        caps = caps_of(o.category, cat)
        placements = set(category.placement) if category is not None else {"floor"}
        if caps.pickable:
            if "floor" in placements:
                for room in rooms:
                    if o.support != "floor" or o.room != room:
                        out.append(Deviation(o.id, room=room, support="floor",
                                             priority=1 if room != o.room else 2,
                                             label=f"{o.id} on the floor of {room}"))
            for h in env.objects:
                if h.id == o.id:
                    continue
                hc = caps_of(h.category, cat)
                if "surface" in placements and hc.surface and o.support != h.id:
                    out.append(Deviation(o.id, support=h.id, priority=2, label=f"{o.id} on {h.id}"))
                if ("inside" in placements and hc.container and o.container != h.id
                        and _fits(category, cat.get(h.category))):
                    if hc.openable:
                        for is_open in (False, True):
                            out.append(Deviation(o.id, container=h.id,
                                                 states=((h.id, "open", is_open),),
                                                 priority=0 if not is_open else 2,
                                                 label=f"{o.id} inside {'open' if is_open else 'closed'} {h.id}"))
                    else:
                        out.append(Deviation(o.id, container=h.id, priority=2,
                                             label=f"{o.id} inside {h.id}"))
        elif o.support == "floor":
            for room in rooms:
                if room != o.room:
                    out.append(Deviation(o.id, room=room, support="floor", priority=1,
                                         label=f"{o.id} in {room}"))
        flags = dict(category.default_states) if category is not None else {}
        flags.update(o.states)
        if caps.openable:
            flags.setdefault("open", False)
        if caps.toggleable:
            flags.setdefault("toggled_on", False)
        for flag, value in sorted(flags.items()):
            out.append(Deviation(o.id, states=((o.id, flag, not value),), priority=3,
                                 label=f"{o.id} {flag}={not value}"))
    return out


def _fits(content: Category | None, holder: Category | None) -> bool:
    """Whether the smallest `content` fits the largest `holder`, dimensions sorted (any rotation)."""
    if content is None or holder is None:
        return True
    return all(a <= b for a, b in zip(sorted(content.size_min), sorted(holder.size_max), strict=True))


@dataclass(slots=True)
class _Obj:
    room: str
    support: str | None
    container: str | None
    states: dict[str, bool]
    present: bool = True


def _state_of(env: EnvSpec) -> _State:
    return {o.id: _Obj(o.room, o.support if o.container is None else None, o.container,
                       dict(o.states)) for o in env.objects}


def _copy(state: _State) -> _State:
    return {k: _Obj(v.room, v.support, v.container, dict(v.states), v.present)
            for k, v in state.items()}


def _apply(state: _State, d: Deviation) -> _State | None:
    """`state` with `d` applied, or None when it breaks an axiom (holder cycle, unknown object)."""
    new = _copy(state)
    if d.obj not in new or not new[d.obj].present:
        return None
    o = new[d.obj]
    if d.absent:
        if any(s.present and d.obj in (s.support, s.container) for s in new.values()):
            return None
        o.present = False
        return new
    holder = d.container or (d.support if d.support not in (None, "floor") else None)
    if holder is not None:
        if holder not in new or not new[holder].present or _inside_of(new, holder, d.obj):
            return None
        o.support, o.container = (None, holder) if d.container else (holder, None)
        _move_room(new, d.obj, new[holder].room)
    elif d.support == "floor":
        o.support, o.container = "floor", None
        _move_room(new, d.obj, d.room or o.room)
    elif d.room is not None:
        _move_room(new, d.obj, d.room)
    for oid, flag, value in d.states:
        if oid not in new or not new[oid].present:
            return None
        new[oid].states[flag] = value
    return new


def _inside_of(state: _State, oid: str, ancestor: str) -> bool:
    """Whether `oid` is `ancestor` or (transitively) held by it."""
    seen: set[str] = set()
    cur: str | None = oid
    while cur is not None and cur not in seen:
        if cur == ancestor:
            return True
        seen.add(cur)
        s = state[cur]
        cur = s.container or (s.support if s.support not in (None, "floor") else None)
    return False


def _move_room(state: _State, oid: str, room: str) -> None:
    state[oid].room = room
    for other, s in state.items():
        if other != oid and (s.container == oid or s.support == oid):
            _move_room(state, other, room)


def _env_of(base: EnvSpec, state: _State, k: int) -> EnvSpec:
    objects: list[EnvObject] = []
    for o in base.objects:
        s = state[o.id]
        if not s.present:
            continue
        objects.append(o.model_copy(update={
            "room": s.room, "support": s.support, "container": s.container, "states": dict(s.states),
        }))
    gone = {oid for oid, s in state.items() if not s.present}
    roles = {r: (None if oid in gone else oid) for r, oid in base.roles.items()}
    return base.model_copy(update={"objects": objects, "roles": roles, "env_id": f"{base.env_id}#w{k}"})


def _realises(task: Task, base: EnvSpec, state: _State | None, want: list[str],
              cat: Catalog) -> bool:
    if state is None:
        return False
    env = _env_of(base, state, 0)
    holds = holds_initial(env, cat)
    if task.violated(holds, env.roles):
        return False
    got = [o.path.key if o.path else None for o in evaluate_task(task, holds)]
    return got == want
