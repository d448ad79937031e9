"""A replay pack replays with the README's command as written (issue 46, item 8): `replay:` of
a run folder's reply cache asks what that run asked, its brief and request protocol, whatever
the defaults became since; what the command line says still wins."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from logicenveval.runner.config import RunConfig, recorded_setup

REPO = Path(__file__).resolve().parents[1]
SMOL = REPO / "reports" / "real" / "SmolLM2-135M-Instruct.Q4_1"


def _folder(tmp_path: Path, results: dict[str, object] | None, config: dict[str, object] | None) -> str:
    if results is not None:
        (tmp_path / "results.json").write_text(json.dumps(results), encoding="utf-8")
    if config is not None:
        (tmp_path / "config.json").write_text(json.dumps(config), encoding="utf-8")
    return f"replay:{tmp_path / 'llm_cache.sqlite'}"


def test_the_recorded_brief_and_protocol_are_read_from_the_run_folder(tmp_path: Path) -> None:
    spec = _folder(tmp_path, {"protocol": 3, "config": {"brief": "roles", "model_args": "protocol=2"}}, None)
    assert (recorded_setup(spec).brief, recorded_setup(spec).protocol) == ("roles", 3)  # type: ignore[union-attr]
    config = RunConfig(model=spec)
    assert config.brief == "roles" and config.model_args == "protocol=3"


def test_the_protocol_falls_back_to_the_model_argument_then_to_1(tmp_path: Path) -> None:
    spec = _folder(tmp_path, None, {"brief": "description", "model_args": "threads=2, protocol = 4"})
    assert RunConfig(model=spec, model_args="threads=2").model_args == "threads=2,protocol=4"
    (tmp_path / "config.json").write_text(json.dumps({"brief": "roles", "model_args": "threads=1"}))
    assert RunConfig(model=spec).model_args == "protocol=1"  # recorded before protocols were named


def test_the_command_line_wins_over_the_recorded_setup(tmp_path: Path) -> None:
    spec = _folder(tmp_path, {"protocol": 3, "config": {"brief": "roles"}}, None)
    config = RunConfig(model=spec, brief="description", model_args="protocol=4")
    assert config.brief == "description" and config.model_args == "protocol=4"


@pytest.mark.parametrize("junk", ["", "{", "[]", '{"config": {"brief": "everything"}}'])
def test_anything_else_keeps_the_defaults(tmp_path: Path, junk: str) -> None:
    (tmp_path / "results.json").write_text(junk, encoding="utf-8")
    spec = f"replay:{tmp_path / 'llm_cache.sqlite'}"
    assert recorded_setup(spec) is None
    assert RunConfig(model=spec).brief == "description" and RunConfig(model=spec).model_args == ""
    assert recorded_setup("offline") is None and RunConfig(model="oracle").brief == "roles"


@pytest.mark.skipif(not (SMOL / "llm_cache.sqlite").is_file(), reason="the SmolLM2 pack is not committed")
def test_the_readme_replay_command_reproduces_the_pack_as_written(tmp_path: Path) -> None:
    """No --brief, no --model-args: the command the README gives, on the pack's own tasks."""
    sys.path.insert(0, str(REPO / "benchmarks"))
    from llm_validity import same_metrics  # type: ignore[import-not-found]

    recorded = json.loads((SMOL / "results.json").read_text(encoding="utf-8"))
    done = subprocess.run(
        [sys.executable, "-m", "logicenveval", "run", "--model", f"replay:{SMOL / 'llm_cache.sqlite'}",
         "--tasks", ",".join(recorded["tasks"]), "--generators", ",".join(recorded["generators"]),
         "--output", str(tmp_path), "--run-id", "replayed", "--quiet"],
        capture_output=True, text=True, cwd=REPO, timeout=600)
    assert "CacheMissError" not in done.stderr + done.stdout and "no cached reply" not in done.stdout
    replayed = json.loads((tmp_path / "replayed" / "results.json").read_text(encoding="utf-8"))
    assert replayed["brief"] == recorded["brief"] and replayed["protocol"] == 1
    assert same_metrics(recorded, replayed)
