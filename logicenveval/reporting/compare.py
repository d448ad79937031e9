"""Regression comparison of two runs (`compare RUN_A RUN_B`), for generators' CI.

Every metric has a direction. The comparison is paired over tasks: both runs' per-task figures
are resampled with the same task draws (and each run's seeds within a drawn task), giving a
95 % bootstrap interval of the difference B - A. A change is a regression only when it goes
against the metric's direction by more than the tolerance (absolute, in the metric's unit:
fractions for rates) AND its interval excludes 0, so noise from a few tasks is not flagged.
Results without per-task figures fall back to the tolerance alone (no interval). Timing (ST)
is shown but judged only when asked; runs over different task sets or task versions are refused
unless the comparison is restricted to the tasks they share.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from logicenveval.errors import ConfigError
from logicenveval.metrics.uncertainty import cells_of, paired_difference
from logicenveval.reporting.tables import COLUMNS, metric

#: metrics where lower is better; all others are better when higher
LOWER_IS_BETTER = frozenset({("st_ms",), ("st_ticks",), ("redundancy",)})
TIMING = frozenset({("st_ms",)})
NOT_JUDGED = frozenset({("n_envs",), ("n_failed",)})


@dataclass(frozen=True)
class Delta:
    generator: str
    metric: str
    before: float | None
    after: float | None
    regression: bool
    #: 95 % paired bootstrap interval of after - before (None without per-task figures)
    ci95: tuple[float, float] | None = None

    @property
    def change(self) -> float | None:
        if self.before is None or self.after is None:
            return None
        return self.after - self.before


def common_tasks(a: dict[str, Any], b: dict[str, Any], *, allow_subset: bool) -> list[str]:
    """The tasks both runs are compared on; refuses mismatched sets unless `allow_subset`."""
    ta, tb = list(a.get("tasks", [])), list(b.get("tasks", []))
    ha = a.get("benchmark", {}).get("task_sha256", {})
    hb = b.get("benchmark", {}).get("task_sha256", {})
    changed = sorted(t for t in set(ta) & set(tb) if t in ha and t in hb and ha[t] != hb[t])
    common = [t for t in ta if t in set(tb) and t not in changed]
    if not allow_subset:
        if set(ta) != set(tb):
            only_a, only_b = sorted(set(ta) - set(tb)), sorted(set(tb) - set(ta))
            raise ConfigError(f"the runs cover different tasks (only in A: {only_a[:5]}, only in "
                              f"B: {only_b[:5]})", field="tasks",
                              hint="re-run on the same tasks, or pass --common-tasks")
        if changed:
            raise ConfigError(f"task(s) {changed[:5]} differ between the runs' benchmark versions",
                              field="benchmark", hint="re-run both on the same benchmark, or "
                              "pass --common-tasks to compare the unchanged tasks only")
    if not common:
        raise ConfigError("the runs share no task", field="tasks", hint="compare runs of one benchmark")
    return common


def compare_results(
    a: dict[str, Any], b: dict[str, Any], *, tolerance: float = 0.02, judge_timing: bool = False,
    common: list[str] | None = None, n_bootstrap: int = 2000,
) -> list[Delta]:
    out: list[Delta] = []
    rng = np.random.default_rng([0, 95])
    generators = list(a["results"]) + [g for g in b["results"] if g not in a["results"]]
    for gen in generators:
        va, vb = a["results"].get(gen), b["results"].get(gen)
        paired = _paired(a, b, gen, common, rng, n_bootstrap) if va and vb else None
        for header, path, _ in COLUMNS:
            judged = path not in NOT_JUDGED and (judge_timing or path not in TIMING)
            if paired is not None and path in paired:
                diff, lo, hi = paired[path]
                before = _point(a, gen, path, common)
                after = None if before is None else before + diff
                worse = diff > tolerance and lo > 0 if path in LOWER_IS_BETTER else (
                    -diff > tolerance and hi < 0)
                out.append(Delta(gen, header, before, after, judged and worse, (lo, hi)))
                continue
            before = metric(va, path) if va is not None else None
            after = metric(vb, path) if vb is not None else None
            if before is None or after is None:
                regression = False  # a row missing on one side is reported, not judged
            elif path in LOWER_IS_BETTER:
                regression = judged and after - before > tolerance
            else:
                regression = judged and before - after > tolerance
            out.append(Delta(gen, header, before, after, regression))
    return out


def _restrict(cells: dict[tuple[str, int], Any], common: list[str] | None) -> dict[tuple[str, int], Any]:
    return cells if common is None else {k: v for k, v in cells.items() if k[0] in set(common)}


def _paired(a: dict[str, Any], b: dict[str, Any], gen: str, common: list[str] | None,
            rng: np.random.Generator, n: int) -> dict[tuple[str, ...], tuple[float, float, float]] | None:
    ca, cb = _restrict(cells_of(a, gen), common), _restrict(cells_of(b, gen), common)
    if not ca or not cb or {t for t, _ in ca} != {t for t, _ in cb}:
        return None
    return paired_difference(ca, cb, rng, n)


def _point(results: dict[str, Any], gen: str, path: tuple[str, ...], common: list[str] | None) -> float | None:
    """The metric over the compared tasks (equal to results.<gen> when all tasks are compared)."""
    if common is None or set(common) == set(results.get("tasks", [])):
        return metric(results["results"][gen], path)
    from logicenveval.metrics.uncertainty import point_metrics

    cells = _restrict(cells_of(results, gen), common)
    return metric(point_metrics(list(cells.values())), path)
