"""`mtsa`: the paper's Minimal Trajectory Selection Algorithm (Algorithm 1) as written.

A constraint is a decision path (paper §3.2). The Cartesian product is scanned in lexicographic
order; a trajectory whose constraints are disjoint from the pool is selected and its constraints
join the pool; one that overlaps the pool partially (not a subset) goes to the candidate set.
Update(T_min, T_cand, C_pool) is under-specified in the paper; we read it as: scan the candidates
in insertion order and select each one whose constraints are not yet all in the pool, adding them.
"""

from __future__ import annotations

import itertools
import time

from logicenveval.errors import TrajectoryError
from logicenveval.logic.constraints import PathConstraints
from logicenveval.logic.selectors import PathsPerSubtask, check_inputs, uncovered
from logicenveval.model.tree import DecisionPath, Trajectory

#: the deadline is checked every this many trajectories, in the scan and in the update pass
#: (~1 ms of work with constraints to check, so the budget holds in every phase)
_CHECK_EVERY = 1024


def mtsa_impl(
    paths_per_subtask: PathsPerSubtask,
    constraints: PathConstraints,
    deadline: float | None = None,
) -> list[Trajectory] | None:
    """Algorithm 1 on trusted inputs; None when `deadline` (time.monotonic) passes first.

    Paths are numbered globally so the scan works on small integer sets (a fair baseline).
    """
    ids: list[range] = []
    flat: list[DecisionPath] = []
    for paths in paths_per_subtask:
        ids.append(range(len(flat), len(flat) + len(paths)))
        flat.extend(paths)
    check = bool(constraints.forbidden)
    pool: set[int] = set()
    selected: list[tuple[int, ...]] = []
    candidates: list[tuple[int, ...]] = []
    for n, combo in enumerate(itertools.product(*ids)):
        if deadline is not None and n % _CHECK_EVERY == 0 and time.monotonic() > deadline:
            return None
        if check and not constraints.admits([flat[i] for i in combo]):
            continue
        if pool.isdisjoint(combo):
            selected.append(combo)
            pool.update(combo)
        elif not pool.issuperset(combo):
            candidates.append(combo)
    for n, combo in enumerate(candidates):  # Update(T_min, T_cand, C_pool)
        if deadline is not None and n % _CHECK_EVERY == 0 and time.monotonic() > deadline:
            return None
        if not pool.issuperset(combo):
            selected.append(combo)
            pool.update(combo)
    return [Trajectory(tuple(flat[i] for i in combo)) for combo in selected]


class MtsaSelector:
    name = "mtsa"

    def select(
        self, paths_per_subtask: PathsPerSubtask, constraints: PathConstraints | None = None
    ) -> list[Trajectory]:
        cons = check_inputs(paths_per_subtask, constraints)
        out = mtsa_impl(paths_per_subtask, cons)
        assert out is not None  # no deadline given
        missing = uncovered(out, paths_per_subtask)
        if missing:
            raise TrajectoryError(
                f"decision path(s) {missing} occur in no admissible trajectory",
                field="constraints",
                hint="relax the forbidden pairs that exclude these paths with every other choice",
            )
        return out


SELECTOR = MtsaSelector()
