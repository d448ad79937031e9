"""Meaning checks of replies: what the paper's verification of a behaviour plan implies, beyond
the schema.

A reply can satisfy its JSON Schema and still mean nothing: a factor whose two responses are the
same condition (SmolLM2 gave `not state(toy, toggled_on)` twice), subtasks that copy the schema's
own description, an object resting on itself, a room adjacent to itself. The reply models call
these checks in their validators when the validation context holds `MEANING_KEY` (`ask` sets it
from request protocol 2 on), so a finding is re-asked like a schema violation, naming the exact
element to change, and counted as an invalid reply (`meaningless` in the validity table).

Exclusive and exhaustive responses are proved with z3 on the structured literals, under the
physical axioms the benchmark's own trees are checked with (`tasks validate`): an object rests on
or in at most one thing and is in at most one room, an attribute has one value, and every literal
about an object other than `exists` implies that the object exists.
"""

from __future__ import annotations

import itertools
import re
import threading
from collections.abc import Sequence
from typing import Any

import z3
from pydantic import ValidationError

#: validation-context key that turns the meaning checks on
MEANING_KEY = "_meaning_checks"


class MeaningError(ValueError):
    """A reply that is valid by its schema but says nothing usable (re-asked, counted apart)."""


def enabled(context: Any) -> bool:
    return isinstance(context, dict) and bool(context.get(MEANING_KEY))


def meaningless(exc: ValidationError) -> bool:
    """Whether a validation error is a meaning finding (not a schema violation)."""
    return any(isinstance((e.get("ctx") or {}).get("error"), MeaningError) for e in exc.errors())


# ----- factor responses -----------------------------------------------------------------------

_ARGS = ("support", "container", "room", "flag", "key", "value")


def _atom(lit: dict[str, Any]) -> tuple[str, ...]:
    return (lit["predicate"], lit["object"], *(str(lit[k]) for k in _ARGS if k in lit))


class _Contexts(threading.local):
    def __init__(self) -> None:
        self.ctx: z3.Context | None = None


_CONTEXTS = _Contexts()


def _context() -> z3.Context:
    """This thread's z3 context, made once: a context costs ~7 ms to make and free, which was
    most of the generation time spent on checking factors (1.0 s over the 25 tasks). Sharing it
    is safe: each check asks a fresh solver for sat/unsat only, which no earlier check can
    change, and a context is never used by two threads."""
    if _CONTEXTS.ctx is None:
        _CONTEXTS.ctx = z3.Context()
    return _CONTEXTS.ctx


class _Literals:
    """Literals as z3 booleans with the physical axioms over the atoms they mention.

    Not `logic.axioms.Axioms`, whose axioms these resemble: a reply's factor is checked before any
    role table is bound, so every subject it names is present unless the factor asks (no optional
    roles), a room is the exact room the reply names (not its type, `room_type_of`), and nothing is
    said of a thing resting on itself or of its support's existence. Sharing `Axioms` would change
    which replies are re-asked, a change of request protocol (`MEANING_KEY`), so the two stay."""

    def __init__(self, conditions: Sequence[Sequence[dict[str, Any]]]) -> None:
        self.ctx = _context()
        self.vars: dict[tuple[str, ...], z3.BoolRef] = {}
        self._solver: z3.Solver | None = None
        atoms = {_atom(lit) for cond in conditions for lit in cond}
        self.axioms: list[z3.BoolRef] = []
        subjects = sorted({a[1] for a in atoms})
        for subject in subjects:
            mine = sorted(a for a in atoms if a[1] == subject)
            ex = self.var(("exists", subject))
            if ("exists", subject) not in atoms:
                self.axioms.append(ex)  # an object the factor does not call missing is present
            self._at_most_one([a for a in mine if a[0] in ("on", "inside")])
            self._at_most_one([a for a in mine if a[0] == "in_room"])
            for key in sorted({a[2] for a in mine if a[0] == "attr"}):
                self._at_most_one([a for a in mine if a[0] == "attr" and a[2] == key])
            self.axioms += [z3.Implies(self.var(a), ex) for a in mine if a[0] != "exists"]

    def _at_most_one(self, atoms: list[tuple[str, ...]]) -> None:
        for a, b in itertools.combinations(atoms, 2):
            self.axioms.append(z3.Not(z3.And(self.var(a), self.var(b))))

    def var(self, atom: tuple[str, ...]) -> z3.BoolRef:
        got = self.vars.get(atom)
        if got is None:
            got = self.vars[atom] = z3.Bool("|".join(atom), self.ctx)
        return got

    def cond(self, literals: Sequence[dict[str, Any]]) -> z3.BoolRef:
        parts = [z3.Not(self.var(_atom(x))) if x["negated"] else self.var(_atom(x)) for x in literals]
        return z3.And(*parts) if parts else z3.BoolVal(True, self.ctx)

    def sat(self, *formulas: z3.BoolRef) -> bool:
        """Whether the axioms and `formulas` can hold together: one solver holds the axioms, each
        check pushes its formulas and pops them (propositional sat/unsat is a fact of the
        formulas, not of the solver's history)."""
        if self._solver is None:
            self._solver = z3.Solver(ctx=self.ctx)
            self._solver.add(*self.axioms)
        self._solver.push()
        try:
            self._solver.add(*formulas)
            return bool(self._solver.check() == z3.sat)
        finally:
            self._solver.pop()


def factor_problem(factor: str, responses: Sequence[tuple[str, Sequence[dict[str, Any]]]]) -> str | None:
    """Why a factor's responses are not distinct, mutually exclusive and jointly exhaustive, naming
    the responses to change; None when they are."""
    seen: dict[frozenset[tuple[Any, ...]], str] = {}
    for name, literals in responses:
        key = frozenset((*_atom(x), x["negated"]) for x in literals)
        if key in seen:
            return (f"factor {factor!r}: responses {seen[key]!r} and {name!r} give the same "
                    "condition; change the condition of one so that they differ")
        seen[key] = name
    logic = _Literals([lits for _, lits in responses])
    conds = [(name, logic.cond(lits)) for name, lits in responses]
    for (a, ca), (b, cb) in itertools.combinations(conds, 2):
        if logic.sat(ca, cb):
            return (f"factor {factor!r}: responses {a!r} and {b!r} can both hold in one "
                    "environment; change one so that they exclude each other (e.g. negate a literal)")
    if logic.sat(z3.Not(z3.Or(*[c for _, c in conds]))):
        return (f"factor {factor!r}: its responses {[n for n, _ in conds]} leave some environments "
                "without an answer; add a response or widen one so that together they cover every case")
    return None


# ----- subtasks ---------------------------------------------------------------------------------

def _words(text: str) -> str:
    return " ".join(re.findall(r"[a-z0-9]+", text.lower()))


def subtask_problem(subtasks: Sequence[tuple[str, str]], schema_texts: Sequence[str]) -> str | None:
    """Why subtasks (id, description) repeat the schema's own text or each other; None when not."""
    copied = {_words(t) for t in schema_texts if t}
    seen: dict[str, str] = {}
    for sid, description in subtasks:
        words = _words(description)
        if words in copied:
            return (f"subtask {sid!r}: its description copies the schema's description text; "
                    "write one sentence saying what this subtask achieves in this task")
        if words in seen:
            return (f"subtask {sid!r}: its description repeats subtask {seen[words]!r}; "
                    "merge them or say what each achieves")
        seen[words] = sid
    return None


# ----- objects and rooms ------------------------------------------------------------------------

#: what `on:` may name besides an object (`on:floor` is the floor, as construction reads it)
SURFACES = frozenset({"floor", "wall", "ceiling"})


def placement_problem(objects: Sequence[tuple[str, str]]) -> str | None:
    """An object (id, placement) placed on or inside itself, or on or inside something that is
    not an object of the same reply (Qwen2.5-Coder-1.5B wrote `inside:kitchen`, a room), named;
    None when none is."""
    ids = {oid for oid, _ in objects}
    for oid, placement in objects:
        kind, _, target = placement.partition(":")
        if kind in ("on", "inside") and target == oid:
            return (f"object {oid!r} is placed {kind}:{oid}, on or in itself; give it another "
                    "support or container, or the floor")
        if kind == "inside" and target not in ids or kind == "on" and target not in ids | SURFACES:
            return (f"object {oid!r} is placed {kind}:{target}, but {target!r} is not an object of "
                    "this reply; place it on the floor, or on or inside an object listed here")
    return None


def adjacency_problem(rooms: Sequence[tuple[str, Sequence[str]]]) -> str | None:
    """A room (id, adjacent_to) adjacent to itself, named; None when none is."""
    for rid, adjacent in rooms:
        if rid in adjacent:
            return f"room {rid!r} lists itself in adjacent_to; list only other rooms"
    return None


def unbound_roles(objects: Sequence[tuple[str, str | None]], roles: Sequence[str]) -> list[str]:
    """The roles no object (id, role) plays: an object binds a role through its `role` field or
    by having the role's name as its id."""
    bound = {role for _, role in objects if role} | {oid for oid, _ in objects}
    return [r for r in roles if r not in bound]


def present_roles(roles: Sequence[str], facts: Sequence[str]) -> list[str]:
    """The roles a situation needs an object for: all but those its facts (condition-language
    strings) declare absent with `not exists(r)`."""
    from logicenveval.model.conditions import Not, Pred, parse

    absent = set()
    for fact in facts:
        cond = parse(fact)
        if isinstance(cond, Not) and isinstance(cond.operand, Pred) and cond.operand.name == "exists":
            absent.add(cond.operand.args[0])
    return [r for r in roles if r not in absent]
