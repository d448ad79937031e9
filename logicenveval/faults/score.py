"""The mutation score of generated environments (`faudr_mut`).

For each task, the killable first-order mutants of its correct BT (`faults.classify`) are the
faults to detect; an environment *kills* a mutant when the mutant does not pass there. The runner
simulates the killable mutants in every valid environment and stores the killed ids per
environment (`EnvSample.killed_mutants`); `metrics.compute` turns them into `faudr_mut`.

Classifying a task's mutants takes exhaustive simulation over every world of every situation, so
the list of killable ids is cached as JSON keyed by a hash of the task, its correct BT and the
number of worlds; a stale cache is recomputed, never trusted.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

from logicenveval.benchmark import policy_path
from logicenveval.domain.catalog import Catalog
from logicenveval.faults.classify import MutantRunner, classify_task
from logicenveval.faults.operators import OPERATORS, Mutant, mutants
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import Task
from logicenveval.sim.loader import load_policy, policy_to_xml
from logicenveval.sim.policy import Policy
from logicenveval.sim.simulator import task_goal
from logicenveval.sim.world import World
from logicenveval.sim.worlds import DEFAULT_WORLDS


class MutationScorer:
    """Killed mutant ids of one task's environments; built once per task, reused per env."""

    def __init__(self, correct: Policy, killable: list[Mutant]) -> None:
        self.killable = killable
        self.classes = {m.id: m.fault_class for m in killable}
        self._runner = MutantRunner(correct, killable)

    def killed(self, env: EnvSpec, task: Task, catalog: Catalog) -> list[str]:
        world = World.from_env(env, catalog)
        got = self._runner.run(world, task_goal(task, world))
        return sorted(self.killable[i].id for i in got)


def scorer_for(task: Task, tasks_dir: str | Path | None, catalog: Catalog, *,
               cache_dir: Path | None = None, worlds: int = DEFAULT_WORLDS) -> MutationScorer:
    """The scorer of `task`: its correct BT and killable mutants (classified or from cache)."""
    correct = load_policy(policy_path(task, "correct", tasks_dir), roles=task.roles, rooms=task.rooms)
    muts = mutants(correct, roles=task.roles, rooms=task.rooms)
    key = hashlib.sha256("\0".join([task.model_dump_json(), policy_to_xml(correct), str(worlds),
                                    catalog.model_dump_json(), *sorted(OPERATORS),
                                    str(len(muts))]).encode()).hexdigest()
    hit = _SCORERS.get(key)
    if hit is not None:
        return hit
    ids = _cached(cache_dir, task.id, key)
    if ids is None:
        report = classify_task(task, tasks_dir, catalog, worlds=worlds)
        ids = [o.id for o in report.killable]
        if cache_dir is not None:
            _write(cache_dir / f"{task.id}.json", json.dumps({"key": key, "killable": ids}, indent=1))
    keep = set(ids)
    scorer = _SCORERS[key] = MutationScorer(correct, [m for m in muts if m.id in keep])
    return scorer


#: scorers by content key: a worker process builds each mutant's tree once for all its units
_SCORERS: dict[str, MutationScorer] = {}


def clear_cache() -> None:
    """Forget the scorers (and their built trees) of this process."""
    _SCORERS.clear()


def _write(path: Path, text: str) -> None:
    """Atomic write (a killed run leaves the old file or none, never half a file)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_text(text + "\n", encoding="utf-8")
    os.replace(tmp, path)


def _cached(cache_dir: Path | None, task_id: str, key: str) -> list[str] | None:
    if cache_dir is None:
        return None
    try:
        data = json.loads((cache_dir / f"{task_id}.json").read_text(encoding="utf-8"))
    except (FileNotFoundError, json.JSONDecodeError):
        return None
    if not isinstance(data, dict) or data.get("key") != key or not isinstance(data.get("killable"), list):
        return None
    return [str(i) for i in data["killable"]]
