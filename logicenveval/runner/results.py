"""Turning committed units into `results.json` and `samples.jsonl` (DESIGN.md §7, §9).

Everything but the `timing` block, `st_ms` and `sim_ms` is a pure function of the units, so the
same command gives byte-identical files apart from those timing fields.
"""

from __future__ import annotations

import hashlib
import importlib.metadata
import json
import platform
import subprocess
import zlib
from collections.abc import Sequence
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from logicenveval.atomic import atomic_write_text
from logicenveval.metrics.compute import aggregate, null_metrics, task_metrics
from logicenveval.metrics.records import UnitRecord
from logicenveval.metrics.uncertainty import ci95
from logicenveval.model.task import Task

RESULTS_SCHEMA = "logicenveval.results/1"
_VERSIONED = ("logicenveval", "numpy", "pydantic", "z3-solver", "py-trees", "trimesh",
              "python-fcl", "shapely", "ortools", "pandas")


def bootstrap_rng(seed: int, generator: str) -> np.random.Generator:
    """The bootstrap's own stream: fixed by the run seed and the row, whatever else ran."""
    return np.random.default_rng([seed, 95, zlib.crc32(generator.encode())])


def task_hashes(tasks: Sequence[Task]) -> dict[str, str]:
    """A digest per task (its full JSON): the benchmark version `compare` checks."""
    return {t.id: hashlib.sha256(json.dumps(t.model_dump(mode="json"), sort_keys=True).encode())
            .hexdigest()[:16] for t in tasks}


def package_versions() -> dict[str, str]:
    out = {"python": platform.python_version()}
    for name in _VERSIONED:
        try:
            out[name] = importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            out[name] = "not installed"
    return out


def git_commit() -> str | None:
    here = Path(__file__).resolve().parent
    try:
        proc = subprocess.run(["git", "rev-parse", "HEAD"], cwd=here, capture_output=True,
                              text=True, timeout=5, check=False)
    except (OSError, subprocess.SubprocessError):
        return None
    return proc.stdout.strip() or None if proc.returncode == 0 else None


class ResultsConfig(Protocol):
    """What results.json records of a run's configuration (`RunConfig`, `EvaluateConfig`)."""

    @property
    def model(self) -> str: ...
    @property
    def seed(self) -> int: ...
    @property
    def brief(self) -> str: ...
    @property
    def generators(self) -> tuple[str, ...]: ...
    def identity(self) -> dict[str, object]: ...
    def resolved_run_id(self) -> str: ...


def build_results(
    config: ResultsConfig,
    tasks: Sequence[Task],
    records: Sequence[UnitRecord],
    *,
    wall_seconds: float | None = None,
    generators: Sequence[str] | None = None,
) -> dict[str, Any]:
    """`generators` are the row names (plug-ins' `name` attributes); default: config.generators."""
    by_task = {t.id: t for t in tasks}
    results: dict[str, Any] = {}
    per_task: dict[str, Any] = {}
    failures: dict[str, list[dict[str, Any]]] = {}
    gen_seconds: dict[str, float] = {}
    llm: dict[str, dict[str, float]] = {}
    for gen in (config.generators if generators is None else generators):
        units = [r for r in records if r.generator == gen]
        measured = [u for u in units if u.measured]
        metrics = [task_metrics(by_task[u.task_id], u.samples, n_failed=u.n_failed,
                                mutants=u.mutants or None) for u in measured]
        per_task[gen] = {u.task_id: {**m.model_dump(mode="json"), "budget_hit": u.budget_hit is not None}
                         for u, m in zip(measured, metrics, strict=True)}
        if metrics:
            results[gen] = aggregate(metrics).model_dump(mode="json")
            results[gen]["ci95"] = ci95({(t, config.seed): m for t, m in per_task[gen].items()},
                                        bootstrap_rng(config.seed, gen))
        else:  # not measured: null figures, never zeros
            results[gen] = {**null_metrics(), "ci95": {}}
        results[gen].update(row_status(
            measured=bool(metrics), not_measured=[u.task_id for u in units if not u.measured],
            budget_hit=[u.task_id for u in measured if u.budget_hit is not None]))
        failures[gen] = [
            {"task": u.task_id, "stage": "unit", "message": u.error, "kind": u.error_kind}
            for u in units if u.error
        ] + [
            {"task": u.task_id, **f.model_dump(mode="json")} for u in units for f in u.failures
        ]
        gen_seconds[gen] = round(sum(u.gen_seconds for u in units), 3)
        llm[gen] = {k: round(sum(u.llm.get(k, 0.0) for u in units), 3)
                    for k in sorted({k for u in units for k in u.llm})}
    return {
        "schema": RESULTS_SCHEMA,
        "run_id": config.resolved_run_id(),
        "config": config.identity(),
        "model": config.model,
        "seed": config.seed,
        "brief": config.brief,
        "tasks": [t.id for t in tasks],
        "benchmark": {"task_sha256": task_hashes(tasks)},
        "versions": package_versions(),
        "git_commit": git_commit(),
        "results": results,
        "per_task": per_task,
        "failures": failures,
        "timing": {
            "wall_seconds": None if wall_seconds is None else round(wall_seconds, 3),
            "generation_seconds": gen_seconds,
            "llm": llm,
        },
    }


#: keys of `results.<generator>` that are not figures (checked apart from the numeric leaves)
STATUS_KEYS = ("measured", "not_measured_tasks", "budget_hit_tasks")


def row_status(*, measured: bool, not_measured: Sequence[str], budget_hit: Sequence[str]) -> dict[str, Any]:
    """What a row is besides its figures: measured at all (False: every unit failed for
    infrastructure reasons, so every figure is null), the tasks left out as not measured, and
    the tasks where a search stopped at its budget (the leaderboard labels such rows)."""
    return {"measured": measured, "not_measured_tasks": sorted(not_measured),
            "budget_hit_tasks": sorted(budget_hit)}


def write_outputs(run_dir: Path, results: dict[str, Any], records: Sequence[UnitRecord]) -> None:
    lines = [json.dumps(s.model_dump(mode="json"), sort_keys=True) for r in records for s in r.samples]
    atomic_write_text(run_dir / "samples.jsonl", "\n".join(lines) + ("\n" if lines else ""))
    atomic_write_text(run_dir / "results.json", json.dumps(results, indent=2, sort_keys=True) + "\n")


def load_results(run_dir: Path) -> dict[str, Any]:
    """A run's results.json, checked enough that reports and comparisons cannot trip on it."""
    from logicenveval.errors import RunStoreError
    from logicenveval.limits import parse_json, read_text

    path = run_dir / "results.json"
    text = read_text(path, what="results.json", error=RunStoreError, max_bytes="max_run_file_bytes",
                     hint="pass a run folder written by `python -m logicenveval run`")
    data = parse_json(text, file=str(path), error=RunStoreError)
    if not isinstance(data, dict) or data.get("schema") != RESULTS_SCHEMA or "results" not in data:
        raise RunStoreError("not a LogicEnvEval results file", file=str(path),
                            hint=f"expected an object with schema {RESULTS_SCHEMA}; re-run the command")
    _check_results(data, str(path))
    return data


def _check_results(data: dict[str, Any], file: str) -> None:
    from logicenveval.errors import RunStoreError

    def bad(field: str, what: str) -> RunStoreError:
        return RunStoreError(f"{what}", file=file, field=field,
                             hint="the file was edited or damaged; re-run the command to rewrite it")

    if not isinstance(data["results"], dict):
        raise bad("results", "must be an object of generators")
    tasks = data.get("tasks", [])
    if not isinstance(tasks, list) or not all(isinstance(t, str) for t in tasks):
        raise bad("tasks", "must be a list of task ids")
    for gen, values in data["results"].items():
        if not isinstance(values, dict):
            raise bad(f"results.{gen}", "must be an object of metrics")
        if not isinstance(values.get("measured", True), bool):
            raise bad(f"results.{gen}.measured", "must be true or false")
        for key in STATUS_KEYS[1:]:
            tasks_of = values.get(key, [])
            if not isinstance(tasks_of, list) or not all(isinstance(t, str) for t in tasks_of):
                raise bad(f"results.{gen}.{key}", "must be a list of task ids")
        figures = {k: v for k, v in values.items() if k not in STATUS_KEYS}
        stack: list[tuple[str, Any]] = [(f"results.{gen}", figures)]
        while stack:  # every leaf of the (nested) metrics is a number or null
            where, v = stack.pop()
            if isinstance(v, dict):
                stack += [(f"{where}.{k}", x) for k, x in v.items()]
            elif isinstance(v, list):  # intervals: [lo, hi]
                stack += [(f"{where}.{i}", x) for i, x in enumerate(v)]
            elif v is not None and (isinstance(v, bool) or not isinstance(v, int | float)):
                raise bad(where, f"metric value {str(v)[:40]!r} is not a number")
    for section in ("per_task", "failures"):
        if not isinstance(data.get(section, {}), dict):
            raise bad(section, "must be an object of generators")
