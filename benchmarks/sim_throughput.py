"""Simulator throughput on one core over every (task, policy, situation) of the benchmark.

Situation environments are built once (z3, untimed); the timed loop resets a world copy per
episode and reuses each policy's py_trees tree (built once). The baseline, measured in the same run, is the
convenience path `simulate()` that rebuilds the world from the EnvSpec and the GT goal each call.
Last line: `episodes_per_s=<float> ticks_per_s=<float>`.
"""

from __future__ import annotations

import argparse
import itertools
import time

from logicenveval.benchmark import load_tasks, policy_path
from logicenveval.domain.catalog import load_catalog
from logicenveval.errors import LogicEnvEvalError
from logicenveval.model.tree import Trajectory, task_paths
from logicenveval.sim.loader import load_policy
from logicenveval.sim.simulator import CompiledPolicy, simulate, task_goal
from logicenveval.sim.situations import situation_env
from logicenveval.sim.world import World


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--tasks-dir", default=None)
    ap.add_argument("--catalog", default=None)
    ap.add_argument("--seconds", type=float, default=3.0, help="time budget of the fast loop")
    ap.add_argument("--max-situations", type=int, default=64, help="per task")
    ap.add_argument("--smoke", action="store_true", help="seconds, not minutes: a small case of the same code path (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = ap.parse_args()
    if args.smoke:
        args.seconds, args.max_situations = 0.2, 2
    catalog = load_catalog(args.catalog)
    cases = []  # (compiled policy, world, goal, policy, env, task)
    skipped = 0
    t0 = time.perf_counter()
    tasks = load_tasks(args.tasks_dir)
    for task in tasks[:5] if args.smoke else tasks:
        try:
            policies = [load_policy(policy_path(task, k, args.tasks_dir), task.roles, task.rooms)
                        for k in task.policies]
        except LogicEnvEvalError as exc:
            print(f"skip {task.id}: {exc}")
            skipped += 1
            continue
        compiled = [CompiledPolicy(p) for p in policies]
        combos = itertools.islice(itertools.product(*task_paths(task)), args.max_situations)
        for combo in combos:
            try:
                env = situation_env(task, Trajectory(tuple(combo)), catalog)
            except LogicEnvEvalError as exc:
                print(f"skip situation of {task.id}: {exc}")
                skipped += 1
                continue
            world = World.from_env(env, catalog)
            goal = task_goal(task, world)
            for cp, p in zip(compiled, policies, strict=True):
                cases.append((cp, world, goal, p, env, task))
    print(f"cases={len(cases)} skipped={skipped} setup_s={time.perf_counter() - t0:.2f}")
    if not cases:
        raise SystemExit("no runnable (task, policy, situation) case")

    # baseline: one pass of the convenience API
    t0 = time.perf_counter()
    for _cp, _w, _g, p, env, task in cases:
        simulate(p, env, task, catalog)
    base_eps = len(cases) / (time.perf_counter() - t0)

    episodes = ticks = 0
    t0 = time.perf_counter()
    while time.perf_counter() - t0 < args.seconds:
        for cp, world, goal, _p, _e, _t in cases:
            ticks += cp.run(world.copy(), goal).ticks
        episodes += len(cases)
    elapsed = time.perf_counter() - t0
    eps, tps = episodes / elapsed, ticks / elapsed
    print(f"baseline simulate() episodes_per_s={base_eps:.1f}")
    print(f"compiled+reset ratio_vs_baseline={eps / base_eps:.2f}")
    print(f"episodes_per_s={eps:.1f} ticks_per_s={tps:.1f}")


if __name__ == "__main__":
    main()
