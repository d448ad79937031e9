"""The Ray executor on a cluster: connecting, shipping, handing units back (runner.cluster)."""

from __future__ import annotations

import contextlib
import json
import os
import socket
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import pytest

from logicenveval.errors import ConfigError
from logicenveval.generators.plugins import GeneratorRef
from logicenveval.metrics.records import UnitRecord
from logicenveval.runner import cluster
from logicenveval.runner.executors import check_reachable, ray_address
from logicenveval.runner.unit import Committed, UnitSpec

ROOT = Path(__file__).resolve().parents[1]
FAKE = ROOT / "tests" / "data" / "fake_llama_server.py"
TASKS = sorted(p.name for p in (ROOT / "benchmark_data" / "tasks").iterdir())[:2]


def _closed_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])  # closed again when the block ends


def test_an_unreachable_address_is_one_clear_error() -> None:
    with pytest.raises(ConfigError, match="no Ray cluster answers at 127.0.0.1:") as err:
        check_reachable(f"127.0.0.1:{_closed_port()}", timeout=2)
    assert err.value.field == "--ray-address" and "ray start --head" in (err.value.hint or "")
    with pytest.raises(ConfigError, match="not HOST:PORT"):
        check_reachable("my-cluster")
    check_reachable("auto")  # left to Ray


def test_the_address_comes_from_the_option_then_the_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("RAY_ADDRESS", "10.0.0.1:6379")
    assert ray_address(None) == "10.0.0.1:6379"
    assert ray_address("10.0.0.2:6379") == "10.0.0.2:6379"
    monkeypatch.delenv("RAY_ADDRESS")
    assert ray_address(None) is None


def test_a_shipment_unpacks_and_localizes_the_drivers_paths(tmp_path: Path,
                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cluster, "NODE_ROOT", tmp_path / "node")
    monkeypatch.setattr(cluster, "_RECEIVED", {})
    pack = tmp_path / "pack.sqlite"
    pack.write_bytes(b"recorded replies")
    shipment = cluster.make_shipment(tasks_dir=None, ids=TASKS, model=f"noisy:replay:{pack}", cache=None)
    cluster.receive("k1", lambda: shipment)
    cluster.receive("k1", lambda: pytest.fail("a worker fetches a shipment once"))
    spec = UnitSpec(generator="cot", task_id=TASKS[0], tasks_dir=None, model=f"noisy:replay:{pack}",
                    model_args="", seed=0, run_dir="/driver/run")
    local = cluster.localized(spec, shipment, tmp_path / "scratch", None)
    assert local.run_dir == str(tmp_path / "scratch")
    assert local.model.startswith("noisy:replay:") and Path(local.model[13:]).read_bytes() == b"recorded replies"
    shipped = Path(local.tasks_dir or "")
    assert sorted(p.name for p in shipped.iterdir()) == TASKS  # only the run's tasks travel
    for task in TASKS:
        source = ROOT / "benchmark_data" / "tasks" / task
        for f in (p for p in source.rglob("*") if p.is_file()):
            assert (shipped / task / f.relative_to(source)).read_bytes() == f.read_bytes()


def test_write_back_writes_files_then_the_unit_and_refuses_escapes(tmp_path: Path) -> None:
    record = UnitRecord(generator="cot", task_id="t")
    done = Committed(record, files={"envs/cot/t/e.json": b"{}", "units/cot/t.json": b"unit"})
    cluster.write_back(tmp_path, done, None)
    assert (tmp_path / "envs/cot/t/e.json").read_bytes() == b"{}"
    assert (tmp_path / "units/cot/t.json").read_bytes() == b"unit"
    with pytest.raises(ConfigError, match="outside the run folder"):
        cluster.write_back(tmp_path, Committed(record, files={"../evil": b"x"}), None)
    assert not (tmp_path.parent / "evil").exists()


def test_replies_a_worker_added_reach_the_drivers_cache(tmp_path: Path) -> None:
    from logicenveval.llm.cache import ReplyCache

    path = tmp_path / "llm_cache.sqlite"
    done = Committed(UnitRecord(generator="cot", task_id="t"), files={"units/cot/t.json": b"u"},
                     replies=(("k", "openai", "m", "plan", "reply"),))
    cluster.write_back(tmp_path, done, str(path))
    assert ReplyCache(path).get("k") == "reply"


def test_the_reply_cache_a_run_writes() -> None:
    run = Path("/out/run")
    assert cluster.reply_cache("offline", None, False, run) is None
    assert cluster.reply_cache("replay:x.sqlite", None, False, run) is None
    assert cluster.reply_cache("openai:m", None, False, run) == "/out/llm_cache.sqlite"
    assert cluster.reply_cache("noisy:llamacpp:m.gguf", "c.sqlite", False, run) == "c.sqlite"
    assert cluster.reply_cache("openai:m", None, True, run) is None


def test_a_loopback_endpoint_serves_only_nodes_on_this_machine() -> None:
    local = "base_url=http://127.0.0.1:8080/v1,model_sha256=ab"
    cluster.check_endpoint_reach(local, "10.0.0.1", ["10.0.0.1", "10.0.0.1"])
    cluster.check_endpoint_reach("base_url=http://10.0.0.1:8080/v1", "10.0.0.1", ["10.0.0.2"])
    cluster.check_endpoint_reach("", "10.0.0.1", ["10.0.0.2"])
    with pytest.raises(ConfigError, match="node.s. at 10.0.0.2 cannot reach") as err:
        cluster.check_endpoint_reach(local, "10.0.0.1", ["10.0.0.1", "10.0.0.2"])
    assert "llama-server --host 0.0.0.0" in (err.value.hint or "")


def test_a_node_with_other_code_is_refused() -> None:
    here = cluster.node_report([GeneratorRef(spec="cot", name="cot", target="cot")])
    cluster.check_nodes([("10.0.0.2 (node a)", dict(here))], here)
    with pytest.raises(ConfigError, match=r"10.0.0.3 \(node b\) would run other code.*harness"):
        cluster.check_nodes([("10.0.0.3 (node b)", {**here, "harness": "0.0 src:other"})], here)
    with pytest.raises(ConfigError, match="cannot run units: ModuleNotFoundError"):
        cluster.check_nodes([("n", ModuleNotFoundError("No module named 'ortools'"))], here)


def test_the_runtime_env_ships_the_project_and_plug_ins(tmp_path: Path) -> None:
    plugin = tmp_path / "src" / "my_gen.py"
    plugin.parent.mkdir()
    plugin.write_text("from logicenveval.baselines.cot import *\n")
    sys.path.insert(0, str(plugin.parent))
    try:
        ref = GeneratorRef(spec="my_gen:X", name="x", target="my_gen:X", search_path=str(plugin.parent))
        env = cluster.project_runtime_env([ref], tmp_path / "staging")
    finally:
        sys.path.remove(str(plugin.parent))
    staged = tmp_path / "staging"
    assert (staged / "logicenveval" / "runner" / "cluster.py").is_file()
    assert (staged / "benchmark_data" / "catalog.json").is_file()
    assert not list(staged.rglob("__pycache__"))
    assert env["working_dir"] == str(staged) and env["py_modules"] == [str(plugin.resolve())]


def _cli(*args: str, env: dict[str, str] | None = None, timeout: float = 600) -> subprocess.CompletedProcess[str]:
    full = {**os.environ, "PYTHONPATH": str(ROOT), **(env or {})}
    return subprocess.run([sys.executable, "-m", "logicenveval", "run", *args], capture_output=True,
                          text=True, env=full, timeout=timeout, check=False)


def test_a_bad_cluster_address_is_one_line_without_a_traceback(tmp_path: Path) -> None:
    pytest.importorskip("ray")
    proc = _cli("--executor", "ray", "--ray-address", f"127.0.0.1:{_closed_port()}", "--tasks",
                TASKS[0], "--output", str(tmp_path), "--quiet", timeout=120)
    assert proc.returncode == 2, proc.stderr
    assert "Traceback" not in proc.stderr
    assert "no Ray cluster answers at 127.0.0.1:" in proc.stderr and "docs/cluster.md" in proc.stderr


def _figures(run_dir: Path) -> dict[str, object]:
    data = json.loads((run_dir / "results.json").read_text())
    for key in ("timing", "git_commit"):
        data.pop(key, None)
    for values in data["results"].values():
        values.pop("st_ms")
    for per in data["per_task"].values():
        for values in per.values():
            values.pop("st_ms")
    return data


def _cache_keys(output: Path) -> set[str]:
    with contextlib.closing(sqlite3.connect(output / "llm_cache.sqlite")) as conn:
        return {row[0] for row in conn.execute("SELECT key FROM replies")}


def _files(run_dir: Path) -> dict[str, bytes]:
    """The run's environment, render and page files (unit files hold timings)."""
    return {p.relative_to(run_dir).as_posix(): p.read_bytes() for p in sorted(run_dir.rglob("*"))
            if p.is_file() and p.relative_to(run_dir).parts[0] in ("envs", "renders")}


@pytest.mark.slow
def test_a_two_node_cluster_run_equals_the_process_executors(tmp_path: Path,
                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip("ray")
    from logicenveval.runner.local_cluster import local_cluster

    starts = tmp_path / "server-starts"  # each stand-in llama-server writes its pid here
    monkeypatch.setenv("FAKE_LLAMA_STARTS", str(starts))  # inherited by the nodes

    tasks = sorted(p.name for p in (ROOT / "benchmark_data" / "tasks").iterdir())[:4]
    common = ["--tasks", ",".join(tasks), "--quiet", "--run-id", "r"]
    local = _cli(*common, "--workers", "2", "--output", str(tmp_path / "local"))
    assert local.returncode == 0, local.stderr
    units = tmp_path / "cluster" / "r" / "units"
    with local_cluster((1, 1), log_dir=tmp_path) as ray_cluster:
        run = [*common, "--executor", "ray", "--ray-address", ray_cluster.address,
               "--output", str(tmp_path / "cluster")]
        # killed (SIGKILL) once some units are committed: the next run keeps them
        killed = subprocess.Popen([sys.executable, "-m", "logicenveval", "run", *run],
                                  env={**os.environ, "PYTHONPATH": str(ROOT), **ray_cluster.env},
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + 300
        while killed.poll() is None and len(list(units.rglob("*.json"))) < 3 \
                and time.monotonic() < deadline:
            time.sleep(0.05)
        killed.kill()
        killed.wait(timeout=60)
        kept = len(list(units.rglob("*.json")))
        assert 3 <= kept < 20  # killed mid-run
        again = _cli(*run, env=ray_cluster.env)
        assert again.returncode == 0, again.stderr
        assert f"computed {20 - kept} unit(s), reused {kept}" in again.stdout  # none redone
        (units / "cot" / f"{tasks[0]}.json").unlink()  # a unit lost: only it is recomputed
        last = _cli(*run, env=ray_cluster.env)
        assert last.returncode == 0, last.stderr
        assert "computed 1 unit(s), reused 19" in last.stdout
        # a managed llama.cpp model (the stand-in server): one server per node, none here; the
        # replies the units added reach the driver's reply cache
        gguf = tmp_path / "tiny-model.gguf"
        gguf.write_bytes(b"GGUF" + bytes(60))
        model = ["--model", f"llamacpp:{gguf}", "--model-args", f"server={FAKE},threads=1",
                 "--tasks", TASKS[0], "--generators", "holodeck,cot", "--brief", "roles",
                 "--quiet", "--run-id", "m"]
        on_cluster = _cli(*model, "--executor", "ray", "--ray-address", ray_cluster.address,
                          "--output", str(tmp_path / "mc"), env=ray_cluster.env)
        assert on_cluster.returncode in (0, 1), on_cluster.stderr  # `{}` is no valid reply
        servers = [int(line) for line in starts.read_text().split()]
        assert len(servers) == 2  # one per node
    for pid in servers:  # stopped with the run
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)
    here = _cli(*model, "--workers", "2", "--output", str(tmp_path / "ml"))
    assert here.returncode in (0, 1), here.stderr
    assert _cache_keys(tmp_path / "mc") == _cache_keys(tmp_path / "ml") != set()
    assert _figures(tmp_path / "mc" / "m") == _figures(tmp_path / "ml" / "m")
    assert _figures(tmp_path / "cluster" / "r") == _figures(tmp_path / "local" / "r")
    assert _files(tmp_path / "cluster" / "r") == _files(tmp_path / "local" / "r")
    details = sorted(p.name for p in (tmp_path / "cluster" / "r" / "details").rglob("*.html"))
    assert details == sorted(p.name for p in (tmp_path / "local" / "r" / "details").rglob("*.html"))


def test_evaluate_refuses_a_cluster_address(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("ray")
    from logicenveval.cli import main

    monkeypatch.setenv("RAY_ADDRESS", f"127.0.0.1:{_closed_port()}")
    envs = ROOT / "reports" / "reference" / "envs" / "holodeck"
    assert main(["evaluate", str(envs), "--executor", "ray", "--output", str(tmp_path)]) == 2
    assert "evaluate runs on this machine only" in capsys.readouterr().err
