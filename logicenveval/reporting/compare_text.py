"""The text `compare` prints: one table per compared pair, then the verdict.

Rates are shown in percent and their changes in percentage points, like the leaderboard; every
column has a header, and the verdict column marks regressions and improvements.
"""

from __future__ import annotations

import io

from rich.console import Console
from rich.table import Table

from logicenveval.metrics.uncertainty import MIN_TASKS
from logicenveval.reporting.compare import (
    IMPROVED,
    INCONCLUSIVE,
    REGRESSION,
    UNRECORDED,
    Comparison,
    Delta,
    Pair,
)

_WIDTH = 132


def _num(value: float | None, percent: bool, signed: bool = False, digits: int = 2) -> str:
    if value is None:
        return "–"
    v = 100 * value if percent else value
    return f"{v:+.{digits}f}" if signed else f"{v:.{digits}f}"


def interval_text(d: Delta, n_tasks: int) -> str:
    if d.ci95 is None:
        return "n/a" if 0 < n_tasks < MIN_TASKS else "–"
    return f"[{_num(d.ci95[0], d.percent, True)}, {_num(d.ci95[1], d.percent, True)}]"


def verdict_text(d: Delta) -> str:
    """The word of a delta, the same in text, JSON and HTML (regressions shouted in text)."""
    if d.regression:
        return "REGRESSION"
    if d.change is None:
        return ""
    return d.verdict or "unchanged"


def pair_table(pair: Pair) -> Table:
    table = Table(title=f"{pair.title} — {pair.n_tasks} paired task(s)", title_justify="left")
    for col, justify in (("metric", "left"), ("A", "right"), ("B", "right"), ("change B − A", "right"),
                         ("95 % CI of change", "right"), ("verdict", "left")):
        table.add_column(col, justify=justify)  # type: ignore[arg-type]
    for d in pair.deltas:
        digits = 0 if d.path == ("n_envs",) else 2
        table.add_row(d.metric + (" (%)" if d.percent else ""), _num(d.before, d.percent, digits=digits),
                      _num(d.after, d.percent, digits=digits), _num(d.change, d.percent, True, digits),
                      interval_text(d, pair.n_tasks), verdict_text(d))
    return table


def fingerprint_table(c: Comparison) -> Table:
    """What made each side (results.json `inputs`): the harness, the catalog, each compared
    generator's code, the compared tasks' files."""
    table = Table(title="What made A and B (fingerprints)", title_justify="left")
    for col in ("input", "A", "B", ""):
        table.add_column(col)
    for f in c.fingerprints:
        table.add_row(f.what, f.a, f.b,
                      "same" if f.same else "" if UNRECORDED in (f.a, f.b) else "differs")
    return table


def comparison_text(c: Comparison, run_a: str, run_b: str) -> str:
    buf = io.StringIO()
    console = Console(file=buf, width=_WIDTH, no_color=True, highlight=False)
    console.print(f"A = {run_a}\nB = {run_b}\n{len(c.tasks)} task(s); tolerance {c.tolerance} "
                  "(fractions; percentage points / 100 for rates); a change is judged when it "
                  "exceeds the tolerance and its paired 95 % bootstrap interval excludes 0; "
                  "'inconclusive': the interval holds 0 but reaches beyond the tolerance; "
                  "'not judged': a metric without a direction (Redundancy, ST, Envs).",
                  markup=False)
    if c.fingerprints:
        console.print(fingerprint_table(c))
    for pair in c.pairs:
        console.print(pair_table(pair))
    lines = [c.warning] if c.warning else []
    lines += [p.left_out_text for p in c.pairs if p.left_out_text]
    if c.new:
        lines.append("only in B (not compared): " + ", ".join(c.new))
    if c.missing:
        lines.append(f"{len(c.missing)} thing(s) of A missing from B"
                     + (" (allowed by --allow-missing):" if c.allow_missing else " (regressions):"))
        lines += [f"  {m.text}" for m in c.missing]
    lines.append(f"{len(c.regressions)} regression(s), {len(c.improvements)} improvement(s), "
                 f"{len(c.inconclusive)} inconclusive")
    for mark, pick in (("REGRESSION", REGRESSION), ("improved", IMPROVED),
                       ("inconclusive", INCONCLUSIVE)):
        lines += [f"  {mark} {d.generator} {d.metric}: {_num(d.change, d.percent, True)} "
                  f"{interval_text(d, p.n_tasks)}" for p in c.pairs for d in p.deltas if d.verdict == pick]
    lines.append("FAILED: " + ("regression(s)" if c.regressions else "missing in B")
                 if c.failed else "no regression")
    return buf.getvalue() + "\n".join(lines)
