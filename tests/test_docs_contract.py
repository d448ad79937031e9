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


README = ROOT / "README.md"


def _quick_start() -> list[str]:
    text = README.read_text()
    section = text[text.index("## Quick start"):]
    block = re.search(r"```bash\n(.*?)```", section, re.S)
    assert block is not None, "the README's quick start has no bash block"
    return [line for line in block.group(1).splitlines() if line.strip()]


def test_readme_is_short_and_has_a_contents_list_whose_links_resolve() -> None:
    """A newcomer's page (issue 48): under 15 KB, a contents list, every section it names there."""
    text = README.read_text()
    assert len(text.encode()) < 15_000, f"README.md is {len(text.encode())} bytes"
    headings = {re.sub(r"[^\w\- ]", "", h).strip().lower().replace(" ", "-")
                for h in re.findall(r"^## (.+)$", text, re.M)}
    contents = text[text.index("**Contents:**"):].split("\n\n")[0]
    anchors = re.findall(r"\]\(#([\w-]+)\)", contents)
    assert len(anchors) >= 6 and set(anchors) <= headings, (anchors, headings)
    for ref in re.findall(r"`((?:docs|reports|benchmarks|examples|tools)/[\w./<>-]*|CHANGELOG\.md)`", text):
        path = ref.split("<")[0]
        assert (ROOT / path).exists(), f"README.md names {ref}, which does not exist"


def test_quick_start_runs_with_the_plain_install_and_tests_with_dev() -> None:
    run, test = _quick_start()
    assert run == "pip install -e . && python -m logicenveval run --model offline"
    assert test == "pip install -e '.[dev]' && python -m pytest -q"


def test_ci_runs_exactly_the_readmes_test_command() -> None:
    _, test = _quick_start()
    install, pytest_cmd = (part.strip() for part in test.split("&&"))
    ci = [line.strip() for line in (ROOT / ".ci" / "run").read_text().splitlines()]
    assert install in ci and pytest_cmd in ci
    assert ci.index(install) < ci.index(pytest_cmd)
