"""What a factor's response may not ask of an object: facts its kind can never have.

Issue 46: with Qwen2.5-Coder-1.5B, LogicEnvGen's plan for `kitchen_dish_cleanup` asked "Is the
counter open?" and "Is the counter on the floor?". A kitchen counter cannot be opened and always
stands on the floor, so half of the task's planned situations could not be built, and every
environment claiming one of them failed to realise its trajectory. A factor whose response can
never hold asks nothing; rule (d) of the plan's verification (`generators.plan.check_factor`)
now names such a response and the factor is asked again, then dropped if it stays impossible.

Only what the harness itself enforces or the catalog states without exception is used, so no
fact a ground-truth tree uses is refused (checked on every task of the benchmark and of the test
sets, `tests/test_plan_feasibility.py`): a state flag needs its affordance (`FLAG_NEEDS`, as the
simulator's actions read it, `sim.world.caps_of`), and furniture (a kind that holds things, is not
pickable and whose only catalog placement is the floor) stands on the floor. The catalog's placement lists of
small things are not used: they name where a generator usually puts a kind, and the tasks ask
whether a towel or a toothbrush lies on the floor.
"""

from __future__ import annotations

from collections.abc import Iterator

from logicenveval.domain.catalog import Catalog
from logicenveval.llm.scene_words import furniture
from logicenveval.model.conditions import And, Cond, Not, Pred
from logicenveval.model.task import Role
from logicenveval.sim.world import caps_of

#: the affordance (a `Caps` field) a kind needs to hold a state flag
FLAG_NEEDS: dict[str, str] = {"open": "openable", "toggled_on": "toggleable"}

#: what each affordance is called in a message
_ABLE: dict[str, str] = {"openable": "opened", "toggleable": "switched on"}


def _literals(cond: Cond, negated: bool = False) -> Iterator[tuple[bool, Pred]]:
    """The literals that must all hold for `cond` to hold: through conjunctions and negated
    atoms only (a disjunction may hold by another of its parts, so it gives none)."""
    if isinstance(cond, Pred):
        yield negated, cond
    elif isinstance(cond, Not) and isinstance(cond.operand, Pred):
        yield not negated, cond.operand
    elif isinstance(cond, And) and not negated:
        for part in cond.operands:
            yield from _literals(part)


def floor_furniture(category: str, catalog: Catalog) -> bool:
    """A piece of furniture (`llm.scene_words.furniture`: it holds things and is not carried)
    placed only on the floor, so never anywhere else. A puddle or a stain is not pickable and lies
    only on the floor too, but "no puddle on the floor" is a situation: it holds nothing. A wall
    shelf is furniture, but off the floor."""
    cat = catalog.get(category)
    return cat is not None and furniture(cat) and cat.placement == ["floor"]


def impossible(cond: Cond, roles: dict[str, Role], catalog: Catalog) -> list[str]:
    """Why `cond` can never hold of the task's objects (one reason per literal), or []; a kind
    the catalog does not know is not judged."""
    reasons = []
    for negated, pred in _literals(cond):
        role = roles.get(pred.args[0]) if pred.args else None
        if role is None or catalog.get(role.category) is None:
            continue
        kind = role.category
        if pred.name == "state" and not negated and pred.args[1] in FLAG_NEEDS:
            need = FLAG_NEEDS[pred.args[1]]
            if not getattr(caps_of(kind, catalog), need):
                reasons.append(f"{pred.name}({', '.join(pred.args)}) can never hold: a {kind} cannot be "
                               f"{_ABLE[need]} (the catalog)")
        elif pred.name in ("on", "inside") and floor_furniture(kind, catalog):
            on_floor = pred.name == "on" and pred.args[1] == "floor"
            # a required piece of furniture is on the floor; an optional one may also be absent
            if on_floor and negated and not role.optional or not on_floor and not negated:
                text = f"{'not ' if negated else ''}{pred.name}({', '.join(pred.args)})"
                reasons.append(f"{text} can never hold: a {kind} is furniture and stands on the floor")
    return reasons
