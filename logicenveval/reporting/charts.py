"""One bar chart per headline metric for the leaderboard page: the methods side by side, each bar
with its 95 % bootstrap interval drawn as a whisker.

A table of twenty columns answers "what is the number"; it does not show at a glance which
differences are larger than their intervals. The charts are computed here from results.json
(geometry in SVG user units) and drawn as inline SVG by the page template (`_charts.html.j2`):
no script, no external library, so the page works offline and prints as it shows. The metrics are
the paper's main-table ones (PhyPR, LogCov, SceVR, FauDR, ST); a metric without an interval
(ST in ticks is deterministic; a row of fewer than two tasks has `n/a`) is drawn without whisker
and says so in the bar's tooltip.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from logicenveval.reporting.tables import fmt, is_measured, metric, row_label

#: (title, path into results.<generator>, rate in percent, higher is better)
HEADLINE: tuple[tuple[str, tuple[str, ...], bool, bool], ...] = (
    ("PhyPR (avg)", ("phypr", "avg"), True, True),
    ("LogCov", ("logcov",), True, True),
    ("SceVR", ("scevr",), True, True),
    ("FauDR (avg)", ("faudr", "avg"), True, True),
    ("ST (ticks)", ("st_ticks",), False, False),
)

#: the drawing's layout, in SVG user units
WIDTH = 360
LABEL_W = 130  # method names, left of the axis
LABEL_CHARS = 21  # of a method's name at the labels' font size
VALUE_W = 52  # the value's text, right of the plot
BAR_H = 14
GAP = 8
TOP = 6
AXIS_H = 22  # ticks and their labels under the bars
#: one colour per method, by row order, the same in every chart (colour-blind-safe palette)
PALETTE = ("#0072b2", "#e69f00", "#009e73", "#cc79a7", "#56b4e9", "#d55e00", "#f0e442", "#000000")


@dataclass(frozen=True)
class Bar:
    label: str
    colour: str
    y: float
    #: bar length (0 when not measured); value text; tooltip
    width: float
    text: str
    tooltip: str
    #: the interval's ends in x (None: no interval to draw)
    lo: float | None = None
    hi: float | None = None

    @property
    def short(self) -> str:
        """The label as it fits left of the axis (the tooltip has it whole)."""
        return self.label if len(self.label) <= LABEL_CHARS else self.label[:LABEL_CHARS - 1] + "…"


@dataclass(frozen=True)
class Tick:
    x: float
    text: str


@dataclass(frozen=True)
class Chart:
    title: str
    note: str
    height: float
    plot_x: float
    plot_w: float
    bars: list[Bar]
    ticks: list[Tick]
    #: id of the metric for tests and anchors (`chart-logcov`)
    key: str

    @property
    def width(self) -> int:
        return WIDTH

    @property
    def whiskers(self) -> bool:
        """Whether any bar has an interval (the caption says what the whiskers are, or that none are)."""
        return any(b.lo is not None for b in self.bars)


def _interval(values: dict[str, Any], path: tuple[str, ...]) -> tuple[float, float] | None:
    cur: Any = values.get("ci95")
    for key in path:
        if not isinstance(cur, dict):
            return None
        cur = cur.get(key)
    if isinstance(cur, list) and len(cur) == 2 and all(isinstance(v, int | float) for v in cur):
        lo, hi = float(cur[0]), float(cur[1])
        return (lo, hi) if math.isfinite(lo) and math.isfinite(hi) else None
    return None


def _nice_max(top: float) -> float:
    """A round upper end of the axis at or above `top` (1, 2, 2.5 or 5 times a power of ten)."""
    if top <= 0 or not math.isfinite(top):
        return 1.0
    power = 10.0 ** math.floor(math.log10(top))
    return float(next(m * power for m in (1.0, 2.0, 2.5, 5.0, 10.0) if m * power >= top))


def chart(results: dict[str, Any], title: str, path: tuple[str, ...], percent: bool, higher: bool) -> Chart:
    """One metric's chart over the rows of `results` in the run's order."""
    rows = list(results["results"].items())
    values = {gen: (metric(v, path) if is_measured(v) else None) for gen, v in rows}
    intervals = {gen: _interval(v, path) for gen, v in rows}
    scale_top = 1.0 if percent else _nice_max(max(
        [x for x in values.values() if x is not None]
        + [hi for iv in intervals.values() if iv is not None for hi in iv[1:]], default=1.0))
    plot_x, plot_w = LABEL_W, WIDTH - LABEL_W - VALUE_W

    def x_of(v: float) -> float:
        return plot_x + plot_w * min(max(v / scale_top, 0.0), 1.0)

    bars = []
    for k, (gen, raw) in enumerate(rows):
        value, iv = values[gen], intervals[gen]
        label = row_label(gen, raw, results)
        y = TOP + k * (BAR_H + GAP)
        if value is None:
            text = "–" if is_measured(raw) else "not measured"
            bars.append(Bar(label, PALETTE[k % len(PALETTE)], y, 0.0, text, f"{label}: {title} {text}"))
            continue
        shown = fmt(value, percent)
        ci = (f"[{fmt(iv[0], percent)}, {fmt(iv[1], percent)}]" if iv is not None
              else "no interval (deterministic or fewer than 2 tasks)")
        bars.append(Bar(label, PALETTE[k % len(PALETTE)], y, x_of(value) - plot_x, shown,
                        f"{label}: {title} {shown}{' %' if percent else ''} {ci}",
                        x_of(iv[0]) if iv else None, x_of(iv[1]) if iv else None))
    steps = 4
    ticks = [Tick(plot_x + plot_w * i / steps,
                  f"{100 * scale_top * i / steps:.0f}" if percent else f"{scale_top * i / steps:g}")
             for i in range(steps + 1)]
    height = TOP + len(rows) * (BAR_H + GAP) + AXIS_H
    note = ("%, " if percent else "") + ("higher is better" if higher else "lower is better")
    key = "-".join(path).replace("_", "-")
    return Chart(title, note, height, plot_x, plot_w, bars, ticks, key)


def headline_charts(results: dict[str, Any]) -> list[Chart]:
    """The charts of the leaderboard page, one per headline metric (none for a run without rows)."""
    if not results.get("results"):
        return []
    return [chart(results, title, path, percent, higher) for title, path, percent, higher in HEADLINE]


__all__ = ["HEADLINE", "Bar", "Chart", "Tick", "chart", "headline_charts"]
