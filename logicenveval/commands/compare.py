"""`compare RUN_A [RUN_B] [--gen-a X --gen-b Y]`: paired differences; exit 1 on a regression."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from logicenveval.commands import options


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("run_a", help="baseline run folder (A)")
    p.add_argument("run_b", nargs="?", default=None,
                   help="candidate run folder (B; default: A itself, to compare two of its generators)")
    p.add_argument("--gen-a", default=None, help="generator of A to compare (default: every generator)")
    p.add_argument("--gen-b", default=None,
                   help="generator of B to compare with --gen-a (default: the same name)")
    p.add_argument("--tolerance", type=options.non_negative_float, default=0.02,
                   help="allowed change per metric, absolute (rates are fractions; default 0.02)")
    p.add_argument("--judge-timing", action="store_true", help="also fail on slower ST (ms)")
    p.add_argument("--common-tasks", action="store_true",
                   help="leave out tasks whose definition differs between the runs instead of refusing")
    p.add_argument("--allow-missing", action="store_true",
                   help="a generator or task of A that B lacks (or did not measure) is reported, "
                   "not a regression")
    p.add_argument("--json", action="store_true", help="print the comparison as JSON")
    p.add_argument("--html", default=None, metavar="PAGE",
                   help="also write the comparison as an HTML page (per-task differences, links "
                   "to both runs' detail pages)")


def run(args: argparse.Namespace) -> int:
    from logicenveval.errors import ConfigError
    from logicenveval.reporting.compare import compare_results, compared_tasks
    from logicenveval.reporting.compare_text import comparison_text
    from logicenveval.runner.results import load_results

    if args.run_b is None and args.gen_a is None and args.gen_b is None:
        raise ConfigError("one run folder compares two of its generators", field="--gen-a",
                          hint="pass RUN_B, or --gen-a X --gen-b Y (e.g. --gen-a logicenvgen --gen-b cot)")
    a = load_results(Path(args.run_a))
    b = a if args.run_b is None else load_results(Path(args.run_b))
    tasks = compared_tasks(a, b, skip_changed=args.common_tasks)
    comparison = compare_results(a, b, tolerance=args.tolerance, judge_timing=args.judge_timing,
                                 tasks=tasks, gen_a=args.gen_a, gen_b=args.gen_b,
                                 allow_missing=args.allow_missing)
    if args.json:
        print(json.dumps({"a": args.run_a, "b": args.run_b or args.run_a, **comparison.to_json()},
                         indent=2))
    else:
        print(comparison_text(comparison, args.run_a, args.run_b or args.run_a))
    if args.html:
        from logicenveval.reporting.compare_html import write_comparison_html

        write_comparison_html(Path(args.html), comparison, a, b, Path(args.run_a),
                              Path(args.run_b or args.run_a))
        if not args.json:
            print(f"comparison page: {args.html}")
    return 1 if comparison.failed else 0
