"""The `oracle` model: answers behaviour-plan requests from the GT task (an upper bound).

It reads the task named in the request payload from the tasks folder and replies with the GT
subtasks, factors and trees; every other request kind goes to the offline handlers. Reports
label runs of this model as an upper bound.
"""

from __future__ import annotations

import itertools
import json
from pathlib import Path
from typing import Any

from logicenveval.benchmark import load_task
from logicenveval.errors import ConfigError
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats
from logicenveval.llm.registry import provider_factory
from logicenveval.llm.structured import literals_of
from logicenveval.model.task import Leaf, Node, Task
from logicenveval.model.tree import task_paths


def _vars_of(node: Node | Leaf) -> list[str]:
    if isinstance(node, Leaf):
        return []
    out = [node.var]
    for child in node.branches.values():
        out += [v for v in _vars_of(child) if v not in out]
    return out


class OracleModel:
    name = "oracle"

    def __init__(self, *, tasks_dir: str | None = None, stats: ModelStats | None = None) -> None:
        self.tasks_dir = Path(tasks_dir) if tasks_dir else None
        self.stats = stats or ModelStats()
        self._offline: ChatModel = provider_factory("offline")(stats=self.stats)  # by name: offline is above llm

    def _task(self, payload: dict[str, Any]) -> Task:
        try:
            task_id = payload["task"]["id"]
        except (KeyError, TypeError):
            raise ConfigError("oracle requests need payload.task.id", field="payload",
                              hint="the oracle can only answer for benchmark tasks") from None
        return load_task(task_id, self.tasks_dir)

    def complete(self, request: ChatRequest) -> str:
        kind, payload = request.kind, request.payload
        if kind not in ("decompose_task", "identify_factors", "tree_step", "tree_leaves",
                        "trajectories_direct"):
            return self._offline.complete(request)
        self.stats.add(requests=1)
        task = self._task(payload)
        reply: dict[str, Any]
        if kind == "decompose_task":
            reply = {"subtasks": [
                {"id": st.id, "description": st.description or st.id,
                 "roles": sorted(task.subtask_roles(st))} for st in task.subtasks]}
        elif kind == "identify_factors":
            st = task.subtask(payload["subtask"]["id"])
            reply = {"factors": [
                {"id": v, "question": task.variables[v].question,
                 "responses": [{"response": x, "condition": literals_of(c)}
                               for x, c in task.variables[v].values.items()]}
                for v in _vars_of(st.tree)]}
        elif kind in ("tree_step", "tree_leaves"):
            st = task.subtask(payload["subtask"]["id"])
            if kind == "tree_step":
                node = _node_at(st.tree, payload.get("path") or [])
                reply = {"next": node.var if isinstance(node, Node) else "act"}
            else:
                leaves = [_node_at(st.tree, p) for p in payload.get("leaves") or []]
                reply = {"leaves": [
                    {"plan": list(n.plan) or [st.description or st.id],
                     "goal": literals_of(n.goal)} if isinstance(n, Leaf)
                    else {"plan": [st.description or st.id], "goal": []} for n in leaves]}
        else:
            reply = {"trajectories": [
                {"description": " | ".join(p.key for p in combo),
                 "facts": [lit for p in combo for v, x in p.steps
                           for lit in literals_of(task.variables[v].values[x])]}
                for combo in itertools.product(*task_paths(task))]}
        return json.dumps(reply)


def _node_at(node: Node | Leaf, path: list[dict[str, str]]) -> Node | Leaf:
    """The GT node a path of answers leads to (a path that leaves the tree ends at a leaf)."""
    for step in path:
        if not isinstance(node, Node) or node.var != step["factor"] or step["response"] not in node.branches:
            return Leaf(plan=[], goal="true")
        node = node.branches[step["response"]]
    return node
