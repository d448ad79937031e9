"""Which generators failed outright or raised, and a one-screen summary of why.

A run whose generator produced no valid unit has not measured that generator: the CLI exits 1
and prints the reasons grouped, so the cause (a bad key, an unreachable server, a bug) is read
in one screen instead of in N unit files. A generator that raised (or broke its contract: returned
no `GenerationResult`, called `sys.exit`) in any unit has a bug, which no score should hide: the
CLI exits `EXIT_GENERATOR_RAISED` and names the exception and the generator's own frame
(file:line), so CI fails and the author reads where. A model's invalid replies are measurements,
not bugs (`error_kind` generation). Other partial failures only appear in the leaderboard.
"""

from __future__ import annotations

import re
import textwrap
from collections import Counter
from collections.abc import Sequence
from pathlib import Path

from logicenveval.generators.plugin_code import is_installed
from logicenveval.metrics.records import UnitRecord

MAX_REASONS = 5
#: the summary's lines are wrapped to this many columns
WIDTH = 100
#: exit status of `run` when a generator raised in some unit (docs/security.md, "Exit codes"):
#: apart from 1 (a generator measured nothing; `compare`'s regression) and 2 (bad input)
EXIT_GENERATOR_RAISED = 3
#: tasks named per exception before "+N more"
MAX_TASKS = 3
_FRAME = re.compile(r'^\s*File "(?P<file>[^"]+)", line (?P<line>\d+), in (?P<func>.+)$', re.M)
_CHAINED = re.compile(r"^(During handling of the above exception|The above exception was the "
                      r"direct cause)", re.M)


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


def raised(record: UnitRecord) -> bool:
    """The unit failed because its generator raised or broke its contract (a bug)."""
    return record.error is not None and record.error_kind == "internal"


def own_frame(traceback: str | None) -> str | None:
    """`file:line in function` of the innermost frame of the generator's own code in a stored
    traceback (outside the installed environment and the harness; else the innermost frame)."""
    if not traceback:
        return None
    last = _CHAINED.split(traceback)[-1]  # the exception that failed the unit
    frames = [(m["file"], m["line"], m["func"].strip()) for m in _FRAME.finditer(last)]
    if not frames:
        return None
    own = [f for f in frames if not f[0].startswith("<") and not is_installed(Path(f[0]))]
    file, line, func = (own or frames)[-1]
    return f"{file}:{line} in {func}"


def _exception(record: UnitRecord) -> str:
    text = (record.error or "").splitlines()[0] if record.error else ""
    return text.removeprefix("internal error: ")


def raised_summary(records: Sequence[UnitRecord], run_dir: Path | None = None) -> str:
    """Per generator that raised: how many units, each distinct exception with the generator's
    own frame and the tasks it failed, and where the whole traceback is (the unit file, in
    `run_dir` when given) ("" when none raised)."""
    lines: list[str] = []
    by_gen: dict[str, list[UnitRecord]] = {}
    for r in records:
        by_gen.setdefault(r.generator, []).append(r)
    for gen, units in by_gen.items():
        bad = [u for u in units if raised(u)]
        if not bad:
            continue
        lines.append(f"{gen}: raised in {len(bad)} of {len(units)} unit(s)")
        groups: dict[tuple[str, str | None], list[str]] = {}
        for u in bad:
            groups.setdefault((_exception(u), own_frame(u.traceback)), []).append(u.task_id)
        for (exc, frame), tasks in sorted(groups.items(), key=lambda kv: -len(kv[1])):
            lines += _wrapped(exc, "  ", "    ")
            named = ", ".join(tasks[:MAX_TASKS]) + (f", +{len(tasks) - MAX_TASKS} more"
                                                    if len(tasks) > MAX_TASKS else "")
            where = f"at {frame}" if frame else "no traceback (it returned or exited)"
            lines += _wrapped(f"{where} — {len(tasks)} unit(s): {named}", "    ", "      ")
        first = next((u for u in bad if u.traceback), bad[0])
        unit = Path("units", gen, f"{first.task_id}.json")
        lines += ["  whole traceback: \"traceback\" of", f"    {run_dir / unit}" if run_dir else
                  f"    {unit} in the seed<S>/ folders of the run folder"]
        lines += _wrapped("(also on the task's page of leaderboard.html; --debug re-raises it)",
                          "    ", "    ")
    if not lines:
        return ""
    return ("error: a generator raised (a bug in the generator, not a measurement; exit "
            f"{EXIT_GENERATOR_RAISED}):\n" + "\n".join(lines))


def _wrapped(text: str, first: str, rest: str) -> list[str]:
    """`text` wrapped to `WIDTH` columns, never cut (a path longer than a line stays whole)."""
    return textwrap.wrap(text, WIDTH, initial_indent=first, subsequent_indent=rest,
                         break_long_words=False, break_on_hyphens=False) or [first.rstrip()]
