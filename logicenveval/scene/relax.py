"""Solve with tracked assumptions; on unsat drop by priority using z3 unsat cores.

Priority (first dropped first): enrichment relations, enrichment objects, then task relations.
Task objects are never tracked: their constraints are hard.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import z3


@dataclass
class Tracked:
    lit: z3.BoolRef
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


def solve_relaxing(s: z3.Solver, tracked: list[Tracked], timeout_s: float
                   ) -> tuple[z3.ModelRef | None, list[Dropped]]:
    """A model honouring as many tracked items as the priorities allow, and what was dropped."""
    active = list(tracked)
    dropped: list[Dropped] = []
    deadline = time.monotonic() + timeout_s
    while True:
        left_ms = max(1, int((deadline - time.monotonic()) * 1000))
        s.set("timeout", left_ms)
        res = s.check(*[t.lit for t in active])
        if res == z3.sat:
            return s.model(), dropped
        if res == z3.unsat:
            core = {str(c) for c in s.unsat_core()}
            cands = [t for t in active if str(t.lit) in core]
            if not cands:
                return None, dropped
            victim = min(reversed(cands), key=lambda t: t.rank)
            others = [t.item for t in cands if t is not victim][:4]
            reason = ("unsatisfiable with the room's hard constraints"
                      + (f" and {', '.join(others)}" if others else ""))
        else:
            if not active:
                return None, dropped
            victim = min(reversed(active), key=lambda t: t.rank)
            reason = "solver timeout"
            deadline = time.monotonic() + max(1.0, timeout_s / 4)
        active.remove(victim)
        dropped.append(Dropped(victim, reason))
        if victim.kind == "object":
            for t in [t for t in active if t.kind == "relation" and victim.item in t.objects]:
                active.remove(t)
                dropped.append(Dropped(t, f"its object {victim.item} was dropped"))
