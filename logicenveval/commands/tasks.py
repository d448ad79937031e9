"""`tasks list | show ID | validate | stats`: browse, check and summarise the benchmark tasks."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rich.console import Console


def add_arguments(p: argparse.ArgumentParser) -> None:
    sub = p.add_subparsers(dest="tasks_command", required=True, metavar="SUBCOMMAND")
    ls = sub.add_parser("list", help="list the tasks")
    show = sub.add_parser("show", help="show one task: roles, variables, trees, policies")
    show.add_argument("task_id")
    val = sub.add_parser("validate", help="check every task; exit 1 on any problem")
    val.add_argument("--task", action="append", default=None, help="validate only this task (repeatable)")
    val.add_argument("--no-simulate", action="store_true", help="skip simulating the four policies")
    val.add_argument("--write-models", action="store_true",
                     help="first rewrite each policy's Groot2 <TreeNodesModel> from the action library")
    st = sub.add_parser("stats", help="per-task logical and policy sizes, with totals")
    st.add_argument("--markdown", action="store_true", help="print a Markdown table (for the README)")
    for q in (ls, show, val, st):
        q.add_argument("--tasks-dir", default=None, help="folder of <task_id>/task.json (default: benchmark)")


def run(args: argparse.Namespace) -> int:
    cmd: str = args.tasks_command
    if cmd == "list":
        return _list(args)
    if cmd == "show":
        return _show(args)
    if cmd == "validate":
        return _validate(args)
    return _stats(args)


def _list(args: argparse.Namespace) -> int:
    from rich.table import Table

    from logicenveval.benchmark import load_tasks

    table = Table(title="benchmark tasks")
    for col in ("id", "rooms", "subtasks", "description"):
        table.add_column(col)
    for t in load_tasks(args.tasks_dir):
        desc = t.description if len(t.description) <= 80 else t.description[:77] + "..."
        table.add_row(t.id, ", ".join(t.rooms), str(len(t.subtasks)), desc)
    _console().print(table)
    return 0


def _show(args: argparse.Namespace) -> int:
    from rich.table import Table
    from rich.tree import Tree

    from logicenveval.benchmark import load_task
    from logicenveval.model.task import Leaf, Node

    t = load_task(args.task_id, args.tasks_dir)
    con = _console()
    con.print(f"[bold]{t.id}[/bold]  rooms: {', '.join(t.rooms)}")
    con.print(t.description)
    roles = Table(title="roles")
    for col in ("role", "category", "attributes"):
        roles.add_column(col)
    for name, r in t.roles.items():
        roles.add_row(name, r.category, ", ".join(f"{k}={v}" for k, v in r.attributes.items()))
    con.print(roles)

    def add(branch: Tree, node: Node | Leaf) -> None:
        if isinstance(node, Leaf):
            branch.add(f"goal: {node.goal}  plan: {'; '.join(node.plan) or '-'}")
            return
        var = t.variables[node.var]
        for value, child in node.branches.items():
            add(branch.add(f"{node.var}={value}  [dim]{var.values[value]}[/dim]"), child)

    for st in t.subtasks:
        tree = Tree(f"[bold]{st.id}[/bold] {st.description}")
        add(tree, st.tree)
        con.print(tree)
    con.print("policies: " + ", ".join(f"{k}={v}" for k, v in t.policies.items()))
    return 0


def _validate(args: argparse.Namespace) -> int:
    from rich.table import Table

    from logicenveval.benchmark import tasks_dir
    from logicenveval.benchmark_validation import validate_all, validate_task

    simulate = not args.no_simulate
    if args.write_models:
        from logicenveval.benchmark_validation import write_models

        for path in write_models(args.tasks_dir, args.task):
            print(f"updated TreeNodesModel of {path}")
    if args.task:
        reports = [validate_task(t, args.tasks_dir, simulate=simulate) for t in args.task]
    else:
        reports = validate_all(args.tasks_dir, simulate=simulate)
    table = Table(title=f"validation of {tasks_dir(args.tasks_dir)}")
    for col in ("task", "situations", "counterfactual", "unreachable", "lackbranch", "result"):
        table.add_column(col)
    for r in reports:
        rev = [f"{len(r.revealing.get(k, []))}/{r.situations}"
               for k in ("counterfactual", "unreachable", "lackbranch")]
        table.add_row(r.task, str(r.situations), *rev,
                      "[green]ok[/green]" if r.ok else f"[red]{len(r.problems)} problem(s)[/red]")
    _console().print(table)
    problems = [p for r in reports for p in r.problems]
    for p in problems:
        print(f"problem: {p}")
    if problems:
        print(f"{len(problems)} problem(s) in {sum(not r.ok for r in reports)} of {len(reports)} task(s)")
        return 1
    print(f"all {len(reports)} task(s) valid")
    return 0


def _stats(args: argparse.Namespace) -> int:
    from rich.table import Table

    from logicenveval.benchmark_stats import COLUMNS, benchmark_stats, to_markdown, totals

    rows = benchmark_stats(args.tasks_dir)
    if args.markdown:
        print(to_markdown(rows))
        return 0
    table = Table(title="benchmark statistics")
    for col in COLUMNS:
        table.add_column(col, justify="left" if col == "task" else "right")
    for r in rows:
        table.add_row(*[str(getattr(r, c)) for c in COLUMNS])
    t = totals(rows)
    table.add_row("total", *[str(t[c]) for c in COLUMNS[1:]], style="bold")
    _console().print(table)
    print(f"{t['tasks']} tasks, {t['policies']} policies")
    return 0


def _console() -> Console:
    """A console at least 140 columns wide, so that piped output keeps task ids whole."""
    from rich.console import Console

    probe = Console()
    return Console(width=max(probe.width, 140))
