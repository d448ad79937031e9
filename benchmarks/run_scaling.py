"""Wall time of the offline benchmark run with 1 and 2 workers, and the share of the report.

Runs `python -m logicenveval run --model offline` twice in fresh folders (1 then 2 workers, same
machine, same load), then `report` on the finished 2-worker run. Prints the load (`uptime`), the
machine's own 2-process capacity (a pure-Python CPU loop run twice serially vs in 2 processes:
~2.0 on an idle 2-core machine, ~1.0 when other sessions take the second core), one line per
configuration (wall time, per-generator generation seconds), the time to write the finished
2-worker run's leaderboards in this process (`write_leaderboards`, what `run` does after its
units), the `report RUN_DIR` time, and, last,
`speedup_2_workers=<x> report_share=<r> total_s=<s>`: the 1-worker / 2-worker wall-time ratio,
the leaderboard time / the 2-worker wall time, and the 2-worker wall time of the full default
run (25 tasks x 4 generators). On a machine shared with other work, wall-time ratios understate
the speed-up; compare it with the capacity line.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def _spin(n: int) -> int:
    x = 0
    for i in range(n):
        x += i * i
    return x


def capacity(n: int = 10_000_000) -> float:
    """Speed-up of two independent CPU-bound processes over running them one after the other."""
    start = time.perf_counter()
    _spin(n)
    _spin(n)
    serial = time.perf_counter() - start
    start = time.perf_counter()
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        pool.map(_spin, [n, n])
    return serial / (time.perf_counter() - start)


def timed_run(workers: int, out: Path, extra: list[str]) -> tuple[float, dict[str, object]]:
    cmd = [sys.executable, "-m", "logicenveval", "run", "--model", "offline", "--quiet",
           "--workers", str(workers), "--output", str(out), *extra]
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    timing: dict[str, object] = json.loads((run_dir / "results.json").read_text())["timing"]
    timing["run_dir"] = str(run_dir)
    return wall, timing


def leaderboard_seconds(run_dir: Path) -> float:
    """Time to write a finished run's leaderboards and per-task pages from its units."""
    from logicenveval.reporting.leaderboard import write_leaderboards
    from logicenveval.runner.results import load_results

    results = load_results(run_dir)
    start = time.perf_counter()
    write_leaderboards(run_dir, results)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--tasks", default="all")
    args = parser.parse_args()
    extra = ["--tasks", args.tasks]
    print("load (1, 5, 15 min): " + " ".join(f"{x:.2f}" for x in os.getloadavg()) + f"; cores {os.cpu_count()}")
    print(f"machine_2_process_capacity={capacity():.2f}")
    walls: dict[int, float] = {}
    run_dir = ""
    with tempfile.TemporaryDirectory() as tmp:
        for workers in (1, 2):
            wall, timing = timed_run(workers, Path(tmp) / f"w{workers}", extra)
            walls[workers] = wall
            gen = timing["generation_seconds"]
            assert isinstance(gen, dict)
            gens = " ".join(f"{g}_gen_s={s:.2f}" for g, s in gen.items())
            run_dir = str(timing["run_dir"])
            print(f"workers={workers} wall_s={wall:.2f} {gens}")
        report_s = leaderboard_seconds(Path(run_dir))
        print(f"report_s={report_s:.3f}")
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "logicenveval", "report", run_dir], check=True,
                       stdout=subprocess.DEVNULL)
        print(f"report_command_s={time.perf_counter() - start:.2f} (interpreter start included)")
    print("load after: " + " ".join(f"{x:.2f}" for x in os.getloadavg())
          + f"; machine_2_process_capacity={capacity():.2f}")
    print(f"speedup_2_workers={walls[1] / walls[2]:.2f} report_share={report_s / walls[2]:.3f} "
          f"total_s={walls[2]:.2f}")


if __name__ == "__main__":
    main()
