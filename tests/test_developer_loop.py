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


def _edit_helper(plugin: Path, text: str = "\nEDITED = 1\n") -> None:
    (plugin / "helper.py").write_text(HELPER.replace('"kitchen"', '"nothing"') + text, encoding="utf-8")


def test_edit_rerun_compare_keeps_the_old_run(plugin: Path, tmp_path: Path) -> None:
    """Edit a helper, run the same command, compare OLD NEW: the old run is still there."""
    _edit_helper(plugin)
    out = tmp_path / "out"
    first = cli(plugin, *run_args(out))
    assert first.returncode == 0, first.stderr
    (old,) = out.iterdir()
    before = (old / "results.json").read_bytes()
    _edit_helper(plugin, "\nEDITED = 2\n")
    second = cli(plugin, *run_args(out))
    assert second.returncode == 0, second.stderr
    new = out / f"{old.name}-2"
    assert (old / "results.json").read_bytes() == before  # the finished run is kept as it was
    assert (new / "results.json").is_file()
    text = " ".join(second.stdout.split())
    assert f"kept the finished run made by other inputs (generator mygen's code), not replaced: " \
           f"{old}" in text
    assert "computed 3 unit(s), reused 0" in text  # every unit of mygen: its helper changed
    assert "recomputed 3 unit(s): generator mygen's code changed" in text
    third = cli(plugin, *run_args(out))  # the same inputs again: the new folder, all reused
    assert "computed 0 unit(s), reused 3" in third.stdout and sorted(out.iterdir()) == [old, new]
    compared = cli(plugin, "compare", str(old), str(new))
    lines = [line for line in compared.stdout.splitlines() if "code of mygen" in line]
    assert len(lines) == 1 and "differs" in lines[0]
    assert "warning" not in compared.stdout
    same = cli(plugin, "compare", str(new), str(new))
    assert "warning: A and B have the same configuration and the same fingerprints" in same.stdout


def test_a_named_finished_run_is_refused_with_the_commands_to_keep_or_replace_it(
        plugin: Path, tmp_path: Path) -> None:
    _edit_helper(plugin)
    out = tmp_path / "out"
    args = run_args(out, "--run-id", "floor-v1")
    assert cli(plugin, *args).returncode == 0
    before = {p: p.read_bytes() for p in (out / "floor-v1").rglob("*") if p.is_file()}
    _edit_helper(plugin, "\nEDITED = 2\n")
    refused = cli(plugin, *args)
    assert refused.returncode == 2
    err = " ".join(refused.stderr.split())
    assert "floor-v1: the run folder holds a finished run made by other inputs (generator " \
           "mygen's code); it is kept, not replaced" in err
    keep = "python -m logicenveval " + " ".join(args).replace("floor-v1", "floor-v1-2")
    assert f"keep it and run under a new id: {keep} ;" in err
    assert "or replace it: python -m logicenveval " + " ".join([*args, "--replace"]) in err
    assert {p: p.read_bytes() for p in (out / "floor-v1").rglob("*") if p.is_file()} == before
    assert sorted(p.name for p in out.iterdir()) == ["floor-v1"]  # nothing else was made
    replaced = cli(plugin, *args, "--replace")
    assert replaced.returncode == 0 and "recomputed 3 unit(s)" in replaced.stdout


def test_an_unfinished_run_resumes_in_place(plugin: Path, tmp_path: Path) -> None:
    """A run with no results.json is not finished: a re-run resumes it, edited or not."""
    _edit_helper(plugin)
    out = tmp_path / "out"
    assert cli(plugin, *run_args(out)).returncode == 0
    (folder,) = out.iterdir()
    (folder / "results.json").unlink()  # as if killed before the end
    again = cli(plugin, *run_args(out))
    assert "computed 0 unit(s), reused 3" in again.stdout and list(out.iterdir()) == [folder]
    (folder / "results.json").unlink()
    _edit_helper(plugin, "\nEDITED = 3\n")
    edited = cli(plugin, *run_args(out))
    assert "computed 3 unit(s), reused 0" in edited.stdout and list(out.iterdir()) == [folder]
