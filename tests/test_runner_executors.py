"""The process executor names why a worker died, from statuses read once and never raced."""

from __future__ import annotations

import os
import signal
import subprocess
import sys

import pytest

from logicenveval.runner.executors import EXIT_TIMED_OUT, ProcessExecutor, _death


def _dies_on_zero(item: int) -> int:
    if item == 0:
        os.kill(os.getpid(), signal.SIGKILL)
    return item


def test_a_killed_worker_is_named_by_its_signal_every_time() -> None:
    """The pool's own thread reaps a broken pool's workers; reading a status beside it used to
    lose the status to end-of-file now and then ("exited with status 255", about 1 in 30)."""
    executor = ProcessExecutor(2)
    reasons = []
    for _ in range(40):
        out = dict(executor.map_unordered(_dies_on_zero, [0, 1], on_crash=lambda item, why: why))
        assert out[1] == 1
        reasons.append(out[0])
    assert set(reasons) == {"its worker process was killed by SIGKILL (as the out-of-memory killer does)"}


@pytest.mark.parametrize("codes,reason", [
    ([-signal.SIGTERM, EXIT_TIMED_OUT], "the unit ignored its time bound"),
    ([-signal.SIGTERM, -signal.SIGKILL], "killed by SIGKILL"),
    ([-signal.SIGTERM], "killed by SIGTERM"),
    ([0, 3], "exited with status 3"),
    ([None, 0], "its worker process died"),
    ([0], "exited with status 0 before the unit finished"),  # os._exit(0) in a generator
])
def test_the_cause_is_not_the_pools_own_sigterm(codes: list[int | None], reason: str) -> None:
    assert reason in _death(codes)


def _gc_threshold(item: int) -> tuple[int, ...]:
    import gc

    return tuple(gc.get_threshold())


def test_workers_collect_garbage_less_often_than_the_default() -> None:
    from logicenveval.runner.executors import WORKER_GC_THRESHOLD

    out = dict(ProcessExecutor(2).map_unordered(_gc_threshold, [0, 1]))
    assert out[0] == out[1] == WORKER_GC_THRESHOLD and WORKER_GC_THRESHOLD[0] > 700


@pytest.mark.parametrize(("executor", "workers", "started"),
                         [("process", 2, True), ("process", 1, True), ("inprocess", 2, False)])
def test_prestart_starts_the_fork_server_only_for_the_process_executor(
        executor: str, workers: int, started: bool) -> None:
    """`run` starts the fork server before importing its own modules, so both import at once."""
    code = ("import multiprocessing.forkserver as f\n"
            "from logicenveval.runner.executors import prestart\n"
            f"prestart({executor!r}, {workers})\n"
            "print(f._forkserver._forkserver_pid is not None)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=120)
    assert out.stdout.strip() == str(started)


@pytest.mark.parametrize(("argv", "started"), [
    (["run", "--workers", "2"], True),
    (["run", "--workers", "2", "--tasks", "clean_living_room"], True),
    (["run", "--workers", "1"], True),  # one worker process isolates the units too
    (["run", "--workers", "2", "--executor", "inprocess"], False),
    (["run", "--workers", "2", "--debug"], False),
    (["run", "--workers", "2", "--help"], False),
    (["run", "--workers", "two"], False),
    (["report", "--workers", "2"], False),
])
def test_run_starts_its_fork_server_before_the_full_parser(argv: list[str], started: bool) -> None:
    """`cli.main` starts `run`'s fork server from the few options that decide it, before the
    parser imports every command; anything it cannot read starts nothing (the parser says why)."""
    code = ("import sys, multiprocessing.forkserver as f\n"
            "from logicenveval.commands.run_start import start_early\n"
            f"said = start_early({argv!r})\n"
            "print(said, f._forkserver._forkserver_pid is not None, 'logicenveval.commands.run' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=120)
    assert out.stdout.split() == [str(started), str(started), "False"]
