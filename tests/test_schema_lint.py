"""The contract in the repo: JSON Schemas generated from the models (docs/schemas/), and `lint`."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import pytest
from jsonschema import Draft202012Validator

from logicenveval.benchmark import DEFAULT_TASKS_DIR
from logicenveval.cli import main
from logicenveval.metrics.results_file import ResultsFile
from logicenveval.runner.score_envs import ARTEFACTS
from logicenveval.schemas import DOCS_DIR, SCHEMAS, json_schema, schema_text

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = ROOT / "reports" / "reference"


def _validator(name: str) -> Draft202012Validator:
    schema = json_schema(name)
    Draft202012Validator.check_schema(schema)
    return Draft202012Validator(schema)


@pytest.mark.parametrize("name", sorted(SCHEMAS))
def test_committed_schemas_are_current(name: str) -> None:
    committed = (DOCS_DIR / f"{name}.schema.json").read_text()
    assert committed == schema_text(name), (
        f"docs/schemas/{name}.schema.json is stale: python -m logicenveval schema {name} "
        f"--out docs/schemas/{name}.schema.json")


def test_every_envspec_field_is_described() -> None:
    """A tool writing EnvSpecs from the schema alone learns what each field means and its unit."""
    schema = json_schema("envspec")
    missing = [f"{name}.{field}" for name, part in [("EnvSpec", schema), *schema["$defs"].items()]
               for field, prop in part.get("properties", {}).items() if not prop.get("description")]
    assert missing == []
    assert "metres" in schema["$defs"]["EnvObject"]["properties"]["position"]["description"]


def test_schema_command_prints_the_committed_text(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["schema", "envspec"]) == 0
    assert capsys.readouterr().out == (DOCS_DIR / "envspec.schema.json").read_text()
    with pytest.raises(SystemExit) as info:
        main(["schema", "nonsense"])
    assert info.value.code == 2


def test_envspec_schema_validates_every_reference_environment() -> None:
    validator = _validator("envspec")
    files = [p for p in (REFERENCE / "envs").rglob("*.json") if p.name not in ARTEFACTS]
    assert len(files) > 600
    for path in files:
        errors = list(validator.iter_errors(json.loads(path.read_text())))
        assert not errors, (path, errors[0].message)


@pytest.mark.parametrize(("edit", "needle"), [
    (lambda d: d.pop("rooms"), "'rooms' is a required property"),
    (lambda d: d["objects"][0].update(position=[1, 2]), "[1, 2]"),
    (lambda d: d["doors"][0].update(state="ajar"), "'ajar'"),
    (lambda d: d.update(schema="logicenveval.env/2"), "logicenveval.env/1"),
])
def test_envspec_schema_rejects_what_the_loader_rejects(edit: Any, needle: str) -> None:
    data = json.loads((ROOT / "tests" / "fixtures" / "envs" / "one_room.json").read_text())
    edit(data)
    messages = [e.message for e in _validator("envspec").iter_errors(data)]
    assert any(needle in m for m in messages), messages


def test_task_schema_validates_every_benchmark_task() -> None:
    validator = _validator("task")
    for path in sorted(DEFAULT_TASKS_DIR.glob("*/task.json")):
        assert not list(validator.iter_errors(json.loads(path.read_text()))), path


def test_results_schema_and_model_hold_the_reference_results() -> None:
    data = json.loads((REFERENCE / "results.json").read_text())
    assert not list(_validator("results").iter_errors(data))
    results = ResultsFile.model_validate(data)
    assert set(results.results) >= {"logicenvgen", "cot"} and results.per_task is not None
    broken = dict(data, results={"cot": {**data["results"]["cot"], "logcov": "high"}})
    assert list(_validator("results").iter_errors(broken))


# ----- lint ---------------------------------------------------------------------------------

TASK = "clean_living_room"


def _folder(tmp_path: Path) -> Path:
    """Three of the reference run's clean_living_room environments (LogicEnvGen's, then
    logicenvgen-exact's), roles removed (to be bound)."""
    folder = tmp_path / "envs" / TASK
    folder.mkdir(parents=True)
    paths = [p for gen in ("logicenvgen", "logicenvgen-exact")
             for p in sorted((REFERENCE / "envs" / gen / TASK).glob(f"{gen}-[0-9]*.json"))]
    for path in paths[:3]:
        data = json.loads(path.read_text())
        data.pop("roles")
        (folder / path.name).write_text(json.dumps(data))
    return folder


def _edit(path: Path, edit: Any) -> None:
    data = json.loads(path.read_text())
    edit(data)
    path.write_text(json.dumps(data))


def test_lint_passes_clean_files_and_names_the_unbound_role(tmp_path: Path,
                                                            capsys: pytest.CaptureFixture[str]) -> None:
    folder = _folder(tmp_path)
    assert main(["lint", str(folder.parent)]) == 0
    assert "3 of 3 file(s) without problems" in capsys.readouterr().out
    first, second, third = sorted(folder.glob("*.json"))

    def no_mop(d: dict[str, Any]) -> None:
        d["objects"] = [o for o in d["objects"] if o["category"] != "mop"]

    _edit(first, no_mop)
    def two_sofas(d: dict[str, Any]) -> None:
        """Two sofas, neither with the role's name as its id (that one would play it)."""
        sofa = next(o for o in d["objects"] if o["category"] == "sofa")
        d["objects"].append({**sofa, "id": "sofa_2", "category": "Couch"})
        for o in d["objects"]:
            o.update({k: "couch_a" for k in ("support", "container") if o.get(k) == sofa["id"]})
        for r in d.get("relations", []):
            r["args"] = ["couch_a" if a == sofa["id"] else a for a in r["args"]]
        sofa["id"] = "couch_a"

    _edit(second, two_sofas)

    def on_the_toy(d: dict[str, Any]) -> None:
        book = next(o for o in d["objects"] if o["category"] == "book")
        book["support"] = next(o["id"] for o in d["objects"] if o["category"] == "mop")
        d["objects"].append({"id": "thing", "category": "Kayak", "room": d["rooms"][0]["id"]})
        d["roles"] = {"sofa": next(o["id"] for o in d["objects"] if o["category"] == "book")}

    _edit(third, on_the_toy)
    assert main(["lint", str(folder.parent)]) == 1
    out = capsys.readouterr().out
    assert "binding: role mop is not bound to an object and no reached path allows it" in out
    assert "binding: role sofa is ambiguous: 2 objects qualify" in out and "sofa_2" in out
    assert "which is not a surface" in out and "role sofa is mapped to" in out
    assert "note (category): category 'Kayak' names no catalog category" in out
    assert "0 of 3 file(s) without problems" in out
    assert main(["lint", str(folder.parent), "--json"]) == 1
    listed = json.loads(capsys.readouterr().out)
    assert [len(f["problems"]) > 0 for f in listed] == [True, True, True]


def test_lint_bad_input_exits_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["lint", str(tmp_path / "missing")]) == 2
    (tmp_path / "not_a_task").mkdir()
    assert main(["lint", str(tmp_path)]) == 2
    assert "no folder named after a task" in capsys.readouterr().err
    folder = tmp_path / TASK
    folder.mkdir()
    (folder / "broken.json").write_text("{")
    shutil.copy(REFERENCE / "envs" / "cot" / "multi_room_trash_run" / "cot-00.json", folder / "other.json")
    assert main(["lint", str(tmp_path)]) == 1
    out = capsys.readouterr().out
    assert "file: not a valid EnvSpec" in out and "task_id 'multi_room_trash_run'" in out


def test_schema_words_in_states_are_a_problem_of_the_environment(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Qwen2.5-Coder-1.5B's scenes carried `"states": {"additionalProperties": false}`: `lint`
    names the object and the flag, and `evaluate` counts the environment ill-formed."""
    from logicenveval.model.envspec import unknown_state_flags

    folder = _folder(tmp_path)
    first = sorted(folder.glob("*.json"))[0]

    def schema_words(d: dict[str, Any]) -> None:
        d["objects"][0]["states"] = {"additionalProperties": False, "dirty": True}

    _edit(first, schema_words)
    assert main(["lint", str(folder.parent)]) == 1
    out = capsys.readouterr().out
    assert "states: object" in out and "unknown state flag(s) ['additionalProperties']" in out
    assert "2 of 3 file(s) without problems" in out
    out_dir = tmp_path / "scored"
    assert main(["evaluate", str(folder.parent), "--output", str(out_dir), "--run-id", "x", "--executor", "inprocess"]) in (0, 1)
    samples = [json.loads(line) for line in (out_dir / "x" / "samples.jsonl").read_text().splitlines()]
    bad = [s for s in samples if s["env_id"] == json.loads(first.read_text())["env_id"]]
    assert len(bad) == 1 and not bad[0]["well_formed"]
    assert any("additionalProperties" in p for p in bad[0]["problems"])
    assert all(s["well_formed"] for s in samples if s is not bad[0])
    from logicenveval.envfiles import load_env

    assert unknown_state_flags(load_env(sorted(folder.glob("*.json"))[1])) == []
