"""Regression comparison of two runs (`compare RUN_A RUN_B`), for generators' CI.

Every metric has a direction; a change against that direction larger than the tolerance
(absolute, in the metric's own unit: fractions for rates) is a regression. Timing (ST) is shown
but only judged when asked, because wall time depends on the machine.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from logicenveval.reporting.tables import COLUMNS, metric

#: metrics where lower is better; all others are better when higher
LOWER_IS_BETTER = frozenset({("st_ms",), ("st_ticks",), ("redundancy",)})
TIMING = frozenset({("st_ms",)})
NOT_JUDGED = frozenset({("n_envs",)})


@dataclass(frozen=True)
class Delta:
    generator: str
    metric: str
    before: float | None
    after: float | None
    regression: bool

    @property
    def change(self) -> float | None:
        if self.before is None or self.after is None:
            return None
        return self.after - self.before


def compare_results(
    a: dict[str, Any], b: dict[str, Any], *, tolerance: float = 0.02, judge_timing: bool = False
) -> list[Delta]:
    out: list[Delta] = []
    generators = list(a["results"]) + [g for g in b["results"] if g not in a["results"]]
    for gen in generators:
        va, vb = a["results"].get(gen), b["results"].get(gen)
        for header, path, _ in COLUMNS:
            before = metric(va, path) if va is not None else None
            after = metric(vb, path) if vb is not None else None
            judged = path not in NOT_JUDGED and (judge_timing or path not in TIMING)
            if before is None or after is None:
                regression = judged and before is not None and after is None
            elif path in LOWER_IS_BETTER:
                regression = judged and after - before > tolerance
            else:
                regression = judged and before - after > tolerance
            out.append(Delta(gen, header, before, after, regression))
    return out
