"""The physical axioms of DESIGN.md §4 over condition-language predicates, as z3 booleans.

Two readers need to know whether conditions can hold together in one environment: `tasks
validate`, proving that a ground-truth variable's values are exclusive and exhaustive on every
path (`benchmark_validation`), and LogicEnvGen's planner, which must not plan a situation its own
factors rule out (`generators.plan`, issue 46: Qwen2.5-Coder-1.5B asked "is the bottle on the
vanity?" and "is the bottle on the floor?" as two factors, and half of the situations crossing
them put one bottle in two places). Both read the same axioms, so a plan is held to what the
benchmark's own trees are held to.

Predicates are free booleans; the axioms are: a role that is not optional and whose existence no
condition mentions exists; an object rests on or in at most one thing, never on or in itself; it
is in at most one room (by room type); an attribute has one value; every predicate about a role
other than `exists` implies that the role exists, and so does resting on or in it.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Mapping

import z3

from logicenveval.model.conditions import And, Cond, Const, Not, Or, Pred, atoms
from logicenveval.model.rooms import room_type_of
from logicenveval.model.task import Role

#: predicates that place their subject on or in another object
_HELD = ("on", "inside")


class Axioms:
    """The axioms over the predicates of `conds` (and of any condition later given to `cond`
    whose predicates were among them), for the roles `roles`.

    Each instance has its own z3 context, so instances in different threads never share solver
    state and a result never depends on earlier solves in the process.

    Not `llm.meaning._Literals`: that one checks a model's reply literals with no role table (every
    subject present unless asked, rooms by exact id), and its findings decide what a model is
    asked again; these axioms hold a task's roles (optional ones, room types, supports), as the
    benchmark's trees are checked."""

    def __init__(self, roles: Mapping[str, Role], conds: Iterable[Cond]) -> None:
        self.ctx = z3.Context()
        self.vars: dict[Pred, z3.BoolRef] = {}
        preds: set[Pred] = {p for c in conds for p in atoms(c)}
        self.axioms: list[z3.BoolRef] = []
        mentioned_exists = {p.args[0] for p in preds if p.name == "exists"}
        for role, spec in roles.items():
            if role not in mentioned_exists and not spec.optional:
                self.axioms.append(self.atom(Pred("exists", (role,))))
        by_subject: dict[str, list[Pred]] = {}
        for p in sorted(preds, key=str):
            by_subject.setdefault(p.args[0], []).append(p)
        for subject, ps in by_subject.items():
            placed = [p for p in ps if p.name in _HELD]
            self.axioms += [z3.Not(self.atom(p)) for p in placed if p.args[1] == subject]
            self._at_most_one([self.atom(p) for p in placed])
            rooms = {room_type_of(p.args[1]): p for p in ps if p.name == "in_room"}
            self._at_most_one([self.atom(p) for p in rooms.values()])
            keys = {p.args[1] for p in ps if p.name == "attr"}
            for key in keys:
                self._at_most_one([self.atom(p) for p in ps if p.name == "attr" and p.args[1] == key])
            if subject in roles:
                ex = self.atom(Pred("exists", (subject,)))
                for p in ps:
                    if p.name != "exists":
                        self.axioms.append(z3.Implies(self.atom(p), ex))
        for p in preds:
            if p.name in _HELD and p.args[1] in roles:
                self.axioms.append(z3.Implies(self.atom(p), self.atom(Pred("exists", (p.args[1],)))))

    def _at_most_one(self, lits: list[z3.BoolRef]) -> None:
        for a, b in itertools.combinations(lits, 2):
            self.axioms.append(z3.Not(z3.And(a, b)))

    def atom(self, p: Pred) -> z3.BoolRef:
        if p.name == "in_room":
            p = Pred("in_room", (p.args[0], room_type_of(p.args[1])))
        got = self.vars.get(p)
        if got is None:
            got = self.vars[p] = z3.Bool(f"{p.name}({', '.join(p.args)})", self.ctx)
        return got

    def cond(self, c: Cond) -> z3.BoolRef:
        if isinstance(c, Const):
            return z3.BoolVal(c.value, self.ctx)
        if isinstance(c, Pred):
            return self.atom(c)
        if isinstance(c, Not):
            return z3.Not(self.cond(c.operand))
        if isinstance(c, And):
            return z3.And(*[self.cond(o) for o in c.operands])
        assert isinstance(c, Or)
        return z3.Or(*[self.cond(o) for o in c.operands])

    def possible(self, *conds: Cond) -> bool:
        """Whether `conds` can all hold in one environment under the axioms (a plain check: the
        planner asks it per factor response on every path, and needs no model)."""
        return bool(self._solver(*(self.cond(c) for c in conds)).check() == z3.sat)

    def _solver(self, *formulas: z3.BoolRef) -> z3.Solver:
        s = z3.Solver(ctx=self.ctx)
        s.add(*self.axioms, *formulas)
        return s

    def witness(self, *formulas: z3.BoolRef) -> str | None:
        """A satisfying assignment of the true atoms, or None when the formulas are unsat."""
        s = self._solver(*formulas)
        if s.check() != z3.sat:
            return None
        m = s.model()
        facts = []
        for p, v in sorted(self.vars.items(), key=lambda kv: str(kv[1])):
            holds = z3.is_true(m.eval(v, model_completion=True))
            if p.name == "exists":
                facts += [] if holds else [f"not {v}"]  # present objects are the default
            elif holds:
                facts.append(str(v))
        return "{" + (", ".join(facts) or "every predicate false") + "}"
