"""What `run` and `evaluate` print at the end: a summary a person reads at a glance.

At most `WIDTH` columns: per method the paper's headline figures (PhyPR, LogCov, SceVR, FauDR
averages) and its failed/attempted environments, then its most frequent reasons, each in the words
of its first example (`role full_bag is ambiguous: 2 objects fit (...)`, not the shape the
reasons are grouped by, `role … is ambiguous: # objects … (…, …, …)`) and wrapped, never cut, then
where the full leaderboard is. The full table (every column, intervals) stays in leaderboard.md
and leaderboard.html; the reasons with examples in leaderboard.html.
"""

from __future__ import annotations

import io
import textwrap
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.table import Table

from logicenveval.reporting.tables import NOT_MEASURED, fmt, is_measured, metric, row_label
from logicenveval.reporting.why import GeneratorReasons, Reason, reason_key

#: the terminal summary's width in columns (the whole printout fits it)
WIDTH = 100
#: (header, path into results.<generator>): the paper's headline figures, rates in percent
HEADLINE: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("PhyPR", ("phypr", "avg")), ("LogCov", ("logcov",)), ("SceVR", ("scevr",)),
    ("FauDR", ("faudr", "avg")),
)
#: reasons listed per method before "+N more"
MAX_REASONS = 3


def path_lines(label: str, path: Path | str, width: int = WIDTH) -> list[str]:
    """`label path` on one line, or the path on a line of its own when that is too wide: a path is
    never clipped (it is there to be copied)."""
    line = f"{label} {path}"
    return [line] if len(line) <= width else [label, str(path)]


def spelled(r: Reason) -> str:
    """A reason in words: its shape with the first example's words put back, and where that
    example is (the shape alone when it has no placeholder, or the example does not fit it)."""
    shaped = reason_key(r.example)
    if ("…" not in r.key and "#" not in r.key) or not shaped or not r.key.endswith(shaped):
        return r.label
    where = f" ({'first: ' if r.count > 1 else ''}{r.where})" if r.where else ""
    return f"{r.kind}: {r.key[: len(r.key) - len(shaped)]}{r.example}{where}"


def reason_lines(g: GeneratorReasons, width: int = WIDTH) -> list[str]:
    """The method's most frequent reasons, a line each (wrapped), most frequent kinds first."""
    if g.clean:
        return _wrap(f"{g.generator}: {g.n_envs} environment(s), none rejected, failed or "
                     "implausible", width)
    lines: list[str] = []
    for i, r in enumerate(g.reasons[:MAX_REASONS]):
        lines += _wrap(f"{g.generator}: " * (i == 0) + f"{r.count} × {spelled(r)}", width,
                       first="  " if i == 0 else "    ")
    more = len(g.reasons) - MAX_REASONS
    if more > 0:
        lines.append(f"    +{more} more reason(s) (leaderboard.html)")
    return lines


def _wrap(text: str, width: int, first: str = "  ") -> list[str]:
    return textwrap.wrap(text, width, initial_indent=first, subsequent_indent=first + "    ",
                         break_long_words=False, break_on_hyphens=False) or [first]


def summary_table(results: dict[str, Any]) -> Table:
    table = Table(title="Results (%; full table: leaderboard.md)", title_justify="left",
                  box=None, pad_edge=False, header_style="bold")
    table.add_column("method", overflow="fold", max_width=40)
    for header, _ in HEADLINE:
        table.add_column(header, justify="right")
    table.add_column("failed/attempted", justify="right")
    for gen, values in results["results"].items():
        label = row_label(gen, values, results)
        if not is_measured(values):
            table.add_row(label, *[NOT_MEASURED if i == 0 else "" for i in range(len(HEADLINE))], "")
            continue
        failed, attempted = values.get("n_failed"), values.get("n_attempted")
        tried = f"{int(failed)}/{int(attempted)}" if failed is not None and attempted is not None else "–"
        table.add_row(label, *[fmt(metric(values, path), True) for _, path in HEADLINE], tried)
    return table


def terminal_summary(results: dict[str, Any], why: Sequence[GeneratorReasons], run_dir: Path,
                     width: int = WIDTH) -> str:
    """The end-of-run printout: the headline table, one reasons line per method, the pages."""
    buf = io.StringIO()
    console = Console(file=buf, width=width, no_color=True, highlight=False, emoji=False)
    console.print(summary_table(results))
    lines = ["Why (count × reason; examples in leaderboard.html):"]
    lines += [line for g in why for line in reason_lines(g, width)]
    lines += path_lines("leaderboard:", run_dir / "leaderboard.html", width)
    return "\n".join(line.rstrip() for line in buf.getvalue().splitlines()) + "\n" + "\n".join(lines)
