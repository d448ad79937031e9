"""Selectors over decision paths: registry, MTSA as written, exact minimum cover (issue 5)."""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import load_task
from logicenveval.errors import TrajectoryError
from logicenveval.logic.constraints import PathConstraints, task_constraints
from logicenveval.logic.exact import exact_cover, independent_cover
from logicenveval.logic.exhaustive import exhaustive_cover
from logicenveval.logic.mtsa import mtsa_impl
from logicenveval.logic.selectors import get_selector, selector_names, uncovered
from logicenveval.model.task import Leaf, Node, Subtask
from logicenveval.model.tree import DecisionPath, Trajectory, task_paths, tree_paths

TASKS = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks"
Forest = list[list[DecisionPath]]
#: product size up to which the brute-force optimum is computed
SMALL = 36


@st.composite
def trees(draw: st.DrawFn, name: str, depth: int = 2) -> Node | Leaf:
    counter = [0]

    def build(level: int) -> Node | Leaf:
        if level == depth or not draw(st.booleans()):
            return Leaf(plan=[], goal="true")
        counter[0] += 1
        width = draw(st.integers(1, 3))
        return Node(var=f"{name}v{counter[0]}", branches={f"b{k}": build(level + 1) for k in range(width)})

    return build(0)


@st.composite
def forests(draw: st.DrawFn, max_subtasks: int = 3) -> Forest:
    n = draw(st.integers(1, max_subtasks))
    return [tree_paths(Subtask(id=f"s{i}", tree=draw(trees(f"s{i}")))) for i in range(n)]


@st.composite
def forests_with_pairs(draw: st.DrawFn) -> tuple[Forest, PathConstraints]:
    forest = draw(forests())
    cross = [
        (a.key, b.key)
        for i, j in itertools.combinations(range(len(forest)), 2)
        for a in forest[i]
        for b in forest[j]
    ]
    chosen = draw(st.lists(st.sampled_from(cross), max_size=6, unique=True)) if cross else []
    return forest, PathConstraints.of_pairs(chosen)


def _admissible(forest: Forest, cons: PathConstraints) -> list[tuple[DecisionPath, ...]]:
    return [c for c in itertools.product(*forest) if cons.admits(c)]


def _coverable(forest: Forest, cons: PathConstraints) -> bool:
    return not uncovered([Trajectory(c) for c in _admissible(forest, cons)], forest)


def _brute_optimum(forest: Forest, cons: PathConstraints) -> int:
    """Smallest cover by iterative deepening: branch on the first uncovered path.

    Pruned by the bound "a subtask with m uncovered paths needs m more trajectories".
    """
    trajs = [frozenset(p.key for p in c) for c in _admissible(forest, cons)]
    keys = [p.key for ps in forest for p in ps]

    def fits(covered: frozenset[str], budget: int) -> bool:
        missing = next((k for k in keys if k not in covered), None)
        if missing is None:
            return True
        need = max(sum(p.key not in covered for p in ps) for ps in forest)
        return budget >= need and any(fits(covered | t, budget - 1) for t in trajs if missing in t)

    return next(k for k in range(len(keys) + 1) if fits(frozenset(), k))


def _keys(trajs: Sequence[Trajectory]) -> list[str]:
    return [t.key for t in trajs]


def _paths(sizes: Sequence[int]) -> Forest:
    return [[DecisionPath(f"s{i}", ((f"v{i}", f"p{a}"),)) for a in range(n)] for i, n in enumerate(sizes)]


def test_registry_names_and_unknown_name() -> None:
    assert selector_names() == ["product", "mtsa", "exhaustive", "exact"]
    assert all(get_selector(n).name == n for n in selector_names())
    with pytest.raises(TrajectoryError, match="unknown trajectory selector 'greedy'"):
        get_selector("greedy")


def test_clean_living_room_selectors() -> None:
    paths = task_paths(load_task("clean_living_room", TASKS))
    assert [len(p) for p in paths] == [3, 2, 2]
    assert len(get_selector("product").select(paths)) == 12
    assert len(get_selector("exhaustive").select(paths)) == 3
    mtsa = get_selector("mtsa").select(paths)
    # Algorithm 1 in lexicographic order: (doll,yes,yes) and (other,no,no) are disjoint from the
    # pool; (no,yes,yes) is a partial overlap picked by Update.
    assert [tuple(p.steps[-1][1] for p in t.paths) for t in mtsa] == [
        ("doll", "yes", "yes"),
        ("other", "no", "no"),
        ("no", "yes", "yes"),
    ]
    exact = get_selector("exact").select(paths)
    assert len(exact) == 3 and not uncovered(exact, paths)


def test_mtsa_update_step_selects_partial_overlaps() -> None:
    # 2 x 3: first row (a0,b0) disjoint; (a1,b1) disjoint; (a0,b2) is a partial overlap -> Update.
    paths = _paths([2, 3])
    out = get_selector("mtsa").select(paths)
    assert _keys(out) == [
        "s0:v0=p0 | s1:v1=p0",
        "s0:v0=p1 | s1:v1=p1",
        "s0:v0=p0 | s1:v1=p2",
    ]


def test_mtsa_deadline_returns_none() -> None:
    assert mtsa_impl(_paths([3, 3]), PathConstraints(), deadline=0.0) is None


def test_independent_cover_rows() -> None:
    rows = independent_cover(_paths([1, 3, 2]))
    assert [[p.steps[0][1] for p in t.paths] for t in rows] == [
        ["p0", "p0", "p0"],
        ["p0", "p1", "p1"],
        ["p0", "p2", "p1"],
    ]


def test_exact_with_forbidden_pairs_is_proven_optimal() -> None:
    paths = _paths([2, 2])
    cons = PathConstraints.of_pairs([("s0:v0=p0", "s1:v1=p0"), ("s0:v0=p1", "s1:v1=p1")])
    result = exact_cover(paths, cons)
    assert result.optimal and len(result.trajectories) == 2
    assert all(cons.admits_trajectory(t) for t in result.trajectories)


def test_exact_names_uncoverable_path() -> None:
    paths = _paths([1, 2])
    cons = PathConstraints.of_pairs([("s0:v0=p0", "s1:v1=p1")])
    with pytest.raises(TrajectoryError, match=r"s1:v1=p1"):
        get_selector("exact").select(paths, cons)
    with pytest.raises(TrajectoryError, match=r"s1:v1=p1"):
        get_selector("mtsa").select(paths, cons)


@pytest.mark.parametrize(
    ("pairs", "message"),
    [
        ([("s0:v0=p0", "nope")], "unknown decision path"),
        ([("s0:v0=p0", "s0:v0=p1")], "different subtasks"),
    ],
)
def test_bad_constraints_are_rejected(pairs: list[tuple[str, str]], message: str) -> None:
    with pytest.raises(TrajectoryError, match=message):
        get_selector("exact").select(_paths([2, 2]), PathConstraints.of_pairs(pairs))


def test_bad_inputs_are_rejected() -> None:
    with pytest.raises(TrajectoryError, match="no subtasks"):
        get_selector("mtsa").select([])
    with pytest.raises(TrajectoryError, match="no decision paths"):
        get_selector("exact").select([[]])
    dup = _paths([2])
    with pytest.raises(TrajectoryError, match="given twice"):
        get_selector("exhaustive").select([dup[0] + dup[0][:1]])


def test_task_constraints_forbid_contradicting_shared_variables() -> None:
    a = Subtask(id="a", tree=Node(var="x", branches={"yes": Leaf(), "no": Leaf()}))
    b = Subtask(id="b", tree=Node(var="x", branches={"yes": Leaf(), "no": Leaf()}))
    forest = [tree_paths(a), tree_paths(b)]
    task = load_task("clean_living_room", TASKS)
    assert not task_constraints(task).forbidden  # the paper's subtasks are independent
    cons = PathConstraints.of_pairs([("a:x=yes", "b:x=no"), ("a:x=no", "b:x=yes")])
    out = get_selector("exact").select(forest, cons)
    assert sorted(_keys(out)) == ["a:x=no | b:x=no", "a:x=yes | b:x=yes"]


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(forests())
def test_property_independent_forests(forest: Forest) -> None:
    results = {n: get_selector(n).select(forest) for n in selector_names()}
    for out in results.values():
        assert not uncovered(out, forest)
    assert len(results["exact"]) <= len(results["mtsa"])
    assert len(results["exact"]) == max(len(p) for p in forest)
    if math.prod(len(p) for p in forest) <= SMALL:
        assert len(results["exact"]) == _brute_optimum(forest, PathConstraints())
        assert len(results["exhaustive"]) == len(results["exact"])  # the search finished


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(forests_with_pairs())
def test_property_forbidden_pairs(case: tuple[Forest, PathConstraints]) -> None:
    forest, cons = case
    if not _coverable(forest, cons):
        for name in ("mtsa", "exact"):
            with pytest.raises(TrajectoryError, match="occur in no admissible trajectory"):
                get_selector(name).select(forest, cons)
        return
    mtsa = get_selector("mtsa").select(forest, cons)
    result = exact_cover(forest, cons)
    for out in (mtsa, list(result.trajectories)):
        assert not uncovered(out, forest)
        assert all(cons.admits_trajectory(t) for t in out)
    assert result.optimal
    assert len(result.trajectories) <= len(mtsa)
    if math.prod(len(p) for p in forest) <= SMALL:
        assert len(result.trajectories) == _brute_optimum(forest, cons)


def test_exact_clique_bound_when_conflicts_force_extra_rows() -> None:
    """a0 and a1 exclude b0 and b1, so {a0, a1, b0, b1} pairwise exclude each other: the minimum
    is 4 > max |paths| = 3 and the conflict-clique bound proves it without a search."""
    paths = _paths([3, 3])
    cons = PathConstraints.of_pairs([(f"s0:v0=p{a}", f"s1:v1=p{b}") for a in (0, 1) for b in (0, 1)])
    result = exact_cover(paths, cons)
    assert len(result.trajectories) == 4 and result.lower_bound == 4 and result.optimal
    assert all(cons.admits_trajectory(t) for t in result.trajectories)
    assert not uncovered(list(result.trajectories), paths)
    assert _brute_optimum(paths, cons) == 4


def test_exact_set_cover_search_improves_a_warm_start_and_proves_it() -> None:
    from logicenveval.logic.exact import _pairs, _solve_set_cover

    paths = _paths([3, 3])
    cons = PathConstraints.of_pairs([(f"s0:v0=p{a}", f"s1:v1=p{b}") for a in (0, 1) for b in (0, 1)])
    start = [(0, 2), (1, 2), (2, 0), (2, 1), (2, 2)]  # a valid cover with one row too many
    rows, optimal = _solve_set_cover(paths, _pairs(paths, cons), start, 3, 0)
    assert optimal and len(rows) == 4
    assert {a for a, _ in rows} == {0, 1, 2} and {b for _, b in rows} == {0, 1, 2}


def test_mtsa_deadline_holds_in_the_update_pass(monkeypatch: pytest.MonkeyPatch) -> None:
    import logicenveval.logic.mtsa as mtsa

    clock = iter([0.0, 100.0])  # the scan's check sees time 0, the update pass's check time 100
    monkeypatch.setattr(mtsa.time, "monotonic", lambda: next(clock))
    assert mtsa_impl(_paths([3, 3]), PathConstraints(), deadline=50.0) is None


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(forests_with_pairs())
def test_property_exhaustive_search_is_a_minimum_cover(case: tuple[Forest, PathConstraints]) -> None:
    forest, cons = case
    if math.prod(len(p) for p in forest) > SMALL or not _coverable(forest, cons):
        return
    result = exhaustive_cover(forest, cons)
    assert result.optimal and not uncovered(list(result.trajectories), forest)
    assert all(cons.admits_trajectory(t) for t in result.trajectories)
    assert len(result.trajectories) == _brute_optimum(forest, cons)


def test_exhaustive_search_falls_back_to_mtsa_when_the_budget_runs_out() -> None:
    paths = _paths([5, 5, 5, 5, 5])  # 3125 trajectories: C(3125, k) subsets up to k = 5
    result = exhaustive_cover(paths, max_subsets=4096)
    assert not result.optimal and result.tested == 4096
    assert _keys(result.trajectories) == _keys(get_selector("mtsa").select(paths))
