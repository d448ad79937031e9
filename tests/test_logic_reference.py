"""The JI reference set on the benchmark tasks, and the Jaccard index."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from logicenveval.benchmark import load_task, task_ids
from logicenveval.logic.constraints import task_constraints
from logicenveval.logic.reference import jaccard, reference_set
from logicenveval.logic.selectors import uncovered
from logicenveval.model.tree import task_paths

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
