"""Mutation suite: one injected fault at a time must fail exactly the right PhyPR dimension."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.domain.shapes import load_shapes
from logicenveval.envfiles import env_from_dict
from logicenveval.physics import check_env
from logicenveval.physics.geometry import build_bodies
from logicenveval.physics.report import DEFAULT_TOLERANCES

FIXTURES = Path(__file__).parent / "fixtures" / "envs"
ENVS = {p.stem: json.loads(p.read_text()) for p in sorted(FIXTURES.glob("*.json"))}
FAST = settings(max_examples=15, deadline=None)


def _copy(name: str) -> dict[str, Any]:
    data: dict[str, Any] = json.loads(json.dumps(ENVS[name]))
    return data


def _obj(data: dict[str, Any], oid: str) -> dict[str, Any]:
    return next(o for o in data["objects"] if o["id"] == oid)


def _move(data: dict[str, Any], oid: str, dx: float, dy: float, dz: float) -> None:
    """Move an object together with everything resting on it or inside it."""
    o = _obj(data, oid)
    o["position"] = [o["position"][0] + dx, o["position"][1] + dy, o["position"][2] + dz]
    for child in data["objects"]:
        if child["support"] == oid or child["container"] == oid:
            _move(data, child["id"], dx, dy, dz)


def _failed(data: dict[str, Any]) -> set[str]:
    return set(check_env(env_from_dict(data)).failed_dimensions())


@pytest.mark.parametrize("name", sorted(ENVS))
def test_valid_environments_pass(name: str) -> None:
    report = check_env(env_from_dict(ENVS[name]))
    assert report.passed, [f.message for f in report.failures()]


#: the depth fraction of a chair's solid back strip (domain.shapes, derived from AI2-THOR's scenes)
CHAIR_BACK = load_shapes().types["Chair"].solid[1].z[1]  # type: ignore[index]
# (env, mover, pre-move dz, direction x, direction z, gap): after the pre-move, moving by gap + d
# along the direction makes `mover` penetrate its neighbour by d. The chair faces the dining table
# 0.30 m away: its seat slides under the table top, and its back strip (the back CHAIR_BACK of its
# 0.5 m depth) meets the top's edge only after 0.30 + (1 - CHAIR_BACK) * 0.5 m.
COLLIDE = [("three_rooms", "laundry_basket_1", 6.9 - 4.8, -1.0, 0.0, 2.25 - 1.65),
           ("three_rooms", "chair_1", 0.0, 0.0, -1.0, 0.30 + (1 - CHAIR_BACK) * 0.5),
           ("one_room", "table_1", 0.0, 0.0, 1.0, 0.55)]


@FAST
@given(case=st.sampled_from(COLLIDE), depth=st.floats(0.02, 0.1))
def test_object_moved_into_another_fails_entity_only(case: tuple[str, str, float, float, float, float],
                                                      depth: float) -> None:
    name, oid, pre_dz, ux, uz, gap = case
    data = _copy(name)
    _move(data, oid, 0.0, 0.0, pre_dz)
    _move(data, oid, ux * (gap + depth), 0.0, uz * (gap + depth))
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"entity"}
    assert any(f.code == "interpenetration" and oid in f.objects for f in report.entity.failures)


@FAST
@given(oid=st.sampled_from(["three_rooms/laundry_basket_1", "three_rooms/chair_1", "one_room/toy_box_1"]),
       lift=st.floats(DEFAULT_TOLERANCES.support_gap + 0.001, DEFAULT_TOLERANCES.settle_drop - 1e-6))
def test_a_short_drop_above_the_support_settles(oid: str, lift: float) -> None:
    """Settle, then judge: a bottom up to `settle_drop` above its support is where AI2-THOR's
    physics puts it on load (ProcTHOR writes spawn positions that high), so it passes."""
    name, obj = oid.split("/")
    data = _copy(name)
    _move(data, obj, 0.0, lift, 0.0)
    assert check_env(env_from_dict(data)).passed


@FAST
@given(depth=st.floats(0.02, (1 - CHAIR_BACK) * 0.5 - 0.02))
def test_a_chair_seat_tucks_under_the_table_top(depth: float) -> None:
    """The free space under a table top (domain.shapes): a chair pushed under the dining table
    by less than its seat depth does not collide; boxes would (the old judgement)."""
    data = _copy("three_rooms")
    _move(data, "chair_1", 0.0, 0.0, -(0.30 + depth))
    assert check_env(env_from_dict(data)).passed


@FAST
@given(oid=st.sampled_from(["three_rooms/laundry_basket_1", "three_rooms/chair_1", "three_rooms/bed_1",
                            "three_rooms/wardrobe_1", "one_room/floor_lamp_1", "one_room/toy_box_1"]),
       lift=st.floats(DEFAULT_TOLERANCES.settle_drop + 0.01, 0.5))
def test_lifted_off_support_fails_entity_only(oid: str, lift: float) -> None:
    name, obj = oid.split("/")
    data = _copy(name)
    _move(data, obj, 0.0, lift, 0.0)
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"entity"}
    assert any(f.code == "not_supported" and f.objects == [obj] for f in report.entity.failures)


@FAST
@given(case=st.sampled_from([("three_rooms", "wardrobe_1", 0.0, 1.0, 8.0 - 7.95),
                             ("one_room", "toy_box_1", 1.0, 0.0, 5.0 - 4.75),
                             ("three_rooms", "cabinet_1", 1.0, 0.0, 9.0 - 8.9)]),
       beyond=st.floats(0.05, 0.4))
def test_pushed_through_wall_fails_entity_only(case: tuple[str, str, float, float, float], beyond: float) -> None:
    name, oid, ux, uz, gap = case
    data = _copy(name)
    _move(data, oid, ux * (gap + beyond), 0.0, uz * (gap + beyond))
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"entity"}
    assert any(f.code == "outside_room" and f.objects == [oid] for f in report.entity.failures)


@FAST
@given(room=st.sampled_from(["kitchen", "bedroom"]), grow=st.floats(0.05, 2.0))
def test_overlapping_rooms_fail_floor_plan_only(room: str, grow: float) -> None:
    data = _copy("three_rooms")
    r = next(r for r in data["rooms"] if r["id"] == room)
    if room == "kitchen":  # pull its west wall into the living room
        r["polygon"] = [[5 - grow, 0], [9, 0], [9, 4], [5 - grow, 4]]
    else:  # pull its north wall into the living room
        r["polygon"] = [[0, 4 - grow], [5, 4 - grow], [5, 8], [0, 8]]
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"floor_plan"}
    assert any(f.code == "rooms_overlap" for f in report.floor_plan.failures)


@FAST
@given(case=st.sampled_from([("d_lk", 0.0, 5.2, 7.0), ("d_lb", 8.0, 1.8, 2.3)]), t=st.floats(0.0, 1.0))
def test_door_on_non_shared_wall_fails_floor_plan_only(case: tuple[str, float, float, float], t: float) -> None:
    door, z, lo, hi = case
    data = _copy("three_rooms")
    x = lo + t * (hi - lo)
    next(d for d in data["doors"] if d["id"] == door)["segment"] = [[x, z], [x + 1.0, z]]
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"floor_plan"}
    assert any(f.code == "door_not_on_wall" and door in f.objects for f in report.floor_plan.failures)


@FAST
@given(name=st.sampled_from(sorted(ENVS)), excess=st.floats(0.01, 1.0), which=st.integers(0, 1))
def test_window_above_ceiling_fails_floor_plan_only(name: str, excess: float, which: int) -> None:
    data = _copy(name)
    w = data["windows"][which % len(data["windows"])]
    w["height"] = data["wall_height"] - w["sill"] + excess
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"floor_plan"}  # Table 2: embedded in the wall
    assert [f.code for f in report.floor_plan.failures] == ["window_above_ceiling"]
    assert report.extended.passed


@FAST
@given(name=st.sampled_from(sorted(ENVS)), off=st.floats(0.08, 1.0))
def test_item_slid_beside_its_support_fails_entity_only(name: str, off: float) -> None:
    """At its supporter's height but with the centre of mass beside the top: floating."""
    data = _copy(name)
    item = next(o for o in data["objects"] if o["support"] not in ("floor", "wall", "ceiling", None))
    sup = _obj(data, item["support"])
    half = max(sup["size"][0], sup["size"][2]) / 2
    item["position"][0] = sup["position"][0] + half + off
    data["relations"] = [r for r in data["relations"] if item["id"] not in r["args"]]
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"entity"}
    assert [f.code for f in report.entity.failures if item["id"] in f.objects][0] == "centre_off_support"


@FAST
@given(z=st.floats(1.3, 1.7))
def test_moved_away_breaks_near_relation_only(z: float) -> None:
    data = _copy("three_rooms")
    _move(data, "table_1", 0.0, 0.0, z - 2.2)
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"relation"}
    assert [f.objects for f in report.relation.failures] == [["table_1", "sofa_1"]]


@FAST
@given(data_=st.data())
def test_declared_near_between_distant_objects_fails_relation_only(data_: st.DataObject) -> None:
    name = data_.draw(st.sampled_from(sorted(ENVS)))
    env = env_from_dict(ENVS[name])
    bodies = build_bodies(env)
    far_pairs = [(a, b) for a in bodies for b in bodies
                 if a < b and bodies[a].footprint.distance(bodies[b].footprint) > 1.0]
    a, b = data_.draw(st.sampled_from(far_pairs))
    data = _copy(name)
    data["relations"].append({"type": "near", "args": [a, b]})
    report = check_env(env_from_dict(data))
    assert report.failed_dimensions() == {"relation"}
    assert report.relation.failures[0].objects == [a, b]


def _transform(data: dict[str, Any], k: int, tx: float, tz: float) -> None:
    """Rotate the whole environment by k × 90° about +y, then translate it on the floor."""
    def f(x: float, z: float) -> list[float]:
        for _ in range(k):
            x, z = z, -x  # R_y(90°) maps (x, z) to (z, −x)
        return [x + tx, z + tz]

    for r in data["rooms"]:
        r["polygon"] = [f(*p) for p in r["polygon"]]
    for d in [*data["doors"], *data["windows"]]:
        d["segment"] = [f(*p) for p in d["segment"]]
    for o in data["objects"]:
        x, z = f(o["position"][0], o["position"][2])
        o["position"] = [x, o["position"][1], z]
        o["yaw"] = o["yaw"] + 90.0 * k


@FAST
@given(name=st.sampled_from(sorted(ENVS)), k=st.integers(0, 3), tx=st.floats(-50, 50), tz=st.floats(-50, 50))
def test_valid_environments_pass_wherever_and_however_turned(name: str, k: int, tx: float, tz: float) -> None:
    data = _copy(name)
    _transform(data, k, tx, tz)
    report = check_env(env_from_dict(data))
    assert report.passed, [f.message for f in report.failures()]
