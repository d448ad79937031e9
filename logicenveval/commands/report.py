"""`report RUN_DIR [RUN_DIR ...] [--out DIR]`: rebuild a run's leaderboards, or merge runs into one.

Every file is written to a temp file and renamed (`logicenveval.atomic`), so an interrupted or
failed report leaves the previous one readable."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("run_dirs", nargs="+", metavar="RUN_DIR", help="folders written by `run`/`evaluate`")
    p.add_argument("--out", default=None,
                   help="folder of the merged leaderboard (default: the run folder for one run, "
                   "reports/merged for several)")


def run(args: argparse.Namespace) -> int:
    dirs = [Path(d) for d in args.run_dirs]
    if len(dirs) == 1 and args.out is None:
        from logicenveval.errors import RunStoreError
        from logicenveval.paths import refuse_links
        from logicenveval.reporting.leaderboard import write_leaderboards
        from logicenveval.runner.results import load_results

        results = load_results(dirs[0])
        refuse_links(dirs[0], error=RunStoreError)  # pages are never written through a link
        pages = write_leaderboards(dirs[0], results).rows
        print(f"wrote {dirs[0] / 'leaderboard.md'}, {dirs[0] / 'leaderboard.html'} and "
              f"{len(pages)} task page(s) under details/")
        return 0
    from logicenveval.reporting.merged import merged_markdown, write_merged

    out = Path(args.out or "reports/merged")
    runs = write_merged(dirs, out)
    print(merged_markdown(runs))
    print(f"wrote {out / 'leaderboard.md'} and {out / 'leaderboard.html'}")
    return 0
