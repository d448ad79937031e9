"""Unit tests of the individual PhyPR checks, the report type and the broad phase."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.envfiles import env_from_dict
from logicenveval.model.envspec import EnvObject, EnvSpec
from logicenveval.physics import (
    DimensionReport,
    PhysicsFailure,
    PhysicsReport,
    Tolerances,
    check_env,
)
from logicenveval.physics.entity import collisions
from logicenveval.physics.geometry import build_body, candidate_pairs, yaw_matrix

FIXTURES = Path(__file__).parent / "fixtures" / "envs"


def _load(name: str) -> dict[str, Any]:
    data: dict[str, Any] = json.loads((FIXTURES / f"{name}.json").read_text())
    return data


def _obj(data: dict[str, Any], oid: str) -> dict[str, Any]:
    return next(o for o in data["objects"] if o["id"] == oid)


def _codes(data: dict[str, Any], dim: str) -> list[str]:
    report = check_env(env_from_dict(data))
    return [f.code for f in getattr(report, dim).failures]


def test_report_json_has_exact_shape_and_round_trips() -> None:
    data = _load("one_room")
    _obj(data, "floor_lamp_1")["position"][1] += 0.2
    report = check_env(env_from_dict(data))
    dumped = report.model_dump(mode="json")
    assert set(dumped) == {"floor_plan", "entity", "relation", "extended"}
    assert all(set(v) == {"passed", "failures"} for v in dumped.values())
    assert PhysicsReport.model_validate_json(report.model_dump_json()) == report
    assert not report.passed and report.failed_dimensions() == {"entity"}
    with pytest.raises(ValueError):
        report.entity.failures[0].__setattr__("code", "x")


def test_dimension_report_of() -> None:
    f = PhysicsFailure(dimension="entity", code="c", message="m")
    assert DimensionReport.of([]).passed and not DimensionReport.of([f]).passed


def test_yaw_front_convention() -> None:
    np.testing.assert_allclose(yaw_matrix(90.0) @ [0, 0, 1], [1, 0, 0], atol=1e-12)
    body = build_body(EnvObject(id="a", category="x", room="r", position=(0, 0.5, 0), size=(2, 1, 0.5), yaw=90))
    x0, z0, x1, z1 = body.footprint.bounds
    assert (x1 - x0, z1 - z0) == pytest.approx((0.5, 2.0))
    np.testing.assert_allclose(body.front(), [1.0, 0.0], atol=1e-12)


def test_missing_geometry_is_an_entity_failure() -> None:
    data = _load("one_room")
    _obj(data, "floor_lamp_1")["position"] = None
    data["relations"] = [r for r in data["relations"] if "floor_lamp_1" not in r["args"]]
    assert _codes(data, "entity") == ["missing_geometry"]


def test_centre_of_mass_beside_the_support_fails_entity() -> None:
    """Table 2 "supported by a surface (i.e., not floating)": at the table's height but with its
    centre of mass beside the top, the book floats."""
    data = _load("one_room")
    _obj(data, "book_1")["position"][0] = 2.55  # table spans x 1.5..2.5
    assert _codes(data, "entity") == ["centre_off_support"] and _codes(data, "extended") == []
    assert _codes(data, "relation") == ["relation_violated"]


def test_object_beside_its_table_at_table_height_fails_entity() -> None:
    """The audit's case: wet wipes moved 0.3 m sideways off the table, bottom still at its top."""
    data = _load("one_room")
    book = _obj(data, "book_1")
    book.update(id="wet_wipe_1", category="wet_wipe", size=[0.2, 0.06, 0.12])
    data["relations"], data["roles"] = [], {}
    book["position"] = [2.0, 0.45 + 0.03, 2.2]
    assert _codes(data, "entity") == []
    book["position"][2] += 0.3 + 0.3  # the table's half depth is 0.3 m: now 0.3 m beside it
    report = check_env(env_from_dict(data))
    assert [f.code for f in report.entity.failures] == ["centre_off_support"]
    assert report.entity.failures[0].measured == pytest.approx(0.3)


def test_contents_of_one_container_must_not_collide() -> None:
    data = _load("one_room")
    assert _codes(data, "entity") == []
    _obj(data, "toy_2")["position"][0] = 4.45  # 15 cm into toy_1, both inside toy_box_1
    report = check_env(env_from_dict(data))
    assert [(f.code, sorted(f.objects)) for f in report.entity.failures] == [
        ("interpenetration", ["toy_1", "toy_2"])]


def test_nested_containers_enclose_their_contents() -> None:
    data = _load("one_room")
    _obj(data, "toy_box_1")["size"] = [0.9, 0.45, 0.45]
    _obj(data, "toy_box_1")["position"][0] = 4.3
    data["objects"].append({"id": "basket_1", "category": "basket", "room": "living_room",
                            "position": [4.05, 0.15, 1.5], "size": [0.3, 0.25, 0.3], "support": None,
                            "container": "toy_box_1"})
    data["objects"].append({"id": "ball_1", "category": "ball", "room": "living_room",
                            "position": [4.05, 0.12, 1.5], "size": [0.1, 0.1, 0.1], "support": None,
                            "container": "basket_1"})
    _obj(data, "toy_2")["position"][0] = 4.35
    _obj(data, "toy_1")["position"][0] = 4.6
    assert _codes(data, "entity") == []  # the ball lies in the basket, and so in the toy box


def test_wall_mounting_needs_the_catalog() -> None:
    data = _load("one_room")
    painting = _obj(data, "painting_1")
    painting["category"] = "armchair"  # the catalog places armchairs on the floor only
    data["relations"] = []
    assert _codes(data, "entity") == ["not_supported"]
    painting["category"] = "a_category_the_catalog_does_not_know"
    assert _codes(data, "entity") == []


def test_content_sticking_out_of_container() -> None:
    data = _load("one_room")
    _obj(data, "toy_2")["position"][1] = 0.45
    assert "not_contained" in _codes(data, "entity")


def test_wall_mounted_object_away_from_wall() -> None:
    data = _load("one_room")
    _obj(data, "painting_1")["position"][2] = 3.5
    assert "not_on_wall" in _codes(data, "entity")
    assert _codes(data, "relation") == ["relation_violated"]


def test_object_in_door_swing_area() -> None:
    data = _load("one_room")
    _obj(data, "floor_lamp_1")["position"] = [2.5, 0.8, 0.5]
    data["relations"] = [r for r in data["relations"] if "floor_lamp_1" not in r["args"]]
    assert _codes(data, "extended") == ["blocks_door"]
    assert _codes(data, "entity") == []  # not a constraint of the paper's Table 2


def test_size_outside_catalog_range() -> None:
    data = _load("one_room")
    _obj(data, "floor_lamp_1")["size"] = [0.35, 2.5, 0.35]
    _obj(data, "floor_lamp_1")["position"][1] = 1.25
    assert _codes(data, "extended") == ["size_out_of_range"] and _codes(data, "entity") == []
    _obj(data, "floor_lamp_1")["size"][1] = 1.9 * 1.09  # inside the ±10 % band
    _obj(data, "floor_lamp_1")["position"][1] = 1.9 * 1.09 / 2
    assert _codes(data, "extended") == []


def test_object_through_the_ceiling() -> None:
    data = _load("three_rooms")
    _obj(data, "wardrobe_1")["position"][1] = 1.0 + 1.0
    assert _codes(data, "entity") == ["not_supported"]
    assert _codes(data, "extended") == ["above_ceiling"]


def test_unreachable_room_and_window_faults() -> None:
    data = _load("three_rooms")
    data["doors"] = [d for d in data["doors"] if d["id"] != "d_lb"]
    assert _codes(data, "extended") == ["unreachable_room"] and _codes(data, "floor_plan") == []
    data = _load("one_room")
    data["windows"][0]["segment"] = [[2.2, 0], [3.5, 0]]
    assert _codes(data, "extended") == ["window_overlaps_door"] and _codes(data, "floor_plan") == []
    data["windows"][0]["segment"] = [[1, 1], [1, 2]]
    assert _codes(data, "floor_plan") == ["window_not_on_wall"]
    data = _load("one_room")
    data["windows"][0]["sill"] = 0.0
    assert _codes(data, "floor_plan") == ["window_sill"]


def test_window_through_the_ceiling_fails_floor_plan() -> None:
    """Table 2: "A window must be embedded in the wall": a top at 3.2 m in a 2.7 m wall is not."""
    data = _load("one_room")
    data["windows"][0].update(sill=1.0, height=2.2)
    report = check_env(env_from_dict(data))
    assert [f.code for f in report.floor_plan.failures] == ["window_above_ceiling"]
    assert report.floor_plan.failures[0].measured == pytest.approx(3.2)
    assert report.failed_dimensions() == {"floor_plan"}


def test_invalid_polygon_and_exterior_door_on_shared_wall() -> None:
    data = _load("one_room")
    data["rooms"][0]["polygon"] = [[0, 0], [5, 4], [5, 0], [0, 4]]  # bow tie
    assert "invalid_polygon" in _codes(data, "floor_plan")
    data = _load("three_rooms")
    data["doors"][0]["segment"] = [[5, 0.2], [5, 1.2]]
    assert _codes(data, "floor_plan") == ["door_not_exterior"]


@pytest.mark.parametrize(("rel", "ok"), [
    ({"type": "face_to", "args": ["table_1", "sofa_1"]}, True),
    ({"type": "face_to", "args": ["toy_box_1", "sofa_1"]}, False),
    ({"type": "far", "args": ["table_1", "sofa_1"]}, False),
    ({"type": "on", "args": ["book_1", "sofa_1"]}, False),
    ({"type": "inside", "args": ["toy_2", "toy_box_1"]}, True),
    ({"type": "above", "args": ["painting_1", "table_1"]}, False),
    ({"type": "edge", "args": ["table_1"]}, False),
    ({"type": "center", "args": ["floor_lamp_1"]}, False),
    ({"type": "side_of", "args": ["table_1", "sofa_1"]}, False),
    ({"type": "in_front_of", "args": ["floor_lamp_1", "sofa_1"]}, False),
    ({"type": "center_aligned", "args": ["toy_box_1", "sofa_1"]}, False),
    ({"type": "wall_mounted", "args": ["floor_lamp_1"]}, False),
    ({"type": "near", "args": ["toy", "sofa"]}, False),
    ({"type": "near", "args": ["book", "sofa"]}, True),
    ({"type": "near", "args": ["ghost", "sofa"]}, False),
])
def test_relation_semantics(rel: dict[str, Any], ok: bool) -> None:
    data = _load("one_room")
    data["relations"] = [rel]
    assert (_codes(data, "relation") == []) is ok


def test_mesh_file_is_used_and_a_missing_one_reported(tmp_path: Path) -> None:
    data = _load("one_room")
    trimesh.creation.box(extents=(0.35, 1.6, 0.35)).export(str(tmp_path / "lamp.stl"))
    _obj(data, "floor_lamp_1")["mesh"] = "lamp.stl"
    assert check_env(env_from_dict(data), mesh_dir=tmp_path).passed
    _obj(data, "floor_lamp_1")["mesh"] = "nope.stl"
    assert [f.code for f in check_env(env_from_dict(data), mesh_dir=tmp_path).entity.failures] == [
        "mesh_not_found"]


def test_unknown_fields_are_ignored_and_tolerances_are_frozen() -> None:
    data = _load("one_room")
    data["extra"] = {"anything": 1}
    _obj(data, "sofa_1")["color_hint"] = "blue"
    assert check_env(env_from_dict(data)).passed
    with pytest.raises(ValueError):
        Tolerances().__setattr__("near_gap", 2.0)
    strict = Tolerances(near_gap=0.1)
    assert not check_env(env_from_dict(_load("one_room")), tolerances=strict).relation.passed


_box = st.tuples(st.floats(0, 4), st.floats(0, 1), st.floats(0, 4), st.floats(0.1, 1.0),
                 st.floats(0.1, 1.0), st.floats(0.1, 1.0), st.floats(0, 360))


def _named(failures: list[PhysicsFailure]) -> dict[str, int]:
    out: dict[str, int] = {}
    for f in failures:
        for o in f.objects:
            out[o] = out.get(o, 0) + 1
    return out


@settings(max_examples=40, deadline=None)
@given(boxes=st.lists(_box, min_size=2, max_size=14), pile=st.integers(0, 12))
def test_broad_phase_finds_the_same_collisions_as_all_pairs(
        boxes: list[tuple[float, float, float, float, float, float, float]], pile: int) -> None:
    """The broad phase (sweep, separating axes, per-object cap) against the old all-pairs path:
    identical while no object reaches the cap; beyond it a subsequence that still names every
    colliding object at least min(its collisions, cap) times."""
    from logicenveval.physics.entity import MAX_COLLISIONS_PER_OBJECT as CAP

    boxes = boxes + [(1.0, 0.5, 1.0, 0.5, 0.5, 0.5, 0.0)] * pile  # a pile in one place
    bodies = [build_body(EnvObject(id=f"o{i}", category="x", room="r", position=(x, y, z), size=(w, h, d), yaw=a))
              for i, (x, y, z, w, h, d, a) in enumerate(boxes)]
    tol = Tolerances()
    fast = collisions(bodies, tol)
    slow = collisions(bodies, tol, broad_phase=False)
    named_slow, named_fast = _named(slow), _named(fast)
    if max(named_slow.values(), default=0) < CAP:
        assert fast == slow
    key = [(f.objects, f.measured) for f in slow]
    positions = [key.index((f.objects, f.measured)) for f in fast]
    assert positions == sorted(positions)  # a subsequence, in the same order
    assert all(named_fast.get(o, 0) >= min(n, CAP) for o, n in named_slow.items())
    pairs = set(candidate_pairs(bodies))
    for f in fast:
        i, j = (int(o[1:]) for o in f.objects)
        assert (min(i, j), max(i, j)) in pairs


@settings(max_examples=60, deadline=None)
@given(a=_box, b=_box)
def test_separated_boxes_never_collide_in_fcl(a: tuple[float, ...], b: tuple[float, ...]) -> None:
    """The separating-axis prefilter only drops pairs fcl finds apart."""
    import numpy as np

    from logicenveval.physics.geometry import penetration_depth, separated

    bodies = [build_body(EnvObject(id=f"o{k}", category="x", room="r", position=(x, y, z), size=(w, h, d), yaw=t))
              for k, (x, y, z, w, h, d, t) in enumerate((a, b))]
    if separated(bodies, np.array([[0, 1]]))[0]:
        assert penetration_depth(bodies[0], bodies[1]) == 0.0


def test_candidate_pairs_match_the_all_pairs_bound_test() -> None:
    import numpy as np

    rng = np.random.default_rng(5)
    for n in (0, 1, 2, 30, 80):
        boxes = [(*rng.uniform(0, 3, 3), *rng.uniform(0.05, 1.2, 3), rng.uniform(0, 360)) for _ in range(n)]
        bodies = [build_body(EnvObject(id=f"o{i}", category="x", room="r", position=tuple(p[:3]),
                                       size=tuple(p[3:6]), yaw=float(p[6]))) for i, p in enumerate(boxes)]
        brute = [(i, j) for i in range(n) for j in range(i + 1, n)
                 if bool(np.all(bodies[i].aabb_min <= bodies[j].aabb_max) and np.all(bodies[j].aabb_min
                                                                                       <= bodies[i].aabb_max))]
        assert candidate_pairs(bodies) == brute


def test_a_pile_of_2000_objects_names_each_a_bounded_number_of_times() -> None:
    """Issue 27 item 13: 2,000 copies of one object in one place (n²/2 colliding pairs). Every
    object is still named at least `CAP` times, and the report has at most CAP x n failures
    (each reported pair moves an object that was below the cap)."""
    from logicenveval.physics.entity import MAX_COLLISIONS_PER_OBJECT as CAP

    data = _load("one_room")
    data["objects"] = [{**_obj(data, "sofa_1"), "id": f"o{i}"} for i in range(2000)]
    data["relations"], data["roles"] = [], {}
    report = check_env(env_from_dict(data))
    named = _named(report.entity.failures)
    assert set(named) == {f"o{i}" for i in range(2000)}
    assert len(report.entity.failures) <= CAP * 2000 and min(named.values()) >= CAP


def test_reference_envs_get_the_same_report_as_with_the_all_pairs_path() -> None:
    """Before/after of the broad phase on a sample of the committed reference run's environments
    (every object below the cap there): the whole report is identical to the old all-pairs path."""
    from logicenveval.envfiles import load_env
    from logicenveval.physics.geometry import clear_body_cache

    files = sorted((Path(__file__).parents[1] / "reports" / "reference" / "envs").glob("*/*/*-*.json"))
    if not files:
        pytest.skip("no committed reference run")
    for path in files[::9]:
        env = load_env(path)
        clear_body_cache()
        fast = check_env(env)
        clear_body_cache()
        assert check_env(env, broad_phase=False) == fast, path


def test_check_env_rejects_a_plain_dict() -> None:
    from logicenveval.errors import EnvSpecError

    with pytest.raises(EnvSpecError, match="needs an EnvSpec"):
        check_env(_load("one_room"))  # type: ignore[arg-type]


@pytest.mark.filterwarnings("ignore:overflow encountered:RuntimeWarning")
def test_render_leaves_out_absurdly_far_objects() -> None:
    """Found by the property below: a finite 2e306 m position overflowed the pixel maths."""
    from logicenveval.physics.render import render_svg

    data = _load("one_room")
    data["objects"][0]["position"][0] = 2.247116418577895e306
    env = env_from_dict(data)
    svg = render_svg(env, check_env(env))
    assert svg.startswith("<svg") and 'width="' in svg


_odd = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.floats(-100, 100))


@pytest.mark.filterwarnings("ignore:overflow encountered:RuntimeWarning")  # huge sizes on purpose
@pytest.mark.filterwarnings("ignore:invalid value encountered:RuntimeWarning")  # shapely on inf-sized shapes
@settings(max_examples=30, deadline=None)
@given(data_=st.data())
def test_check_env_never_raises_on_odd_numbers(data_: st.DataObject) -> None:
    """A careless generator's environment is a finding, never a crash (the runner relies on it)."""
    from logicenveval.physics.render import render_svg

    data = _load(data_.draw(st.sampled_from(["one_room", "three_rooms"])))
    for _ in range(data_.draw(st.integers(1, 4))):
        where = data_.draw(st.sampled_from(["object", "room", "door", "window", "wall"]))
        value = data_.draw(_odd)
        if where == "object":
            o = data_.draw(st.sampled_from(data["objects"]))
            field = data_.draw(st.sampled_from(["position", "size"]))
            o[field][data_.draw(st.integers(0, 2))] = value
        elif where == "room":
            r = data_.draw(st.sampled_from(data["rooms"]))
            r["polygon"][data_.draw(st.integers(0, 3))][data_.draw(st.integers(0, 1))] = value
        elif where == "door":
            data["doors"][0]["segment"][0][data_.draw(st.integers(0, 1))] = value
        elif where == "window":
            data["windows"][0][data_.draw(st.sampled_from(["sill", "height"]))] = value
        else:
            data["wall_height"] = value
    env = env_from_dict(data)
    report = check_env(env)
    assert isinstance(report.passed, bool)
    assert render_svg(env, report).startswith("<svg")


def test_rect_pairs_matches_the_all_pairs_test() -> None:
    import numpy as np

    from logicenveval.physics.geometry import rect_pairs

    rng = np.random.default_rng(3)
    for _ in range(50):
        def rects(n: int) -> list[tuple[float, float, float, float]]:
            lo = rng.uniform(0, 10, size=(n, 2))
            hi = lo + rng.uniform(0, 3, size=(n, 2))
            return [(float(a[0]), float(a[1]), float(b[0]), float(b[1])) for a, b in zip(lo, hi, strict=True)]
        a, b = rects(int(rng.integers(0, 12))), rects(int(rng.integers(0, 5)))
        a.append((float("nan"),) * 4)
        brute = sorted((i, j) for i, r in enumerate(a) for j, q in enumerate(b)
                       if r[0] <= q[2] and q[0] <= r[2] and r[1] <= q[3] and q[1] <= r[3])
        assert rect_pairs(a, b) == brute


def test_a_room_outline_shared_by_environments_is_built_once() -> None:
    """Generators lay out many environments of a task in the same rooms: the checker builds and
    buffers each outline once; a changed outline is its own polygon, with its own findings."""
    from logicenveval.physics.floorplan import room_band, valid_rooms

    data = _load("one_room")
    a, b = env_from_dict(data), env_from_dict(json.loads(json.dumps(data)))
    pa, pb = valid_rooms(a, []), valid_rooms(b, [])
    rid = next(iter(pa))
    assert pa[rid] is pb[rid]
    band = room_band(a, rid, pa[rid], 0.05, outline=True)
    assert room_band(b, rid, pb[rid], 0.05, outline=True) is band
    assert band.equals(pa[rid].exterior.buffer(0.05))
    assert room_band(a, rid, pa[rid], 0.1).equals(pa[rid].buffer(0.1))
    moved = json.loads(json.dumps(data))
    moved["rooms"][0]["polygon"] = [[x + 100.0, z] for x, z in moved["rooms"][0]["polygon"]]
    assert valid_rooms(env_from_dict(moved), [])[rid] is not pa[rid]
    assert "outside_room" in _codes(moved, "entity")


_BOX = st.tuples(*[st.floats(-50, 50, allow_nan=False)] * 4).map(
    lambda b: (min(b[0], b[2]), min(b[1], b[3]), max(b[0], b[2]), max(b[1], b[3])))


@given(st.lists(_BOX, max_size=12), _BOX)
@settings(max_examples=200, deadline=None)
def test_label_cover_is_the_sum_of_the_overlaps_to_the_last_bit(placed, box) -> None:  # type: ignore[no-untyped-def]
    """The renderer's inlined cover test places every label where the plain sum placed it."""
    from logicenveval.physics.render import _covered, _overlap

    assert _covered(box, placed) == sum(_overlap(box, b) for b in placed)
    assert _covered(box, placed) == 0 or any(_overlap(box, b) > 0 for b in placed)


def test_bodies_build_fcl_objects_only_for_pairs_the_broad_phase_keeps() -> None:
    """Two boxes apart never reach fcl, so neither builds its fcl objects; a touching pair
    does, with the same shapes as a body built alone (footprints come out of one vectorised
    step for all boxes)."""
    from logicenveval.physics.geometry import build_bodies, clear_body_cache

    objs = [EnvObject(id="a", category="x", room="r", position=(0, 0.5, 0), size=(1, 1, 1), yaw=30),
            EnvObject(id="b", category="x", room="r", position=(5, 0.5, 0), size=(1, 1, 1)),
            EnvObject(id="c", category="x", room="r", position=(0.4, 0.5, 0.2), size=(0.5, 1, 0.5), yaw=-12.5)]
    env = EnvSpec.model_validate({"task_id": "t", "env_id": "e", "rooms": [{"id": "r"}],
                                  "objects": [o.model_dump() for o in objs]})
    clear_body_cache()
    bodies = build_bodies(env)
    assert all("collision" not in b.__dict__ for b in bodies.values())
    check_env(env)
    assert {k for k, b in bodies.items() if "collision" in b.__dict__} == {"a", "c"}
    for o in objs:
        alone = build_body(o)
        assert alone.footprint.equals_exact(bodies[o.id].footprint, 0.0)
        assert list(alone.footprint.exterior.coords) == list(bodies[o.id].footprint.exterior.coords)
        assert (alone.aabb_min == bodies[o.id].aabb_min).all() and (alone.aabb_max == bodies[o.id].aabb_max).all()


def test_vectorised_room_and_door_tests_equal_the_per_body_ones() -> None:
    """`check_entities` tests all footprints against their rooms, and takes all their bounds for
    the door broad phase, in one shapely call each: the same answers as body by body."""
    from logicenveval.envfiles import load_env
    from logicenveval.physics.entity import _door_candidates, _inside_rooms, swing_areas
    from logicenveval.physics.floorplan import check_floor_plan, room_band
    from logicenveval.physics.geometry import build_bodies, rect_pairs
    from logicenveval.physics.report import DEFAULT_TOLERANCES as TOL

    files = sorted((Path(__file__).parents[1] / "reports" / "reference" / "envs").glob("*/*/*-*.json"))
    if not files:
        pytest.skip("no committed reference run")
    outside = 0
    for path in files[::5]:
        env = load_env(path)
        _, polys = check_floor_plan(env, TOL)
        grown = {rid: room_band(env, rid, poly, TOL.room_margin) for rid, poly in polys.items()}
        bodies = list(build_bodies(env).values())
        inside = _inside_rooms(bodies, grown)
        assert inside == [b.obj.room not in grown or grown[b.obj.room].contains(b.footprint) for b in bodies]
        outside += inside.count(False)
        doors = swing_areas(env)
        pairs = rect_pairs([b.footprint.bounds for b in bodies], [a.bounds for _, a in doors])
        assert _door_candidates(bodies, doors) == {
            i: [d for j, d in pairs if j == i] for i in sorted({i for i, _ in pairs})}
    assert outside  # the sample holds footprints that leave their rooms
