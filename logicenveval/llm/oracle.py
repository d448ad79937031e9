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
from logicenveval.llm.base import ChatRequest, ModelStats
from logicenveval.llm.offline import OfflineModel
from logicenveval.model.task import Leaf, Node, Task
from logicenveval.model.tree import task_paths


def _tree_draft(task: Task, node: Node | Leaf) -> dict[str, Any]:
    if isinstance(node, Leaf):
        return {"plan": list(node.plan), "goal": node.goal}
    return {
        "var": node.var,
        "query": task.variables[node.var].question,
        "branches": {v: _tree_draft(task, child) for v, child in node.branches.items()},
    }


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
        self._offline = OfflineModel(stats=self.stats)

    def _task(self, payload: dict[str, Any]) -> Task:
        try:
            task_id = payload["task"]["id"]
        except (KeyError, TypeError):
            raise ConfigError("oracle requests need payload.task.id", field="payload",
                              hint="the oracle can only answer for benchmark tasks") from None
        return load_task(task_id, self.tasks_dir)

    def complete(self, request: ChatRequest) -> str:
        kind, payload = request.kind, request.payload
        if kind not in ("decompose_task", "identify_factors", "build_tree", "trajectories_direct"):
            return self._offline.complete(request)
        self.stats.add(requests=1)
        task = self._task(payload)
        reply: dict[str, Any]
        if kind == "decompose_task":
            reply = {"reasoning": "ground truth", "subtasks": [
                {"id": st.id, "description": st.description or st.id,
                 "roles": sorted(task.subtask_roles(st))} for st in task.subtasks]}
        elif kind == "identify_factors":
            st = task.subtask(payload["subtask"]["id"])
            reply = {"subtask": st.id, "factors": [
                {"id": v, "question": task.variables[v].question, "values": dict(task.variables[v].values)}
                for v in _vars_of(st.tree)]}
        elif kind == "build_tree":
            st = task.subtask(payload["subtask"]["id"])
            reply = {"subtask": st.id, "tree": _tree_draft(task, st.tree)}
        else:
            reply = {"trajectories": [
                {"description": " | ".join(p.key for p in combo),
                 "facts": [task.variables[v].values[x] for p in combo for v, x in p.steps]}
                for combo in itertools.product(*task_paths(task))]}
        return json.dumps(reply)

