"""The reference minimal trajectory set used by JI, and the Jaccard index.

The paper compares a generator's trajectory set with "the ground-truth set (minimal)". A task has
usually several minimum covers (any pairing of the subtasks' paths into max_i |paths_i| rows), and
the paper does not say which one; scoring against one fixed cover would punish a generator for
picking another, equally minimal one (MTSA and our exact cover pick different ones on
`clean_living_room`). So the reference is the minimum cover **closest** to the generator's set:
among all covers of minimum size that respect the task's forbidden pairs, the one maximising the
Jaccard index with the realised trajectories. With |C| fixed at the minimum size m, maximising
|R ∩ C| / (|R| + m - |R ∩ C|) is maximising the overlap |R ∩ C|, which CP-SAT solves exactly.

`reference_set(task)` stays the canonical minimum cover (`exact` on the GT trees with the task's
consistency pairs; for the paper's independent subtasks the plain max_i |paths_i| cover).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from ortools.sat.python import cp_model

from logicenveval.logic.constraints import PathConstraints, task_constraints
from logicenveval.logic.exact import exact_cover
from logicenveval.logic.selectors import PathsPerSubtask, check_inputs
from logicenveval.model.task import Task
from logicenveval.model.tree import Trajectory, task_paths

#: CP-SAT budget of one closest-cover solve; benchmark tasks are proven optimal in milliseconds
TIME_LIMIT_S = 30.0


@dataclass(frozen=True, slots=True)
class ClosestCover:
    #: a minimum cover of the GT trajectories, closest to the realised set
    trajectories: tuple[Trajectory, ...]
    #: realised trajectories that are rows of that cover
    overlap: int
    #: the Jaccard index between the realised set and `trajectories`
    ji: float
    #: True when CP-SAT proved the overlap maximum (always, unless the time limit was hit)
    optimal: bool


def reference_set(task: Task) -> list[Trajectory]:
    return list(exact_cover(task_paths(task), task_constraints(task)).trajectories)


def jaccard(a: Iterable[str], b: Iterable[str]) -> float:
    """|A ∩ B| / |A ∪ B| over trajectory keys; 0.0 when both are empty."""
    sa, sb = set(a), set(b)
    union = sa | sb
    return len(sa & sb) / len(union) if union else 0.0


def closest_reference(task: Task, realised: Iterable[str]) -> ClosestCover:
    """The minimum cover of `task`'s GT trajectories closest to the `realised` trajectory keys."""
    return closest_cover(task_paths(task), realised, task_constraints(task))


def closest_cover(
    paths_per_subtask: PathsPerSubtask,
    realised: Iterable[str],
    constraints: PathConstraints | None = None,
) -> ClosestCover:
    """Among the minimum covers, one maximising the Jaccard index with `realised` (keys).

    Realised keys that are not admissible trajectories of these paths can be in no cover; they
    still count in the union, as in `jaccard`.
    """
    cons = check_inputs(paths_per_subtask, constraints)
    base = exact_cover(paths_per_subtask, cons).trajectories
    keys = set(realised)
    index = {p.key: (i, a) for i, ps in enumerate(paths_per_subtask) for a, p in enumerate(ps)}
    rows: list[tuple[int, ...]] = []
    for key in sorted(keys):
        parts = key.split(" | ")
        if len(parts) != len(paths_per_subtask) or any(p not in index for p in parts):
            continue
        row = tuple(index[p][1] for p in parts)
        if [index[p][0] for p in parts] == list(range(len(parts))) and cons.admits(
                [paths_per_subtask[i][a] for i, a in enumerate(row)]):
            rows.append(row)
    if not rows:
        return ClosestCover(base, 0, jaccard(keys, (t.key for t in base)), True)
    chosen, optimal = _max_overlap(paths_per_subtask, cons, len(base), rows, base)
    cover = tuple(Trajectory(tuple(paths_per_subtask[i][a] for i, a in enumerate(r))) for r in chosen)
    ref = {t.key for t in cover}
    return ClosestCover(cover, len(keys & ref), jaccard(keys, ref), optimal)


class _Model(cp_model.CpModel):
    """A CP-SAT model without the ~60 camelCase aliases `CpModel` binds to every new instance
    (a fifth of a closest-cover solve's time, measured over a run's 125 units); the model proto,
    hence the cover chosen, is unchanged (`scene.layout_cpsat` does the same)."""

    def _add_pre_pep8_methods(self) -> None:
        return None


def _max_overlap(
    paths_per_subtask: PathsPerSubtask,
    cons: PathConstraints,
    size: int,
    rows: list[tuple[int, ...]],
    hint: tuple[Trajectory, ...],
) -> tuple[list[tuple[int, ...]], bool]:
    """`size` slots forming a cover (one-hot path per subtask, forbidden pairs excluded) that
    contain as many of `rows` as possible; returns the slots sorted, and whether proven optimal."""
    index = {p.key: (i, a) for i, ps in enumerate(paths_per_subtask) for a, p in enumerate(ps)}
    pairs = [(index[x], index[y]) for x, y in (sorted(pair) for pair in cons.forbidden)]
    model = _Model()
    x = [[[model.new_bool_var(f"x{k}_{i}_{a}") for a in range(len(ps))]
          for i, ps in enumerate(paths_per_subtask)] for k in range(size)]
    for k in range(size):
        for choice in x[k]:
            model.add_exactly_one(choice)
        for (i, a), (j, b) in pairs:
            model.add_bool_or([x[k][i][a].Not(), x[k][j][b].Not()])
    for i, ps in enumerate(paths_per_subtask):
        for a in range(len(ps)):
            model.add_bool_or([x[k][i][a] for k in range(size)])
    hits = []
    for r, row in enumerate(rows):
        here = []
        for k in range(size):
            z = model.new_bool_var(f"z{k}_{r}")
            for i, a in enumerate(row):
                model.add_implication(z, x[k][i][a])
            here.append(z)
        hit = model.new_bool_var(f"y{r}")
        model.add_bool_or([hit.Not(), *here])
        hits.append(hit)
    model.maximize(sum(hits))
    for k, t in enumerate(hint):
        for i, p in enumerate(t.paths):
            for a in range(len(paths_per_subtask[i])):
                model.add_hint(x[k][i][a], int(a == index[p.key][1]))
    solver = cp_model.CpSolver()
    solver.parameters.num_workers = 1  # deterministic, and the machine is shared
    solver.parameters.random_seed = 0
    solver.parameters.max_time_in_seconds = TIME_LIMIT_S
    status = solver.solve(model)
    if status not in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        return sorted(tuple(index[p.key][1] for p in t.paths) for t in hint), False
    chosen = sorted(tuple(next(a for a, v in enumerate(choice) if solver.value(v)) for choice in x[k])
                    for k in range(size))
    return chosen, status == cp_model.OPTIMAL
