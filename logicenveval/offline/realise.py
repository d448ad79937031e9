"""Choosing where each task object is, and its attributes and states, so that situation facts
hold: the answer an LLM gives when asked to select objects for a situation.

Facts are conditions on roles (DESIGN.md §3). Positive facts fix a placement, an attribute or a
state; negated facts rule options out, and the object then goes to its most typical remaining
place (a free surface of its room, the floor, a container). Nothing here reads ground truth.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from logicenveval.domain.catalog import Catalog
from logicenveval.llm.scene_words import furniture
from logicenveval.model.conditions import And, Cond, Const, Not, Or, Pred, parse
from logicenveval.model.rooms import room_type_of
from logicenveval.offline.analysis import stated_states
from logicenveval.offline.placement import described_placements
from logicenveval.scene.compat import can_hold

#: placement of an object that must rest on some surface when its room has none among the roles
NEEDS_SURFACE = "on:?"
#: a part of furniture (a drawer: the catalog places it only inside one) whose room has no piece
#: it fits in: `task_objects` adds a cabinet for it, as it adds a side table for a thing with no
#: surface
NEEDS_CONTAINER = "inside:?"


@dataclass
class RoleChoice:
    present: bool = True
    placement: str | None = None  # "floor" | "wall" | "on:<role>" | "inside:<role>"
    room: str | None = None
    attributes: dict[str, str] = field(default_factory=dict)
    states: dict[str, bool] = field(default_factory=dict)
    banned_places: set[str] = field(default_factory=set)
    banned_values: dict[str, set[str]] = field(default_factory=dict)
    banned_rooms: set[str] = field(default_factory=set)


def _literals(cond: Cond, positive: bool = True) -> list[tuple[Pred, bool]]:
    """Atoms with polarity from a conjunction; a disjunction contributes its first option."""
    if isinstance(cond, Pred):
        return [(cond, positive)]
    if isinstance(cond, Not):
        return _literals(cond.operand, not positive)
    if isinstance(cond, And) and positive or isinstance(cond, Or) and not positive:
        return [lit for c in cond.operands for lit in _literals(c, positive)]
    if isinstance(cond, Or | And):
        return _literals(cond.operands[0], positive)
    assert isinstance(cond, Const)
    return []


def realise(brief: Mapping[str, Any], facts: list[str], catalog: Catalog) -> dict[str, RoleChoice]:
    """A placement, room, attributes and states for every role satisfying `facts` if possible."""
    roles: dict[str, Any] = dict(brief["roles"])
    rooms: list[str] = list(brief["rooms"])
    choice = {r: RoleChoice() for r in roles}
    for text in facts:
        for pred, pos in _literals(parse(text)):
            _apply(choice, pred, pos)
    _described(choice, brief, facts, catalog)
    _stated(choice, brief, facts, catalog)
    _possible(choice, roles, catalog)
    for r, c in choice.items():
        cat = catalog.get(roles[r]["category"])
        fixed = {k: str(v) for k, v in roles[r].get("attributes", {}).items()}
        c.attributes = {**fixed, **c.attributes}
        for key, banned in c.banned_values.items():
            if key in c.attributes and c.attributes[key] not in banned:
                continue
            domain = cat.attributes.get(key, []) if cat else []
            other = next((v for v in domain if v not in banned), None)
            c.attributes[key] = other or f"other_{key}"
        if cat:
            c.states = {**cat.default_states, **c.states}
    _rooms(choice, roles, rooms, catalog)
    _places(choice, roles, catalog)
    return choice


def _apply(choice: dict[str, RoleChoice], pred: Pred, pos: bool) -> None:
    r = pred.args[0]
    if r not in choice:
        return
    c = choice[r]
    if pred.name == "exists":
        c.present = pos
    elif pred.name in ("on", "inside"):
        place = ("floor" if pred.args[1] == "floor" else
                 f"{'on' if pred.name == 'on' else 'inside'}:{pred.args[1]}")
        if pos:
            c.placement = place
        else:
            c.banned_places.add(place)
    elif pred.name == "in_room":
        if pos:
            c.room = pred.args[1]
        else:
            c.banned_rooms.add(pred.args[1])
    elif pred.name == "attr":
        if pos:
            c.attributes[pred.args[1]] = pred.args[2]
        else:
            c.banned_values.setdefault(pred.args[1], set()).add(pred.args[2])
    elif pred.name == "state":
        c.states[pred.args[1]] = pos


#: predicates that say where an object is
_WHERE = frozenset({"on", "inside", "in_room"})


def _described(choice: dict[str, RoleChoice], brief: Mapping[str, Any], facts: list[str],
               catalog: Catalog) -> None:
    """Placements the description states ("a nightstand with a lamp", "the drying rack out on the
    balcony"), for objects whose place no situation fact speaks of, held by an object present and
    not ruled out (`offline.placement`): a reader of the text puts them there."""
    # a negated placement says where the object is not; the description may still say where it is
    placed = {pred.args[0] for text in facts for pred, pos in _literals(parse(text)) if pred.name in _WHERE and pos}
    for text in described_placements(brief, catalog):
        for pred, pos in _literals(parse(text)):
            c = choice.get(pred.args[0])
            if c is None or pred.args[0] in placed or not c.present:
                continue
            if pred.name == "in_room" and pred.args[1] in c.banned_rooms:
                continue
            if pred.name == "on" and pred.args[1] == "floor":
                if "floor" in c.banned_places:
                    continue
            elif pred.name in ("on", "inside") and (
                    pred.args[1] not in choice or not choice[pred.args[1]].present
                    or f"{pred.name}:{pred.args[1]}" in c.banned_places
                    or not _fits_on(pred.args[0], pred.args[1], pred.name, brief["roles"], catalog)):
                continue
            _apply(choice, pred, pos)


def _fits_on(item: str, holder: str, relation: str, roles: Mapping[str, Any], catalog: Catalog) -> bool:
    """Whether the catalog lets `item` be `relation` (on / inside) `holder` (`scene.compat.can_hold`):
    a place the text states that the layout cannot build ("my hat hangs on the hook behind the
    door", where a hook's top holds no hat) is left, and the thing goes to its typical place, so
    that the situation can still be built; a stated place is a description, not a condition the
    task asks about."""
    a, b = catalog.get(roles[item]["category"]), catalog.get(roles[holder]["category"])
    return a is None or b is None or can_hold(a, b, relation)


def _machine(role: str, roles: Mapping[str, Any], catalog: Catalog) -> bool:
    """Whether the role's kind switches on and off (a stove, a washing machine: `Category.toggleable`)."""
    kind = catalog.get(roles[role]["category"]) if role in roles else None
    return kind is not None and kind.toggleable


def _stated(choice: dict[str, RoleChoice], brief: Mapping[str, Any], facts: list[str], catalog: Catalog) -> None:
    """States the description gives a thing outright ("the ceiling fan in there is broken":
    `analysis.stated_states`), for a present object whose state no situation fact speaks of: a
    reader of the text makes the fan broken, as `_described` puts a thing where the text says."""
    if not brief.get("description"):
        return
    spoken = {(pred.args[0], pred.args[1]) for text in facts for pred, _ in _literals(parse(text))
              if pred.name == "state"}
    for text in stated_states(brief, catalog):
        for pred, pos in _literals(parse(text)):
            c = choice.get(pred.args[0])
            if pred.name == "state" and c is not None and c.present and (pred.args[0], pred.args[1]) not in spoken:
                _apply(choice, pred, pos)


def _possible(choice: dict[str, RoleChoice], roles: dict[str, Any], catalog: Catalog) -> None:
    """A placement the scene's words rule out (`llm.scene_words`: furniture rests on nothing, an
    item goes on a role that is a surface or inside one that is a container) is dropped, and the
    object goes to its typical place: a model constrained by the request's grammar cannot write it,
    whatever fact (a misread one: "the sofa inside the toy box") asked for it."""
    for r, c in choice.items():
        how, _, holder = (c.placement or "").partition(":")
        if how not in ("on", "inside"):
            continue
        item, host = catalog.get(roles[r]["category"]), catalog.get(roles[holder]["category"]) if holder in roles else None
        if item is None or holder not in roles:
            continue
        if furniture(item) or host is None or not (host.surface if how == "on" else host.container):
            c.banned_places.add(str(c.placement))
            c.placement = None


def _home_room(category: str, rooms: list[str], catalog: Catalog) -> str:
    cat = catalog.get(category)
    if cat:
        for room in rooms:
            if room_type_of(room) in cat.rooms:
                return room
    return rooms[0]


def _rooms(choice: dict[str, RoleChoice], roles: dict[str, Any], rooms: list[str], catalog: Catalog) -> None:
    # holders first: an object placed on/in another shares the holder's room
    for r, c in choice.items():
        if c.room is None and not (c.placement or "").startswith(("on:", "inside:")):
            options = [x for x in rooms if x not in c.banned_rooms] or rooms
            home = _home_room(roles[r]["category"], options, catalog)
            c.room = home if home in options else options[0]
    for _ in range(len(choice)):
        for c in choice.values():
            if c.placement and c.placement.startswith(("on:", "inside:")):
                holder = c.placement.split(":", 1)[1]
                if holder in choice and choice[holder].room is not None:
                    c.room = choice[holder].room
    for r, c in choice.items():
        c.room = c.room or _home_room(roles[r]["category"], rooms, catalog)


def _places(choice: dict[str, RoleChoice], roles: dict[str, Any], catalog: Catalog) -> None:
    for r, c in choice.items():
        if c.placement is not None:
            continue
        cat = catalog.get(roles[r]["category"])
        typical = cat.placement if cat else ["floor"]
        if typical[0] in ("floor", "wall", "ceiling") and (
                typical[0] not in c.banned_places or cat is not None and furniture(cat)):
            # furniture (a fridge, a wardrobe: `scene_words.furniture`, which rests on nothing in
            # the reply schema) stays where it stands even when a fact rules that out ("not
            # on(fridge, floor)"): a model that knows the assets never sets a fridge on a table,
            # and the unrealisable fact then simply fails, instead of every attempt at the
            # selection being refused; a mop ruled off the floor still goes on or in something
            c.placement = typical[0]
            continue
        holders = []
        for other, oc in choice.items():
            ocat = catalog.get(roles[other]["category"])
            if other == r or ocat is None or not oc.present or oc.room != c.room:
                continue
            if typical == ["inside"]:
                # a drawer is part of a piece of furniture it fits in, openable or not (a dresser,
                # a nightstand): no surface or loose place will do
                if cat is not None and ocat.container and not ocat.pickable and can_hold(cat, ocat, "inside"):
                    holders.append(f"inside:{other}")
                continue
            if oc.placement and oc.placement.startswith(("on:", "inside:")) or ocat.placement[0] == "surface":
                # no stacking on objects that themselves rest on others, placed yet or not: a
                # dish rack or a microwave stands on a counter, it is no counter for the coffee
                # machine (only a fact or the text puts a thing on or in one)
                continue
            # (a holder the catalog's sizes rule out is none: a hat on a hook's small top has no layout)
            if ocat.surface and not ocat.pickable and (cat is None or can_hold(cat, ocat, "on")):
                holders.append(f"on:{other}")
            elif ocat.container and not ocat.openable and not ocat.pickable and (
                    cat is None or can_hold(cat, ocat, "inside")):
                holders.append(f"inside:{other}")
        preferred = [h for h in holders if h not in c.banned_places]
        taken = {oc.placement for other, oc in choice.items() if other != r}
        if cat is not None and not cat.pickable:
            # an appliance nobody carries (a desktop computer, a microwave) with no place of its
            # own stands on a holder nothing rests on yet ("the desktop computer" on the desk, not
            # on the shelving unit the box of cables sits on), as a person setting up a room puts
            # it: it takes most of a top, and the layout fails where it shares one. A holder that
            # is itself a machine (a stove, a washing machine) is no place for it: its top is for
            # its own use (a toaster on the hob keeps the pan off it)
            free = [h for h in preferred if h not in taken and not _machine(h.partition(":")[2], roles, catalog)]
            preferred = free + [h for h in preferred if h not in free]
        surfaces = [h for h in preferred if h.startswith("on:")]
        if typical[0] == "inside":
            surfaces = [h for h in preferred if h.startswith("inside:")] + surfaces
        options = surfaces or preferred
        if typical[0] == "floor" and surfaces:
            # a thing of the floor a path rules off it (the scrubs "if found on floor") goes on a
            # surface nothing else rests on yet; where every surface of the room already holds
            # something ("the mug lives on the bedside table"), on one added for it: a small
            # holder seldom takes two things, and the layout then fails
            options = [h for h in surfaces if h not in taken]
            if not options:
                c.placement = NEEDS_SURFACE
                continue
        if options:
            c.placement = options[0]
        elif typical == ["inside"]:
            c.placement = NEEDS_CONTAINER
        else:
            c.placement = "floor" if "floor" not in c.banned_places else NEEDS_SURFACE


def task_objects(task: Mapping[str, Any], facts: list[str], catalog: Catalog) -> list[dict[str, Any]]:
    """Object drafts for the task's roles (id = role name) realising `facts`; a side table is added
    when an item needs a surface its room lacks, and a second one when the first is ruled out for
    it (`not on(hat, side_table_entryway_1)`: the layout found the first too crowded), and a cabinet
    for a drawer its room has no furniture for."""
    roles = task["roles"]
    objects: list[dict[str, Any]] = []
    tables: dict[str, str] = {}  # side table added -> its room
    cabinets: dict[str, str] = {}  # cabinet added for a part of furniture -> its room
    added = {("side_table", "a side table to put things on"): tables,
             ("cabinet", "a cabinet its drawers belong to"): cabinets}
    for role, c in realise(task, facts, catalog).items():
        if not c.present:
            continue
        placement = c.placement or "floor"
        room = c.room or task["rooms"][0]
        if placement == NEEDS_SURFACE:
            # a side table the situation or the layout ruled out (too crowded) makes room for another
            table = next(f"side_table_{room}_{k}" for k in range(1, len(roles) + 2)
                         if f"on:side_table_{room}_{k}" not in c.banned_places)
            tables.setdefault(table, room)
            placement = f"on:{table}"
        elif placement == NEEDS_CONTAINER:
            cabinet = f"cabinet_{room}_1"
            cabinets.setdefault(cabinet, room)
            placement = f"inside:{cabinet}"
        objects.append({"id": role, "category": roles[role]["category"], "room": room, "role": role,
                        "placement": placement, "attributes": c.attributes, "states": c.states,
                        "description": f"the {role.replace('_', ' ')}"})
    for (category, description), rooms in added.items():
        objects += [{"id": oid, "category": category, "room": room, "role": None, "placement": "floor",
                     "attributes": {}, "states": {}, "description": description} for oid, room in rooms.items()]
    return objects
