"""Turning committed units into `results.json` and `samples.jsonl` (DESIGN.md §7, §9).

Everything but the `timing` block, `st_ms` and `sim_ms` is a pure function of the units, so the
same command gives byte-identical files apart from those timing fields.
"""

from __future__ import annotations

import hashlib
import importlib.metadata
import json
import math
import platform
import subprocess
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any, Protocol

from logicenveval.atomic import atomic_write_text
from logicenveval.llm.base import KIND_PREFIX
from logicenveval.llm.registry import request_protocol
from logicenveval.metrics.compute import TaskMetrics, aggregate, null_metrics, task_metrics
from logicenveval.metrics.records import UnitRecord
from logicenveval.metrics.uncertainty import ci95
from logicenveval.model.task import FAULTY_KINDS, Task
from logicenveval.paths import shown

RESULTS_SCHEMA = "logicenveval.results/1"
_VERSIONED = ("logicenveval", "numpy", "pydantic", "z3-solver", "py-trees", "trimesh",
              "python-fcl", "shapely", "ortools", "pandas")


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


def unit_metrics(task: Task, unit: UnitRecord) -> TaskMetrics:
    """A measured unit's figures (results.json `per_task`), a pure function of the unit."""
    return task_metrics(task, unit.samples, n_failed=unit.n_failed, mutants=unit.mutants or None,
                        reported=[a.target for a in unit.attempts],
                        claims_realised=[a.realised for a in unit.attempts if a.realised is not None])


def per_task_entry(metrics: TaskMetrics, unit: UnitRecord) -> dict[str, Any]:
    """A unit's `per_task` entry of results.json."""
    return {**metrics.model_dump(mode="json"), "budget_hit": unit.budget_hit is not None}


def unit_failures(unit: UnitRecord) -> tuple[list[dict[str, Any]], list[dict[str, Any]]]:
    """A unit's entries of results.json `failures`: its error (a unit failed as a whole), then
    each generation failure, then the reason of every failed attempt that no failure states
    (counted: `attempts`), so every reason a row's failed column counts is on record. IFG's
    attempts for the intents a reply did not give were counted failed, but said nowhere
    (Qwen2.5-Coder-1.5B: 21 of 24)."""
    error = [{"task": unit.task_id, "stage": "unit", "message": unit.error, "kind": unit.error_kind,
              "attempts": unit.n_failed}] if unit.error else []
    found = [{"task": unit.task_id, **f.model_dump(mode="json")} for f in unit.failures]
    if unit.error:
        return error, found
    stated = {f.message for f in unit.failures}
    unstated: dict[tuple[str, str], list[str]] = {}
    for a in unit.attempts:
        if a.reason is not None and a.reason not in stated:
            unstated.setdefault((a.stage or "generation", a.reason), []).append(a.id)
    return error, found + [{"task": unit.task_id, "stage": stage, "message": reason,
                            **({"env_id": ids[0]} if len(ids) == 1 else {}), "attempts": len(ids)}
                           for (stage, reason), ids in unstated.items()]


def build_results(
    config: ResultsConfig,
    tasks: Sequence[Task],
    records: Sequence[UnitRecord],
    *,
    wall_seconds: float | None = None,
    generators: Sequence[str] | None = None,
    computed: Mapping[tuple[str, str], TaskMetrics] | None = None,
) -> dict[str, Any]:
    """`generators` are the row names (plug-ins' `name` attributes); default: config.generators.
    `computed`: figures of units already worked out (`unit_metrics`, by the workers that ran
    them), by (generator, task); the others are worked out here."""
    by_task = {t.id: t for t in tasks}
    computed = computed or {}
    results: dict[str, Any] = {}
    per_task: dict[str, Any] = {}
    failures: dict[str, list[dict[str, Any]]] = {}
    gen_seconds: dict[str, float] = {}
    llm: dict[str, dict[str, float]] = {}
    validity: dict[str, dict[str, dict[str, float]]] = {}
    for gen in (config.generators if generators is None else generators):
        units = [r for r in records if r.generator == gen]
        measured = [u for u in units if u.measured]
        metrics = [computed.get((u.generator, u.task_id)) or unit_metrics(by_task[u.task_id], u)
                   for u in measured]
        per_task[gen] = {u.task_id: per_task_entry(m, u) for u, m in zip(measured, metrics, strict=True)}
        if metrics:
            results[gen] = aggregate(metrics).model_dump(mode="json")
            results[gen]["ci95"] = ci95({(t, config.seed): m for t, m in per_task[gen].items()})
        else:  # not measured: null figures, never zeros
            results[gen] = {**null_metrics(), "ci95": {}}
        results[gen].update(row_status(
            measured=bool(metrics), not_measured=[u.task_id for u in units if not u.measured],
            budget_hit=[u.task_id for u in measured if u.budget_hit is not None]))
        listed = [unit_failures(u) for u in units]
        failures[gen] = [f for errors, _ in listed for f in errors] + [f for _, found in listed for f in found]
        gen_seconds[gen] = round(sum(u.gen_seconds for u in units), 3)
        llm[gen] = {k: round(sum(u.llm.get(k, 0.0) for u in units), 3)
                    for k in sorted({k for u in units for k in u.llm}) if not k.startswith(KIND_PREFIX)}
        validity[gen] = reply_validity(units)
    return {
        "schema": RESULTS_SCHEMA,
        "run_id": config.resolved_run_id(),
        "config": config.identity(),
        "model": config.model,
        "seed": config.seed,
        "brief": config.brief,
        # a model's run: the protocol its requests were asked in (what a replay must ask)
        **({"protocol": request_protocol(model_args)}
           if isinstance(model_args := getattr(config, "model_args", None), str) else {}),
        "tasks": [t.id for t in tasks],
        "benchmark": {"task_sha256": task_hashes(tasks)},
        "versions": package_versions(),
        "git_commit": git_commit(),
        "generators": list(results),
        "results": results,
        "per_task": per_task,
        "failures": failures,
        "llm": validity,
        "timing": {
            "wall_seconds": None if wall_seconds is None else round(wall_seconds, 3),
            "generation_seconds": gen_seconds,
            "llm": llm,
            "phases": phase_seconds(records, list(gen_seconds)),
            "per_task": {gen: {u.task_id: unit_cost(u) for u in records if u.generator == gen}
                         for gen in gen_seconds},
        },
    }


#: what one unit cost, per generator and task (results.json `timing.per_task`)
COST_KEYS = ("requests", "cache_hits", "reasks", "prompt_tokens", "completion_tokens", "latency_s",
             "recorded_replies", "recorded_prompt_tokens", "recorded_completion_tokens", "recorded_seconds")


def unit_cost(unit: UnitRecord) -> dict[str, float]:
    """A unit's generation seconds and model traffic: a user planning a run on a slow model
    reads what each method asked of a task (a 1.5B model on 2 cores: hours per method)."""
    return {"generation_seconds": round(unit.gen_seconds, 3),
            **{k: round(float(unit.llm.get(k, 0.0)), 3) for k in COST_KEYS}}


def phase_seconds(records: Sequence[UnitRecord], generators: Sequence[str]) -> dict[str, dict[str, float]]:
    """Per generator, the seconds its units spent per phase (`UnitRecord.phases`), summed."""
    out: dict[str, dict[str, float]] = {}
    for gen in generators:
        row: dict[str, float] = {}
        for u in records:
            if u.generator == gen:
                for name, seconds in u.phases.items():
                    row[name] = row.get(name, 0.0) + seconds
        out[gen] = {k: round(v, 3) for k, v in sorted(row.items())}
    return out


def reply_validity(units: Sequence[UnitRecord]) -> dict[str, dict[str, float]]:
    """Per request kind (and `all`): questions asked, attempts sent, valid first replies, valid
    after re-asks, attempts cut at max_tokens, and the two shares (docs/llm.md)."""
    counts: dict[str, dict[str, float]] = {}
    for u in units:
        for key, value in u.llm.items():
            if key.startswith(KIND_PREFIX):
                kind, _, counter = key[len(KIND_PREFIX):].rpartition(".")
                for name in (kind, "all"):
                    row = counts.setdefault(name, {})
                    row[counter] = row.get(counter, 0) + value
    for row in counts.values():
        # a question whose request the unit's budget cut short was never answered: the shares
        # count answered questions (runs recorded before the `answered` counter count all)
        asked = row.get("answered", row.get("questions", 0))
        for counter in ("questions", "attempts", "valid_first", "valid", "truncated"):
            row[counter] = int(row.get(counter, 0))
        for counter in ("answered", "meaningless", "clamped"):
            if counter in row:
                row[counter] = int(row[counter])
        row["valid_first_share"] = round(row["valid_first"] / asked, 4) if asked else 0.0
        row["valid_share"] = round(row["valid"] / asked, 4) if asked else 0.0
    return dict(sorted(counts.items()))


#: keys of `results.<generator>` that are not figures (checked apart from the numeric leaves)
STATUS_KEYS = ("measured", "not_measured_tasks", "budget_hit_tasks")


def row_status(*, measured: bool, not_measured: Sequence[str], budget_hit: Sequence[str]) -> dict[str, Any]:
    """What a row is besides its figures: measured at all (False: every unit failed for
    infrastructure reasons, so every figure is null), the tasks left out as not measured, and
    the tasks where a search stopped at its budget (the leaderboard labels such rows)."""
    return {"measured": measured, "not_measured_tasks": sorted(not_measured),
            "budget_hit_tasks": sorted(budget_hit)}


def write_outputs(run_dir: Path, results: dict[str, Any], records: Sequence[UnitRecord]) -> None:
    lines = [json.dumps(s.model_dump(mode="json"), sort_keys=True, separators=(",", ":"))
             for r in records for s in r.samples]
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
    return in_run_order(data)


def in_run_order(data: dict[str, Any]) -> dict[str, Any]:
    """`results` in the run's row order (`generators`; results.json is written with sorted keys,
    so without it a report would list the rows alphabetically, unlike the run's own leaderboard).
    A file written before `generators` existed is ordered by the generators its `config` asked
    for (built-in row names are those names). Rows neither list names (a plug-in's row, a file
    edited by hand) follow in the file's order."""
    rows = data["results"]
    config = data.get("config")
    asked = config.get("generators") if isinstance(config, dict) else None
    listed = data.get("generators") or (asked if isinstance(asked, list) else [])
    order = [g for g in dict.fromkeys(listed) if isinstance(g, str) and g in rows]
    return {**data, "results": {**{g: rows[g] for g in order}, **rows}}


#: per-task figures that reports and comparisons compute with (`metrics.uncertainty`)
_CELL_NUMBERS = ("n_envs", "n_failed", "n_attempted", "n_floor_plan_ok", "n_entity_ok",
                 "n_relation_ok", "n_valid", "n_extended_ok", "logcov", "ld", "ji", "ji_fixed", "redundancy",
                 "st_ms", "st_ticks", "faudr_mut")
#: keys of `results.<generator>` that hold lists of task ids, and those that hold a flag
_ROW_TASK_LISTS = ("not_measured_tasks", "budget_hit_tasks")
_ROW_FLAGS = ("measured",)


class _Damaged(Exception):
    def __init__(self, field: str, what: str) -> None:
        super().__init__(what)
        self.field, self.what = field, what


def _check_results(data: dict[str, Any], file: str) -> None:
    """Every field `report` and `compare` read has the type they read it as (else the field)."""
    from logicenveval.errors import RunStoreError

    try:
        _check_top(data)
    except _Damaged as exc:
        raise RunStoreError(exc.what, file=file, field=exc.field,
                            hint="the file was edited or damaged; re-run the command to rewrite it") from None


def _need(ok: bool, field: str, what: str) -> None:
    if not ok:
        raise _Damaged(field, what)


#: the largest integer a results file holds (counts, seeds < 2**63): JSON lets an integer have
#: hundreds of digits, which no float can hold (OverflowError wherever it is computed with)
MAX_INT = 2**63


def _is_number(v: object) -> bool:
    if isinstance(v, int) and not isinstance(v, bool):
        return -MAX_INT <= v <= MAX_INT
    return isinstance(v, float) and math.isfinite(v)


def _not_finite(v: object) -> str:
    if isinstance(v, int):  # never printed: a 400-digit number floods the message
        return f"an integer of {v.bit_length()} bits is out of range (at most 2**63)"
    return f"{v!r} is not a finite number"


def _check_leaves(where: str, value: object) -> None:
    """No NaN or infinity anywhere (JSON has none; a file holding them was not written by us)."""
    stack: list[tuple[str, object]] = [(where, value)]
    while stack:
        at, v = stack.pop()
        if isinstance(v, dict):
            stack += [(f"{at}.{k}", x) for k, x in v.items()]
        elif isinstance(v, list):
            stack += [(f"{at}.{i}", x) for i, x in enumerate(v)]
        else:
            _need(not isinstance(v, int | float) or isinstance(v, bool) or _is_number(v), at,
                  _not_finite(v))


def _check_top(data: dict[str, Any]) -> None:
    _need(isinstance(data["results"], dict), "results", "must be an object of generators")
    for key, section in data.items():  # every section a report shows (llm, timing, ...) too
        _check_leaves(key, section)
    order = data.get("generators", [])
    _need(isinstance(order, list) and all(isinstance(g, str) for g in order), "generators",
          "must be a list of generator names (the row order)")
    tasks = data.get("tasks", [])
    _need(isinstance(tasks, list) and all(isinstance(t, str) for t in tasks), "tasks",
          "must be a list of task ids")
    for key in ("run_id", "model"):
        _need(isinstance(data.get(key, ""), str), key, "must be a string")
    seeds = data.get("seeds")
    _need(seeds is None or (isinstance(seeds, list) and all(_is_number(s) for s in seeds)),
          "seeds", "must be a list of integers")
    _need(data.get("seed") is None or _is_number(data["seed"]), "seed", "must be an integer")
    bench = data.get("benchmark", {})
    _need(isinstance(bench, dict), "benchmark", "must be an object")
    hashes = bench.get("task_sha256", {})
    _need(isinstance(hashes, dict) and all(isinstance(v, str) for v in hashes.values()),
          "benchmark.task_sha256", "must map task ids to digests")
    for gen, values in data["results"].items():
        _check_row(f"results.{gen}", values)
    for section, depth in (("per_task", 2), ("per_task_seed", 3)):
        _check_cells(section, data.get(section, {}), depth)
    failures = data.get("failures", {})
    _need(isinstance(failures, dict), "failures", "must be an object of generators")
    for gen, items in failures.items():
        _need(isinstance(items, list) and all(isinstance(f, dict) for f in items),
              f"failures.{gen}", "must be a list of failures")
    _need(isinstance(data.get("runs", {}), dict), "runs", "must map seeds to folders")
    _check_consistent(data)


#: metrics stored as fractions in [0, 1] (shown as percentages), with everything nested under them
_RATES = frozenset({"logcov", "ld", "ji", "scevr", "faudr", "faudr_mut", "faudr_mut_by_class",
                    "phypr", "plausibility.rate"})


def _is_rate(path: tuple[str, ...]) -> bool:
    return bool(path) and (path[0] in _RATES or ".".join(path[:2]) in _RATES)


def _check_consistent(data: dict[str, Any]) -> None:
    """Values a run cannot have produced: a rate outside [0, 1] (shown as 0-100 %), an interval
    whose low end is above its high end, more failed than attempted environments, a row order
    naming a row twice, a row it does not name, a task cell of a task it does not list (a row
    it names without results is a lost generator, which `compare` reports)."""
    rows: dict[str, Any] = data["results"]
    order = data.get("generators")
    if order is not None:
        twice = sorted({g for g in order if order.count(g) > 1})
        _need(not twice, "generators", f"names {shown(twice[0])} more than once" if twice else "")
        unknown = [g for g in rows if g not in order]
        _need(not unknown, f"results.{unknown[0] if unknown else ''}",
              "is a row the file's `generators` does not list")
    tasks = data.get("tasks")
    for gen, cells in data.get("per_task", {}).items():
        stray = [t for t in cells if tasks and t not in tasks]
        _need(not stray, f"per_task.{gen}.{stray[0] if stray else ''}",
              "is a task the file's `tasks` does not list")
    for gen, values in rows.items():
        _check_numbers(f"results.{gen}", values)
    for section, depth in (("per_task", 2), ("per_task_seed", 3)):
        stack: list[tuple[str, Any, int]] = [(section, data.get(section, {}), depth)]
        while stack:
            where, node, left = stack.pop()
            if left:
                stack += [(f"{where}.{k}", v, left - 1) for k, v in node.items()]
            else:
                _check_numbers(where, node)


def _check_numbers(where: str, values: dict[str, Any]) -> None:
    """Rates in [0, 1], intervals ordered, n_failed <= n_attempted in one row or cell."""
    stack: list[tuple[tuple[str, ...], object]] = [((k,), v) for k, v in values.items()]
    while stack:
        path, v = stack.pop()
        at = ".".join((where, *path))
        if path[0] == "ci95":
            if isinstance(v, dict):
                stack += [((*path, k), x) for k, x in v.items()]
            elif isinstance(v, list):
                lo, hi = v
                _need(lo <= hi, at, f"interval [{lo:.4g}, {hi:.4g}] has its low end above its high end")
                _need(not _is_rate(path[1:]) or (lo >= 0 and hi <= 1), at,
                      f"interval [{lo:.4g}, {hi:.4g}] of a rate is outside [0, 1] (0-100 %)")
        elif isinstance(v, dict):
            stack += [((*path, k), x) for k, x in v.items()]
        elif _is_rate(path) and isinstance(v, int | float) and _is_number(v):
            _need(0 <= v <= 1, at, f"rate {v:.4g} is outside [0, 1] (shown as {100 * v:.4g} %)")
    failed, attempted = values.get("n_failed"), values.get("n_attempted")
    if isinstance(failed, int | float) and isinstance(attempted, int | float) \
            and _is_number(failed) and _is_number(attempted):
        _need(failed <= attempted, f"{where}.n_failed",
              f"{failed} failed environments are more than the {attempted} attempted")


def _check_row(where: str, values: object) -> None:
    _need(isinstance(values, dict), where, "must be an object of metrics")
    assert isinstance(values, dict)
    _check_leaves(where, values)
    stack: list[tuple[str, str, object]] = [(where, k, v) for k, v in values.items()]
    while stack:  # every leaf of the (nested) metrics is a number or null
        parent, key, v = stack.pop()
        at = f"{parent}.{key}"
        if parent == where and key in _ROW_FLAGS:
            _need(isinstance(v, bool), at, "must be true or false")
        elif parent == where and key in _ROW_TASK_LISTS:
            _need(isinstance(v, list) and all(isinstance(t, str) for t in v), at, "must be a list of task ids")
        elif parent == where and key == "ci95":
            _check_intervals(at, v)
        elif parent == where and key in ("n_envs", "n_attempted", "n_failed"):
            _need(v is None or (isinstance(v, int | float) and _is_number(v) and v >= 0), at,
                  f"{str(v)[:40]!r} is not a count")
        elif isinstance(v, dict):
            stack += [(at, k, x) for k, x in v.items()]
        else:
            _need(v is None or _is_number(v), at, f"metric value {str(v)[:40]!r} is not a number")


def _check_intervals(where: str, tree: object) -> None:
    _need(isinstance(tree, dict), where, "must be an object of intervals")
    assert isinstance(tree, dict)
    for key, v in tree.items():
        at = f"{where}.{key}"
        if isinstance(v, dict):
            _check_intervals(at, v)
        else:
            _need(v is None or (isinstance(v, list) and len(v) == 2 and all(_is_number(x) for x in v)),
                  at, "must be an interval [lo, hi] or null")


def _check_cells(section: str, tree: object, depth: int) -> None:
    """`per_task.<gen>.<task>` (depth 2) or `per_task_seed.<gen>.<task>.<seed>` (depth 3)."""
    stack: list[tuple[str, object, int]] = [(section, tree, depth)]
    while stack:
        where, node, left = stack.pop()
        _need(isinstance(node, dict), where, "must be an object" if left else "must be an object of metrics")
        assert isinstance(node, dict)
        if left:
            stack += [(f"{where}.{k}", v, left - 1) for k, v in node.items()]
            continue
        _check_leaves(where, node)
        for key in _CELL_NUMBERS:
            v = node.get(key)
            _need(v is None or _is_number(v), f"{where}.{key}", f"{str(v)[:40]!r} is not a number")
        if node.get("n_envs") is None:
            continue  # a task that was not measured has no figures
        faudr = node.get("faudr")
        _need(isinstance(faudr, dict) and all(isinstance(faudr.get(k), bool | int | float) for k in FAULTY_KINDS),
              f"{where}.faudr", f"must map each fault kind ({', '.join(FAULTY_KINDS)}) to true/false")
        for key in ("faudr_mut_by_class", "extended_codes"):
            sub = node.get(key) or {}
            _need(isinstance(sub, dict) and all(_is_number(v) for v in sub.values()),
                  f"{where}.{key}", "must map names to numbers")
