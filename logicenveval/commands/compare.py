"""`compare RUN_A RUN_B`: paired per-metric differences; exit 1 on a regression."""

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
    p.add_argument("--common-tasks", action="store_true",
                   help="compare over the tasks both runs share (same task versions) instead of "
                   "refusing different task sets")


def run(args: argparse.Namespace) -> int:
    from rich.console import Console
    from rich.table import Table

    from logicenveval.reporting.compare import common_tasks, compare_results
    from logicenveval.runner.results import load_results

    a, b = load_results(Path(args.run_a)), load_results(Path(args.run_b))
    common = common_tasks(a, b, allow_subset=args.common_tasks)
    deltas = compare_results(a, b, tolerance=args.tolerance, judge_timing=args.judge_timing,
                             common=common)
    table = Table(title=f"{args.run_a} → {args.run_b} ({len(common)} tasks, tolerance "
                        f"{args.tolerance}; change with its 95 % paired bootstrap interval)")
    for col in ("generator", "metric", "before", "after", "change", "95% CI of change", ""):
        table.add_column(col, justify="left" if col in ("generator", "metric", "") else "right")
    for d in deltas:
        table.add_row(d.generator, d.metric,
                      "–" if d.before is None else f"{d.before:.4f}",
                      "–" if d.after is None else f"{d.after:.4f}",
                      "–" if d.change is None else f"{d.change:+.4f}",
                      "–" if d.ci95 is None else f"[{d.ci95[0]:+.4f}, {d.ci95[1]:+.4f}]",
                      "[red]REGRESSION[/red]" if d.regression else "")
    Console(width=160).print(table)
    regressions = [d for d in deltas if d.regression]
    if regressions:
        print(f"{len(regressions)} regression(s): beyond tolerance {args.tolerance} with a paired "
              "95 % interval excluding 0")
        for d in regressions:
            ci = "" if d.ci95 is None else f" [{d.ci95[0]:+.4f}, {d.ci95[1]:+.4f}]"
            change = "missing in B" if d.change is None else f"{d.change:+.4f}"
            print(f"  {d.generator} {d.metric}: {change}{ci}")
        return 1
    print("no regression")
    return 0
