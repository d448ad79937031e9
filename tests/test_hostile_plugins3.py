"""Hostile inputs, round 3 (issue 37, classes 4, 8, 9, 13, 16, 21): plug-in imports, plug-in
constructors, `--generator-args`, numeric options and `LOGICENVEVAL_MAX_*` limits. Each case
asserts the exit code, one line naming the problem (file and line for a plug-in), no traceback,
and, for limits, that nothing a limit caused is reused by a later run.

The plug-ins are written into the test's folder: a broken module never reaches other tests.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from cli_support import cli

from logicenveval.errors import ConfigError
from logicenveval.generators.base import import_target
from logicenveval.limits import current, limit, pinned, raise_hint
from logicenveval.runner.config import RunConfig
from logicenveval.runner.unit import GeneratorBroke, UnitSpec, make_bounded, run_unit

HERE = Path(__file__).parent
TASK = "clean_living_room"
TASK2 = "kitchen_fridge_restock"

GOOD = '''
import json
from pathlib import Path
from logicenveval.generators.base import GenerationResult
from logicenveval.model.envspec import EnvSpec

FIXTURE = Path({fixture!r})


def env(brief, env_id):
    data = json.loads(FIXTURE.read_text())
    data.update(env_id=env_id, task_id=brief.id)
    return EnvSpec.model_validate(data)


class Named:
    """The documented form: a factory taking `name` (issue 37, class 9)."""

    def __init__(self, name="named", n=1):
        self.name = name
        self.n = n

    def generate(self, brief, ctx):
        return GenerationResult(envs=[env(brief, f"e{{i}}") for i in range(self.n)])


class Needs(Named):
    """A factory that cannot be made without arguments."""

    def __init__(self, name, n):
        super().__init__(name, n)


class HangsInWorkers(Named):
    """Made at once in the run's own process, never in a worker (issue 37, class 16)."""

    def __init__(self):
        import multiprocessing
        import time
        super().__init__("hangs-in-workers")
        while multiprocessing.parent_process() is not None:
            time.sleep(0.05)


class Hangs(Named):
    def __init__(self):
        import time
        super().__init__("hangs")
        while True:
            time.sleep(0.05)
'''.format(fixture=str(HERE / "fixtures" / "envs" / "one_room.json"))

#: module name -> (source, the words of the one-line error, the line it names)
BROKEN: dict[str, tuple[str, str, int | None]] = {
    "syntax_error": ("class G:\n    name = 'g'\n  def x(\n", "syntax error", 3),
    "raises_at_import": ("import os\nraise RuntimeError('boom at import')\n",
                         "raised RuntimeError: boom at import", 2),
    "exits_0": ("import sys\nsys.exit(0)\n", "called sys.exit(0) while being imported", 2),
    "exits_3": ("import sys\n\nsys.exit(3)\n", "called sys.exit(3) while being imported", 3),
    "getattr_raises": ("def __getattr__(name):\n    raise RuntimeError('no ' + name)\n",
                       "looking up 'G' in module 'getattr_raises' raised RuntimeError: no G", 2),
    "name_raises": ("class G:\n    @property\n    def name(self):\n        raise ValueError('bad')\n"
                    "    def generate(self, brief, ctx):\n        pass\n",
                    "reading `name` of generator 'name_raises:G' raised ValueError: bad", 4),
    "missing_dependency": ("import json\nimport no_such_dependency_xyz\n",
                           "imports a missing module", 2),
    "unprintable": ("class E(Exception):\n    def __str__(self):\n        raise TypeError('no')\n"
                    "raise E()\n", "raised E: <unprintable>", 4),
}


@pytest.fixture
def plugins(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A folder on the Python path (and the working folder) holding the plug-ins above."""
    folder = tmp_path / "plugins"
    folder.mkdir()
    (folder / "good3.py").write_text(GOOD)
    for name, (source, _, _) in BROKEN.items():
        (folder / f"{name}.py").write_text(source)
    monkeypatch.syspath_prepend(str(folder))
    monkeypatch.chdir(folder)
    return folder


def run_args(out: Path, generators: str, *extra: str, tasks: str = TASK) -> list[str]:
    return ["run", "--generators", generators, "--tasks", tasks, "--executor", "inprocess",
            "--output", str(out), "--quiet", *extra]


def one_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


def sub(cwd: Path, *argv: str, env: dict[str, str] | None = None,
        timeout: float = 300) -> subprocess.CompletedProcess[str]:
    proc = subprocess.run([sys.executable, "-m", "logicenveval", *argv], capture_output=True,
                          text=True, cwd=cwd, timeout=timeout, env={**os.environ, **(env or {})})
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr
    return proc


# ----- class 8: plug-in imports are one boundary --------------------------------------------

@pytest.mark.parametrize("module", sorted(BROKEN))
def test_a_plugin_that_cannot_load_is_one_line_exit_2(plugins: Path, tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str],
                                                      module: str) -> None:
    _, words, line = BROKEN[module]
    code, _, err = cli(capsys, *run_args(tmp_path / "out", f"{module}:G"))
    message = one_line(err)
    assert code == 2 and words in message, message
    assert f"{plugins / module}.py:{line}" in message  # the module's file and line
    assert not (tmp_path / "out").exists()  # refused before any work


@pytest.mark.parametrize("module", ["exits_0", "exits_3", "raises_at_import"])
def test_a_plugin_that_cannot_load_in_a_fresh_process(plugins: Path, tmp_path: Path,
                                                      module: str) -> None:
    """sys.exit at import used to end the CLI with the plug-in's own status (0 or 3)."""
    proc = sub(plugins, *run_args(tmp_path / "out", f"{module}:G"))
    assert proc.returncode == 2 and f"{module}.py:" in one_line(proc.stderr)


@pytest.mark.parametrize("spec", [".good3:Named", "..good3:Named", ".:G", "a b:G", "good3.:G"])
def test_relative_and_malformed_module_forms_are_refused(plugins: Path, spec: str) -> None:
    with pytest.raises(ConfigError) as info:
        import_target(spec)
    assert "--generators" in str(info.value)


def test_the_boundary_lets_a_real_interrupt_through(plugins: Path) -> None:
    (plugins / "interrupts.py").write_text("raise KeyboardInterrupt\n")
    with pytest.raises(KeyboardInterrupt):
        import_target("interrupts:G")


# ----- class 9: `name` is the factory's own argument ----------------------------------------

def test_generator_args_may_pass_name(plugins: Path, tmp_path: Path,
                                      capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = cli(capsys, *run_args(tmp_path / "out", "good3:Named", "--generator-args",
                                         "good3:Named:name=renamed,n=2"))
    assert code == 0, err
    (run_dir,) = (tmp_path / "out").iterdir()
    results = json.loads((run_dir / "results.json").read_text())
    assert results["generators"] == ["renamed"] and results["results"]["renamed"]["n_envs"] == 2


# ----- class 21: --generator-args by row name --------------------------------------------------

def test_generator_args_by_the_row_name_of_a_factory_that_needs_them(
        plugins: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = cli(capsys, *run_args(tmp_path / "out", "good3:Needs", "--generator-args",
                                         "mine:name=mine,n=3"))
    assert code == 0, err
    (run_dir,) = (tmp_path / "out").iterdir()
    assert json.loads((run_dir / "results.json").read_text())["results"]["mine"]["n_envs"] == 3


@pytest.mark.parametrize("extra,words", [
    (["--generator-args", "good3:Named:n=2", "--generator-args", "named:n=3"],
     "given for 'good3:Named' and for its row name 'named'"),
    (["--generator-args", "nmaed:n=3"], "names ['nmaed'], which is not in --generators"),
    (["--generator-args", "cot:n=3"], "names ['cot'], which is not in --generators"),
])
def test_generator_args_that_would_be_dropped_are_refused(
        plugins: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str], extra: list[str],
        words: str) -> None:
    code, _, err = cli(capsys, *run_args(tmp_path / "out", "good3:Named", *extra))
    assert code == 2 and words in one_line(err)
    assert not (tmp_path / "out").exists()


# ----- class 16: a constructor that never returns -------------------------------------------

def test_a_constructor_that_never_returns_is_bounded_in_the_run(plugins: Path,
                                                                 tmp_path: Path) -> None:
    proc = sub(plugins, *run_args(tmp_path / "out", "good3:Hangs", "--unit-timeout", "0.5"),
               timeout=120)  # the run's own process makes the generator once: bounded there too
    assert proc.returncode == 2 and "was not made within 0.5 s" in one_line(proc.stderr)


def test_a_constructor_bound_inside_a_unit(plugins: Path) -> None:
    with pytest.raises(GeneratorBroke) as info:
        make_bounded("good3:Hangs", {}, 0.3)
    assert info.value.kind == "generation" and "constructor did not return" in str(info.value)


def test_a_constructor_that_hangs_only_in_workers(plugins: Path, tmp_path: Path) -> None:
    """The budget is 5 s, not 1: the well-behaved generator's units must finish inside it too, and
    with 1 s they did not on a loaded 2-core machine (a worker's start and a unit's scoring)."""
    proc = sub(plugins, "run", "--generators", "good3:HangsInWorkers,good3:Named", "--tasks",
               f"{TASK},{TASK2}", "--workers", "2", "--executor", "process", "--unit-timeout", "5",
               "--output", str(tmp_path / "out"), "--quiet")
    assert proc.returncode == 1, proc.stderr
    assert "constructor did not return within 5 s" in proc.stderr
    (run_dir,) = (tmp_path / "out").iterdir()
    assert json.loads((run_dir / "results.json").read_text())["results"]["named"]["n_envs"] == 2


# ----- class 13: every numeric option bounded at parse time ----------------------------------

@pytest.mark.parametrize("argv", [
    ["run", "--unit-timeout", "5e9"],
    ["run", "--unit-timeout", "604801"],
    ["run", "--limit", "10000001"],
    ["run", "--limit", "9" * 5000],
    ["run", "--max-infra-failures", "99999999999999999999"],
    ["run", "--seed", str(2**63)],
    ["run", "--workers", "100000"],
    ["generate", "--generator", "cot", "--task", TASK, "--out", "x", "--seed", str(2**64)],
    ["simulate", "--task", TASK, "--policy", "correct", "--tick-limit", "1000000000"],
])
def test_numeric_options_out_of_bounds_exit_2_at_parse(capsys: pytest.CaptureFixture[str],
                                                       argv: list[str]) -> None:
    code, _, err = cli(capsys, *argv)
    assert code == 2 and "error: argument" in err


@pytest.mark.parametrize("argv", [
    ["run", "--unit-timeout", "5e9"], ["run", "--limit", "10000001"],
    ["simulate", "--task", TASK, "--policy", "correct", "--tick-limit", "1000000000"],
])
def test_numeric_options_name_their_range(argv: list[str]) -> None:
    proc = sub(HERE, *argv)
    assert proc.returncode == 2 and ("out of range" in proc.stderr or "a week" in proc.stderr)


def test_run_config_bounds_the_library_call_too() -> None:
    for kwargs in ({"unit_timeout": 5e9}, {"limit": 10**7}, {"max_infra_failures": 10**7},
                   {"seed": 2**63}):
        with pytest.raises(ValueError):
            RunConfig(**kwargs)  # type: ignore[arg-type]


# ----- class 4: limits read once, never frozen into results ---------------------------------

@pytest.mark.parametrize("env,words", [
    ({"LOGICENVEVAL_MAX_WORKERS": "abc"}, "LOGICENVEVAL_MAX_WORKERS='abc' is not an integer"),
    ({"LOGICENVEVAL_MAX_ENV_OBJECTS": "0"}, "LOGICENVEVAL_MAX_ENV_OBJECTS='0' is not an integer"),
    ({"LOGICENVEVAL_MAX_ENV_OBJECTS": "9" * 40}, "is not an integer between 1 and"),
    ({"LOGICENVEVAL_MAX_ENV_OBJECT": "5000"}, "LOGICENVEVAL_MAX_ENV_OBJECT names no limit"),
])
def test_a_bad_limit_is_one_line_before_any_work(tmp_path: Path, env: dict[str, str],
                                                 words: str) -> None:
    proc = sub(HERE, "run", "--generators", "cot", "--tasks", TASK, "--workers", "2",
               "--output", str(tmp_path / "out"), "--quiet", env=env)
    assert proc.returncode == 2 and words in one_line(proc.stderr)
    assert not (tmp_path / "out").exists()


def test_limits_are_pinned_in_units(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("LOGICENVEVAL_MAX_ENV_OBJECTS", "7")
    values = current()
    assert values["max_env_objects"] == 7
    monkeypatch.setenv("LOGICENVEVAL_MAX_ENV_OBJECTS", "not a number")  # a worker's environment
    with pinned(values) as hit:
        assert limit("max_env_objects") == 7
        raise_hint("max_env_objects")
    assert hit == {"max_env_objects"}
    with pytest.raises(ConfigError):
        limit("max_env_objects")


def _unit(tmp_path: Path, limits: dict[str, int]) -> dict[str, Any]:
    spec = UnitSpec(generator="with-args", generator_target="hostile_generators:WithArgs",
                    task_id=TASK, tasks_dir=None, model="offline", model_args="", seed=0,
                    run_dir=str(tmp_path), generator_args={"n_envs": 2}, limits=limits)
    return run_unit(spec).model_dump()


def test_a_unit_a_limit_failed_is_an_environment_failure(tmp_path: Path,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.syspath_prepend(str(HERE))
    monkeypatch.setenv("LOGICENVEVAL_MAX_ENV_OBJECTS", "garbage")  # pinned values win
    low = _unit(tmp_path / "low", {**_defaults(), "max_env_objects": 1})
    assert low["error_kind"] == "infrastructure" and low["attempts"] == []
    assert low["limits"] == {"max_env_objects": 1} and "LOGICENVEVAL_MAX_ENV_OBJECTS" in low["error"]
    fine = _unit(tmp_path / "fine", _defaults())
    assert fine["error"] is None and fine["limits"] == {} and len(fine["samples"]) == 2


def test_a_refusal_under_the_default_limits_stays_the_generators_failure() -> None:
    """The documented contract (at most 2,000 environments): kept, but tied to the value."""
    from logicenveval.metrics.records import UnitRecord
    from logicenveval.runner.unit import limited

    record = UnitRecord(generator="g", task_id=TASK, error="generate() returned 10001 environments",
                        error_kind="generation")
    kept = limited(record, {"max_unit_envs": 2000})
    assert kept.error_kind == "generation" and kept.limits == {"max_unit_envs": 2000}
    assert kept.error == record.error
    assert limited(record, {"max_unit_envs": 3000}).error_kind == "infrastructure"
    assert limited(record, {}) is record


def _defaults() -> dict[str, int]:
    from logicenveval.limits import DEFAULTS

    return {name: value for name, (value, _) in DEFAULTS.items()}


def test_a_rerun_after_raising_a_limit_recomputes(tmp_path: Path) -> None:
    """Too-low limit: the units are not results; the re-run without it computes them."""
    argv = ["run", "--generators", "hostile_generators:WithArgs", "--tasks", TASK,
            "--executor", "inprocess", "--output", str(tmp_path), "--run-id", "r", "--quiet",
            "--max-infra-failures", "0"]
    first = sub(HERE, *argv, env={"LOGICENVEVAL_MAX_ENV_OBJECTS": "1"})
    assert first.returncode == 1 and "LOGICENVEVAL_MAX_ENV_OBJECTS" in first.stderr
    unit = json.loads((tmp_path / "r" / "units" / "with-args" / f"{TASK}.json").read_text())["unit"]
    assert unit["error_kind"] == "infrastructure" and unit["limits"] == {"max_env_objects": 1}
    second = sub(HERE, *argv)
    assert second.returncode == 0 and "computed 1 unit(s), reused 0" in second.stdout
    results = json.loads((tmp_path / "r" / "results.json").read_text())
    assert results["results"]["with-args"]["n_envs"] == 1


def test_a_partly_limited_unit_is_recomputed_when_the_limit_changes(tmp_path: Path) -> None:
    """One environment refused by a limit, the others judged: kept under the same limits,
    recomputed under others."""
    (tmp_path / "mixed.py").write_text(
        "import json\nfrom hostile_generators import fixture_env\n"
        "from logicenveval.generators.base import GenerationResult\n"
        "class Mixed:\n    name = 'mixed'\n    def generate(self, brief, ctx):\n"
        "        small = fixture_env(brief, 'small')\n"
        "        more = [o.model_copy(update={'id': f'{o.id}_{k}'}) for k in range(3) for o in small.objects]\n"
        "        big = small.model_copy(update={'env_id': 'big', 'objects': small.objects + more})\n"
        "        return GenerationResult(envs=[small, big])\n")
    n = len(json.loads((HERE / "fixtures" / "envs" / "one_room.json").read_text())["objects"])
    argv = ["run", "--generators", "mixed:Mixed", "--tasks", TASK, "--executor", "inprocess",
            "--output", str(tmp_path / "out"), "--run-id", "r", "--quiet"]
    env = {"PYTHONPATH": f"{tmp_path}{os.pathsep}{HERE}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    low = {**env, "LOGICENVEVAL_MAX_ENV_OBJECTS": str(n)}
    assert sub(tmp_path, *argv, env=low).returncode == 0
    assert "reused 1" in sub(tmp_path, *argv, env=low).stdout  # same limits: a result
    assert "computed 1 unit(s), reused 0" in sub(tmp_path, *argv, env=env).stdout
    results = json.loads((tmp_path / "out" / "r" / "results.json").read_text())
    assert results["results"]["mixed"]["n_envs"] == 2
