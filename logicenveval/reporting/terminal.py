"""What `run` and `evaluate` print at the end: a summary a person reads at a glance.

At most `WIDTH` columns: per method the paper's headline figures (PhyPR, LogCov, SceVR, FauDR
averages) and its failed/attempted environments, then one line of its most frequent reasons, then
where the full leaderboard is. The full table (every column, intervals) stays in leaderboard.md
and leaderboard.html; the reasons with examples in leaderboard.html.
"""

from __future__ import annotations

import io
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.table import Table

from logicenveval.reporting.tables import NOT_MEASURED, fmt, is_measured, metric, row_label
from logicenveval.reporting.why import GeneratorReasons

#: the terminal summary's width in columns (the whole printout fits it)
WIDTH = 100
#: (header, path into results.<generator>): the paper's headline figures, rates in percent
HEADLINE: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("PhyPR", ("phypr", "avg")), ("LogCov", ("logcov",)), ("SceVR", ("scevr",)),
    ("FauDR", ("faudr", "avg")),
)
#: reasons named on a method's line before "…"
MAX_REASONS = 3


def _clip(text: str, width: int) -> str:
    return text if len(text) <= width else text[: width - 1] + "…"


def path_lines(label: str, path: Path | str, width: int = WIDTH) -> list[str]:
    """`label path` on one line, or the path on a line of its own when that is too wide: a path is
    never clipped (it is there to be copied)."""
    line = f"{label} {path}"
    return [line] if len(line) <= width else [label, str(path)]


def reasons_line(g: GeneratorReasons) -> str:
    """The method's reasons on one line: counts and shapes, most frequent kinds first."""
    if g.clean:
        return f"{g.generator}: {g.n_envs} environment(s), none rejected, failed or implausible"
    parts = [f"{r.count} × {r.label}" for r in g.reasons[:MAX_REASONS]]
    more = len(g.reasons) - MAX_REASONS
    return f"{g.generator}: " + "; ".join(parts) + (f"; +{more} more" if more > 0 else "")


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
    lines += [_clip("  " + reasons_line(g), width) for g in why]
    lines += path_lines("leaderboard:", run_dir / "leaderboard.html", width)
    return "\n".join(line.rstrip() for line in buf.getvalue().splitlines()) + "\n" + "\n".join(lines)
