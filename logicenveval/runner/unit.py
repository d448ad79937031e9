"""One unit of work: one generator on one task, from generation to evaluated samples.

Units are independent and deterministic: the random generator of a unit is seeded from the run
seed and the unit's names, so results do not depend on scheduling or on the number of workers.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import signal
import sqlite3
import threading
import time
import traceback
from collections.abc import Callable, Iterator
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from logicenveval import phases
from logicenveval.atomic import atomic_write_text
from logicenveval.benchmark import load_task, policy_path, tasks_dir
from logicenveval.domain.catalog import DEFAULT_CATALOG, Catalog, load_catalog, reload_catalogs
from logicenveval.envfiles import env_from_dict, env_to_json
from logicenveval.errors import (
    CacheMissError,
    LogicEnvEvalError,
    ModelConnectionError,
    UnitBudgetError,
)
from logicenveval.generators.base import (
    Attempt,
    GenerationContext,
    GenerationFailure,
    GenerationResult,
    Generator,
    Overdue,
    counted_attempts,
    make_generator,
    unit_seed,
)
from logicenveval.generators.brief import BriefMode, NamedBrief, named_brief
from logicenveval.generators.plugins import ensure_importable
from logicenveval.limits import DEFAULTS, limit, pinned, raise_hint
from logicenveval.llm.base import ChatModel, ChatRequest
from logicenveval.llm.fewshot import FewShotModel
from logicenveval.metrics.compute import TaskMetrics
from logicenveval.metrics.records import EnvDetail, EnvSample, UnitRecord
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import POLICY_KINDS, Task, TaskBrief
from logicenveval.paths import child, name_problem, shown
from logicenveval.redact import redact
from logicenveval.runner import executors
from logicenveval.runner.results import unit_metrics
from logicenveval.runner.store import RunStore, text_digest
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
    #: keyword arguments of the generator's factory (`--generator-args`)
    generator_args: dict[str, Any] = Field(default_factory=dict)
    #: seconds the generator may take for this unit (`--unit-timeout`); None: unbounded
    unit_timeout: float | None = None
    #: re-raise a generator's exception instead of recording it (`--debug`, in-process only)
    debug: bool = False
    #: the run's limits, read and checked once in the parent (`limits.current`); empty: this
    #: process's own environment
    limits: dict[str, int] = Field(default_factory=dict)
    #: fingerprints of what makes the unit (`UnitRecord.inputs`, `runner.fingerprint`)
    inputs: dict[str, str] = Field(default_factory=dict)
    #: commit the record to the run's `units/` where it was computed (`run_units`)
    commit: bool = False
    #: called where the unit was computed, once committed, with its figures (`committed`): the
    #: command layer passes one that writes the unit's report page, so pages are made in
    #: parallel (the runner never imports reporting); a module-level function, to be pickled
    on_commit: Callable[..., None] | None = None


def _unique_ids(envs: list[EnvSpec]) -> list[EnvSpec]:
    """Environments keep their ids; a repeated id gets a numeric suffix so no file is lost.

    Ids are compared ignoring case, so two files never collide on a case-insensitive disk."""
    seen: set[str] = set()
    out = []
    for env in envs:
        env_id, k = env.env_id, 1
        while env_id.casefold() in seen:
            k += 1
            env_id = f"{env.env_id}-{k}"
        seen.add(env_id.casefold())
        out.append(env if env_id == env.env_id else env.model_copy(update={"env_id": env_id}))
    return out


# ----- the generator boundary -----------------------------------------------------------------

class GeneratorBroke(Exception):
    """What the boundary concludes when a generator misbehaves as a whole (the unit fails)."""

    def __init__(self, message: str, kind: Literal["generation", "internal"] = "internal") -> None:
        super().__init__(message)
        self.kind = kind


class UnitTimeout(Overdue):
    """Raised inside the generator when its time bound passes.

    A BaseException, so a generator's own `except Exception` does not swallow it."""


@dataclass
class Checked:
    """A generator's output after the boundary: valid environments of this task with plain,
    unique ids, every rejected one as a failure, and the artefacts as JSON text."""

    envs: list[EnvSpec]
    failures: list[GenerationFailure]
    plan_text: str | None
    returned: int  # environments the generator returned, rejected ones included
    attempts: list[Attempt]  # `counted_attempts` of what the generator returned
    budget_hit: str | None
    origin: list[str]  # the generator's own env_id of each kept environment (before `-2` suffixes)
    rejected: list[tuple[str, str, str]]  # env_id, stage, reason of each environment not kept


def call_generator(generator: Generator, brief: TaskBrief | Callable[[], TaskBrief],
                   ctx: GenerationContext, *, task_id: str, timeout: float | None) -> Checked:
    """Run `generator.generate` behind the one boundary every unit uses.

    `brief` may be made here (a callable: `--brief description` asks the model for the objects
    the description names), so that its model request is inside the unit's time bound and
    watchdog too: a server that never finishes its reply cannot hold the unit past its bound.
    The generator gets its own copy of the brief; its wall time is bounded (`_time_bound`);
    anything it raises besides an ordinary exception (SystemExit, KeyboardInterrupt, other
    BaseExceptions) and anything it returns that is not a `GenerationResult` of EnvSpecs with
    JSON artefacts becomes `GeneratorBroke` with the reason. Ordinary exceptions propagate
    to the caller, which classifies them (`failure_kind`). A real Ctrl-C still stops the run.
    """
    start = time.monotonic()
    with _interrupts() as interrupted:
        try:
            with _time_bound(timeout):
                given = brief() if callable(brief) else brief
                result = generator.generate(given.model_copy(deep=True), ctx)
        except UnitTimeout:
            raise GeneratorBroke(_late(timeout), "generation") from None
        except KeyboardInterrupt:
            if interrupted():
                raise
            raise GeneratorBroke("the generator raised KeyboardInterrupt") from None
        except SystemExit as exc:
            raise GeneratorBroke(f"the generator called sys.exit({exc.code!r})") from None
        except Exception:
            raise
        except BaseException as exc:  # GeneratorExit and other BaseException subclasses
            raise GeneratorBroke(f"the generator raised {type(exc).__name__}: {str(exc)[:200]}") from None
    if timeout is not None and time.monotonic() - start > timeout:
        raise GeneratorBroke(_late(timeout), "generation")
    return check_result(result, task_id)


def make_bounded(target: str, args: dict[str, Any], timeout: float | None) -> Generator:
    """Make the generator within `timeout` (a constructor that never returns fails the unit
    like a `generate` that never returns)."""
    try:
        with _time_bound(timeout):
            return make_generator(target, **args)
    except UnitTimeout:
        raise GeneratorBroke(_late(timeout, "the generator's constructor"), "generation") from None


def _late(timeout: float | None, what: str = "the generator") -> str:
    return (f"{what} did not return within {timeout:g} s (--unit-timeout; raise it if the "
            "generator is genuinely slow)")


def check_result(result: object, task_id: str) -> Checked:
    """Validate what a generator returned (see `call_generator`)."""
    if not isinstance(result, GenerationResult):
        raise GeneratorBroke(f"generate() returned {_what(result)}, not a GenerationResult")
    envs, failures, artifacts = result.envs, result.failures, result.artifacts
    if not isinstance(envs, list | tuple):
        raise GeneratorBroke(f"GenerationResult.envs is {_what(envs)}, not a list of EnvSpecs")
    cap = limit("max_unit_envs")
    if len(envs) > cap:
        raise GeneratorBroke(f"generate() returned {len(envs)} environments, more than the limit of "
                             f"{cap} ({raise_hint('max_unit_envs')})", "generation")
    for i, env in enumerate(envs):
        if not isinstance(env, EnvSpec):
            raise GeneratorBroke(f"GenerationResult.envs[{i}] is {_what(env)}, not an EnvSpec")
    if not isinstance(failures, list | tuple) or not all(isinstance(f, GenerationFailure) for f in failures):
        raise GeneratorBroke("GenerationResult.failures must be a list of GenerationFailure")
    if not isinstance(artifacts, dict):
        raise GeneratorBroke(f"GenerationResult.artifacts is {_what(artifacts)}, not a dict")
    plan_text = None
    if artifacts:
        try:
            plan_text = json.dumps(artifacts, indent=2, sort_keys=True, default=str) + "\n"
        except (ValueError, TypeError, RecursionError) as exc:
            raise GeneratorBroke("GenerationResult.artifacts cannot be written as JSON "
                                 f"({type(exc).__name__}: {str(exc)[:200]})") from None
    attempts = result.attempts
    if not isinstance(attempts, list | tuple) or not all(isinstance(a, Attempt) for a in attempts):
        raise GeneratorBroke("GenerationResult.attempts must be a list of Attempt")
    kept: list[EnvSpec] = []
    rejected: list[tuple[str, str, str]] = []
    out_failures = list(failures)
    for env in envs:
        checked = _checked_env(env, task_id)
        if isinstance(checked, EnvSpec):
            kept.append(checked)
        else:
            env_id = getattr(env, "env_id", None)
            safe = isinstance(env_id, str) and name_problem(env_id) is None
            out_failures.append(GenerationFailure(stage="validate", message=checked,
                                                  env_id=env_id if safe else None))
            rejected.append((env_id if isinstance(env_id, str) else "", "validate", checked))
    return Checked(envs=_unique_ids(kept), failures=out_failures, plan_text=plan_text,
                   returned=len(envs), attempts=counted_attempts(result),
                   budget_hit=result.budget_hit if isinstance(result.budget_hit, str) else None,
                   origin=[e.env_id for e in kept], rejected=rejected)


def _checked_env(env: EnvSpec, task_id: str) -> EnvSpec | str:
    """The environment as its file will hold it (re-validated), or why it is rejected."""
    env_id = getattr(env, "env_id", None)
    problem = name_problem(env_id)
    if problem is not None:
        return f"env_id {shown(env_id)} {problem}, so it cannot name a file; not judged"
    if getattr(env, "task_id", None) != task_id:
        return (f"environment {env_id!r} has task_id {shown(getattr(env, 'task_id', None))}, but "
                f"this unit is task {task_id!r}; not judged")
    objects = getattr(env, "objects", ())
    objects = objects if isinstance(objects, list | tuple) else ()
    cap = limit("max_env_objects")
    if len(objects) > cap:
        return (f"environment {env.env_id!r} has {len(objects)} objects, more than the limit of "
                f"{cap} ({raise_hint('max_env_objects')}); not judged")
    try:
        return env_from_dict(json.loads(env_to_json(env)), source=env.env_id)
    except LogicEnvEvalError as exc:
        return f"environment {env.env_id!r} is not a valid EnvSpec: {exc}"
    except Exception as exc:  # e.g. a model_construct()ed EnvSpec holding anything
        return (f"environment {env.env_id!r} cannot be written as an EnvSpec "
                f"({type(exc).__name__}: {str(exc)[:200]})")


def _what(value: object) -> str:
    return "None" if value is None else f"a {type(value).__name__}"


@contextlib.contextmanager
def _time_bound(seconds: float | None) -> Iterator[None]:
    """Raise `UnitTimeout` in this thread after `seconds` (again every second if swallowed).

    Only the main thread of a process can receive the alarm; elsewhere (a library caller's
    thread) the bound is checked when the generator returns. In a pool worker a watchdog
    thread also ends the process shortly after the bound, for a generator that blocks the
    alarm or sits in native code; the process executor then reports the unit as timed out.
    """
    if not seconds or not hasattr(signal, "setitimer") or \
            threading.current_thread() is not threading.main_thread():
        yield
        return

    def fire(signum: int, frame: object) -> None:
        raise UnitTimeout()

    old = signal.signal(signal.SIGALRM, fire)
    watchdog = None
    if executors.IN_WORKER:
        grace = max(2.0, min(seconds, 30.0))
        watchdog = threading.Timer(seconds + grace, os._exit, args=(executors.EXIT_TIMED_OUT,))
        watchdog.daemon = True
        watchdog.start()
    signal.setitimer(signal.ITIMER_REAL, seconds, 1.0)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
        if watchdog is not None:
            watchdog.cancel()


@contextlib.contextmanager
def _interrupts() -> Iterator[Callable[[], bool]]:
    """Tell a real Ctrl-C (which must stop the run) from a KeyboardInterrupt a generator raises.

    Pool workers ignore SIGINT (the run stops them), so there every KeyboardInterrupt is the
    generator's own. In the main thread the handler in place (Python's default, or the managed
    llama.cpp server's, which stops the server first) is wrapped, not replaced: a real Ctrl-C is
    noted, then handled as before."""
    seen = [False]
    previous = signal.getsignal(signal.SIGINT)
    if threading.current_thread() is not threading.main_thread() or not callable(previous):
        yield lambda: False
        return

    def on_sigint(signum: int, frame: Any) -> None:
        seen[0] = True
        if previous is not signal.default_int_handler:
            previous(signum, frame)
        raise KeyboardInterrupt

    signal.signal(signal.SIGINT, on_sigint)
    try:
        yield lambda: seen[0]
    finally:
        signal.signal(signal.SIGINT, previous)


# ----- shared state a generator could change -----------------------------------------------

_BASELINE: list[str] = []  # digest of the catalog as its file defines it (once per process)
_CHANGED: list[Catalog] = []  # catalogs a generator changed: kept alive so their id is never reused


def _digest(catalog: Catalog) -> str:
    return hashlib.sha256(catalog.model_dump_json().encode()).hexdigest()


def shared_catalog() -> tuple[Catalog, bool]:
    """The process's cached catalog, and whether it had to be restored from its file because a
    generator changed it in place (caches keyed by a catalog's id then never see the new one
    under an old id)."""
    if not _BASELINE:
        _BASELINE.append(_digest(Catalog.model_validate_json(DEFAULT_CATALOG.read_text("utf-8"))))
    catalog = load_catalog()
    if _digest(catalog) == _BASELINE[0]:
        _CHECKED[:] = [catalog]
        return catalog, False
    _CHECKED.clear()
    _CHANGED.append(catalog)
    reload_catalogs()
    return load_catalog(), True


#: the catalog the last check in this process found as its file defines it (`shared_catalog`)
_CHECKED: list[Catalog] = []


def unit_catalog() -> Catalog:
    """The catalog a unit starts from. Every unit checks the catalog after its generator ran
    (`shared_catalog`), and between that check and the next unit only the harness runs (judging,
    the unit's page), which never changes it: so a unit whose process checked this very catalog
    clean takes it without dumping it again (two dumps per unit were ~0.15 s of a default run);
    the first unit of a process, or one after a restore, checks it."""
    if _CHECKED and load_catalog() is _CHECKED[0]:
        return _CHECKED[0]
    return shared_catalog()[0]


def run_unit(spec: UnitSpec) -> UnitRecord:
    """Generate and evaluate under the run's limits; a failing generation is recorded, never
    raised. A unit a limit refused something in records the values of those limits (a re-run
    under other values recomputes it); one a limit failed as a whole is an environment failure,
    like an infrastructure one: not a result, never kept (`limited`). The record carries where
    the unit's time went (`UnitRecord.phases`; time not in a named phase is `start-up`)."""
    with phases.collect() as spent, phases.phase("start-up"), pinned(spec.limits) as hit:
        record = _run_unit(spec)
    record = limited(record, {n: spec.limits.get(n) or limit(n) for n in sorted(hit)})
    return record.model_copy(update={"phases": spent})


def limited(record: UnitRecord, values: dict[str, int]) -> UnitRecord:
    """`record` with the limits that refused something in it (`UnitRecord.limits`).

    A unit failed as a whole under a limit this run's environment set away from its default
    (`LOGICENVEVAL_MAX_*`) is an environment failure (`infrastructure`: not a result, recomputed
    by the next run). Under the defaults the refusal is the documented contract of a generator
    (docs/own-generator.md) and stays the generator's failure; either way a run under other
    values recomputes the unit."""
    if not values:
        return record
    update: dict[str, Any] = {"limits": values}
    changed = {k: v for k, v in values.items() if v != DEFAULTS[k][0]}
    if record.error is not None and changed:
        named = ", ".join(f"LOGICENVEVAL_{k.upper()}={v}" for k, v in changed.items())
        update.update(error_kind="infrastructure", attempts=[],
                      error=f"refused under {named} (a limit of this run, not the generator's "
                      f"result; the next run recomputes it): {record.error}")
    return record.model_copy(update=update)


def _run_unit(spec: UnitSpec) -> UnitRecord:
    from logicenveval.faults.score import scorer_for
    from logicenveval.llm.registry import make_model, with_unit_budget
    from logicenveval.physics.render import render_svg
    from logicenveval.runner.evaluation import evaluate_env, with_killed_mutants
    from logicenveval.sim.loader import load_policy

    with phases.phase("tasks"):
        task = _task(spec.task_id, spec.tasks_dir)
        catalog = unit_catalog()
        policies = {k: _policy(load_policy, policy_path(task, k, spec.tasks_dir)) for k in POLICY_KINDS}
    run_dir = Path(spec.run_dir)
    start = time.perf_counter()
    model: ChatModel | None = None
    ctx: GenerationContext | None = None
    try:
        watched = _Watched(make_model(spec.model, _oracle_tasks(spec, with_unit_budget(
                                          spec.model, spec.model_args, spec.unit_timeout)),
                                      cache_path=spec.cache,
                                      no_cache=spec.no_cache, run_dir=run_dir))
        model = watched
        if spec.brief == "description":
            model = FewShotModel(watched)
        target = spec.generator_target or spec.generator
        ensure_importable(target, spec.generator_path)
        generator = make_bounded(target, spec.generator_args, spec.unit_timeout)
        ctx = GenerationContext(
            model=model,
            catalog=catalog,
            rng=np.random.default_rng(unit_seed(spec.seed, spec.generator, spec.task_id)),
            seed=spec.seed,
            work_dir=run_dir / "work" / spec.generator / spec.task_id,
            layout_solver=spec.layout_solver,
        )
        with phases.phase("generation"):
            briefs: list[NamedBrief] = []

            def make_brief() -> TaskBrief:
                assert model is not None
                briefs.append(named_brief(task, spec.brief, model, seed=spec.seed, catalog=catalog))
                return briefs[0].brief

            result = call_generator(generator, make_brief, ctx, task_id=task.id,
                                    timeout=spec.unit_timeout)
            brief, retrieved = briefs[0].brief, briefs[0].retrieved
    except GeneratorBroke as exc:
        shared_catalog()
        cause = exc.__context__ if exc.kind == "internal" else None
        if spec.debug and isinstance(cause, Exception):  # sys.exit() & co. are recorded, shown
            raise cause from None
        return UnitRecord(generator=spec.generator, task_id=spec.task_id, error=redact(str(exc)),
                          error_kind=exc.kind, gen_seconds=time.perf_counter() - start,
                          traceback=None if cause is None else full_traceback(cause),
                          llm=_stats(model), attempts=planned_failures(
                              spec.generator, ctx.planned_attempts if ctx is not None else 0))
    except KeyboardInterrupt:
        if not executors.IN_WORKER:  # a real Ctrl-C of the run (workers ignore SIGINT)
            raise
        shared_catalog()
        return UnitRecord(generator=spec.generator, task_id=spec.task_id,
                          error="internal error: the generator raised KeyboardInterrupt",
                          error_kind="internal", gen_seconds=time.perf_counter() - start,
                          llm=_stats(model), attempts=planned_failures(spec.generator, 0))
    except BaseException as exc:  # a failing unit must not kill the run; it is recorded
        shared_catalog()  # (also SystemExit from a factory: it is the generator's, not ours)
        kind = failure_kind(exc)
        if spec.debug and kind != "infrastructure":
            raise
        planned = ctx.planned_attempts if ctx is not None else 0
        return UnitRecord(generator=spec.generator, task_id=spec.task_id, error=_reason(exc),
                          error_kind=kind, gen_seconds=time.perf_counter() - start,
                          traceback=full_traceback(exc),
                          llm=_stats(model), attempts=[] if kind == "infrastructure"
                          else planned_failures(spec.generator, planned))
    gen_seconds = time.perf_counter() - start
    catalog, changed = shared_catalog()  # judged with the catalog as its file defines it
    if changed:
        result.failures.append(GenerationFailure(
            stage="isolation", message="the generator changed the shared asset catalog in place; "
            "the change was undone before judging (work on ctx.catalog.model_copy(deep=True))"))
    if watched.infra_error is not None:  # the generator absorbed it, but its output is incomplete
        return UnitRecord(generator=spec.generator, task_id=spec.task_id,
                          error="infrastructure failure during generation: " + watched.infra_error,
                          error_kind="infrastructure", gen_seconds=gen_seconds, llm=_stats(model))
    rel_dir = child(Path("envs"), spec.generator, spec.task_id)
    samples: list[EnvSample] = []
    details: list[EnvDetail] = []
    files: dict[str, str] = {}
    failures = list(result.failures)
    with phases.phase("mutants"):
        scorer = scorer_for(task, spec.tasks_dir, catalog, cache_dir=run_dir / "work" / "mutants")
    unjudged = list(result.rejected)
    for env, origin in zip(result.envs, result.origin, strict=True):  # ids checked by the boundary
        _write(run_dir, child(rel_dir, env.env_id, suffix=".json"), env_to_json(env), files)
        try:
            done = evaluate_env(spec.generator, task, env, policies, catalog)
            sample = with_killed_mutants(done, task, scorer, catalog)
        except Exception as exc:  # one environment the harness cannot judge must not stop the others
            failures.append(GenerationFailure(stage="evaluate", env_id=env.env_id,
                                              message=_reason(exc)))
            unjudged.append((origin, "evaluate", _reason(exc)))
            continue
        render = child(Path("renders"), spec.generator, spec.task_id, env.env_id, suffix=".svg").as_posix()
        # drawn from the environment as stored, as `report` re-draws a lost render (with
        # `--brief description` the judged copy also maps the task's roles)
        with phases.phase("render"):
            atomic_write_text(run_dir / render, render_svg(env, done.physics), durable=False)
        samples.append(sample)
        details.append(EnvDetail(env_id=env.env_id, render=render, traces=done.traces))
    if spec.brief != "roles":
        _write(run_dir, rel_dir / "brief.json", brief.model_dump_json(indent=2) + "\n", files)
    if retrieved:  # what request protocol 6's retrieval changed in the name_objects reply
        _write(run_dir, rel_dir / "retrieval.json",
               json.dumps([asdict(r) for r in retrieved], indent=2) + "\n", files)
    if result.plan_text is not None:
        _write(run_dir, rel_dir / "plan.json", result.plan_text, files)
    error = None
    if result.returned and not samples:  # every environment was rejected or could not be judged
        first = next(f.message for f in failures if f.stage in ("validate", "evaluate"))
        error = f"none of the {result.returned} environment(s) returned could be judged; first: {first}"
    return UnitRecord(generator=spec.generator, task_id=spec.task_id, samples=samples,
                      failures=failures, gen_seconds=gen_seconds, llm=_stats(model),
                      mutants=scorer.classes, details=details, files=files, error=error,
                      error_kind=None if error is None else "generation",
                      attempts=_settled(result.attempts, unjudged), budget_hit=result.budget_hit)


def planned_failures(generator: str, planned: int) -> list[Attempt]:
    """A unit that failed as a whole for generation reasons: every environment it planned
    (`GenerationContext.plan_attempts`, at least one) is a failed attempt."""
    return [Attempt(id=f"{generator}-{i:02d}", stage="unit", reason="the unit failed as a whole (see its error)")
            for i in range(max(1, planned))]


def _settled(attempts: list[Attempt], unjudged: list[tuple[str, str, str]]) -> list[Attempt]:
    """The attempts with every built environment that was not judged — rejected by the boundary
    or not judgeable (`unjudged`: the generator's env_id, stage, reason) — turned into a failed
    attempt, so that n_attempted = judged samples + failed attempts."""
    pending: dict[str, list[tuple[str, str]]] = {}
    for env_id, stage, reason in unjudged:
        pending.setdefault(env_id, []).append((stage, reason))
    out = []
    for a in attempts:
        if a.env_id is not None and pending.get(a.env_id):
            stage, reason = pending[a.env_id].pop(0)
            a = Attempt(id=a.id, target=a.target, stage=stage, reason=reason)
        out.append(a)
    return out


@dataclass(frozen=True)
class Committed:
    """A finished unit as its worker hands it back: the record, its figures when it was measured
    (`runner.results.unit_metrics`: results.json needs them, so they are worked out in parallel
    too) and whether its `on_commit` hook (the report page) ran. A unit computed on another
    machine (`runner.cluster`) also brings the files it wrote (run-folder-relative path ->
    bytes) and the replies its model added to the reply cache, for the run's process to write."""

    record: UnitRecord
    metrics: TaskMetrics | None = None
    paged: bool = False
    files: dict[str, bytes] = field(default_factory=dict)
    replies: tuple[tuple[str, str, str, str, str], ...] = ()


def run_units(specs: tuple[UnitSpec, ...]) -> list[Committed]:
    """Several units in one hand-off to a worker (see `runner.schedule.hand_offs`), each
    committed as it finishes (`committed`)."""
    return [committed(spec, run_unit(spec)) for spec in specs]


def committed(spec: UnitSpec, record: UnitRecord) -> Committed:
    """The record with its inputs and figures, written to `units/` (atomic, durable) by the
    process that computed it when `spec.commit` (workers commit in parallel, the run's process
    only gathers), then handed to `spec.on_commit`; the write's waits on the disk overlap the
    figures and the hook, and it is done before the record is handed back. The record handed back counts the write as
    its `saving` phase (a file cannot time its own write), its figures as `results` and the hook
    as `report`; figures or a page that fail here are left to the run's process (a measured
    unit's page is not written without its figures)."""
    record = record.model_copy(update={"inputs": spec.inputs})
    if not spec.commit:
        return Committed(record)
    spent = dict(record.phases)
    with phases.collect() as more:
        with phases.phase("saving"):
            saved = RunStore(Path(spec.run_dir)).save_meanwhile(record)
        metrics = None
        if record.measured:  # a unit its figures cannot be worked out of: the run's process
            with phases.phase("results"), contextlib.suppress(Exception):  # tries and says why
                metrics = unit_metrics(_task(spec.task_id, spec.tasks_dir), record)
        paged = False
        if spec.on_commit is not None and (metrics is not None or not record.measured):
            with phases.phase("report"), contextlib.suppress(Exception):
                spec.on_commit(spec, record, metrics)
                paged = True
        with phases.phase("saving"):
            saved()
    for name, seconds in more.items():
        spent[name] = round(spent.get(name, 0.0) + seconds, 4)
    return Committed(record.model_copy(update={"phases": spent}), metrics, paged)


def _write(run_dir: Path, rel: Path, text: str, files: dict[str, str]) -> None:
    """A file only generation can rebuild: not fsynced, but its digest goes into the unit."""
    with phases.phase("writing"):
        atomic_write_text(run_dir / rel, text, durable=False)
    files[rel.as_posix()] = text_digest(text)


#: parsed tasks of this process by (folder, id, inode, size, mtime): a worker reads a task once
#: for all its units (a task's units travel together, `runner.schedule`) and their figures
_TASKS: dict[tuple[str | None, str, int, int, int], Task] = {}


def _oracle_tasks(spec: UnitSpec, kwargs: dict[str, Any]) -> dict[str, Any]:
    """The oracle reads its GT plans from the run's own tasks folder (`--tasks-dir`), unless
    `--model-args tasks_dir=` says otherwise: a run of another folder answered from the built-in
    tasks would be refused for an unknown task, or worse, score another task's plans."""
    if spec.model == "oracle" and spec.tasks_dir and "tasks_dir" not in kwargs:
        return {**kwargs, "tasks_dir": spec.tasks_dir}
    return kwargs


def _task(task_id: str, directory: str | None) -> Task:
    """`load_task`, cached while its task.json is unchanged (a miss is always `load_task`'s, so
    a bad id or file is reported by it, as before)."""
    try:
        st = (tasks_dir(directory) / task_id / "task.json").stat()
    except (OSError, ValueError):
        return load_task(task_id, directory)
    key = (directory, task_id, st.st_ino, st.st_size, st.st_mtime_ns)
    hit = _TASKS.get(key)
    if hit is None:
        if len(_TASKS) > 256:
            _TASKS.clear()
        hit = _TASKS[key] = load_task(task_id, directory)
    return hit


#: parsed policies of this process by (path, inode, size, mtime): a worker parses a task's four
#: BTs once for all its units (and the simulator compiles each once, `sim.simulator.compiled`)
_POLICIES: dict[tuple[str, int, int, int], Any] = {}


def _policy(load: Callable[[Path], Any], path: Path) -> Any:
    """`load(path)`, cached while the file is unchanged (an edit gets a new key and is re-read)."""
    try:
        st = path.stat()
    except OSError:
        return load(path)  # the loader reports it
    key = (str(path), st.st_ino, st.st_size, st.st_mtime_ns)
    hit = _POLICIES.get(key)
    if hit is None:
        if len(_POLICIES) > 512:
            _POLICIES.clear()
        hit = _POLICIES[key] = load(path)
    return hit


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
    run recomputes them instead of reusing them. A unit budget that ran out inside a model
    request is the generator's (`UnitBudgetError`), as when the runner's alarm fires first."""
    if isinstance(exc, UnitBudgetError):
        return "generation"
    if isinstance(exc, ModelConnectionError | CacheMissError | OSError | sqlite3.Error | MemoryError):
        return "infrastructure"
    return "generation" if isinstance(exc, LogicEnvEvalError) else "internal"


def _reason(exc: BaseException) -> str:
    if isinstance(exc, LogicEnvEvalError):
        text = f"{type(exc).__name__}: {exc}"
    else:
        text = "internal error: " + traceback.format_exception_only(type(exc), exc)[-1].strip()
    return redact(text if len(text) <= 2000 else text[:1997] + "...")


#: the longest traceback a unit keeps (its end: the innermost frames and the message)
MAX_TRACEBACK = 20_000


def full_traceback(exc: BaseException) -> str:
    """The exception's whole traceback (file and line of every frame, chained causes), redacted
    of secrets: what `--debug` and the task's detail page show for a unit that failed."""
    text = "".join(traceback.format_exception(type(exc), exc, exc.__traceback__))
    if len(text) > MAX_TRACEBACK:
        text = "...\n" + text[-MAX_TRACEBACK:]
    return redact(text.rstrip("\n"))


def _stats(model: object) -> dict[str, float]:
    stats = getattr(model, "stats", None)
    return dict(stats.as_dict()) if stats is not None else {}
