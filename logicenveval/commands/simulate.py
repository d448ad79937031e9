"""`simulate`: run one policy (BT) of a task in an EnvSpec or in a GT situation.

An EnvSpec is taken in as `evaluate` takes it (`domain.roles.prepare_env`): categories mapped to
catalog keys, the task's roles it does not map bound by category, attributes and name; what
makes it no valid scenario (an unbound role with its nearest objects, a violated task
constraint) is printed before the verdict.
"""

from __future__ import annotations

import argparse
import json
from typing import TYPE_CHECKING

from logicenveval.commands import options
from logicenveval.errors import ConfigError

if TYPE_CHECKING:
    from logicenveval.domain.catalog import Catalog
    from logicenveval.domain.roles import PreparedEnv
    from logicenveval.model.task import Task


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--task", required=True, help="task id (folder under the tasks dir)")
    parser.add_argument("--policy", required=True,
                        help="correct|counterfactual|unreachable|lackbranch or a BT.CPP v4 XML file")
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--env", help="EnvSpec JSON file to run in")
    where.add_argument("--situation",
                       help="GT situation as var=value,... (a symbolic environment is built)")
    parser.add_argument("--trace", action="store_true", help="print every leaf tick")
    parser.add_argument("--json", action="store_true", help="print the verdict as JSON")
    parser.add_argument("--show-tree", action="store_true",
                        help="also print the policy's tree (rendered with py_trees)")
    parser.add_argument("--tick-limit", type=options.int_range(1, options.MAX_TICKS), default=50,
                        help="root ticks (default 50)")
    parser.add_argument("--tasks-dir", default=None, help="tasks folder (default: the benchmark's)")
    parser.add_argument("--catalog", default=None, help="catalog.json (default: the benchmark's)")


def _situation(text: str) -> dict[str, str]:
    out: dict[str, str] = {}
    for part in filter(None, (p.strip() for p in text.split(","))):
        key, sep, value = part.partition("=")
        if not sep or not key.strip() or not value.strip():
            raise ConfigError(f"--situation item {part!r} is not var=value", field="--situation",
                              hint="e.g. --situation toy_on_floor=yes,toy_kind=doll")
        out[key.strip()] = value.strip()
    return out


def env_problems(task: Task, prepared: PreparedEnv, catalog: Catalog) -> list[str]:
    """Why the prepared environment is no valid scenario before any tick: each role left unbound
    (one message, the nearest objects), a tree reaching no leaf, a violated task constraint."""
    from logicenveval.metrics.evaluate import constraint_problems, coverage
    from logicenveval.sim.world import holds_initial

    holds = holds_initial(prepared.env, catalog)
    cov = coverage(task, holds, prepared.env.roles, prepared.binding)
    return [*prepared.binding.problems, *cov.problems,
            *constraint_problems(task, prepared.env, holds)]


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from logicenveval.benchmark import load_task, policy_path
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.domain.roles import prepare_env
    from logicenveval.envfiles import load_env
    from logicenveval.model.task import POLICY_KINDS
    from logicenveval.model.tree import trajectory_from_assignment
    from logicenveval.paths import shown
    from logicenveval.sim.loader import load_policy
    from logicenveval.sim.simulator import simulate
    from logicenveval.sim.situations import situation_env

    task = load_task(args.task, args.tasks_dir)
    catalog = load_catalog(args.catalog)
    if args.policy in POLICY_KINDS:
        path = policy_path(task, args.policy, args.tasks_dir)
    else:
        path = Path(args.policy)
        if not path.is_file():
            raise ConfigError(f"--policy {args.policy!r} is neither a policy kind nor a file",
                              field="--policy", hint=f"use one of {list(POLICY_KINDS)} or a path")
    # a policy the loader refuses (unknown node, bad port, unknown role, ...) is bad input:
    # exit 2 with file:line and a fix, like every other input (docs/security.md)
    policy = load_policy(path, roles=task.roles, rooms=task.rooms)
    unfit: list[str] = []
    if args.env:  # categories mapped and roles bound exactly as `evaluate` judges the file
        loaded = load_env(args.env)
        if loaded.task_id != task.id:  # its roles and GT are another task's: a pass means nothing
            raise ConfigError(f"the environment is for task {shown(loaded.task_id)}, not "
                              f"{task.id!r}", file=args.env, field="task_id",
                              hint=f"simulate it with --task {shown(loaded.task_id)}, or pass "
                              f"an environment of {task.id}")
        prepared = prepare_env(loaded, task.roles, catalog)
        env = prepared.env
        unfit = env_problems(task, prepared, catalog)
        if not args.json:
            for note in [*prepared.categories.notes(), *unfit]:
                print(f"note: {note}")
    else:
        try:
            trajectory = trajectory_from_assignment(task, _situation(args.situation))
        except ValueError as exc:
            raise ConfigError(str(exc), field="--situation",
                              hint="give var=value for every variable the trees ask") from None
        env = situation_env(task, trajectory, catalog)
    verdict = simulate(policy, env, task, catalog, tick_limit=args.tick_limit, trace=args.trace)
    if args.show_tree and not args.json:
        from logicenveval.sim.pytrees_io import load_tree, unicode_tree

        print(unicode_tree(load_tree(path)))
    if args.json:
        print(json.dumps({**verdict.model_dump(mode="json"), "env_problems": unfit}, indent=2))
    else:
        _print(verdict, str(path), env.env_id)
    return 0 if verdict.passed else 1


def _print(verdict: object, policy: str, env_id: str) -> None:
    from rich.console import Console
    from rich.table import Table

    from logicenveval.sim.verdict import Verdict

    assert isinstance(verdict, Verdict)
    console = Console()
    colour = "green" if verdict.passed else "red"
    console.print(f"[bold]{policy}[/] in [bold]{env_id}[/]: [{colour} bold]{verdict.status}[/]"
                  f" after {verdict.ticks} tick(s)")
    if verdict.fault_path:
        console.print(f"  fault at [bold]{verdict.fault_node}[/] ({verdict.fault_path})")
    if verdict.message:
        console.print(f"  {verdict.message}", markup=False)
    if verdict.goal is not None:
        console.print(f"  goal: {verdict.goal} -> {verdict.goal_holds}", markup=False)
    if verdict.trace:
        table = Table("tick", "node", "status", "path / detail")
        ports: dict[str, str] = {}  # recorded on a node's first event, carried forward by path
        for ev in verdict.trace:
            if ev.get("ports"):
                ports[str(ev["path"])] = str(ev["ports"])
            node = " ".join(x for x in (str(ev["node"]), ports.get(str(ev["path"]))) if x)
            table.add_row(str(ev["tick"]), node, str(ev["status"]),
                          str(ev.get("detail") or ev["path"]))
        console.print(table)
