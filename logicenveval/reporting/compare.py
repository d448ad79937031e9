"""Regression comparison (`compare RUN_A [RUN_B] [--gen-a X --gen-b Y]`), for generators' CI.

Pairs are generator X of run A against generator Y of run B: by default every generator of A
against the one of the same name in B; `--gen-a/--gen-b` compare two different generators, also
of one run. A metric is judged only when it has a declared direction (`DIRECTION`: the rates,
LD and JI, higher is better); Redundancy, ST and the environment count are reported, not judged
(a generator that builds fewer environments must not look "improved"). The comparison is paired
over tasks: both sides' per-task figures are resampled with the same task draws (and each side's
seeds within a drawn task), giving a 95 % bootstrap interval of the difference B - A (`n/a` with
fewer than two tasks). A change is a regression only when it goes against the metric's direction
by more than the tolerance (absolute, in the metric's unit: fractions for rates) AND its interval
excludes 0, so noise from a few tasks is not flagged; an improvement is the same in the metric's
direction; an interval that holds 0 but reaches beyond the tolerance is "inconclusive" (`verdict`).
Without an interval the tolerance alone decides. Timing (ST ms) is judged only when asked. Anything of A missing from B — a generator, a task, a measurement (a row or task B did not
measure) — is a regression unless allowed; tasks whose definition changed between the runs are
refused unless the comparison is restricted to the unchanged ones.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field
from typing import Any

from logicenveval.errors import ConfigError
from logicenveval.metrics.uncertainty import (
    cells_of,
    paired_cells,
    paired_difference,
    point_metrics,
)
from logicenveval.reporting.tables import COLUMNS, is_measured, metric

#: each judged metric's declared direction: "higher" is better (every other metric is reported,
#: never judged: Redundancy is good near 1 and below 1 means under-coverage, ST and Envs follow
#: how many environments a generator built, so fewer environments must not read as "improved")
DIRECTION: dict[tuple[str, ...], str] = {
    path: "higher" for _, path, _ in COLUMNS
    if path not in {("st_ms",), ("st_ticks",), ("redundancy",), ("n_envs",)}
}
#: ST (ms) is judged, lower being better, only with `judge_timing` (--judge-timing)
TIMING = ("st_ms",)

REGRESSION, IMPROVED, UNCHANGED, INCONCLUSIVE, INFO = (
    "regression", "improved", "", "inconclusive", "not judged")


def direction(path: tuple[str, ...], judge_timing: bool = False) -> str | None:
    """"higher", "lower" or None (reported, not judged) for a metric of `COLUMNS`."""
    if judge_timing and path == TIMING:
        return "lower"
    return DIRECTION.get(path)


def verdict(diff: float | None, ci: tuple[float, float] | None, tolerance: float,
            way: str | None) -> str:
    """What a change says. Without a direction: "not judged". With an interval: a regression
    or improvement when the change exceeds the tolerance and the interval excludes 0;
    "inconclusive" when the interval holds 0 but reaches beyond the tolerance (a change that
    large is as compatible with the data as none); else unchanged. Without an interval (one
    task, or results without per-task figures) the tolerance alone decides."""
    if diff is None:
        return UNCHANGED
    if way is None:
        return INFO
    gain = diff if way == "higher" else -diff
    clear = ci is None or ci[0] > 0 or ci[1] < 0
    if abs(diff) > tolerance and clear:
        return IMPROVED if gain > 0 else REGRESSION
    if ci is not None and ci[0] <= 0 <= ci[1] and (ci[0] < -tolerance or ci[1] > tolerance):
        return INCONCLUSIVE
    return UNCHANGED


@dataclass(frozen=True)
class Delta:
    gen_a: str
    gen_b: str
    metric: str
    before: float | None
    after: float | None
    #: regression, improved, inconclusive, "" (unchanged) or "not judged" (`verdict`)
    verdict: str
    #: 95 % paired bootstrap interval of after - before (None: no per-task figures, or < 2 tasks)
    ci95: tuple[float, float] | None = None
    percent: bool = False
    path: tuple[str, ...] = ()
    #: "higher" or "lower" is better, or None: reported, not judged
    direction: str | None = None

    @property
    def change(self) -> float | None:
        if self.before is None or self.after is None:
            return None
        return self.after - self.before

    @property
    def regression(self) -> bool:
        return self.verdict == REGRESSION

    @property
    def improved(self) -> bool:
        return self.verdict == IMPROVED

    @property
    def generator(self) -> str:
        return self.gen_a if self.gen_a == self.gen_b else f"{self.gen_a} → {self.gen_b}"

    def to_json(self) -> dict[str, Any]:
        return {"metric": self.metric, "key": ".".join(self.path), "a": self.before, "b": self.after,
                "change": self.change, "ci95": None if self.ci95 is None else list(self.ci95),
                "direction": self.direction,
                "verdict": None if self.change is None else (self.verdict or "unchanged")}


@dataclass(frozen=True)
class Missing:
    """Something A measured that B does not have: a generator, or a task of a generator."""

    generator: str
    task: str = ""
    why: str = "missing"

    @property
    def text(self) -> str:
        what = f"task {self.task} of {self.generator}" if self.task else f"generator {self.generator}"
        return f"{what}: {self.why} in B"


@dataclass(frozen=True)
class Pair:
    gen_a: str
    gen_b: str
    tasks: list[str]
    deltas: list[Delta]
    #: the interval is over this many tasks (< 2: n/a)
    n_tasks: int = 0
    #: (task, side that built nothing there: "A" or "B"): paired tasks left out of ST and
    #: Redundancy, which exist only where environments do (`uncertainty.paired_cells`)
    left_out: tuple[tuple[str, str], ...] = ()
    #: (A, B) ST (ms) as each side's own leaderboard averages it, over its own tasks
    own_st: tuple[float | None, float | None] = (None, None)

    @property
    def title(self) -> str:
        return self.gen_a if self.gen_a == self.gen_b else f"{self.gen_a} (A) → {self.gen_b} (B)"

    @property
    def left_out_text(self) -> str:
        """Which tasks ST and Redundancy leave out and why the figures differ from the
        leaderboards' ("" when none is left out)."""
        if not self.left_out:
            return ""
        named = ", ".join(f"{t} ({side} built nothing)" for t, side in self.left_out[:MAX_NAMED])
        more = len(self.left_out) - MAX_NAMED
        text = (f"note: {self.title}: ST (ms), ST (ticks) and Redundancy are paired over the "
                f"{self.n_tasks - len(self.left_out)} task(s) where both sides built an environment; "
                f"left out: {named}" + (f", +{more} more" if more > 0 else ""))
        st = next((d for d in self.deltas if d.path == ("st_ms",)), None)
        own_a, own_b = self.own_st
        if st is not None and own_a is not None and own_b is not None:
            text += (f". Each leaderboard averages its own tasks: ST (ms) A {own_a:.2f} and B "
                     f"{own_b:.2f} there, {_fmt(st.before)} and {_fmt(st.after)} here")
        return text


#: tasks named in a note before "+N more"
MAX_NAMED = 5


def _fmt(value: float | None) -> str:
    return "–" if value is None else f"{value:.2f}"


#: what a side shows for a fingerprint its results.json does not record (an older harness)
UNRECORDED = "not recorded"


@dataclass(frozen=True)
class Fingerprint:
    """One input of both sides (results.json `inputs`, runner.placement): what made A and B."""

    what: str  # harness, catalog, "code of <generator>", "<n> task(s)"
    a: str
    b: str

    @property
    def same(self) -> bool:
        return self.a == self.b != UNRECORDED


@dataclass(frozen=True)
class Comparison:
    tasks: list[str]
    pairs: list[Pair]
    missing: list[Missing] = field(default_factory=list)
    #: generators of B that A does not have (informational)
    new: list[str] = field(default_factory=list)
    allow_missing: bool = False
    tolerance: float = 0.02
    #: the fingerprints of both sides' inputs (harness, catalog, each pair's code, the tasks)
    fingerprints: list[Fingerprint] = field(default_factory=list)
    #: the two sides' configurations (results.json `config`) are the same
    same_config: bool = False

    @property
    def same_inputs(self) -> bool:
        """Every fingerprint is recorded on both sides and equal: the same code, tasks, catalog."""
        return bool(self.fingerprints) and all(f.same for f in self.fingerprints)

    @property
    def warning(self) -> str:
        """Why the comparison may compare nothing ("" when the inputs differ)."""
        if not self.same_inputs:
            return ""
        if self.same_config:
            return ("warning: A and B have the same configuration and the same fingerprints: they "
                    "are one computation and can differ only in timings (did a re-run with "
                    "--replace overwrite the run meant as A? docs/runner.md, 'Finished runs')")
        return ("warning: A and B have the same fingerprints (harness, generator code, tasks, "
                "catalog): any difference comes from their configurations, not from the code")

    @property
    def deltas(self) -> list[Delta]:
        return [d for p in self.pairs for d in p.deltas]

    @property
    def regressions(self) -> list[Delta]:
        return [d for d in self.deltas if d.regression]

    @property
    def improvements(self) -> list[Delta]:
        return [d for d in self.deltas if d.improved]

    @property
    def inconclusive(self) -> list[Delta]:
        return [d for d in self.deltas if d.verdict == INCONCLUSIVE]

    @property
    def failed(self) -> bool:
        """What makes `compare` exit 1: a regression, or something missing from B (unless allowed)."""
        return bool(self.regressions) or (bool(self.missing) and not self.allow_missing)

    def to_json(self) -> dict[str, Any]:
        return {
            "tasks": self.tasks, "tolerance": self.tolerance, "allow_missing": self.allow_missing,
            "pairs": [{"a": p.gen_a, "b": p.gen_b, "n_tasks": p.n_tasks,
                       "metrics": [d.to_json() for d in p.deltas],
                       "left_out_of_st": [{"task": t, "built_nothing": side}
                                          for t, side in p.left_out]} for p in self.pairs],
            "missing": [{"generator": m.generator, "task": m.task or None, "why": m.why} for m in self.missing],
            "new_in_b": self.new,
            "regressions": len(self.regressions), "improvements": len(self.improvements),
            "inconclusive": len(self.inconclusive), "failed": self.failed,
            "fingerprints": [{"input": f.what, "a": f.a, "b": f.b, "same": f.same}
                             for f in self.fingerprints],
            "same_inputs": self.same_inputs, "warning": self.warning or None,
        }


def compared_tasks(a: dict[str, Any], b: dict[str, Any], *, skip_changed: bool) -> list[str]:
    """A's tasks, less those whose definition differs in B (refused unless `skip_changed`).

    Tasks of A that B lacks stay in: the comparison reports them as missing from B."""
    ta, tb = list(a.get("tasks", [])), set(b.get("tasks", []))
    ha = a.get("benchmark", {}).get("task_sha256", {})
    hb = b.get("benchmark", {}).get("task_sha256", {})
    changed = sorted(t for t in set(ta) & tb if t in ha and t in hb and ha[t] != hb[t])
    if changed and not skip_changed:
        raise ConfigError(f"task(s) {changed[:5]} differ between the runs' benchmark versions",
                          field="benchmark", hint="re-run both on the same benchmark, or "
                          "pass --common-tasks to compare the unchanged tasks only")
    if not any(t in tb and t not in changed for t in ta):
        raise ConfigError(f"the runs share no task (A: {ta[:5]}, B: {sorted(tb)[:5]})", field="tasks",
                          hint="compare runs of one benchmark")
    return [t for t in ta if t not in changed]


def _pairs(a: dict[str, Any], b: dict[str, Any], gen_a: str | None,
           gen_b: str | None) -> tuple[list[tuple[str, str]], list[str], list[str]]:
    """(pairs, generators of A missing from B, generators only in B)."""
    ra, rb = a["results"], b["results"]
    if gen_a is None and gen_b is None:
        pairs = [(g, g) for g in ra if g in rb]
        return pairs, [g for g in ra if g not in rb], [g for g in rb if g not in ra]
    x, y = gen_a or gen_b, gen_b or gen_a
    assert x is not None and y is not None
    for name, side, opt in ((x, ra, "--gen-a"), (y, rb, "--gen-b")):
        if name not in side:
            raise ConfigError(f"no generator {name!r} in run {'A' if opt == '--gen-a' else 'B'} "
                              f"(it has {sorted(side)[:8]})", field=opt,
                              hint="name a generator of that run's leaderboard")
    return [(x, y)], [], []


def compare_results(
    a: dict[str, Any], b: dict[str, Any], *, tolerance: float = 0.02, judge_timing: bool = False,
    tasks: list[str] | None = None, n_bootstrap: int = 2000, gen_a: str | None = None,
    gen_b: str | None = None, allow_missing: bool = False,
) -> Comparison:
    """Compare every pair of generators of A and B over `tasks` (default: A's tasks)."""
    tasks = list(a.get("tasks", [])) if tasks is None else list(tasks)
    in_b = set(b.get("tasks", []))
    pairs, lost, new = _pairs(a, b, gen_a, gen_b)
    missing = [Missing(g) for g in lost if is_measured(a["results"][g])]
    out = []
    for x, y in pairs:
        va, vb = a["results"][x], b["results"][y]
        if not is_measured(va):
            continue  # nothing of A to keep
        if not is_measured(vb):
            missing.append(Missing(y, why="not measured"))
            continue
        ca = {k: c for k, c in cells_of(a, x).items() if k[0] in set(tasks)}
        cb = {k: c for k, c in cells_of(b, y).items() if k[0] in set(tasks)}
        ta, tb = {t for t, _ in ca}, {t for t, _ in cb}
        missing += [Missing(y, t, "not measured" if t in in_b else "missing")
                    for t in tasks if t in ta and t not in tb]
        shared = [t for t in tasks if t in ta and t in tb]
        out.append(_pair(x, y, va, vb, ca, cb, shared, tolerance, judge_timing, n_bootstrap))
    return Comparison(tasks, out, missing, new, allow_missing, tolerance,
                      fingerprints(a, b, pairs, tasks), a.get("config") == b.get("config"))


def fingerprints(a: dict[str, Any], b: dict[str, Any], pairs: list[tuple[str, str]],
                 tasks: list[str]) -> list[Fingerprint]:
    """The fingerprints of what made each side: harness, catalog, each compared generator's
    code, and one digest over the compared tasks' files (`UNRECORDED` where a side has none)."""
    ia, ib = _inputs(a), _inputs(b)
    out = [Fingerprint(key, _short(ia.get(key)), _short(ib.get(key))) for key in ("harness", "catalog")]
    for x, y in pairs:
        label = f"code of {x}" if x == y else f"code of {x} (A) / {y} (B)"
        out.append(Fingerprint(label, _short(_get(ia, "generators", x)),
                               _short(_get(ib, "generators", y))))
    out.append(Fingerprint(f"{len(tasks)} task(s)", _tasks_digest(ia, tasks),
                           _tasks_digest(ib, tasks)))
    return out


def _inputs(results: dict[str, Any]) -> dict[str, Any]:
    inputs = results.get("inputs")
    return inputs if isinstance(inputs, dict) else {}


def _get(inputs: dict[str, Any], key: str, name: str) -> Any:
    group = inputs.get(key)
    return group.get(name) if isinstance(group, dict) else None


def _short(value: Any) -> str:
    """A fingerprint as a person reads it (digests cut to 8 hex digits), or `UNRECORDED`."""
    if not isinstance(value, str):
        return UNRECORDED
    return " ".join(w[:8] if len(w) > 8 and all(c in "0123456789abcdef" for c in w) else
                    (w[:12] if w.startswith("src:") else w) for w in value.split())


def _tasks_digest(inputs: dict[str, Any], tasks: list[str]) -> str:
    found = {t: _get(inputs, "tasks", t) for t in tasks}
    if not found or any(not isinstance(v, str) for v in found.values()):
        return UNRECORDED
    return hashlib.sha256(json.dumps(found, sort_keys=True).encode()).hexdigest()[:8]


def _pair(x: str, y: str, va: dict[str, Any], vb: dict[str, Any], ca: dict[tuple[str, int], Any],
          cb: dict[tuple[str, int], Any], shared: list[str], tolerance: float, judge_timing: bool,
          n_bootstrap: int) -> Pair:
    paired: dict[tuple[str, ...], tuple[float, float | None, float | None]] = {}
    point_a = point_b = None
    left_out: list[tuple[str, str]] = []
    if shared:
        left_out = _left_out(ca, cb, shared)
        ca = {k: c for k, c in ca.items() if k[0] in set(shared)}
        cb = {k: c for k, c in cb.items() if k[0] in set(shared)}
        ca, cb = paired_cells(ca, cb)  # ST and Redundancy over the tasks both sides have them
        paired = paired_difference(ca, cb, n=n_bootstrap)
        point_a, point_b = point_metrics(list(ca.values())), point_metrics(list(cb.values()))
    deltas = []
    for header, path, pct in COLUMNS:
        ci: tuple[float, float] | None = None
        if path in paired and point_a is not None and point_b is not None:
            _, lo, hi = paired[path]
            before, after = metric(point_a, path), metric(point_b, path)
            ci = None if lo is None or hi is None else (lo, hi)
        else:  # results without per-task figures: the tolerance alone
            before, after = metric(va, path), metric(vb, path)
        diff = None if before is None or after is None else after - before
        way = direction(path, judge_timing)
        deltas.append(Delta(x, y, header, before, after, verdict(diff, ci, tolerance, way), ci, pct,
                            path, way))
    return Pair(x, y, shared, deltas, len(shared), tuple(left_out),
                (metric(va, ("st_ms",)), metric(vb, ("st_ms",))))


def _left_out(ca: dict[tuple[str, int], Any], cb: dict[tuple[str, int], Any],
              shared: list[str]) -> list[tuple[str, str]]:
    """Paired tasks where one side has no ST (it built no environment there) and the other has:
    the paired ST and Redundancy leave them out, each side's leaderboard does not."""
    def lacking(cells: dict[tuple[str, int], Any], task: str) -> bool:
        return any(c.get("st_ms", 0.0) is None for (t, _), c in cells.items() if t == task)

    out = []
    for task in shared:
        a, b = lacking(ca, task), lacking(cb, task)
        if a != b:
            out.append((task, "A" if a else "B"))
    return out
