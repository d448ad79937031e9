"""Fault injection (issue 20): a 10-task run with 2 workers against a loopback server that fails,
hangs, trickles and echoes the API key by turns. The run ends within bounded time, the key is in
no file of the run folder or cache, and a second run after the server is fixed recomputes exactly
the failed units. Only 127.0.0.1 is contacted.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from loopback import Loopback, messages_key

from logicenveval.benchmark import load_task, task_ids
from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.base import GenerationContext, make_generator, unit_seed
from logicenveval.llm.base import ChatRequest
from logicenveval.offline.model import OfflineModel

SECRET = "sk-fault-injection-SECRET-abcdef0123456789"
GENERATOR = "cot"  # one request per unit: each fault maps to one unit
TASKS = task_ids()[:10]


class Recorder:
    """The offline model, remembering each reply under the hash of its request's messages."""

    name = "offline"

    def __init__(self) -> None:
        self.inner = OfflineModel()
        self.replies: dict[str, str] = {}

    def complete(self, request: ChatRequest) -> str:
        reply = self.inner.complete(request)
        self.replies[messages_key(request.messages)] = reply
        return reply


@pytest.fixture(scope="module")
def recorded(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    """Good replies for the 10 tasks, recorded from the offline model with each unit's seed."""
    rec = Recorder()
    work = tmp_path_factory.mktemp("rec")
    for task_id in TASKS:
        ctx = GenerationContext(model=rec, catalog=load_catalog(), seed=0, work_dir=work,
                                rng=np.random.default_rng(unit_seed(0, GENERATOR, task_id)))
        make_generator(GENERATOR).generate(load_task(task_id).brief(), ctx)
    assert len(rec.replies) == len(TASKS)
    return rec.replies


def _run(out: Path, url: str, *extra: str) -> subprocess.CompletedProcess[str]:
    argv = [sys.executable, "-m", "logicenveval", "run", "--model", "openai:fake-model",
            "--model-args", f"base_url={url},api_key_env=FAULT_KEY,timeout=2,max_retries=0",
            "--generators", GENERATOR, "--tasks", ",".join(TASKS), "--workers", "2",
            "--brief", "roles", "--output", str(out), "--quiet", *extra]  # one recorded reply per task
    proc = subprocess.run(argv, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "FAULT_KEY": SECRET})
    assert "Traceback" not in proc.stdout + proc.stderr
    assert SECRET not in proc.stdout + proc.stderr
    return proc


def _units(run_dir: Path) -> dict[str, dict[str, object]]:
    return {p.stem: json.loads(p.read_text())["unit"]
            for p in sorted((run_dir / "units" / GENERATOR).glob("*.json"))}


def test_faulty_server_run(tmp_path: Path, recorded: dict[str, str]) -> None:
    out = tmp_path / "out"
    cache = ["--cache", str(out / "cache.sqlite"), "--run-id", "faulty"]
    with Loopback(replies=recorded, modes=["ok", "fail", "hang", "trickle", "echo"],
                  hang_s=10, trickle_s=0.3) as server:
        first = _run(out, server.url, *cache, "--max-infra-failures", "0")
        assert first.returncode == 0, first.stderr
        assert server.posts == len(TASKS)
        assert {"fail", "hang", "trickle", "echo"} <= set(server.seen)
        run_dir = out / "faulty"
        units = _units(run_dir)
        assert len(units) == len(TASKS)
        failed = {t for t, u in units.items() if u["error"]}
        assert failed and all(units[t]["error_kind"] == "infrastructure" for t in failed)
        assert len(failed) == sum(m in ("fail", "hang", "trickle") for m in server.seen)
        kept = {t: (run_dir / "units" / GENERATOR / f"{t}.json").read_bytes()
                for t in units if t not in failed}

        for path in out.rglob("*"):  # results, units, envs, plans, leaderboards, cache + WAL
            if path.is_file():
                assert SECRET.encode() not in path.read_bytes(), path
                assert b"Bearer sk-" not in path.read_bytes(), path

        server.set_modes(["ok"])
        before = server.posts
        second = _run(out, server.url, *cache, "--max-infra-failures", "0")
        assert second.returncode == 0, second.stderr
        assert f"computed {len(failed)} unit(s), reused {len(TASKS) - len(failed)}" in second.stdout
        assert server.posts - before == len(failed)  # exactly the failed units asked again
        units = _units(run_dir)
        assert not any(u["error"] for u in units.values())
        for t, blob in kept.items():
            assert (run_dir / "units" / GENERATOR / f"{t}.json").read_bytes() == blob


def test_run_stops_after_consecutive_infrastructure_failures(tmp_path: Path) -> None:
    with Loopback(modes=["fail"]) as server:
        proc = _run(tmp_path, server.url, "--no-cache", "--max-infra-failures", "3", "--workers", "1")
        assert proc.returncode == 1
        assert "stopped after 3 consecutive infrastructure failures" in proc.stderr
        assert "HTTP 500" in proc.stderr
        assert server.posts < len(TASKS)  # queued units were dropped, not run
    units = list(tmp_path.rglob("units/*/*.json"))
    assert 3 <= len(units) < len(TASKS)


def _children(pid: int) -> set[int]:
    out = set()
    for status in Path("/proc").glob("[0-9]*/status"):
        try:
            fields = dict(line.split(":\t", 1) for line in status.read_text().splitlines() if ":\t" in line)
        except OSError:
            continue
        if fields.get("PPid", "").strip() == str(pid):
            out.add(int(status.parent.name))
    return out


def _cmdline(pid: int) -> bytes:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return b""


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="needs /proc (Linux)")
def test_workers_die_with_a_killed_run(tmp_path: Path) -> None:
    """SIGKILL of `run` leaves no orphaned pool worker behind (issue 20, item 13)."""
    import signal
    import time

    cmd = [sys.executable, "-m", "logicenveval", "run", "--generators", "logicenvgen", "--tasks",
           ",".join(TASKS[:6]), "--workers", "2", "--output", str(tmp_path), "--quiet"]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    workers: set[int] = set()
    for _ in range(600):  # until both workers have started (bounded: 60 s)
        helpers = {c for c in _children(proc.pid) if b"multiprocessing" in _cmdline(c)}
        pool = {g for c in helpers for g in _children(c)}  # workers forked by the fork server
        direct = {c for c in helpers if b"spawn_main" in _cmdline(c)}  # or spawned directly
        workers = helpers | pool
        if len(pool | direct) >= 2:
            break
        time.sleep(0.1)
    assert len(workers) >= 2
    time.sleep(1.0)  # let the workers run their initializer
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    for _ in range(100):
        alive = {w for w in workers if Path(f"/proc/{w}").exists()
                 and "zombie" not in Path(f"/proc/{w}/status").read_text()}
        if not alive:
            break
        time.sleep(0.1)
    assert not alive
    # a worker killed between writing a temp file and renaming it cannot clean up after SIGKILL;
    # the resumed run removes such leftovers and finishes
    resumed = subprocess.run(cmd, capture_output=True, text=True)
    assert resumed.returncode == 0, resumed.stderr
    assert not list(tmp_path.rglob("*.tmp"))
