"""`import-house HOUSE.json --task ID --out ENV.json`: a ProcTHOR/AI2-THOR house as an EnvSpec."""

from __future__ import annotations

import argparse


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("house", help="ProcTHOR / AI2-THOR house JSON (schema 1.0.0)")
    p.add_argument("--task", required=True, help="task id the environment is scored for")
    p.add_argument("--out", required=True, help="EnvSpec JSON to write (e.g. ENVS_DIR/<task>/<name>.json)")
    p.add_argument("--env-id", default=None, help="env_id (default: the --out file's name)")
    p.add_argument("--tasks-dir", default=None, help="folder of <task_id>/task.json (default: the benchmark)")
    p.add_argument("--catalog", default=None, help="catalog.json (default: the benchmark's)")


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.domain.roles import bind_roles
    from logicenveval.envfiles import save_env
    from logicenveval.scene.house_import import import_house, load_house

    task = load_task(args.task, args.tasks_dir)
    catalog = load_catalog(args.catalog)
    path = Path(args.house)
    report = import_house(load_house(path), task_id=task.id,
                          env_id=args.env_id or Path(args.out).name.removesuffix(".json"),
                          catalog=catalog, source=str(path),
                          role_categories=[r.category for r in task.roles.values()])
    save_env(report.env, args.out)
    env = report.env
    print(f"wrote {args.out}: {len(env.rooms)} room(s), {len(env.doors)} door(s), "
          f"{len(env.windows)} window(s), {len(env.objects)} object(s)")
    for w in report.warnings:
        print(f"warning: {w}")
    for otype, names in sorted(report.ambiguous_types.items()):
        print(f"note: AI2-THOR type {otype} fits categories {', '.join(names)}; used "
              f"{report.chosen[otype]} (docs/own-generator.md: house import)")
    binding = bind_roles(env, task.roles, catalog)
    bound = {r: o for r, o in binding.roles.items() if o is not None}
    print(f"roles of {task.id} the harness binds: "
          + (", ".join(f"{r}={o}" for r, o in bound.items()) or "none"))
    for problem in binding.problems:
        print(f"not well-formed: {problem}")
    return 0
