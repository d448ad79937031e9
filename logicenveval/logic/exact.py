"""`exact`: a provably minimum set of trajectories that takes every decision path at least once.

Independent subtasks: any cover needs at least max_i |paths_i| trajectories (subtask i's paths are
pairwise exclusive) and that many suffice — row j takes path min(j, |paths_i| - 1) of subtask i
(later rows repeat the last path, which keeps the set deterministic and readable). Built in
O(Σ|paths_i|) without touching the product.

With forbidden cross-subtask pairs the problem is set cover over admissible trajectories:

1. Lower bound: max_i |paths_i|. Matching construction (warm start): the subtasks are placed
   one after another into K rows, each by a bipartite matching of its paths to compatible rows;
   a subtask that does not fit moves to the front and the pass restarts. A cover with K = the
   lower bound is optimal without any search (the common case).
2. Otherwise the bound is raised by greedy cliques of the conflict graph (paths that pairwise
   cannot share a trajectory each need their own), and K grows from it until the construction
   finds a cover.
3. When the construction finds no cover at all, a greedy cover (CP-SAT finds, per uncovered path,
   the admissible trajectory through it that covers most; a path with none is reported by key in
   a `TrajectoryError`) is the upper bound instead.
4. Above the lower bound, CP-SAT minimises the used slots among the upper bound's count, with that
   cover as hint, the lower bound as a constraint, and symmetry broken by anchoring the paths of
   one subtask to the first slots. `optimal` reports whether CP-SAT proved OPTIMAL.
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

#: a forbidden pair as ((subtask, path), (subtask, path)) indices
Pair = tuple[tuple[int, int], tuple[int, int]]
#: `conflicts[i][a][j]`: the paths of subtask j that path a of subtask i cannot share a row with
Conflicts = list[list[list[set[int]]]]
Row = tuple[int, ...]


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


def _pairs(paths_per_subtask: PathsPerSubtask, constraints: PathConstraints) -> list[Pair]:
    index = {p.key: (i, a) for i, paths in enumerate(paths_per_subtask) for a, p in enumerate(paths)}
    return [
        (index[x], index[y]) for x, y in (sorted(pair) for pair in constraints.forbidden)
    ]


def _conflicts(paths_per_subtask: PathsPerSubtask, pairs: list[Pair]) -> Conflicts:
    c: Conflicts = [[[set() for _ in paths_per_subtask] for _ in ps] for ps in paths_per_subtask]
    for (i, a), (j, b) in pairs:
        c[i][a][j].add(b)
        c[j][b][i].add(a)
    return c


def _clique_bound(sizes: list[int], conflicts: Conflicts) -> int:
    """The largest of greedy cliques of the conflict graph, one grown from every path.

    Paths that pairwise cannot share a trajectory (same subtask, or a forbidden pair) each need
    their own. Bitsets over the global path numbering; a greedy step adds the candidate with the
    most neighbours among the remaining candidates.
    """
    offset = [sum(sizes[:i]) for i in range(len(sizes))]
    adj: list[int] = []
    for i, n in enumerate(sizes):
        same = ((1 << n) - 1) << offset[i]
        for a in range(n):
            mask = same & ~(1 << (offset[i] + a))
            for j, others in enumerate(conflicts[i][a]):
                for b in others:
                    mask |= 1 << (offset[j] + b)
            adj.append(mask)
    best = 0
    for v in range(len(adj)):
        size, cand = 1, adj[v]
        while cand:
            u = max(_bits(cand), key=lambda w: ((adj[w] & cand).bit_count(), -w))
            cand &= adj[u]
            size += 1
        best = max(best, size)
    return best


def _bits(mask: int) -> list[int]:
    out = []
    while mask:
        low = mask & -mask
        out.append(low.bit_length() - 1)
        mask ^= low
    return out


def _rows_by_matching(sizes: list[int], conflicts: Conflicts, rows: int,
                      order: list[int]) -> list[Row] | None:
    """A cover with exactly `rows` trajectories, or None when the construction finds none.

    One pass (`_match_pass`) places the subtasks in `order`; when a subtask does not fit, it
    moves to the front of the order and the pass restarts ("squeaky wheel"), at most
    4 × subtasks passes. Deterministic.
    """
    order = list(order)
    for _ in range(4 * len(sizes)):
        got = _match_pass(sizes, conflicts, rows, order)
        if not isinstance(got, int):
            return got
        order.remove(got)
        order.insert(0, got)
    return None


def _match_pass(sizes: list[int], conflicts: Conflicts, rows: int, order: list[int]) -> list[Row] | int:
    """Place the subtasks in `order` into `rows` rows; the rows, or the subtask that did not fit.

    The first subtask puts path min(k, n-1) in row k; each later one matches its paths to
    distinct compatible rows (Kuhn's augmenting paths, so every path is used), then fills the
    remaining rows with their first compatible path.
    """
    if max(sizes) > rows:
        return order[0]
    chosen: list[dict[int, int]] = [{} for _ in range(rows)]  # row -> {subtask: path}
    first = order[0]
    for k in range(rows):
        chosen[k][first] = min(k, sizes[first] - 1)
    for i in order[1:]:
        n = sizes[i]
        fits = [[k for k in range(rows)
                 if all(b not in conflicts[i][a][j] for j, b in chosen[k].items())] for a in range(n)]
        row_of: dict[int, int] = {}  # row -> path of subtask i
        for a in sorted(range(n), key=lambda a: (len(fits[a]), a)):
            if not _augment(a, fits, row_of, set()):
                return i
        for k in range(rows):
            if k not in row_of:
                free = [a for a in range(n) if k in fits[a]]
                if not free:
                    return i
                row_of[k] = free[0]
        for k, a in row_of.items():
            chosen[k][i] = a
    return [tuple(row[i] for i in range(len(sizes))) for row in chosen]


def _augment(a: int, fits: list[list[int]], row_of: dict[int, int], seen: set[int]) -> bool:
    """Give path `a` a row of its own, moving earlier paths along an augmenting path if needed."""
    for k in fits[a]:
        if k in seen:
            continue
        seen.add(k)
        if k not in row_of or _augment(row_of[k], fits, row_of, seen):
            row_of[k] = a
            return True
    return False


def _best_witness(
    paths_per_subtask: PathsPerSubtask,
    pairs: list[Pair],
    fixed: tuple[int, int],
    uncovered: set[tuple[int, int]],
) -> Row | None:
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


def _greedy_cover(paths_per_subtask: PathsPerSubtask, pairs: list[Pair]) -> list[Row]:
    """An upper bound that also names every path in no admissible trajectory."""
    all_paths = [(i, a) for i, ps in enumerate(paths_per_subtask) for a in range(len(ps))]
    uncovered = set(all_paths)
    greedy: list[Row] = []
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
    return greedy


def _constrained_cover(
    paths_per_subtask: PathsPerSubtask, constraints: PathConstraints
) -> CoverResult:
    pairs = _pairs(paths_per_subtask, constraints)
    conflicts = _conflicts(paths_per_subtask, pairs)
    sizes = [len(ps) for ps in paths_per_subtask]
    # large, conflict-rich subtasks first: they are the hardest to fit into rows filled by others
    degree = [sum(len(s) for per_path in conflicts[i] for s in per_path) for i in range(len(sizes))]
    order = sorted(range(len(sizes)), key=lambda i: (-sizes[i], -degree[i], i))
    lower = max(sizes)
    rows = _rows_by_matching(sizes, conflicts, lower, order)
    if rows is None:  # the conflicts may force more rows: a better bound, then larger K
        lower = max(lower, _clique_bound(sizes, conflicts))
        for k in range(lower, lower + max(sizes) + 1):
            rows = _rows_by_matching(sizes, conflicts, k, order)
            if rows is not None:
                break
    if rows is None:  # also names the paths that are in no admissible trajectory
        rows = _greedy_cover(paths_per_subtask, pairs)
    optimal = len(rows) == lower
    if not optimal:
        rows, optimal = _solve_set_cover(paths_per_subtask, pairs, rows, lower, order[0])
    trajectories = tuple(
        Trajectory(tuple(paths_per_subtask[i][a] for i, a in enumerate(row))) for row in sorted(rows)
    )
    return CoverResult(trajectories, optimal, lower)


def _anchored(rows: list[Row], anchor: int, n: int) -> list[Row]:
    """The same rows, reordered so that row k (k < n) takes path k of subtask `anchor`."""
    first: dict[int, int] = {}
    for r, row in enumerate(rows):
        first.setdefault(row[anchor], r)
    head = {first[a] for a in range(n)}
    return [rows[first[a]] for a in range(n)] + [row for r, row in enumerate(rows) if r not in head]


def _solve_set_cover(
    paths_per_subtask: PathsPerSubtask,
    pairs: list[Pair],
    start: list[Row],
    lower: int,
    anchor: int,
) -> tuple[list[Row], bool]:
    """Fewest used slots out of len(start), proven by CP-SAT.

    Symmetry breaking: every path of the `anchor` subtask lies in some used slot and slots are
    interchangeable, so slot k < n_anchor takes the anchor's path k; later slots are used in
    order. The warm start `start` is reordered to agree with that.
    """
    start = _anchored(start, anchor, len(paths_per_subtask[anchor]))
    model = cp_model.CpModel()
    slots = len(start)
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
        if k < len(paths_per_subtask[anchor]):
            model.add(x[k][anchor][k] == 1)
        elif k + 1 < slots:
            model.add_implication(used[k + 1], used[k])
    for i, ps in enumerate(paths_per_subtask):
        for a in range(len(ps)):
            model.add_bool_or([x[k][i][a] for k in range(slots)])
    model.add(sum(used) >= lower)
    model.minimize(sum(used))
    for k, hint in enumerate(start):
        model.add_hint(used[k], 1)
        for i, chosen in enumerate(hint):
            for a in range(len(paths_per_subtask[i])):
                model.add_hint(x[k][i][a], int(a == chosen))
    solver = _solver()
    status = solver.solve(model)
    if status not in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        return start, False
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
