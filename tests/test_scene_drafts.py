"""Generator adapters: LLM drafts → scene (solver) and → EnvSpec with the model's own coordinates."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from test_scene_layout import living_spec

from logicenveval.domain.catalog import load_catalog
from logicenveval.errors import EnvSpecError
from logicenveval.llm.replies import ObjectDraft, PlacedObject, RelationDraft
from logicenveval.physics import check_env
from logicenveval.scene.construct import (
    construct_environment,
    construct_from_drafts,
    env_from_placed,
)

CAT = load_catalog()
BRIEF = SimpleNamespace(id="clean_living_room", roles={"toy": {}, "sofa": {}, "box": {}})
ROOMS = [{"id": "living_room", "type": "LivingRoom", "area_m2": 22.0, "adjacent_to": [],
          "doors": [{"to": "exterior", "type": "door", "width": 0.9, "state": "closed"}],
          "windows": [{"wall": "e", "width": 1.0, "height": 1.2, "sill": 0.9, "state": "open"}]}]


def test_construct_from_drafts_builds_a_valid_env() -> None:
    objects = [ObjectDraft(id="sofa_1", category="Sofas", room="living_room", role="sofa", placement="floor"),
               ObjectDraft(id="box_1", category="toy_box", room="living_room", role="box", placement="floor"),
               ObjectDraft(id="toy_1", category="toy", room="living_room", role="toy", placement="inside:box_1",
                           attributes={"kind": "doll"}),
               ObjectDraft(id="lamp", category="floor_lamp", room="living_room", placement="floor")]
    relations = [RelationDraft(type="near", args=["lamp", "sofa_1"]), RelationDraft(type="edge", args=["sofa_1"])]
    res = construct_from_drafts(brief=BRIEF, env_id="e1", generator="logicenvgen", rooms=ROOMS, objects=objects,
                                relations=relations, claimed_trajectory={"tidy": {"toy_on_floor": "no"}},
                                catalog=CAT, rng=np.random.default_rng(0))
    env = res.env
    assert env.obj("sofa_1").category == "sofa"
    assert env.roles == {"sofa": "sofa_1", "box": "box_1", "toy": "toy_1"}
    assert env.obj("toy_1").attributes == {"kind": "doll"}
    assert env.windows[0].state == "open"
    assert check_env(env, CAT).passed


def test_env_from_placed_keeps_model_coordinates_and_openings() -> None:
    """No CAS: objects, doors and windows where the model put them; an opening it left out has no
    segment, which the floor-plan check reports (nothing is repaired)."""
    from logicenveval.offline.scene_answers import spread_openings
    from logicenveval.scene.construct import room_requests
    from logicenveval.scene.floorplan import plan_floor

    plan = plan_floor(room_requests(ROOMS), np.random.default_rng(0))
    requests = plan.opening_requests()
    assert [(r["id"], r["kind"]) for r in requests] == [("d0", "door"), ("w0", "window")]
    placed = [PlacedObject(id="sofa_1", category="sofa", room="living_room", role="sofa", placement="floor",
                           position=(2.0, 0.4, 1.0), size=(2.0, 0.8, 0.9), yaw=0.0)]
    segments = {o["id"]: tuple(map(tuple, o["segment"])) for o in spread_openings(requests)}
    env = env_from_placed(brief=BRIEF, env_id="e", generator="cot", plan=plan, placed=placed, relations=[],
                          openings=segments, claimed_trajectory=None, catalog=CAT)
    assert env.obj("sofa_1").position == (2.0, 0.4, 1.0) and env.roles == {"sofa": "sofa_1"}
    assert env.doors[0].segment == segments["d0"] and env.windows[0].segment == segments["w0"]
    assert check_env(env, CAT).floor_plan.passed
    env = env_from_placed(brief=BRIEF, env_id="e", generator="cot", plan=plan, placed=placed, relations=[],
                          openings={"d0": segments["d0"]}, claimed_trajectory=None, catalog=CAT)
    assert [(f.code, f.objects) for f in check_env(env, CAT).floor_plan.failures] == [("missing_geometry", ["w0"])]


def test_unknown_solver_is_rejected() -> None:
    with pytest.raises(EnvSpecError, match="solver"):
        construct_environment(living_spec(0), catalog=CAT, rng=np.random.default_rng(0), solver="gurobi")  # type: ignore[arg-type]
