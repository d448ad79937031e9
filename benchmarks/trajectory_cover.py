"""Trajectory selectors on random independent forests, and the per-task table (issues 5, 18).

    python benchmarks/trajectory_cover.py            # forests 6x4, 8x5, 10x6; last line = 8x5 figures
    python benchmarks/trajectory_cover.py --tasks    # the paper's Table on MTSA, per benchmark task
    python benchmarks/trajectory_cover.py --forbidden 0.15 --subtasks 12 --paths 20
        # random forests where each cross-subtask path pair is forbidden with that probability;
        # last line `exact_median_s=... proven=<proven>/<draws with a cover> mtsa_s=...`

Selectors: `product` (the Cartesian product, "W/O MTSA"), `mtsa` (paper Algorithm 1),
`exhaustive` (the paper's exponential minimum-set-cover search, 10 s budget), `exact` (ours).
Trees are drawn from a seeded numpy Generator; each subtask's tree has exactly the stated number
of leaves (random shape, depth up to 3). The product and MTSA are skipped when the product or the
time budget is too large, and a search that runs out of budget says so; nothing is hidden.
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
from collections.abc import Callable
from functools import partial
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from logicenveval.benchmark import load_task, task_ids  # noqa: E402
from logicenveval.errors import LogicEnvEvalError  # noqa: E402
from logicenveval.logic.constraints import PathConstraints, task_constraints  # noqa: E402
from logicenveval.logic.exact import exact_cover  # noqa: E402
from logicenveval.logic.exhaustive import exhaustive_cover  # noqa: E402
from logicenveval.logic.mtsa import mtsa_impl  # noqa: E402
from logicenveval.logic.reference import reference_set  # noqa: E402
from logicenveval.logic.selectors import get_selector, uncovered  # noqa: E402
from logicenveval.model.task import Leaf, Node, Subtask  # noqa: E402
from logicenveval.model.tree import DecisionPath, task_paths, tree_paths  # noqa: E402

CASES = [(6, 4), (8, 5), (10, 6)]
HEADLINE = (8, 5)
PRODUCT_MAX = 500_000
MTSA_BUDGET_S = 20.0
EXHAUSTIVE_BUDGET_S = 10.0


def random_tree(rng: np.random.Generator, leaves: int, prefix: str, depth: int = 0) -> Node | Leaf:
    """A tree with exactly `leaves` leaves: split the leaf count over 2..min(3, leaves) branches."""
    if leaves == 1:
        return Leaf(plan=[], goal="true")
    width = leaves if depth == 2 else int(rng.integers(2, min(3, leaves) + 1))
    cuts = np.sort(rng.choice(np.arange(1, leaves), size=width - 1, replace=False))
    sizes = np.diff(np.concatenate(([0], cuts, [leaves]))).tolist()
    var = f"{prefix}d{depth}_{int(rng.integers(1 << 30))}"
    return Node(
        var=var,
        branches={f"b{k}": random_tree(rng, int(n), f"{prefix}{k}", depth + 1) for k, n in enumerate(sizes)},
    )


def random_forest(rng: np.random.Generator, subtasks: int, paths: int) -> list[list[DecisionPath]]:
    return [tree_paths(Subtask(id=f"s{i}", tree=random_tree(rng, paths, f"s{i}"))) for i in range(subtasks)]


def median_ms(fn: Callable[[], object], repeat: int = 1) -> float:
    """Median wall time of `fn` in milliseconds over `repeat` runs."""
    times: list[float] = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append((time.perf_counter() - t0) * 1000)
    return statistics.median(times)


def run_forests(seed: int) -> int:
    rng = np.random.default_rng(seed)
    headline: tuple[float, int, int] | None = None
    print(f"seed={seed}; exact timed as the median of 50 runs, MTSA once (budget {MTSA_BUDGET_S:.0f} s)")
    print(f"{'case':>6} {'product':>12} {'all of product':>22} {'mtsa':>22} {'exhaustive search':>30} "
          f"{'exact':>18}")
    for n, k in CASES:
        forest = random_forest(rng, n, k)
        product = math.prod(len(p) for p in forest)
        ex_txt = f"skipped ({product:,})"
        search_txt = "skipped (product too large)"
        if product <= PRODUCT_MAX:
            t0 = time.perf_counter()
            ex = get_selector("product").select(forest)
            ex_txt = f"{len(ex)} in {(time.perf_counter() - t0) * 1000:.1f} ms"
            del ex
            t0 = time.perf_counter()
            search = exhaustive_cover(forest, budget_s=EXHAUSTIVE_BUDGET_S)
            search_ms = (time.perf_counter() - t0) * 1000
            search_txt = (f"{len(search.trajectories)} in {search_ms:.1f} ms" if search.optimal
                          else f"budget out ({search.tested:,} sets)")
        t0 = time.perf_counter()
        mt = mtsa_impl(forest, PathConstraints(), time.monotonic() + MTSA_BUDGET_S)
        mt_ms = (time.perf_counter() - t0) * 1000
        exact = exact_cover(forest).trajectories
        exact_ms = median_ms(partial(exact_cover, forest), repeat=50)
        assert not uncovered(exact, forest)
        mt_txt = f"skipped (> {MTSA_BUDGET_S:.0f} s)" if mt is None else f"{len(mt)} in {mt_ms:.1f} ms"
        print(f"{n:>2}x{k:<3} {product:>12,} {ex_txt:>22} {mt_txt:>22} {search_txt:>30} "
              f"{len(exact):>3} in {exact_ms:.3f} ms")
        if mt is not None:
            assert not uncovered(mt, forest) and len(exact) <= len(mt)
        if (n, k) == HEADLINE:
            if mt is None:
                print("mtsa did not finish on the headline case", file=sys.stderr)
                return 1
            headline = (mt_ms / exact_ms, len(exact), len(mt))
    assert headline is not None
    speedup, exact_size, mtsa_size = headline
    print(f"exact_speedup_vs_mtsa={speedup:.0f} exact_size={exact_size} mtsa_size={mtsa_size}")
    return 0


def random_pairs(rng: np.random.Generator, forest: list[list[DecisionPath]], share: float) -> PathConstraints:
    """Each pair of paths of different subtasks is forbidden with probability `share`."""
    keys = [[p.key for p in paths] for paths in forest]
    pairs = [(a, b) for i in range(len(keys)) for j in range(i + 1, len(keys))
             for a in keys[i] for b in keys[j]]
    drawn = rng.random(len(pairs)) < share
    return PathConstraints.of_pairs(p for p, keep in zip(pairs, drawn, strict=True) if keep)


def run_forbidden(seed: int, share: float, subtasks: int, paths: int, draws: int, mtsa_budget: float) -> int:
    import os

    rng = np.random.default_rng(seed)
    print(f"load={' '.join(f'{x:.2f}' for x in os.getloadavg())} seed={seed} draws={draws} "
          f"forest={subtasks}x{paths} forbidden={share:.2f}")
    times: list[float] = []
    proven = covered = 0
    first: tuple[list[list[DecisionPath]], PathConstraints] | None = None
    for d in range(draws):
        forest = random_forest(rng, subtasks, paths)
        cons = random_pairs(rng, forest, share)
        t0 = time.perf_counter()
        try:
            result = exact_cover(forest, cons)
        except LogicEnvEvalError:
            print(f"draw {d}: {len(cons.forbidden)} pairs, no cover (a path is in no admissible trajectory)")
            continue
        elapsed = time.perf_counter() - t0
        out = list(result.trajectories)
        assert not uncovered(out, forest) and all(cons.admits_trajectory(t) for t in out)
        times.append(elapsed)
        covered += 1
        proven += result.optimal
        first = first or (forest, cons)
        print(f"draw {d}: {len(cons.forbidden)} pairs, size {len(out)}, lower bound {result.lower_bound}, "
              f"proven {result.optimal}, {elapsed:.3f} s")
    mtsa_txt = "n/a"
    if first is not None:
        t0 = time.perf_counter()
        mt = mtsa_impl(first[0], first[1], time.monotonic() + mtsa_budget)
        mtsa_s = time.perf_counter() - t0
        state = f"gave up at its {mtsa_budget:.0f} s budget" if mt is None else f"{len(mt)} trajectories"
        print(f"mtsa on draw 0 with a cover: {state} after {mtsa_s:.2f} s")
        mtsa_txt = f"{mtsa_s:.2f}"
    median = statistics.median(times) if times else float("nan")
    print(f"exact_median_s={median:.3f} proven={proven}/{covered} mtsa_s={mtsa_txt}")
    return 0 if proven == covered else 1


def run_tasks(tasks_dir: Path) -> int:
    """Per task: sizes and runtimes of MTSA, the exhaustive search and exact (medians of repeats)."""
    ids = task_ids(tasks_dir)
    rows: list[str] = []
    broken: list[str] = []
    times: dict[str, list[float]] = {"mtsa": [], "exhaustive": [], "exact": []}
    for task_id in ids:
        try:
            task = load_task(task_id, tasks_dir)
        except LogicEnvEvalError as exc:
            broken.append(f"{task_id} ({exc.message})")
            continue
        paths = task_paths(task)
        cons = task_constraints(task)
        product = math.prod(len(p) for p in paths)
        mt = mtsa_impl(paths, cons, time.monotonic() + MTSA_BUDGET_S)
        search = exhaustive_cover(paths, cons, budget_s=EXHAUSTIVE_BUDGET_S)
        result = exact_cover(paths, cons)
        ms = {"mtsa": median_ms(partial(mtsa_impl, paths, cons), repeat=21),
              "exhaustive": median_ms(partial(exhaustive_cover, paths, cons, budget_s=EXHAUSTIVE_BUDGET_S),
                                      repeat=5),
              "exact": median_ms(partial(exact_cover, paths, cons), repeat=21)}
        for name, value in ms.items():
            times[name].append(value)
        ref = reference_set(task)
        mt_txt = "skipped" if mt is None else str(len(mt))
        search_txt = str(len(search.trajectories)) if search.optimal else "budget out"
        proven = "" if result.optimal else " (not proven)"
        rows.append(
            f"| {task.id} | {len(paths)} | {sum(len(p) for p in paths)} | {product:,} | {mt_txt} | "
            f"{search_txt} | {len(result.trajectories)}{proven} | {len(ref)} | {len(cons.forbidden)} | "
            f"{ms['mtsa']:.2f} | {ms['exhaustive']:.2f} | {ms['exact']:.3f} |"
        )
    print(f"{len(rows)} of {len(ids)} task folders loaded")
    print("| task | subtasks | paths | product | MTSA | exhaustive | exact | reference (JI) | forbidden pairs "
          "| MTSA ms | exhaustive ms | exact ms |")
    print("|---|---|---|---|---|---|---|---|---|---:|---:|---:|")
    print("\n".join(rows))
    mean = {name: statistics.fmean(v) for name, v in times.items() if v}
    if mean:
        print("mean runtime per task (the paper's Table on MTSA: Exhaustive 38.12 ms, MTSA 0.99 ms): "
              + ", ".join(f"{name} {value:.3f} ms" for name, value in mean.items())
              + f"; exhaustive/mtsa = {mean['exhaustive'] / mean['mtsa']:.1f}x")
    for b in broken:
        print(f"not loaded: {b}")
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", action="store_true", help="print the per-task table instead")
    parser.add_argument("--tasks-dir", type=Path, default=ROOT / "benchmark_data" / "tasks")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--forbidden", type=float, default=None,
                        help="share of cross-subtask path pairs forbidden (switches to that benchmark)")
    parser.add_argument("--subtasks", type=int, default=12)
    parser.add_argument("--paths", type=int, default=20)
    parser.add_argument("--draws", type=int, default=10)
    parser.add_argument("--mtsa-budget", type=float, default=MTSA_BUDGET_S)
    args = parser.parse_args()
    if args.forbidden is not None:
        return run_forbidden(args.seed, args.forbidden, args.subtasks, args.paths, args.draws, args.mtsa_budget)
    return run_tasks(args.tasks_dir) if args.tasks else run_forests(args.seed)


if __name__ == "__main__":
    raise SystemExit(main())
