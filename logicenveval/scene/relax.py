"""Solve with tracked assumptions; on unsat drop by priority, reading the solver's core.

Priority (first dropped first): enrichment relations, enrichment objects, then task relations.
Task objects are never tracked: their constraints are hard. The loop is backend-neutral: a layout
backend (Z3, CP-SAT) supplies a `Check` that solves under the active assumptions and names the
tracked items of its core.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal, Protocol

Status = Literal["sat", "unsat", "unknown"]


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


Check = Callable[[list[Tracked], float], tuple[Status, list[Tracked]]]
"""Solve assuming every item of `active` within `timeout_s`; on unsat also the core's items (in `active` order)."""


def relax(check: Check, tracked: list[Tracked], timeout_s: float) -> tuple[bool, list[Dropped]]:
    """Whether a solution honours as many tracked items as the priorities allow, and what was dropped.

    On True the backend's last `check` call holds the solution.
    """
    active = list(tracked)
    dropped: list[Dropped] = []
    deadline = time.monotonic() + timeout_s
    while True:
        res, cands = check(active, deadline - time.monotonic())
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
            reason = "solver timeout"
            deadline = time.monotonic() + max(1.0, timeout_s / 4)
        active.remove(victim)
        dropped.append(Dropped(victim, reason))
        if victim.kind == "object":
            for t in [t for t in active if t.kind == "relation" and victim.item in t.objects]:
                active.remove(t)
                dropped.append(Dropped(t, f"its object {victim.item} was dropped"))
