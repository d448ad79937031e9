"""GT evaluation of an environment's initial state: coverage and well-formedness."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from logicenveval.benchmark import load_task, task_ids
from logicenveval.metrics.evaluate import Coverage, coverage
from logicenveval.model.conditions import Holds
from logicenveval.model.task import Task, task_from_dict
from logicenveval.model.tree import task_paths

CLR = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks" / "clean_living_room" / "task.json"


def _data() -> dict[str, Any]:
    data: dict[str, Any] = json.loads(CLR.read_text())
    return data


def _task(data: dict[str, Any] | None = None) -> Task:
    return task_from_dict(data if data is not None else _data())


def _holds(*facts: tuple[str, ...]) -> Holds:
    known = {(f[0], tuple(f[1:])) for f in facts}
    return lambda name, args: (name, args) in known


def _all_bound(task: Task) -> dict[str, str | None]:
    return {r: f"obj_{r}" for r in task.roles}


DOLL_BOOK_WIPE = _holds(
    ("on", "toy", "floor"), ("attr", "toy", "kind", "doll"), ("on", "book", "floor"), ("on", "wet_wipe", "table")
)


def test_paper_example_environment() -> None:
    task = _task()
    cov = coverage(task, DOLL_BOOK_WIPE, _all_bound(task))
    assert cov.well_formed and cov.problems == []
    assert cov.covered_paths == [
        "tidy_toy:toy_on_floor=yes/toy_kind=doll",
        "tidy_book:book_on_floor=yes",
        "clean_mark:wipe_on_table=yes",
    ]
    assert cov.trajectory == " | ".join(cov.covered_paths)
    assert cov.conditions == [
        ("toy_on_floor", "yes"), ("toy_kind", "doll"), ("book_on_floor", "yes"), ("wipe_on_table", "yes")
    ]


def test_unbound_role_makes_env_ill_formed() -> None:
    task = _task()
    roles = _all_bound(task) | {"mop": None}
    cov = coverage(task, DOLL_BOOK_WIPE, roles)
    assert not cov.well_formed
    assert cov.problems == ["role mop is not bound to an object and no reached path allows it"]
    assert cov.trajectory is not None  # the trees still reach leaves; validity is separate


def test_not_exists_path_allows_unbound_role() -> None:
    data = _data()
    data["variables"]["toy_on_floor"]["values"]["no"] = "not exists(toy)"
    task = _task(data)
    roles = _all_bound(task) | {"toy": None}
    absent = coverage(task, _holds(("on", "book", "floor")), roles)
    assert absent.well_formed, absent.problems
    assert absent.covered_paths[0] == "tidy_toy:toy_on_floor=no"
    present = coverage(task, DOLL_BOOK_WIPE, roles)  # a reached path that needs the toy
    assert not present.well_formed


def test_tree_reaching_no_leaf_is_reported() -> None:
    data = _data()
    data["variables"]["toy_kind"]["values"]["other"] = "attr(toy, kind, car)"
    task = _task(data)
    holds = _holds(("on", "toy", "floor"), ("attr", "toy", "kind", "ball"))
    cov = coverage(task, holds, _all_bound(task))
    assert not cov.well_formed and cov.trajectory is None
    assert cov.problems == ["subtask tidy_toy: variable toy_kind reaches no leaf (no value holds)"]
    assert cov.covered_paths == ["tidy_book:book_on_floor=no", "clean_mark:wipe_on_table=no"]


def test_coverage_json_round_trip() -> None:
    task = _task()
    cov = coverage(task, DOLL_BOOK_WIPE, _all_bound(task))
    assert Coverage.model_validate_json(cov.model_dump_json()) == cov


def test_situation_envs_realise_their_trajectories() -> None:
    from logicenveval.logic.reference import reference_set
    from logicenveval.metrics.evaluate import coverage_of_env
    from logicenveval.sim.situations import situation_env

    task = _task()
    for traj in reference_set(task):
        cov = coverage_of_env(task, situation_env(task, traj))
        assert cov.well_formed, cov.problems
        assert cov.trajectory == traj.key


@pytest.mark.slow
@pytest.mark.parametrize("task_id", task_ids(CLR.parents[1]))
def test_every_situation_of_every_task_is_recovered(task_id: str) -> None:
    from logicenveval.logic.selectors import get_selector
    from logicenveval.metrics.evaluate import coverage_of_env
    from logicenveval.sim.situations import situation_env

    task = load_task(task_id, CLR.parents[1])
    for traj in get_selector("product").select(task_paths(task)):
        cov = coverage_of_env(task, situation_env(task, traj))
        assert cov.well_formed and cov.trajectory == traj.key, (traj.key, cov.problems)


def test_ld_counts_every_value_the_environment_realises_not_only_on_reached_paths() -> None:
    """Paper Def. 1: a doll that is not on the floor still realises toy_kind=doll (issue 34)."""
    task = _task()
    cov = coverage(task, _holds(("attr", "toy", "kind", "doll")), _all_bound(task))
    assert cov.covered_paths[0] == "tidy_toy:toy_on_floor=no"
    assert ("toy_kind", "doll") in cov.conditions and ("toy_on_floor", "no") in cov.conditions
    absent = coverage(task, _holds(), _all_bound(task) | {"toy": None})
    assert not [c for c in absent.conditions if c[0] == "toy_kind"]  # no toy: its kind is no value
