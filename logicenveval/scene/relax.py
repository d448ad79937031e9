"""Solve with tracked assumptions; on unsat drop by priority, reading the solver's core.

Priority (first dropped first): enrichment relations, enrichment objects, then task relations.
Task objects are never tracked: their constraints are hard. The loop is backend-neutral: a layout
backend (Z3, CP-SAT) supplies a `Check` that solves under the active assumptions and names the
tracked items of its core.

The budget is counted in the solvers' own deterministic work (CP-SAT's deterministic time, Z3's
resource count), converted to seconds of a calibrating machine, never in wall-clock time: a solve
that runs out of budget runs out on every machine at the same point, so which item a timeout drops,
hence the layout and every request built on it, does not depend on the machine's speed or load.
A wall-clock cap (`WALL_CAP` times the budget) only guards against a machine far slower than the
calibrating one; a solve it ends is reported as such (`CAPPED`), the one machine-dependent path.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal, Protocol

Status = Literal["sat", "unsat", "unknown", "capped"]
"""`unknown`: the deterministic budget ran out; `capped`: the wall-clock cap did first."""

#: the wall-clock cap of a solve, as a multiple of its budget (at least 1 s of budget)
WALL_CAP = 10.0

#: the reason a drop records when the wall-clock cap, not the budget, ended the solve
CAPPED = "solver wall-clock cap (this machine was too slow for the budget: results may differ elsewhere)"


def wall_cap(budget: float) -> float:
    """Seconds of wall clock a solve with `budget` may take before the cap ends it."""
    return WALL_CAP * max(1.0, budget)


@dataclass(eq=False)  # identity: backend literals overload `==`
class Tracked:
    lit: Any  # the backend's assumption literal (z3.BoolRef, CP-SAT IntVar)
    kind: str  # "relation" | "object"
    item: str
    task: bool
    objects: tuple[str, ...] = field(default=())

    @property
    def rank(self) -> int:
        if self.kind == "relation":
            return 2 if self.task else 0
        return 1


@dataclass
class Dropped:
    tracked: Tracked
    reason: str


class _Keyed(Protocol):
    @property
    def id(self) -> str: ...

    @property
    def task(self) -> bool: ...


def object_literals(boxes: Sequence[_Keyed], new_lit: Callable[[str], Any], prefix: str
                    ) -> tuple[dict[str, Any], list[Tracked]]:
    """One tracked literal `new_lit(f"{prefix}_{k}")` per enrichment box k; task boxes stay hard."""
    lit: dict[str, Any] = {}
    tracked: list[Tracked] = []
    for k, b in enumerate(boxes):
        if not b.task:
            lit[b.id] = new_lit(f"{prefix}_{k}")
            tracked.append(Tracked(lit[b.id], "object", b.id, False, (b.id,)))
    return lit, tracked


Check = Callable[[list[Tracked], float], tuple[Status, list[Tracked], float]]
"""Solve assuming every item of `active` within a budget (calibrated seconds of deterministic work):
the status, on unsat the core's items (in `active` order), and the budget the call spent."""


def relax(check: Check, tracked: list[Tracked], budget: float) -> tuple[bool, list[Dropped]]:
    """Whether a solution honours as many tracked items as the priorities allow, and what was dropped.

    `budget` is the room's (`SceneSpec.room_timeout_s`), in calibrated seconds of deterministic
    work; a drop for lack of it grants a quarter of it again (at least 1). On True the backend's
    last `check` call holds the solution.
    """
    active = list(tracked)
    dropped: list[Dropped] = []
    left = budget
    while True:
        res, cands, spent = check(active, left)
        left -= spent
        if res == "sat":
            return True, dropped
        if res == "unsat":
            if not cands:
                return False, dropped
            victim = min(reversed(cands), key=lambda t: t.rank)
            others = [t.item for t in cands if t is not victim][:4]
            reason = ("unsatisfiable with the room's hard constraints"
                      + (f" and {', '.join(others)}" if others else ""))
        else:
            if not active:
                return False, dropped
            victim = min(reversed(active), key=lambda t: t.rank)
            reason = CAPPED if res == "capped" else "solver budget (deterministic work) spent"
            left = max(1.0, budget / 4)
        active.remove(victim)
        dropped.append(Dropped(victim, reason))
        if victim.kind == "object":
            for t in [t for t in active if t.kind == "relation" and victim.item in t.objects]:
                active.remove(t)
                dropped.append(Dropped(t, f"its object {victim.item} was dropped"))
