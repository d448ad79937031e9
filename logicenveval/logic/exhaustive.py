"""`exhaustive`: the paper's exponential minimum-set-cover search (Table on MTSA, "Exhaustive").

The paper compares MTSA with "the Exhaustive algorithm", which "theoretically guarantees a minimum
set-cover" at O(2^N) cost, N being the number of trajectories of the Cartesian product. We
implement exactly that search: subsets of the admissible product are enumerated by increasing
size (itertools.combinations, lexicographic), and the first subset that takes every decision path
is returned — a minimum cover by construction. Paths are bit masks, so each test is a few integer
ORs: a fair implementation, not a strawman.

The search has a time budget (`budget_s`, default 10 s). When it runs out, `exhaustive_cover`
reports `optimal=False` and returns the MTSA cover instead, so a generator still gets a cover;
`logicenvgen-exhaustive` records that in its artefacts.
"""

from __future__ import annotations

import itertools
import time
from dataclasses import dataclass
from functools import reduce
from operator import or_

from logicenveval.errors import TrajectoryError
from logicenveval.logic.constraints import PathConstraints
from logicenveval.logic.mtsa import SELECTOR as MTSA
from logicenveval.logic.selectors import PathsPerSubtask, check_inputs, uncovered
from logicenveval.model.tree import Trajectory

#: default search budget in seconds
BUDGET_S = 10.0


@dataclass(frozen=True, slots=True)
class SearchResult:
    trajectories: tuple[Trajectory, ...]
    #: True when the search finished (the cover is minimum); False: budget hit, MTSA's cover
    optimal: bool
    #: subsets tested
    tested: int


def exhaustive_cover(
    paths_per_subtask: PathsPerSubtask,
    constraints: PathConstraints | None = None,
    *,
    budget_s: float = BUDGET_S,
) -> SearchResult:
    cons = check_inputs(paths_per_subtask, constraints)
    product = [c for c in itertools.product(*paths_per_subtask) if cons.admits(c)]
    missing = uncovered([Trajectory(c) for c in product], paths_per_subtask)
    if missing:
        raise TrajectoryError(
            f"decision path(s) {missing} occur in no admissible trajectory",
            field="constraints",
            hint="relax the forbidden pairs that exclude these paths with every other choice",
        )
    bit = {p.key: 1 << n for n, p in enumerate(p for ps in paths_per_subtask for p in ps)}
    full = (1 << len(bit)) - 1
    masks = [reduce(or_, (bit[p.key] for p in c)) for c in product]
    deadline = time.monotonic() + budget_s
    tested = 0
    for size in range(1, len(masks) + 1):
        subsets = zip(itertools.combinations(range(len(masks)), size),
                      itertools.combinations(masks, size), strict=True)
        for subset, chosen in subsets:
            tested += 1
            if tested % 4096 == 0 and time.monotonic() > deadline:
                return SearchResult(tuple(MTSA.select(paths_per_subtask, cons)), False, tested)
            if reduce(or_, chosen) == full:
                return SearchResult(tuple(Trajectory(product[i]) for i in subset), True, tested)
    raise AssertionError("the whole admissible product covers every path")  # checked above


class ExhaustiveSelector:
    name = "exhaustive"

    def __init__(self, budget_s: float = BUDGET_S) -> None:
        self.budget_s = budget_s

    def select(
        self, paths_per_subtask: PathsPerSubtask, constraints: PathConstraints | None = None
    ) -> list[Trajectory]:
        return list(exhaustive_cover(paths_per_subtask, constraints, budget_s=self.budget_s).trajectories)


SELECTOR = ExhaustiveSelector()
