"""The mutation score of generated environments (`faudr_mut`).

For each task, the killable first-order mutants of its correct BT (`faults.classify`) are the
faults to detect; an environment *kills* a mutant when the mutant does not pass there. The runner
simulates the killable mutants in every valid environment and stores the killed ids per
environment (`EnvSample.killed_mutants`); `metrics.compute` turns them into `faudr_mut`.

Classifying a task's mutants takes exhaustive simulation over every world of every situation
(seconds per task), so the list of killable ids is shipped in each benchmark task folder
(`killable_mutants.json`, written by `tasks mutants --write`) and cached per run, both keyed by a
hash of the task, its correct BT, the catalog, the operators and the number of worlds; a stale
file is recomputed, never trusted.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from logicenveval.atomic import atomic_write_text
from logicenveval.benchmark import policy_path
from logicenveval.domain.catalog import Catalog
from logicenveval.errors import LogicEnvEvalError, PolicyFormatError, RunStoreError
from logicenveval.faults.classify import MutantRunner, classify_task
from logicenveval.faults.operators import OPERATORS, Mutant, mutants
from logicenveval.limits import DEFAULTS, limit, read_bytes
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import Task
from logicenveval.sim.loader import load_policy, policy_to_xml
from logicenveval.sim.policy import Policy
from logicenveval.sim.simulator import task_goal
from logicenveval.sim.world import World, symbolic_key
from logicenveval.sim.worlds import DEFAULT_WORLDS


class MutationScorer:
    """Killed mutant ids of one task's environments; built once per task, reused per env."""

    def __init__(self, correct: Policy, killable: list[Mutant]) -> None:
        self.killable = killable
        self.classes = {m.id: m.fault_class for m in killable}
        self._runner = MutantRunner(correct, killable)
        self._killed: dict[str, list[str]] = {}

    def killed(self, env: EnvSpec, task: Task, catalog: Catalog, *,
               initial: World | None = None, key: str | None = None) -> list[str]:
        """Killed ids; memoised by the env's symbolic world, since the simulator sees nothing else
        (different generators often realise the same situation with the same objects).
        `initial` and `key`: `World.from_env(env, catalog)` (not changed) and
        `symbolic_key(env)` when the caller has them."""
        key = key if key is not None else symbolic_key(env)
        hit = self._killed.get(key)
        if hit is None:
            world = initial if initial is not None else World.from_env(env, catalog)
            got = self._runner.run(world, task_goal(task, world))
            hit = self._killed[key] = sorted(self.killable[i].id for i in got)
        return list(hit)

    def forget_killed(self) -> None:
        """Drop the memoised results but keep the built trees (to time a warm worker)."""
        self._killed.clear()


#: file of killable mutant ids shipped in a task folder (`tasks mutants --write`), keyed like the cache
SHIPPED_NAME = "killable_mutants.json"


def scorer_key(task: Task, correct: Policy, muts: list[Mutant], catalog: Catalog, worlds: int) -> str:
    """Content key of a task's classification: any change to what it depends on makes it stale."""
    return _key(task.model_dump_json(), policy_to_xml(correct), worlds, catalog, len(muts))


def _key(task_json: str, correct_xml: str, worlds: int, catalog: Catalog, n_mutants: int) -> str:
    return hashlib.sha256("\0".join([task_json, correct_xml, str(worlds),
                                      catalog.model_dump_json(), *sorted(OPERATORS),
                                      str(n_mutants)]).encode()).hexdigest()


def shipped_path(task: Task, tasks_dir: str | Path | None) -> Path:
    return policy_path(task, "correct", tasks_dir).parent.parent / SHIPPED_NAME


def _prepared(task: Task, tasks_dir: str | Path | None, catalog: Catalog,
              worlds: int) -> tuple[Policy, list[Mutant], str]:
    """The correct BT, its mutants and the scorer's key. Parsing the BT and listing its mutants
    is the costly part and is done once per process for the same task, BT file content and
    limits (every unit of a task in a worker needs it); the key still reads the catalog each
    time, since a generator may have changed a catalog in place."""
    path = policy_path(task, "correct", tasks_dir)
    task_json = task.model_dump_json()
    try:
        data = read_bytes(path, what="policy file", error=PolicyFormatError,
                          max_bytes="max_xml_bytes", hint="give an existing BT.CPP v4 XML file")
    except LogicEnvEvalError:
        data = None  # not cached: the loader reports it
    memo = None if data is None else (str(path), hashlib.sha256(data).digest(), task_json,
                                      tuple(limit(n) for n in DEFAULTS))
    hit = _PREPARED.get(memo) if memo is not None else None
    if hit is None:
        correct = load_policy(path, roles=task.roles, rooms=task.rooms)
        muts = mutants(correct, roles=task.roles, rooms=task.rooms)
        hit = (correct, muts, policy_to_xml(correct))
        if memo is not None:
            if len(_PREPARED) > 256:
                _PREPARED.clear()
            _PREPARED[memo] = hit
    correct, muts, xml = hit
    return correct, muts, _key(task_json, xml, worlds, catalog, len(muts))


def scorer_for(task: Task, tasks_dir: str | Path | None, catalog: Catalog, *,
               cache_dir: Path | None = None, worlds: int = DEFAULT_WORLDS) -> MutationScorer:
    """The scorer of `task`: its correct BT and killable mutants.

    The killable ids come from the task folder's shipped file, else the run's cache, else
    classification; a file whose key does not match the current task, BT, catalog and operators
    is ignored (recomputed, never trusted)."""
    correct, muts, key = _prepared(task, tasks_dir, catalog, worlds)
    hit = _SCORERS.get(key)
    if hit is not None:
        return hit
    ids = _read(shipped_path(task, tasks_dir), key)
    if ids is None and cache_dir is not None:
        ids = _read(cache_dir / f"{task.id}.json", key)
    if ids is None:
        report = classify_task(task, tasks_dir, catalog, worlds=worlds)
        ids = [o.id for o in report.killable]
        if cache_dir is not None:
            atomic_write_text(cache_dir / f"{task.id}.json", json.dumps({"key": key, "killable": ids}, indent=1) + "\n",
                              durable=False)
    keep = set(ids)
    scorer = _SCORERS[key] = MutationScorer(correct, [m for m in muts if m.id in keep])
    return scorer


def write_shipped(task: Task, tasks_dir: str | Path | None, catalog: Catalog, killable: list[str], *,
                  worlds: int = DEFAULT_WORLDS) -> Path:
    """Ship a task's killable ids in its folder, so runs need not classify it again."""
    _, _, key = _prepared(task, tasks_dir, catalog, worlds)
    path = shipped_path(task, tasks_dir)
    atomic_write_text(path, json.dumps({"key": key, "killable": killable}, indent=1) + "\n", durable=False)
    return path


def shipped_is_current(task: Task, tasks_dir: str | Path | None, catalog: Catalog, *,
                       worlds: int = DEFAULT_WORLDS) -> bool:
    _, _, key = _prepared(task, tasks_dir, catalog, worlds)
    return _read(shipped_path(task, tasks_dir), key) is not None


#: scorers by content key: a worker process builds each mutant's tree once for all its units
_SCORERS: dict[str, MutationScorer] = {}
#: correct BT, mutants and BT XML by (BT path, digest of its bytes, task JSON, limits)
_PREPARED: dict[tuple[str, bytes, str, tuple[int, ...]], tuple[Policy, list[Mutant], str]] = {}


def clear_cache() -> None:
    """Forget the scorers (and their built trees) and the parsed BTs of this process."""
    _SCORERS.clear()
    _PREPARED.clear()


def _read(path: Path, key: str) -> list[str] | None:
    """The killable ids of a shipped or cached file, or None when it is absent, unreadable
    (a folder, not UTF-8, not JSON) or stale: such a file is recomputed, never trusted."""
    try:
        data = json.loads(read_bytes(path, what="killable-mutants file", error=RunStoreError,
                                     max_bytes="max_run_file_bytes", hint="it is recomputed"))
    except (LogicEnvEvalError, ValueError, RecursionError):
        return None
    if not isinstance(data, dict) or data.get("key") != key or not isinstance(data.get("killable"), list):
        return None
    return [str(i) for i in data["killable"]]
