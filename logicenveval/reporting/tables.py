"""The leaderboard table in the layout of the paper's main table, as plain rows.

A cell is a value and, for the rates with a bootstrap interval, the interval's bounds `[lo, hi]`
(never `± half-width`: the percentile interval is asymmetric near 0 and 100); `n/a` where the row
covers fewer than two tasks. A row that was not measured (every unit failed for infrastructure
reasons) says so in every cell; old results files without these fields render as before.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from logicenveval.metrics.uncertainty import MIN_TASKS, cells_of

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
    ("Extra checks", ("plausibility", "rate"), True),
)

#: the HTML header's groups: (group title, first column index, number of columns)
GROUPS: tuple[tuple[str, int, int], ...] = (("PhyPR", 0, 4), ("FauDR", 6, 4), ("ST", 11, 2))
#: the sub-header of a grouped column (the part of its header after the group's name)
SUBHEADERS = {0: "Floor", 1: "Entity", 2: "Relation", 3: "Avg", 6: "CF", 7: "Unreach",
              8: "LBranch", 9: "Avg", 11: "ms", 12: "ticks"}

N_HEADER = "n (tasks×seeds)"
FAILED_HEADER = "Failed / attempted"
NOT_MEASURED = "not measured"

#: what the columns mean, under every leaderboard (markdown and HTML)
LEGEND = (
    "Rates in percent. PhyPR: the paper's three dimensions only (Table 2). ST (ms) = wall time to "
    "simulate one BT over a generator's environments for a task (varies with machine load); "
    "ST (ticks) = the same in simulator ticks (deterministic). JI = Jaccard index vs the minimum "
    "cover of the GT trajectories closest to the generator's set; Redundancy = environments / "
    "minimum cover size; Extra checks = share of environments passing our plausibility checks "
    "beyond the paper's PhyPR (catalog sizes, door swing areas, objects through the ceiling, "
    "unreachable rooms, windows over doors; not part of PhyPR). n = tasks × seeds the row was "
    "measured on; Failed / attempted = environments the generator set out to build but could not; "
    "PhyPR and SceVR divide by all attempted. \"not measured\": every unit failed for infrastructure "
    "reasons (endpoint, cache), so there is no result."
)


@dataclass(frozen=True)
class Cell:
    """One table cell: the value, its 95 % interval (`[lo, hi]`, `[n/a]` or empty) and a sort key."""

    value: str
    interval: str = ""
    sort: float | None = None

    @property
    def text(self) -> str:
        return f"{self.value} {self.interval}".strip()


def metric(values: dict[str, Any], path: tuple[str, ...]) -> float | None:
    cur: Any = values
    for key in path:
        if isinstance(cur, list) and key.isdigit() and int(key) < len(cur):
            cur = cur[int(key)]
            continue
        if not isinstance(cur, dict) or key not in cur:
            return None
        cur = cur[key]
    return None if cur is None or isinstance(cur, dict | list | str) else float(cur)


def fmt(value: float | None, percent: bool) -> str:
    if value is None:
        return "–"
    if percent:
        return f"{100 * value:.2f}"
    return f"{value:.2f}" if abs(value) < 1000 else f"{value:.0f}"


def method_label(generator: str, model: str) -> str:
    return f"{generator} (oracle: upper bound)" if model == "oracle" else generator


def is_measured(values: dict[str, Any]) -> bool:
    return values.get("measured") is not False


def generator_args(results: dict[str, Any], generator: str) -> dict[str, Any]:
    """The `--generator-args` a row was made with (keyed in results.json's `config` by the item as
    written in `--generators`, or by the row's name), {} when none."""
    config = results.get("config")
    if not isinstance(config, dict) or not isinstance(given := config.get("generator_args"), dict):
        return {}
    args = given.get(generator)
    if args is None:
        items, rows = config.get("generators"), results.get("generators")
        if isinstance(items, list) and isinstance(rows, list) and len(items) == len(rows) \
                and generator in rows:
            args = given.get(str(items[rows.index(generator)]))
    return dict(args) if isinstance(args, dict) else {}


def args_text(args: dict[str, Any]) -> str:
    """`n_envs=3, seed_offset=2`: generator args as `--generator-args` spells them."""
    return ", ".join(f"{k}={json.dumps(v) if isinstance(v, bool) else v}" for k, v in sorted(args.items()))


def row_label(generator: str, values: dict[str, Any], results: dict[str, Any]) -> str:
    """The method's name with what qualifies its row: its generator args (two runs that differ
    only in them are told apart), oracle, selector budget hit, tasks missed."""
    label = method_label(generator, str(results.get("model", "")))
    n_tasks = len(results.get("tasks", []))
    marks = []
    args = generator_args(results, generator)
    if args:
        marks.append(args_text(args))
    budget = values.get("budget_hit_tasks") or []
    if budget:
        marks.append(f"budget hit {len(budget)}/{n_tasks}")
    missing = values.get("not_measured_tasks") or []
    if missing and is_measured(values):
        marks.append(f"not measured on {len(missing)}/{n_tasks}")
    return f"{label} ({', '.join(marks)})" if marks else label


def n_tasks_seeds(results: dict[str, Any], generator: str) -> tuple[int, int]:
    """(tasks, seeds) the row's figures come from."""
    cells = cells_of(results, generator)
    tasks = {t for t, _ in cells}
    seeds = len(results.get("seeds") or []) or 1
    return len(tasks), seeds


def _interval(values: dict[str, Any], path: tuple[str, ...], pct: bool, n_tasks: int) -> str:
    ci = values.get("ci95")
    if not isinstance(ci, dict):
        return ""
    node: Any = ci
    for key in path:
        if not isinstance(node, dict) or key not in node:
            return ""  # a figure without an interval (ST, redundancy, ...)
        node = node[key]
    if node is None or n_tasks < MIN_TASKS:
        return "[n/a]"
    lo, hi = metric(values, ("ci95", *path, "0")), metric(values, ("ci95", *path, "1"))
    if lo is None or hi is None:
        return "[n/a]"
    return f"[{fmt(lo, pct)}, {fmt(hi, pct)}]"


def cell(values: dict[str, Any], path: tuple[str, ...], pct: bool, n_tasks: int = MIN_TASKS) -> Cell:
    """One leaderboard cell: the value and the bounds of its 95 % interval when results carry one."""
    if not is_measured(values):
        return Cell(NOT_MEASURED)
    value = metric(values, path)
    if path == ("n_envs",):
        return Cell("–" if value is None else str(int(value)), sort=value)
    if value is None:
        return Cell("–")
    return Cell(fmt(value, pct), _interval(values, path, pct, n_tasks),
                sort=100 * value if pct else value)


def row_cells(results: dict[str, Any], generator: str) -> list[Cell]:
    """n, every column of `COLUMNS`, failed/attempted: the row of one generator (label apart)."""
    values = results["results"][generator]
    if not is_measured(values):
        return [Cell(NOT_MEASURED)] * (len(COLUMNS) + 2)
    tasks, seeds = n_tasks_seeds(results, generator)
    n = Cell(str(tasks) if seeds == 1 else f"{tasks}×{seeds}", sort=float(tasks * seeds))
    attempted, failed = values.get("n_attempted"), values.get("n_failed")
    tried = (Cell(f"{int(failed)}/{int(attempted)}", sort=float(failed))
             if attempted is not None and failed is not None else Cell("–"))
    return [n, *(cell(values, path, pct, tasks) for _, path, pct in COLUMNS), tried]


def headers() -> list[str]:
    return ["Method", N_HEADER] + [h + (" (%)" if pct else "") for h, _, pct in COLUMNS] + [FAILED_HEADER]


def rows(results: dict[str, Any]) -> list[list[str]]:
    return [[row_label(gen, values, results)] + [c.text for c in row_cells(results, gen)]
            for gen, values in results["results"].items()]


def md_escape(text: str) -> str:
    """Text for one Markdown table cell: no pipe or line break can split the row."""
    return " ".join(text.replace("\\", "\\\\").replace("|", "\\|").split())


def interval_note(results: dict[str, Any]) -> str:
    """What the bracketed bounds mean under a leaderboard."""
    over = "tasks and seeds" if results.get("seeds") else "tasks"
    return (f"[lo, hi] = the 95 % bootstrap interval over {over} (n/a with fewer than {MIN_TASKS} "
            "tasks; docs/runner.md).")


def llm_validity(results: dict[str, Any]) -> list[tuple[str, float, float, int]]:
    """(generator, valid first-reply share, valid share after re-asks, questions) from the
    results' `llm` block, for generators that asked a model anything (none in old results)."""
    block = results.get("llm")
    out = []
    for gen in results.get("results", {}):
        row = block.get(gen, {}).get("all") if isinstance(block, dict) and isinstance(block.get(gen), dict) else None
        if not isinstance(row, dict):
            continue
        first, share, asked = metric(row, ("valid_first_share",)), metric(row, ("valid_share",)), metric(row, ("questions",))
        if first is not None and share is not None and asked:
            out.append((gen, first, share, int(asked)))
    return out


def _seed_text(results: dict[str, Any]) -> str:
    seeds = results.get("seeds")
    return f"seeds {', '.join(str(s) for s in seeds)}" if seeds else f"seed {results.get('seed')}"


def markdown(results: dict[str, Any]) -> str:
    header = headers()
    lines = [
        f"# LogicEnvEval leaderboard — run `{md_escape(str(results.get('run_id', '?')))}`",
        "",
        f"Model: `{md_escape(str(results.get('model')))}` · {_seed_text(results)} · "
        f"brief `{results.get('brief', 'roles')}` · "
        f"{len(results.get('tasks', []))} tasks · commit `{results.get('git_commit') or 'n/a'}`",
        "",
        "| " + " | ".join(header) + " |",
        "|" + "|".join(["---"] + ["---:"] * (len(header) - 1)) + "|",
    ]
    lines += ["| " + " | ".join(md_escape(c) for c in r) + " |" for r in rows(results)]
    fails = {g: len(f) for g, f in results.get("failures", {}).items() if f}
    if fails:
        lines += ["", "Failure entries in results.json `failures` (why attempts failed, counted by "
                  "their `attempts`, and problems of environments that were built; not the failed "
                  "column): "
                  + ", ".join(f"{md_escape(g)}: {n}" for g, n in sorted(fails.items()))]
    for key, what in (("not_measured_tasks", "Not measured (infrastructure failures; left out of "
                       "the row)"), ("budget_hit_tasks", "Search budget hit (MTSA's cover used)")):
        listed = {g: v[key] for g, v in results["results"].items() if v.get(key)}
        if listed:
            lines += ["", f"{what}: " + "; ".join(f"{md_escape(g)}: {', '.join(t)}"
                                                  for g, t in listed.items())]
    valid = llm_validity(results)
    if valid:
        lines += ["", "Valid model replies (first reply / after re-asks, of questions asked): "
                  + ", ".join(f"{md_escape(g)}: {100 * a:.1f} % / {100 * b:.1f} % of {n}" for g, a, b, n in valid)]
    lines += ["", LEGEND + " " + interval_note(results), ""]
    return "\n".join(lines)
