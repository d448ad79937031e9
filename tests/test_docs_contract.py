"""The user-facing contract lives in the repo: the examples of docs/envspec.md and
docs/task-format.md load and match the schemas, and no doc sends a reader outside the repo."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from jsonschema import Draft202012Validator

from logicenveval.envfiles import env_from_dict
from logicenveval.model.task import task_from_dict
from logicenveval.physics import check_env
from logicenveval.schemas import json_schema

ROOT = Path(__file__).resolve().parents[1]
USER_DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")), *sorted((ROOT / "examples").rglob("*.md"))]


def _json_blocks(doc: str) -> list[dict[str, object]]:
    text = (ROOT / "docs" / doc).read_text()
    return [json.loads(block) for block in re.findall(r"```json\n(.*?)```", text, re.S)]


def test_envspec_examples_load_validate_and_the_full_one_is_plausible() -> None:
    full, symbolic = _json_blocks("envspec.md")
    validator = Draft202012Validator(json_schema("envspec"))
    for data in (full, symbolic):
        assert not list(validator.iter_errors(data))
        env_from_dict(data)
    report = check_env(env_from_dict(full))
    assert report.passed and report.extended.passed, report


def test_task_example_is_a_valid_task() -> None:
    (data,) = _json_blocks("task-format.md")
    assert not list(Draft202012Validator(json_schema("task")).iter_errors(data))
    task = task_from_dict(data)
    assert [s.id for s in task.subtasks] == ["tidy_toy"]


@pytest.mark.parametrize("path", USER_DOCS, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_doc_sends_the_reader_outside_the_repo(path: Path) -> None:
    text = path.read_text()
    assert "DESIGN.md" not in text and "shared/" not in text
    for ref in re.findall(r"docs/[A-Za-z_.-]+\.md", text):
        assert (ROOT / ref).is_file(), f"{path.name} names {ref}, which does not exist"
