"""`evaluate ENVS_DIR`: score a folder of EnvSpecs made by any tool, like a generator in `run`."""

from __future__ import annotations

import argparse
import os

from logicenveval.commands import options


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("envs_dir", help="folder of <task_id>/*.json EnvSpecs (e.g. a run's envs/<generator>)")
    p.add_argument("--name", default=None, help="leaderboard row name (default: the folder's name)")
    p.add_argument("--tasks", default=(), type=_tasks,
                   help="comma-separated task ids; 'found' (default) = every task folder in ENVS_DIR")
    p.add_argument("--tasks-dir", default=None, help="folder of <task_id>/task.json (default: the benchmark)")
    p.add_argument("--workers", type=options.workers, default=os.cpu_count() or 1)
    p.add_argument("--executor", default="process", choices=["process", "inprocess", "ray"])
    p.add_argument("--output", default="reports", help="parent folder of run folders")
    p.add_argument("--run-id", default=None, type=options.folder_name,
                   help="run folder name (default: derived from the inputs)")
    p.add_argument("--roles", default=None, metavar="ROLE=ID,...",
                   help="bind these roles to these object ids first, in every file of a task "
                   "that has the role (e.g. red_box=box_2)")


def run(args: argparse.Namespace) -> int:
    from logicenveval.domain.roles import parse_role_map
    from logicenveval.reporting.publish import publish
    from logicenveval.runner.score_envs import EvaluateConfig, evaluate_envs

    config = EvaluateConfig(
        envs_dir=args.envs_dir,
        name=args.name,
        tasks=args.tasks,
        tasks_dir=args.tasks_dir,
        workers=args.workers,
        executor=args.executor,
        output=args.output,
        run_id=args.run_id,
        roles=args.roles,
    )
    parse_role_map(args.roles)  # malformed items are bad input before any scoring
    outcome = evaluate_envs(config)
    shown = publish(outcome.run_dir, outcome.results, outcome.records)
    print(shown.summary)
    for folder in outcome.skipped_folders:
        print(f"skipped {folder}/: not a task of the tasks dir")
    for f in outcome.results["failures"].get(config.generator_name, []):
        print(f"failure {f['task']}: {f.get('env_id') or ''} {f['message']}".replace("  ", " "))
    print(f"run folder: {outcome.run_dir} (scored {outcome.computed} task folder(s), "
          f"reused {outcome.reused})")
    from logicenveval.commands.run import report_failures
    from logicenveval.runner.run import stale_text

    if outcome.stale:
        print(stale_text(outcome.stale))

    return report_failures(outcome.records)


def _tasks(text: str) -> tuple[str, ...]:
    """`found` (every task folder present: returned as ()) or a list of task ids."""
    return () if text.strip() == "found" else options.name_list(text)
