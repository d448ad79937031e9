"""Executors that run independent units, registered by name with lazy import.

All executors run the same picklable unit function and yield `(item, result)` pairs as units
finish, so the caller commits each unit as soon as it is done, whatever the executor.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import importlib
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from typing import Any, Protocol, TypeVar

from logicenveval.errors import ConfigError

T = TypeVar("T")
R = TypeVar("R")


class Executor(Protocol):
    name: str

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T]) -> Iterator[tuple[T, R]]: ...


class InProcessExecutor:
    """Runs units one after another in this process (debugging, profiling)."""

    name = "inprocess"

    def __init__(self, workers: int = 1) -> None:
        self.workers = 1

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T]) -> Iterator[tuple[T, R]]:
        for item in items:
            yield item, fn(item)


#: imported once in the fork server, so that every worker starts with them loaded
PRELOAD: tuple[str, ...] = ("logicenveval.runner.preload",)


def _context() -> multiprocessing.context.BaseContext:
    """A fork server where the platform has one (Linux, macOS), else spawn.

    Forking the main process is not safe (it runs the progress thread); the fork server is a
    clean single-threaded process that imports the heavy modules once and forks workers from
    that state, so a worker costs a fork instead of a fresh interpreter and ~2 s of imports.
    """
    if "forkserver" in multiprocessing.get_all_start_methods():
        ctx = multiprocessing.get_context("forkserver")
        ctx.set_forkserver_preload(list(PRELOAD))
        return ctx
    return multiprocessing.get_context("spawn")


class ProcessExecutor:
    """A pool of worker processes started once per run from a preloaded fork server.

    Units are handed out one at a time as workers free up: a unit takes 30 ms to a few seconds,
    far more than the ~1 ms a hand-off costs, so larger chunks would only lengthen the tail.
    The caller lists the expensive units first (longest processing time first).
    """

    name = "process"

    def __init__(self, workers: int = 1) -> None:
        self.workers = max(1, workers)
        self._ctx: multiprocessing.context.BaseContext | None = None

    def warm_up(self) -> None:
        """Start the fork server now, so its imports overlap the caller's own start-up work."""
        if self.workers > 1 and self._ctx is None:
            self._ctx = _context()
            if self._ctx.get_start_method() == "forkserver":
                from multiprocessing import forkserver

                forkserver.ensure_running()

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T]) -> Iterator[tuple[T, R]]:
        if self.workers == 1 or len(items) <= 1:
            yield from InProcessExecutor().map_unordered(fn, items)
            return
        self.warm_up()
        ctx = self._ctx or _context()
        pool = ProcessPoolExecutor(max_workers=min(self.workers, len(items)), mp_context=ctx,
                                   initializer=_die_with_parent)
        try:
            pending: dict[Future[R], T] = {pool.submit(fn, item): item for item in items}
            while pending:
                done, _ = wait(pending, return_when=FIRST_COMPLETED)
                for fut in done:
                    item = pending.pop(fut)
                    yield item, fut.result()
        finally:  # also when the caller stops early: queued units are dropped, not run
            pool.shutdown(wait=True, cancel_futures=True)


def kill_me_with_parent() -> None:
    """Ask Linux to SIGKILL this process when its parent dies (PR_SET_PDEATHSIG; no-op elsewhere).

    Also used by the fork server (runner/preload.py), so that it exits with the run and its
    workers follow."""
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
            libc.prctl(1, signal.SIGKILL)


def _die_with_parent() -> None:
    """Worker initializer: a worker never outlives the run (even a SIGKILLed one).

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


class RayExecutor:
    """Ray tasks, for users with a cluster (`pip install -e '.[ray]'`)."""

    name = "ray"

    def __init__(self, workers: int = 1, address: str | None = None) -> None:
        try:
            self._ray: Any = importlib.import_module("ray")
        except ModuleNotFoundError:
            raise ConfigError("the ray executor needs Ray", field="--executor",
                              hint="pip install -e '.[ray]'") from None
        self.workers = workers
        self.address = address

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T]) -> Iterator[tuple[T, R]]:
        ray = self._ray
        started_here = not ray.is_initialized()
        if started_here:
            ray.init(address=self.address, num_cpus=None if self.address else self.workers,
                     include_dashboard=False, log_to_driver=False)
        try:
            remote = ray.remote(fn)
            pending = {remote.remote(item): item for item in items}
            while pending:
                done, _ = ray.wait(list(pending), num_returns=1)
                for ref in done:
                    yield pending.pop(ref), ray.get(ref)
        finally:
            if started_here:
                ray.shutdown()


_EXECUTORS: dict[str, str] = {
    "inprocess": "logicenveval.runner.executors:InProcessExecutor",
    "process": "logicenveval.runner.executors:ProcessExecutor",
    "ray": "logicenveval.runner.executors:RayExecutor",
}


def make_executor(name: str, workers: int) -> Executor:
    if name not in _EXECUTORS:
        raise ConfigError(f"unknown executor {name!r}", field="--executor",
                          hint="use one of " + ", ".join(sorted(_EXECUTORS)))
    module, attr = _EXECUTORS[name].split(":")
    executor: Executor = getattr(importlib.import_module(module), attr)(workers=workers)
    return executor
