"""The developer loop of a plug-in author (issue 48): edit a helper, re-run, compare; a crashing
plug-in fails CI with its own file and line. Each case runs the CLI in a fresh process."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from logicenveval.runner.failures import EXIT_GENERATOR_RAISED

TASKS = "clean_living_room,kitchen_dish_cleanup,kitchen_fridge_restock"
MYGEN = '''
from helper import pick
from logicenveval.baselines.cot import CoT


class MyGen(CoT):
    def __init__(self) -> None:
        super().__init__(name="mygen", max_environments=2)

    def generate(self, brief, ctx):
        pick(brief.id)
        return super().generate(brief, ctx)
'''
HELPER = '''
def pick(task_id):
    if task_id.startswith("kitchen"):
        return [][1]
    return 0
'''


@pytest.fixture
def plugin(tmp_path: Path) -> Path:
    """A one-file plug-in `mygen.py` with a sibling `helper.py` that raises on kitchen tasks."""
    folder = tmp_path / "plug"
    folder.mkdir()
    (folder / "mygen.py").write_text(MYGEN, encoding="utf-8")
    (folder / "helper.py").write_text(HELPER, encoding="utf-8")
    return folder


def cli(cwd: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    """`python -m logicenveval ARGV` in a fresh process whose Python path holds the plug-in."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [str(Path(__file__).resolve().parents[1]), str(cwd), os.environ.get("PYTHONPATH", "")])}
    proc = subprocess.run([sys.executable, "-m", "logicenveval", *argv], capture_output=True,
                          text=True, cwd=cwd, env=env, timeout=600)
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr
    return proc


def run_args(out: Path, *extra: str) -> list[str]:
    return ["run", "--generators", "mygen:MyGen", "--tasks", TASKS, "--executor", "inprocess",
            "--quiet", "--output", str(out), *extra]


def test_a_plugin_that_raises_in_some_units_exits_3_naming_its_own_frame(
        plugin: Path, tmp_path: Path) -> None:
    proc = cli(plugin, *run_args(tmp_path / "out"))
    assert proc.returncode == EXIT_GENERATOR_RAISED == 3
    err = " ".join(proc.stderr.split())
    assert "mygen: raised in 2 of 3 unit(s)" in err
    assert "IndexError: list index out of range" in err
    assert f"at {plugin / 'helper.py'}:4 in pick — 2 unit(s): kitchen_dish_cleanup, " \
           "kitchen_fridge_restock" in err
    assert "internal error: IndexError…" not in proc.stdout + proc.stderr
    assert max(len(line) for line in proc.stderr.splitlines()) <= 100
