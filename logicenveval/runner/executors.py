"""Executors that run independent units, registered by name with lazy import.

All executors run the same picklable unit function and yield `(item, result)` pairs as units
finish, so the caller commits each unit as soon as it is done, whatever the executor.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import gc
import importlib
import logging
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections import deque
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from typing import Any, Protocol, TypeVar

from logicenveval.errors import ConfigError

T = TypeVar("T")
R = TypeVar("R")


#: how long (s) an item may run in a worker process before the pool is stopped; None = no bound
Budget = Callable[[Any], "float | None"]
#: the result standing for an item whose worker process died (killed, out of memory, timed out)
OnCrash = Callable[[Any, str], Any]


class Executor(Protocol):
    name: str
    workers: int  # units at a time (a Ray executor's: its cluster's CPUs, once started)

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T], *,
                      budget: Budget | None = None, on_crash: OnCrash | None = None,
                      split: Callable[[T], Sequence[T]] | None = None) -> Iterator[tuple[T, R]]: ...


class InProcessExecutor:
    """Runs units one after another in this process (debugging, profiling; the process
    executor never runs units here, even with one worker or one unit).

    Nothing can stop a unit from outside here: a unit that never returns holds the run (the
    runner's in-unit time bound, `runner.unit`, stops Python code that returns to the
    interpreter; the process executor also kills a worker)."""

    name = "inprocess"

    def __init__(self, workers: int = 1) -> None:
        self.workers = 1

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T], *,
                      budget: Budget | None = None, on_crash: OnCrash | None = None,
                      split: Callable[[T], Sequence[T]] | None = None) -> Iterator[tuple[T, R]]:
        for item in items:
            yield item, fn(item)


#: imported once in the fork server, so that every worker starts with them loaded
PRELOAD: tuple[str, ...] = ("logicenveval.runner.preload",)
#: modules of higher layers the fork server imports too (`prestart`'s `preload`: the command
#: layer's report page, which every unit's `on_commit` hook writes)
_MORE_PRELOAD: list[str] = []
#: exit status of a worker whose unit ignored its time bound (`runner.unit`'s watchdog)
EXIT_TIMED_OUT = 86


def _context() -> multiprocessing.context.BaseContext:
    """A fork server where the platform has one (Linux, macOS), else spawn.

    Forking the main process is not safe (it runs the progress thread); the fork server is a
    clean single-threaded process that imports the heavy modules once and forks workers from
    that state, so a worker costs a fork instead of a fresh interpreter and ~2 s of imports.
    """
    if "forkserver" in multiprocessing.get_all_start_methods():
        ctx = multiprocessing.get_context("forkserver")
        ctx.set_forkserver_preload([*PRELOAD, *_MORE_PRELOAD])
        return ctx
    return multiprocessing.get_context("spawn")


#: thread pools of native libraries, one thread per worker: the workers are the parallelism
SINGLE_THREADED = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


@contextlib.contextmanager
def single_threaded_children() -> Iterator[None]:
    """Processes started in the block (the fork server, spawned workers) size their native
    thread pools to one thread, unless the user set the variable; this process is unchanged.
    (CP-SAT is given `num_workers=1` and Z3 runs one thread where they are called.)"""
    added = [k for k in SINGLE_THREADED if k not in os.environ]
    os.environ.update({k: "1" for k in added})
    try:
        yield
    finally:
        for k in added:
            os.environ.pop(k, None)


def _death(codes: Sequence[int | None]) -> str:
    """Why the worker processes of a broken pool died, from their exit statuses."""
    # the pool itself SIGTERMs the survivors of a broken pool: the cause is another status
    dead = sorted({c for c in codes if c not in (None, 0)}, key=lambda c: (c == -signal.SIGTERM, c))
    if EXIT_TIMED_OUT in dead:
        return "the unit ignored its time bound (--unit-timeout), so its worker was stopped"
    for code in dead:
        if code is not None and code < 0:
            try:
                name = signal.Signals(-code).name
            except ValueError:
                name = f"signal {-code}"
            oom = " (as the out-of-memory killer does)" if -code == signal.SIGKILL else ""
            return f"its worker process was killed by {name}{oom}"
    if dead:
        return f"its worker process exited with status {dead[0]}"
    if codes and all(c == 0 for c in codes):  # os._exit(0) in the unit: no exception, no result
        return "its worker process exited with status 0 before the unit finished"
    return "its worker process died"


class _Pool:
    """One ProcessPoolExecutor whose workers can be stopped at once (timeouts, interrupts)."""

    def __init__(self, ctx: multiprocessing.context.BaseContext, workers: int) -> None:
        self.workers = workers
        self.pool = ProcessPoolExecutor(max_workers=workers, mp_context=ctx,
                                        initializer=_worker_init)

    def processes(self) -> list[multiprocessing.process.BaseProcess]:
        procs: dict[int, multiprocessing.process.BaseProcess] = getattr(self.pool, "_processes", None) or {}
        return list(procs.values())

    def exit_codes(self) -> list[int | None]:
        """The workers' exit statuses, once the broken pool's own thread has reaped them.

        That thread stops and joins every worker of a broken pool; joining a worker from here at
        the same time races it (two readers of the fork server's one status message: the loser
        sees end-of-file and reports 255, CPython gh-130895), so this waits for it instead."""
        manager: threading.Thread | None = getattr(self.pool, "_executor_manager_thread", None)
        if manager is not None:
            manager.join(5)
            if manager.is_alive():  # a worker outlives SIGTERM and holds the pool's own join
                self.kill()
                manager.join(5)
        out = []
        for p in self.processes():
            if manager is None or manager.is_alive():
                p.join(0.5)  # nothing else reaps it
            out.append(p.exitcode)
        return out

    def kill(self) -> None:
        for p in self.processes():
            with contextlib.suppress(OSError, ValueError, AttributeError):
                p.kill()

    def close(self, *, kill: bool) -> None:
        """Shut down; with `kill`, running units are stopped instead of awaited (an interrupt,
        a caller that stopped early), so this never waits for a unit that does not return."""
        if kill:
            self.kill()
        self.pool.shutdown(wait=not kill, cancel_futures=True)
        if kill:
            for p in self.processes():
                p.join(5)


class ProcessExecutor:
    """A pool of worker processes started once per run from a preloaded fork server.

    Units are handed out one at a time as workers free up: a unit takes 30 ms to a few seconds,
    far more than the ~1 ms a hand-off costs, so larger chunks would only lengthen the tail.
    The caller lists the expensive units first (longest processing time first).

    A worker that dies (the out-of-memory killer, a crash in native code, a unit that outlived
    its `budget` and was stopped) breaks the pool; the items it was running are then re-run
    one per fresh process (`split` into smaller items first), so the item that kills its worker
    again gets `on_crash`'s result with the reason, and every other item completes.
    """

    name = "process"

    def __init__(self, workers: int = 1) -> None:
        self.workers = max(1, workers)
        self._ctx: multiprocessing.context.BaseContext | None = None

    def warm_up(self) -> None:
        """Start the fork server now, so its imports overlap the caller's own start-up work."""
        if self._ctx is None:
            self._ctx = _context()
            if self._ctx.get_start_method() == "forkserver":
                from multiprocessing import forkserver

                with single_threaded_children():
                    forkserver.ensure_running()

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T], *,
                      budget: Budget | None = None, on_crash: OnCrash | None = None,
                      split: Callable[[T], Sequence[T]] | None = None) -> Iterator[tuple[T, R]]:
        if not items:  # every unit runs in a worker, whatever the workers and units: a unit
            return  # that calls os._exit or blocks the alarm cannot take the run with it
        self.warm_up()
        ctx = self._ctx or _context()
        queue: deque[T] = deque(items)
        while queue:
            suspects: list[T] = []
            yield from self._round(ctx, fn, queue, budget, on_crash, suspects)
            isolated = [part for s in suspects for part in (split(s) if split else (s,))]
            yield from self._isolated(ctx, fn, isolated, budget, on_crash)

    def _round(self, ctx: multiprocessing.context.BaseContext, fn: Callable[[T], R], queue: deque[T],
               budget: Budget | None, on_crash: OnCrash | None,
               suspects: list[T]) -> Iterator[tuple[T, R]]:
        """Run queued items on one pool until the queue is empty or the pool breaks.

        When a deadline passes, the pool is stopped: the overdue items get `on_crash`, the
        others go back to the queue. When a worker dies otherwise, the items the pool was
        running become `suspects` (one of them killed it; `_isolated` finds which)."""
        pool = _Pool(ctx, min(self.workers, len(queue)))
        running: dict[Future[R], tuple[T, float | None]] = {}
        overdue: set[Future[R]] = set()
        stopped = True

        def fill() -> None:  # one item per worker, so a broken pool tells which items it lost
            while queue and not overdue and len(running) < pool.workers:
                item = queue.popleft()
                limit = budget(item) if budget else None
                try:
                    fut = pool.pool.submit(fn, item)
                except BrokenProcessPool:  # broke since the last result: the next round retries it
                    queue.appendleft(item)
                    return
                running[fut] = (item, None if limit is None else time.monotonic() + limit)

        try:
            while queue or running:
                fill()
                if not running:  # the pool broke with none of our items on it
                    return
                deadlines = [d for _, d in running.values() if d is not None]
                wait_s = max(0.0, min(deadlines) - time.monotonic()) if deadlines else None
                done, _ = wait(running, timeout=wait_s, return_when=FIRST_COMPLETED)
                if not done:  # a deadline passed: stop the pool (nothing else stops native code)
                    now = time.monotonic()
                    overdue |= {f for f, (_, d) in running.items() if d is not None and d <= now}
                    pool.kill()
                    continue
                lost: list[tuple[Future[R], T]] = []
                finished: list[tuple[Future[R], T]] = []
                for fut in done:
                    item, _ = running.pop(fut)
                    (lost if isinstance(fut.exception(), BrokenProcessPool) else finished).append((fut, item))
                if not lost:
                    fill()  # the next items start before the caller commits these results
                for fut, item in finished:
                    yield item, fut.result()
                if not lost:
                    continue
                lost += [(fut, item) for fut, (item, _) in running.items()]  # gone with the pool
                running.clear()
                codes = pool.exit_codes()
                if not overdue and (len(lost) == 1 or codes.count(EXIT_TIMED_OUT) == len(lost)):
                    # it ran alone, or every worker that ran one ended itself at its time bound
                    for _, item in lost:
                        yield item, _crashed(on_crash, item, _death(codes))
                    return
                for fut, item in lost:
                    if fut in overdue:
                        yield item, _crashed(on_crash, item, "the unit did not finish within its "
                                             "time budget, so its worker was stopped")
                    elif overdue:
                        queue.appendleft(item)  # the culprit is known: re-run the others
                    else:
                        suspects.append(item)
                return
            stopped = False
        finally:  # also when the caller stops early or the user interrupts: stop, never wait
            pool.close(kill=stopped)

    def _isolated(self, ctx: multiprocessing.context.BaseContext, fn: Callable[[T], R],
                  items: list[T], budget: Budget | None,
                  on_crash: OnCrash | None) -> Iterator[tuple[T, R]]:
        """Each item in a process of its own (several at a time), to find the one that kills it."""
        queue = deque(items)
        running: dict[Future[R], tuple[T, _Pool, float | None]] = {}
        try:
            while queue or running:
                while queue and len(running) < self.workers:
                    item = queue.popleft()
                    pool = _Pool(ctx, 1)
                    limit = budget(item) if budget else None
                    running[pool.pool.submit(fn, item)] = (item, pool, None if limit is None else
                                                           time.monotonic() + limit)
                deadlines = [d for _, _, d in running.values() if d is not None]
                wait_s = max(0.0, min(deadlines) - time.monotonic()) if deadlines else None
                done, _ = wait(running, timeout=wait_s, return_when=FIRST_COMPLETED)
                if not done:
                    now = time.monotonic()
                    for fut, (item, pool, d) in list(running.items()):
                        if d is not None and d <= now:
                            del running[fut]
                            pool.close(kill=True)
                            yield item, _crashed(on_crash, item, "the unit did not finish within "
                                                 "its time budget, so its worker was stopped")
                    continue
                for fut in done:
                    item, pool, _ = running.pop(fut)
                    if isinstance(fut.exception(), BrokenProcessPool):
                        why = _death(pool.exit_codes())
                        pool.close(kill=True)
                        yield item, _crashed(on_crash, item, why)
                    else:
                        pool.close(kill=False)
                        yield item, fut.result()
        finally:
            for _, pool, _ in running.values():
                pool.close(kill=True)


def _crashed(on_crash: OnCrash | None, item: Any, why: str) -> Any:
    if on_crash is None:
        raise BrokenProcessPool(why)
    return on_crash(item, why)


def kill_me_with_parent() -> None:
    """Ask Linux to SIGKILL this process when its parent dies (PR_SET_PDEATHSIG; no-op elsewhere).

    Also used by the fork server (runner/preload.py), so that it exits with the run and its
    workers follow."""
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
            libc.prctl(1, signal.SIGKILL)


#: a worker's collector thresholds (CPython's default: 700, 10, 10). A unit allocates millions
#: of short-lived objects (episodes, geometry, models): with the default the collector ran
#: ~1,800 times per default run and took ~5 % of the units' CPU; this takes about half of that
WORKER_GC_THRESHOLD = (5000, 20, 20)


def _worker_init() -> None:
    """Worker initializer: die with the run; leave Ctrl-C to the run, which stops the workers
    (a terminal's SIGINT reaches the whole process group); collect garbage less often."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    global IN_WORKER
    IN_WORKER = True
    gc.set_threshold(*WORKER_GC_THRESHOLD)
    _die_with_parent()


#: True in a pool worker (`runner.unit` may then end the process when a unit ignores its bound)
IN_WORKER = False


def _die_with_parent() -> None:
    """A worker never outlives the run (even a SIGKILLed one).

    The worker's parent is the run itself or its fork server, which exits with the run. Linux
    delivers SIGKILL to the worker when that parent dies (prctl PDEATHSIG); elsewhere a daemon
    thread notices the re-parenting within a second and exits.
    """
    parent = os.getppid()
    kill_me_with_parent()
    if parent == 1 or os.getppid() != parent:  # the parent died before the call took effect
        os._exit(1)

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(1.0)
        os._exit(1)

    threading.Thread(target=watch, daemon=True, name="die-with-parent").start()


#: seconds a cluster address may take to accept a TCP connection before it is called unreachable
#: (Ray itself retries an unreachable address for minutes before it gives up)
RAY_CONNECT_TIMEOUT = 5.0


def ray_address(address: str | None) -> str | None:
    """The cluster to connect to: `--ray-address`, else `RAY_ADDRESS`, else None (a local Ray
    instance is started for the run)."""
    return address or os.environ.get("RAY_ADDRESS") or None


def check_reachable(address: str, timeout: float = RAY_CONNECT_TIMEOUT) -> None:
    """A `host:port` address that accepts no TCP connection within `timeout` is one clear error
    (`auto` and `ray://` addresses are left to Ray, which reports them at once)."""
    if address == "auto" or "://" in address:
        return
    host, sep, port = address.rpartition(":")
    if not sep or not host or not port.isdigit():
        raise ConfigError(f"the Ray address {address!r} is not HOST:PORT", field="--ray-address",
                          hint=_ADDRESS_HINT)
    import socket

    try:
        with socket.create_connection((host.strip("[]"), int(port)), timeout=timeout):
            pass
    except (OSError, ValueError) as exc:
        raise ConfigError(f"no Ray cluster answers at {address} ({exc.__class__.__name__}: "
                          f"{exc})", field="--ray-address", hint=_ADDRESS_HINT) from None


#: seconds a node may take to run the start-up probe (the first use of a run's code on a node
#: sets up its `runtime_env`: unpacking the shipped project)
PROBE_TIMEOUT = 600.0

_ADDRESS_HINT = ("start the head node with `ray start --head --port=6379` and pass the address it "
                 "prints (--ray-address HOST:6379 or RAY_ADDRESS=HOST:6379); a cluster with token "
                 "authentication also needs its token here (RAY_AUTH_MODE=token and RAY_AUTH_TOKEN, "
                 "or ~/.ray/auth_token); see docs/cluster.md")


class RayExecutor:
    """Ray tasks on a cluster (`--ray-address`/`RAY_ADDRESS`) or on a local Ray instance started
    for the run (`pip install -e '.[ray]'`; docs/cluster.md).

    Connected to a cluster it takes its size from the cluster (its CPUs: one unit per CPU at a
    time) and passes none of the local-only arguments Ray refuses for a cluster (`num_cpus`).
    Ray workers may run on other machines: the caller ships what they need through `start`
    (`runtime_env`: the code; `shared`: data every task receives, put in the object store once)
    and has each task hand its files back (runner.cluster)."""

    name = "ray"

    def __init__(self, workers: int = 1, address: str | None = None) -> None:
        try:
            self._ray: Any = importlib.import_module("ray")
        except ModuleNotFoundError:
            raise ConfigError("the ray executor needs Ray", field="--executor",
                              hint="pip install -e '.[ray]'") from None
        self.workers = max(1, workers)
        self.address = ray_address(address)
        self._started_here = False
        self._shared: list[Any] = []
        self._setup: Setup | None = None

    def start(self, *, runtime_env: dict[str, Any] | None = None, shared: Any = None,
              setup: Setup | None = None) -> None:
        """Connect (or start the local instance) with `runtime_env`, then size the executor from
        the cluster. `shared` goes to the object store once; a task's worker runs
        `setup(key, load)` before its item (`load()` fetches `shared`, `key` names it: a worker
        that already has it need not fetch it again). `setup` is a module-level function."""
        ray = self._ray
        if not ray.is_initialized():
            if self.address is not None:
                check_reachable(self.address)
            local = {} if self.address is not None else {"num_cpus": self.workers}
            try:
                ray.init(address=self.address, runtime_env=runtime_env or None,
                         include_dashboard=False, log_to_driver=False,
                         logging_level=logging.WARNING, **local)
            except (ConnectionError, RuntimeError, ValueError, TimeoutError) as exc:
                why = " ".join(f"{str(e).strip().splitlines()[0][:300]}" for e in (exc, exc.__cause__)
                               if e is not None and str(e).strip()) or type(exc).__name__
                raise ConfigError(f"cannot connect to the Ray cluster at "
                                  f"{self.address or 'a new local instance'}: {why}",
                                  field="--ray-address", hint=_ADDRESS_HINT) from None
            self._started_here = True
        cpus = int(ray.cluster_resources().get("CPU", 0))
        if cpus < 1:
            self.close()
            raise ConfigError(f"the Ray cluster at {self.address} has no CPU to run units on",
                              field="--ray-address",
                              hint="start its nodes with --num-cpus=N (N >= 1)")
        self.workers = cpus
        if shared is not None:
            self.share(shared, setup)

    def share(self, shared: Any, setup: Setup | None) -> None:
        """Put `shared` in the object store once for every later task's `setup` (`start`)."""
        self._shared = [self._ray.put(shared)]  # boxed: Ray leaves it unfetched in a task's args
        self._setup = setup

    def driver_ip(self) -> str:
        """This process's address as the cluster sees it."""
        return str(self._ray.util.get_node_ip_address())

    def nodes(self) -> list[dict[str, Any]]:
        """The cluster's alive nodes (Ray's `ray.nodes()` entries)."""
        return [n for n in self._ray.nodes() if n.get("Alive")]

    def on_each_node(self, fn: Callable[[], R]) -> list[tuple[str, R | BaseException]]:
        """`fn()` once on every alive node (the node's address, its result or what it raised),
        after the task's `setup`: a start-up probe that every node can run units."""
        ray = self._ray
        from ray.util.scheduling_strategies import NodeAffinitySchedulingStrategy

        remote = ray.remote(_ray_probe)
        refs = {}
        for node in self.nodes():
            strategy = NodeAffinitySchedulingStrategy(node_id=node["NodeID"], soft=False)
            where = f"{node.get('NodeManagerAddress', '?')} (node {node['NodeID'][:8]})"
            refs[where] = remote.options(
                num_cpus=0, scheduling_strategy=strategy, max_retries=0).remote(
                fn, self._setup, self._shared)
        out: list[tuple[str, R | BaseException]] = []
        for where, ref in refs.items():
            try:  # bounded: a node that never runs the probe is reported, not waited on forever
                out.append((where, ray.get(ref, timeout=PROBE_TIMEOUT)))
            except Exception as exc:  # the probe's own failure, wrapped by Ray
                out.append((where, getattr(exc, "cause", None) or exc))
        return out

    def close(self) -> None:
        """Disconnect (a local instance started for the run stops with it)."""
        if self._started_here:
            self._started_here = False
            self._ray.shutdown()

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T], *,
                      budget: Budget | None = None, on_crash: OnCrash | None = None,
                      split: Callable[[T], Sequence[T]] | None = None) -> Iterator[tuple[T, R]]:
        """A task whose worker dies gets `on_crash`'s result; one past its budget is cancelled."""
        ray = self._ray
        own = not ray.is_initialized()  # not started by the caller: started and closed here
        if own:
            self.start()
        pending: dict[Any, tuple[T, float | None]] = {}
        try:
            remote = ray.remote(_ray_call).options(max_retries=0)
            for item in items:
                limit = budget(item) if budget else None
                ref = remote.remote(fn, item, self._setup, self._shared)
                pending[ref] = (item, None if limit is None else time.monotonic() + limit)
            while pending:
                deadlines = [d for _, d in pending.values() if d is not None]
                wait_s = max(0.0, min(deadlines) - time.monotonic()) if deadlines else None
                done, _ = ray.wait(list(pending), num_returns=1, timeout=wait_s)
                if not done:
                    now = time.monotonic()
                    for ref, (item, d) in list(pending.items()):
                        if d is not None and d <= now:
                            ray.cancel(ref, force=True)
                            del pending[ref]
                            yield item, _crashed(on_crash, item, "the unit did not finish within "
                                                 "its time budget, so its task was cancelled")
                    continue
                for ref in done:
                    item, _ = pending.pop(ref)
                    try:
                        result = ray.get(ref)
                    except Exception as exc:  # the worker died (Ray wraps the cause)
                        result = _crashed(on_crash, item, f"its Ray worker failed: {type(exc).__name__}")
                    yield item, result
        finally:
            for ref in pending:  # stopped early (Ctrl-C, too many failures): drop the rest
                with contextlib.suppress(Exception):
                    ray.cancel(ref, force=True)
            if own:
                self.close()


#: a Ray task's set-up: (key naming the shared data, function fetching it) -> None
Setup = Callable[[str, Callable[[], Any]], None]


def _set_up(setup: Setup | None, shared: list[Any]) -> None:
    if setup is not None and shared:
        import ray

        ref = shared[0]
        setup(ref.hex(), lambda: ray.get(ref))


def _ray_call(fn: Callable[[T], R], item: T, setup: Setup | None, shared: list[Any]) -> R:
    """A Ray task: the caller's `setup` (`RayExecutor.start`), then `fn(item)`."""
    _set_up(setup, shared)
    return fn(item)


def _ray_probe(fn: Callable[[], R], setup: Setup | None, shared: list[Any]) -> R:
    """`_ray_call` of a function of no item (`RayExecutor.on_each_node`)."""
    _set_up(setup, shared)
    return fn()


_EXECUTORS: dict[str, str] = {
    "inprocess": "logicenveval.runner.executors:InProcessExecutor",
    "process": "logicenveval.runner.executors:ProcessExecutor",
    "ray": "logicenveval.runner.executors:RayExecutor",
}


def prestart(name: str, workers: int, preload: Sequence[str] = ()) -> None:
    """Start the fork server of a `process` executor at once, before the
    caller imports the run's own modules: the two import in parallel (about 1 s of a 2-worker
    run's wall on 2 cores, when the fork server was started only once the run was set up). A
    later executor reuses the running server; one unneeded (a resumed run with nothing left)
    costs nothing but a background process that ends with the caller. `preload`: modules the fork server
    imports besides `PRELOAD` (what the caller's `on_commit` hook needs), so that each worker
    does not import them on its first unit."""
    _MORE_PRELOAD[:] = preload
    if name == "process" and workers >= 1:
        ProcessExecutor(workers=workers).warm_up()


def make_executor(name: str, workers: int, *, ray_address: str | None = None) -> Executor:
    """The executor `name` (`ray_address`: the `ray` executor's cluster, `--ray-address`)."""
    if name not in _EXECUTORS:
        raise ConfigError(f"unknown executor {name!r}", field="--executor",
                          hint="use one of " + ", ".join(sorted(_EXECUTORS)))
    module, attr = _EXECUTORS[name].split(":")
    options: dict[str, Any] = {"address": ray_address} if name == "ray" else {}
    executor: Executor = getattr(importlib.import_module(module), attr)(workers=workers, **options)
    return executor
