"""import-house: hand-written houses in ProcTHOR's schema-1.0.0 layout become scorable EnvSpecs."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import load_task
from logicenveval.cli import main
from logicenveval.domain.catalog import load_catalog
from logicenveval.domain.roles import bind_roles
from logicenveval.envfiles import load_env
from logicenveval.errors import EnvSpecError
from logicenveval.metrics.evaluate import coverage_of_env
from logicenveval.scene.house_import import import_house, load_house

HOUSES = Path(__file__).resolve().parent / "fixtures" / "houses"
CATALOG = load_catalog()


def _import(name: str, task_id: str):  # type: ignore[no-untyped-def]
    task = load_task(task_id)
    return import_house(load_house(HOUSES / f"{name}.json"), task_id=task_id, env_id=name,
                        catalog=CATALOG, role_categories=[r.category for r in task.roles.values()])


def test_kitchen_house_geometry_objects_and_states() -> None:
    rep = _import("kitchen_breakfast", "kitchen_breakfast_prep")
    env = rep.env
    (room,) = env.rooms
    assert (room.id, room.type, room.polygon) == ("kitchen", "Kitchen", [(0, 0), (5, 0), (5, 4), (0, 4)])
    (door,) = env.doors
    assert door.rooms == ("kitchen", "exterior") and door.state == "closed" and door.type == "doorway"
    assert door.segment == ((1.5, 0.0), (2.5, 0.0)) and door.height == pytest.approx(2.1)
    (window,) = env.windows
    # the north wall's polygon starts at (5, 4): hole x runs from there toward (0, 4)
    assert window.segment == ((4.0, 4.0), (2.8, 4.0))
    assert (window.sill, window.height) == (pytest.approx(0.9), pytest.approx(1.2))
    objs = {o.id: o for o in env.objects}
    assert objs["small_2_0"].category == "bread" and objs["small_2_0"].support == "CounterTop_2_0"
    assert objs["small_2_4"].container == "Fridge_2_1" and objs["small_2_4"].support is None
    assert objs["small_2_5"].support == "StoveBurner_2_2"
    toaster = objs["small_2_1"]  # no objectType: read from assetId Toaster_26
    assert toaster.category == "toaster" and toaster.states == {"toggled_on": True}
    assert objs["small_2_2"].states == {"toggled_on": False, "filled": False}
    assert objs["Fridge_2_1"].states == {"open": False}
    assert objs["CounterTop_2_0"].category == "kitchen_counter" and objs["CounterTop_2_0"].yaw == 180
    cat = CATALOG.categories["fridge"]
    assert objs["Fridge_2_1"].size == tuple((a + b) / 2 for a, b in zip(cat.size_min, cat.size_max, strict=True))
    assert objs["2_4"].category == "wall_clock"  # no ai2thor_type, but a catalog name
    assert rep.unknown_types == {"Dumbbell": ["2_5"]}
    assert objs["2_5"].category == "dumbbell" and objs["2_5"].size is None
    assert env.agent.room == "kitchen" and env.agent.position == (1.0, 1.0)
    assert env.roles == {}


def test_kitchen_house_covers_the_paths_it_was_written_for() -> None:
    env = _import("kitchen_breakfast", "kitchen_breakfast_prep").env
    task = load_task("kitchen_breakfast_prep")
    binding = bind_roles(env, task.roles, CATALOG)
    assert binding.well_formed and None not in binding.roles.values()
    cov = coverage_of_env(task, binding.apply(env), CATALOG)
    assert cov.well_formed
    assert cov.covered_paths == ["toast:bread_status=on_counter/toaster_on=on",
                                 "kettle:kettle_filled=empty",
                                 "fry_egg:egg_in_fridge=yes/pan_on_stove=yes"]


def test_two_room_house_doors_and_ambiguous_roles() -> None:
    rep = _import("two_rooms_trash", "multi_room_trash_run")
    env = rep.env
    assert [(r.id, r.type) for r in env.rooms] == [("living_room", "LivingRoom"), ("kitchen", "Kitchen")]
    inner, outer = env.doors
    assert inner.rooms == ("living_room", "kitchen") and inner.state == "open"
    assert inner.segment == ((4.0, 2.0), (4.0, 3.0))
    assert outer.rooms == ("living_room", "exterior")
    assert rep.chosen["GarbageCan"] == "trash_can" and rep.chosen["GarbageBag"] == "trash_bag"
    assert {o.room for o in env.objects if o.id.startswith("Garbage")} == {"kitchen"}
    b = bind_roles(env, load_task("multi_room_trash_run").roles, CATALOG)
    assert b.candidates == {"full_bag": ["GarbageBag_3_1", "GarbageBag_3_2"],
                            "spare_bag": ["GarbageBag_3_1", "GarbageBag_3_2"]}
    assert b.roles["newspaper"] == "small_2_0" and b.roles["trash_can"] == "GarbageCan_3_0"


def test_cli_writes_a_scorable_envspec(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "envs" / "kitchen_breakfast_prep" / "house.json"
    assert main(["import-house", str(HOUSES / "kitchen_breakfast.json"), "--task",
                 "kitchen_breakfast_prep", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "AI2-THOR type Dumbbell names no catalog category" in text and "bread=small_2_0" in text
    assert load_env(out).env_id == "house"
    assert main(["evaluate", str(tmp_path / "envs"), "--name", "procthor", "--executor", "inprocess",
                 "--output", str(tmp_path / "reports")]) == 0
    (run_dir,) = list((tmp_path / "reports").iterdir())
    sample = json.loads((run_dir / "samples.jsonl").read_text())
    assert sample["well_formed"] and sample["verdicts"]["correct"] == "passed"


@pytest.mark.parametrize(("edit", "words"), [
    (lambda h: h.pop("rooms"), ["missing 'rooms'"]),
    (lambda h: h["metadata"].update(schema="0.0.1"), ["schema '0.0.1'", "upgrade"]),
    (lambda h: h["doors"][0].update(room0="room|9"), ["doors[0].room0", "'room|9' is not a room id"]),
    (lambda h: h["objects"][0].pop("position"), ["objects[0].position"]),
])
def test_bad_houses_exit_2_naming_the_field(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                            edit: object, words: list[str]) -> None:
    house = json.loads((HOUSES / "kitchen_breakfast.json").read_text())
    edit(house)  # type: ignore[operator]
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(house))
    assert main(["import-house", str(path), "--task", "kitchen_breakfast_prep",
                 "--out", str(tmp_path / "out.json")]) == 2
    err = capsys.readouterr().err
    for w in words:
        assert w in err, err
    assert not (tmp_path / "out.json").exists()


def _paths(node: object, prefix: tuple[object, ...] = ()) -> list[tuple[object, ...]]:
    out: list[tuple[object, ...]] = [prefix] if prefix else []
    if isinstance(node, dict):
        for k, v in node.items():
            out += _paths(v, (*prefix, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out += _paths(v, (*prefix, i))
    return out


_HOUSE = json.loads((HOUSES / "kitchen_breakfast.json").read_text())
_PATHS = _paths(_HOUSE)
_JUNK = [None, "x", "", [], {}, -1, 0, 1e308, float("nan"), float("inf"), [1, 2], {"x": "a"}, True]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.sampled_from(_PATHS), st.sampled_from([*_JUNK, "DELETE"])),
                min_size=1, max_size=4))
def test_any_mangled_house_imports_or_names_the_problem(edits: list[tuple[tuple[object, ...], object]]) -> None:
    house = copy.deepcopy(_HOUSE)
    for path, value in edits:
        parent: Any = house
        try:
            for key in path[:-1]:
                parent = parent[key]
            if value == "DELETE" and isinstance(parent, dict):
                parent.pop(path[-1], None)
            else:
                parent[path[-1]] = value
        except (KeyError, IndexError, TypeError):
            continue  # an earlier edit removed or replaced this path
    try:
        import_house(house, task_id="kitchen_breakfast_prep", env_id="h", catalog=CATALOG)
    except EnvSpecError as exc:
        assert "fix:" in str(exc)
