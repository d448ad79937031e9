"""`exact`: a provably minimum set of trajectories that takes every decision path at least once.

Independent subtasks: any cover needs at least max_i |paths_i| trajectories (subtask i's paths are
pairwise exclusive) and that many suffice — row j takes path min(j, |paths_i| - 1) of subtask i
(later rows repeat the last path, which keeps the set deterministic and readable). Built in
O(Σ|paths_i|) without touching the product.

With forbidden cross-subtask pairs the problem is set cover over admissible trajectories; we solve
it with OR-Tools CP-SAT over K trajectory slots (K = a greedy cover's size, its solution as hint),
minimising the used slots, and report whether optimality was proven. Paths that occur in no
admissible trajectory are reported by key (TrajectoryError).
"""

from __future__ import annotations

from dataclasses import dataclass

from ortools.sat.python import cp_model

from logicenveval.errors import TrajectoryError
from logicenveval.logic.constraints import PathConstraints
from logicenveval.logic.selectors import PathsPerSubtask, check_inputs
from logicenveval.model.tree import Trajectory

#: CP-SAT budget per solve; tasks have tens of paths, so optimality is proven far below it
TIME_LIMIT_S = 30.0


@dataclass(frozen=True, slots=True)
class CoverResult:
    trajectories: tuple[Trajectory, ...]
    #: True when the size is proven minimum (lower bound reached or CP-SAT status OPTIMAL)
    optimal: bool
    lower_bound: int


def independent_cover(paths_per_subtask: PathsPerSubtask) -> list[Trajectory]:
    """The max_i |paths_i| rows; row j takes path min(j, |paths_i| - 1) of subtask i."""
    rows = max(len(paths) for paths in paths_per_subtask)
    return [
        Trajectory(tuple(paths[min(j, len(paths) - 1)] for paths in paths_per_subtask))
        for j in range(rows)
    ]


def _solver() -> cp_model.CpSolver:
    solver = cp_model.CpSolver()
    solver.parameters.num_workers = 1  # deterministic, and the machine is shared
    solver.parameters.random_seed = 0
    solver.parameters.max_time_in_seconds = TIME_LIMIT_S
    return solver


def _pairs(
    paths_per_subtask: PathsPerSubtask, constraints: PathConstraints
) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    index = {p.key: (i, a) for i, paths in enumerate(paths_per_subtask) for a, p in enumerate(paths)}
    return [
        (index[x], index[y]) for x, y in (sorted(pair) for pair in constraints.forbidden)
    ]


def _best_witness(
    paths_per_subtask: PathsPerSubtask,
    pairs: list[tuple[tuple[int, int], tuple[int, int]]],
    fixed: tuple[int, int],
    uncovered: set[tuple[int, int]],
) -> tuple[int, ...] | None:
    """An admissible trajectory through `fixed` covering the most still-uncovered paths."""
    model = cp_model.CpModel()
    x = [[model.new_bool_var(f"x{i}_{a}") for a in range(len(ps))] for i, ps in enumerate(paths_per_subtask)]
    for row in x:
        model.add_exactly_one(row)
    for (i, a), (j, b) in pairs:
        model.add_bool_or([x[i][a].Not(), x[j][b].Not()])
    model.add(x[fixed[0]][fixed[1]] == 1)
    model.maximize(sum(x[i][a] for i, a in sorted(uncovered)))
    solver = _solver()
    status = solver.solve(model)
    if status not in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        return None
    return tuple(next(a for a, v in enumerate(row) if solver.value(v)) for row in x)


def _constrained_cover(
    paths_per_subtask: PathsPerSubtask, constraints: PathConstraints
) -> CoverResult:
    pairs = _pairs(paths_per_subtask, constraints)
    all_paths = [(i, a) for i, ps in enumerate(paths_per_subtask) for a in range(len(ps))]
    lower = max(len(ps) for ps in paths_per_subtask)
    uncovered = set(all_paths)
    greedy: list[tuple[int, ...]] = []
    impossible: list[str] = []
    for i, a in all_paths:
        if (i, a) not in uncovered:
            continue
        witness = _best_witness(paths_per_subtask, pairs, (i, a), uncovered)
        if witness is None:
            impossible.append(paths_per_subtask[i][a].key)
            uncovered.discard((i, a))
            continue
        greedy.append(witness)
        uncovered -= set(enumerate(witness))
    if impossible:
        raise TrajectoryError(
            f"decision path(s) {impossible} occur in no admissible trajectory",
            field="constraints",
            hint="relax the forbidden pairs that exclude these paths with every other choice",
        )
    optimal = len(greedy) == lower
    rows = greedy
    if not optimal:
        rows, optimal = _solve_set_cover(paths_per_subtask, pairs, greedy, lower)
    trajectories = tuple(
        Trajectory(tuple(paths_per_subtask[i][a] for i, a in enumerate(row))) for row in sorted(rows)
    )
    return CoverResult(trajectories, optimal, lower)


def _solve_set_cover(
    paths_per_subtask: PathsPerSubtask,
    pairs: list[tuple[tuple[int, int], tuple[int, int]]],
    greedy: list[tuple[int, ...]],
    lower: int,
) -> tuple[list[tuple[int, ...]], bool]:
    model = cp_model.CpModel()
    slots = len(greedy)
    used = [model.new_bool_var(f"u{k}") for k in range(slots)]
    x = [
        [[model.new_bool_var(f"x{k}_{i}_{a}") for a in range(len(ps))] for i, ps in enumerate(paths_per_subtask)]
        for k in range(slots)
    ]
    for k in range(slots):
        for row in x[k]:
            model.add(sum(row) == used[k])
        for (i, a), (j, b) in pairs:
            model.add_bool_or([x[k][i][a].Not(), x[k][j][b].Not()])
        if k + 1 < slots:
            model.add_implication(used[k + 1], used[k])  # symmetry breaking
    for i, ps in enumerate(paths_per_subtask):
        for a in range(len(ps)):
            model.add_bool_or([x[k][i][a] for k in range(slots)])
    model.add(sum(used) >= lower)
    model.minimize(sum(used))
    for k, hint in enumerate(greedy):
        model.add_hint(used[k], 1)
        for i, chosen in enumerate(hint):
            for a in range(len(paths_per_subtask[i])):
                model.add_hint(x[k][i][a], int(a == chosen))
    solver = _solver()
    status = solver.solve(model)
    if status not in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        return greedy, False
    rows = [
        tuple(next(a for a, v in enumerate(row) if solver.value(v)) for row in x[k])
        for k in range(slots)
        if solver.value(used[k])
    ]
    return rows, status == cp_model.OPTIMAL


def exact_cover(
    paths_per_subtask: PathsPerSubtask, constraints: PathConstraints | None = None
) -> CoverResult:
    """Minimum cover with its optimality certificate (see module docstring)."""
    cons = check_inputs(paths_per_subtask, constraints)
    lower = max(len(ps) for ps in paths_per_subtask)
    if not cons.forbidden:
        return CoverResult(tuple(independent_cover(paths_per_subtask)), True, lower)
    return _constrained_cover(paths_per_subtask, cons)


class ExactSelector:
    name = "exact"

    def select(
        self, paths_per_subtask: PathsPerSubtask, constraints: PathConstraints | None = None
    ) -> list[Trajectory]:
        return list(exact_cover(paths_per_subtask, constraints).trajectories)


SELECTOR = ExactSelector()

