"""`tasks list | show ID | validate | stats`: browse, check and summarise the benchmark tasks."""

from __future__ import annotations

import argparse
import contextlib
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

from logicenveval.commands import options

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
    val.add_argument("--worlds", type=_positive, default=None,
                     help="worlds simulated per situation (default 12; 1 = the minimal world only)")
    val.add_argument("--write-models", action="store_true",
                     help="first rewrite each policy's Groot2 <TreeNodesModel> from the action library")
    mu = sub.add_parser("mutants", help="first-order mutants of the correct BTs, classified by simulation")
    mu.add_argument("--tasks", default=(), type=options.task_list, help="all or comma-separated task ids")
    mu.add_argument("--worlds", type=_positive, default=None,
                    help="worlds simulated per situation (default 12, as tasks validate)")
    mu.add_argument("--json", action="store_true", help="print JSON (every mutant and what kills it)")
    mu.add_argument("--write", action="store_true",
                    help="also write each task folder's killable_mutants.json (read by run/evaluate)")
    st = sub.add_parser("stats", help="per-task logical and policy sizes, with totals")
    st.add_argument("--markdown", action="store_true", help="print a Markdown table (as in docs/benchmark.md)")
    for q in (ls, show, val, mu, st):
        q.add_argument("--tasks-dir", default=None, help="folder of <task_id>/task.json (default: benchmark)")


def run(args: argparse.Namespace) -> int:
    cmd: str = args.tasks_command
    if cmd != "show" and not (cmd == "validate" and args.task):
        _some_tasks(args.tasks_dir)
    if cmd == "list":
        return _list(args)
    if cmd == "show":
        return _show(args)
    if cmd == "validate":
        return _validate(args)
    if cmd == "mutants":
        return _mutants(args)
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
    from logicenveval.benchmark_validation import validate_all
    from logicenveval.sim.worlds import DEFAULT_WORLDS

    simulate = not args.no_simulate
    if args.write_models:
        from logicenveval.benchmark_validation import write_models

        for path in write_models(args.tasks_dir, args.task):
            print(f"updated TreeNodesModel of {path}")
    worlds = args.worlds or DEFAULT_WORLDS
    with _progress("validating") as progress:
        reports = validate_all(args.tasks_dir, simulate=simulate, worlds=worlds,
                               ids=args.task or (), progress=progress)
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


def _mutants(args: argparse.Namespace) -> int:
    import json

    from rich.table import Table

    from logicenveval.benchmark import task_ids
    from logicenveval.errors import ConfigError, did_you_mean
    from logicenveval.faults.classify import classify_tasks
    from logicenveval.sim.worlds import DEFAULT_WORLDS

    known = task_ids(args.tasks_dir)
    ids = list(args.tasks) or known
    unknown = [t for t in ids if t not in known]
    if unknown:
        raise ConfigError(f"unknown task id(s) {unknown}"
                          + "".join(did_you_mean(t, known) for t in unknown[:5]), field="--tasks",
                          hint=f"use all or some of: {', '.join(known)}")
    reports = classify_tasks(ids, args.tasks_dir, worlds=args.worlds or DEFAULT_WORLDS)
    if args.write:
        from logicenveval.benchmark import load_task
        from logicenveval.domain.catalog import load_catalog
        from logicenveval.faults.score import write_shipped

        for r in reports:
            write_shipped(load_task(r.task, args.tasks_dir), args.tasks_dir, load_catalog(),
                          [o.id for o in r.killable], worlds=args.worlds or DEFAULT_WORLDS)
    if args.json:
        print(json.dumps([r.to_json() for r in reports], indent=2, sort_keys=True))
        return 0
    table = Table(title="first-order mutants of the correct BTs")
    for col in ("task", "mutants", "equivalent", "killable", "cf / unr / lack", "hand-written reproduced"):
        table.add_column(col)
    for r in reports:
        j = r.to_json()
        by = j["by_class"]
        assert isinstance(by, dict)
        hw = ", ".join(f"{k}: {'yes' if h.reproduced_by else 'no'}" for k, h in r.handwritten.items())
        table.add_row(r.task, str(j["mutants"]), str(j["equivalent"]), str(j["killable"]),
                      f"{by['counterfactual']} / {by['unreachable']} / {by['lackbranch']}", hw)
    _console().print(table)
    ops: dict[str, list[int]] = {}
    for r in reports:
        for op, row in r.by_operator().items():
            acc = ops.setdefault(op, [0, 0])
            acc[0] += row["mutants"]
            acc[1] += row["killable"]
    print("by operator: " + ", ".join(f"{op} {m}/{k}" for op, (m, k) in sorted(ops.items()))
          + "  (mutants/killable)")
    total = sum(len(r.killable) for r in reports)
    print(f"{len(reports)} task(s): {sum(len(r.outcomes) for r in reports)} mutants, {total} killable "
          f"({total / len(reports):.1f} per task)")
    for r in reports:
        for kind, h in r.handwritten.items():
            if not h.reproduced_by:
                print(f"not reproduced: {r.task} {kind}: {h.reason}; closest {h.closest} "
                      f"(Jaccard {h.closest_jaccard:.2f})")
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


def _some_tasks(tasks_dir: str | None) -> None:
    """A tasks folder without any task is a mistake (a wrong path), not an empty benchmark."""
    from logicenveval.benchmark import task_ids
    from logicenveval.benchmark import tasks_dir as folder
    from logicenveval.errors import ConfigError

    if not task_ids(tasks_dir):
        raise ConfigError("no task in this folder (no <task_id>/task.json)", file=str(folder(tasks_dir)),
                          field="--tasks-dir", hint="pass the folder that holds the task folders")


def _positive(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}")
    return n


@contextlib.contextmanager
def _progress(what: str) -> Iterator[Callable[[int, int, str], None]]:
    """A progress bar on stderr (stdout keeps only the result) for a per-task callback
    `(done, total, task)`; it disappears when done."""
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    with Progress(TextColumn(f"{what} {{task.description}}"), BarColumn(), MofNCompleteColumn(),
                  TimeElapsedColumn(), console=Console(stderr=True), transient=True) as bar:
        job = bar.add_task("", total=None)

        def advance(done: int, total: int, task: str) -> None:
            bar.update(job, completed=done, total=total, description=task)

        yield advance


def _console() -> Console:
    """A console at least 140 columns wide, so that piped output keeps task ids whole."""
    from rich.console import Console

    probe = Console()
    return Console(width=max(probe.width, 140))
