"""`check-env` exit codes and output, and the deterministic renders."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from PIL import Image

from logicenveval.cli import main
from logicenveval.envfiles import env_from_dict, load_env
from logicenveval.physics import check_env
from logicenveval.physics.render import render_png, render_svg

FIXTURES = Path(__file__).parent / "fixtures" / "envs"


def _write(tmp_path: Path, data: dict[str, Any], name: str = "broken.json") -> Path:
    out = tmp_path / name
    out.write_text(json.dumps(data))
    return out


def _broken(tmp_path: Path) -> Path:
    data = json.loads((FIXTURES / "one_room.json").read_text())
    next(o for o in data["objects"] if o["id"] == "floor_lamp_1")["position"][1] += 0.3  # floating
    return _write(tmp_path, data)


def test_valid_env_exits_zero_with_json(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check-env", str(FIXTURES / "one_room.json"), "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report == {d: {"passed": True, "failures": []}
                      for d in ("floor_plan", "entity", "relation", "extended")}


def test_failing_env_exits_one_and_names_the_fault(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("COLUMNS", "160")
    assert main(["check-env", str(_broken(tmp_path))]) == 1
    out = capsys.readouterr().out
    assert "not_supported" in out and "FAIL" in out


def _beside_table(data: dict[str, Any]) -> None:
    """The audit's case: an item 0.3 m beside its table, bottom still at the table's top."""
    book = next(o for o in data["objects"] if o["id"] == "book_1")
    book["position"][2] = 2.2 + 0.3 + 0.3  # the coffee table's top ends 0.3 m from its centre
    data["relations"] = [r for r in data["relations"] if "book_1" not in r["args"]]


def _window_through_ceiling(data: dict[str, Any]) -> None:
    data["windows"][0].update(sill=1.0, height=2.2)  # top 3.2 m in a 2.7 m wall


@pytest.mark.parametrize(("flaw", "dimension", "code"), [(_beside_table, "entity", "centre_off_support"),
                                                         (_window_through_ceiling, "floor_plan",
                                                          "window_above_ceiling")])
def test_table2_violations_fail_their_dimension(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                flaw: Callable[[dict[str, Any]], None], dimension: str,
                                                code: str) -> None:
    data = json.loads((FIXTURES / "one_room.json").read_text())
    flaw(data)
    assert main(["check-env", str(_write(tmp_path, data)), "--json"]) == 1
    report = json.loads(capsys.readouterr().out)
    assert {d for d, r in report.items() if not r["passed"]} == {dimension}
    assert [f["code"] for f in report[dimension]["failures"]] == [code]


def _chair_in_doorway(data: dict[str, Any]) -> None:
    data["objects"].append({"id": "chair_1", "category": "chair", "room": "living_room",
                            "position": [2.5, 0.45, 0.5], "yaw": 0, "size": [0.5, 0.9, 0.5],
                            "support": "floor"})


def _short_book(data: dict[str, Any]) -> None:
    next(o for o in data["objects"] if o["id"] == "book_1")["size"] = [0.2, 0.04, 0.15]


@pytest.mark.parametrize(("flaw", "code"), [(_chair_in_doorway, "blocks_door"), (_short_book, "size_out_of_range")])
def test_extra_check_failure_leaves_the_paper_dimensions_passing(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], flaw: Callable[[dict[str, Any]], None],
        code: str) -> None:
    data = json.loads((FIXTURES / "one_room.json").read_text())
    flaw(data)
    path = _write(tmp_path, data)
    assert main(["check-env", str(path), "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert all(report[d] == {"passed": True, "failures": []} for d in ("floor_plan", "entity", "relation"))
    assert report["extended"]["passed"] is False
    assert [f["code"] for f in report["extended"]["failures"]] == [code]
    assert main(["check-env", str(path), "--strict"]) == 1
    assert code in capsys.readouterr().out


def test_malformed_file_exits_two_with_field_path(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data = json.loads((FIXTURES / "one_room.json").read_text())
    data["objects"][0]["position"] = [1, 2]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(data))
    assert main(["check-env", str(bad)]) == 2
    assert "objects.0.position" in capsys.readouterr().err


def test_render_svg_is_deterministic_and_highlights_failures(tmp_path: Path) -> None:
    env = load_env(_broken(tmp_path))
    report = check_env(env)
    svg = render_svg(env, report)
    assert svg == render_svg(env, report)
    assert svg.startswith("<svg") and ">sofa</text>" in svg and ">toy_box_1</text>" in svg
    # the legend's "named by a failure" swatch is red in both; only the failing render outlines shapes
    assert svg.count('stroke="#d62728"') > render_svg(env).count('stroke="#d62728"') == 1


def test_render_is_seen_from_above_with_legend_scale_and_axes() -> None:
    """docs/envspec.md: y up, floor x-z in AI2-THOR's frame; seen from above +z points up the page."""
    import re

    data = json.loads((FIXTURES / "one_room.json").read_text())
    (first, *_rest) = data["objects"]
    low = {**first, "id": "low_one", "position": [first["position"][0], first["position"][1], 0.6]}
    high = {**first, "id": "high_one", "position": [first["position"][0], first["position"][1], 2.4]}
    data["objects"] = [low, high]
    data["roles"] = {}
    svg = render_svg(env_from_dict(data))

    def label_y(name: str) -> float:
        m = re.search(rf'<text x="[^"]+" y="([^"]+)"[^>]*>{name}</text>', svg)
        assert m, name
        return float(m.group(1))

    assert label_y("high_one") < label_y("low_one")  # larger z is higher on the page
    for text in (">+x</text>", ">+z</text>", ">1 m</text>", ">named by a failure</text>", ">window</text>"):
        assert text in svg


def test_render_png_via_cli(tmp_path: Path) -> None:
    out_a, out_b = tmp_path / "a.png", tmp_path / "b.png"
    assert main(["check-env", str(FIXTURES / "three_rooms.json"), "--render", str(out_a)]) == 0
    render_png(load_env(FIXTURES / "three_rooms.json"), out_b, check_env(load_env(FIXTURES / "three_rooms.json")))
    assert out_a.read_bytes() == out_b.read_bytes()
    with Image.open(out_a) as img:
        assert img.size[0] > 300 and img.size[1] > 300
        assert len(img.getcolors(maxcolors=100000) or []) > 3
    assert main(["check-env", str(FIXTURES / "three_rooms.json"), "--render", str(tmp_path / "x.gif")]) == 2


def test_env_without_geometry_fails_entity(tmp_path: Path) -> None:
    env = env_from_dict({"task_id": "t", "env_id": "e", "rooms": [{"id": "r", "polygon": [[0, 0], [3, 0], [3, 3]]}],
                         "objects": [{"id": "a", "category": "toy", "room": "r"}]})
    report = check_env(env)
    assert report.floor_plan.passed and not report.entity.passed and report.relation.passed


def test_table_shows_a_bounded_number_of_failures(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    from logicenveval.commands.check_env import TABLE_ROWS

    monkeypatch.setenv("COLUMNS", "200")
    data = json.loads((FIXTURES / "one_room.json").read_text())
    sofa = next(o for o in data["objects"] if o["id"] == "sofa_1")
    data["objects"] = [{**sofa, "id": f"o{i}"} for i in range(30)]  # a pile: 30 x 8 / 2 > TABLE_ROWS pairs
    data["relations"], data["roles"] = [], {}
    path = _write(tmp_path, data)
    assert main(["check-env", str(path)]) == 1
    out = capsys.readouterr().out
    n = len(check_env(load_env(path)).entity.failures)
    assert n > TABLE_ROWS and f"{n - TABLE_ROWS} more failures" in out
    assert out.count("interpenetrate") == TABLE_ROWS
