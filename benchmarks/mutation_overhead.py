"""Cost of mutation scoring (`faudr_mut`) against the run's own policy simulation.

Reads the environments of a finished offline run (`--run DIR`, default: run the offline pipeline
on `--tasks` into a temporary folder first) and times, in this process and on one core:

- `policies_s`: the four shipped BTs with `simulate()` on every environment, as the runner does;
- `mutants_cold_s`: every killable mutant on every valid environment, trees built on first use
  (what a fresh worker pays: anchors spliced into the correct BT's tree);
- `mutants_warm_s`: the same again with the trees built (a worker that already scored the task).

Classification (which mutants are killable) is cached per task and not timed here.
Last line: `mutants_cold_ratio=<x> mutants_warm_ratio=<y>` (ratios to `policies_s`; each pass
starts with an empty per-symbolic-world memo, as a fresh worker does) and `in_run_ratio=<z>`: the run's own recorded `sim_ms` of the mutants
against its four BTs (compiled policies, with the memo) — the stricter baseline.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

from logicenveval.benchmark import load_task, policy_path
from logicenveval.cli import main as cli_main
from logicenveval.domain.catalog import load_catalog
from logicenveval.envfiles import load_env
from logicenveval.faults.score import MutationScorer, clear_cache, scorer_for
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import Task
from logicenveval.sim.loader import load_policy
from logicenveval.sim.policy import Policy
from logicenveval.sim.simulator import simulate


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--run", default=None, help="a run folder (with samples.jsonl and envs/)")
    ap.add_argument("--tasks", default="clean_living_room,hallway_coat_and_bag,kitchen_dish_cleanup,"
                    "lamp_or_pillow_fetch,multi_room_pet_care")
    ap.add_argument("--smoke", action="store_true", help="seconds, not minutes: a small case of the same code path (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = ap.parse_args()
    if args.smoke:
        args.tasks = "lamp_or_pillow_fetch"
    if args.run is None:
        out = Path(tempfile.mkdtemp(prefix="mutation_overhead_"))
        cli_main(["run", "--model", "offline", "--tasks", args.tasks, "--executor", "inprocess",
                  "--output", str(out), "--quiet", "--no-cache",
                  *(["--generators", "logicenvgen"] if args.smoke else [])])
        run = next(p for p in out.iterdir() if p.is_dir())
        clear_cache()  # time a cold worker, not the trees the run just built
    else:
        run = Path(args.run)
    catalog = load_catalog()
    valid: dict[tuple[str, str, str], bool] = {}
    for line in (run / "samples.jsonl").read_text().splitlines():
        s = json.loads(line)
        valid[(s["generator"], s["task_id"], s["env_id"])] = (
            s["well_formed"] and s["verdicts"].get("correct") == "passed")
    jobs: list[tuple[Task, EnvSpec, list[Policy], MutationScorer, bool]] = []
    scorers: dict[str, MutationScorer] = {}
    unit_policies: dict[tuple[str, str], list[Policy]] = {}  # loaded once per unit, as the runner does
    for gen, task_id, env_id in valid:
        task = load_task(task_id)
        if task_id not in scorers:
            scorers[task_id] = scorer_for(task, None, catalog, cache_dir=run / "work" / "mutants")
        policies = unit_policies.setdefault(
            (gen, task_id), [load_policy(policy_path(task, k)) for k in task.policies])
        env = load_env(run / "envs" / gen / task_id / f"{env_id}.json")
        jobs.append((task, env, policies, scorers[task_id], valid[(gen, task_id, env_id)]))
    t0 = time.perf_counter()
    for task, env, policies, _, _ in jobs:
        for p in policies:
            simulate(p, env, task, catalog)
    policies_s = time.perf_counter() - t0
    timings = []
    for _ in range(2):
        for scorer in scorers.values():
            scorer.forget_killed()  # time the simulation, not the memo of the first pass
        t0 = time.perf_counter()
        killed = 0
        for task, env, _, scorer, ok in jobs:
            if ok:
                killed += len(scorer.killed(env, task, catalog))
        timings.append(time.perf_counter() - t0)
    n_valid = sum(ok for *_, ok in jobs)
    n_mut = sum(len(s.killable) for s in scorers.values())
    print(f"run={run} envs={len(jobs)} valid={n_valid} tasks={len(scorers)} killable_mutants={n_mut} "
          f"kills={killed}")
    print(f"policies_s={policies_s:.3f} mutants_cold_s={timings[0]:.3f} mutants_warm_s={timings[1]:.3f}")
    in_run: dict[str, float] = {}
    for line in (run / "samples.jsonl").read_text().splitlines():
        for kind, ms in json.loads(line).get("sim_ms", {}).items():
            in_run[kind] = in_run.get(kind, 0.0) + ms
    bts = sum(v for k, v in in_run.items() if k != "mutants")
    print(f"in-run sim_ms: mutants {in_run.get('mutants', 0.0) / 1000:.3f} s vs the BTs {bts / 1000:.3f} s "
          "(compiled policies, memoised per symbolic world, as the runner does)")
    print(f"mutants_cold_ratio={timings[0] / policies_s:.2f} mutants_warm_ratio={timings[1] / policies_s:.2f} "
          f"in_run_ratio={in_run.get('mutants', 0.0) / bts if bts else float('nan'):.2f}")


if __name__ == "__main__":
    main()
