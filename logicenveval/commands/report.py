"""`report RUN_DIR`: rebuild leaderboard.md and leaderboard.html from a run folder."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("run_dir", help="a folder written by `run`")


def run(args: argparse.Namespace) -> int:
    from logicenveval.reporting.leaderboard import write_leaderboards
    from logicenveval.runner.results import load_results

    run_dir = Path(args.run_dir)
    write_leaderboards(run_dir, load_results(run_dir))
    print(f"wrote {run_dir / 'leaderboard.md'} and {run_dir / 'leaderboard.html'}")
    return 0
