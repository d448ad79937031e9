"""Generators from outside the package: MODULE:ATTR, entry points, register_generator."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

import logicenveval
from logicenveval.cli import main
from logicenveval.errors import ConfigError
from logicenveval.generators import plugins
from logicenveval.generators.base import GenerationContext, GenerationResult
from logicenveval.generators.plugins import resolve_generator
from logicenveval.model.task import TaskBrief
from logicenveval.runner.score_envs import ARTEFACTS

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "my_generator"
TASKS = "clean_living_room,kitchen_fridge_restock"


class Named:
    """A generator defined in the test module (importable by workers as tests' module)."""

    name = "named-in-tests"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        return GenerationResult()


def _cli(out: Path, generators: str, *extra: str, cwd: Path = EXAMPLE) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": ""}
    return subprocess.run(
        [sys.executable, "-m", "logicenveval", "run", "--model", "offline", "--tasks", TASKS,
         "--generators", generators, "--output", str(out), "--quiet", *extra],
        cwd=cwd, env=env, capture_output=True, text=True, timeout=600, check=False)


def _only_dir(out: Path) -> Path:
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    return run_dir


def _results(out: Path) -> dict[str, Any]:
    data: dict[str, Any] = json.loads((_only_dir(out) / "results.json").read_text())
    return data


def test_builtin_names_resolve_to_themselves() -> None:
    ref = resolve_generator("cot")
    assert (ref.name, ref.target, ref.portable) == ("cot", "cot", True)


def test_module_attr_resolves_to_the_generators_name(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.syspath_prepend(str(EXAMPLE))
    ref = resolve_generator("my_generator:MyGenerator")
    assert ref.name == "my-generator" and ref.target == "my_generator:MyGenerator"


def test_entry_point_names_resolve(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.syspath_prepend(str(EXAMPLE))
    monkeypatch.setattr(plugins, "entry_points", lambda: {"mine": "my_generator:MyGenerator"})
    ref = resolve_generator("mine")
    assert ref.name == "my-generator" and ref.target == "my_generator:MyGenerator"


@pytest.mark.parametrize(("spec", "words"), [
    ("no_such_module_xyz:Gen", ["cannot import module 'no_such_module_xyz'", "No module named", "fix:"]),
    ("logicenveval.errors:NoSuchThing", ["has no attribute 'NoSuchThing'", "fix:"]),
    ("logicenveval:__version__", ["is not callable", "fix:"]),
    ("not-a-generator", ["unknown generator 'not-a-generator'", "PKG.MODULE:ATTR", "logicenvgen"]),
    ("logicenveval.errors:LogicEnvEvalError", ["could not be constructed", "fix:"]),
])
def test_bad_specs_are_config_errors_with_the_cause(spec: str, words: list[str]) -> None:
    with pytest.raises(ConfigError) as info:
        resolve_generator(spec)
    for w in words:
        assert w in str(info.value), str(info.value)


def test_unknown_module_on_the_command_line_exits_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--model", "offline", "--tasks", TASKS, "--generators", "nope_mod:Gen",
                 "--output", str(tmp_path), "--quiet"])
    assert code == 2
    err = capsys.readouterr().err
    assert "nope_mod" in err and "No module named" in err and "fix:" in err
    assert not any(tmp_path.iterdir())  # nothing was started


@pytest.fixture
def clean_registry(monkeypatch: pytest.MonkeyPatch) -> None:
    """Registrations made by a test stay in that test."""
    from logicenveval.generators import base

    base.registered()
    monkeypatch.setattr(base, "_REGISTRY", dict(base._REGISTRY))


@pytest.mark.usefixtures("clean_registry")
def test_register_generator_from_python(tmp_path: Path) -> None:
    logicenveval.register_generator("mine-registered", Named)
    ref = resolve_generator("mine-registered")
    assert ref.target == f"{__name__}:Named" and ref.portable
    # Named returns no environment anywhere: measured nothing, so exit 1 (docs/security.md), but
    # the registered generator was found and made, and its row is written
    assert main(["run", "--model", "offline", "--tasks", "clean_living_room",
                 "--generators", "mine-registered", "--executor", "inprocess",
                 "--output", str(tmp_path), "--quiet"]) == 1
    assert list(_results(tmp_path)["results"]) == ["mine-registered"]


@pytest.mark.usefixtures("clean_registry")
def test_unimportable_factory_is_refused_for_worker_processes(tmp_path: Path) -> None:
    logicenveval.register_generator("lambda-gen", lambda: Named())
    assert not resolve_generator("lambda-gen").portable
    with pytest.raises(ConfigError, match="worker processes cannot import"):
        from logicenveval.runner.config import RunConfig
        from logicenveval.runner.run import resolve_generators

        resolve_generators(RunConfig(generators=("lambda-gen",), workers=2, output=str(tmp_path)))


def test_module_attr_with_two_worker_processes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The must-show: MODULE:ATTR from the current folder, --workers 2, row under its name."""
    proc = _cli(tmp_path / "pool", "my_generator:MyGenerator", "--workers", "2", "--executor", "process")
    assert proc.returncode == 0, proc.stderr
    results = _results(tmp_path / "pool")
    assert list(results["results"]) == ["my-generator"]
    assert results["results"]["my-generator"]["n_envs"] == 6
    assert results["failures"]["my-generator"] == []
    run_dir = _only_dir(tmp_path / "pool")
    assert "| my-generator |" in (run_dir / "leaderboard.md").read_text()
    envs = [p for p in (run_dir / "envs" / "my-generator" / "clean_living_room").glob("*.json")
            if p.name not in ARTEFACTS]  # brief.json: what the generator was shown
    assert len(envs) == 3
    # the same in this process: identical results (the resolution travels in the unit spec)
    monkeypatch.syspath_prepend(str(EXAMPLE))
    assert main(["run", "--model", "offline", "--tasks", TASKS, "--generators", "my_generator:MyGenerator",
                 "--executor", "inprocess", "--output", str(tmp_path / "inproc"), "--quiet"]) == 0
    a, b = results["results"]["my-generator"], _results(tmp_path / "inproc")["results"]["my-generator"]
    assert {k: v for k, v in a.items() if k != "st_ms"} == {k: v for k, v in b.items() if k != "st_ms"}


@pytest.mark.slow
def test_entry_point_after_pip_install(tmp_path: Path) -> None:
    pip = [sys.executable, "-m", "pip", "install", "-q", "--no-deps",
           "-e", str(EXAMPLE)]
    subprocess.run(pip, check=True, capture_output=True, timeout=600)
    try:
        proc = _cli(tmp_path, "my-generator", "--workers", "2", cwd=tmp_path)
        assert proc.returncode == 0, proc.stderr
        assert list(_results(tmp_path)["results"]) == ["my-generator"]
    finally:
        subprocess.run([sys.executable, "-m", "pip", "uninstall", "-q", "-y",
                        "my-logicenveval-generator"], check=False, capture_output=True, timeout=600)


def test_a_worker_without_the_module_on_its_path_imports_it_from_the_spec(tmp_path: Path) -> None:
    """What a Ray worker started in another folder does: the unit spec carries the module's root."""
    import sys as _sys

    _sys.path.insert(0, str(EXAMPLE))
    try:
        ref = resolve_generator("my_generator:MyGenerator")
    finally:
        _sys.path.remove(str(EXAMPLE))
    assert ref.search_path == str(EXAMPLE.resolve())
    from logicenveval.runner.unit import UnitSpec

    spec = UnitSpec(generator=ref.name, generator_target=ref.target, generator_path=ref.search_path,
                    task_id="clean_living_room", tasks_dir=None, model="offline", model_args="",
                    seed=0, run_dir=str(tmp_path / "run"))
    code = ("import json, sys; from logicenveval.runner.unit import UnitSpec, run_unit; "
            "r = run_unit(UnitSpec.model_validate_json(sys.argv[1])); "
            "print(json.dumps([r.error, len(r.samples)]))")
    proc = subprocess.run([sys.executable, "-c", code, spec.model_dump_json()], cwd=tmp_path,
                          env={**os.environ, "PYTHONPATH": ""}, capture_output=True, text=True,
                          timeout=600, check=False)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout.strip().splitlines()[-1]) == [None, 3]


SCRIPT = '''
import sys
import logicenveval
from logicenveval.generators.base import GenerationResult
from logicenveval.runner.config import RunConfig
from logicenveval.runner.run import run


class ScriptGen:
    name = "script-gen"

    def generate(self, brief, ctx):
        raise RuntimeError("generator bug in the user script")


logicenveval.register_generator("from-script", ScriptGen)

if __name__ == "__main__":
    out = run(RunConfig(generators=("from-script",), tasks=("clean_living_room", "kitchen_fridge_restock"),
                        workers=2, executor="process", output=sys.argv[1]), show_progress=False)
    print(sorted(out.results["failures"]["from-script"][0].items()))
'''


def test_register_generator_in_a_script_reaches_process_workers(tmp_path: Path) -> None:
    """The issue's first report: register() in a user script was unknown to the pool workers."""
    script = tmp_path / "user_script.py"
    script.write_text(SCRIPT)
    proc = subprocess.run([sys.executable, str(script), str(tmp_path / "out")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=600, check=False)
    assert proc.returncode == 0, proc.stderr
    # the workers made the generator (no "unknown generator"): its own error is what is recorded
    assert "generator bug in the user script" in proc.stdout
    assert "unknown generator" not in proc.stdout


@pytest.mark.slow
def test_module_attr_with_the_ray_executor(tmp_path: Path) -> None:
    pytest.importorskip("ray")
    proc = _cli(tmp_path, "my_generator:MyGenerator", "--workers", "2", "--executor", "ray")
    assert proc.returncode == 0, proc.stderr
    results = _results(tmp_path)
    assert list(results["results"]) == ["my-generator"] and results["failures"]["my-generator"] == []
    assert results["results"]["my-generator"]["n_envs"] == 6


def test_swapping_the_registry_before_the_first_load_leaves_the_built_ins(tmp_path: Path) -> None:
    """Order-dependent before: with a once-only load, a test that put a copy of the (still empty)
    registry in place, made a generator, then restored it, left every later test of its worker
    process with no built-in generator ("unknown generator 'cot'"). A fresh process, so that this
    is the first load."""
    code = ("from logicenveval.generators import base\n"
            "saved = base._REGISTRY\n"
            "base._REGISTRY = dict(saved)\n"
            "base.registered()\n"
            "base._REGISTRY = saved\n"
            "print(','.join(base.registered()))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                          cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert {"logicenvgen", "cot", "ifg", "holodeck"} <= set(done.stdout.strip().split(","))
