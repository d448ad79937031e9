"""Bootstrap intervals over tasks (and seeds) for the leaderboard rates, and paired differences.

The unit of resampling is the task: a benchmark score is a mean over tasks, and tasks, not
environments, are what a different benchmark draw would change. With several seeds, each drawn
task also redraws its seeds (a two-level bootstrap), so seed-to-seed variation widens the
interval. A metric is recomputed from per-cell (task, seed) counts exactly as `aggregate` does:
PhyPR and SceVR are shares of all environment slots, the others means over cells. Draws come
from an explicit `numpy.random.Generator` with a fixed seed (`bootstrap_rng`): an interval is a
function of the per-task figures alone, so the same environments scored under another row name,
run seed or run give the same interval. With fewer than two tasks there is nothing to resample:
the interval is `None` (shown as n/a).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from logicenveval.errors import MetricsError
from logicenveval.model.task import FAULTY_KINDS

#: resamples per interval; 2,000 keeps the 2.5/97.5 percentiles stable to ~0.1 point
N_BOOTSTRAP = 2000
#: the bootstrap's seed: fixed, never derived from a row name or the run seed
BOOTSTRAP_SEED = 95
#: an interval needs at least this many distinct tasks (one task resamples to itself)
MIN_TASKS = 2

#: path into results.<generator> -> the per-cell column it is computed from
_Path = tuple[str, ...]
_RATIOS: dict[_Path, str] = {("phypr", "floor_plan"): "n_floor_plan_ok", ("phypr", "entity"): "n_entity_ok",
           ("phypr", "relation"): "n_relation_ok", ("scevr",): "n_valid"}
_MEANS: dict[_Path, str] = {("logcov",): "logcov", ("ld",): "ld", ("ji",): "ji",
          **{("faudr", k): f"faudr_{k}" for k in FAULTY_KINDS}}
#: figures reported but not given intervals in results.json (compare still pairs them)
_OTHER_MEANS: dict[_Path, str] = {("redundancy",): "redundancy", ("st_ms",): "st_ms",
                                  ("st_ticks",): "st_ticks"}
_OTHER_RATIOS: dict[_Path, str] = {("plausibility", "rate"): "n_extended_ok"}
#: per-task figures a task without environments does not have (means over the tasks that do)
_PRESENT_ONLY = frozenset({"redundancy", "st_ms", "st_ticks"})
CI_METRICS: tuple[tuple[str, ...], ...] = (
    *_RATIOS, ("phypr", "avg"), *_MEANS, ("faudr", "avg"))

Cell = Mapping[str, Any]  # one TaskMetrics as JSON (results.json per_task entries)


def _columns(cells: Sequence[Cell]) -> dict[str, np.ndarray]:
    cols = {name: np.array([float(c.get(name) or 0.0) for c in cells])
            for name in ("n_floor_plan_ok", "n_entity_ok", "n_relation_ok", "n_valid", "logcov",
                         "ld", "ji", "redundancy", "st_ms", "st_ticks", "n_extended_ok")}
    for name in _PRESENT_ONLY:  # null for a task without environments: left out, never 0
        cols[f"{name}_present"] = np.array([0.0 if c.get(name, 0.0) is None else 1.0 for c in cells])
    cols["slots"] = np.array([float(c["n_envs"]) + float(c.get("n_failed", 0)) for c in cells])
    for k in FAULTY_KINDS:
        cols[f"faudr_{k}"] = np.array([float(bool(c["faudr"][k])) for c in cells])
    mut = [c.get("faudr_mut") for c in cells]  # None where the task has no mutants scored
    cols["faudr_mut"] = np.array([float(m) if m is not None else 0.0 for m in mut])
    cols["faudr_mut_scored"] = np.array([0.0 if m is None else 1.0 for m in mut])
    return cols


def metrics_from_weights(cells: Sequence[Cell], weights: np.ndarray) -> dict[tuple[str, ...], np.ndarray]:
    """Every metric for each row of `weights` (draws x cells): counts of each cell in a draw."""
    cols = _columns(cells)
    w = np.atleast_2d(weights).astype(float)
    total = w.sum(axis=1)
    slots = w @ cols["slots"]
    out: dict[tuple[str, ...], np.ndarray] = {}
    with np.errstate(invalid="ignore", divide="ignore"):
        for path, col in {**_RATIOS, **_OTHER_RATIOS}.items():
            out[path] = np.where(slots > 0, (w @ cols[col]) / slots, 0.0)
        for path, col in {**_MEANS, **_OTHER_MEANS}.items():
            if col in _PRESENT_ONLY:
                present = w @ cols[f"{col}_present"]
                out[path] = np.where(present > 0, (w @ (cols[col] * cols[f"{col}_present"])) / present, np.nan)
            else:
                out[path] = (w @ cols[col]) / total
        scored = w @ cols["faudr_mut_scored"]
        out[("faudr_mut",)] = np.where(scored > 0, (w @ (cols["faudr_mut"] * cols["faudr_mut_scored"]))
                                       / scored, np.nan)
    out[("phypr", "avg")] = (out[("phypr", "floor_plan")] + out[("phypr", "entity")]
                             + out[("phypr", "relation")]) / 3
    out[("faudr", "avg")] = np.mean([out[("faudr", k)] for k in FAULTY_KINDS], axis=0)
    return out


def point_metrics(cells: Sequence[Cell]) -> dict[str, Any]:
    """`results.<generator>` over all cells (every task and seed counted once)."""
    m = {p: float(v[0]) for p, v in metrics_from_weights(cells, np.ones((1, len(cells)))).items()}
    nested: dict[str, Any] = {"n_envs": int(sum(int(c["n_envs"]) for c in cells)),
                              "n_failed": int(sum(int(c.get("n_failed", 0)) for c in cells))}
    nested["n_attempted"] = nested["n_envs"] + nested["n_failed"]
    for path, value in m.items():
        _put(nested, path, None if np.isnan(value) else value)
    by_class: dict[str, list[float]] = {}
    for c in cells:
        if c.get("faudr_mut") is not None:
            for cls, v in (c.get("faudr_mut_by_class") or {}).items():
                by_class.setdefault(cls, []).append(float(v))
    nested["faudr_mut_by_class"] = {k: sum(v) / len(v) for k, v in sorted(by_class.items())}
    codes: Counter[str] = Counter()
    for c in cells:
        codes.update(c.get("extended_codes") or {})
    nested["plausibility"]["codes"] = dict(sorted(codes.items()))
    return nested


def _put(tree: dict[str, Any], path: tuple[str, ...], value: object) -> None:
    for key in path[:-1]:
        tree = tree.setdefault(key, {})
    tree[path[-1]] = value


def _weights(groups: Sequence[Sequence[int]], task_draw: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Weights (draws x cells) for drawn tasks (draws x tasks); each drawn task redraws its seeds."""
    s = len(groups[0])
    if any(len(g) != s for g in groups):
        raise MetricsError("tasks have different numbers of seeds", field="per_task",
                           hint="bootstrap runs in which every task ran with every seed")
    table = np.array(groups)  # tasks x seeds -> cell index
    n, t = task_draw.shape
    n_cells = table.size
    picks = table[task_draw[..., None], rng.integers(0, s, size=(n, t, s))].reshape(n, t * s)
    flat = (picks + np.arange(n)[:, None] * n_cells).ravel()
    return np.bincount(flat, minlength=n * n_cells).reshape(n, n_cells)


def _groups(keys: Sequence[tuple[str, int]]) -> tuple[list[str], list[list[int]]]:
    order: dict[str, list[int]] = {}
    for i, (task, _seed) in enumerate(keys):
        order.setdefault(task, []).append(i)
    return list(order), list(order.values())


def bootstrap_rng() -> np.random.Generator:
    """The bootstrap's own stream, the same for every row: intervals depend on the data only."""
    return np.random.default_rng(BOOTSTRAP_SEED)


def ci95(cells: Mapping[tuple[str, int], Cell], rng: np.random.Generator | None = None,
         n: int = N_BOOTSTRAP) -> dict[str, Any]:
    """95 % percentile intervals `[lo, hi]` of every `CI_METRICS` rate, nested like results;
    `None` for each when the cells cover fewer than `MIN_TASKS` tasks."""
    if not cells:
        raise MetricsError("no per-task metrics", field="per_task", hint="evaluate at least one task")
    keys = sorted(cells)
    _, groups = _groups(keys)
    out: dict[str, Any] = {}
    if len(groups) < MIN_TASKS:
        for path in CI_METRICS:
            _put(out, path, None)
        return out
    rng = bootstrap_rng() if rng is None else rng
    weights = _weights(groups, rng.integers(0, len(groups), size=(n, len(groups))), rng)
    draws = metrics_from_weights([cells[k] for k in keys], weights)
    for path in CI_METRICS:
        lo, hi = np.percentile(draws[path], [2.5, 97.5])
        _put(out, path, [float(lo), float(hi)])
    return out


def paired_cells(a: Mapping[tuple[str, int], Cell], b: Mapping[tuple[str, int], Cell]
                 ) -> tuple[dict[tuple[str, int], Cell], dict[tuple[str, int], Cell]]:
    """Both sides with ST and Redundancy nulled on the tasks where either side lacks them (a task
    without environments): a paired figure compares the same tasks, so failing a task never
    looks faster or leaner."""
    out_a, out_b = dict(a), dict(b)
    for name in _PRESENT_ONLY:
        lacking = {k[0] for side in (a, b) for k, c in side.items() if c.get(name, 0.0) is None}
        for side in (out_a, out_b):
            for k, c in side.items():
                if k[0] in lacking and c.get(name, 0.0) is not None:
                    side[k] = {**c, name: None}
    return out_a, out_b


def paired_difference(a: Mapping[tuple[str, int], Cell], b: Mapping[tuple[str, int], Cell],
                      rng: np.random.Generator | None = None, n: int = N_BOOTSTRAP
                      ) -> dict[tuple[str, ...], tuple[float, float | None, float | None]]:
    """Per metric: (b - a, lo, hi), resampling the same tasks for both sides in every draw.

    Both sides must cover the same tasks (pass only the common ones); each side's seeds of a
    drawn task are redrawn independently. With fewer than `MIN_TASKS` tasks `lo`, `hi` are None.
    """
    a, b = paired_cells(a, b)
    ka, kb = sorted(a), sorted(b)
    tasks_a, groups_a = _groups(ka)
    tasks_b, groups_b = _groups(kb)
    if tasks_a != tasks_b:
        raise MetricsError("paired runs cover different tasks", field="per_task",
                           hint="compare over the common tasks (--common-tasks)")
    if not ka:
        raise MetricsError("no common task to compare", field="per_task", hint="check the run folders")
    cells_a, cells_b = [a[k] for k in ka], [b[k] for k in kb]
    pa = metrics_from_weights(cells_a, np.ones((1, len(ka))))
    pb = metrics_from_weights(cells_b, np.ones((1, len(kb))))
    if len(tasks_a) < MIN_TASKS:
        return {path: (float(pb[path][0] - pa[path][0]), None, None) for path in pa
                if not (np.isnan(pa[path][0]) or np.isnan(pb[path][0]))}
    rng = bootstrap_rng() if rng is None else rng
    task_draw = rng.integers(0, len(tasks_a), size=(n, len(tasks_a)))
    wa, wb = _weights(groups_a, task_draw, rng), _weights(groups_b, task_draw, rng)
    da, db = metrics_from_weights(cells_a, wa), metrics_from_weights(cells_b, wb)
    out: dict[tuple[str, ...], tuple[float, float | None, float | None]] = {}
    for path in da:
        if np.isnan(pa[path][0]) or np.isnan(pb[path][0]):
            continue  # a figure one of the runs does not have (e.g. no mutants scored)
        lo, hi = np.nanpercentile(db[path] - da[path], [2.5, 97.5])
        out[path] = (float(pb[path][0] - pa[path][0]), float(lo), float(hi))
    return out


def measured(cell: Cell) -> bool:
    """A per-task cell with figures (a task that was not measured has `n_envs` null)."""
    return cell.get("n_envs") is not None


def cells_of(results: Mapping[str, Any], generator: str) -> dict[tuple[str, int], Cell]:
    """(task, seed) -> per-task metrics of one generator, from a single- or multi-seed results;
    tasks the generator was not measured on are left out."""
    skip = set((results.get("results", {}).get(generator) or {}).get("not_measured_tasks") or ())
    if "per_task_seed" in results:
        per = results["per_task_seed"].get(generator, {})
        cells = {(task, int(seed)): m for task, by_seed in per.items() for seed, m in by_seed.items()}
    else:
        seed = int(results.get("seed") or 0)
        cells = {(task, seed): m for task, m in results.get("per_task", {}).get(generator, {}).items()}
    return {k: m for k, m in cells.items() if k[0] not in skip and measured(m)}
