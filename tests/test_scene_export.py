"""Exporters: ProcTHOR-style house JSON and GLB; spec JSON round trips."""

from __future__ import annotations

import io
import json

import numpy as np
import trimesh
from test_scene_layout import living_spec

from logicenveval.domain.catalog import load_catalog
from logicenveval.scene.construct import construct_environment
from logicenveval.scene.export import _colour, _wall_pieces, to_glb, to_procthor
from logicenveval.scene.spec import SceneResult, SceneSpec

CAT = load_catalog()


def _result() -> SceneResult:
    return construct_environment(living_spec(3), catalog=CAT, rng=np.random.default_rng(5))


def test_procthor_house_structure() -> None:
    env = _result().env
    house = to_procthor(env, CAT)
    json.dumps(house)
    wall_ids = {w["id"] for w in house["walls"]}
    assert {r["id"] for r in house["rooms"]} == {r.id for r in env.rooms}
    assert all(len(r["floorPolygon"]) == 4 for r in house["rooms"])
    for d in house["doors"] + house["windows"]:
        assert d["wall0"] in wall_ids and d["wall1"] in wall_ids
        lo, hi = d["holePolygon"]
        assert hi["x"] > lo["x"] and hi["y"] > lo["y"]
    flat = []
    stack = list(house["objects"])
    while stack:
        o = stack.pop()
        flat.append(o)
        stack += o["children"]
    assert {o["id"] for o in flat} == {o.id for o in env.objects}
    sofa = next(o for o in flat if o["id"] == "sofa_1")
    assert sofa["objectType"] == "Sofa"
    table = next(o for o in flat if o["id"] == "table_1")
    assert [c["id"] for c in table["children"]] == ["book_1"]


def test_glb_loads_back_with_objects_floors_and_walls_with_openings() -> None:
    env = _result().env
    data = to_glb(env)
    scene = trimesh.load(io.BytesIO(data), file_type="glb")
    assert isinstance(scene, trimesh.Scene)
    names = set(scene.graph.nodes_geometry)
    assert {o.id for o in env.objects} <= names
    assert len(names) == len(env.objects) + len(env.rooms) + 1  # one mesh holds every wall piece
    pieces = _wall_pieces(env)
    walls = scene.geometry[scene.graph["walls"][1]]
    assert len(walls.faces) == 12 * len(pieces) and walls.is_winding_consistent and walls.volume > 0
    # every door leaves a gap from the floor to its height: only a lintel above it
    for d in env.doors:
        assert d.segment is not None
        mid = ((d.segment[0][0] + d.segment[1][0]) / 2, (d.segment[0][1] + d.segment[1][1]) / 2)
        covering = [(y0, y1) for (p0, p1), y0, y1 in pieces
                    if _on_segment(mid, p0, p1)]
        assert covering and all(y0 >= d.height - 1e-6 for y0, _ in covering)
    for w in env.windows:
        assert w.segment is not None
        mid = ((w.segment[0][0] + w.segment[1][0]) / 2, (w.segment[0][1] + w.segment[1][1]) / 2)
        spans = sorted((y0, y1) for (p0, p1), y0, y1 in pieces if _on_segment(mid, p0, p1))
        assert spans == [(0.0, w.sill), (w.sill + w.height, env.wall_height)]
    floor, wall = _colour("sofa"), _colour("toy")
    assert floor != wall  # per-category colours


def _on_segment(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> bool:
    cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    inside = min(a[0], b[0]) - 1e-6 <= p[0] <= max(a[0], b[0]) + 1e-6 and \
        min(a[1], b[1]) - 1e-6 <= p[1] <= max(a[1], b[1]) + 1e-6
    return abs(cross) < 1e-6 and inside


def test_spec_and_result_json_round_trip() -> None:
    spec = living_spec(2)
    assert SceneSpec.model_validate_json(spec.model_dump_json()) == spec
    res = _result()
    again = SceneResult.model_validate_json(res.model_dump_json(by_alias=True))
    assert again.env.to_json_dict() == res.env.to_json_dict()
    assert again.relaxation_log == res.relaxation_log
