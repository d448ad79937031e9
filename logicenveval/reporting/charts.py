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
from collections.abc import Sequence
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
PLOT_W = 180  # the bars' axis
CHAR_W = 6.6  # of a label character at the labels' font size (11 px sans-serif)
LABEL_CHARS = 44  # a longer label is shortened in its middle (the tooltip has it whole)
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
        """The label as drawn: whole up to `LABEL_CHARS`, else its start and its end (a merged
        report's labels end with the method's name) around an ellipsis."""
        if len(self.label) <= LABEL_CHARS:
            return self.label
        tail = LABEL_CHARS // 2
        return self.label[:LABEL_CHARS - tail - 1] + "…" + self.label[-tail:]


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
    width: float
    bars: list[Bar]
    ticks: list[Tick]
    #: id of the metric for tests and anchors (`chart-logcov`)
    key: str

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


def chart(rows: Sequence[tuple[str, dict[str, Any]]], title: str, path: tuple[str, ...], percent: bool,
          higher: bool) -> Chart:
    """One metric's chart over `rows` (label, results.json values of a method), in their order."""
    values = [metric(v, path) if is_measured(v) else None for _, v in rows]
    intervals = [_interval(v, path) for _, v in rows]
    scale_top = 1.0 if percent else _nice_max(max(
        [x for x in values if x is not None] + [iv[1] for iv in intervals if iv is not None], default=1.0))
    longest = max(min(len(label), LABEL_CHARS) for label, _ in rows)
    plot_x, plot_w = round(8 + CHAR_W * longest), PLOT_W  # room for the labels, then the axis

    def x_of(v: float) -> float:
        return plot_x + plot_w * min(max(v / scale_top, 0.0), 1.0)

    bars = []
    for k, ((label, raw), value, iv) in enumerate(zip(rows, values, intervals, strict=True)):
        y = TOP + k * (BAR_H + GAP)
        colour = PALETTE[k % len(PALETTE)]
        if value is None:
            text = "–" if is_measured(raw) else "not measured"
            bars.append(Bar(label, colour, y, 0.0, text, f"{label}: {title} {text}"))
            continue
        shown = fmt(value, percent)
        ci = (f"[{fmt(iv[0], percent)}, {fmt(iv[1], percent)}]" if iv is not None
              else "no interval (deterministic or fewer than 2 tasks)")
        bars.append(Bar(label, colour, y, x_of(value) - plot_x, shown,
                        f"{label}: {title} {shown}{' %' if percent else ''} {ci}",
                        x_of(iv[0]) if iv else None, x_of(iv[1]) if iv else None))
    steps = 4
    ticks = [Tick(plot_x + plot_w * i / steps,
                  f"{100 * scale_top * i / steps:.0f}" if percent else f"{scale_top * i / steps:g}")
             for i in range(steps + 1)]
    height = TOP + len(rows) * (BAR_H + GAP) + AXIS_H
    note = ("%, " if percent else "") + ("higher is better" if higher else "lower is better")
    key = "-".join(path).replace("_", "-")
    return Chart(title, note, height, plot_x, plot_w, plot_x + plot_w + VALUE_W, bars, ticks, key)


def charts_of(rows: Sequence[tuple[str, dict[str, Any]]]) -> list[Chart]:
    """One chart per headline metric over `rows` (label, a method's results.json values)."""
    if not rows:
        return []
    return [chart(rows, title, path, percent, higher) for title, path, percent, higher in HEADLINE]


def headline_charts(results: dict[str, Any]) -> list[Chart]:
    """The charts of a run's leaderboard page: its methods, labelled as its table labels them."""
    return charts_of([(row_label(gen, values, results), values)
                      for gen, values in (results.get("results") or {}).items()])


__all__ = ["HEADLINE", "Bar", "Chart", "Tick", "chart", "charts_of", "headline_charts"]
