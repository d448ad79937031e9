"""`import-house HOUSE.json --task ID --out ENV.json`: a ProcTHOR/AI2-THOR house as an EnvSpec.

Prints what the harness will judge: where object types and sizes came from, the categories
chosen for types that fit several, the types kept as obstacles, and the role binding.
Exit 0 when written, 2 on a bad house or output path (nothing is written then).
"""

from __future__ import annotations

import argparse


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("house", help="ProcTHOR / AI2-THOR house JSON (schema 1.0.0)")
    p.add_argument("--task", required=True, help="task id the environment is scored for")
    p.add_argument("--out", required=True, help="EnvSpec JSON to write (e.g. ENVS_DIR/<task>/<name>.json)")
    p.add_argument("--env-id", default=None, help="env_id (default: the --out file's name)")
    p.add_argument("--procthor-db", metavar="DIR", default=None,
                   help="ProcTHOR's procthor/databases folder: exact types and sizes of its asset ids "
                   "(default: those of the installed `procthor` package, the [procthor] extra; "
                   "else our recorded mapping, then the catalog)")
    p.add_argument("--tasks-dir", default=None, help="folder of <task_id>/task.json (default: the benchmark)")
    p.add_argument("--catalog", default=None, help="catalog.json (default: the benchmark's)")
    p.add_argument("--roles", default=None, metavar="ROLE=ID,...",
                   help="bind these roles to these object ids (written into the EnvSpec's roles)")


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.domain.roles import parse_role_map, prepare_env
    from logicenveval.envfiles import env_to_json
    from logicenveval.scene.export_files import write_output
    from logicenveval.scene.house_import import import_house, load_house
    from logicenveval.scene.import_report import format_rooms, house_report
    from logicenveval.scene.procthor import installed_procthor_db, load_procthor_db

    task = load_task(args.task, args.tasks_dir)
    catalog = load_catalog(args.catalog)
    assets = load_procthor_db(args.procthor_db) if args.procthor_db else installed_procthor_db()
    path, out = Path(args.house), Path(args.out)
    report = import_house(load_house(path), task_id=task.id,
                          env_id=args.env_id or out.name.removesuffix(".json"),
                          catalog=catalog, source=str(path), assets=assets,
                          role_categories=[r.category for r in task.roles.values()])
    env = report.env
    given = parse_role_map(args.roles, task.roles)
    prepared = prepare_env(env, task.roles, catalog, given)  # checks the ids before writing
    if given:
        env = env.model_copy(update={"roles": {**env.roles, **given}})
    write_output(out, env_to_json(env), what="EnvSpec")
    print(f"wrote {out}: {len(env.rooms)} room(s), {len(env.doors)} door(s), "
          f"{len(env.windows)} window(s), {len(env.objects)} object(s)")
    print("object types from " + _counts(report.type_sources)
          + "; sizes from " + _counts(report.size_sources))
    for w in report.warnings:
        print(f"warning: {w}")
    house = house_report(report, catalog)
    unreachable = [f.rooms[0] for f in house.physics.extended.failures if f.code == "unreachable_room"]
    print(f"PhyPR of the imported house: floor plan {'passes' if house.physics.floor_plan.passed else 'fails'}"
          f" ({len(unreachable)} unreachable room(s)), {house.objects - house.entity_failed} of {house.objects}"
          " object(s) pass entity; per room:")
    for line in format_rooms(house):
        print(line)
    for otype, names in sorted(report.ambiguous_types.items()):
        print(f"note: AI2-THOR type {otype} fits categories {', '.join(names)}; used "
              f"{report.chosen[otype]} (docs/scene.md: Importing houses)")
    binding = prepared.binding
    bound = {r: o for r, o in binding.roles.items() if o is not None}
    print(f"roles of {task.id} the harness binds: "
          + (", ".join(f"{r}={o}" for r, o in bound.items()) or "none"))
    for role, why in sorted(binding.why.items()):
        optional = " (optional: may be absent)" if task.roles[role].optional else ""
        print(f"unbound {role}{optional}: {why}")
    for problem in binding.problems:
        print(f"not well-formed: {problem}")
    return 0


def _counts(counts: dict[str, int]) -> str:
    return ", ".join(f"{k} {v}" for k, v in sorted(counts.items(), key=lambda kv: -kv[1])) or "nothing"
