"""EnvSpec schema (DESIGN.md §6): JSON round trip, extra fields kept, precise errors."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from logicenveval.envfiles import env_from_dict, env_to_json, load_env
from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import EnvSpec


def example() -> dict[str, Any]:
    return {
        "schema": "logicenveval.env/1", "task_id": "clean_living_room", "generator": "hand", "env_id": "e0",
        "claimed_trajectory": {"tidy_toy": {"toy_on_floor": "yes", "toy_kind": "doll"}},
        "wall_height": 2.7,
        "rooms": [{"id": "living_room", "type": "LivingRoom", "polygon": [[0, 0], [5, 0], [5, 4], [0, 4]],
                   "floor_material": "oak"}],
        "doors": [{"id": "d0", "rooms": ["living_room", "exterior"], "segment": [[2, 0], [3, 0]],
                   "height": 2.1, "type": "door", "state": "closed"}],
        "windows": [{"id": "w0", "room": "living_room", "segment": [[0, 1], [0, 2.5]], "sill": 0.9,
                     "height": 1.2, "state": "closed"}],
        "objects": [
            {"id": "sofa_1", "category": "sofa", "room": "living_room", "position": [2.5, 0.4, 3.5],
             "yaw": 180, "size": [2.0, 0.8, 0.9], "support": "floor", "container": None,
             "attributes": {}, "states": {}},
            {"id": "toy_1", "category": "toy", "room": "living_room", "position": [1.2, 0.1, 2.0],
             "yaw": 90, "size": [0.3, 0.2, 0.2], "support": "floor", "container": None,
             "attributes": {"kind": "doll", "color": "pink"}, "states": {"dirty": False}},
        ],
        "relations": [{"type": "near", "args": ["toy_1", "sofa_1"]}],
        "roles": {"toy": "toy_1", "sofa": "sofa_1"},
        "agent": {"room": "living_room", "position": [0.5, 0.5]},
    }


def test_round_trip_is_byte_stable(tmp_path: Path) -> None:
    env = env_from_dict(example())
    text = env_to_json(env)
    again = EnvSpec.model_validate_json(text)
    assert again == env
    assert env_to_json(again) == text
    # one line per top-level field and per list item (an object, a room...), each plain JSON
    lines = text.splitlines()
    assert lines[0] == "{" and lines[-1] == "}" and lines[1] == '  "schema": "logicenveval.env/1",'
    objects = lines.index('  "objects": [')
    assert [json.loads(x.strip().rstrip(","))["id"] for x in lines[objects + 1:objects + 1 + len(env.objects)]] \
        == [o.id for o in env.objects]
    # an object's empty container, attributes, states and mesh are left out: the same EnvSpec
    assert env_from_dict(json.loads(text)) == env
    written = {o["id"]: o for o in json.loads(text)["objects"]}
    for obj in env.objects:
        left_out = {k for k in ("container", "attributes", "states", "mesh") if not getattr(obj, k)}
        assert left_out and not left_out & set(written[obj.id]) and "support" in written[obj.id]
    dumped = json.loads(text)
    assert dumped["schema"] == "logicenveval.env/1"
    assert dumped["rooms"][0]["floor_material"] == "oak"  # unknown fields are kept
    (tmp_path / "e.json").write_text(text)
    assert load_env(tmp_path / "e.json") == env


def test_geometry_is_optional() -> None:
    data = example()
    for o in data["objects"]:
        o.pop("position")
        o.pop("size")
    data["rooms"][0].pop("polygon")
    env = env_from_dict(data)
    assert env.objects[0].position is None


@pytest.mark.parametrize(
    ("mutate", "field", "fragment"),
    [
        (lambda d: d["objects"][1].update(room="kitchen"), "<root>", "room 'kitchen' is not one of"),
        (lambda d: d["objects"][1].update(support="table_9"), "<root>", "support 'table_9'"),
        (lambda d: d["roles"].update(book="book_1"), "<root>", "roles.book"),
        (lambda d: d["relations"].append({"type": "hovering", "args": ["toy_1"]}), "relations.1", "unknown relation"),
        (lambda d: d["relations"].append({"type": "near", "args": ["toy_1"]}), "relations.1", "takes 2"),
        (lambda d: d["objects"][1].update(position=[1, 2]), "objects.1.position.2", "Field required"),
        (lambda d: d.update(schema="other/2"), "schema", ""),
        (lambda d: d["objects"].append(dict(d["objects"][0])), "<root>", "repeated: ['sofa_1']"),
    ],
)
def test_errors_name_the_field(mutate: Any, field: str, fragment: str) -> None:
    data = example()
    mutate(data)
    with pytest.raises(EnvSpecError) as info:
        env_from_dict(data, source="env.json")
    text = str(info.value)
    assert "env.json" in text and f"field '{field}'" in text and fragment in text and "fix:" in text


def test_bad_json_file(tmp_path: Path) -> None:
    p = tmp_path / "bad.json"
    p.write_text("{ not json")
    with pytest.raises(EnvSpecError, match="bad.json:1"):
        load_env(p)
