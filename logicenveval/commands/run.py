"""`run`: evaluate generators on the benchmark and write results and leaderboards."""

from __future__ import annotations

import argparse
import os
import shlex
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from logicenveval.commands import options
from logicenveval.errors import LogicEnvEvalError
from logicenveval.runner.config import DEFAULT_GENERATORS, DEFAULT_UNIT_TIMEOUT, MAX_COUNT
from logicenveval.scene.layout import DEFAULT_SOLVER, SOLVERS

if TYPE_CHECKING:
    from logicenveval.metrics.records import UnitRecord
    from logicenveval.runner.config import RunConfig
    from logicenveval.runner.placement import FinishedRunError


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--model", default="offline",
                   help="offline (rule-based, no network) | oracle (the GT plans: an upper bound) | "
                   "openai:<model> (any OpenAI-compatible endpoint) | replay:<cache.sqlite> | "
                   "llamacpp:<model.gguf> (a managed local llama.cpp server) | "
                   "noisy:<model> (a model whose replies are perturbed; rate= in --model-args); "
                   "default offline (docs/llm.md)")
    p.add_argument("--model-args", default="",
                   help="key=value,... e.g. base_url=...,api_key_env=... (default: none; docs/llm.md)")
    p.add_argument("--generators", default=DEFAULT_GENERATORS, type=options.name_list,
                   help="comma-separated: built-in names (ablations by name), installed plug-ins, "
                   f"or PKG.MODULE:ATTR (default {','.join(DEFAULT_GENERATORS)}; see "
                   "`python -m logicenveval generators list`, docs/own-generator.md)")
    p.add_argument("--tasks", default=(), type=options.task_list,
                   help="all or comma-separated task ids (default all; `python -m logicenveval "
                   "tasks list`)")
    p.add_argument("--tasks-dir", default=None, help="folder of <task_id>/task.json (default: the benchmark)")
    p.add_argument("--limit", type=options.int_range(1, MAX_COUNT), default=None,
                   help="only the first N tasks (default: every selected task)")
    p.add_argument("--seed", type=options.int_range(0, options.MAX_SEED), default=0,
                   help="seed of every random choice (generators, layouts, the noisy model): the "
                   "same seed gives the same results.json (default 0)")
    p.add_argument("--seeds", default=None, type=options.seed_list,
                   help="comma-separated seeds: one run per seed, aggregated with intervals over "
                   "tasks and seeds (overrides --seed; default: one run, of --seed)")
    p.add_argument("--layout-solver", default=DEFAULT_SOLVER, choices=SOLVERS,
                   help=f"layout backend of solver-based generators (default {DEFAULT_SOLVER}; docs/scene.md)")
    p.add_argument("--workers", type=options.workers, default=os.cpu_count() or 1,
                   help="parallel worker processes of --executor process or ray (default: the "
                   f"number of cores, here {os.cpu_count() or 1}); results do not depend on it")
    p.add_argument("--executor", default="process", choices=["process", "inprocess", "ray"],
                   help="process: a pool of --workers processes (default); inprocess: this process, "
                   "for debugging and profiling; ray: Ray tasks, on a local instance or the "
                   "cluster of --ray-address / RAY_ADDRESS (docs/runner.md, docs/cluster.md)")
    p.add_argument("--ray-address", default=None, metavar="HOST:PORT",
                   help="with --executor ray: the cluster to run on (default RAY_ADDRESS, else a "
                   "local Ray instance); it sets the number of workers (docs/cluster.md)")
    p.add_argument("--output", default="reports",
                   help="parent folder of run folders (default reports)")
    p.add_argument("--run-id", default=None, type=options.folder_name,
                   help="run folder name inside --output (default: derived from the config)")
    p.add_argument("--max-infra-failures", type=options.int_range(0, MAX_COUNT), default=5,
                   help="stop after N consecutive units failed for infrastructure reasons "
                   "(endpoint, cache, disk); 0 never stops (default 5)")
    cache = p.add_mutually_exclusive_group()
    cache.add_argument("--cache", default=None,
                       help="SQLite cache of LLM replies (default <output>/llm_cache.sqlite)")
    cache.add_argument("--no-cache", action="store_true", help="bypass the LLM reply cache")
    p.add_argument("--brief", default=None, choices=["roles", "description"],
                   help="what generators get: as in the paper, only id, description and rooms, with the "
                        "paper's few-shot example (default; roles with --model oracle), or the task's "
                        "roles (our variant; docs/fidelity.md)")
    p.add_argument("--unit-timeout", type=options.timeout, default=DEFAULT_UNIT_TIMEOUT,
                   metavar="SECONDS",
                   help="wall-time bound of one generator on one task; a generator that does not "
                   f"return in time fails that unit (default {DEFAULT_UNIT_TIMEOUT:g}; 0: no bound; "
                   "docs/runner.md)")
    p.add_argument("--generator-args", action="append", default=[], type=options.generator_args,
                   metavar="NAME:key=value,...",
                   help="keyword arguments of a generator's factory (repeat per generator; NAME as "
                   "in --generators); part of the run's identity (default: none; "
                   "docs/own-generator.md)")
    p.add_argument("--fresh", action="store_true",
                   help="recompute every unit (by default a unit is reused only when the "
                   "configuration, harness, generator code, task files and catalog are unchanged)")
    p.add_argument("--replace", action="store_true",
                   help="let this run replace a finished run of other code, tasks or catalog in its "
                   "folder (by default such a run goes to a new folder <run>-2, or is refused "
                   "under --run-id; docs/runner.md)")
    p.add_argument("--debug", action="store_true",
                   help="run in this process and re-raise a generator's exception with its "
                   "traceback (for a debugger: python -m pdb -m logicenveval run --debug ...); "
                   "also prints the stored traceback of every failed unit")
    p.add_argument("--quiet", action="store_true", help="no progress bars")
    p.add_argument("--export", default="", metavar="FORMATS",
                   help="also write procthor and/or glb files next to every environment "
                        "(e.g. procthor,glb; default: none)")


def run(args: argparse.Namespace) -> int:
    from logicenveval.commands.run_start import PAGE_MODULES
    from logicenveval.runner.executors import prestart

    if not args.debug:  # started already by `cli.main` (`run_start`) unless that read nothing
        prestart(args.executor, args.workers, preload=PAGE_MODULES)
    from logicenveval.runner.config import RunConfig

    config = RunConfig(
        model=args.model,
        model_args=args.model_args,
        generators=tuple(args.generators),
        tasks=args.tasks,
        tasks_dir=args.tasks_dir,
        limit=args.limit,
        seed=args.seed,
        layout_solver=args.layout_solver,
        workers=args.workers,
        executor=args.executor,
        ray_address=args.ray_address,
        output=args.output,
        cache=args.cache,
        no_cache=args.no_cache,
        run_id=args.run_id,
        max_infra_failures=args.max_infra_failures,
        brief=args.brief,
        unit_timeout=args.unit_timeout,
        generator_args=_generator_args(args.generator_args),
        fresh=args.fresh,
        debug=args.debug,
        replace=args.replace,
    )
    formats = [f.strip() for f in args.export.split(",") if f.strip()]
    if formats:
        from logicenveval.errors import ConfigError
        from logicenveval.scene.export_files import SUFFIX

        unknown = sorted(set(formats) - set(SUFFIX))
        if unknown:
            raise ConfigError(f"unknown export format(s) {unknown}", field="--export",
                              hint=f"use a comma-separated subset of {', '.join(SUFFIX)}")
    try:
        return _run(args, config, formats)
    except LogicEnvEvalError as exc:
        from logicenveval.runner.placement import FinishedRunError

        if isinstance(exc, FinishedRunError):
            raise _with_commands(exc, getattr(args, "argv", None)) from None
        raise


def _run(args: argparse.Namespace, config: RunConfig, formats: list[str]) -> int:
    if args.seeds is not None:
        from logicenveval.runner.seeds import run_seeds

        multi = run_seeds(config, args.seeds, show_progress=not args.quiet)
        from logicenveval.reporting.publish import publish
        from logicenveval.reporting.terminal import path_lines

        if formats:
            from logicenveval.scene.export_files import export_run

            n = sum(len(export_run(d, formats)) for d in multi.seed_dirs)
            print(f"exported {n} file(s) ({', '.join(formats)}) next to the environments")
        shown = publish(multi.run_dir, multi.results, multi.records)
        print(shown.summary)
        print(f"computed {multi.computed} unit(s), reused {multi.reused} over "
              f"{len(multi.seed_dirs)} seed run(s) (seed<N>/ in the run folder)")
        print("\n".join(path_lines("run folder:", multi.run_dir)))
        if multi.note:
            print(multi.note)
        print_size(multi.run_dir)
        _say_stale(multi.stale, multi.records, args.debug)
        return report_failures(multi.records)  # the seeds' units are in seed<S>/
    from functools import partial

    from logicenveval.reporting.unit_page import write_unit_page
    from logicenveval.runner.run import run as run_benchmark

    # each unit's report page is written by the worker that ran it (`reporting.unit_page`)
    pages = partial(write_unit_page, model=config.model)
    outcome = run_benchmark(config, show_progress=not args.quiet, on_commit=pages,
                            meanwhile=_load_report)
    from logicenveval.reporting.publish import publish
    from logicenveval.reporting.terminal import path_lines

    if formats:
        from logicenveval.scene.export_files import export_run

        written = export_run(outcome.run_dir, formats)
        print(f"exported {len(written)} file(s) ({', '.join(formats)}) next to the environments")
    shown = publish(outcome.run_dir, outcome.results, outcome.records, outcome.paged)
    print(shown.summary)
    print(f"computed {outcome.computed} unit(s), reused {outcome.reused}")
    print("\n".join(path_lines("run folder:", outcome.run_dir)))
    if outcome.note:
        print(outcome.note)
    print_size(outcome.run_dir)
    _say_stale(outcome.stale, outcome.records, args.debug)
    return report_failures(outcome.records, outcome.run_dir)


def _with_commands(exc: FinishedRunError, argv: Sequence[str] | None) -> FinishedRunError:
    """The refusal with the two exact commands: keep the finished run (a new id) or replace it."""
    from logicenveval.runner.placement import FinishedRunError

    if not argv:
        return exc
    keep = "python -m logicenveval " + shlex.join(_with_option(list(argv), "--run-id", exc.free_id))
    replace = "python -m logicenveval " + shlex.join([*argv, "--replace"])
    out = FinishedRunError(exc.run_dir, exc.changed, exc.free_id)
    out.hint = f"keep it and run under a new id: {keep} ; or replace it: {replace}"
    out.args = (out._format(),)
    return out


def _with_option(argv: list[str], option: str, value: str) -> list[str]:
    """`argv` with `option`'s value set to `value` (`--opt v` and `--opt=v` forms replaced; else
    appended, which also overrides an abbreviation such as `--run`: the last one wins)."""
    out, skip, found = [], False, False
    for i, item in enumerate(argv):
        if skip:
            skip = False
            continue
        if item == option and i + 1 < len(argv):
            out += [option, value]
            skip = found = True
        elif item.startswith(option + "="):
            out.append(f"{option}={value}")
            found = True
        else:
            out.append(item)
    return out if found else [*out, option, value]


def _load_report() -> None:
    """What the command needs once the units are done (the leaderboards), imported while they
    run (`runner.run.run`'s `meanwhile`) instead of before them: the workers wait for this
    process's set-up, not for its report."""
    import logicenveval.reporting.publish  # noqa: F401
    import logicenveval.reporting.terminal  # noqa: F401


def _say_stale(stale: dict[str, int], records: Sequence[UnitRecord], debug: bool) -> None:
    """Why stored units were recomputed; with --debug, every failed unit's traceback (stderr)."""
    from logicenveval.runner.run import stale_text

    if stale:
        print(stale_text(stale))
    if debug:
        for r in records:
            if r.traceback:
                print(f"--- {r.generator} on {r.task_id}: {r.error}\n{r.traceback}", file=sys.stderr)


def print_size(run_dir: Path) -> None:
    """The run folder's size by part, so that a run that grows its folder is noticed."""
    from logicenveval.runner.footprint import folder_bytes, size_text

    print(f"run folder size: {size_text(folder_bytes(run_dir), parts=3)}")  # fits 100 columns


def report_failures(records: Sequence[UnitRecord], run_dir: Path | None = None) -> int:
    """Exit status of a finished run: `EXIT_GENERATOR_RAISED` (3) with the exceptions and the
    generator's own frames when a generator raised in any unit; else 1 with a summary when a
    generator has no valid unit; else 0 (docs/security.md, "Exit codes")."""
    from logicenveval.runner.failures import (
        EXIT_GENERATOR_RAISED,
        failed_generators,
        raised_summary,
        summary,
    )

    dead = failed_generators(records)
    if dead:
        print(f"error: {len(dead)} generator(s) produced no environment in any unit\n(a row of "
              "failed attempts is still a measurement; infrastructure failures are 'not "
              "measured'):\n" + summary(records, dead), file=sys.stderr)
    bugs = raised_summary(records, run_dir)
    if bugs:
        print(bugs, file=sys.stderr)
        return EXIT_GENERATOR_RAISED
    return 1 if dead else 0


def _generator_args(items: Sequence[tuple[str, dict[str, Any]]]) -> dict[str, dict[str, Any]]:
    from logicenveval.errors import ConfigError

    out: dict[str, dict[str, Any]] = {}
    for name, kwargs in items:
        if name in out:
            raise ConfigError(f"--generator-args given twice for {name!r}", field="--generator-args",
                              hint="give all of a generator's arguments in one NAME:k=v,k=v")
        out[name] = kwargs
    return out
