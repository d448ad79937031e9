"""Which generators failed outright, and a one-screen summary of why.

A run whose generator produced no valid unit has not measured that generator: the CLI exits 1
and prints the reasons grouped, so the cause (a bad key, an unreachable server, a bug) is read
in one screen instead of in N unit files. Partial failures only appear in the leaderboard.
"""

from __future__ import annotations

import textwrap
from collections import Counter
from collections.abc import Sequence

from logicenveval.metrics.records import UnitRecord

MAX_REASONS = 5
#: the summary's lines are wrapped to this many columns
WIDTH = 100


def failed(record: UnitRecord) -> bool:
    """A unit is failed when it crashed as a whole, or produced no environment and said why.

    A unit that returns nothing without a failure has been measured (zero coverage)."""
    return record.error is not None or (not record.samples and bool(record.failures))


def failed_generators(records: Sequence[UnitRecord]) -> list[str]:
    """Generators (in first-seen order) all of whose units failed, or that produced no judged
    environment in any unit: the run exits 1 (docs/security.md); their rows still count the failed
    attempts, unless every unit failed for infrastructure reasons ("not measured")."""
    by_gen: dict[str, list[UnitRecord]] = {}
    for r in records:
        by_gen.setdefault(r.generator, []).append(r)
    return [g for g, units in by_gen.items()
            if units and (all(failed(u) for u in units) or not any(u.samples for u in units))]


def _reason(record: UnitRecord) -> str:
    if record.error:
        return record.error.splitlines()[0][:160]
    if record.failures:
        f = record.failures[0]
        return f"{f.stage}: {f.message}".splitlines()[0][:160]
    return "the generator returned no environment"


def summary(records: Sequence[UnitRecord], generators: Sequence[str]) -> str:
    """A few lines per generator: failed units and the most frequent reasons."""
    lines = []
    for g in generators:
        units = [r for r in records if r.generator == g]
        bad = [u for u in units if failed(u)]
        empty = [u for u in units if not failed(u) and not u.samples]
        lines.append(f"{g}: {len(bad)} of {len(units)} unit(s) failed"
                     + (f", {len(empty)} returned no environment" if empty else ""))
        reasons: Counter[str] = Counter()
        for u in bad + empty:  # failed attempts per cause: a unit that failed planned several
            reasons[_reason(u)] += max(1, u.n_failed)
        for reason, n in reasons.most_common(MAX_REASONS):  # wrapped, never cut: it is the cause
            lines += textwrap.wrap(f"{n} failed attempt(s): {reason}", WIDTH, initial_indent="  ",
                                   subsequent_indent="    ", break_on_hyphens=False)
        if len(reasons) > MAX_REASONS:
            lines.append(f"  ... and {len(reasons) - MAX_REASONS} other reason(s); see results.json "
                         "'failures'")
    return "\n".join(lines)
