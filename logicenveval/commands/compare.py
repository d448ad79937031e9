"""`compare RUN_A RUN_B`: per-metric deltas; exit 1 when a metric regresses beyond tolerance."""

from __future__ import annotations

import argparse
from pathlib import Path

from logicenveval.commands import options


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("run_a", help="baseline run folder")
    p.add_argument("run_b", help="candidate run folder")
    p.add_argument("--tolerance", type=options.non_negative_float, default=0.02,
                   help="allowed drop per metric, absolute (rates are fractions; default 0.02)")
    p.add_argument("--judge-timing", action="store_true", help="also fail on slower ST")


def run(args: argparse.Namespace) -> int:
    from rich.console import Console
    from rich.table import Table

    from logicenveval.errors import ConfigError
    from logicenveval.reporting.compare import compare_results
    from logicenveval.runner.results import load_results

    a, b = load_results(Path(args.run_a)), load_results(Path(args.run_b))
    if sorted(a.get("tasks", [])) != sorted(b.get("tasks", [])):
        only_a = sorted(set(a.get("tasks", [])) - set(b.get("tasks", [])))
        only_b = sorted(set(b.get("tasks", [])) - set(a.get("tasks", [])))
        raise ConfigError(f"the runs cover different tasks (only in A: {only_a[:5]}, only in B: "
                          f"{only_b[:5]}); their metrics are not comparable", field="run_b",
                          hint="compare runs made with the same --tasks/--limit")
    deltas = compare_results(a, b, tolerance=args.tolerance, judge_timing=args.judge_timing)
    table = Table(title=f"{args.run_a} → {args.run_b} (tolerance {args.tolerance})")
    for col in ("generator", "metric", "before", "after", "change", ""):
        table.add_column(col, justify="right" if col in ("before", "after", "change") else "left")
    for d in deltas:
        table.add_row(d.generator, d.metric,
                      "–" if d.before is None else f"{d.before:.4f}",
                      "–" if d.after is None else f"{d.after:.4f}",
                      "–" if d.change is None else f"{d.change:+.4f}",
                      "[red]REGRESSION[/red]" if d.regression else "")
    Console().print(table)
    for gen in [g for g in a["results"] if g not in b["results"]]:
        print(f"note: generator {gen} is only in {args.run_a}; it is not judged")
    regressions = [d for d in deltas if d.regression]
    if regressions:
        print(f"{len(regressions)} regression(s) beyond tolerance {args.tolerance}")
        return 1
    print("no regression")
    return 0
