"""`leaderboard.md` and a static, self-contained `leaderboard.html` for a run folder.

The HTML drill-down shows, per generator and task, every environment's top-down render, the GT
decision paths it covers, its physics failures and each BT's verdict with the tick trace (traces
are recomputed from the stored EnvSpecs, so they never bloat `samples.jsonl`).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from jinja2 import Environment, PackageLoader, select_autoescape

from logicenveval.reporting.tables import COLUMNS, LEGEND, markdown, method_label, rows
from logicenveval.runner.store import atomic_write_text


def _samples(run_dir: Path) -> list[dict[str, Any]]:
    path = run_dir / "samples.jsonl"
    if not path.exists():
        return []
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]


def _drilldown(run_dir: Path, results: dict[str, Any], tasks_dir: str | None) -> list[dict[str, Any]]:
    from logicenveval.benchmark import load_task, policy_path
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.domain.roles import bind_roles
    from logicenveval.envfiles import load_env
    from logicenveval.errors import LogicEnvEvalError
    from logicenveval.model.task import POLICY_KINDS
    from logicenveval.physics import check_env
    from logicenveval.physics.render import render_svg
    from logicenveval.sim.loader import load_policy
    from logicenveval.sim.simulator import simulate

    catalog = load_catalog()
    samples = _samples(run_dir)
    out: list[dict[str, Any]] = []
    for gen in results["results"]:
        gen_block: dict[str, Any] = {"name": gen, "tasks": []}
        for task_id in results.get("tasks", []):
            try:
                task = load_task(task_id, tasks_dir)
                policies = {k: load_policy(policy_path(task, k, tasks_dir)) for k in POLICY_KINDS}
            except LogicEnvEvalError:
                continue
            envs = []
            for s in (x for x in samples if x["generator"] == gen and x["task_id"] == task_id):
                env_path = run_dir / "envs" / gen / task_id / f"{s['env_id']}.json"
                entry: dict[str, Any] = {"sample": s, "render": None, "traces": {}}
                if env_path.exists():
                    env = load_env(env_path)
                    env = bind_roles(env, task.roles, catalog).apply(env)  # as it was judged
                    svg = render_svg(env, check_env(env, catalog))
                    rel = Path("renders") / gen / task_id / f"{s['env_id']}.svg"
                    atomic_write_text(run_dir / rel, svg)
                    entry["render"] = rel.as_posix()
                    for kind, policy in policies.items():
                        verdict = simulate(policy, env, task, catalog, trace=True)
                        entry["traces"][kind] = {"status": verdict.status, "message": verdict.message,
                                                 "trace": [str(t) for t in verdict.trace]}
                envs.append(entry)
            per_task = results.get("per_task", {}).get(gen, {}).get(task_id, {})
            gen_block["tasks"].append({"id": task_id, "metrics": per_task, "envs": envs})
        out.append(gen_block)
    return out


def render_html(run_dir: Path, results: dict[str, Any]) -> str:
    env = Environment(loader=PackageLoader("logicenveval", "reporting/templates"),
                      autoescape=select_autoescape(["html", "j2"]))
    template = env.get_template("leaderboard.html.j2")
    tasks_dir = results.get("config", {}).get("tasks_dir")
    return template.render(
        results=results,
        headers=["Method"] + [h + (" (%)" if pct else "") for h, _, pct in COLUMNS],
        rows=rows(results),
        legend=LEGEND,
        generators=_drilldown(run_dir, results, tasks_dir),
        label=lambda g: method_label(g, results.get("model", "")),
    )


def write_leaderboards(run_dir: Path, results: dict[str, Any]) -> None:
    atomic_write_text(run_dir / "leaderboard.md", markdown(results))
    atomic_write_text(run_dir / "leaderboard.html", render_html(run_dir, results))
