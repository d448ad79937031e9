"""`python -m logicenveval evaluate ENVS_DIR`: score environments made by any tool.

`ENVS_DIR/<task_id>/*.json` are EnvSpecs (DESIGN.md §6). Each task folder is one unit, judged
exactly as a `run` judges a generator's environments (`runner.evaluation.evaluate_env`: physics,
role binding, GT coverage, the four policies), committed to the same resumable store and
summarised into the same results.json and samples.jsonl (leaderboards: `reporting`). So scoring the
`envs/<generator>` folder of a run reproduces that run's metrics for the generator.

Every candidate file is one attempted environment (docs/logic.md). A file that is not a valid
EnvSpec (bad JSON, a missing field, another task's `task_id`) is a recorded failure of that file
with its reason and one failed attempt (it fails PhyPR and SceVR); the task's other files still
count. A task folder with no file is one failed attempt (zero coverage).
"""

from __future__ import annotations

import hashlib
import json
import re
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.atomic import atomic_write_text
from logicenveval.benchmark import load_task, load_tasks, policy_path, task_ids
from logicenveval.domain.catalog import load_catalog
from logicenveval.domain.roles import parse_role_map, unknown_roles
from logicenveval.envfiles import env_to_json, load_env
from logicenveval.errors import ConfigError, LogicEnvEvalError
from logicenveval.generators.base import Attempt, GenerationFailure
from logicenveval.limits import current as current_limits
from logicenveval.limits import limit, pinned
from logicenveval.metrics.records import EnvDetail, UnitRecord
from logicenveval.model.task import POLICY_KINDS, Task
from logicenveval.paths import check_name, child, shown
from logicenveval.runner.config import RUN_ID_PATTERN, selected_tasks
from logicenveval.runner.executors import make_executor
from logicenveval.runner.fingerprint import changed_inputs, scored_inputs, stale_reason
from logicenveval.runner.results import build_results, write_outputs
from logicenveval.runner.store import RunStore, text_digest
from logicenveval.runner.unit import limited

#: artefacts a run writes next to its environments; not EnvSpecs, so not scored
ARTEFACTS = frozenset({"plan.json", "brief.json", "retrieval.json"})


class EvaluateConfig(BaseModel):
    """What `evaluate` scores; its identity names the run folder, so a re-run resumes it."""

    model_config = ConfigDict(frozen=True, extra="forbid")
    envs_dir: str
    name: str | None = None  # leaderboard row; default: the folder's name
    tasks: tuple[str, ...] = ()  # empty: every task folder found in envs_dir
    tasks_dir: str | None = None
    workers: int = Field(default=1, ge=1)
    executor: str = "process"
    output: str = "reports"
    run_id: str | None = Field(default=None, pattern=RUN_ID_PATTERN)
    model: str = "external"
    seed: int = 0
    brief: str = "external"  # what the making tool was told is unknown to the harness
    #: `--roles ROLE=ID,...`: roles bound first in every file of a task that has them
    roles: str | None = None

    @property
    def generator_name(self) -> str:
        """The row name, checked to be a plain folder name (it names units/ and envs/ folders)."""
        if self.name is not None:
            return check_name(self.name, what="--name", field="--name")
        return check_name(Path(self.envs_dir).resolve().name, what="the folder's name (the row "
                          "name unless --name is given)", file=self.envs_dir)

    @property
    def generators(self) -> tuple[str, ...]:
        return (self.generator_name,)

    def identity(self) -> dict[str, object]:
        """What is scored, including a digest of the files: edited files give a new run folder."""
        return {
            "mode": "evaluate",
            "envs_dir": str(Path(self.envs_dir).resolve()),
            "envs_sha256": folder_digest(Path(self.envs_dir)),
            "generators": [self.generator_name],
            "tasks": list(self.tasks),
            "tasks_dir": self.tasks_dir,
            **({"roles": self.roles} if self.roles else {}),
        }

    def resolved_run_id(self) -> str:
        if self.run_id:
            return self.run_id
        blob = json.dumps(self.identity(), sort_keys=True).encode()
        slug = re.sub(r"[^A-Za-z0-9]+", "-", self.generator_name).strip("-").lower()[:40] or "envs"
        return f"evaluate-{slug}-{hashlib.sha256(blob).hexdigest()[:8]}"

    def run_dir(self) -> Path:
        return Path(self.output) / self.resolved_run_id()


class ScoreUnitSpec(BaseModel):
    """One task folder to score (picklable for process and Ray workers)."""

    model_config = ConfigDict(frozen=True)
    generator: str
    task_id: str
    folder: str
    tasks_dir: str | None
    run_dir: str
    roles: str | None = None
    #: the run's limits, read once in the parent (`runner.unit.UnitSpec.limits`)
    limits: dict[str, int] = Field(default_factory=dict)


@dataclass(frozen=True)
class EvaluateOutcome:
    run_dir: Path
    results: dict[str, Any]
    computed: int
    reused: int
    skipped_folders: list[str] = field(default_factory=list)  # not tasks of the tasks dir
    records: tuple[UnitRecord, ...] = ()  # one unit per task, in task order
    #: why stored units were recomputed -> how many (`runner.run.RunOutcome.stale`)
    stale: dict[str, int] = field(default_factory=dict)


def folder_digest(root: Path) -> str:
    """SHA-256 over every candidate EnvSpec file's relative path and content.

    A file above the size limit is refused when scored without being read, so only its size
    and modification time enter the digest; the others are hashed in chunks (no file is held in
    memory whole)."""
    h = hashlib.sha256()
    cap = limit("max_env_bytes")
    if root.is_dir():
        for folder in sorted(p for p in root.iterdir() if p.is_dir()):
            for path in env_files(folder):
                h.update(f"{folder.name}/{path.name}\0".encode("utf-8", "surrogateescape"))
                try:
                    st = path.stat()
                    if st.st_size > cap:
                        h.update(f"size {st.st_size} mtime {st.st_mtime_ns}".encode())
                        continue
                    with path.open("rb") as fh:
                        h.update(hashlib.file_digest(fh, "sha256").digest())
                except OSError as exc:  # unreadable: the per-file failure says so when scored
                    h.update(f"unreadable {exc.errno}".encode())
    return h.hexdigest()[:16]


def _natural(path: Path) -> list[object]:
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", path.name)]


def env_files(folder: Path) -> list[Path]:
    """The EnvSpec candidates of a task folder, in natural name order (env-2 before env-10)."""
    return sorted((p for p in folder.glob("*.json")
                   if p.is_file() and p.name not in ARTEFACTS and not p.name.startswith(".")),
                  key=_natural)


def score_unit(spec: ScoreUnitSpec) -> UnitRecord:
    """Judge every EnvSpec of one task folder under the run's limits (`runner.unit.run_unit`)."""
    with pinned(spec.limits) as hit:
        record = _score_unit(spec)
    return limited(record, {n: spec.limits.get(n) or limit(n) for n in sorted(hit)})


def _score_unit(spec: ScoreUnitSpec) -> UnitRecord:
    """Judge every EnvSpec of one task folder; a bad file is a failure, never an exception."""
    from logicenveval.faults.score import scorer_for
    from logicenveval.physics.render import render_svg
    from logicenveval.runner.evaluation import evaluate_env, with_killed_mutants
    from logicenveval.sim.loader import load_policy

    task = load_task(spec.task_id, spec.tasks_dir)
    catalog = load_catalog()
    policies = {k: load_policy(policy_path(task, k, spec.tasks_dir)) for k in POLICY_KINDS}
    folder = Path(spec.folder)
    failures: list[GenerationFailure] = []
    attempts: list[Attempt] = []
    samples = []
    details: list[EnvDetail] = []
    files: dict[str, str] = {}
    seen: set[str] = set()  # casefolded: two files never collide on a case-insensitive disk
    scorer = scorer_for(task, spec.tasks_dir, catalog, cache_dir=Path(spec.run_dir) / "work" / "mutants")
    for path in env_files(folder):
        try:
            env = load_env(path)
            if env.task_id != task.id:
                raise ConfigError(f"task_id {shown(env.task_id)} but the file is in the folder of task "
                                  f"{task.id!r}", file=str(path), field="task_id",
                                  hint="move the file to its task's folder or fix its task_id")
            check_name(env.env_id, what="env_id", file=str(path), field="env_id")
            if env.env_id.casefold() in seen:
                raise ConfigError(f"env_id {env.env_id!r} is used by another file of this task",
                                  file=str(path), field="env_id", hint="give every environment its own env_id")
            seen.add(env.env_id.casefold())
            given = parse_role_map(spec.roles, task.roles, strict=False)
            done = evaluate_env(spec.generator, task, env, policies, catalog, given)
            sample = with_killed_mutants(done, task, scorer, catalog)
        except LogicEnvEvalError as exc:
            failures.append(GenerationFailure(stage="load", message=str(exc), env_id=path.stem))
            attempts.append(Attempt(id=path.stem, target=path.name, stage="load", reason=str(exc)))
            continue
        except Exception as exc:  # a malformed-but-valid env must not stop the others
            why = traceback.format_exception_only(type(exc), exc)[-1].strip()
            failures.append(GenerationFailure(stage="evaluate", message=f"{path}: internal error: {why}",
                                              env_id=path.stem))
            attempts.append(Attempt(id=path.stem, target=path.name, stage="evaluate",
                                    reason=f"internal error: {why}"))
            continue
        attempts.append(Attempt(id=path.stem, target=path.name, env_id=env.env_id))
        text = env_to_json(env)  # the file as given: a resumed run re-reads it, not the bound copy
        rel = child(Path("envs"), spec.generator, spec.task_id, env.env_id, suffix=".json").as_posix()
        atomic_write_text(Path(spec.run_dir) / rel, text, durable=False)
        files[rel] = text_digest(text)
        render = child(Path("renders"), spec.generator, spec.task_id, env.env_id,
                       suffix=".svg").as_posix()
        atomic_write_text(Path(spec.run_dir) / render, render_svg(done.env, done.physics),
                          durable=False)
        samples.append(sample)
        details.append(EnvDetail(env_id=env.env_id, render=render, traces=done.traces))
    error = None
    if not samples:
        error = (f"no valid EnvSpec in {folder}" if folder.is_dir()
                 else f"no folder {folder} for this task")
    if not attempts:
        attempts.append(Attempt(id=spec.task_id, stage="load", reason=error or "no EnvSpec file"))
    return UnitRecord(generator=spec.generator, task_id=spec.task_id, samples=samples,
                      failures=failures, error=error, mutants=scorer.classes, details=details,
                      files=files, attempts=attempts)


def _task_ids(config: EvaluateConfig) -> tuple[list[str], list[str]]:
    root = Path(config.envs_dir)
    if not root.is_dir():
        raise ConfigError("not a folder", file=str(root),
                          hint="pass a folder of <task_id>/*.json EnvSpecs (e.g. a run's envs/<generator>)")
    config.generator_name  # noqa: B018  (checked before any work: it names folders)
    known = task_ids(config.tasks_dir)
    if config.tasks:
        return selected_tasks(config.tasks, known), []
    folders = sorted(p.name for p in root.iterdir() if p.is_dir() and not p.name.startswith("."))
    found = [t for t in known if t in folders]
    if not found:
        raise ConfigError(f"no folder named after a task (found {folders[:5]})", file=str(root),
                          hint="lay out ENVS_DIR/<task_id>/*.json; task ids: "
                          "`python -m logicenveval tasks list`")
    return found, [f for f in folders if f not in known]


def evaluate_envs(config: EvaluateConfig) -> EvaluateOutcome:
    """Score `config.envs_dir` into `config.run_dir()` (resuming committed task units)."""
    ids, skipped = _task_ids(config)
    tasks = load_tasks(config.tasks_dir, ids)
    unknown_roles(config.roles, [t.roles for t in tasks])  # a typo binds nothing: bad input
    run_dir = config.run_dir()
    store = RunStore(run_dir)
    store.claim(config.identity())  # held until the end: one run per folder at a time
    try:
        return _score(config, ids, skipped, tasks, run_dir, store)
    finally:
        store.unlock()


def _crashed(spec: ScoreUnitSpec, why: str) -> UnitRecord:
    return UnitRecord(generator=spec.generator, task_id=spec.task_id, error=why,
                      error_kind="infrastructure")


def _score(config: EvaluateConfig, ids: list[str], skipped: list[str], tasks: list[Task],
           run_dir: Path, store: RunStore) -> EvaluateOutcome:
    store.remove_stale_temp_files()
    name = config.generator_name
    limits = current_limits()
    specs = [ScoreUnitSpec(generator=name, task_id=t, folder=str(Path(config.envs_dir) / t),
                           tasks_dir=config.tasks_dir, run_dir=str(run_dir), roles=config.roles,
                           limits=limits)
             for t in ids]
    records: dict[str, UnitRecord] = {}
    pending = []
    inputs = {t: scored_inputs(t, config.tasks_dir) for t in ids}
    stale: dict[str, int] = {}
    for spec in specs:
        stored = store.load(name, spec.task_id)
        if stored is None or stored.error_kind == "infrastructure" or not store.files_intact(stored) \
                or any(limits.get(k) != v for k, v in stored.limits.items()):
            pending.append(spec)  # never scored, corrupt, its files changed, its worker died, or
            # shaped by a limit whose value has changed since
            continue
        changed = changed_inputs(stored.inputs, inputs[spec.task_id])
        if changed:  # judged by other code or against another task or catalog: judged again
            pending.append(spec)
            for what in changed:
                why = stale_reason(what, name, spec.task_id, stored.inputs, inputs[spec.task_id])
                stale[why] = stale.get(why, 0) + 1
        else:
            records[spec.task_id] = stored
    reused = len(records)
    start = time.perf_counter()
    executor = make_executor(config.executor, config.workers)
    if getattr(executor, "address", None) is not None:  # its workers write the run folder
        raise ConfigError("evaluate runs on this machine only: --executor ray with a cluster "
                          "address (RAY_ADDRESS) is supported by `run`", field="--executor",
                          hint="unset RAY_ADDRESS (a local Ray instance is started) or use "
                          "--executor process (docs/cluster.md)")
    for spec, record in executor.map_unordered(score_unit, pending, on_crash=_crashed):
        record = record.model_copy(update={"inputs": inputs[spec.task_id]})
        store.save(record)
        records[spec.task_id] = record
    ordered = [records[t] for t in ids]
    results = build_results(config, tasks, ordered, wall_seconds=time.perf_counter() - start,
                            generators=[name])
    write_outputs(run_dir, results, ordered)
    return EvaluateOutcome(run_dir=run_dir, results=results, computed=len(pending), reused=reused,
                           skipped_folders=skipped, records=tuple(ordered), stale=stale)

