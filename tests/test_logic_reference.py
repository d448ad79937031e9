"""The JI reference set on the benchmark tasks, and the Jaccard index."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import load_task, task_ids
from logicenveval.logic.constraints import PathConstraints, task_constraints
from logicenveval.logic.exact import exact_cover
from logicenveval.logic.reference import closest_cover, closest_reference, jaccard, reference_set
from logicenveval.logic.selectors import get_selector, uncovered
from logicenveval.model.tree import DecisionPath, Trajectory, task_paths

Forest = list[list[DecisionPath]]

TASKS = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks"


def test_clean_living_room_reference() -> None:
    ref = reference_set(load_task("clean_living_room", TASKS))
    assert [t.key for t in ref] == [
        "tidy_toy:toy_on_floor=yes/toy_kind=doll | tidy_book:book_on_floor=yes | clean_mark:wipe_on_table=yes",
        "tidy_toy:toy_on_floor=yes/toy_kind=other | tidy_book:book_on_floor=no | clean_mark:wipe_on_table=no",
        "tidy_toy:toy_on_floor=no | tidy_book:book_on_floor=no | clean_mark:wipe_on_table=no",
    ]


@pytest.mark.parametrize("task_id", task_ids(TASKS))
def test_reference_covers_every_path_of_every_task(task_id: str) -> None:
    task = load_task(task_id, TASKS)
    paths = task_paths(task)
    ref = reference_set(task)
    assert not uncovered(ref, paths)
    assert all(task_constraints(task).admits_trajectory(t) for t in ref)
    assert len(ref) >= max(len(p) for p in paths)
    assert len({t.key for t in ref}) == len(ref)


def test_jaccard_values() -> None:
    assert jaccard(["a", "b"], ["b", "c"]) == pytest.approx(1 / 3)
    assert jaccard([], []) == 0.0
    assert jaccard(["a"], ["a"]) == 1.0


@given(st.sets(st.sampled_from("abcdef")), st.sets(st.sampled_from("abcdef")))
def test_jaccard_properties(a: set[str], b: set[str]) -> None:
    j = jaccard(a, b)
    assert 0.0 <= j <= 1.0 and j == jaccard(b, a)
    assert (j == 1.0) == (bool(a) and a == b)


def test_closest_cover_scores_mtsa_against_its_own_minimum_cover() -> None:
    task = load_task("clean_living_room", TASKS)
    mtsa = [t.key for t in get_selector("mtsa").select(task_paths(task))]
    canonical = [t.key for t in reference_set(task)]
    assert len(mtsa) == len(canonical) and set(mtsa) != set(canonical)  # another minimum cover
    assert jaccard(mtsa, canonical) < 1.0
    closest = closest_reference(task, mtsa)
    assert closest.ji == 1.0 and closest.optimal and sorted(t.key for t in closest.trajectories) == sorted(mtsa)


def _admissible(forest: Forest, cons: PathConstraints) -> list[str]:
    return [Trajectory(c).key for c in itertools.product(*forest) if cons.admits(c)]


def _brute_closest(forest: Forest, cons: PathConstraints, realised: set[str]) -> float:
    """Max Jaccard over every minimum cover, by enumerating subsets of admissible trajectories."""
    trajs = _admissible(forest, cons)
    keys = {p.key for ps in forest for p in ps}
    for size in range(1, len(trajs) + 1):
        covers = [c for c in itertools.combinations(trajs, size)
                  if {k for t in c for k in t.split(" | ")} == keys]
        if covers:
            return max(jaccard(realised, c) for c in covers)
    raise AssertionError("no cover")


@st.composite
def small_cases(draw: st.DrawFn) -> tuple[Forest, PathConstraints, set[str]]:
    sizes = draw(st.lists(st.integers(1, 3), min_size=1, max_size=3))
    forest = [[DecisionPath(f"s{i}", ((f"v{i}", f"p{a}"),)) for a in range(n)] for i, n in enumerate(sizes)]
    cross = [(a.key, b.key) for i, j in itertools.combinations(range(len(forest)), 2)
             for a in forest[i] for b in forest[j]]
    pairs = draw(st.lists(st.sampled_from(cross), max_size=3, unique=True)) if cross else []
    cons = PathConstraints.of_pairs(pairs)
    every = [Trajectory(c).key for c in itertools.product(*forest)]  # inadmissible ones too
    realised = set(draw(st.lists(st.sampled_from(every), max_size=5)))
    return forest, cons, realised


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(small_cases())
def test_property_closest_cover_equals_brute_force(case: tuple[Forest, PathConstraints, set[str]]) -> None:
    forest, cons, realised = case
    admissible = _admissible(forest, cons)
    keys = {p.key for ps in forest for p in ps}
    if {k for t in admissible for k in t.split(" | ")} != keys:
        return  # some path is in no admissible trajectory: no cover exists
    closest = closest_cover(forest, realised, cons)
    assert closest.optimal
    assert closest.ji == pytest.approx(_brute_closest(forest, cons, realised))
    ref = [t.key for t in closest.trajectories]
    assert not uncovered(list(closest.trajectories), forest)
    assert all(t in admissible for t in ref)
    assert len(ref) == len(exact_cover(forest, cons).trajectories) == len(set(ref))
    assert closest.ji == pytest.approx(jaccard(realised, ref))
