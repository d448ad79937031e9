"""`run --seeds 0,1,2`: one complete run per seed, then one results.json over all of them.

Each seed is an ordinary run in `<parent>/seed<S>/` (its own units, resumable on its own), so a
multi-seed run killed midway keeps every finished unit of every seed. The parent's results.json
has the usual `results.<generator>` keys computed over every (task, seed) cell exactly as a
single run computes them over tasks, `per_task_seed.<generator>.<task>.<seed>` instead of
`per_task`, and intervals from a two-level bootstrap (tasks, then seeds; metrics.uncertainty).
"""

from __future__ import annotations

import hashlib
import json
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rich.console import Console

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import ConfigError
from logicenveval.metrics.compute import null_metrics
from logicenveval.metrics.records import UnitRecord
from logicenveval.metrics.uncertainty import ci95, point_metrics
from logicenveval.runner.config import RunConfig
from logicenveval.runner.placement import Placement, place
from logicenveval.runner.results import RESULTS_SCHEMA, row_status
from logicenveval.runner.run import check_tasks, current_inputs, resolve_generators, run
from logicenveval.runner.store import RunStore, new_folders, remove_created


@dataclass(frozen=True)
class SeedsOutcome:
    run_dir: Path
    results: dict[str, Any]
    seed_dirs: list[Path]
    computed: int
    reused: int
    records: tuple[UnitRecord, ...] = ()  # every unit of every seed, seed by seed
    #: why stored units were recomputed -> how many (summed over the seeds; `RunOutcome.stale`)
    stale: dict[str, int] = field(default_factory=dict)
    #: which finished run of other inputs was kept, and where this run went (`RunOutcome.note`)
    note: str = ""


def seeds_identity(config: RunConfig, seeds: Sequence[int]) -> dict[str, object]:
    identity = {k: v for k, v in config.identity().items() if k != "seed"}
    return {**identity, "seeds": list(seeds)}


def seeds_run_dir(config: RunConfig, seeds: Sequence[int]) -> Path:
    if config.run_id:
        return Path(config.output) / config.run_id
    blob = json.dumps(seeds_identity(config, seeds), sort_keys=True).encode()
    slug = re.sub(r"[^A-Za-z0-9]+", "-", config.model).strip("-").lower()[:40] or "model"
    tag = "-".join(str(s) for s in seeds)
    if len(tag) > 40:  # a long list would make the folder name too long: the hash tells it apart
        tag = f"{seeds[0]}-to-{seeds[-1]}-n{len(seeds)}"
    return Path(config.output) / f"{slug}-seeds{tag}-{hashlib.sha256(blob).hexdigest()[:8]}"


def run_seeds(config: RunConfig, seeds: Sequence[int], *, console: Console | None = None,
              show_progress: bool = True) -> SeedsOutcome:
    if not seeds or len(set(seeds)) != len(seeds):
        raise ConfigError(f"--seeds needs distinct seeds, got {list(seeds)}", field="--seeds",
                          hint="e.g. --seeds 0,1,2")
    # a finished multi-seed run of other inputs is kept, as a single run is (runner.placement)
    inputs = current_inputs(config, resolve_generators(config), check_tasks(config))
    placement = place(seeds_run_dir(config, seeds), inputs, named=config.run_id is not None,
                      replace=config.replace)
    parent = placement.run_dir
    created = new_folders(parent)
    store = RunStore(parent)
    store.claim(seeds_identity(config, seeds))  # the parent folder is this run's until it ends
    try:
        return _run_seeds(config, seeds, placement, inputs, console, show_progress)
    except BaseException:
        if created:  # refused before any seed ran (exit 2): no empty run folder is left
            store.unlock()
            store.discard_if_unused()
            remove_created(created[1:])
        raise
    finally:
        store.unlock()


def _run_seeds(config: RunConfig, seeds: Sequence[int], placement: Placement,
               inputs: dict[str, Any], console: Console | None,
               show_progress: bool) -> SeedsOutcome:
    parent = placement.run_dir
    per_seed = []
    records: list[UnitRecord] = []
    computed = reused = 0
    stale: dict[str, int] = {}
    for seed in seeds:
        # the parent was placed: its seed runs resume or replace in place, and copy the
        # unchanged units of the kept finished run's seed runs
        one = config.model_copy(update={"seed": seed, "output": str(parent), "run_id": f"seed{seed}",
                                        "replace": True})
        earlier = placement.previous / f"seed{seed}" if placement.previous is not None else None
        outcome = run(one, console=console, show_progress=show_progress, previous=earlier)
        per_seed.append(outcome.results)
        records.extend(outcome.records)
        computed += outcome.computed
        reused += outcome.reused
        for why, n in outcome.stale.items():
            stale[why] = stale.get(why, 0) + n
    results = combine_seeds(parent.name, seeds_identity(config, seeds), per_seed)
    results["inputs"] = inputs
    atomic_write_text(parent / "results.json", json.dumps(results, indent=2, sort_keys=True) + "\n")
    return SeedsOutcome(run_dir=parent, results=results,
                        seed_dirs=[parent / f"seed{s}" for s in seeds], computed=computed,
                        reused=reused, records=tuple(records), stale=stale, note=placement.note())


def combine_seeds(run_id: str, identity: dict[str, object],
                  per_seed: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """One results dict over several single-seed results of the same generators and tasks."""
    first = per_seed[0]
    seeds = [int(r["seed"]) for r in per_seed]
    for r in per_seed[1:]:
        if r["tasks"] != first["tasks"] or list(r["results"]) != list(first["results"]):
            raise ConfigError("seed runs differ in tasks or generators", field="--seeds",
                              hint="combine runs of one configuration")
    results: dict[str, Any] = {}
    per_task_seed: dict[str, Any] = {}
    failures: dict[str, list[dict[str, Any]]] = {}
    for gen in first["results"]:
        # a task not measured in some seed (infrastructure failure) is left out for every seed:
        # the two-level bootstrap needs the same seeds for every task
        missing = sorted({t for r in per_seed for t in first["tasks"] if t not in r["per_task"][gen]})
        per_task_seed[gen] = {t: {str(r["seed"]): r["per_task"][gen][t] for r in per_seed}
                              for t in first["tasks"] if t not in missing}
        cells = {(t, int(s)): m for t, by in per_task_seed[gen].items() for s, m in by.items()}
        if cells:
            results[gen] = point_metrics(list(cells.values()))
            results[gen]["ci95"] = ci95(cells)
        else:
            results[gen] = {**null_metrics(), "ci95": {}}
        results[gen].update(row_status(
            measured=bool(cells), not_measured=missing,
            budget_hit=sorted({t for t, by in per_task_seed[gen].items()
                               if any(m.get("budget_hit") for m in by.values())})))
        failures[gen] = [{**f, "seed": r["seed"]} for r in per_seed for f in r["failures"].get(gen, [])]
    return {
        "schema": RESULTS_SCHEMA,
        "run_id": run_id,
        "config": identity,
        "model": first["model"],
        "seed": None,
        "seeds": seeds,
        "brief": first.get("brief", "roles"),
        **({"protocol": first["protocol"]} if "protocol" in first else {}),
        "runs": {str(r["seed"]): f"seed{r['seed']}" for r in per_seed},
        "generators": list(results),
        "tasks": first["tasks"],
        "benchmark": first.get("benchmark", {}),
        "versions": first["versions"],
        "git_commit": first["git_commit"],
        "results": results,
        "per_task_seed": per_task_seed,
        "failures": failures,
        "timing": {"per_seed": {str(r["seed"]): r["timing"] for r in per_seed}},
    }
