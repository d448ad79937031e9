"""The phase stopwatch: nested phases are exclusive, `collect` keeps a block's phases apart."""

from __future__ import annotations

import time

import pytest

from logicenveval import phases


def test_nested_phases_pause_the_outer_one_and_add_up(monkeypatch: pytest.MonkeyPatch) -> None:
    """On a clock the test moves by hand: exclusive phases add up to the wall time exactly."""
    now = [100.0]
    monkeypatch.setattr(phases.time, "perf_counter", lambda: now[0])
    phases.take()
    with phases.phase("generation"):
        now[0] += 0.02
        with phases.phase("layout"):
            now[0] += 0.05
        now[0] += 0.02
    got = phases.take()
    assert got == {"generation": 0.04, "layout": 0.05}  # counted twice, layout would be in both
    assert phases.take() == {}


def test_same_phase_nested_counts_once() -> None:
    phases.take()
    with phases.phase("layout"), phases.phase("layout"):
        time.sleep(0.01)
    got = phases.take()
    assert list(got) == ["layout"] and got["layout"] >= 0.01


def test_collect_keeps_a_units_phases_apart_and_the_run_counts_its_wall_time() -> None:
    phases.take()
    with phases.phase("units"):
        time.sleep(0.01)
        with phases.collect() as unit, phases.phase("start-up"), phases.phase("generation"):
            time.sleep(0.02)
        time.sleep(0.01)
    run = phases.take()
    assert set(unit) == {"start-up", "generation"} and unit["generation"] >= 0.02
    assert set(run) == {"units"} and run["units"] >= 0.02 + unit["generation"]  # the unit's wall time


def test_a_phase_left_by_an_exception_is_closed() -> None:
    phases.take()
    try:
        with phases.phase("physics"):
            raise ValueError
    except ValueError:
        pass
    with phases.phase("simulation"):
        pass
    assert set(phases.take()) == {"physics", "simulation"}
