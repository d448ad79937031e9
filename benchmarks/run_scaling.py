"""Wall time of the offline benchmark run with 1 and 2 workers, and per generator.

Prints one line per configuration and, last, `speedup_2_workers=<x> total_s=<s>` where total_s is
the 2-worker wall time of the full default run (25 tasks x 4 generators).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def timed_run(workers: int, out: Path, extra: list[str]) -> tuple[float, dict[str, float]]:
    cmd = [sys.executable, "-m", "logicenveval", "run", "--model", "offline", "--quiet",
           "--workers", str(workers), "--output", str(out), *extra]
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    results = json.loads((run_dir / "results.json").read_text())
    return wall, results["timing"]["generation_seconds"]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--tasks", default="all")
    args = parser.parse_args()
    extra = ["--tasks", args.tasks]
    walls = {}
    with tempfile.TemporaryDirectory() as tmp:
        for workers in (1, 2):
            wall, per_gen = timed_run(workers, Path(tmp) / f"w{workers}", extra)
            walls[workers] = wall
            gens = " ".join(f"{g}_gen_s={s:.2f}" for g, s in per_gen.items())
            print(f"workers={workers} wall_s={wall:.2f} {gens}")
    print(f"speedup_2_workers={walls[1] / walls[2]:.2f} total_s={walls[2]:.2f}")


if __name__ == "__main__":
    main()
