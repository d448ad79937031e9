"""`generate`: run one generator on one task and write its EnvSpecs, plan and renders."""

from __future__ import annotations

import argparse

from logicenveval.commands import options
from logicenveval.scene.layout import DEFAULT_SOLVER, SOLVERS


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--generator", required=True,
                   help="a built-in name, an installed plug-in or PKG.MODULE:ATTR, e.g. logicenvgen "
                   "(`python -m logicenveval generators list`)")
    p.add_argument("--generator-args", default={}, type=options.factory_args, metavar="key=value,...",
                   help="keyword arguments of the generator's factory (as `run --generator-args`)")
    p.add_argument("--task", required=True, help="task id")
    p.add_argument("--model", default="offline", help="offline | oracle | openai:<model> | replay:<file>")
    p.add_argument("--model-args", default="", help="key=value,...")
    p.add_argument("--tasks-dir", default=None)
    p.add_argument("--seed", type=options.int_range(0, options.MAX_SEED), default=0)
    p.add_argument("--layout-solver", default=DEFAULT_SOLVER, choices=SOLVERS,
                   help=f"layout backend (default {DEFAULT_SOLVER})")
    p.add_argument("--out", required=True,
                   help="output folder: the environments go to OUT/<task>/, the layout `evaluate OUT` "
                   "scores")
    p.add_argument("--cache", default=None, help="SQLite cache of LLM replies")
    p.add_argument("--no-render", action="store_true", help="skip the SVG renders")


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from rich.console import Console

    from logicenveval.errors import LogicEnvEvalError, RunFailedError
    from logicenveval.generators.generate import generate_to_folder

    try:
        summary = generate_to_folder(
            generator=args.generator, task_id=args.task, model=args.model, model_args=args.model_args,
            tasks_dir=args.tasks_dir, seed=args.seed, out=Path(args.out), cache=args.cache,
            render=not args.no_render, layout_solver=args.layout_solver,
            generator_args=args.generator_args,
        )
    except (LogicEnvEvalError, OSError):
        raise
    except Exception as exc:  # the generator's own bug: one line, exit 1 (docs/security.md)
        raise RunFailedError(f"generator {args.generator!r} failed: {type(exc).__name__}: "
                             f"{str(exc)[:300]}", field="--generator",
                             hint="fix the generator; `run` records such a failure per unit") from None
    console = Console()
    for line in summary.lines():
        console.print(line)
    return 0 if summary.written else 1  # nothing written: the work failed (docs/security.md)
