"""A generator's exception is kept with its traceback, shown on its page and with --debug, and
counted as the failed attempts it cost (issue 36)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from logicenveval.cli import main
from logicenveval.reporting.why import reasons
from logicenveval.runner.config import RunConfig
from logicenveval.runner.failures import summary
from logicenveval.runner.run import run

TASK = "clean_living_room"
PLUGIN = '''
def _helper():
    raise RuntimeError("boom api_key=sk-abcdefghijkl")


class Crash:
    name = "crash"

    def generate(self, brief, ctx):
        ctx.plan_attempts(3)
        _helper()
'''


@pytest.fixture
def plug(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    path = tmp_path / "crash_plug.py"
    path.write_text(PLUGIN, encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.delitem(sys.modules, "crash_plug", raising=False)
    return path


def _args(tmp_path: Path) -> list[str]:
    return ["run", "--generators", "crash_plug:Crash,cot", "--tasks", TASK, "--executor", "inprocess",
            "--quiet", "--output", str(tmp_path / "out")]


def test_traceback_is_kept_redacted_and_on_the_task_page(plug: Path, tmp_path: Path) -> None:
    outcome = run(RunConfig(generators=("crash_plug:Crash",), tasks=(TASK,), executor="inprocess",
                            output=str(tmp_path / "out")), show_progress=False)
    [unit] = outcome.records
    assert unit.error_kind == "internal" and unit.traceback is not None
    assert f'File "{plug}", line 3, in _helper' in unit.traceback
    assert f'File "{plug}", line 11, in generate' in unit.traceback
    assert "RuntimeError: boom" in unit.traceback and "sk-abcdefghijkl" not in unit.traceback
    stored = json.loads((outcome.run_dir / "units" / "crash" / f"{TASK}.json").read_text())
    assert stored["unit"]["traceback"] == unit.traceback
    from logicenveval.reporting.publish import publish

    publish(outcome.run_dir, outcome.results, outcome.records)
    page = (outcome.run_dir / "details" / "crash" / f"{TASK}.html").read_text(encoding="utf-8")
    assert "Traceback of the exception that failed this unit" in page
    assert "line 3, in _helper" in page and "sk-abcdefghijkl" not in page


def test_failed_attempts_are_counted_per_cause(plug: Path, tmp_path: Path) -> None:
    outcome = run(RunConfig(generators=("crash_plug:Crash",), tasks=(TASK,), executor="inprocess",
                            output=str(tmp_path / "out")), show_progress=False)
    [entry] = outcome.results["failures"]["crash"]
    assert entry["attempts"] == 3
    [why] = reasons([], outcome.results["failures"], scores=outcome.results["results"])
    assert [r.count for r in why.reasons] == [3]
    assert "  3 failed attempt(s): internal error: RuntimeError: boom" in summary(outcome.records, ["crash"])


def test_debug_reraises_in_process_and_recomputes_the_failed_unit(
        plug: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(_args(tmp_path)) == 3  # crash raised
    out = capsys.readouterr().out
    assert "crash: 3 × generation: unit (internal): internal error: RuntimeError: boom" in out
    with pytest.raises(RuntimeError, match="boom"):  # what a post-mortem debugger stops at
        main([*_args(tmp_path), "--debug", "--workers", "2", "--executor", "process"])


def test_debug_prints_stored_tracebacks(plug: Path, tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    plug.write_text(PLUGIN.replace("        _helper()", "        raise SystemExit(3)"), encoding="utf-8")
    assert main([*_args(tmp_path), "--debug"]) == 3
    err = capsys.readouterr().err
    assert f"--- crash on {TASK}: the generator called sys.exit(3)" in err
    assert f'File "{plug}", line 11, in generate' in err
