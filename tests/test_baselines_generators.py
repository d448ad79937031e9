"""CoT, IFG and Holodeck-like on benchmark tasks with the offline model (test catalog)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from logicenveval import domain
from logicenveval.baselines.holodeck_solver import Box
from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.domain.shapes import load_shapes
from logicenveval.generators.base import (
    GenerationContext,
    GenerationResult,
    make_generator,
    registered,
)
from logicenveval.generators.logicenvgen import LogicEnvGen
from logicenveval.llm.base import ChatRequest
from logicenveval.model.envspec import EnvSpec
from logicenveval.offline import baseline_answers as oh
from logicenveval.offline.model import OfflineModel
from logicenveval.runner.config import RunConfig

TASKS = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks"
IDS = ["clean_living_room", "multi_room_laundry_collect", "hallway_coat_and_bag"]

_F = (["floor"], False)
_S = (["surface", "floor"], True)
_SPECS: dict[str, tuple[list[float], list[float], list[str], dict[str, Any]]] = {
    "sofa": ([1.8, 0.8, 0.8], [2.2, 0.9, 1.0], ["floor"], {"surface": True, "rooms": ["LivingRoom"]}),
    "coffee_table": ([0.9, 0.4, 0.5], [1.2, 0.5, 0.7], ["floor"], {"surface": True, "rooms": ["LivingRoom"]}),
    "armchair": ([0.7, 0.8, 0.7], [0.9, 1.0, 0.9], ["floor"], {"surface": True, "rooms": ["LivingRoom"]}),
    "tv_stand": ([1.2, 0.5, 0.4], [1.6, 0.6, 0.5], ["floor"], {"surface": True, "rooms": ["LivingRoom"]}),
    "side_table": ([0.4, 0.5, 0.4], [0.6, 0.6, 0.5], ["floor"], {"surface": True, "rooms": ["LivingRoom", "Hallway"]}),
    "bed": ([1.4, 0.5, 2.0], [1.8, 0.6, 2.1], ["floor"], {"surface": True, "rooms": ["Bedroom"]}),
    "wardrobe": ([1.0, 1.9, 0.55], [1.4, 2.1, 0.6], ["floor"], {"container": True, "openable": True, "rooms": ["Bedroom"]}),
    "washing_machine": ([0.6, 0.85, 0.6], [0.6, 0.85, 0.6], ["floor"], {"container": True, "openable": True, "rooms": ["LaundryRoom"]}),
    "towel_rack": ([0.5, 0.8, 0.1], [0.6, 0.9, 0.15], ["wall"], {"rooms": ["Bathroom"]}),
    "painting": ([0.6, 0.4, 0.03], [0.9, 0.7, 0.04], ["wall"], {"rooms": ["LivingRoom", "Bedroom", "Hallway"]}),
    "coat_rack": ([0.5, 1.7, 0.5], [0.6, 1.8, 0.6], ["floor"], {"surface": True, "rooms": ["Hallway"]}),
    "bench": ([1.0, 0.45, 0.4], [1.2, 0.5, 0.45], ["floor"], {"surface": True, "rooms": ["Hallway"]}),
    "kitchen_counter": ([1.5, 0.9, 0.6], [2.0, 0.9, 0.65], ["floor"], {"surface": True, "rooms": ["Kitchen"]}),
    "fridge": ([0.7, 1.7, 0.7], [0.8, 1.8, 0.75], ["floor"], {"container": True, "openable": True, "rooms": ["Kitchen"]}),
    "toy_box": ([0.5, 0.4, 0.4], [0.6, 0.5, 0.45], ["floor"], {"container": True, "rooms": ["LivingRoom"]}),
    "laundry_basket": ([0.5, 0.5, 0.4], [0.55, 0.6, 0.45], ["floor"], {"container": True, "rooms": ["Bathroom", "LaundryRoom"]}),
    "hamper": ([0.45, 0.6, 0.4], [0.5, 0.65, 0.45], ["floor"], {"container": True, "rooms": ["Bedroom", "Bathroom"]}),
    "mop": ([0.3, 1.2, 0.3], [0.35, 1.3, 0.35], ["floor"], {"pickable": True}),
    "floor_stain": ([0.3, 0.01, 0.3], [0.5, 0.01, 0.5], ["floor"], {"default_states": {"dirty": True}}),
    "toy": ([0.15, 0.15, 0.1], [0.3, 0.25, 0.2], ["floor", "surface"], {"pickable": True, "attributes": {"kind": ["doll", "car", "ball"]}}),
    "book": ([0.15, 0.03, 0.22], [0.2, 0.05, 0.28], ["surface"], {"pickable": True}),
    "wet_wipe": ([0.15, 0.05, 0.1], [0.2, 0.07, 0.12], ["surface"], {"pickable": True}),
    "sock": ([0.1, 0.03, 0.2], [0.12, 0.04, 0.25], ["floor"], {"pickable": True}),
    "shirt": ([0.4, 0.03, 0.3], [0.5, 0.04, 0.35], ["surface"], {"pickable": True, "attributes": {"color": ["white", "blue"]}}),
    "towel": ([0.4, 0.05, 0.3], [0.5, 0.06, 0.35], ["surface"], {"pickable": True}),
    "coat": ([0.5, 0.1, 0.3], [0.6, 0.12, 0.35], ["surface"], {"pickable": True}),
    "umbrella": ([0.1, 0.8, 0.1], [0.12, 0.9, 0.12], ["floor"], {"pickable": True}),
    "backpack": ([0.3, 0.45, 0.2], [0.35, 0.5, 0.25], ["floor"], {"pickable": True}),
    "lunch_box": ([0.2, 0.08, 0.15], [0.25, 0.1, 0.18], ["surface"], {"pickable": True}),
    "keys": ([0.05, 0.02, 0.08], [0.06, 0.03, 0.1], ["surface"], {"pickable": True}),
}
CATALOG_DATA = {"schema": "logicenveval.catalog/1", "categories": {
    name: {"size_min": lo, "size_max": hi, "placement": pl, **extra} for name, (lo, hi, pl, extra) in _SPECS.items()}}


@pytest.fixture(autouse=True)
def catalog(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch) -> Catalog:
    path = tmp_path_factory.getbasetemp() / "baselines_catalog.json"
    if not path.exists():
        path.write_text(json.dumps(CATALOG_DATA), encoding="utf-8")
    monkeypatch.setattr(domain.catalog, "DEFAULT_CATALOG", path)
    return load_catalog()


def _run(name: str, task_id: str, seed: int = 7, **options: Any) -> GenerationResult:
    task = load_task(task_id, TASKS)
    ctx = GenerationContext(model=OfflineModel(), catalog=load_catalog(), rng=np.random.default_rng(seed), seed=seed)
    return make_generator(name, **options).generate(task.brief(), ctx)


def test_registered() -> None:
    assert {"cot", "ifg", "holodeck"} <= set(registered())


@pytest.mark.parametrize("name", ["cot", "ifg", "holodeck"])
@pytest.mark.parametrize("task_id", IDS)
def test_schema_valid_envs_binding_roles(name: str, task_id: str) -> None:
    brief = load_task(task_id, TASKS).brief()
    result = _run(name, task_id)
    assert result.envs or result.failures
    ids = [e.env_id for e in result.envs]
    assert len(set(ids)) == len(ids)
    for env in result.envs:
        again = EnvSpec.model_validate_json(json.dumps(env.to_json_dict()))
        assert again == env
        assert env.generator == name and env.claimed_trajectory is None and env.task_id == task_id
        # only the roles the reply gives an object: the others are the judge's (domain.roles)
        assert set(env.roles) <= set(brief.roles) and None not in env.roles.values()
        assert len(env.roles) >= len(brief.roles) - 1
        for role, oid in env.roles.items():
            if oid is not None:
                assert env.obj(oid).category == brief.roles[role].category
    if name == "holodeck":
        assert len(result.envs) == 1


@pytest.mark.parametrize("name", ["cot", "ifg", "holodeck"])
def test_same_seed_same_json(name: str) -> None:
    a = [e.to_json_dict() for e in _run(name, "clean_living_room", seed=3).envs]
    b = [e.to_json_dict() for e in _run(name, "clean_living_room", seed=3).envs]
    assert json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True)


def test_cot_realises_each_flat_situation() -> None:
    result = _run("cot", "clean_living_room")
    assert len(result.envs) >= 3
    kinds = {e.obj(e.roles["toy"] or "").attributes.get("kind") for e in result.envs}
    assert "doll" in kinds and len(kinds) >= 2  # the doll case and its alternative


def test_ifg_keeps_duplicates_and_k() -> None:
    result = _run("ifg", "clean_living_room", k=12)
    assert len(result.envs) == 12
    intents = [tuple(e.model_extra["intent"]) for e in result.envs if e.model_extra]
    assert len(set(intents)) < len(intents)  # duplicates are kept, not removed


def _intents(temperature: float, seed: int, k: int = 200) -> list[tuple[str, ...]]:
    task = load_task("clean_living_room", TASKS).brief().model_dump(mode="json")
    req = ChatRequest(kind="ifg_intents", payload={"task": task, "k": k}, messages=[], schema=None,
                      temperature=temperature, seed=seed)
    return [tuple(t["facts"]) for t in oh.ifg_intents({"task": task, "k": k}, req)["trajectories"]]


def test_ifg_temperature_changes_distribution() -> None:
    cold, hot = _intents(0.2, 1), _intents(1.1, 1)
    assert len(set(hot)) > len(set(cold))
    assert _intents(0.0, 5) == _intents(0.0, 9)  # greedy does not depend on the seed
    assert _intents(1.1, 1) == hot and _intents(1.1, 2) != hot


def test_value_probabilities() -> None:
    assert oh.value_probabilities(2, 0.0).tolist() == [1.0, 0.0]
    hot, cold = oh.value_probabilities(3, 1.1), oh.value_probabilities(3, 0.5)
    assert hot.sum() == pytest.approx(1.0) and hot[0] < cold[0] and hot[1] == hot[2]


def test_handlers_read_only_the_payload(monkeypatch: pytest.MonkeyPatch) -> None:
    """The brief alone: task files, variables and policies are unreachable to the handlers."""
    import builtins

    real_open = builtins.open

    def guarded(file: Any, *args: Any, **kwargs: Any) -> Any:
        if "tasks" in str(file) or "policies" in str(file):
            raise AssertionError(f"handler opened {file}")
        return real_open(file, *args, **kwargs)

    monkeypatch.setattr(builtins, "open", guarded)
    brief = {"id": "x", "rooms": ["living_room"], "description": "If the toy is on the floor, put it in the toy box.",
             "roles": {"toy": {"category": "toy", "attributes": {}}, "box": {"category": "toy_box", "attributes": {}}}}
    req = ChatRequest(kind="cot_environments", payload={}, messages=[], schema=None, seed=0)
    envs = oh.cot_environments({"task": brief, "n_environments": 5}, req)["environments"]
    placements = {o["placement"] for e in envs for o in e["objects"] if o["id"] == "toy"}
    assert "floor" in placements and len(placements) == 2
    intents = oh.ifg_intents({"task": brief, "k": 4}, req)["trajectories"]
    assert all(t["facts"] for t in intents)


def test_holodeck_layout_is_physically_sound() -> None:
    """No two floor objects overlap, every object inside its room, held objects on their holder."""
    for task_id in IDS:
        env = _run("holodeck", task_id).envs[0]
        rooms = {r.id: r.polygon for r in env.rooms}
        floor = []
        for o in env.objects:
            assert o.position is not None and o.size is not None and o.room in rooms
            poly = rooms[o.room] or []
            xs, zs = [p[0] for p in poly], [p[1] for p in poly]
            fx, fz = (o.size[2], o.size[0]) if round(o.yaw) % 180 == 90 else (o.size[0], o.size[2])
            assert min(xs) - 1e-6 <= o.position[0] - fx / 2 and o.position[0] + fx / 2 <= max(xs) + 1e-6
            assert min(zs) - 1e-6 <= o.position[2] - fz / 2 and o.position[2] + fz / 2 <= max(zs) + 1e-6
            if o.support == "floor":
                assert o.position[1] == pytest.approx(o.size[1] / 2)
                floor.append(Box(o.position[0], o.position[2], fx, fz))
            elif o.support not in (None, "wall"):
                s = env.obj(o.support)
                assert s.position and s.size
                shape = load_shapes().of(s.category)  # a seat holds things on its seat, not its top
                level = shape.surface()[0] if shape is not None else 1.0
                assert o.position[1] - o.size[1] / 2 == pytest.approx(s.position[1] + (level - 0.5) * s.size[1])
        for i, a in enumerate(floor):
            assert not any(a.overlaps(b, 0.0) for b in floor[i + 1:])
        assert not _interpenetrations(env)


def test_holodeck_passes_physics_checker() -> None:
    physics = pytest.importorskip("logicenveval.physics")
    if not hasattr(physics, "check_env"):
        pytest.skip("the physics checker is not built yet")
    for task_id in IDS:
        env = _run("holodeck", task_id).envs[0]
        report = physics.check_env(env, load_catalog())
        assert report.passed, report


def test_invalid_draft_is_a_recorded_failure() -> None:
    from logicenveval.baselines.drafts import env_from_draft
    from logicenveval.baselines.replies import WrittenEnvironment
    from logicenveval.errors import EnvSpecError

    brief = load_task("clean_living_room", TASKS).brief()
    toy = {"id": "toy", "category": "toy", "room": "living_room", "role": "toy", "placement": "on:shelf_9",
           "position": (1.0, 0.5, 1.0), "size": (0.2, 0.2, 0.2)}
    draft = WrittenEnvironment.model_validate({
        "rooms": [{"id": "living_room", "type": "LivingRoom", "polygon": [(0, 0), (5, 0), (5, 4), (0, 4)]}],
        "doors": [{"rooms": ["living_room", "exterior"], "segment": [(2, 0), (2.9, 0)]}],
        "windows": [{"room": "living_room", "segment": [(1, 4), (2.2, 4)], "sill": 1.0, "height": 2.2}],
        "objects": [toy]})
    with pytest.raises(EnvSpecError, match="shelf_9"):
        env_from_draft(brief, env_id="cot-00", generator="cot", draft=draft)
    ok = env_from_draft(brief, env_id="cot-00", generator="cot",
                        draft=draft.model_copy(update={"objects": [draft.objects[0].model_copy(
                            update={"placement": "floor"})]}))
    assert ok.roles == {"toy": "toy"}  # no null for the roles it leaves out: the judge binds them
    assert ok.doors[0].id == "d0" and ok.doors[0].segment == ((2, 0), (2.9, 0))
    assert ok.windows[0].segment == ((1, 4), (2.2, 4)) and ok.windows[0].height == 2.2  # as written, not repaired
    assert [f.code for f in __import__("logicenveval.physics", fromlist=["check_env"]).check_env(
        ok).floor_plan.failures] == ["window_above_ceiling"]


def test_cot_and_ifg_floor_plans_are_their_own_and_judged_as_written() -> None:
    """The offline writer's coarse rule: rooms in a row, every room joined to the hub. On
    multi_room_laundry_collect (bedroom | bathroom | laundry_room) the bedroom–laundry door is drawn
    on the bedroom's east wall, which the laundry room does not share: a floor-plan failure."""
    from logicenveval.physics import check_env

    brief = load_task("multi_room_laundry_collect", TASKS).brief().model_dump(mode="json")
    plan = oh.written_floor_plan(brief)
    for name in ("cot", "ifg"):
        env = _run(name, "multi_room_laundry_collect").envs[0]
        assert [r.polygon for r in env.rooms] == [[tuple(p) for p in r["polygon"]] for r in plan["rooms"]]
        assert [d.segment for d in env.doors] == [tuple(tuple(p) for p in d["segment"]) for d in plan["doors"]]
        polys = [r.polygon or [] for r in env.rooms]
        for left, right in zip(polys, polys[1:], strict=False):
            assert left[1][0] == right[0][0]  # east wall of one room is the west wall of the next
        report = check_env(env)
        far = next(d.id for d in env.doors if set(d.rooms) == {"bedroom", "laundry_room"})
        assert [(f.code, f.objects, f.rooms) for f in report.floor_plan.failures] == [
            ("door_not_on_wall", [far], ["laundry_room"])]


def test_written_reply_models_round_trip_as_json() -> None:
    from logicenveval.baselines.replies import WrittenEnvironmentsReply
    from logicenveval.llm.replies import PlacementReply

    req = ChatRequest(kind="cot_environments", payload={}, messages=[], schema=None, seed=0)
    brief = load_task("multi_room_laundry_collect", TASKS).brief().model_dump(mode="json")
    reply = WrittenEnvironmentsReply.model_validate(oh.cot_environments({"task": brief, "n_environments": 2}, req))
    assert WrittenEnvironmentsReply.model_validate_json(reply.model_dump_json()) == reply
    assert len(reply.environments) == 2 and len(reply.environments[0].doors) == 3
    placement = PlacementReply.model_validate({"objects": [reply.environments[0].objects[0].model_dump()],
                                               "openings": [{"id": "d0", "segment": [[0, 0], [0.9, 0]]}]})
    assert PlacementReply.model_validate_json(placement.model_dump_json()) == placement


def test_written_floor_plan_hub_is_the_hallway() -> None:
    plan = oh.written_floor_plan({"rooms": ["kitchen", "living_room", "hallway"]})
    assert [d["rooms"] for d in plan["doors"]] == [["hallway", "exterior"], ["hallway", "kitchen"],
                                                   ["hallway", "living_room"]]
    assert [w["room"] for w in plan["windows"]] == ["kitchen", "living_room"]
    single = oh.written_floor_plan({"rooms": ["bathroom"]})
    assert len(single["doors"]) == 1 and len(single["windows"]) == 1


REAL_CATALOG = Path(__file__).resolve().parents[1] / "benchmark_data" / "catalog.json"


@pytest.mark.skipif(not REAL_CATALOG.exists(), reason="benchmark catalog not written yet")
def test_every_task_with_the_benchmark_catalog(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every benchmark task: envs or an explained failure; Holodeck covers fewer paths than CoT and
    IFG and passes the physics checker."""
    from logicenveval.benchmark import task_ids
    from logicenveval.model.tree import evaluate_task, task_paths
    from logicenveval.sim.world import holds_initial

    monkeypatch.setattr(domain.catalog, "DEFAULT_CATALOG", REAL_CATALOG)
    cat = load_catalog()
    try:
        import logicenveval.physics as physics
    except ImportError:
        physics = None
    coverage: dict[str, list[float]] = {"cot": [], "ifg": [], "holodeck": []}
    for task_id in task_ids(TASKS):
        task = load_task(task_id, TASKS)
        total = {p.key for paths in task_paths(task) for p in paths}
        for name in coverage:
            ctx = GenerationContext(model=OfflineModel(), catalog=cat, rng=np.random.default_rng(0), seed=0)
            result = make_generator(name).generate(task.brief(), ctx)
            assert result.envs or all(f.message for f in result.failures)
            if name == "holodeck":
                assert not _interpenetrations(result.envs[0]), task_id
                if physics is not None:
                    assert physics.check_env(result.envs[0], cat).passed, task_id
            covered = {o.path.key for e in result.envs for o in evaluate_task(task, holds_initial(e, cat)) if o.path}
            coverage[name].append(len(covered & total) / len(total))
    mean = {k: sum(v) / len(v) for k, v in coverage.items()}
    assert mean["holodeck"] < mean["cot"] and mean["holodeck"] < mean["ifg"]


def _interpenetrations(env: EnvSpec) -> list[tuple[str, str]]:
    """Pairs of objects whose boxes overlap by more than 1 cm on every axis (not holder pairs)."""
    def aabb(o: Any) -> tuple[np.ndarray, np.ndarray]:
        sx, sy, sz = o.size
        fx, fz = (sz, sx) if round(o.yaw) % 180 == 90 else (sx, sz)
        x, y, z = o.position
        return np.array([x - fx / 2, y - sy / 2, z - fz / 2]), np.array([x + fx / 2, y + sy / 2, z + fz / 2])

    out = []
    for i, a in enumerate(env.objects):
        for b in env.objects[i + 1:]:
            if a.room != b.room or a.id in (b.support, b.container) or b.id in (a.support, a.container):
                continue
            (lo1, hi1), (lo2, hi2) = aabb(a), aabb(b)
            if ((np.minimum(hi1, hi2) - np.maximum(lo1, lo2)) > 0.01).all():
                out.append((a.id, b.id))
    return out


@pytest.mark.parametrize(("name", "options"), [("cot", {"max_environments": 0}), ("ifg", {"k": 0}),
                                               ("ifg", {"intent_temperature": -1.0}), ("holodeck", {"grid": 0.0})])
def test_bad_options_are_config_errors(name: str, options: dict[str, Any]) -> None:
    from logicenveval.errors import ConfigError

    with pytest.raises(ConfigError, match=next(iter(options)).split("_")[0]):
        make_generator(name, **options)


def test_paper_method_names_and_old_alias_warns() -> None:
    assert {"logicenvgen", "logicenvgen-exact", "logicenvgen-no-dbp", "logicenvgen-no-mtsa",
            "logicenvgen-exhaustive", "logicenvgen-no-cas"} <= set(registered())
    gens = {n: make_generator(n) for n in ("logicenvgen", "logicenvgen-exact", "logicenvgen-no-mtsa",
                                           "logicenvgen-exhaustive", "logicenvgen-no-cas")}
    selectors = {n: g.selector for n, g in gens.items() if isinstance(g, LogicEnvGen)}
    assert selectors == {"logicenvgen": "mtsa", "logicenvgen-exact": "exact", "logicenvgen-no-mtsa": "product",
                         "logicenvgen-exhaustive": "exhaustive", "logicenvgen-no-cas": "mtsa"}
    with pytest.warns(FutureWarning, match="'logicenvgen-mtsa' is an old name of 'logicenvgen'"):
        gen = make_generator("logicenvgen-mtsa")
    assert gen.name == "logicenvgen"
    with pytest.warns(FutureWarning, match="old name"):
        config = RunConfig(generators=("logicenvgen-mtsa", "cot"))
    assert config.generators == ("logicenvgen", "cot")
