"""Regenerate every table of figures in README.md and docs/*.md from committed data.

Docs drift from data when figures are typed by hand. Every table of figures therefore sits between
markers and is written by this script from the committed runs and the benchmark itself:

    <!-- figures:NAME -->          a whole table (NAME is a key of BLOCKS)
    ...
    <!-- /figures -->
    <!--fig:NAME-->1,475<!--/fig-->   one figure inside a sentence (NAME is a key of INLINE)

Sources: `reports/reference/results.json` (the default generators), `reports/figures/<run>/
results.json` (the ablation, oracle and `--brief roles` runs: only their results are
committed), `reports/real/*/results.json` (the real-model replay packs), `reports/real/stability/
<model>/seed*/results.json` (repeated real-model runs, paper App. C), and the task folders
(`tasks stats`, trajectory selectors, shipped killable-mutant lists). Benchmark timings
(`docs/performance.md`, `benchmarks/*.py`) are measurements of a machine, not data, and stay
hand-written.

    python tools/docs_figures.py            # rewrite the marked tables and figures in place
    python tools/docs_figures.py --check    # exit 1 and list what differs (tests/test_docs_figures.py)
    python tools/docs_figures.py --rerun    # first re-run the runs the figures come from (minutes)

In the fidelity table ("paper-vs-ours") only the paper and ours columns are generated; the
"why" column is prose, kept as it is in the file.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Callable, Sequence
from functools import cache
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))  # the benchmark scripts whose tables the docs embed

from logicenveval.benchmark import load_task, task_ids, tasks_dir  # noqa: E402
from logicenveval.benchmark_stats import benchmark_stats, to_markdown, totals  # noqa: E402
from logicenveval.errors import RunFailedError  # noqa: E402
from logicenveval.logic.constraints import task_constraints  # noqa: E402
from logicenveval.logic.exact import exact_cover  # noqa: E402
from logicenveval.logic.exhaustive import exhaustive_cover  # noqa: E402
from logicenveval.logic.reference import reference_set  # noqa: E402
from logicenveval.logic.selectors import get_selector  # noqa: E402
from logicenveval.model.tree import task_paths  # noqa: E402
from logicenveval.runner.results import load_results  # noqa: E402

REFERENCE = ROOT / "reports" / "reference"
FIGURES = ROOT / "reports" / "figures"
REAL = ROOT / "reports" / "real"
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]

#: the runs besides the reference whose results.json the tables read, and the command of each
RUNS: dict[str, list[str]] = {
    "ablation": ["--generators", "logicenvgen,logicenvgen-exact,logicenvgen-no-dbp,logicenvgen-no-mtsa,"
                 "logicenvgen-exhaustive,logicenvgen-no-cas,logicenvgen-reselect"],
    "oracle": ["--model", "oracle", "--generators", "logicenvgen,logicenvgen-exact"],
    "brief-roles": ["--brief", "roles"],
}
LABELS = {"logicenvgen": "logicenvgen (MTSA)", "logicenvgen-exact": "logicenvgen-exact (ours)",
          "logicenvgen-no-mtsa": "logicenvgen-no-mtsa (product)"}
NOT_MEASURED = "not measured"

#: an empty block is the two markers on consecutive lines (the body then matches nothing)
BLOCK = re.compile(r"(<!-- figures:([a-z0-9-]+) -->\n)(?:(.*?)\n)??(<!-- /figures -->)", re.S)
FIG = re.compile(r"(<!--fig:([a-z0-9_.-]+)-->)(.*?)(<!--/fig-->)", re.S)


# ---------------------------------------------------------------- sources

@cache
def results(name: str) -> dict[str, Any]:
    return load_results(REFERENCE if name == "reference" else FIGURES / name)


@cache
def stats() -> tuple[Any, ...]:
    return tuple(benchmark_stats())


@cache
def killable() -> dict[str, int]:
    d = tasks_dir()
    return {t: len(json.loads((d / t / "killable_mutants.json").read_text())["killable"])
            for t in task_ids(d)}


# ---------------------------------------------------------------- formatting

def pct(x: float | None) -> str:
    return "–" if x is None else f"{100 * x:.2f}"


def num(x: float | None) -> str:
    return "–" if x is None else f"{x:.2f}"


def thousands(n: float) -> str:
    return f"{n:,.0f}" if float(n).is_integer() else f"{n:,.1f}"


def get(values: dict[str, Any], *path: str) -> Any:
    cur: Any = values
    for key in path:
        if not isinstance(cur, dict) or key not in cur:
            return None
        cur = cur[key]
    return cur


def label(gen: str, values: dict[str, Any], res: dict[str, Any]) -> str:
    text = LABELS.get(gen, gen)
    hit = values.get("budget_hit_tasks") or []
    if hit:
        text += f" (budget hit {len(hit)}/{len(res.get('tasks', []))})"
    return text


def failed(values: dict[str, Any]) -> str:
    f, a = values.get("n_failed"), values.get("n_attempted")
    return "–" if f is None or a is None else f"{int(f)}/{int(a)}"


Column = tuple[str, Callable[[dict[str, Any]], str]]


def table(res: dict[str, Any], columns: Sequence[Column], first: str = "Method",
          generators: Sequence[str] | None = None) -> str:
    head = "| " + " | ".join([first] + [c for c, _ in columns]) + " |"
    sep = "|---|" + "|".join("---:" for _ in columns) + "|"
    lines = [head, sep]
    for gen in generators or res["results"]:  # load_results: the run's row order
        values = res["results"][gen]
        cells = ([NOT_MEASURED] * len(columns) if values.get("measured") is False
                 else [fn(values) for _, fn in columns])
        lines.append("| " + " | ".join([label(gen, values, res)] + cells) + " |")
    return "\n".join(lines)


def rate(*path: str) -> Callable[[dict[str, Any]], str]:
    return lambda v: pct(get(v, *path))


def plain(*path: str) -> Callable[[dict[str, Any]], str]:
    return lambda v: num(get(v, *path))


ENVS: Column = ("Envs", lambda v: str(int(v["n_envs"])) if v.get("n_envs") is not None else "–")
FAILED: Column = ("Failed", failed)
EXTRA: Column = ("Extra checks", rate("plausibility", "rate"))
MAIN: list[Column] = [
    ("PhyPR Floor", rate("phypr", "floor_plan")), ("Entity", rate("phypr", "entity")),
    ("Relation", rate("phypr", "relation")), ("Avg", rate("phypr", "avg")),
    ("LogCov", rate("logcov")), ("SceVR", rate("scevr")),
    ("FauDR CF", rate("faudr", "counterfactual")), ("Unreach", rate("faudr", "unreachable")),
    ("LBranch", rate("faudr", "lackbranch")), ("Avg", rate("faudr", "avg")),
    ("FauDR-mut", rate("faudr_mut")), ("ST (ms)", plain("st_ms")), ("ST (ticks)", plain("st_ticks")),
    ("LD", rate("ld")), ("JI", plain("ji")), ("Redundancy", plain("redundancy")),
    ENVS, FAILED, EXTRA,
]
ABLATION: list[Column] = [
    ("PhyPR Avg", rate("phypr", "avg")), ("LogCov", rate("logcov")), ("SceVR", rate("scevr")),
    ("FauDR Avg", rate("faudr", "avg")), ("FauDR-mut", rate("faudr_mut")),
    ("ST (ticks)", plain("st_ticks")), ("JI", plain("ji")), ("Redundancy", plain("redundancy")),
    ENVS, FAILED,
]


# ---------------------------------------------------------------- blocks

def block_reference() -> str:
    return table(results("reference"), MAIN)


def block_ablation() -> str:
    return table(results("ablation"), ABLATION)


def block_oracle() -> str:
    cols: list[Column] = [("PhyPR avg", rate("phypr", "avg")), ("LogCov", rate("logcov")),
                          ("SceVR", rate("scevr")), ("FauDR avg", rate("faudr", "avg")),
                          ("JI", plain("ji")), ("Redundancy", plain("redundancy")), ENVS,
                          ("ST (ticks)", plain("st_ticks"))]
    return table(results("oracle"), cols, first="generator")


def block_brief() -> str:
    cols: list[Column] = [("PhyPR avg", rate("phypr", "avg")), ("LogCov", rate("logcov")),
                          ("SceVR", rate("scevr")), ("FauDR avg", rate("faudr", "avg")),
                          ("JI", plain("ji")), ENVS, FAILED, EXTRA]
    if not (FIGURES / "brief-roles" / "results.json").exists():
        return "(the `--brief roles` run is not committed yet: `python tools/docs_figures.py --rerun`)"
    return table(results("brief-roles"), cols, first="generator")


def block_faudr_mut() -> str:
    def by_class(v: dict[str, Any]) -> str:
        c = v.get("faudr_mut_by_class") or {}
        return " / ".join("–" if c.get(k) is None else f"{100 * c[k]:.1f}"
                          for k in ("counterfactual", "unreachable", "lackbranch"))
    cols: list[Column] = [("FauDR avg", rate("faudr", "avg")), ("FauDR-mut", rate("faudr_mut")),
                          ("cf / unr / lack", by_class)]
    return table(results("reference"), cols, first="generator")


def block_baselines() -> str:
    def phypr(v: dict[str, Any]) -> str:
        return " / ".join(pct(get(v, "phypr", k)) for k in ("floor_plan", "entity", "relation", "avg"))
    cols: list[Column] = [ENVS, FAILED, ("LogCov", rate("logcov")),
                          ("PhyPR floor plan / entity / relation / avg", phypr),
                          ("Extra checks", rate("plausibility", "rate"))]
    gens = [g for g in ("cot", "ifg", "holodeck") if g in results("reference")["results"]]
    return table(results("reference"), cols, first="generator", generators=gens)


def block_task_stats() -> str:
    return to_markdown(list(stats()))


@cache
def block_selectors() -> str:
    head = ("| task | subtasks | paths | product | MTSA | exhaustive | exact | reference (JI) | "
            "forbidden pairs |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    rows = [head]
    total = {"mtsa": 0, "exact": 0}
    d = tasks_dir()
    for tid in task_ids(d):
        task = load_task(tid, d)
        paths = task_paths(task)
        cons = task_constraints(task)
        mtsa = get_selector("mtsa").select(paths, cons)
        search = exhaustive_cover(paths, cons)
        exact = exact_cover(paths, cons)
        total["mtsa"] += len(mtsa)
        total["exact"] += len(exact.trajectories)
        rows.append(f"| {tid} | {len(paths)} | {sum(len(p) for p in paths)} | "
                    f"{math.prod(len(p) for p in paths)} | {len(mtsa)} | "
                    f"{len(search.trajectories) if search.optimal else 'budget hit'} | "
                    f"{len(exact.trajectories)} | {len(reference_set(task))} | {len(cons.forbidden)} |")
    return "\n".join(rows)


def _model_label(res: dict[str, Any]) -> str:
    """`llamacpp:/x/SmolLM2-135M-Instruct.Q4_1.gguf` -> `SmolLM2-135M-Instruct.Q4_1`, with the
    brief the pack was recorded with (`--brief roles`, `--brief description`): one model's packs
    recorded in both setups are told apart."""
    name = Path(str(res.get("model", "?")).split(":", 1)[-1]).name.removesuffix(".gguf")
    return f"{name}, brief {res.get('brief', 'roles')}"


def block_real() -> str:
    """The committed real-model replay packs, one row per method, labelled with model and tasks."""
    cols = [c for c in MAIN if c[0] != "ST (ms)"]
    head: list[str] = []
    rows: list[str] = []
    for path in sorted(REAL.glob("*/results.json")):
        res = load_results(path.parent)
        model = _model_label(res)
        lines = table(res, cols).splitlines()
        head = lines[:2]
        for line in lines[2:]:
            gen = line.split(" | ")[0].removeprefix("| ")
            rows.append(line.replace(f"| {gen} |", f"| {gen} — {model}, {len(res['tasks'])} tasks |", 1))
    return "\n".join(head + rows) if rows else "(no real-model pack committed)"


def block_validity() -> str:
    """Share of valid first replies and after re-asks per method and request kind, from the `llm`
    block of each committed replay pack (the table `benchmarks/llm_validity.py` prints)."""
    from llm_validity import validity_table  # type: ignore[import-not-found]

    out: list[str] = []
    for path in sorted(REAL.glob("*/results.json")):
        res = json.loads(path.read_text())
        model = _model_label(res)
        lines, _ = validity_table(res.get("llm", {}))
        out += [*([""] if out else []), f"*{model}, tasks: {', '.join(res['tasks'])}*", "", *lines]
    return "\n".join(out) if out else "(no real-model pack committed)"


def block_validity_before() -> str:
    """Per request kind, a pack's valid replies under the protocol it was recorded with (3 on) next
    to those its cache holds from protocol 2 (the replies recorded before protocol 3's keyed scene,
    replayed with `llm_validity.replay(..., protocol=2)`): per side the questions answered (a
    question never recorded under protocol 2 is a cache miss, not measured, so not counted);
    packs recorded before protocol 3, and packs whose cache holds no protocol-2 reply (a run
    stops on its cache misses), have no such column."""
    from llm_validity import pack_protocol, replay  # type: ignore[import-not-found]

    out: list[str] = []
    for path in sorted(REAL.glob("*/results.json")):
        config = json.loads((path.parent / "config.json").read_text())
        if pack_protocol(config) < 3:
            continue
        recorded = json.loads(path.read_text())
        after = recorded.get("llm", {})
        with tempfile.TemporaryDirectory() as tmp:
            try:
                before = replay(path.parent, Path(tmp), protocol=2).get("llm", {})
            except RunFailedError:
                continue  # recorded under protocol 3 on only: its cache holds no protocol-2 reply
        head = ("| method | request kind | protocol 2: answered | valid first (%) | valid (%) | cut | "
                f"protocol {pack_protocol(config)}: answered | valid first (%) | valid (%) | cut |\n"
                "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        rows = [head]
        for gen in after:
            for kind in sorted(set(after[gen]) | set(before.get(gen, {}))):
                cells = []
                for side in (before.get(gen, {}).get(kind), after[gen].get(kind)):
                    answered = side.get("answered", side["questions"]) if side else 0
                    cells += (["-"] * 4 if not answered else
                              [str(answered), f"{100 * side['valid_first_share']:.1f}",
                               f"{100 * side['valid_share']:.1f}", str(side["truncated"])])
                rows.append(f"| {gen} | {kind} | " + " | ".join(cells) + " |")
        out += [*([""] if out else []), f"*{_model_label(recorded)}*", "", *rows]
    return "\n".join(out) if out else "(no pack recorded with protocol 3)"


def block_stability() -> str:
    """Paper App. C: per method, mean ± sd (range) of each metric over the committed seed runs of
    a real model (`reports/real/stability/<model>/seed*/results.json`, `benchmarks/stability.py`)."""
    from stability import load_runs  # type: ignore[import-not-found]
    from stability import table as stability_table

    out: list[str] = []
    for folder in sorted((REAL / "stability").glob("*/")):
        if any(folder.glob("seed*/results.json")):
            caption, *rows = stability_table(load_runs(folder))
            out += [*([""] if out else []), f"*{caption}*", "", *rows]
    return "\n".join(out) if out else "(no stability runs committed yet)"


# ---------------------------------------------------------------- paper vs ours

def _three(v: dict[str, Any]) -> str:
    return " / ".join(pct(get(v, "phypr", k)) for k in ("floor_plan", "entity", "relation"))


def _row(gen: str, run: str = "reference") -> dict[str, Any]:
    values: dict[str, Any] = results(run)["results"].get(gen, {})
    return values


#: (row, the paper's DeepSeek-v3 figure as it prints it, ours)
PAPER: list[tuple[str, str, Callable[[], str]]] = [
    ("LogicEnvGen PhyPR floor / entity / relation", "100.00 / 100.00 / 100.00",
     lambda: _three(_row("logicenvgen"))),
    ("LogicEnvGen LogCov", "99.06", lambda: pct(_row("logicenvgen")["logcov"])),
    ("LogicEnvGen SceVR", "93.75", lambda: pct(_row("logicenvgen")["scevr"])),
    ("LogicEnvGen FauDR CF / Unreach / LBranch (avg)", "96.00 / 92.00 / 96.00 (94.67)",
     lambda: _faudr(_row("logicenvgen"))),
    ("LogicEnvGen ST", "49.88 min",
     lambda: f"{num(_row('logicenvgen')['st_ms'])} ms, {num(_row('logicenvgen')['st_ticks'])} ticks"),
    ("LogicEnvGen JI", "0.88", lambda: num(_row("logicenvgen")["ji"])),
    ("CoT PhyPR floor / entity / relation (avg)", "96.00 / 40.00 / 20.00 (52.00)",
     lambda: f"{_three(_row('cot'))} ({pct(_row('cot')['phypr']['avg'])})"),
    ("CoT LogCov", "63.38", lambda: pct(_row("cot")["logcov"])),
    ("CoT SceVR / FauDR avg", "85.71 / 58.67",
     lambda: f"{pct(_row('cot')['scevr'])} / {pct(_row('cot')['faudr']['avg'])}"),
    ("IFG PhyPR floor / entity / relation (avg)", "90.84 / 11.00 / 13.04 (38.29)",
     lambda: f"{_three(_row('ifg'))} ({pct(_row('ifg')['phypr']['avg'])})"),
    ("IFG LogCov", "91.08", lambda: pct(_row("ifg")["logcov"])),
    ("IFG SceVR / FauDR avg", "90.72 / 90.67",
     lambda: f"{pct(_row('ifg')['scevr'])} / {pct(_row('ifg')['faudr']['avg'])}"),
    ("IFG ST", "87.96 min (highest)",
     lambda: f"{num(_row('ifg')['st_ms'])} ms, {num(_row('ifg')['st_ticks'])} ticks"),
    ("Holodeck PhyPR avg", "100.00", lambda: pct(_row("holodeck")["phypr"]["avg"])),
    ("Holodeck LogCov / SceVR / FauDR avg", "37.05 / 76.00 / 26.67",
     lambda: " / ".join(pct(x) for x in (_row("holodeck")["logcov"], _row("holodeck")["scevr"],
                                         _row("holodeck")["faudr"]["avg"]))),
    ("W/O DBP LogCov / SceVR / FauDR avg / JI", "95.19 / 89.70 / 93.33 / 0.32",
     lambda: _ablation("logicenvgen-no-dbp")),
    ("W/O MTSA LogCov / JI", "99.06 / 0.30",
     lambda: f"{pct(_row('logicenvgen-no-mtsa', 'ablation')['logcov'])} / "
             f"{num(_row('logicenvgen-no-mtsa', 'ablation')['ji'])}"),
    ("Exhaustive LogCov / JI", "99.06 / 0.95",
     lambda: f"{pct(_row('logicenvgen-exhaustive', 'ablation')['logcov'])} / "
             f"{num(_row('logicenvgen-exhaustive', 'ablation')['ji'])}"),
    ("W/O CAS PhyPR avg (CoT minus W/O CAS)", "32.08 (19.92)",
     lambda: f"{pct(_row('logicenvgen-no-cas', 'ablation')['phypr']['avg'])} "
             f"({num(100 * (_row('cot')['phypr']['avg'] - _row('logicenvgen-no-cas', 'ablation')['phypr']['avg']))})"),
    ("(ours) Extra checks: LogicEnvGen / CoT / IFG / no-CAS", "—",
     lambda: " / ".join(pct(get(v, "plausibility", "rate")) for v in (
         _row("logicenvgen"), _row("cot"), _row("ifg"), _row("logicenvgen-no-cas", "ablation")))),
]


def _faudr(v: dict[str, Any]) -> str:
    f = v["faudr"]
    return f"{pct(f['counterfactual'])} / {pct(f['unreachable'])} / {pct(f['lackbranch'])} ({pct(f['avg'])})"


def _ablation(gen: str) -> str:
    v = _row(gen, "ablation")
    return f"{pct(v['logcov'])} / {pct(v['scevr'])} / {pct(v['faudr']['avg'])} / {num(v['ji'])}"


def block_paper_vs_ours(current: str) -> str:
    why = {}
    for line in current.splitlines()[2:]:
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if len(cells) >= 4:
            why[cells[0]] = " | ".join(cells[3:])
    lines = ["| row | paper (DeepSeek-v3) | ours | why |", "|---|---|---|---|"]
    for row, paper, ours in PAPER:
        lines.append(f"| {row} | {paper} | {ours()} | {why.get(row, 'TODO: say why')} |")
    return "\n".join(lines)


# ---------------------------------------------------------------- orderings

PAPER_TABLE = ROOT / "benchmark_data" / "paper_main_table.json"
#: (row, the paper's key, our results path, higher is better)
ORDERED: list[tuple[str, str, tuple[str, ...], bool]] = [
    ("PhyPR avg", "phypr_avg", ("phypr", "avg"), True),
    ("LogCov", "logcov", ("logcov",), True),
    ("SceVR", "scevr", ("scevr",), True),
    ("FauDR CF", "faudr_counterfactual", ("faudr", "counterfactual"), True),
    ("FauDR Unreach", "faudr_unreachable", ("faudr", "unreachable"), True),
    ("FauDR LBranch", "faudr_lackbranch", ("faudr", "lackbranch"), True),
    ("FauDR avg", "faudr_avg", ("faudr", "avg"), True),
    ("ST (ours: ticks)", "st_min", ("st_ticks",), False),
]


def ordering(values: dict[str, float], higher: bool) -> str:
    """Methods best first; `=` joins ties at the printed precision (two decimals)."""
    groups: dict[float, list[str]] = {}
    for name, v in values.items():
        groups.setdefault(round(v, 2), []).append(name)
    keys = sorted(groups, reverse=higher)
    return " > ".join(" = ".join(sorted(groups[k])) for k in keys)


def block_orderings() -> str:
    """Per metric, the paper's order of the four methods under each of its LLMs and ours (the
    reference run), and under which LLMs ours is the same order."""
    paper = json.loads(PAPER_TABLE.read_text())
    names: dict[str, str] = paper["methods"]
    llms = list(paper["models"])
    res = results("reference")
    head = ["metric", *(f"paper, {m}" for m in llms), f"ours ({_model_label(res)})",
            "same order as"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for row, key, path, higher in ORDERED:
        orders = [ordering({n: paper["models"][m][n][key] for n in names}, higher) for m in llms]
        ours_values = {n: get(res["results"].get(gen, {}), *path) for n, gen in names.items()}
        if any(v is None for v in ours_values.values()):
            ours, same = NOT_MEASURED, "—"
        else:
            scale = 100.0 if path[0] not in PLAIN else 1.0
            ours = ordering({n: scale * float(v) for n, v in ours_values.items()}, higher)
            same = ", ".join(m for m, o in zip(llms, orders, strict=True) if o == ours) or "none"
        lines.append(f"| {row} | " + " | ".join(orders) + f" | {ours} | {same} |")
    return "\n".join(lines)


BLOCKS: dict[str, Callable[[], str]] = {
    "orderings": block_orderings,
    "reference": block_reference, "ablation": block_ablation, "oracle": block_oracle,
    "brief": block_brief, "faudr-mut": block_faudr_mut, "baselines": block_baselines,
    "task-stats": block_task_stats, "selectors": block_selectors, "real": block_real,
    "stability": block_stability, "validity": block_validity, "validity-before": block_validity_before,
}


# ---------------------------------------------------------------- inline figures

def _ref_gen(gen: str, *path: str) -> Callable[[], str]:
    return lambda: pct(get(_row(gen), *path))


INLINE: dict[str, Callable[[], str]] = {
    "tasks": lambda: str(len(stats())),
    "bt_nodes": lambda: thousands(totals(list(stats()))["bt_nodes"]),
    "situations": lambda: thousands(totals(list(stats()))["trajectories"]),
    "decision_paths": lambda: thousands(totals(list(stats()))["decision_paths"]),
    "min_cover": lambda: thousands(totals(list(stats()))["min_cover"]),
    "killable": lambda: thousands(sum(killable().values())),
    "killable_per_task": lambda: f"{sum(killable().values()) / len(killable()):.1f}",
    "categories": lambda: str(len(json.loads((ROOT / "benchmark_data" / "catalog.json").read_text())
                                  ["categories"])),
    "mtsa_total": lambda: str(sum(int(r.split(" | ")[4]) for r in block_selectors().splitlines()[2:])),
    "exact_total": lambda: str(sum(int(r.split(" | ")[6]) for r in block_selectors().splitlines()[2:])),
    "logicenvgen_envs": lambda: str(int(_row("logicenvgen")["n_envs"])),
    "exact_envs": lambda: str(int(_row("logicenvgen-exact")["n_envs"])),
    "exact_fewer_envs": lambda: f"{100 * (1 - _row('logicenvgen-exact')['n_envs'] / _row('logicenvgen')['n_envs']):.0f}",
    "no_mtsa_envs": lambda: thousands(_row("logicenvgen-no-mtsa", "ablation")["n_envs"]),
    "no_mtsa_redundancy": lambda: f"{_row('logicenvgen-no-mtsa', 'ablation')['redundancy']:.1f}",
    "no_mtsa_ticks_ratio": lambda: f"{_row('logicenvgen-no-mtsa', 'ablation')['st_ticks'] / _row('logicenvgen', 'ablation')['st_ticks']:.1f}",
    "no_mtsa_logcov_gain": lambda: f"{100 * (_row('logicenvgen-no-mtsa', 'ablation')['logcov'] - _row('logicenvgen', 'ablation')['logcov']):+.2f}",
}


#: figures written as numbers, not percentages
PLAIN = ("ji", "redundancy", "st_ticks", "st_ms")


def data_figure(name: str) -> str | None:
    """`RUN.GENERATOR.METRIC[.SUB]` (RUN: reference or a run of `RUNS`), e.g.
    `reference.cot.phypr.floor_plan` -> 82.39, `ablation.logicenvgen-no-dbp.ji` -> 0.32."""
    parts = name.split(".")
    if len(parts) < 3 or (parts[0] != "reference" and parts[0] not in RUNS):
        return None
    value = get(_row(parts[1], parts[0]), *parts[2:])
    if parts[-1] == "n_envs":
        return thousands(value)
    return num(value) if parts[-1] in PLAIN else pct(value)


# ---------------------------------------------------------------- driver

def render(text: str) -> str:
    def block(m: re.Match[str]) -> str:
        name = m.group(2)
        if name == "paper-vs-ours":
            body = block_paper_vs_ours(m.group(3) or "")
        elif name in BLOCKS:
            body = BLOCKS[name]()
        else:
            raise SystemExit(f"unknown figures block {name!r}; known: {', '.join(sorted(BLOCKS))}")
        return m.group(1) + body + "\n" + m.group(4)

    def inline(m: re.Match[str]) -> str:
        name = m.group(2)
        value = INLINE[name]() if name in INLINE else data_figure(name)
        if value is None:
            raise SystemExit(f"unknown inline figure {name!r}; known: RUN.GENERATOR.METRIC or "
                             + ", ".join(sorted(INLINE)))
        return m.group(1) + value + m.group(4)

    return FIG.sub(inline, BLOCK.sub(block, text))


def differences(paths: Sequence[Path] = DOCS) -> list[str]:
    """Per file whose marked tables or figures differ from what the data gives, the first lines."""
    out = []
    for path in paths:
        text = path.read_text()
        new = render(text)
        if new != text:
            old_lines, new_lines = text.splitlines(), new.splitlines()
            diff = [f"{path.relative_to(ROOT) if path.is_relative_to(ROOT) else path}:{i + 1}: "
                    f"committed {a!r} but the data gives {b!r}"
                    for i, (a, b) in enumerate(zip(old_lines, new_lines, strict=False)) if a != b]
            out += diff[:5] or [f"{path}: line count differs"]
    return out


def rerun() -> None:
    """Re-run the runs the figures come from: the reference run and the others (`RUNS`)."""
    base = [sys.executable, "-m", "logicenveval", "run", "--model", "offline", "--quiet"]
    shutil.rmtree(REFERENCE, ignore_errors=True)  # a kept run folder would resume its old units
    subprocess.run([*base, "--output", str(REFERENCE.parent), "--run-id", REFERENCE.name],
                   check=True, cwd=ROOT)
    for name, args in RUNS.items():
        with tempfile.TemporaryDirectory() as tmp:
            cmd = [*base, *args, "--output", tmp, "--run-id", name]
            subprocess.run(cmd, check=True, cwd=ROOT)
            (FIGURES / name).mkdir(parents=True, exist_ok=True)
            for file in ("results.json", "leaderboard.md"):
                shutil.copy(Path(tmp) / name / file, FIGURES / name / file)
            (FIGURES / name / "COMMAND").write_text(
                "python -m logicenveval run --model offline " + " ".join(args) + "\n")


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="only compare; exit 1 on a difference")
    parser.add_argument("--rerun", action="store_true", help="re-run the source runs first")
    args = parser.parse_args(argv)
    if args.rerun:
        rerun()
    if args.check:
        diff = differences()
        for line in diff:
            print(line)
        if diff:
            print("docs tables differ from the data: run `python tools/docs_figures.py`")
        return 1 if diff else 0
    for path in DOCS:
        text = path.read_text()
        new = render(text)
        if new != text:
            path.write_text(new)
            print(f"rewrote {path.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
