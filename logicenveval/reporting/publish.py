"""What `run` and `evaluate` do once their units are committed: write the leaderboards, say why.

The runner stops at results.json and samples.jsonl (it sits below reporting); the command layer
calls `publish` with what the run returned, so no lower layer imports this one.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from logicenveval.metrics.records import UnitRecord
from logicenveval.reporting.leaderboard import write_leaderboards
from logicenveval.reporting.tables import markdown
from logicenveval.reporting.terminal import terminal_summary
from logicenveval.reporting.why import reasons, summary_text


@dataclass(frozen=True)
class Published:
    #: the full leaderboard as Markdown (leaderboard.md)
    table: str
    #: why environments were rejected or failed, per generator, with examples
    why: str
    #: what the command prints: headline figures, a reasons line per method, where the pages are
    summary: str = ""


def publish(run_dir: Path, results: dict[str, Any], records: Sequence[UnitRecord],
            paged: Collection[tuple[str, str]] = ()) -> Published:
    """Write `leaderboard.md`, `leaderboard.html` and `details/` (for a multi-seed run also each
    seed's), and return the text the command prints: the "why" summary is read from the pages'
    index, so it names the same examples (with their seed in a multi-seed run) as the HTML.
    `paged`: units whose page their worker wrote (`RunOutcome.paged`, `unit_page`)."""
    got = write_leaderboards(run_dir, results, None if results.get("runs") else records,
                             () if results.get("runs") else paged)
    why = reasons(got.samples, results.get("failures", {}), messages=got.messages, scores=results["results"])
    return Published(markdown(results), summary_text(why), terminal_summary(results, why, run_dir))
