"""Task model, decision paths and GT-tree evaluation (DESIGN.md §4)."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from logicenveval.benchmark import load_task, load_task_file
from logicenveval.errors import TaskFormatError
from logicenveval.model.conditions import to_text
from logicenveval.model.task import Leaf, Node, Task
from logicenveval.model.tree import (
    atomic_conditions,
    evaluate_task,
    goal_of,
    task_paths,
    trajectory_from_assignment,
    trajectory_from_claim,
    tree_paths,
)

ROOT = Path(__file__).resolve().parents[1]
CLR = ROOT / "benchmark_data" / "tasks" / "clean_living_room" / "task.json"


def _data() -> dict[str, Any]:
    return json.loads(CLR.read_text())


def test_clean_living_room_paths() -> None:
    task = load_task("clean_living_room")
    keys = [[p.key for p in ps] for ps in task_paths(task)]
    assert keys == [
        ["tidy_toy:toy_on_floor=yes/toy_kind=doll", "tidy_toy:toy_on_floor=yes/toy_kind=other", "tidy_toy:toy_on_floor=no"],
        ["tidy_book:book_on_floor=yes", "tidy_book:book_on_floor=no"],
        ["clean_mark:wipe_on_table=yes", "clean_mark:wipe_on_table=no"],
    ]
    assert len(atomic_conditions(task)) == 8
    assert task.brief().model_dump().keys() == {"id", "description", "rooms", "roles"}


def test_json_round_trip() -> None:
    task = load_task("clean_living_room")
    again = Task.model_validate_json(task.model_dump_json())
    assert again == task


def _facts(on: set[tuple[str, str]], attrs: set[tuple[str, str, str]]):  # type: ignore[no-untyped-def]
    def holds(name: str, args: tuple[str, ...]) -> bool:
        if name == "on":
            return (args[0], args[1]) in on
        if name == "attr":
            return (args[0], args[1], args[2]) in attrs
        return False

    return holds


def test_evaluate_reaches_leaves_and_goal() -> None:
    task = load_task("clean_living_room")
    holds = _facts({("toy", "floor"), ("wet_wipe", "table")}, {("toy", "kind", "doll")})
    outcomes = evaluate_task(task, holds)
    assert [o.path.key for o in outcomes if o.path] == [
        "tidy_toy:toy_on_floor=yes/toy_kind=doll",
        "tidy_book:book_on_floor=no",
        "clean_mark:wipe_on_table=yes",
    ]
    goal = goal_of(outcomes)
    assert goal is not None
    assert to_text(goal) == "inside(toy, red_box) and not on(book, floor) and not state(mark, dirty)"


def test_no_branch_holds_is_reported() -> None:
    data = _data()
    data["variables"]["toy_kind"]["values"]["other"] = "attr(toy, kind, car)"
    task = Task.model_validate(data)
    outcomes = evaluate_task(task, _facts({("toy", "floor")}, set()))
    assert outcomes[0].path is None and outcomes[0].stuck_var == "toy_kind"
    assert goal_of(outcomes) is None


def test_trajectory_resolution() -> None:
    task = load_task("clean_living_room")
    traj = trajectory_from_assignment(
        task, {"toy_on_floor": "yes", "toy_kind": "other", "book_on_floor": "no", "wipe_on_table": "yes"}
    )
    assert trajectory_from_claim(task, traj.as_claim()) == traj
    with pytest.raises(ValueError, match="needs a value for 'toy_kind'"):
        trajectory_from_assignment(task, {"toy_on_floor": "yes", "book_on_floor": "no", "wipe_on_table": "yes"})
    with pytest.raises(ValueError, match="unknown variable"):
        trajectory_from_assignment(task, {"colour": "red"})


@pytest.mark.parametrize(
    ("mutate", "fragment"),
    [
        (lambda d: d["subtasks"][0]["tree"].update(var="nope"), "variable 'nope' is not declared"),
        (lambda d: d["variables"]["toy_kind"]["values"].update(other="attr(ghost, kind, x)"), "'ghost'"),
        (lambda d: d["subtasks"][1]["tree"]["branches"].pop("no"), "must be exactly the values"),
        (lambda d: d["subtasks"][1]["tree"].update(var="toy_on_floor"), "used by subtasks"),
        (lambda d: d["variables"]["book_on_floor"]["values"].update(yes="on(book, floor"), "variables.book_on_floor.values"),
        (lambda d: d["variables"]["book_on_floor"]["values"].update(yes="holding(book)"), "speaks about the agent"),
        (lambda d: d.update(colour="red"), "colour"),
    ],
)
def test_malformed_tasks_name_file_and_field(tmp_path: Path, mutate: Any, fragment: str) -> None:
    data = _data()
    mutate(data)
    folder = tmp_path / "clean_living_room"
    folder.mkdir()
    (folder / "task.json").write_text(json.dumps(data))
    with pytest.raises(TaskFormatError) as info:
        load_task_file(folder / "task.json")
    text = str(info.value)
    assert fragment in text and "task.json" in text and "fix:" in text


def test_broken_json_names_line(tmp_path: Path) -> None:
    folder = tmp_path / "t"
    folder.mkdir()
    (folder / "task.json").write_text('{\n "id": "t",\n}')
    with pytest.raises(TaskFormatError, match=r"task.json:3"):
        load_task_file(folder / "task.json")


@st.composite
def trees(draw: st.DrawFn, depth: int = 0, counter: list[int] | None = None) -> Node | Leaf:
    counter = counter if counter is not None else [0]
    if depth >= 3 or draw(st.booleans()) and depth > 0:
        return Leaf(plan=[], goal="true")
    counter[0] += 1
    var = f"v{counter[0]}"
    n = draw(st.integers(2, 3))
    return Node(var=var, branches={f"x{i}": draw(trees(depth + 1, counter)) for i in range(n)})


def _leaves(node: Node | Leaf) -> int:
    return 1 if isinstance(node, Leaf) else sum(_leaves(c) for c in node.branches.values())


@given(trees())
def test_paths_are_root_to_leaf_and_distinct(tree: Node | Leaf) -> None:
    from logicenveval.model.task import Subtask

    st_ = Subtask(id="s", tree=tree)
    paths = tree_paths(st_)
    assert len(paths) == _leaves(tree)
    assert len({p.key for p in paths}) == len(paths)
    for p in paths:  # every path is a walk from the root following existing branches
        node = copy.copy(tree)
        for var, value in p.steps:
            assert isinstance(node, Node) and node.var == var
            node = node.branches[value]
        assert isinstance(node, Leaf)
