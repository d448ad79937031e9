"""Offline answers to the behaviour-plan request kinds, derived from the description alone.

Each handler re-runs the deterministic analyser on the brief in the payload, so requests stay
independent (as with a real LLM) and nothing but the payload is read.
"""

from __future__ import annotations

from typing import Any

from logicenveval.llm.analysis import Factor, TaskAnalysis, analyse, nest
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.offline import handler
from logicenveval.model.conditions import parse

_KIND_OF_PRED = {"exists": "exists", "on": "location", "inside": "location", "in_room": "location",
                 "state": "state", "attr": "attr"}


def _analysis(payload: dict[str, Any]) -> TaskAnalysis:
    return analyse(payload["task"])


def _subtask_id(index: int, subject: str) -> str:
    return f"handle_{subject}" if index == 0 else f"handle_{subject}_{index}"


@handler("decompose_task")
def decompose(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    a = _analysis(payload)
    by_id = {f.id: f for f in a.factors}
    subtasks = []
    for group, roles in zip(a.groups, a.group_roles, strict=True):
        subject = by_id[group[0]].subject
        clauses = [c for f in group for c in by_id[f].consequences]
        subtasks.append({
            "id": _subtask_id(0, subject),
            "description": clauses[0] if clauses else f"deal with the {subject.replace('_', ' ')}",
            "roles": [subject] + sorted(roles - {subject}),
        })
    if not subtasks:  # an unconditional task: one subtask doing everything
        subtasks.append({"id": "whole_task", "description": payload["task"]["description"][:200],
                         "roles": sorted(payload["task"]["roles"])})
    return {"reasoning": f"{len(a.factors)} uncertain factor(s) found in "
            f"{len(a.sentences)} sentence(s); subtasks grouped by the object each factor tests",
            "subtasks": subtasks}


def _factors_for(a: TaskAnalysis, subtask: dict[str, Any]) -> list[Factor]:
    """The factors of the analysis group whose first-tested object leads the subtask's roles."""
    roles = list(subtask.get("roles") or [])
    subject = roles[0] if roles else None
    by_id = {f.id: f for f in a.factors}
    for group in a.groups:
        if by_id[group[0]].subject == subject:
            return [by_id[f] for f in group]
    return [f for f in a.factors if f.subject == subject]


@handler("identify_factors")
def identify_factors(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    a = _analysis(payload)
    factors = _factors_for(a, payload["subtask"])
    return {"subtask": payload["subtask"]["id"], "factors": [
        {"id": f.id, "question": f.question, "values": dict(f.values)} for f in factors]}


def _as_factor(draft: dict[str, Any], order: int) -> Factor:
    first = next(iter(draft["values"].values()))
    atoms = _atoms(first)
    kind = _KIND_OF_PRED.get(atoms[0].name, "state") if atoms else "state"
    subject = atoms[0].args[0] if atoms else ""
    return Factor(draft["id"], subject, draft.get("question", ""), dict(draft["values"]), kind, order)


def _atoms(text: str) -> list[Any]:
    from logicenveval.model.conditions import atoms

    return list(atoms(parse(text)))


@handler("build_tree")
def build_tree(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """Nest the given factors; a factor the reading found stated under a condition of another
    (`if there is no sponge` within `if the table is dirty`) is asked only under it."""
    known = {f.id: f for f in _analysis(payload).factors}
    factors = []
    for i, d in enumerate(payload.get("factors") or []):
        f = known.get(d["id"])
        factors.append(f if f is not None and f.values == d["values"] else _as_factor(d, i))
    ids = {f.id for f in factors}
    for f in factors:
        f.context = [(dep, allowed) for dep, allowed in f.context if dep in ids]
    return {"subtask": payload["subtask"]["id"], "tree": nest(factors)}


@handler("refine_tree")
def refine_tree(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    tree: dict[str, Any] = build_tree(payload, request)
    return tree


@handler("trajectories_direct")
def trajectories_direct(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """A flat reading without trees: a baseline situation, then one factor changed at a time."""
    a = _analysis(payload)
    base = {f.id: next(iter(f.values)) for f in a.factors}
    situations = [dict(base)]
    for f in a.factors:
        for value in list(f.values)[1:]:
            situations.append({**base, f.id: value})
    by_id = {f.id: f for f in a.factors}
    return {"trajectories": [
        {"description": ", ".join(f"{k}={v}" for k, v in s.items()),
         "facts": [by_id[k].values[v] for k, v in s.items()]}
        for s in situations]}
