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


class ProcessExecutor:
    """A pool of worker processes (spawned: safe with threads, SQLite and solvers)."""

    name = "process"

    def __init__(self, workers: int = 1) -> None:
        self.workers = max(1, workers)

    def map_unordered(self, fn: Callable[[T], R], items: Sequence[T]) -> Iterator[tuple[T, R]]:
        if self.workers == 1 or len(items) <= 1:
            yield from InProcessExecutor().map_unordered(fn, items)
            return
        ctx = multiprocessing.get_context("spawn")
        pool = ProcessPoolExecutor(max_workers=min(self.workers, len(items)), mp_context=ctx,
                                   initializer=_die_with_parent, initargs=(os.getpid(),))
        try:
            pending: dict[Future[R], T] = {pool.submit(fn, item): item for item in items}
            while pending:
                done, _ = wait(pending, return_when=FIRST_COMPLETED)
                for fut in done:
                    item = pending.pop(fut)
                    yield item, fut.result()
        finally:  # also when the caller stops early: queued units are dropped, not run
            pool.shutdown(wait=True, cancel_futures=True)


def _die_with_parent(parent: int) -> None:
    """Worker initializer: a worker never outlives the run (even a SIGKILLed one).

    Linux delivers SIGKILL to the worker when its parent dies (prctl PDEATHSIG); elsewhere a
    daemon thread notices the re-parenting within a second and exits.
    """
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
            libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    if os.getppid() != parent:  # the parent died before the call above took effect
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
