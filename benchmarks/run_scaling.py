"""Wall time of the offline benchmark run with 1 and 2 workers, and the share of the report.

Runs `python -m logicenveval run --model offline` twice in fresh folders (1 then 2 workers, same
machine, same load), then `report` on the finished 2-worker run. Prints the load (`uptime`), the
machine's own 2-process capacity (a pure-Python CPU loop run twice serially vs in 2 processes:
~2.0 on an idle 2-core machine, ~1.0 when other sessions take the second core), one line per
configuration (wall time, per-generator generation seconds), the time to write the finished
2-worker run's leaderboards in this process (`write_leaderboards`, what `run` does after its
units: the index and main page, the task pages being written by the workers; and with every
page), the `report RUN_DIR` time, and, last,
`speedup_2_workers=<x> report_share=<r> total_s=<s>`: the 1-worker / 2-worker wall-time ratio,
the leaderboard time / the 2-worker wall time, and the 2-worker wall time of the full default
run (25 tasks x 5 generators). The package is byte-compiled first (`--no-compile` leaves it),
so the figures are those of an installed package, not of a checkout whose environment forbids
writing bytecode. On a machine shared with other work, wall-time ratios understate
the speed-up; compare it with the capacity line.

Where the time goes (issue 38), from the run's own instrumentation (results.json `timing`:
`run_phases` of the main process, `phases` of each generator's units, `logicenveval.phases`), per
configuration: `main` — the run process's phases (start-up, tasks, resume scan, units = waiting
for workers, saving units, results) and `rest` = wall − those (interpreter start and imports,
samples.jsonl/results.json, leaderboards); `units` — seconds summed over all units (CPU-ish time
of the workers: start-up, task loading, generation per method, layout, physics, coverage,
simulation, traces, mutants, render, writing, and after it `saving` the unit file, `results` its
figures and `report` its task page); `busy` — that sum / (wall × workers), how much of
the workers' time units used. Last the run folder's size by part.
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


#: the order phases are printed in (others follow alphabetically)
UNIT_PHASES = ("start-up", "tasks", "generation", "layout", "physics", "coverage", "simulation",
               "traces", "mutants", "render", "writing", "saving", "results", "report")
RUN_PHASES = ("start-up", "tasks", "resume scan", "units", "saving", "results")


def _ordered(values: dict[str, float], order: tuple[str, ...]) -> list[tuple[str, float]]:
    return [(k, values[k]) for k in order if k in values] + sorted(
        (k, v) for k, v in values.items() if k not in order)


def phase_lines(workers: int, wall: float, timing: dict[str, object]) -> list[str]:
    """The per-phase breakdown of one run, from its results.json `timing`."""
    run_phases = timing.get("run_phases") or {}
    per_gen = timing.get("phases") or {}
    assert isinstance(run_phases, dict) and isinstance(per_gen, dict)
    main = " ".join(f"{k.replace(' ', '_')}={v:.2f}" for k, v in _ordered(run_phases, RUN_PHASES))
    rest = wall - sum(run_phases.values())
    totals: dict[str, float] = {}
    for phases in per_gen.values():
        for k, v in phases.items():
            totals[k] = totals.get(k, 0.0) + v
    units = " ".join(f"{k}={v:.2f}" for k, v in _ordered(totals, UNIT_PHASES))
    gen = " ".join(f"{g}={p.get('generation', 0.0):.2f}+layout {p.get('layout', 0.0):.2f}"
                   for g, p in per_gen.items())
    busy = sum(totals.values()) / (wall * workers) if wall else 0.0
    return [f"  main_s: {main} rest={rest:.2f}",
            f"  units_s (summed over units): {units} total={sum(totals.values()):.2f} busy={busy:.2f}",
            f"  generation_s per method: {gen}"]


def leaderboard_seconds(run_dir: Path) -> tuple[float, float]:
    """Seconds to write a finished run's report in this process, from its units held in memory:
    as `run` does after its units (the index and main page; each task page was written by the
    worker that ran its unit, `reporting.unit_page`), and every page too (a resumed run whose
    units are all reused; `report RUN_DIR` also reads the units)."""
    from logicenveval.reporting.leaderboard import jinja, write_leaderboards
    from logicenveval.runner.results import load_results
    from logicenveval.runner.store import RunStore

    results = load_results(run_dir)
    store = RunStore(run_dir)
    records = [r for g in results["results"] for t in results["tasks"] if (r := store.load(g, t))]
    paged = {(r.generator, r.task_id) for r in records}
    write_leaderboards(run_dir, results, records, paged)  # imports done, as in `run` ...
    jinja.cache_clear()  # ... but the templates compiled within the time, as `run` does
    start = time.perf_counter()
    write_leaderboards(run_dir, results, records, paged)
    tail = time.perf_counter() - start
    start = time.perf_counter()
    write_leaderboards(run_dir, results, records)
    return tail, time.perf_counter() - start


def byte_compile() -> str:
    """Byte-compile the package's modules into `__pycache__`, as `pip install` does for an
    installed package and as any earlier run does unless writing bytecode is off: with
    PYTHONDONTWRITEBYTECODE=1 and no `.pyc`, every process of a run (the run's, the fork
    server's) compiles ~150 modules again, ~0.3 s of the serial start-up the workers wait for."""
    import compileall

    import logicenveval

    root = Path(logicenveval.__file__).parent
    ok = compileall.compile_dir(root, quiet=1)
    return f"bytecode=compiled ({root.name}/**/__pycache__, ok={bool(ok)})"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--tasks", default="all")
    parser.add_argument("--no-compile", action="store_true",
                        help="leave the package's bytecode as it is (with PYTHONDONTWRITEBYTECODE=1 "
                             "and no .pyc, every process compiles the package's modules)")
    parser.add_argument("--smoke", action="store_true",
                        help="seconds, not minutes: one task, two generators, no byte-compiling, a short "
                        "capacity loop (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = parser.parse_args()
    extra = ["--tasks", args.tasks]
    spin = 10_000_000
    if args.smoke:
        extra = ["--tasks", "lamp_or_pillow_fetch", "--generators", "logicenvgen,holodeck"]
        args.no_compile, spin = True, 200_000
    print("load (1, 5, 15 min): " + " ".join(f"{x:.2f}" for x in os.getloadavg()) + f"; cores {os.cpu_count()}")
    print(f"bytecode=as found (PYTHONDONTWRITEBYTECODE={os.environ.get('PYTHONDONTWRITEBYTECODE', '')!r})"
          if args.no_compile else byte_compile())
    print(f"machine_2_process_capacity={capacity(spin):.2f}")
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
            for line in phase_lines(workers, wall, timing):
                print(line)
        report_s, every_page_s = leaderboard_seconds(Path(run_dir))
        print(f"report_s={report_s:.3f} (what `run` writes after its units: leaderboards and index; "
              f"the task pages come from the workers) report_every_page_s={every_page_s:.3f}")
        from logicenveval.runner.footprint import folder_bytes, size_text

        print(f"run_folder={size_text(folder_bytes(Path(run_dir)), parts=8)}")
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "logicenveval", "report", run_dir], check=True,
                       stdout=subprocess.DEVNULL)
        print(f"report_command_s={time.perf_counter() - start:.2f} (interpreter start included)")
    print("load after: " + " ".join(f"{x:.2f}" for x in os.getloadavg())
          + f"; machine_2_process_capacity={capacity(spin):.2f}")
    print(f"speedup_2_workers={walls[1] / walls[2]:.2f} report_share={report_s / walls[2]:.3f} "
          f"total_s={walls[2]:.2f}")


if __name__ == "__main__":
    main()
