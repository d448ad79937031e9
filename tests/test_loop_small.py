"""The smaller items of issue 36: broken pipes, `generators list`, `generate` laid out for
`evaluate`, the example's untracked reports, `tasks validate` progress, `run --help`."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from cli_support import cli

from logicenveval.benchmark_validation import validate_all
from logicenveval.cli import build_parser
from logicenveval.runner.config import DEFAULT_GENERATORS

ROOT = Path(__file__).resolve().parents[1]
TASK = "clean_living_room"


@pytest.mark.parametrize("argv", [["tasks", "stats", "--markdown"], ["tasks", "list"], ["tasks", "stats"]])
def test_a_reader_that_goes_away_ends_the_command_quietly(argv: list[str]) -> None:
    """`tasks stats | head -5` exited 2 with "Broken pipe (fix: check that the path exists...)"."""
    read, write = os.pipe()
    os.close(read)  # the reader is gone before the first line
    try:
        done = subprocess.run([sys.executable, "-m", "logicenveval", *argv], stdout=write,
                              stderr=subprocess.PIPE, timeout=300, cwd=ROOT,
                              env={**os.environ, "PYTHONPATH": str(ROOT)})
    finally:
        os.close(write)
    assert done.returncode == 1 and done.stderr.decode() == ""


def test_generators_list_names_builtins_and_plugins(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    """An installed plug-in (a real distribution on the path) is listed with its version."""
    (tmp_path / "fakeplug.py").write_text('class Gen:\n    """Fake plug-in for the listing."""\n'
                                          '    name = "fake"\n', encoding="utf-8")
    info = tmp_path / "fakeplug-0.3.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: fakeplug\nVersion: 0.3.1\n")
    (info / "entry_points.txt").write_text("[logicenveval.generators]\nfake = fakeplug:Gen\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    code, out, _ = cli(capsys, "generators", "list", "--json")
    assert code == 0
    rows = {r["name"]: r for r in json.loads(out)}
    assert rows["logicenvgen"] == {"name": "logicenvgen", "paper_name": "LogicEnvGen", "source": "built-in",
                                   "description": rows["logicenvgen"]["description"]}
    assert rows["logicenvgen-exact"]["paper_name"] == "" and rows["cot"]["paper_name"] == "CoT"
    assert set(DEFAULT_GENERATORS) <= set(rows) and all(r["description"] for r in rows.values())
    assert rows["fake"]["source"] == "plug-in fakeplug 0.3.1"
    assert rows["fake"]["description"] == "Fake plug-in for the listing."
    code, out, _ = cli(capsys, "generators", "list")
    assert code == 0 and "Holodeck" in out and "plug-in fakeplug 0.3.1" in out


def test_generate_with_arguments_writes_what_evaluate_scores(tmp_path: Path,
                                                             capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "gen"
    code, _, _ = cli(capsys, "generate", "--generator", "cot", "--generator-args", "max_environments=2",
                     "--task", TASK, "--out", str(out), "--no-render")
    assert code == 0
    assert len([p for p in (out / TASK).glob("cot-*.json")]) == 2  # the argument reached the factory
    code, stdout, err = cli(capsys, "evaluate", str(out), "--name", "gen", "--executor", "inprocess",
                            "--output", str(tmp_path / "scored"))
    assert code == 0, err
    assert "scored 1 task folder(s)" in stdout
    code, _, err = cli(capsys, "generate", "--generator", "cot", "--generator-args", "oops",
                       "--task", TASK, "--out", str(out))
    assert code == 2 and "key=value" in err


def test_own_generator_doc_leaves_no_untracked_reports() -> None:
    doc = (ROOT / "docs" / "own-generator.md").read_text(encoding="utf-8")
    block = doc[doc.index("cd examples/my_generator"):]
    command = block[:block.index("```")]
    assert "--output ../../reports" in command  # the repository's ignored reports/ folder
    ignored = subprocess.run(["git", "check-ignore", "-q", "examples/my_generator/reports/x/results.json"],
                             cwd=ROOT, check=False)
    assert ignored.returncode == 0


def test_validate_reports_progress_per_task() -> None:
    calls: list[tuple[int, int, str]] = []
    reports = validate_all(None, simulate=False, ids=[TASK, "kitchen_dish_cleanup"],
                           progress=lambda done, total, task: calls.append((done, total, task)))
    assert [r.task for r in reports] == [TASK, "kitchen_dish_cleanup"]
    assert calls == [(0, 2, TASK), (1, 2, "kitchen_dish_cleanup"), (2, 2, "")]


def test_validate_progress_goes_to_stderr_only(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = cli(capsys, "tasks", "validate", "--task", TASK, "--no-simulate")
    assert code == 0 and "validating" not in out and "all 1 task(s) valid" in out


def test_run_help_lists_every_model_provider_and_the_default_generators() -> None:
    sub = build_parser()._subparsers._group_actions[0].choices["run"]  # type: ignore[union-attr]
    text = " ".join(sub.format_help().split())
    for provider in ("offline", "oracle", "openai:", "replay:", "llamacpp:", "noisy:"):
        assert provider in text
    assert ",".join(DEFAULT_GENERATORS) in text.replace(", ", ",")
