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
    assert "whole traceback: \"traceback\" of" in err and "/units/mygen/kitchen_dish_cleanup.json" in err
    # 100 columns but for a path, which is never cut (it is there to be copied)
    assert max(len(line) for line in proc.stderr.splitlines() if str(tmp_path) not in line) <= 100


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


# ----- the smaller items of issue 48 point 5 ------------------------------------------------

@pytest.mark.parametrize("extra", [["--model", "gpt4"], ["--model", "gpt4", "--seeds", "0,1"],
                                   ["--model", "openai:gpt-4o", "--model-args",
                                    "base_url=http://127.0.0.1:9/v1"]])
def test_a_refused_run_leaves_no_run_folder(tmp_path: Path, extra: list[str]) -> None:
    out = tmp_path / "new" / "reports"
    proc = cli(tmp_path, "run", "--tasks", "clean_living_room", "--output", str(out), *extra)
    assert proc.returncode == 2, proc.stderr
    left = sorted(p.relative_to(tmp_path).as_posix() for p in (tmp_path / "new").rglob("*")) \
        if (tmp_path / "new").exists() else []
    # neither the run folder nor the folders made for it; the reply cache the endpoint's
    # preflight opened stays (another run may be using it)
    assert left in ([], ["new/reports", "new/reports/llm_cache.sqlite"]), left


def test_run_help_states_every_default() -> None:
    import argparse

    from logicenveval.cli import build_parser

    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    run_parser = sub.choices["run"]
    lacking = [a.option_strings[0] for a in run_parser._actions
               if a.option_strings and a.nargs != 0 and "default" not in (a.help or "")]
    assert lacking == []
    text = run_parser.format_help()
    for option in ("--seed SEED", "--workers WORKERS", "--executor"):
        assert option in text


@pytest.mark.parametrize("argv,guess", [
    (["run", "--generators", "logicenvgne"], "(did you mean 'logicenvgen'"),
    (["run", "--tasks", "clean_livingroom"], "(did you mean 'clean_living_room'?)"),
    (["run", "--model", "ofline"], "(did you mean 'offline'?)"),
    (["run", "--model", "openia:gpt-4o"], "(did you mean 'openai:gpt-4o'?)"),
    (["run", "--model", "gpt4"], "(did you mean 'openai:gpt4'?)"),
    (["tasks", "show", "clean_livingroom"], "(did you mean 'clean_living_room'?)"),
])
def test_typos_get_a_did_you_mean(tmp_path: Path, argv: list[str], guess: str) -> None:
    from logicenveval.cli import main

    extra = ["--output", str(tmp_path / "out")] if argv[0] == "run" else []
    with pytest.MonkeyPatch.context() as mp:
        mp.chdir(tmp_path)
        code = main([*argv, *extra])
    assert code == 2
    assert not (tmp_path / "out").exists()


def test_typos_get_a_did_you_mean_on_stderr(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from logicenveval.cli import main

    assert main(["run", "--tasks", "clean_livingroom", "--output", str(tmp_path)]) == 2
    assert "unknown task(s) ['clean_livingroom'] (did you mean 'clean_living_room'?)" in \
        capsys.readouterr().err


def test_piped_output_has_no_progress_bar(plugin: Path, tmp_path: Path) -> None:
    _edit_helper(plugin)
    proc = cli(plugin, "run", "--generators", "mygen:MyGen", "--tasks", TASKS, "--executor",
               "inprocess", "--output", str(tmp_path / "out"))
    assert proc.returncode == 0
    assert "━" not in proc.stderr and "mygen: 3/3 unit(s) done" in proc.stderr
    lines = [line for line in (proc.stdout + proc.stderr).splitlines()
             if str(tmp_path) not in line]  # a path is never cut, it is there to be copied
    assert max(len(line) for line in lines) <= 100


def test_compare_says_which_tasks_st_leaves_out(plugin: Path, tmp_path: Path) -> None:
    """A side that built nothing in a task has no ST there: the paired ST leaves the task out,
    and compare says so with the leaderboard's figure beside its own (issue 48)."""
    out = tmp_path / "out"
    assert cli(plugin, *run_args(out)).returncode == 3  # raises on the two kitchen tasks
    (old,) = out.iterdir()
    _edit_helper(plugin)
    assert cli(plugin, *run_args(out)).returncode == 0
    new = out / f"{old.name}-2"
    compared = cli(plugin, "compare", str(old), str(new))
    text = " ".join(compared.stdout.split())
    assert "note: mygen: ST (ms), ST (ticks) and Redundancy are paired over the 1 task(s) where " \
           "both sides built an environment; left out: kitchen_dish_cleanup (A built nothing), " \
           "kitchen_fridge_restock (A built nothing). Each leaderboard averages its own tasks: " \
           "ST (ms) A " in text
    import json

    data = json.loads(cli(plugin, "compare", str(old), str(new), "--json").stdout)
    assert [e["task"] for e in data["pairs"][0]["left_out_of_st"]] == [
        "kitchen_dish_cleanup", "kitchen_fridge_restock"]
    assert {f["input"]: f["same"] for f in data["fingerprints"]}["code of mygen"] is False
    page = tmp_path / "compare.html"
    assert cli(plugin, "compare", str(old), str(new), "--html", str(page)).returncode == 0
    html = page.read_text(encoding="utf-8")
    assert "What made A and B (fingerprints)" in html and "kitchen_dish_cleanup (A built nothing)" in html


def test_a_multi_seed_run_of_other_inputs_goes_to_a_new_parent(plugin: Path, tmp_path: Path) -> None:
    _edit_helper(plugin)
    out = tmp_path / "out"
    args = ["run", "--generators", "mygen:MyGen", "--tasks", "clean_living_room", "--seeds", "0,1",
            "--executor", "inprocess", "--quiet", "--output", str(out)]
    assert cli(plugin, *args).returncode == 0
    (old,) = out.iterdir()
    before = (old / "results.json").read_bytes()
    _edit_helper(plugin, "\nEDITED = 2\n")
    again = cli(plugin, *args)
    assert again.returncode == 0 and "kept the finished run made by other inputs" in again.stdout
    assert (old / "results.json").read_bytes() == before
    assert sorted(p.name for p in (out / f"{old.name}-2").iterdir()) == [
        ".lock", "config.json", "leaderboard.html", "leaderboard.md", "results.json", "seed0", "seed1"]
