"""The leaderboard table in the layout of the paper's main table, as plain rows."""

from __future__ import annotations

from typing import Any

#: (header, path into results.<generator>, is a rate shown in percent)
COLUMNS: tuple[tuple[str, tuple[str, ...], bool], ...] = (
    ("PhyPR Floor", ("phypr", "floor_plan"), True),
    ("PhyPR Entity", ("phypr", "entity"), True),
    ("PhyPR Relation", ("phypr", "relation"), True),
    ("PhyPR Avg", ("phypr", "avg"), True),
    ("LogCov", ("logcov",), True),
    ("SceVR", ("scevr",), True),
    ("FauDR CF", ("faudr", "counterfactual"), True),
    ("FauDR Unreach", ("faudr", "unreachable"), True),
    ("FauDR LBranch", ("faudr", "lackbranch"), True),
    ("FauDR Avg", ("faudr", "avg"), True),
    ("FauDR-mut", ("faudr_mut",), True),
    ("ST (ms)", ("st_ms",), False),
    ("ST (ticks)", ("st_ticks",), False),
    ("LD", ("ld",), True),
    ("JI", ("ji",), False),
    ("Redundancy", ("redundancy",), False),
    ("Envs", ("n_envs",), False),
    ("Failed", ("n_failed",), False),
    ("Extra checks", ("plausibility", "rate"), True),
)

#: what the columns mean, under every leaderboard (markdown and HTML)
LEGEND = (
    "Rates in percent. PhyPR: the paper's three dimensions only (Table 2). ST (ms) = wall time to "
    "simulate one BT over a generator's environments for a task (varies with machine load); "
    "ST (ticks) = the same in simulator ticks (deterministic). JI = Jaccard index vs the minimum "
    "cover of the GT trajectories closest to the generator's set; Redundancy = environments / "
    "minimum cover size; Extra checks = share of environments passing our plausibility checks "
    "beyond the paper's PhyPR (catalog sizes, door swing areas, objects through the ceiling, "
    "unreachable rooms, windows over doors; not part of PhyPR). Failed = attempted environments the "
    "generator could not build / all it attempted; PhyPR and SceVR divide by all attempted. \"not "
    "measured\": every unit failed for infrastructure reasons (endpoint, cache), so there is no result."
)

NOT_MEASURED = "not measured"


def metric(values: dict[str, Any], path: tuple[str, ...]) -> float | None:
    cur: Any = values
    for key in path:
        if isinstance(cur, list) and key.isdigit() and int(key) < len(cur):
            cur = cur[int(key)]
            continue
        if not isinstance(cur, dict) or key not in cur:
            return None
        cur = cur[key]
    return None if cur is None else float(cur)


def fmt(value: float | None, percent: bool) -> str:
    if value is None:
        return "–"
    if percent:
        return f"{100 * value:.2f}"
    return f"{value:.2f}" if abs(value) < 1000 else f"{value:.0f}"


def method_label(generator: str, model: str) -> str:
    return f"{generator} (oracle: upper bound)" if model == "oracle" else generator


def row_label(generator: str, values: dict[str, Any], results: dict[str, Any]) -> str:
    """The method label, with the tasks where a search stopped at its budget (docs/logic.md)."""
    label = method_label(generator, results.get("model", ""))
    hit = values.get("budget_hit_tasks") or []
    if hit:
        measured = len(results.get("tasks", [])) - len(values.get("not_measured_tasks") or [])
        label += f" (budget hit {len(hit)}/{measured})"
    return label


def cell(values: dict[str, Any], path: tuple[str, ...], pct: bool) -> str:
    """One leaderboard cell: `value ± half-width` of the 95 % interval when results carry one."""
    if values.get("measured") is False:
        return NOT_MEASURED
    if path == ("n_envs",):
        return str(int(values["n_envs"]))
    if path == ("n_failed",):
        failed, attempted = values.get("n_failed"), values.get("n_attempted")
        return "–" if failed is None or attempted is None else f"{int(failed)}/{int(attempted)}"
    text = fmt(metric(values, path), pct)
    lo, hi = metric(values.get("ci95", {}), path + ("0",)), metric(values.get("ci95", {}), path + ("1",))
    if lo is None or hi is None:
        return text
    half = (hi - lo) / 2
    return f"{text} ± {100 * half:.2f}" if pct else f"{text} ± {half:.2f}"


def rows(results: dict[str, Any]) -> list[list[str]]:
    out = []
    for gen, values in results["results"].items():
        out.append([row_label(gen, values, results)]
                   + [cell(values, path, pct) for _, path, pct in COLUMNS])
    return out


def interval_note(results: dict[str, Any]) -> str:
    """What `±` means under a leaderboard."""
    over = "tasks and seeds" if results.get("seeds") else "tasks"
    return f"± = half-width of the 95 % bootstrap interval over {over} (docs/runner.md)."


def _seed_text(results: dict[str, Any]) -> str:
    seeds = results.get("seeds")
    return f"seeds {', '.join(str(s) for s in seeds)}" if seeds else f"seed {results.get('seed')}"


def markdown(results: dict[str, Any]) -> str:
    header = ["Method"] + [h + (" (%)" if pct else "") for h, _, pct in COLUMNS]
    lines = [
        f"# LogicEnvEval leaderboard — run `{results.get('run_id', '?')}`",
        "",
        f"Model: `{results.get('model')}` · {_seed_text(results)} · "
        f"brief `{results.get('brief', 'roles')}` · "
        f"{len(results.get('tasks', []))} tasks · commit `{results.get('git_commit') or 'n/a'}`",
        "",
        "| " + " | ".join(header) + " |",
        "|" + "|".join(["---"] + ["---:"] * (len(header) - 1)) + "|",
    ]
    lines += ["| " + " | ".join(r) + " |" for r in rows(results)]
    fails = {g: len(f) for g, f in results.get("failures", {}).items() if f}
    if fails:
        lines += ["", "Recorded generation failures: "
                  + ", ".join(f"{g}: {n}" for g, n in sorted(fails.items()))]
    for key, what in (("not_measured_tasks", "Not measured (infrastructure failures; left out of "
                       "the row)"), ("budget_hit_tasks", "Search budget hit (MTSA's cover used)")):
        listed = {g: v[key] for g, v in results["results"].items() if v.get(key)}
        if listed:
            lines += ["", f"{what}: " + "; ".join(f"{g}: {', '.join(t)}" for g, t in listed.items())]
    lines += ["", LEGEND + " " + interval_note(results), ""]
    return "\n".join(lines)
