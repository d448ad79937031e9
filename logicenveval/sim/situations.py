"""Minimal symbolic environments that realise one logical trajectory (issue 3, item 7).

The chosen values of every decision path are encoded in z3 together with the physical axioms
(each object has exactly one support or one container, one room, lives in its holder's room,
supports are surfaces, containers are containers, no holder cycles, attribute values from the
catalog's domains); soft constraints prefer natural defaults (furniture on the floor, small
objects on a surface of their room or on the floor and not in containers, catalog default
states). The task's explicit constraints are hard (a constraint about an optional role only
when that role exists). The result is re-checked with the GT trees and the constraints, so the
environment reaches exactly the requested leaves.
"""

from __future__ import annotations

from typing import Any

import z3

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.errors import TrajectoryError
from logicenveval.model.conditions import And, Cond, Const, Not, Or, Pred
from logicenveval.model.envspec import Door, EnvObject, EnvSpec, Room
from logicenveval.model.rooms import room_type_of
from logicenveval.model.task import Node, Task
from logicenveval.model.tree import Trajectory, evaluate_task
from logicenveval.sim.world import caps_of, holds_initial

_OTHER = "other"


class _Encoding:
    """z3 variables of one situation: one object per role, id = role name."""

    def __init__(self, task: Task, catalog: Catalog) -> None:
        self.task = task
        self.catalog = catalog
        self.roles = list(task.roles)
        self.index = {r: i for i, r in enumerate(self.roles)}
        self.rooms = list(task.rooms)
        n = len(self.roles)
        self.caps = [caps_of(task.roles[r].category, catalog) for r in self.roles]
        # a private z3 context: the optimum found must not depend on earlier solves in the process
        self.ctx = z3.Context()
        self.exists = [z3.Bool(f"exists_{r}", self.ctx) for r in self.roles]
        self.room = [z3.Int(f"room_{r}", self.ctx) for r in self.roles]
        # support: 0 none, 1 floor, 2 + j object j; container: 0 none, 1 + j object j
        self.sup = [z3.Int(f"sup_{r}", self.ctx) for r in self.roles]
        self.cont = [z3.Int(f"cont_{r}", self.ctx) for r in self.roles]
        self.level = [z3.Int(f"level_{r}", self.ctx) for r in self.roles]
        self.attrs: dict[tuple[int, str], tuple[z3.ArithRef, list[str]]] = {}
        self.flags: dict[tuple[int, str], z3.BoolRef] = {}
        self.opt = z3.Optimize(ctx=self.ctx)
        self._axioms(n)

    def _axioms(self, n: int) -> None:
        o = self.opt
        for i in range(n):
            o.add(self.room[i] >= 0, self.room[i] < len(self.rooms))
            o.add(self.sup[i] >= 0, self.sup[i] <= n + 1, self.sup[i] != 2 + i)
            o.add(self.cont[i] >= 0, self.cont[i] <= n, self.cont[i] != 1 + i)
            o.add((self.sup[i] == 0) != (self.cont[i] == 0))  # one support XOR one container
            for j in range(n):
                if j == i:
                    continue
                on_j, in_j = self.sup[i] == 2 + j, self.cont[i] == 1 + j
                if not self.caps[j].surface:
                    o.add(z3.Not(on_j))
                if not self.caps[j].container:
                    o.add(z3.Not(in_j))
                holder = z3.Or(on_j, in_j)
                o.add(z3.Implies(holder, z3.And(self.exists[j], self.room[i] == self.room[j],
                                                 self.level[i] > self.level[j])))
            # natural defaults
            o.add_soft(self.exists[i], 100)
            if self.caps[i].pickable:
                o.add_soft(self.cont[i] == 0, 3)
                # on furniture (a non-pickable surface), not stacked on another small object
                furniture = [self.sup[i] == 2 + j for j in range(n)
                             if j != i and self.caps[j].surface and not self.caps[j].pickable]
                if furniture:
                    o.add_soft(z3.Or(*furniture), 1)
                for j in range(n):
                    if j != i and self.caps[j].pickable:
                        o.add_soft(z3.And(self.sup[i] != 2 + j, self.cont[i] != 1 + j), 2)
            else:
                o.add_soft(self.sup[i] == 1, 5)
            cat = self.catalog.get(self.task.roles[self.roles[i]].category)
            if cat is not None and cat.rooms:
                good = [k for k, r in enumerate(self.rooms) if room_type_of(r) in cat.rooms]
                if good:
                    o.add_soft(z3.Or(*[self.room[i] == k for k in good]), 1)
            o.add_soft(self.room[i] == 0, 1)

    # ----- predicates --------------------------------------------------------------------
    def _obj(self, name: str) -> int | None:
        return self.index.get(name)

    def _attr(self, i: int, key: str, value: str) -> z3.BoolRef:
        got = self.attrs.get((i, key))
        if got is None:
            role = self.task.roles[self.roles[i]]
            cat = self.catalog.get(role.category)
            domain = list(cat.attributes.get(key, [])) if cat is not None else []
            for v in self._mentioned_values(self.roles[i], key):
                if v not in domain:
                    domain.append(v)
            if _OTHER not in domain:
                domain.append(_OTHER)
            var = z3.Int(f"attr_{self.roles[i]}_{key}", self.ctx)
            self.opt.add(var >= 0, var < len(domain))
            fixed = role.attributes.get(key)
            if fixed is not None:
                self.opt.add(var == domain.index(fixed))
            got = self.attrs[(i, key)] = (var, domain)
        var, domain = got
        return var == domain.index(value) if value in domain else z3.BoolVal(False, self.ctx)

    def _mentioned_values(self, role: str, key: str) -> list[str]:
        out: list[str] = []
        fixed = self.task.roles[role].attributes.get(key)
        if fixed is not None:
            out.append(fixed)
        for var in self.task.variables.values():
            for value in var.values:
                for p in _atoms(var.condition(value)):
                    if p.name == "attr" and p.args[0] == role and p.args[1] == key:
                        out.append(p.args[2])
        for c in self.task.constraints:
            for p in _atoms(c.condition()):
                if p.name == "attr" and p.args[0] == role and p.args[1] == key:
                    out.append(p.args[2])
        return out

    def _flag(self, i: int, flag: str) -> z3.BoolRef:
        got = self.flags.get((i, flag))
        if got is None:
            got = self.flags[(i, flag)] = z3.Bool(f"state_{self.roles[i]}_{flag}", self.ctx)
            cat = self.catalog.get(self.task.roles[self.roles[i]].category)
            default = bool(cat.default_states.get(flag, False)) if cat is not None else False
            self.opt.add_soft(got if default else z3.Not(got), 2)
        return got

    def pred(self, p: Pred) -> z3.BoolRef:
        name, args = p.name, p.args
        if name in ("holding", "near"):
            return z3.BoolVal(args[0] == "floor" and name == "near", self.ctx)
        if name == "agent_in":
            return z3.BoolVal(bool(self.rooms) and (args[0] == self.rooms[0]
                                                    or args[0] == room_type_of(self.rooms[0])), self.ctx)
        i = self._obj(args[0])
        if i is None:
            return z3.BoolVal(False, self.ctx)
        ex = self.exists[i]
        if name == "exists":
            return ex
        if name == "on":
            if args[1] == "floor":
                return z3.And(ex, self.sup[i] == 1)
            j = self._obj(args[1])
            return z3.And(ex, self.sup[i] == 2 + j) if j is not None else z3.BoolVal(False, self.ctx)
        if name == "inside":
            j = self._obj(args[1])
            return z3.And(ex, self.cont[i] == 1 + j) if j is not None else z3.BoolVal(False, self.ctx)
        if name == "in_room":
            ks = [k for k, r in enumerate(self.rooms) if args[1] in (r, room_type_of(r))]
            return z3.And(ex, z3.Or(*[self.room[i] == k for k in ks])) if ks else z3.BoolVal(False, self.ctx)
        if name == "attr":
            return z3.And(ex, self._attr(i, args[1], args[2]))
        if name == "state":
            return z3.And(ex, self._flag(i, args[1]))
        return z3.BoolVal(False, self.ctx)

    def cond(self, c: Cond) -> z3.BoolRef:
        if isinstance(c, Const):
            return z3.BoolVal(c.value, self.ctx)
        if isinstance(c, Pred):
            return self.pred(c)
        if isinstance(c, Not):
            return z3.Not(self.cond(c.operand))
        if isinstance(c, And):
            return z3.And(*[self.cond(x) for x in c.operands])
        if isinstance(c, Or):
            return z3.Or(*[self.cond(x) for x in c.operands])
        raise TypeError(c)


def _atoms(c: Cond) -> list[Pred]:
    if isinstance(c, Pred):
        return [c]
    if isinstance(c, Not):
        return _atoms(c.operand)
    if isinstance(c, And | Or):
        return [a for x in c.operands for a in _atoms(x)]
    return []


def _path_constraints(task: Task, trajectory: Trajectory) -> list[tuple[str, str, Cond, bool]]:
    """(subtask, variable, condition, wanted truth) for every edge of every chosen path."""
    out: list[tuple[str, str, Cond, bool]] = []
    for path in trajectory.paths:
        node = task.subtask(path.subtask).tree
        for var, value in path.steps:
            if not isinstance(node, Node) or node.var != var or value not in node.branches:
                raise TrajectoryError(f"path {path.key} does not follow the tree of subtask "
                                      f"{path.subtask!r} at {var}={value}",
                                      field=f"subtasks.{path.subtask}",
                                      hint="build trajectories with trajectory_from_assignment")
            variable = task.variables[var]
            for other in node.branches:
                out.append((path.subtask, var, variable.condition(other), other == value))
            node = node.branches[value]
    return out


_CACHE: dict[tuple[str, str, int], tuple[Catalog, EnvSpec]] = {}


def situation_env(task: Task, trajectory: Trajectory, catalog: Catalog | None = None) -> EnvSpec:
    """A symbolic EnvSpec (no geometry) in which the GT trees reach exactly `trajectory`.

    Results are memoised per (task content, trajectory, catalog): EnvSpecs are immutable and
    validation, benchmarks and metrics ask for the same situations repeatedly.
    """
    cat = catalog if catalog is not None else load_catalog()
    key = (task.model_dump_json(), trajectory.key, id(cat))
    hit = _CACHE.get(key)
    if hit is not None and hit[0] is cat:
        return hit[1]
    env = _situation_env(task, trajectory, cat)
    if len(_CACHE) > 4096:
        _CACHE.clear()
    _CACHE[key] = (cat, env)
    return env


def _situation_env(task: Task, trajectory: Trajectory, cat: Catalog) -> EnvSpec:
    if [p.subtask for p in trajectory.paths] != [s.id for s in task.subtasks]:
        raise TrajectoryError("the trajectory must give one path per subtask in task order",
                              field="trajectory", hint=f"subtasks: {[s.id for s in task.subtasks]}")
    enc = _Encoding(task, cat)
    edges = _path_constraints(task, trajectory)
    labels: list[tuple[z3.BoolRef, str, str]] = []
    for k, (subtask, var, cond, wanted) in enumerate(edges):
        lit = z3.Bool(f"edge_{k}", enc.ctx)
        f = enc.cond(cond)
        enc.opt.add(lit == (f if wanted else z3.Not(f)))
        labels.append((lit, subtask, var))
    for k, c in enumerate(task.constraints):
        lit = z3.Bool(f"constraint_{k}", enc.ctx)
        cond = c.condition()
        optional = sorted({a for p in _atoms(cond) for a in p.args
                           if a in task.roles and task.roles[a].optional})
        guard = z3.And(*[enc.exists[enc.index[r]] for r in optional]) if optional else None
        f = enc.cond(cond)
        enc.opt.add(lit == (f if guard is None else z3.Implies(guard, f)))
        labels.append((lit, "constraint", c.fact))
    check = enc.opt.check(*[lit for lit, _, _ in labels])
    if check != z3.sat:
        core = enc.opt.unsat_core() if check == z3.unsat else []
        names = {str(c) for c in core}
        blamed = [f"{st} {var}" if st == "constraint" else f"{st}/{var}"
                  for lit, st, var in labels if str(lit) in names] or ["?"]
        raise TrajectoryError(f"trajectory {trajectory.key} cannot be realised: the conditions of "
                              f"{', '.join(dict.fromkeys(blamed))} contradict each other or the "
                              "physical axioms", field="trajectory",
                              hint="check the variables' conditions, the constraints and the "
                              "roles' categories")
    env = _to_env(task, trajectory, enc, enc.opt.model())
    holds = holds_initial(env, cat)
    broken = task.violated(holds, env.roles)
    if broken:
        raise TrajectoryError(f"situation for {trajectory.key} violates constraint {broken[0].fact}",
                              field="constraints", hint="a constraint uses a predicate the "
                              "symbolic encoding cannot express; simplify it")
    got = [o.path.key if o.path else None for o in evaluate_task(task, holds)]
    want = [p.key for p in trajectory.paths]
    if got != want:
        bad = [w for g, w in zip(got, want, strict=True) if g != w]
        raise TrajectoryError(f"situation for {trajectory.key} reaches {got} instead of {bad}",
                              field="trajectory", hint="a variable uses a predicate the symbolic "
                              "encoding cannot express; simplify its condition")
    return env


def _to_env(task: Task, trajectory: Trajectory, enc: _Encoding, m: z3.ModelRef) -> EnvSpec:
    def val(x: z3.ArithRef) -> int:
        return int(m.eval(x, model_completion=True).as_long())

    present = [bool(z3.is_true(m.eval(e, model_completion=True))) for e in enc.exists]
    objects: list[EnvObject] = []
    for i, role in enumerate(enc.roles):
        if not present[i]:
            continue
        r = task.roles[role]
        sup, cont = val(enc.sup[i]), val(enc.cont[i])
        attributes = dict(r.attributes)
        for (k, key), (var, domain) in enc.attrs.items():
            if k == i:
                attributes[key] = domain[val(var)]
        cat = enc.catalog.get(r.category)
        states: dict[str, bool] = dict(cat.default_states) if cat is not None else {}
        for (k, flag), b in enc.flags.items():
            if k == i:
                states[flag] = bool(z3.is_true(m.eval(b, model_completion=True)))
        objects.append(EnvObject(
            id=role, category=r.category, room=enc.rooms[val(enc.room[i])],
            support=None if sup == 0 else "floor" if sup == 1 else enc.roles[sup - 2],
            container=None if cont == 0 else enc.roles[cont - 1],
            attributes=attributes, states=states,
        ))
    rooms = [Room(id=r, type=room_type_of(r)) for r in task.rooms]
    doors = [Door(id="d_exterior", rooms=(task.rooms[0], "exterior"))]
    doors += [Door(id=f"d{k}", rooms=(a, b)) for k, (a, b) in
              enumerate(zip(task.rooms, task.rooms[1:], strict=False))]
    data: dict[str, Any] = {
        "schema": "logicenveval.env/1", "task_id": task.id, "generator": "situation",
        "env_id": "situation:" + ",".join(f"{k}={v}" for k, v in trajectory.assignment().items()),
        "claimed_trajectory": trajectory.as_claim(), "rooms": rooms, "doors": doors,
        "objects": objects,
        "roles": {role: (role if present[i] else None) for i, role in enumerate(enc.roles)},
        "agent": {"room": task.rooms[0]},
    }
    return EnvSpec.model_validate(data)
