"""Offline answers to the behaviour-plan request kinds, derived from the description alone.

Each handler re-runs the deterministic analyser on the brief in the payload, so requests stay
independent (as with a real LLM) and nothing but the payload is read.
"""

from __future__ import annotations

import re
from typing import Any

from logicenveval.llm.base import ChatRequest
from logicenveval.llm.structured import literals_of
from logicenveval.model.conditions import parse
from logicenveval.offline.analysis import Factor, TaskAnalysis, analyse, nest
from logicenveval.offline.handlers import handler

_KIND_OF_PRED = {"exists": "exists", "on": "location", "inside": "location", "in_room": "location",
                 "state": "state", "attr": "attr"}


def _analysis(payload: dict[str, Any]) -> TaskAnalysis:
    return analyse(payload["task"])


def _gist(text: str) -> str:
    """A description's words, as the reply check compares them (punctuation and case aside)."""
    return " ".join(re.findall(r"[a-z0-9]+", text.lower()))


def _subtask_id(index: int, subject: str) -> str:
    return f"handle_{subject}" if index == 0 else f"handle_{subject}_{index}"


@handler("decompose_task")
def decompose(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    a = _analysis(payload)
    by_id = {f.id: f for f in a.factors}
    subtasks = []
    said: set[str] = set()
    for group, roles in zip(a.groups, a.group_roles, strict=True):
        subject = by_id[group[0]].subject
        clauses = [c for f in group for c in by_id[f].consequences]
        description = clauses[0].strip() if clauses else ""
        if not description or _gist(description) in said:
            # "Bottle empty: into the recycling bin. Newspaper: into the recycling bin.": one
            # instruction for two objects, each subtask says which it deals with
            description = f"deal with the {subject.replace('_', ' ')}" + (f": {description}" if description else "")
        said.add(_gist(description))
        subtasks.append({
            "id": _subtask_id(0, subject),
            "description": description,
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
    return {"factors": [
        {"id": f.id, "question": f.question,
         "responses": [{"response": v, "condition": literals_of(c)} for v, c in f.values.items()]}
        for f in factors]}


def _as_factor(draft: dict[str, Any], order: int) -> Factor:
    first = next(iter(draft["values"].values()))
    atoms = _atoms(first)
    kind = _KIND_OF_PRED.get(atoms[0].name, "state") if atoms else "state"
    subject = atoms[0].args[0] if atoms else ""
    return Factor(draft["id"], subject, draft.get("question", ""), dict(draft["values"]), kind, order)


def _atoms(text: str) -> list[Any]:
    from logicenveval.model.conditions import atoms

    return list(atoms(parse(text)))


def _tree(payload: dict[str, Any]) -> dict[str, Any]:
    """The whole tree over the given factors; a factor the reading found stated under a
    condition of another (`if there is no sponge` within `if the table is dirty`) is asked only
    under it."""
    known = {f.id: f for f in _analysis(payload).factors}
    factors = []
    for i, d in enumerate(payload.get("factors") or []):
        f = known.get(d["id"])
        factors.append(f if f is not None and f.values == d["values"] else _as_factor(d, i))
    ids = {f.id for f in factors}
    for f in factors:
        f.context = [(dep, allowed) for dep, allowed in f.context if dep in ids]
    return nest(factors)


def _node_at(tree: dict[str, Any], path: list[dict[str, str]]) -> dict[str, Any]:
    node = tree
    for step in path:
        if "var" not in node or node["var"] != step["factor"] or step["response"] not in node["branches"]:
            return {"plan": [], "goal": "true"}  # the path left this tree: act
        node = node["branches"][step["response"]]
    return node


@handler("tree_step")
def tree_step(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """The factor this reading asks next on the request's path (`act` at a leaf)."""
    node = _node_at(_tree(payload), list(payload.get("path") or []))
    return {"next": node.get("var", "act")}


@handler("tree_leaves")
def tree_leaves(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    tree = _tree(payload)
    leaves = []
    for path in payload.get("leaves") or []:
        node = _node_at(tree, path)
        plan = list(node.get("plan") or []) or [payload["subtask"]["description"]]
        leaves.append({"plan": plan, "goal": literals_of(node.get("goal", "true"))})
    return {"leaves": leaves}


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
         "facts": [lit for k, v in s.items() for lit in literals_of(by_id[k].values[v])]}
        for s in situations]}
