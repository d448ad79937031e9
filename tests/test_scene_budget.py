"""The layout budget is deterministic work, not wall-clock time (non-negotiable 5: the same command
gives the same results.json on any machine, at any load).

`relax` decides only from what its `Check` returns; each backend counts its budget in its own
deterministic work (CP-SAT's deterministic time, Z3's resource count), and the wall clock only
caps a solve far beyond the budget, reported as such."""

from __future__ import annotations

import pytest

from logicenveval.scene import layout_cpsat, layout_z3, relax
from logicenveval.scene.layout import Box
from logicenveval.scene.relax import CAPPED, Status, Tracked


def _tracked(n: int) -> list[Tracked]:
    return [Tracked(object(), "object", f"o{k}", False, (f"o{k}",)) for k in range(n)]


def test_relax_spends_the_budget_the_checks_report_and_drops_on_running_out() -> None:
    """A scripted check: what relax grants each call is the budget minus the work reported,
    a drop for lack of budget grants a quarter of it again, and no clock is read."""
    script: list[tuple[Status, float]] = [("unknown", 9.5), ("unknown", 3.0), ("sat", 0.5)]
    granted: list[float] = []

    def check(active: list[Tracked], budget: float) -> tuple[Status, list[Tracked], float]:
        granted.append(budget)
        status, spent = script[len(granted) - 1]
        return status, [], spent

    ok, dropped = relax.relax(check, _tracked(3), 10.0)
    assert ok
    assert granted == [10.0, 2.5, 2.5]
    assert [d.tracked.item for d in dropped] == ["o2", "o1"]
    assert all(d.reason.startswith("solver budget") for d in dropped)


def test_relax_names_the_wall_clock_cap_when_it_ended_a_solve() -> None:
    calls = iter([("capped", 0.1), ("sat", 0.1)])

    def check(active: list[Tracked], budget: float) -> tuple[Status, list[Tracked], float]:
        status, spent = next(calls)
        return status, [], spent  # type: ignore[return-value]

    ok, dropped = relax.relax(check, _tracked(2), 10.0)
    assert ok and [d.reason for d in dropped] == [CAPPED]


def _dense() -> list[Box]:
    """Twelve enrichment boxes that cannot all fit a small floor: proving it takes work."""
    return [Box(f"b{k}", (0.5, 0.5, 0.5), (4, 3), k < 2) for k in range(12)]


@pytest.mark.parametrize("mod", [layout_cpsat, layout_z3], ids=["cpsat", "z3"])
def test_a_tiny_budget_runs_out_at_the_same_point_every_time(mod: object) -> None:
    """With almost no budget the solver runs out (a deterministic drop, never the wall-clock
    cap), and the outcome repeats exactly."""
    runs = [mod.pack((12, 12), _dense(), seed=1, timeout_s=1e-6) for _ in range(2)]  # type: ignore[attr-defined]
    assert runs[0][0] == runs[1][0]
    assert [(d.tracked.item, d.reason) for d in runs[0][1]] == [(d.tracked.item, d.reason) for d in runs[1][1]]
    reasons = {d.reason for d in runs[0][1]}
    assert CAPPED not in reasons
    assert any(r.startswith("solver budget") for r in reasons), reasons


@pytest.mark.parametrize("mod", [layout_cpsat, layout_z3], ids=["cpsat", "z3"])
def test_an_ample_budget_gives_what_no_budget_limit_gives(mod: object) -> None:
    """The default budget is far above what a room of the benchmark needs (the longest solve of
    the 25-task offline run: 0.003 deterministic units): nothing is dropped for want of it."""
    boxes = _dense()[:8]
    placed, dropped = mod.pack((12, 12), boxes, seed=1, timeout_s=10.0)  # type: ignore[attr-defined]
    assert dropped == [] and set(placed) == {b.id for b in boxes}
