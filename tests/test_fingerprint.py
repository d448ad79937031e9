"""A resumed run reuses a unit only when what made it is unchanged (runner.fingerprint)."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import pytest

from logicenveval.benchmark import DEFAULT_TASKS_DIR
from logicenveval.cli import main
from logicenveval.generators.plugins import resolve_generator
from logicenveval.runner import fingerprint
from logicenveval.runner.config import RunConfig
from logicenveval.runner.run import RunOutcome, run

TASKS = ("clean_living_room", "kitchen_dish_cleanup")
PLUGIN = '''
from logicenveval.baselines.cot import CoT


class Plug(CoT):
    VERSION = {version}

    def __init__(self) -> None:
        super().__init__(name="plug", max_environments=2)
'''


@pytest.fixture
def world(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A tasks folder of two tasks and a plug-in module on the Python path."""
    for t in TASKS:
        shutil.copytree(DEFAULT_TASKS_DIR / t, tmp_path / "tasks" / t)
    (tmp_path / "plugs").mkdir()
    (tmp_path / "plugs" / "fp_plug.py").write_text(PLUGIN.format(version=1), encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path / "plugs"))
    monkeypatch.delitem(sys.modules, "fp_plug", raising=False)  # another test's copy
    return tmp_path


def _run(world: Path, **kw: object) -> RunOutcome:
    config = RunConfig(generators=("fp_plug:Plug", "cot"), tasks=TASKS,
                       tasks_dir=str(world / "tasks"), executor="inprocess",
                       output=str(world / "out"), **kw)  # type: ignore[arg-type]
    return run(config, show_progress=False)


def test_unchanged_inputs_reuse_every_unit(world: Path) -> None:
    first = _run(world)
    assert (first.computed, first.reused) == (4, 0)
    assert all(set(r.inputs) == set(fingerprint.INPUTS) for r in first.records)
    again = _run(world)
    assert (again.computed, again.reused, again.stale) == (0, 4, {})


def test_edited_plugin_recomputes_its_units_only(world: Path) -> None:
    _run(world)
    (world / "plugs" / "fp_plug.py").write_text(PLUGIN.format(version=2), encoding="utf-8")
    after = _run(world)
    assert (after.computed, after.reused) == (2, 2)
    [(why, n)] = after.stale.items()
    assert n == 2 and why.startswith("generator plug's code changed\n  was plug-in src:")


def test_edited_task_recomputes_its_units_only(world: Path) -> None:
    _run(world)
    task_json = world / "tasks" / TASKS[1] / "task.json"
    task_json.write_text(task_json.read_text(encoding="utf-8") + "\n", encoding="utf-8")
    after = _run(world)
    assert (after.computed, after.reused) == (2, 2)
    [(why, n)] = after.stale.items()
    assert n == 2 and why.startswith(f"task {TASKS[1]}'s files changed\n  was ")


def test_harness_and_catalog_fingerprints_recompute_everything(
        world: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _run(world)
    monkeypatch.setattr(fingerprint, "harness_fingerprint", lambda: "9.9.9 src:bumped")
    bumped = _run(world)
    assert (bumped.computed, bumped.reused) == (4, 0)
    assert list(bumped.stale.values()) == [4] and "the harness changed" in bumped.stale_text()
    monkeypatch.setattr(fingerprint, "catalog_fingerprint", lambda: "other")
    assert _run(world).computed == 4
    assert _run(world).computed == 0


def test_fresh_recomputes_everything(world: Path) -> None:
    _run(world)
    fresh = _run(world, fresh=True)
    assert (fresh.computed, fresh.reused, fresh.stale) == (4, 0, {"--fresh": 4})


def test_unit_without_fingerprints_is_recomputed() -> None:
    assert fingerprint.changed_inputs({}, {"harness": "x"}) == ["unrecorded"]
    assert fingerprint.changed_inputs({"harness": "a", "generator": "g", "task": "t", "catalog": "c"},
                                      {"harness": "b", "generator": "g", "task": "u", "catalog": "c"}) \
        == ["harness", "task"]


def test_generator_fingerprints(world: Path) -> None:
    builtin = fingerprint.generator_fingerprint(resolve_generator("cot"))
    assert builtin.startswith("built-in src:")
    plug = resolve_generator("fp_plug:Plug")
    before = fingerprint.generator_fingerprint(plug)
    (world / "plugs" / "fp_plug.py").write_text(PLUGIN.format(version=3), encoding="utf-8")
    assert fingerprint.generator_fingerprint(plug) != before


def test_cli_says_what_changed(world: Path, capsys: pytest.CaptureFixture[str]) -> None:
    args = ["run", "--generators", "fp_plug:Plug", "--tasks", ",".join(TASKS), "--tasks-dir",
            str(world / "tasks"), "--executor", "inprocess", "--quiet", "--output", str(world / "out")]
    assert main(args) == 0
    (world / "plugs" / "fp_plug.py").write_text(PLUGIN.format(version=2), encoding="utf-8")
    capsys.readouterr()
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "computed 2 unit(s), reused 0" in out
    assert "recomputed 2 unit(s): generator plug's code changed" in out
    assert main([*args, "--fresh"]) == 0
    assert "recomputed 2 unit(s): --fresh" in capsys.readouterr().out


def test_evaluate_rejudges_units_when_the_harness_or_a_task_changed(
        world: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from logicenveval.generators.generate import generate_to_folder
    from logicenveval.runner.score_envs import EvaluateConfig, evaluate_envs

    for t in TASKS:
        generate_to_folder(generator="cot", task_id=t, model="offline", model_args="",
                           tasks_dir=str(world / "tasks"), seed=0, out=world / "envs", render=False,
                           generator_args={"max_environments": 1})
    config = EvaluateConfig(envs_dir=str(world / "envs"), tasks_dir=str(world / "tasks"),
                            executor="inprocess", output=str(world / "scored"))
    assert evaluate_envs(config).computed == 2
    assert evaluate_envs(config).computed == 0
    task_json = world / "tasks" / TASKS[0] / "task.json"
    task_json.write_text(task_json.read_text(encoding="utf-8") + "\n", encoding="utf-8")
    again = evaluate_envs(config)
    assert (again.computed, list(again.stale.values())) == (1, [1])
    monkeypatch.setattr(fingerprint, "harness_fingerprint", lambda: "9.9.9 src:bumped")
    assert evaluate_envs(config).computed == 2


HELPED = '''
from fp_helper import N_ENVS
from logicenveval.baselines.cot import CoT


class Helped(CoT):
    def __init__(self) -> None:
        super().__init__(name="helped", max_environments=N_ENVS)
'''


def test_a_sibling_helper_module_is_part_of_a_one_file_plugin(world: Path) -> None:
    """Issue 48: editing `helper.py` beside a one-file plug-in recomputes its units."""
    plugs = world / "plugs"
    (plugs / "fp_helped.py").write_text(HELPED, encoding="utf-8")
    (plugs / "fp_helper.py").write_text("N_ENVS = 1\n", encoding="utf-8")
    (plugs / "fp_unused.py").write_text("X = 1\n", encoding="utf-8")
    ref = resolve_generator("fp_helped:Helped")
    before = fingerprint.generator_fingerprint(ref)
    (plugs / "fp_unused.py").write_text("X = 2\n", encoding="utf-8")  # not imported: no change
    assert fingerprint.generator_fingerprint(ref) == before
    (plugs / "fp_helper.py").write_text("N_ENVS = 2\n", encoding="utf-8")
    assert fingerprint.generator_fingerprint(ref) != before


def test_imports_are_followed_transitively_and_lazily_but_not_into_the_environment(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from logicenveval.generators.plugin_code import own_code

    (tmp_path / "pk").mkdir()
    (tmp_path / "pk" / "__init__.py").write_text("from .sub import f\n", encoding="utf-8")
    (tmp_path / "pk" / "sub.py").write_text("import json\nimport numpy\n", encoding="utf-8")
    (tmp_path / "fp_top.py").write_text(
        "import logicenveval.baselines.cot\n\ndef g():\n    from fp_mid import x\n", encoding="utf-8")
    (tmp_path / "fp_mid.py").write_text("from pk import sub\nfrom . import nothing\n", encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))
    found = own_code("fp_top")
    assert found is not None
    root, files = found
    assert root == tmp_path.resolve()
    assert sorted(p.relative_to(root).as_posix() for p in files) == [
        "fp_mid.py", "fp_top.py", "pk/__init__.py", "pk/sub.py"]
    assert "fp_mid" not in sys.modules and "pk" not in sys.modules  # nothing was imported


def test_a_dot_named_policy_file_is_part_of_the_task(world: Path) -> None:
    """Issue 48: a task naming `policies/.correct.xml` recomputes when that file changes."""
    folder = world / "tasks" / TASKS[0]
    (folder / "policies" / "correct.xml").rename(folder / "policies" / ".correct.xml")
    task_json = folder / "task.json"
    task_json.write_text(task_json.read_text(encoding="utf-8").replace(
        '"policies/correct.xml"', '"policies/.correct.xml"'), encoding="utf-8")
    before = fingerprint.task_fingerprint(TASKS[0], world / "tasks")
    policy = folder / "policies" / ".correct.xml"
    policy.write_text(policy.read_text(encoding="utf-8") + "\n", encoding="utf-8")
    assert fingerprint.task_fingerprint(TASKS[0], world / "tasks") != before
