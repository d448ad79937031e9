"""One unit of work: one generator on one task, from generation to evaluated samples.

Units are independent and deterministic: the random generator of a unit is seeded from the run
seed and the unit's names, so results do not depend on scheduling or on the number of workers.
"""

from __future__ import annotations

import json
import sqlite3
import time
import traceback
from collections.abc import Sequence
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict

from logicenveval.atomic import atomic_write_text
from logicenveval.benchmark import load_task, policy_path
from logicenveval.domain.catalog import load_catalog
from logicenveval.envfiles import env_to_json
from logicenveval.errors import CacheMissError, LogicEnvEvalError, ModelConnectionError
from logicenveval.generators.base import (
    Attempt,
    GenerationContext,
    counted_attempts,
    make_generator,
    unit_seed,
)
from logicenveval.generators.brief import BriefMode, generator_brief
from logicenveval.generators.plugins import ensure_importable
from logicenveval.llm.base import ChatModel, ChatRequest
from logicenveval.llm.fewshot import FewShotModel
from logicenveval.metrics.records import EnvDetail, EnvSample, UnitRecord
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import POLICY_KINDS
from logicenveval.redact import redact
from logicenveval.runner.store import text_digest
from logicenveval.scene.layout import DEFAULT_SOLVER, Solver


class UnitSpec(BaseModel):
    """Everything a worker process needs to run one unit (picklable, no live objects)."""

    model_config = ConfigDict(frozen=True)
    generator: str  # the row name: seeds, storage and records use it
    task_id: str
    tasks_dir: str | None
    model: str
    model_args: str
    seed: int
    run_dir: str
    layout_solver: Solver = DEFAULT_SOLVER
    cache: str | None = None
    no_cache: bool = False
    brief: BriefMode = "roles"
    #: what the worker makes (a registered name or MODULE:ATTR; generators.plugins); None = name
    generator_target: str | None = None
    #: where the target's module was found in the parent (generators.plugins.GeneratorRef)
    generator_path: str | None = None


def _unique_ids(envs: list[EnvSpec]) -> list[EnvSpec]:
    """Environments keep their ids; a repeated id gets a numeric suffix so no file is lost."""
    seen: set[str] = set()
    out = []
    for env in envs:
        env_id, k = env.env_id, 1
        while env_id in seen:
            k += 1
            env_id = f"{env.env_id}-{k}"
        seen.add(env_id)
        out.append(env if env_id == env.env_id else env.model_copy(update={"env_id": env_id}))
    return out


def run_unit(spec: UnitSpec) -> UnitRecord:
    """Generate and evaluate; a failing generation is recorded, never raised."""
    from logicenveval.faults.score import scorer_for
    from logicenveval.llm.registry import make_model
    from logicenveval.physics.render import render_svg
    from logicenveval.runner.evaluation import evaluate_env, with_killed_mutants
    from logicenveval.sim.loader import load_policy

    task = load_task(spec.task_id, spec.tasks_dir)
    catalog = load_catalog()
    policies = {k: load_policy(policy_path(task, k, spec.tasks_dir)) for k in POLICY_KINDS}
    run_dir = Path(spec.run_dir)
    start = time.perf_counter()
    model: ChatModel | None = None
    ctx: GenerationContext | None = None
    try:
        watched = _Watched(make_model(spec.model, spec.model_args, cache_path=spec.cache,
                                      no_cache=spec.no_cache, run_dir=run_dir))
        model = watched
        if spec.brief == "description":
            model = FewShotModel(watched)
        target = spec.generator_target or spec.generator
        ensure_importable(target, spec.generator_path)
        generator = make_generator(target)
        ctx = GenerationContext(
            model=model,
            catalog=catalog,
            rng=np.random.default_rng(unit_seed(spec.seed, spec.generator, spec.task_id)),
            seed=spec.seed,
            work_dir=run_dir / "work" / spec.generator / spec.task_id,
            layout_solver=spec.layout_solver,
        )
        brief = generator_brief(task, spec.brief, model, seed=spec.seed)
        result = generator.generate(brief, ctx)
    except Exception as exc:  # a failing unit must not kill the run; it is recorded
        kind = failure_kind(exc)
        planned = ctx.planned_attempts if ctx is not None else 0
        return UnitRecord(generator=spec.generator, task_id=spec.task_id, error=_reason(exc),
                          error_kind=kind, gen_seconds=time.perf_counter() - start,
                          llm=_stats(model), attempts=[] if kind == "infrastructure"
                          else planned_failures(spec.generator, planned))
    gen_seconds = time.perf_counter() - start
    if watched.infra_error is not None:  # the generator absorbed it, but its output is incomplete
        return UnitRecord(generator=spec.generator, task_id=spec.task_id,
                          error="infrastructure failure during generation: " + watched.infra_error,
                          error_kind="infrastructure", gen_seconds=gen_seconds, llm=_stats(model))
    rel_dir = Path("envs") / spec.generator / spec.task_id
    samples: list[EnvSample] = []
    details: list[EnvDetail] = []
    files: dict[str, str] = {}
    scorer = scorer_for(task, spec.tasks_dir, catalog, cache_dir=run_dir / "work" / "mutants")
    for env in _unique_ids(result.envs):
        _write(run_dir, rel_dir / f"{env.env_id}.json", env_to_json(env), files)
        done = evaluate_env(spec.generator, task, env, policies, catalog)
        sample = with_killed_mutants(done, task, scorer, catalog)
        render = (Path("renders") / spec.generator / spec.task_id / f"{env.env_id}.svg").as_posix()
        atomic_write_text(run_dir / render, render_svg(done.env, done.physics), durable=False)
        samples.append(sample)
        details.append(EnvDetail(env_id=env.env_id, render=render, traces=done.traces))
    if spec.brief != "roles":
        _write(run_dir, rel_dir / "brief.json", brief.model_dump_json(indent=2) + "\n", files)
    if result.artifacts:
        _write(run_dir, rel_dir / "plan.json",
               json.dumps(result.artifacts, indent=2, sort_keys=True, default=str) + "\n", files)
    return UnitRecord(generator=spec.generator, task_id=spec.task_id, samples=samples,
                      failures=list(result.failures), gen_seconds=gen_seconds, llm=_stats(model),
                      mutants=scorer.classes, details=details, files=files,
                      attempts=counted_attempts(result), budget_hit=result.budget_hit)


def planned_failures(generator: str, planned: int) -> list[Attempt]:
    """A unit that failed as a whole for generation reasons: every environment it planned
    (`GenerationContext.plan_attempts`, at least one) is a failed attempt."""
    return [Attempt(id=f"{generator}-{i:02d}", stage="unit", reason="the unit failed as a whole (see its error)")
            for i in range(max(1, planned))]


def run_units(specs: tuple[UnitSpec, ...]) -> list[UnitRecord]:
    """Several units in one hand-off to a worker (see `chunk_units`)."""
    return [run_unit(spec) for spec in specs]


def chunk_units(specs: Sequence[UnitSpec], workers: int) -> list[tuple[UnitSpec, ...]]:
    """Hand-offs for `workers` processes.

    With at least 4 tasks per worker, the units of one task travel together, so they share the
    worker's memoised task analysis (the offline model reads each brief once per process, not
    once per generator) and the tail stays one task long (0.15–0.5 CPU-s per task on the
    offline run); with fewer tasks every unit is its own hand-off so that all workers get work.
    """
    by_task: dict[str, list[UnitSpec]] = {}
    for spec in specs:
        by_task.setdefault(spec.task_id, []).append(spec)
    if workers > 1 and len(by_task) >= 4 * workers:
        return [tuple(g) for g in by_task.values()]
    return [(spec,) for spec in specs]


def _write(run_dir: Path, rel: Path, text: str, files: dict[str, str]) -> None:
    """A file only generation can rebuild: not fsynced, but its digest goes into the unit."""
    atomic_write_text(run_dir / rel, text, durable=False)
    files[rel.as_posix()] = text_digest(text)


class _Watched:
    """A ChatModel proxy that remembers an infrastructure failure even when the generator
    catches it and carries on: such a unit is incomplete and must be recomputed next run."""

    def __init__(self, inner: ChatModel) -> None:
        self._inner = inner
        self.name = inner.name
        self.infra_error: str | None = None

    def complete(self, request: ChatRequest) -> str:
        try:
            return self._inner.complete(request)
        except Exception as exc:
            if self.infra_error is None and failure_kind(exc) == "infrastructure":
                self.infra_error = _reason(exc)
            raise

    def __getattr__(self, attr: str) -> Any:
        return getattr(self._inner, attr)


def failure_kind(exc: BaseException) -> Literal["infrastructure", "generation", "internal"]:
    """Infrastructure failures (endpoint, cache, disk) are not the generator's result: the next
    run recomputes them instead of reusing them."""
    if isinstance(exc, ModelConnectionError | CacheMissError | OSError | sqlite3.Error | MemoryError):
        return "infrastructure"
    return "generation" if isinstance(exc, LogicEnvEvalError) else "internal"


def _reason(exc: BaseException) -> str:
    if isinstance(exc, LogicEnvEvalError):
        text = f"{type(exc).__name__}: {exc}"
    else:
        text = "internal error: " + traceback.format_exception_only(type(exc), exc)[-1].strip()
    return redact(text if len(text) <= 2000 else text[:1997] + "...")


def _stats(model: object) -> dict[str, float]:
    stats = getattr(model, "stats", None)
    return dict(stats.as_dict()) if stats is not None else {}
