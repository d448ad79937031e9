"""Wall time of the same run on a Ray cluster of one node and of two (docs/cluster.md).

Starts a local Ray cluster on this machine (`runner.local_cluster`: one `ray start --block`
process per node, each with `--num-cpus=1` and its own temp folder and token; stopped by PID at
the end), and runs, each in a fresh folder:

1. the offline run (`--model offline`, the first `--limit` tasks, default generators) on a
   one-node cluster, then on a two-node cluster (`--executor ray --ray-address ...`);
2. on the two-node cluster, a replay-pack run (`--model replay:<pack>/llm_cache.sqlite` with the
   pack's tasks, generators and settings, docs/llm.md) whose metrics must equal the pack's;
3. with `--process`, the same offline run with the process executor and 2 workers, for reference.

Prints the load average before and after each run and the machine's 2-process capacity
(`run_scaling.capacity`: ~2.0 on an idle 2-core machine, ~1.0 when other work takes a core), one
line per run (wall time of the command, the run's own start-up and units phases from
results.json `timing.run_phases`), and last
`cluster_speedup_2_nodes=<x> units_speedup=<x> one_node_s=<s> two_nodes_s=<s> replay_two_nodes_s=<s>
replay_same=<b>` (the wall-time ratio of one node to two, and the same ratio of the units phase
alone, without the start-up of connecting, shipping and probing).
Both nodes share this machine's cores: on a shared machine the ratio understates what two
machines give; compare it with the capacity line. `--smoke` (or `--quick`): 2 tasks, no
replay (a smoke run).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from llm_validity import pack_protocol, same_metrics  # noqa: E402
from run_scaling import capacity  # noqa: E402

from logicenveval.runner.local_cluster import local_cluster  # noqa: E402

PACK = ROOT / "reports" / "real" / "SmolLM2-135M-Instruct.Q4_1"


def _load() -> str:
    return "load {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def _run(args: list[str], env: dict[str, str] | None, output: Path, label: str) -> tuple[float, dict[str, Any]]:
    """One `run` command; its wall time and results.json."""
    full = {**os.environ, "PYTHONPATH": str(ROOT), **(env or {})}
    before = _load()
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "logicenveval", "run", *args, "--quiet",
                           "--output", str(output), "--run-id", "r"], env=full, cwd=ROOT,
                          capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    if proc.returncode not in (0, 1):
        raise SystemExit(f"{label} failed ({proc.returncode}):\n{proc.stderr[-3000:]}")
    results = json.loads((output / "r" / "results.json").read_text())
    phases = results["timing"]["run_phases"]
    print(f"{label:<28} wall {wall:7.1f} s  start-up {phases.get('start-up', 0):5.1f} s  "
          f"units {phases.get('units', 0):6.1f} s  ({before} -> {_load()})", flush=True)
    return wall, results


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--limit", type=int, default=10, help="tasks of the offline run (default 10)")
    parser.add_argument("--quick", "--smoke", action="store_true",
                        help="2 tasks, no replay run (a smoke run)")
    parser.add_argument("--process", action="store_true",
                        help="also the process executor with 2 workers, for reference")
    args = parser.parse_args()
    limit = 2 if args.quick else args.limit
    offline = ["--model", "offline", "--limit", str(limit)]
    print(f"{_load()}; 2-process capacity {capacity():.2f}", flush=True)
    with tempfile.TemporaryDirectory(prefix="cluster-scaling-") as tmp:
        out = Path(tmp)
        if args.process:
            _run([*offline, "--workers", "2"], None, out / "process", "process executor, 2 workers")
        with local_cluster((1,), log_dir=out) as one:
            one_s, one_res = _run([*offline, "--executor", "ray", "--ray-address", one.address],
                                  one.env, out / "one", f"ray, 1 node ({limit} tasks)")
        replay_s, replay_same = float("nan"), None
        with local_cluster((1, 1), log_dir=out) as two:
            two_s, two_res = _run([*offline, "--executor", "ray", "--ray-address", two.address],
                                  two.env, out / "two", f"ray, 2 nodes ({limit} tasks)")
            if not args.quick:
                config = json.loads((PACK / "config.json").read_text())
                replay = ["--model", f"replay:{PACK / 'llm_cache.sqlite'}",
                          "--model-args", f"protocol={pack_protocol(config)}",
                          "--generators", ",".join(config["generators"]),
                          "--tasks", ",".join(config["tasks"]), "--brief", config["brief"],
                          "--layout-solver", config["layout_solver"],
                          "--executor", "ray", "--ray-address", two.address]
                replay_s, replayed = _run(replay, two.env, out / "replay",
                                          f"ray, 2 nodes, replay {PACK.name[:12]}")
                recorded = json.loads((PACK / "results.json").read_text())
                replay_same = same_metrics(recorded, replayed)
        same = same_metrics(one_res, two_res)
    print(f"one-node and two-node figures equal: {same}")
    units = [r["timing"]["run_phases"].get("units", float("nan")) for r in (one_res, two_res)]
    print(f"cluster_speedup_2_nodes={one_s / two_s:.2f} units_speedup={units[0] / units[1]:.2f} "
          f"one_node_s={one_s:.1f} two_nodes_s={two_s:.1f} replay_two_nodes_s={replay_s:.1f} "
          f"replay_same={replay_same}")
    return 0 if same and replay_same is not False else 1


if __name__ == "__main__":
    raise SystemExit(main())
