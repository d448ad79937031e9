"""`python -m logicenveval run`: generators × tasks → committed units → results (no leaderboard)."""

from __future__ import annotations

import contextlib
import dataclasses
import functools
import os
import tempfile
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TaskID,
    TextColumn,
    TimeRemainingColumn,
)

from logicenveval import phases
from logicenveval.benchmark import load_tasks, policy_path, task_ids
from logicenveval.benchmark_validation import situation_count
from logicenveval.errors import ConfigError, RunFailedError
from logicenveval.generators.plugins import GeneratorRef, NotConstructed, resolve_generator
from logicenveval.limits import current as current_limits
from logicenveval.metrics.compute import TaskMetrics, load_aggregation
from logicenveval.metrics.records import UnitRecord
from logicenveval.model.task import POLICY_KINDS, Task
from logicenveval.runner.config import RunConfig, selected_tasks
from logicenveval.runner.executors import Executor, RayExecutor, make_executor
from logicenveval.runner.fingerprint import (
    catalog_fingerprint,
    changed_inputs,
    generator_fingerprint,
    harness_fingerprint,
    stale_reason,
    task_fingerprint,
    unit_inputs,
)
from logicenveval.runner.placement import Placement, adopt, place, run_inputs
from logicenveval.runner.results import build_results, write_outputs
from logicenveval.runner.schedule import hand_offs
from logicenveval.runner.store import RunStore, new_folders, remove_created
from logicenveval.runner.unit import Committed, UnitSpec, planned_failures, run_units


@dataclass(frozen=True)
class HandBack:
    """Units come back with their files, which this process writes (runner.cluster); their new
    replies go to `cache` (None: the run keeps no reply cache)."""

    cache: str | None


@dataclass(frozen=True)
class RunOutcome:
    run_dir: Path
    results: dict[str, Any]
    computed: int  # units computed in this invocation
    reused: int  # units found committed from an earlier, interrupted invocation
    records: tuple[UnitRecord, ...] = ()  # every unit of the run, in (generator, task) order
    #: why stored units were recomputed (what changed, or --fresh) -> how many units it cost
    stale: dict[str, int] = field(default_factory=dict)
    #: (generator, task) of the units whose `on_commit` hook (their report page) ran in a worker
    paged: frozenset[tuple[str, str]] = frozenset()
    #: which finished run of other inputs was kept, and where this run went ("" if none)
    note: str = ""

    def stale_text(self) -> str:
        """One line per reason stored units were recomputed ("" when none was)."""
        return stale_text(self.stale)


def stale_text(stale: dict[str, int]) -> str:
    return "\n".join(f"recomputed {n} unit(s): {why}" for why, n in stale.items())


def resolve_generators(config: RunConfig) -> list[GeneratorRef]:
    """Resolve every `--generators` item (built-in, plug-in, MODULE:ATTR) before any unit runs.

    `--generator-args` of an item are keyed by the item as written or by its row name (the
    generator's `name`); a key that is neither, or both keys for one item, is refused."""
    args = config.generator_args
    by_row = {k: a for k, a in args.items() if k not in config.generators}  # only row names
    refs: list[GeneratorRef] = []
    for g in config.generators:
        refs.append(_resolved(g, args.get(g), by_row, config.unit_timeout))
    unknown = sorted(set(args) - set(config.generators) - {r.name for r in refs})
    if unknown:
        raise ConfigError(f"--generator-args names {unknown}, which is not in --generators "
                          f"{list(config.generators)} nor the row name of one "
                          f"({[r.name for r in refs]}); it would be ignored",
                          field="--generator-args",
                          hint="write NAME:key=value,... with NAME as listed in --generators")
    for g, r in zip(config.generators, refs, strict=True):
        if g != r.name and g in args and r.name in args:
            raise ConfigError(f"--generator-args given for {g!r} and for its row name {r.name!r}",
                              field="--generator-args",
                              hint="give a generator's arguments once, under one of its names")
    names = [r.name for r in refs]
    if len(set(names)) != len(names):
        raise ConfigError(f"two generators share a name in {names}", field="--generators",
                          hint="list each generator once; plug-ins need distinct `name`s")
    parallel = config.executor in ("ray", "process")  # units run in worker processes
    for r in refs:
        if parallel and not r.portable:
            raise ConfigError(
                f"generator {r.spec!r} was registered with a factory that worker processes "
                "cannot import (a lambda, a nested function or a notebook cell)",
                field="--generators",
                hint="define it in a module and pass MODULE:ATTR, or use --executor inprocess")
    return refs


def _resolved(item: str, own: dict[str, Any] | None, by_row: dict[str, dict[str, Any]],
              timeout: float | None) -> GeneratorRef:
    """One item, made with its own arguments or, when it has none, with the arguments keyed by
    its row name (learnt by making it: without arguments, or with each row-keyed set in turn
    when its factory needs some)."""
    if own is not None:
        return resolve_generator(item, own, timeout=timeout)
    try:
        ref = resolve_generator(item, {}, timeout=timeout)
    except NotConstructed as exc:
        for key in by_row:
            try:
                ref = resolve_generator(item, by_row[key], timeout=timeout)
            except ConfigError:
                continue
            if ref.name == key:
                return ref
        raise exc from None
    if ref.name in by_row:
        return resolve_generator(item, by_row[ref.name], timeout=timeout)
    return ref


def current_inputs(config: RunConfig, refs: list[GeneratorRef], ids: list[str]) -> dict[str, Any]:
    """The fingerprints of everything a run of `refs` on `ids` is made by (results.json
    `inputs`; `runner.placement`)."""
    return run_inputs(harness_fingerprint(), catalog_fingerprint(),
                      {r.name: generator_fingerprint(r) for r in refs},
                      {t: task_fingerprint(t, config.tasks_dir) for t in ids})


def check_tasks(config: RunConfig) -> list[str]:
    """The task ids a run of `config` covers (`--tasks`, `--limit`), checked."""
    if not config.generators:
        raise ConfigError("no generator selected", field="--generators",
                          hint="name at least one generator (see docs/own-generator.md)")
    available = task_ids(config.tasks_dir)
    if not available:
        raise ConfigError("no task in the tasks folder (no <task_id>/task.json)",
                          file=str(config.tasks_dir), field="--tasks-dir",
                          hint="pass the folder that holds the task folders")
    ids = selected_tasks(config.tasks, available) or available
    return ids[: config.limit] if config.limit else ids


def _preflight(config: RunConfig, run_dir: Path, model_args: str) -> dict[str, Any]:
    """Fail fast on an unreachable endpoint: one clear error instead of N failed units."""
    from logicenveval.llm.registry import make_model

    model = make_model(config.model, model_args, cache_path=config.cache,
                       no_cache=config.no_cache, run_dir=run_dir)
    check = getattr(model, "preflight", None)
    if callable(check):
        check()
    return {"model": getattr(model, "name", config.model)}


def _prepare_dir(run_dir: Path) -> None:
    """Refuse an output location that cannot hold a run before any work is done."""
    try:
        run_dir.mkdir(parents=True, exist_ok=True)
        fd, probe = tempfile.mkstemp(prefix=".write-probe.", suffix=".tmp", dir=run_dir)
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise ConfigError(f"cannot write the run folder: {exc.strerror or exc}", file=str(run_dir),
                          field="--output",
                          hint="choose a writable folder (not a file) with --output") from None


def run(config: RunConfig, *, console: Console | None = None, show_progress: bool = True,
        on_commit: Callable[..., None] | None = None,
        meanwhile: Callable[[], None] | None = None, previous: Path | None = None) -> RunOutcome:
    """Run (or resume) the units of `config`; a managed local model (`llamacpp:`) is served by
    one server for the whole run, stopped when the run ends however it ends (llm.llamacpp).
    `on_commit(spec, record, metrics)` runs where each computed unit was committed
    (`UnitSpec.on_commit`: the command layer writes the unit's report page there).
    `meanwhile()` runs in a background thread of this process while the units run, and is
    awaited before results.json is written: the imports the run's end needs (pandas for the
    aggregation, here; the report for the command layer) are then no serial work after the
    units, nor before them, where this process's set-up is what the workers wait for.

    A finished run of other inputs in the configured folder is never replaced: the run goes to a
    new version of the folder, or is refused under `--run-id` (`runner.placement`).
    `previous`: the run folder whose unchanged units to copy, decided by the caller (a seed run
    of `--seeds`, whose parent folder was placed); then no placement is done here."""
    from logicenveval.llm.llamacpp import serving

    limits = current_limits()  # once, before any work: every unit runs under these values
    phases.take()  # the run's own phases (`timing.run_phases`) start here
    with phases.phase("start-up"):
        refs = resolve_generators(config)  # the whole spec, before a server starts (minutes)
        ids = check_tasks(config)
    with phases.phase("tasks"):
        tasks = load_tasks(config.tasks_dir, ids)
        for task in tasks:  # before any unit: policy paths confined, situation count bounded
            for kind in POLICY_KINDS:
                policy_path(task, kind, config.tasks_dir)
            situation_count(task)
        inputs = current_inputs(config, refs, ids)
    placement = Placement(config.run_dir(), previous) if previous is not None else \
        place(config.run_dir(), inputs, named=config.run_id is not None, replace=config.replace)
    if placement.run_dir != config.run_dir():
        config = config.model_copy(update={"run_id": placement.run_dir.name})
    per_node = served_per_node(config)
    with serving(config.model, config.model_args, log_path=config.run_dir() / "llama-server.log",
                 start=not per_node) as model_args:
        outcome = _run(config, model_args, refs, ids, tasks, limits, inputs, placement,
                       console=console, show_progress=show_progress, on_commit=on_commit,
                       meanwhile=meanwhile, per_node=per_node)
    return replace(outcome, note=placement.note() if previous is None else "")


def served_per_node(config: RunConfig) -> bool:
    """Whether each node of the run's Ray cluster serves its managed `llamacpp:` model itself
    (one server per node, shared by its workers; runner.cluster.NodeServer) instead of one server
    on this machine: a managed model (no `base_url`) on a cluster named by an address."""
    from logicenveval.llm.llamacpp import managed_path
    from logicenveval.llm.registry import parse_model_args
    from logicenveval.runner.executors import ray_address

    return (config.executor == "ray" and not config.debug and ray_address(config.ray_address) is not None
            and managed_path(config.model) is not None
            and "base_url" not in parse_model_args(config.model_args))


def _run(config: RunConfig, model_args: str, refs: list[GeneratorRef], ids: list[str],
         tasks: list[Task], limits: dict[str, int], inputs: dict[str, Any], placement: Placement,
         *, console: Console | None, show_progress: bool,
         on_commit: Callable[..., None] | None = None,
         meanwhile: Callable[[], None] | None = None, per_node: bool = False) -> RunOutcome:
    run_dir = config.run_dir()
    with phases.phase("start-up"), _undone_if_refused(new_folders(run_dir)):
        executor = make_executor("inprocess" if config.debug else config.executor, config.workers,
                                 ray_address=config.ray_address)
        warm_up = getattr(executor, "warm_up", None)
        if callable(warm_up):
            warm_up()  # workers' imports overlap the preflight and resume scan below
        _prepare_dir(run_dir)
        if not per_node:  # else each node's server is checked when it starts (runner.cluster)
            _preflight(config, run_dir, model_args)
        store = RunStore(run_dir)
        store.claim(config.identity())  # held until the run ends: one run per folder at a time
    try:
        with _nodes_ready(executor, config, refs, ids, model_args, run_dir, per_node) as hand_back:
            return _run_units(config, refs, ids, tasks, run_dir, store, executor, console,
                              show_progress, model_args, limits, on_commit, meanwhile, inputs,
                              placement.previous, hand_back)
    finally:
        store.unlock()


def _plain_progress(console: Console, progress: Progress, bar: TaskID, start: float) -> None:
    """The line a generator gets when its last unit is done, where no bar is drawn."""
    task = next(t for t in progress.tasks if t.id == bar)
    if task.total is not None and task.completed == task.total:
        console.print(f"{task.description}: {int(task.completed)}/{int(task.total)} unit(s) done "
                      f"({time.perf_counter() - start:.0f} s)", markup=False, highlight=False,
                      soft_wrap=True)


def _adopted(earlier: RunStore | None, store: RunStore, record: UnitRecord) -> bool:
    """Copy an unchanged unit of the kept finished run into this run's folder: the files it
    wrote, its renders when they are there (a missing one is re-drawn), then the unit itself."""
    if earlier is None or not adopt(earlier.run_dir, store.run_dir, list(record.files)):
        return False
    for detail in record.details:
        if detail.render is not None:
            adopt(earlier.run_dir, store.run_dir, [detail.render])
    store.save(record)
    return True


@contextlib.contextmanager
def _undone_if_refused(created: list[Path]) -> Iterator[None]:
    """A start-up that is refused (an unknown model, an unreachable endpoint: exit 2) leaves
    no run folder behind: the folders in `created` (none existed before it) are removed again
    when empty, deepest first (`store.remove_created`)."""
    try:
        yield
    except BaseException:
        remove_created(created)
        raise


@contextlib.contextmanager
def _nodes_ready(executor: Executor, config: RunConfig, refs: list[GeneratorRef], ids: list[str],
                 model_args: str, run_dir: Path, per_node: bool) -> Iterator[HandBack | None]:
    """For an executor whose workers may be on other machines (Ray): connect, ship the code and
    data, and check every node (runner.cluster); yields how units come back (None: the
    executor's workers write the run folder themselves); disconnects when the run ends."""
    if not isinstance(executor, RayExecutor):
        yield None
        return
    from logicenveval.runner import cluster

    with phases.phase("start-up"), tempfile.TemporaryDirectory(prefix="logicenveval-ship-") as staging:
        cache = cluster.reply_cache(config.model, config.cache, config.no_cache, run_dir)
        shipment = cluster.make_shipment(tasks_dir=config.tasks_dir, ids=ids, model=config.model,
                                         cache=cache)
        executor.start(runtime_env=cluster.project_runtime_env(refs, Path(staging)))
    stops: list[Callable[[], None]] = []  # the nodes' model servers
    try:
        with phases.phase("start-up"):
            if per_node:  # `per_node`: one managed server on every node
                node_args, stop = cluster.serve_on_each_node(executor, config.model, config.model_args,
                                                                model_args)
                stops.append(stop)
                shipment = dataclasses.replace(shipment, node_model_args=node_args)
            executor.share(shipment, cluster.receive)
            cluster.check_endpoint_reach(model_args, executor.driver_ip(),
                                         [str(n.get("NodeManagerAddress")) for n in executor.nodes()])
            probe = functools.partial(cluster.node_report, refs, config.model, model_args, warm=True)
            cluster.check_nodes(executor.on_each_node(probe),
                                cluster.node_report(refs))
        yield HandBack(cache)
        # the run's folders on the nodes go; after a failure they stay (the cluster may be gone)
        with phases.phase("results"):
            executor.on_each_node(functools.partial(cluster.forget, shipment.run_key))
    finally:
        for stop in stops:
            stop()
        executor.close()


def _budget(config: RunConfig) -> Callable[[tuple[UnitSpec, ...]], float | None]:
    """The hard bound of a hand-off in a worker: the generator's own bound (`--unit-timeout`,
    enforced inside the unit) twice over plus ten minutes of judging per unit, so only a unit
    stuck where nothing else can stop it (native code holding the interpreter) meets it."""
    timeout = config.unit_timeout
    return lambda chunk: None if timeout is None else len(chunk) * (2 * timeout + 600.0)


def _crashed(chunk: tuple[UnitSpec, ...], why: str) -> list[Committed]:
    """The record of units whose worker died (committed here, since the worker could not):
    recomputed by the next run unless timed out."""
    timed_out = "time" in why
    records = [UnitRecord(generator=s.generator, task_id=s.task_id, error=why, inputs=s.inputs,
                          error_kind="generation" if timed_out else "infrastructure",
                          attempts=planned_failures(s.generator, 0) if timed_out else [])
               for s in chunk]
    with phases.phase("saving"):
        for spec, record in zip(chunk, records, strict=True):
            if spec.commit:
                RunStore(Path(spec.run_dir)).save(record)
    return [Committed(r) for r in records]


class _Background:
    """Imports the end of a run needs, done in a thread while the units run (`run`'s
    `meanwhile`): this process only waits for its workers then. A failure is left to the
    import that needs the module, which raises it where it is used."""

    def __init__(self, meanwhile: Callable[[], None] | None) -> None:
        self._meanwhile = meanwhile
        self._thread = threading.Thread(target=self._work, name="logicenveval-imports", daemon=True)
        self._thread.start()

    def _work(self) -> None:
        with contextlib.suppress(Exception):
            load_aggregation()
            if self._meanwhile is not None:
                self._meanwhile()

    def join(self) -> None:
        self._thread.join()


def _run_units(config: RunConfig, refs: list[GeneratorRef], ids: list[str], tasks: list[Task],
               run_dir: Path, store: RunStore, executor: Executor, console: Console | None,
               show_progress: bool, model_args: str, limits: dict[str, int],
               on_commit: Callable[..., None] | None,
               meanwhile: Callable[[], None] | None, run_fingerprints: dict[str, Any],
               previous: Path | None, hand_back: HandBack | None = None) -> RunOutcome:
    """`hand_back`: None when workers commit their units; else units come back with their
    files and are written here (runner.cluster)."""
    store.remove_stale_temp_files()
    specs = [
        UnitSpec(generator=r.name, generator_target=r.target, generator_path=r.search_path, task_id=t,
                 tasks_dir=config.tasks_dir, model=config.model, model_args=model_args,
                 seed=config.seed, run_dir=str(run_dir), cache=config.cache,
                 no_cache=config.no_cache, layout_solver=config.layout_solver, brief=config.brief,
                 generator_args=r.args, unit_timeout=config.unit_timeout, debug=config.debug,
                 limits=limits)
        for r in refs for t in ids
    ]
    code, files = run_fingerprints["generators"], run_fingerprints["tasks"]
    by_name = {r.name: r for r in refs}
    inputs = {(s.generator, s.task_id): unit_inputs(by_name[s.generator], s.task_id, config.tasks_dir,
                                                    generator=code[s.generator], task=files[s.task_id])
              for s in specs}
    records: dict[tuple[str, str], UnitRecord] = {}
    pending: list[UnitSpec] = []
    stale: dict[str, int] = {}
    earlier = RunStore(previous) if previous is not None else None
    with phases.phase("resume scan"):
        for spec in specs:
            key = (spec.generator, spec.task_id)
            stored, source = store.load(spec.generator, spec.task_id), store
            if stored is None and earlier is not None:  # the kept finished run's unit
                stored, source = earlier.load(spec.generator, spec.task_id), earlier
            if stored is None or stored.error_kind == "infrastructure" or not source.files_intact(stored) \
                    or any(limits.get(k) != v for k, v in stored.limits.items()):
                pending.append(spec)  # never computed, corrupt, edited, failed for a reason outside
                # it, or shaped by a limit whose value has changed since
                continue
            changed = ["fresh"] if config.fresh else changed_inputs(stored.inputs, inputs[key])
            if config.debug and (stored.error_kind == "internal" or stored.traceback is not None):
                changed = changed or ["debug"]
            if changed:  # made by other code or data: recomputed, and the run says why
                pending.append(spec)
                for what in changed:
                    why = ("--debug re-runs a generator that raised" if what == "debug" else
                           stale_reason(what, spec.generator, spec.task_id, stored.inputs, inputs[key]))
                    stale[why] = stale.get(why, 0) + 1
            elif source is store or _adopted(earlier, store, stored):
                records[key] = stored
            else:
                pending.append(spec)
    reused = len(records)
    pending = [s.model_copy(update={"inputs": inputs[(s.generator, s.task_id)], "commit": True,
                                    "on_commit": on_commit})
               for s in pending]  # each worker commits its units (`unit.committed`)
    computed: dict[tuple[str, str], TaskMetrics] = {}
    paged: set[tuple[str, str]] = set()
    start = time.perf_counter()
    console = console or Console(stderr=True)
    # bars only on a terminal: piped into a log, a bar is one line as wide as rich guesses
    # (~150 columns) redrawn; there each generator gets one plain line when its units are done
    bars_shown = show_progress and console.is_terminal
    with phases.phase("units"), Progress(  # the units, run (and committed) here or awaited
        TextColumn("[bold]{task.description:<14}"), BarColumn(), MofNCompleteColumn(),
        TimeRemainingColumn(), console=console, disable=not bars_shown, transient=False,
    ) as progress:
        bars = {
            r.name: progress.add_task(r.name, total=len(ids),
                                      completed=sum(1 for (gg, _) in records if gg == r.name))
            for r in refs
        }
        streak = 0
        # closing(): stopping early stops the pool at once and drops the queued units
        if hand_back is not None:
            from logicenveval.runner.cluster import run_units_remote, write_back
        chunks = executor.map_unordered(run_units if hand_back is None else run_units_remote,
                                        hand_offs(pending, config.workers if hand_back is None
                                                  else executor.workers),
                                        budget=_budget(config), on_crash=_crashed,
                                        split=lambda chunk: [(s,) for s in chunk])
        background = _Background(meanwhile)
        try:
            with contextlib.closing(chunks) as finished:  # type: ignore[type-var]  # generators have close()
                for _, chunk in finished:
                    for done in chunk:
                        if hand_back is not None and done.files:
                            with phases.phase("saving"):
                                write_back(run_dir, done, hand_back.cache)
                        record = done.record
                        key = (record.generator, record.task_id)
                        records[key] = record
                        if done.metrics is not None:
                            computed[key] = done.metrics
                        if done.paged:
                            paged.add(key)
                        progress.advance(bars[record.generator])
                        if show_progress and not bars_shown:
                            _plain_progress(console, progress, bars[record.generator], start)
                        streak = streak + 1 if record.error_kind == "infrastructure" else 0
                        if config.max_infra_failures and streak >= config.max_infra_failures:
                            raise RunFailedError(
                                f"stopped after {streak} consecutive infrastructure failures; last: "
                                f"{record.error}", file=str(run_dir),
                                hint="fix the endpoint or cache, then re-run the same command: "
                                "finished units are kept and the failed ones are recomputed "
                                "(--max-infra-failures 0 never stops)")
        finally:  # before the report's imports are needed, or the process ends
            background.join()
    ordered = [records[(s.generator, s.task_id)] for s in specs]
    with phases.phase("results"):
        results = build_results(config, tasks, ordered, wall_seconds=time.perf_counter() - start,
                                generators=[r.name for r in refs], computed=computed)
    results["timing"]["run_phases"] = phases.take()
    results["inputs"] = run_fingerprints
    write_outputs(run_dir, results, ordered)
    return RunOutcome(run_dir=run_dir, results=results, computed=len(pending), reused=reused,
                      records=tuple(ordered), stale=stale, paged=frozenset(paged))
