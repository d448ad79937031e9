"""`lint ENVS_DIR [--json] [--roles ROLE=ID,...]`: the binding, constraint, category and
affordance problems of each EnvSpec in a folder laid out as `evaluate` scores it
(`<task_id>/*.json`), before any scoring, and how each object's category was read.

Exit 0 when no file has a problem (notes allowed), 1 when one has, 2 on bad input (no such
folder, no task folder, no EnvSpec file in the task folders: nothing checked).
"""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("envs_dir", metavar="ENVS_DIR", help="folder of <task_id>/*.json EnvSpecs")
    parser.add_argument("--tasks-dir", default=None, help="tasks folder (default: the benchmark's)")
    parser.add_argument("--json", action="store_true", help="print the findings as JSON")
    parser.add_argument("--quiet", action="store_true", help="list only files with problems")
    parser.add_argument("--roles", default=None, metavar="ROLE=ID,...",
                        help="bind these roles to these object ids first (e.g. red_box=box_2)")


def run(args: argparse.Namespace) -> int:
    import json

    from logicenveval.lint import lint_folder

    reports = lint_folder(args.envs_dir, args.tasks_dir, roles=args.roles)
    bad = [r for r in reports if not r.clean]
    if args.json:
        print(json.dumps([{"file": r.path, "task_id": r.task_id, "env_id": r.env_id,
                           "problems": [{"kind": k, "message": m} for k, m in r.problems],
                           "notes": [{"kind": k, "message": m} for k, m in r.notes],
                           "categories": [{"object": o, "written": w, "read_as": c}
                                          for o, w, c in r.readings]}
                          for r in reports], indent=2))
    else:
        for r in reports:
            if r.clean and (args.quiet or not r.notes):
                if not args.quiet:
                    print(f"{r.path}: ok")
                continue
            print(f"{r.path}: {len(r.problems)} problem(s)" if r.problems else f"{r.path}: ok")
            for kind, message in r.problems:
                print(f"  {kind}: {message}")
            for kind, message in r.notes:
                print(f"  note ({kind}): {message}")
            print("  categories: " + ", ".join(
                f"{o} {w!r}->{c or '?'}" if w != c else f"{o} {c}" for o, w, c in r.readings))
        print(f"{len(reports) - len(bad)} of {len(reports)} file(s) without problems")
    return 1 if bad else 0
