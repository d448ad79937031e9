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
    assert rep.unknown_types == {"Kayak": ["2_5"]}
    assert objs["2_5"].category == "kayak" and objs["2_5"].size is None
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
    # neither bag says it is the spare one (`purpose`): the full one is either, the spare none
    assert b.candidates == {"full_bag": ["GarbageBag_3_1", "GarbageBag_3_2"]}
    assert b.roles["spare_bag"] is None and "has no purpose" in b.why["spare_bag"]
    assert b.roles["newspaper"] == "small_2_0" and b.roles["trash_can"] == "GarbageCan_3_0"


def test_cli_writes_a_scorable_envspec(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "envs" / "kitchen_breakfast_prep" / "house.json"
    assert main(["import-house", str(HOUSES / "kitchen_breakfast.json"), "--task",
                 "kitchen_breakfast_prep", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "AI2-THOR type Kayak names no catalog category" in text and "bread=small_2_0" in text
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


def json_paths(node: object, prefix: tuple[object, ...] = ()) -> list[tuple[object, ...]]:
    """Every path into a JSON value (dict keys and list indices)."""
    out: list[tuple[object, ...]] = [prefix] if prefix else []
    if isinstance(node, dict):
        for k, v in node.items():
            out += json_paths(v, (*prefix, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out += json_paths(v, (*prefix, i))
    return out


def mangled(house: dict[str, Any], edits: list[tuple[tuple[object, ...], object]]) -> dict[str, Any]:
    """A copy of `house` with each path set to junk (or removed: "DELETE")."""
    out = copy.deepcopy(house)
    for path, value in edits:
        parent: Any = out
        try:
            for key in path[:-1]:
                parent = parent[key]
            if value == "DELETE" and isinstance(parent, dict):
                parent.pop(path[-1], None)
            else:
                parent[path[-1]] = value
        except (KeyError, IndexError, TypeError):
            continue  # an earlier edit removed or replaced this path
    return out


_HOUSE = json.loads((HOUSES / "kitchen_breakfast.json").read_text())
_PATHS = json_paths(_HOUSE)
JUNK = [None, "x", "", [], {}, -1, 0, 1e308, float("nan"), float("inf"), [1, 2], {"x": "a"}, True]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.sampled_from(_PATHS), st.sampled_from([*JUNK, "DELETE"])),
                min_size=1, max_size=4))
def test_any_mangled_house_imports_or_names_the_problem(edits: list[tuple[tuple[object, ...], object]]) -> None:
    house = mangled(_HOUSE, edits)
    try:
        import_house(house, task_id="kitchen_breakfast_prep", env_id="h", catalog=CATALOG)
    except EnvSpecError as exc:
        assert "fix:" in str(exc)


#: a house in the layout of the ProcTHOR-10K houses AI2-THOR ships as test data (same keys, id
#: forms `CounterTop|2|0`, `Bread|surface|2|1`, `Sink|2|2|0`, no objectType, real asset ids; a
#: Doorframe door without openable/openness, exterior walls listing their top points first),
#: written for kitchen_breakfast_prep
PROCTHOR10K = HOUSES / "procthor10k_kitchen.json"
#: ProcTHOR's asset database has no stove: an AI2-THOR kitchen (iTHOR) has a StoveBurner
STOVE = {"assetId": "Stove_LogicEnvEval_1", "id": "StoveBurner|2|9", "kinematic": True,
         "position": {"x": 2.9, "y": 0.45, "z": 3.15}, "rotation": {"x": 0, "y": 180, "z": 0},
         "layer": "Procedural1", "material": None}


def test_procthor10k_house_takes_types_from_ids_and_sizes_from_the_catalog() -> None:
    task = load_task("kitchen_breakfast_prep")
    rep = import_house(load_house(PROCTHOR10K), task_id=task.id, env_id="h", catalog=CATALOG,
                       role_categories=[r.category for r in task.roles.values()])
    objs = {o.id: o for o in rep.env.objects}
    assert rep.type_sources == {"id": 22}
    assert rep.unknown_types == {"Faucet": ["Faucet_2_2_1"]}  # AI2-THOR has it, our catalog not
    counter = objs["CounterTop_2_0"]
    assert counter.category == "kitchen_counter" and counter.size == (1.8314, 0.9375, 0.6106)  # our mapping's asset
    assert counter.model_dump()["object_type"] == "CounterTop"
    assert objs["Bread_surface_2_1"].category == "bread" and objs["Bread_surface_2_1"].support == "CounterTop_2_0"
    assert objs["Tomato_surface_2_6"].container == "Fridge_2_1"
    assert objs["Toaster_surface_2_4"].states == {"toggled_on": False}
    assert objs["FloorLamp_3_3_1"].states == {"toggled_on": True} and objs["FloorLamp_3_3_1"].room == "living_room"
    assert all(o.size is not None for o in rep.env.objects if o.id != "Faucet_2_2_1")
    assert rep.size_sources == {"catalog": 16, "asset database": 5, "none": 1}
    inner, outer = rep.env.doors
    assert inner.rooms == ("kitchen", "living_room") and inner.state == "closed" and inner.type == "door"
    assert outer.rooms == ("living_room", "exterior") and outer.type == "doorway"
    assert rep.env.wall_height == pytest.approx(2.6135)
    binding = bind_roles(rep.env, task.roles, CATALOG)
    assert {r for r, o in binding.roles.items() if o is None} == {"stove"}  # ProcTHOR has none
    assert binding.well_formed


def test_procthor10k_house_scores_with_every_role_bound(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                        no_procthor: None) -> None:
    house = json.loads(PROCTHOR10K.read_text())
    house["objects"].append(STOVE)
    src = tmp_path / "house.json"
    src.write_text(json.dumps(house))
    envs = tmp_path / "envs" / "kitchen_breakfast_prep"
    for name, path in (("as_procthor", PROCTHOR10K), ("with_stove", src)):
        assert main(["import-house", str(path), "--task", "kitchen_breakfast_prep",
                     "--out", str(envs / f"{name}.json")]) == 0
    out = capsys.readouterr().out
    assert "object types from id 22" in out and "unbound stove: no object is a stove" in out
    assert "sizes from catalog" in out and "AI2-THOR type Faucet is a fixture (mounted on a sink" in out
    assert main(["evaluate", str(tmp_path / "envs"), "--name", "procthor", "--executor", "inprocess",
                 "--output", str(tmp_path / "reports")]) == 0
    (run_dir,) = list((tmp_path / "reports").iterdir())
    samples = {s["env_id"]: s for s in map(json.loads, (run_dir / "samples.jsonl").read_text().splitlines())}
    bare, full = samples["as_procthor"], samples["with_stove"]
    assert not bare["well_formed"] and any("role stove is not bound" in p for p in bare["problems"])
    assert full["well_formed"] and full["verdicts"]["correct"] == "passed"
    assert full["covered_paths"] == ["toast:bread_status=on_counter/toaster_on=off",
                                     "kettle:kettle_filled=empty", "fry_egg:egg_in_fridge=no"]
    assert full["unknown_categories"] == {"faucet": ["Faucet_2_2_1"]}
    res = json.loads((run_dir / "results.json").read_text())["results"]["procthor"]
    assert res["logcov"] > 0 and res["scevr"] > 0 and res["faudr"]["avg"] > 0
    assert res["phypr"]["floor_plan"] == 1.0


def test_procthor10k_house_passes_check_house_without_object_types(capsys: pytest.CaptureFixture[str],
                                                                   no_procthor: None) -> None:
    assert main(["check-house", str(PROCTHOR10K), "--json"]) == 0
    (report,) = json.loads(capsys.readouterr().out).values()
    assert report["problems"] == []
    fridge = next(w for w in report["warnings"] if w["where"] == "objects[1].assetId")
    assert "asset id 'Fridge_1' is not in our mapping" in fridge["message"]


def test_export_then_import_keeps_categories_sizes_and_places() -> None:
    from logicenveval.scene.export import to_procthor

    env = load_env(Path(__file__).parent / "fixtures" / "envs" / "three_rooms.json")
    back = import_house(to_procthor(env, CATALOG), task_id=env.task_id, env_id="back", catalog=CATALOG).env
    before = {o.id: o for o in env.objects}
    assert {o.id for o in back.objects} == set(before)
    for o in back.objects:
        src = before[o.id]
        assert o.category == src.category and o.size is not None and src.size is not None
        assert o.size == pytest.approx(src.size, abs=1e-3) and o.position == pytest.approx(src.position, abs=1e-3)
