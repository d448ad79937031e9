"""ProcTHOR house export against ProcTHOR's database format: a small database in that format is
built here (the real one is not shipped); the export uses only ids, holes and materials that the
database has, and `check-house` finds each kind of problem."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from test_scene_layout import living_spec

from logicenveval.cli import main
from logicenveval.domain.catalog import load_catalog
from logicenveval.envfiles import env_to_json
from logicenveval.errors import ConfigError
from logicenveval.scene.construct import construct_environment
from logicenveval.scene.export import to_procthor
from logicenveval.scene.house_check import check_house
from logicenveval.scene.procthor import (
    AI2THOR_ROOM_TYPES,
    choose_assets,
    load_mapping,
    load_procthor_db,
    mapping_db,
)

CAT = load_catalog()
ENV = construct_environment(living_spec(3), catalog=CAT, rng=np.random.default_rng(5)).env


def _asset(aid: str, otype: str, size: tuple[float, float, float], prop: str = "Static") -> dict[str, Any]:
    return {"assetId": aid, "objectType": otype, "primaryProperty": prop,
            "boundingBox": {"x": size[0], "y": size[1], "z": size[2]}}


def _hole(w: float, h: float) -> dict[str, Any]:
    return {"min": {"x": 0, "y": 0, "z": 0}, "max": {"x": w, "y": h, "z": 0.07},
            "offset": {"x": -0.001, "y": 0.0, "z": 0.02}}


def tiny_db(folder: Path) -> Path:
    """A database in ProcTHOR's format: two sofas, a book, a ball, a painting, openings."""
    assets = {
        "Sofa": [_asset("Sofa_small", "Sofa", (1.5, 0.8, 0.8)), _asset("Sofa_big", "Sofa", (2.4, 0.9, 1.0))],
        "Book": [_asset("Book_1", "Book", (0.2, 0.04, 0.25), "CanPickup")],
        "BasketBall": [_asset("Ball_1", "BasketBall", (0.24, 0.24, 0.24), "CanPickup")],
        "Bed": [_asset("Bed_1", "Bed", (1.4, 0.6, 2.0))],
        "Painting": [_asset("Photo_1", "Painting", (0.5, 0.4, 0.03))],
        "Doorframe": [_asset("Doorframe_1", "Doorframe", (1.0, 2.07, 0.1)),
                      _asset("Doorframe_Double_1", "Doorframe", (1.9, 2.07, 0.1))],
        "Doorway": [_asset("Doorway_1", "Doorway", (1.0, 2.07, 0.1)),
                    _asset("Doorway_Double_1", "Doorway", (1.9, 2.07, 0.1))],
        "Window": [_asset("Window_A", "Window", (0.9, 1.2, 0.1)), _asset("Window_B", "Window", (1.5, 1.2, 0.1))],
    }
    holes = {"Doorway_1": _hole(0.99, 2.07), "Doorway_Double_1": _hole(1.9, 2.07),
             "Window_A": _hole(0.9, 1.2), "Window_B": _hole(1.5, 1.2)}
    mats = {"Wall": ["Drywall", "PureWhite"], "Wood": ["DarkWoodFloors"]}
    folder.mkdir(parents=True, exist_ok=True)
    for name, data in (("asset-database.json", assets), ("wall-holes.json", holes),
                       ("material-database.json", mats)):
        (folder / name).write_text(json.dumps(data), encoding="utf-8")
    return folder


def tiny_mapping(db_dir: Path) -> dict[str, Any]:
    m = choose_assets(CAT, load_procthor_db(db_dir))
    return {**m, "materials": {"floor": "DarkWoodFloors", "wall": "Drywall", "ceiling": "PureWhite"}}


def test_choice_prefers_the_type_then_the_closest_size(tmp_path: Path) -> None:
    m = choose_assets(CAT, load_procthor_db(tiny_db(tmp_path)))
    # catalog sofa: mean 2.0 x 0.85 x 0.9 m, closer to the 2.4 m sofa than to the 1.5 m one
    assert m["categories"]["sofa"] == {"assetId": "Sofa_big", "objectType": "Sofa",
                                       "size": [2.4, 0.9, 1.0], "standIn": False}
    assert m["categories"]["toy"]["standIn"] and m["categories"]["toy"]["assetId"] in {"Ball_1", "Book_1"}
    assert m["categories"]["mirror"]["assetId"] == "Photo_1"  # wall-mounted stand-in
    assert set(m["openings"]["door"]) == {"Doorframe_1", "Doorframe_Double_1"}


def test_export_passes_check_house_against_the_database(tmp_path: Path) -> None:
    db_dir = tiny_db(tmp_path / "db")
    house = to_procthor(ENV, CAT, tiny_mapping(db_dir))
    report = check_house(house, load_procthor_db(db_dir))
    assert report.passed, report.problems
    assert report.assets == len(ENV.objects) + len(ENV.doors) + len(ENV.windows)
    assert all(r["roomType"] in AI2THOR_ROOM_TYPES for r in house["rooms"])
    assert house["metadata"]["agentPoses"]["default"]["position"]["y"] == 0.95
    for d in house["doors"] + house["windows"]:
        lo, hi = d["holePolygon"]
        assert d["assetId"] in {"Doorframe_1", "Doorframe_Double_1", "Doorway_1", "Doorway_Double_1",
                                "Window_A", "Window_B"}
        assert hi["x"] > lo["x"] >= -0.01 and hi["y"] > lo["y"]


def test_check_house_finds_each_problem(tmp_path: Path) -> None:
    db_dir = tiny_db(tmp_path / "db")
    db = load_procthor_db(db_dir)
    house = to_procthor(ENV, CAT, tiny_mapping(db_dir))
    house["objects"][0]["assetId"] = "Toy|toy"
    house["objects"][1]["isToggled"] = True
    house["rooms"][0]["floorMaterial"] = {"name": "WoodFloor"}
    house["rooms"][0]["roomType"] = "Study"
    house["windows"][0]["assetId"] = "Window_1"
    house["doors"][0]["wall0"] = "wall|nowhere"
    house["objects"][2]["room"] = "attic"
    del house["metadata"]["agentPoses"]
    report = check_house(house, db)
    where = {p.where for p in report.problems}
    assert {"objects[0].assetId", "objects[1].isToggled", "rooms[0].floorMaterial", "rooms[0].roomType",
            "windows[0].assetId", "doors[0].wall0", "objects[2].room", "metadata.agentPoses"} <= where
    assert report.unknown_ids == 2 and report.unknown_materials == 1


def test_shipped_mapping_covers_the_catalog_and_checks_itself() -> None:
    m = load_mapping()
    assert set(m["categories"]) == set(CAT.categories)
    assert "procthor" in m["source"] and "Apache" in m["licence"]
    report = check_house(to_procthor(ENV, CAT), mapping_db(m))
    assert report.passed and report.against.startswith("our mapping")


def test_room_types_outside_procthor_are_mapped_and_kept() -> None:
    env = ENV.model_copy(update={"rooms": [ENV.rooms[0].model_copy(update={"type": "Study"}),
                                           *ENV.rooms[1:]]})
    room = to_procthor(env, CAT)["rooms"][0]
    assert room["roomType"] == "Bedroom" and room["logicenvevalRoomType"] == "Study"


def test_cli_export_and_check_house(tmp_path: Path, capsys: pytest.CaptureFixture[str], no_procthor: None) -> None:
    env_file = tmp_path / "env.json"
    env_file.write_text(env_to_json(ENV), encoding="utf-8")
    house, glb, model = tmp_path / "h.house.json", tmp_path / "e.glb", tmp_path / "m.xml"
    assert main(["export", str(env_file), "--format", "procthor", "--out", str(house)]) == 0
    assert main(["export", str(env_file), "--format", "glb", "--out", str(glb)]) == 0
    assert main(["export", "--format", "bt-model", "--out", str(model)]) == 0
    assert glb.read_bytes()[:4] == b"glTF" and "<TreeNodesModel>" in model.read_text()
    assert main(["check-house", str(house)]) == 0
    assert "our recorded mapping only" in capsys.readouterr().out
    db_dir = tiny_db(tmp_path / "db")
    assert main(["check-house", str(house), "--procthor-db", str(db_dir)]) == 1  # other ids
    bad = json.loads(house.read_text())
    bad["objects"][0]["assetId"] = "nope"  # our mapping cannot say it is not ProcTHOR's: a warning
    house.write_text(json.dumps(bad))
    capsys.readouterr()
    assert main(["check-house", str(house)]) == 0
    assert "'nope' is not in our mapping" in capsys.readouterr().out
    bad["objects"][0]["position"]["x"] = float("nan")
    house.write_text(json.dumps(bad))
    assert main(["check-house", str(house)]) == 1
    assert "objects[0].position.x: not a finite number" in capsys.readouterr().out
    assert main(["check-house", str(tmp_path / "missing.json")]) == 2
    with pytest.raises(ConfigError):
        load_procthor_db(tmp_path)
