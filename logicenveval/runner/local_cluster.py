"""A Ray cluster of several nodes on this machine, for tests and measurements (docs/cluster.md).

Each node is one `ray start --block` process with its own CPU count and temp folder: stopping
that process (SIGTERM) stops the node's Ray processes, so the cluster is torn down by the PIDs
it started, never by `ray stop` (which would stop every Ray instance of the machine's user). The
cluster gets a token of its own (`RAY_AUTH_TOKEN`, Ray's token authentication), so it neither
reads nor writes `~/.ray/auth_token`; `env` holds what a driver needs to connect.
"""

from __future__ import annotations

import contextlib
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from logicenveval.errors import ConfigError

#: each node's object store (bytes): small, this is a test cluster on a shared machine
OBJECT_STORE_BYTES = 100_000_000
#: how long a node may take to start (s)
START_TIMEOUT = 120.0


@dataclass(frozen=True)
class LocalCluster:
    address: str  # HOST:PORT of the head node (`--ray-address`)
    env: dict[str, str]  # the environment a driver connects with (the cluster's token)
    pids: tuple[int, ...]  # the `ray start --block` process of each node


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _ray_command() -> list[str]:
    ray = shutil.which("ray") or str(Path(sys.executable).with_name("ray"))
    if not Path(ray).exists():
        raise ConfigError("the `ray` command is not installed", field="--executor ray",
                          hint="pip install -e '.[ray]'")
    return [ray]


def _wait_for_nodes(address: str, env: dict[str, str], count: int, deadline: float) -> None:
    """Until the cluster lists `count` alive nodes (asked through `ray status`)."""
    while time.monotonic() < deadline:
        done = subprocess.run([*_ray_command(), "status", f"--address={address}"], env=env,
                              capture_output=True, text=True, timeout=60, check=False)
        if done.returncode == 0 and done.stdout.count("node_") >= count:
            return
        time.sleep(1.0)
    raise TimeoutError(f"the local Ray cluster at {address} did not list {count} nodes in time")


@contextlib.contextmanager
def local_cluster(cpus: Sequence[int] = (1, 1), *, log_dir: Path | None = None) -> Iterator[LocalCluster]:
    """Start a head node and one worker node per further entry of `cpus` (their CPU counts),
    yield the cluster, stop every node it started however the block ends."""
    # short, so under /tmp even when TMPDIR is deep: Ray's socket paths (~107 bytes) live in it
    root = Path(tempfile.mkdtemp(prefix="lee-ray-", dir="/tmp" if Path("/tmp").is_dir() else None))
    logs = log_dir or root
    port = _free_port()
    address = f"127.0.0.1:{port}"
    env = {**os.environ, "RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN": secrets.token_hex(32),
           "RAY_USAGE_STATS_ENABLED": "0"}
    env.pop("RAY_ADDRESS", None)
    common = ["--block", "--node-ip-address=127.0.0.1", "--disable-usage-stats",
              f"--object-store-memory={OBJECT_STORE_BYTES}"]
    procs: list[subprocess.Popen[bytes]] = []
    try:
        for i, n in enumerate(cpus):
            role = ["--head", f"--port={port}", "--include-dashboard=false"] if i == 0 \
                else [f"--address={address}"]
            with (logs / f"ray-node{i}.log").open("wb") as log:
                procs.append(subprocess.Popen(
                    [*_ray_command(), "start", *role, f"--num-cpus={n}",
                     f"--temp-dir={root / f'n{i}'}", *common],
                    env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True))
            _wait_for_nodes(address, env, i + 1, time.monotonic() + START_TIMEOUT)
        yield LocalCluster(address=address, env={k: env[k] for k in ("RAY_AUTH_MODE", "RAY_AUTH_TOKEN")},
                           pids=tuple(p.pid for p in procs))
    finally:
        for proc in reversed(procs):  # workers first, the head last
            with contextlib.suppress(ProcessLookupError):
                proc.send_signal(signal.SIGTERM)
            try:
                proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                with contextlib.suppress(ProcessLookupError):
                    os.killpg(proc.pid, signal.SIGKILL)  # the node's own session
                proc.wait(timeout=10)
        shutil.rmtree(root, ignore_errors=True)
