"""One leaderboard across runs (`report RUN_DIR RUN_DIR ... --out DIR`).

Runs of different models, generators or seeds are merged row by row with a Model and a Seeds
column; rows are only comparable on the same tasks of the same benchmark version, so mixed task
sets are refused with the runs that differ.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from jinja2 import Environment, PackageLoader, select_autoescape

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import ConfigError
from logicenveval.reporting.tables import COLUMNS, cell, row_label

HEADERS = ["Model", "Method", "Seeds"] + [h + (" (%)" if pct else "") for h, _, pct in COLUMNS]


def _seeds(results: dict[str, Any]) -> str:
    seeds = results.get("seeds")
    return ",".join(str(s) for s in seeds) if seeds else str(results.get("seed", "–"))


def check_same_tasks(runs: Sequence[tuple[Path, dict[str, Any]]]) -> None:
    """Refuse runs over different task sets or task versions, naming the first that differs."""
    first_dir, first = runs[0]
    tasks = set(first.get("tasks", []))
    hashes = first.get("benchmark", {}).get("task_sha256", {})
    for run_dir, r in runs[1:]:
        other = set(r.get("tasks", []))
        if other != tasks:
            raise ConfigError(
                f"{run_dir} covers other tasks than {first_dir} (only there: "
                f"{sorted(other - tasks)[:5]}, missing: {sorted(tasks - other)[:5]})",
                field="tasks", hint="merge runs made on the same tasks (--tasks/--limit)")
        theirs = r.get("benchmark", {}).get("task_sha256", {})
        changed = sorted(t for t in tasks if t in hashes and t in theirs and hashes[t] != theirs[t])
        if changed:
            raise ConfigError(f"{run_dir} used other versions of task(s) {changed[:5]} than {first_dir}",
                              field="benchmark", hint="merge runs made on the same benchmark version")


def merged_rows(runs: Sequence[tuple[Path, dict[str, Any]]]) -> list[list[str]]:
    out = []
    for _, r in runs:
        for gen, values in r["results"].items():
            out.append([str(r.get("model", "?")), row_label(gen, values, r), _seeds(r)]
                       + [cell(values, path, pct) for _, path, pct in COLUMNS])
    return out


def merged_markdown(runs: Sequence[tuple[Path, dict[str, Any]]]) -> str:
    tasks = runs[0][1].get("tasks", [])
    lines = ["# LogicEnvEval leaderboard — merged runs", "",
             f"{len(runs)} run(s) · {len(tasks)} tasks: " + ", ".join(f"`{d}`" for d, _ in runs), "",
             "| " + " | ".join(HEADERS) + " |",
             "|" + "|".join(["---"] * 3 + ["---:"] * (len(HEADERS) - 3)) + "|"]
    lines += ["| " + " | ".join(r) + " |" for r in merged_rows(runs)]
    lines += ["", "Rates in percent, ± half-width of the 95 % bootstrap interval over tasks (and "
              "seeds for multi-seed runs).", ""]
    return "\n".join(lines)


def write_merged(run_dirs: Sequence[Path], out: Path) -> list[tuple[Path, dict[str, Any]]]:
    from logicenveval.runner.results import load_results

    runs = [(d, load_results(d)) for d in run_dirs]
    check_same_tasks(runs)
    env = Environment(loader=PackageLoader("logicenveval", "reporting/templates"),
                      autoescape=select_autoescape(["html", "j2"]))
    html = env.get_template("merged.html.j2").render(
        headers=HEADERS, rows=merged_rows(runs), runs=[str(d) for d, _ in runs],
        n_tasks=len(runs[0][1].get("tasks", [])))
    atomic_write_text(out / "leaderboard.md", merged_markdown(runs))
    atomic_write_text(out / "leaderboard.html", html)
    atomic_write_text(out / "runs.json", json.dumps([str(d) for d, _ in runs], indent=2) + "\n")
    return runs
