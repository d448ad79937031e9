"""`leaderboard.md` and a static, self-contained `leaderboard.html` for a run folder.

The HTML drill-down shows, per generator and task, every environment's top-down render, the GT
decision paths it covers, its physics failures and each BT's verdict with the tick trace. All of
it was recorded by the units when they evaluated the environments (`UnitRecord.details`), so a
report only reads: no physics check, no simulation, no solving. A render file that is missing
(renders are not fsynced) is re-drawn from the stored environment and stored physics failures.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from jinja2 import Environment, PackageLoader, select_autoescape

from logicenveval.atomic import atomic_write_text
from logicenveval.metrics.records import EnvDetail, UnitRecord
from logicenveval.model.task import POLICY_KINDS
from logicenveval.reporting.tables import COLUMNS, LEGEND, markdown, method_label, rows
from logicenveval.runner.store import RunStore

_NOT_RECORDED = "no trace recorded (the unit was written by a version that did not store traces)"


def _samples(run_dir: Path) -> list[dict[str, Any]]:
    from logicenveval.errors import RunStoreError
    from logicenveval.limits import read_text

    path = run_dir / "samples.jsonl"
    if not path.exists():
        return []
    text = read_text(path, what="samples.jsonl", error=RunStoreError, max_bytes="max_run_file_bytes",
                     hint="re-run the command to rewrite it")
    out = []
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            sample = json.loads(line)
        except (ValueError, RecursionError):
            sample = None
        if not isinstance(sample, dict) or not {"generator", "task_id", "env_id"} <= set(sample):
            raise RunStoreError("not a complete sample (truncated or edited file)", file=str(path),
                                line=n, hint="re-run the same `run` command: it rewrites samples.jsonl "
                                "from the committed units")
        out.append(sample)
    return out


def _redraw(run_dir: Path, gen: str, task_id: str, sample: dict[str, Any], rel: str) -> str | None:
    """Draw a missing render from the stored environment and its stored physics failures."""
    from logicenveval.envfiles import load_env
    from logicenveval.errors import LogicEnvEvalError
    from logicenveval.physics.render import render_svg
    from logicenveval.physics.report import DimensionReport, PhysicsFailure, PhysicsReport

    env_path = run_dir / "envs" / gen / task_id / f"{sample['env_id']}.json"
    if not env_path.exists():
        return None
    try:
        env = load_env(env_path)
    except LogicEnvEvalError:
        return None
    physics = sample["physics"]
    failures = [PhysicsFailure.model_validate(f) for f in physics.get("failures", [])]
    extended = [PhysicsFailure.model_validate(f) for f in physics.get("extended_failures", [])]
    report = PhysicsReport(**{d: DimensionReport.of([f for f in failures if f.dimension == d])
                              for d in ("floor_plan", "entity", "relation")},
                           extended=DimensionReport.of(extended))
    atomic_write_text(run_dir / rel, render_svg(env, report), durable=False)
    return rel


def _entry(run_dir: Path, gen: str, task_id: str, sample: dict[str, Any],
           detail: EnvDetail | None) -> dict[str, Any]:
    rel = detail.render if detail is not None and detail.render else \
        (Path("renders") / gen / task_id / f"{sample['env_id']}.svg").as_posix()
    render = rel if (run_dir / rel).exists() else _redraw(run_dir, gen, task_id, sample, rel)
    if detail is not None:  # in policy-kind order (unit files store keys sorted)
        order = {k: i for i, k in enumerate(POLICY_KINDS)}
        kinds = sorted(detail.traces, key=lambda k: (order.get(k, len(order)), k))
        traces = {k: detail.traces[k].model_dump(mode="json") for k in kinds}
    else:
        traces = {k: {"status": v, "message": _NOT_RECORDED, "trace": []}
                  for k, v in sample.get("verdicts", {}).items()}
    return {"sample": sample, "render": render, "traces": traces}


def _drilldown(run_dir: Path, results: dict[str, Any],
               records: Sequence[UnitRecord] | None) -> list[dict[str, Any]]:
    """Per generator and task, the stored environments with their recorded details."""
    units: dict[tuple[str, str], UnitRecord] = {(r.generator, r.task_id): r for r in records or ()}
    store = RunStore(run_dir)
    loose: dict[tuple[str, str], list[dict[str, Any]]] | None = None
    out: list[dict[str, Any]] = []
    for gen in results["results"]:
        gen_block: dict[str, Any] = {"name": gen, "tasks": []}
        for task_id in results.get("tasks", []):
            unit = units.get((gen, task_id)) or store.load(gen, task_id)
            envs = []
            if unit is not None:
                by_id = {d.env_id: d for d in unit.details}
                for s in unit.samples:
                    envs.append(_entry(run_dir, gen, task_id, s.model_dump(mode="json"),
                                       by_id.get(s.env_id)))
            else:  # a folder without units (e.g. a published reference run): samples only
                if loose is None:
                    loose = {}
                    for x in _samples(run_dir):
                        loose.setdefault((x["generator"], x["task_id"]), []).append(x)
                envs = [_entry(run_dir, gen, task_id, x, None) for x in loose.get((gen, task_id), [])]
            per_task = results.get("per_task", {}).get(gen, {}).get(task_id, {})
            gen_block["tasks"].append({"id": task_id, "metrics": per_task, "envs": envs})
        out.append(gen_block)
    return out


def render_html(run_dir: Path, results: dict[str, Any],
                records: Sequence[UnitRecord] | None = None) -> str:
    env = Environment(loader=PackageLoader("logicenveval", "reporting/templates"),
                      autoescape=select_autoescape(["html", "j2"]))
    template = env.get_template("leaderboard.html.j2")
    return template.render(
        results=results,
        headers=["Method"] + [h + (" (%)" if pct else "") for h, _, pct in COLUMNS],
        rows=rows(results),
        legend=LEGEND,
        generators=_drilldown(run_dir, results, records),
        label=lambda g: method_label(g, results.get("model", "")),
    )


def write_leaderboards(run_dir: Path, results: dict[str, Any],
                       records: Sequence[UnitRecord] | None = None) -> None:
    """Both leaderboards; `records` are the run's units when the caller holds them already
    (otherwise they are read from `units/`)."""
    atomic_write_text(run_dir / "leaderboard.md", markdown(results), durable=False)
    atomic_write_text(run_dir / "leaderboard.html", render_html(run_dir, results, records),
                      durable=False)
