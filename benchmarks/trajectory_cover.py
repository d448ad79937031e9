"""Trajectory selectors on random independent forests, and the per-task table (issues 5, 18).

    python benchmarks/trajectory_cover.py            # forests 6x4, 8x5, 10x6; last line = 8x5 figures
    python benchmarks/trajectory_cover.py --tasks    # the paper's Table on MTSA, per benchmark task
    python benchmarks/trajectory_cover.py --forbidden 0.15 --subtasks 12 --paths 20
        # random forests where each cross-subtask path pair is forbidden with that probability;
        # last line `exact_median_s=... proven=<proven>/<draws with a cover> mtsa_s=...`
    python benchmarks/trajectory_cover.py --plans    # the exhaustive search on the plans the
        # offline model derives (what `logicenvgen-exhaustive` searches): per-task subsets and time

Selectors: `product` (the Cartesian product, "W/O MTSA"), `mtsa` (paper Algorithm 1),
`exhaustive` (the paper's exponential minimum-set-cover search; its budget counts subsets),
`exact` (ours).
Trees are drawn from a seeded numpy Generator; each subtask's tree has exactly the stated number
of leaves (random shape, depth up to 3). The product and MTSA are skipped when the product or the
time budget is too large, and a search that runs out of budget says so; nothing is hidden.
"""

from __future__ import annotations

import argparse
import itertools
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
from logicenveval.logic.exhaustive import MAX_SUBSETS, exhaustive_cover  # noqa: E402
from logicenveval.logic.mtsa import mtsa_impl  # noqa: E402
from logicenveval.logic.reference import reference_set  # noqa: E402
from logicenveval.logic.selectors import get_selector, uncovered  # noqa: E402
from logicenveval.model.task import Leaf, Node, Subtask  # noqa: E402
from logicenveval.model.tree import DecisionPath, task_paths, tree_paths  # noqa: E402

CASES = [(6, 4), (8, 5), (10, 6)]
HEADLINE = (8, 5)
#: `--smoke`: one small forest, the headline of the smoke test (tests/test_benchmarks_smoke.py)
SMOKE_CASES = [(4, 3)]
PRODUCT_MAX = 500_000
MTSA_BUDGET_S = 20.0
#: the random forests' budget for the exhaustive search (the generator's default is larger)
EXHAUSTIVE_SUBSETS = 10**9


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


def run_forests(seed: int, cases: list[tuple[int, int]] = CASES,
                headline_case: tuple[int, int] = HEADLINE) -> int:
    rng = np.random.default_rng(seed)
    headline: tuple[float, int, int] | None = None
    print(f"seed={seed}; exact timed as the median of 50 runs, MTSA once (budget {MTSA_BUDGET_S:.0f} s)")
    print(f"{'case':>6} {'product':>12} {'all of product':>22} {'mtsa':>22} {'exhaustive search':>30} "
          f"{'exact':>18}")
    for n, k in cases:
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
            search = exhaustive_cover(forest, max_subsets=EXHAUSTIVE_SUBSETS)
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
        if (n, k) == headline_case:
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
        search = exhaustive_cover(paths, cons)
        result = exact_cover(paths, cons)
        ms = {"mtsa": median_ms(partial(mtsa_impl, paths, cons), repeat=21),
              "exhaustive": median_ms(partial(exhaustive_cover, paths, cons), repeat=5),
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


def _masks(paths: list[list[DecisionPath]]) -> tuple[list[int], int]:
    """The product's path masks as `exhaustive_cover` builds them (no constraints)."""
    bit = {p.key: 1 << n for n, p in enumerate(p for ps in paths for p in ps)}
    masks = [sum(bit[p.key] for p in c) for c in itertools.product(*paths)]
    return masks, (1 << len(bit)) - 1


def run_plans(tasks_dir: Path, max_subsets: int, only: list[str], plain_subsets: int) -> int:
    """Per task: the exhaustive search on the plan the offline model derives (the trees
    `logicenvgen-exhaustive` searches, not the GT), with its subsets tested and wall time; and,
    as the baseline of the same run, the plain Python loop's rate over its first subsets."""
    import os

    from logicenveval.domain.catalog import load_catalog
    from logicenveval.generators.base import GenerationContext
    from logicenveval.generators.brief import generator_brief
    from logicenveval.generators.plan import derive_plan
    from logicenveval.llm.registry import make_model
    from logicenveval.logic.exhaustive import _search_plain

    model = make_model("offline", "", no_cache=True)
    catalog = load_catalog()
    print(f"load={' '.join(f'{x:.2f}' for x in os.getloadavg())} max_subsets={max_subsets:,}")
    print("| task | paths per subtask | product N | minimum cover | subsets tested | finished | "
          "exhaustive s | subsets/s | plain loop subsets/s | MTSA size |")
    print("|---|---|---:|---:|---:|---|---:|---:|---:|---:|")
    total = plain_total = 0.0
    tested_total = plain_tested = 0
    hit: list[str] = []
    for task_id in only or task_ids(tasks_dir):
        task = load_task(task_id, tasks_dir)
        brief = generator_brief(task, "roles", model, seed=0)
        ctx = GenerationContext(model=model, catalog=catalog, rng=np.random.default_rng(0), seed=0)
        paths = task_paths(derive_plan(brief, ctx).task)
        t0 = time.perf_counter()
        search = exhaustive_cover(paths, max_subsets=max_subsets)
        elapsed = time.perf_counter() - t0
        masks, full = _masks(paths)
        t0 = time.perf_counter()
        _, plain_n = _search_plain(masks, full, min(plain_subsets, search.tested))
        plain_s = time.perf_counter() - t0
        total, tested_total = total + elapsed, tested_total + search.tested
        plain_total, plain_tested = plain_total + plain_s, plain_tested + plain_n
        exact = exact_cover(paths)
        if search.optimal:
            assert len(search.trajectories) == len(exact.trajectories)
        else:
            hit.append(task_id)
        mtsa = get_selector("mtsa").select(paths)
        print(f"| {task_id} | {'×'.join(str(len(p)) for p in paths)} | {math.prod(len(p) for p in paths):,} | "
              f"{len(exact.trajectories)} | {search.tested:,} | {'yes' if search.optimal else 'budget hit'} | "
              f"{elapsed:.2f} | {search.tested / elapsed:.3g} | {plain_n / plain_s:.3g} | {len(mtsa)} |")
    rate, plain_rate = tested_total / total, plain_tested / plain_total
    print(f"exhaustive_total_s={total:.1f} budget_hit={len(hit)} {','.join(hit)} "
          f"subsets_per_s={rate:.3g} plain_loop_subsets_per_s={plain_rate:.3g} speedup={rate / plain_rate:.0f}")
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
    parser.add_argument("--plans", action="store_true",
                        help="the exhaustive search on the offline model's derived plans, per task")
    parser.add_argument("--max-subsets", type=int, default=MAX_SUBSETS,
                        help="the exhaustive search's budget in subsets tested (--plans)")
    parser.add_argument("--only", default="", help="comma-separated task ids (--plans)")
    parser.add_argument("--plain-subsets", type=int, default=2_000_000,
                        help="subsets the plain-loop baseline tests per task (--plans)")
    parser.add_argument("--smoke", action="store_true",
                        help="seconds, not minutes: one 4x3 forest (with --tasks: 3 tasks; with "
                        "--forbidden: 2 small draws); the figures are not the documented ones")
    args = parser.parse_args()
    if args.smoke and args.plans:
        return run_plans(args.tasks_dir, args.max_subsets, ["clean_living_room"], 10_000)
    if args.smoke and args.forbidden is not None:
        return run_forbidden(args.seed, args.forbidden, 4, 4, 2, 2.0)
    if args.smoke and not args.tasks:
        return run_forests(args.seed, SMOKE_CASES, SMOKE_CASES[0])
    if args.plans:
        return run_plans(args.tasks_dir, args.max_subsets, [t for t in args.only.split(",") if t],
                         args.plain_subsets)
    if args.forbidden is not None:
        return run_forbidden(args.seed, args.forbidden, args.subtasks, args.paths, args.draws, args.mtsa_budget)
    return run_tasks(args.tasks_dir) if args.tasks else run_forests(args.seed)


if __name__ == "__main__":
    raise SystemExit(main())
