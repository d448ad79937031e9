"""A run's figures as pandas DataFrames and CSV files: one row per environment, per (method, task)
and per method.

The leaderboards are for reading; an analysis (a plot, a regression, a spreadsheet) wants the
numbers in columns. These frames are read from what a run folder already holds — `results.json`
and `samples.jsonl` (each seed's folder of a multi-seed run, with a `seed` column) — so they work
on any finished run, committed ones included, and never recompute a figure:

    from logicenveval.reporting.frames import samples_frame, methods_frame
    samples_frame("reports/reference").groupby("generator")["well_formed"].mean()

Nested records are flattened into dotted column names (`physics.entity`, `verdicts.correct`,
`phypr.avg`), task-specific records (`JSON_CELLS`) kept as one JSON cell; a 95 % interval `[lo, hi]` becomes `<metric>.ci_lo` / `<metric>.ci_hi`; a list
becomes its length (`n_<name>`) and, for the short text lists a reader filters on
(`TEXT_LISTS`), its items joined with "; ". `python -m logicenveval export RUN_DIR --csv --out
DIR` writes the three frames as `samples.csv`, `tasks.csv` and `methods.csv`.
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from logicenveval.reporting.details import samples_file, sources
from logicenveval.runner.results import load_results

#: list fields kept as text ("; "-joined) besides their length: what a reader filters samples on
#: (other lists, e.g. the killed mutants' names, keep only their length: the unit files hold them)
TEXT_LISTS = frozenset({"covered_paths", "problems", "violations", "failures", "extended_failures",
                        "realised_trajectories",
                        "not_measured_tasks", "budget_hit_tasks"})
#: task-specific records (a column per task variable would make the frame mostly empty): one cell
#: of compact JSON each
JSON_CELLS = frozenset({"claimed_trajectory", "categories", "unknown_categories"})
#: the CSV files `write_csv` writes, and the frame each holds
CSV_FILES = ("samples.csv", "tasks.csv", "methods.csv")


def _flat(record: Mapping[str, Any], prefix: str = "") -> Iterator[tuple[str, Any]]:
    """(column, scalar) pairs of a JSON record: dicts dotted, lists counted (and joined when text)."""
    for key, value in record.items():
        name = f"{prefix}{key}"
        if key in JSON_CELLS:
            yield name, json.dumps(value, sort_keys=True, separators=(",", ":"))
        elif isinstance(value, Mapping):
            if key == "ci95":
                yield from _intervals(value, prefix)
            else:
                yield from _flat(value, f"{name}.")
        elif isinstance(value, list):
            yield f"{prefix}n_{key}", len(value)
            if key in TEXT_LISTS:
                yield name, "; ".join(_text(v) for v in value)
        else:
            yield name, value


def _intervals(ci: Mapping[str, Any], prefix: str) -> Iterator[tuple[str, Any]]:
    """`ci95` blocks ({metric: [lo, hi]} or {metric: {part: [lo, hi]}}) as `<metric>.ci_lo/hi`."""
    for key, value in ci.items():
        if isinstance(value, Mapping):
            yield from _intervals(value, f"{prefix}{key}.")
        else:
            lo, hi = value if isinstance(value, list) and len(value) == 2 else (None, None)
            yield f"{prefix}{key}.ci_lo", lo
            yield f"{prefix}{key}.ci_hi", hi


def _text(value: Any) -> str:
    """A list item as text: a failure record by its message, anything else as itself."""
    if isinstance(value, Mapping):
        return str(value.get("message", value))
    return str(value)


def _runs(run_dir: Path) -> list[tuple[str, Path, dict[str, Any]]]:
    """(seed, folder, results) of a run, or of each seed of a multi-seed run ('' for one run)."""
    results = load_results(run_dir)
    return [(s.seed, s.run_dir, s.results) for s in sources(run_dir, results)]


def _frame(rows: list[dict[str, Any]], first: list[str]) -> pd.DataFrame:
    frame = pd.DataFrame(rows)
    if frame.empty:
        return pd.DataFrame(columns=first)
    lead = [c for c in first if c in frame.columns]
    order = [c for c in frame.columns if c not in lead and not c.endswith((".ci_lo", ".ci_hi"))]
    for c in [c for c in frame.columns if c.endswith(".ci_lo")]:  # each interval after its metric
        base, pair = c[:-len(".ci_lo")], [c, c[:-2] + "hi"]
        at = order.index(base) + 1 if base in order else len(order)
        order[at:at] = [p for p in pair if p in frame.columns]
    return frame[lead + order]


def samples_frame(run_dir: str | Path) -> pd.DataFrame:
    """One row per generated environment (`samples.jsonl`): generator, task_id, env_id, whether it
    is well formed, its physics verdicts, each BT's verdict, ticks and ms, what it covers."""
    rows = []
    seeded = False
    for seed, folder, results in _runs(Path(run_dir)):
        seeded = seeded or bool(seed)
        order = {g: k for k, g in enumerate(results["results"])}
        grouped = samples_file(folder)
        for key in sorted(grouped, key=lambda k: (order.get(k[0], len(order)), k[0], k[1])):
            for sample in grouped[key]:
                row = {"seed": seed} if seed else {}
                row.update(_flat(sample))
                rows.append(row)
    return _frame(rows, ["seed", "generator", "task_id", "env_id", "well_formed"] if seeded
                  else ["generator", "task_id", "env_id", "well_formed"])


def tasks_frame(run_dir: str | Path) -> pd.DataFrame:
    """One row per (method, task) (`results.json` `per_task`): the task's metrics for that method."""
    rows = []
    seeded = False
    for seed, _folder, results in _runs(Path(run_dir)):
        seeded = seeded or bool(seed)
        for gen, per_task in (results.get("per_task") or {}).items():
            for task_id, entry in per_task.items():
                row = {"seed": seed} if seed else {}
                row.update({"generator": gen, "task_id": task_id})
                row.update(_flat(entry) if isinstance(entry, Mapping) else {})
                rows.append(row)
    return _frame(rows, ["seed", "generator", "task_id"] if seeded else ["generator", "task_id"])


def methods_frame(run_dir: str | Path) -> pd.DataFrame:
    """One row per method (`results.json` `results`): every headline metric with its 95 % interval
    (`<metric>.ci_lo`, `<metric>.ci_hi`), environments built, attempted and failed. A multi-seed
    run gives its pooled rows (intervals over tasks and seeds), as its leaderboard does."""
    results = load_results(Path(run_dir))
    rows = []
    for gen, values in results["results"].items():
        row: dict[str, Any] = {"generator": gen, "model": results.get("model"), "brief": results.get("brief")}
        row.update(_flat(values) if isinstance(values, Mapping) else {})
        rows.append(row)
    return _frame(rows, ["generator", "model", "brief"])


def write_csv(run_dir: str | Path, out: str | Path) -> list[Path]:
    """`samples.csv`, `tasks.csv` and `methods.csv` of a run in the folder `out` (created)."""
    from logicenveval.atomic import atomic_write_text

    frames = (samples_frame(run_dir), tasks_frame(run_dir), methods_frame(run_dir))  # read all first
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for name, frame in zip(CSV_FILES, frames, strict=True):
        path = folder / name
        atomic_write_text(path, frame.to_csv(index=False))
        written.append(path)
    return written


__all__ = ["CSV_FILES", "methods_frame", "samples_frame", "tasks_frame", "write_csv"]
