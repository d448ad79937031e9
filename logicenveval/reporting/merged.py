"""One leaderboard across runs (`report RUN_DIR RUN_DIR ... --out DIR`).

Runs of different models, generators or seeds are merged row by row with Run, Model and Seeds
columns; rows are only comparable on the same tasks of the same benchmark version, so mixed task
sets are refused with the runs that differ. Every run keeps its drill-down: its per-task pages
are written under `DIR/details/run<k>/` and its renders and environment files copied under
`DIR/files/run<k>/`, so the merged folder stands alone.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import ConfigError
from logicenveval.reporting.charts import charts_of
from logicenveval.reporting.details import sources
from logicenveval.reporting.leaderboard import (
    Collected,
    TableRow,
    group_rows,
    header_rows,
    jinja,
    remove_stale,
    table_rows,
    write_details,
)
from logicenveval.reporting.tables import LEGEND, headers, md_escape, row_cells, row_label
from logicenveval.reporting.why import GeneratorReasons, Where, reasons

LEAD = ["Run", "Model", "Seeds"]


def _seeds(results: dict[str, Any]) -> str:
    seeds = results.get("seeds")
    return ",".join(str(s) for s in seeds) if seeds else str(results.get("seed", "–"))


def run_labels(runs: Sequence[tuple[Path, dict[str, Any]]]) -> list[str]:
    """A short, distinct name per run: its run id (folder name), numbered where two coincide."""
    names = [str(r.get("run_id") or d.name) for d, r in runs]
    return [f"{n} ({i + 1})" if names.count(n) > 1 else n for i, n in enumerate(names)]


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
    for label, (_, r) in zip(run_labels(runs), runs, strict=True):
        for gen, values in r["results"].items():
            out.append([label, str(r.get("model", "?")), _seeds(r), row_label(gen, values, r)]
                       + [c.text for c in row_cells(r, gen)])
    return out


def merged_markdown(runs: Sequence[tuple[Path, dict[str, Any]]]) -> str:
    tasks = runs[0][1].get("tasks", [])
    header = LEAD + headers()
    lines = ["# LogicEnvEval leaderboard — merged runs", "",
             f"{len(runs)} run(s) · {len(tasks)} tasks: "
             + ", ".join(f"`{md_escape(str(d))}`" for d, _ in runs), "",
             "| " + " | ".join(header) + " |",
             "|" + "|".join(["---"] * (len(LEAD) + 1) + ["---:"] * (len(header) - len(LEAD) - 1)) + "|"]
    lines += ["| " + " | ".join(md_escape(c) for c in r) + " |" for r in merged_rows(runs)]
    lines += ["", LEGEND + " [lo, hi] = the 95 % bootstrap interval over tasks (and seeds for "
              "multi-seed runs); n/a with fewer than 2 tasks.", ""]
    return "\n".join(lines)


def write_merged(run_dirs: Sequence[Path], out: Path) -> list[tuple[Path, dict[str, Any]]]:
    """The merged `leaderboard.md`, `leaderboard.html` (+ `details/`) and `runs.json` in `out`."""
    from logicenveval.runner.results import load_results

    runs = [(d, load_results(d)) for d in run_dirs]
    check_same_tasks(runs)
    env = jinja()
    labels = run_labels(runs)
    table: list[TableRow] = []
    groups: list[dict[str, Any]] = []
    why: list[tuple[str, GeneratorReasons, dict[Where, str]]] = []
    charted: list[tuple[str, dict[str, Any]]] = []  # (run · method, values): the charts' bars
    written: set[Path] = set()
    for k, (label, (run_dir, results)) in enumerate(zip(labels, runs, strict=True)):
        scope = f"run{k}"
        srcs = sources(run_dir, results, prefix=f"{scope}/")
        got: Collected = write_details(out, srcs, list(results["results"]), env)
        written |= got.written
        lead = [label, str(results.get("model", "?")), _seeds(results)]
        run_why = reasons(got.samples, results.get("failures", {}), messages=got.messages,
                          scores=results["results"])
        table += table_rows(results, lead, scope, run_why)
        charted += [(f"{label} · {row_label(gen, values, results)}", values)
                    for gen, values in results["results"].items()]
        groups += [{**grp, "run": label} for grp in group_rows(got.rows, scope)]
        why += [(label, g, got.hrefs) for g in run_why]
    remove_stale(out / "details", written)
    for kind in ("*.svg", "*.json"):  # only what a report copies there (renders, environments)
        remove_stale(out / "files", written, kind)
    top, sub = header_rows([*LEAD, "Method"])
    html = env.get_template("merged.html.j2").render(
        top=top, sub=sub, rows=table, runs=[(label, str(d)) for label, (d, _) in zip(labels, runs, strict=True)],
        n_tasks=len(runs[0][1].get("tasks", [])), legend=LEGEND, groups=groups, why=why,
        seeded=any(r.get("runs") for _, r in runs), charts=charts_of(charted))
    atomic_write_text(out / "leaderboard.md", merged_markdown(runs))
    atomic_write_text(out / "leaderboard.html", html)
    atomic_write_text(out / "runs.json", json.dumps([str(d) for d, _ in runs], indent=2) + "\n")
    return runs
