"""Where a unit's time goes: a per-thread stopwatch of named phases.

`benchmarks/run_scaling.py` prints these per phase (start-up, task loading, generation, layout,
physics, simulation, mutants, writing), so a slowdown names its phase. Phases nest exclusively:
entering `layout` inside `generation` pauses `generation`, so the phases of a unit add up to its
wall time. Timings only: nothing computed depends on them.
"""

from __future__ import annotations

import contextlib
import threading
import time
from collections.abc import Iterator


class _State(threading.local):
    def __init__(self) -> None:
        self.totals: dict[str, float] = {}
        self.stack: list[list[object]] = []  # [name, start of its current slice]


_STATE = _State()


@contextlib.contextmanager
def phase(name: str) -> Iterator[None]:
    """Count the time of the block to `name` (not to the phase it interrupts)."""
    state = _STATE
    now = time.perf_counter()
    if state.stack:
        _close(state, now)
    state.stack.append([name, now])
    try:
        yield
    finally:
        end = time.perf_counter()
        _close(state, end)
        state.stack.pop()
        if state.stack:
            state.stack[-1][1] = end


def _close(state: _State, now: float) -> None:
    name, since = state.stack[-1]
    assert isinstance(name, str) and isinstance(since, float)
    state.totals[name] = state.totals.get(name, 0.0) + now - since
    state.stack[-1][1] = now


@contextlib.contextmanager
def collect() -> Iterator[dict[str, float]]:
    """Count the block's phases apart: the dict yielded holds them when the block ends, and the
    enclosing phase counts the block's wall time as its own (a unit run in the run's own
    process keeps its phases in its record; the run's `units` phase is the time it took)."""
    state = _STATE
    saved = state.totals, state.stack
    state.totals, state.stack = {}, []
    out: dict[str, float] = {}
    try:
        yield out
    finally:
        out.update(take())
        state.totals, state.stack = saved


def take() -> dict[str, float]:
    """The seconds per phase counted in this thread since the last `take` (then reset), the
    time of phases still open included up to now."""
    state = _STATE
    if state.stack:
        _close(state, time.perf_counter())
    out = {k: round(v, 4) for k, v in sorted(state.totals.items())}
    state.totals = {}
    return out
