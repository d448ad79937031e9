"""Hand-offs: longest units first, whole tasks together, the last tasks one unit at a time;
what a worker does once for all its units."""

from __future__ import annotations

from pathlib import Path

import pytest

from logicenveval.runner.schedule import hand_offs, unit_cost
from logicenveval.runner.unit import UnitSpec

GENS = ("cot", "logicenvgen", "ifg", "logicenvgen-exact")


def _specs(n_tasks: int) -> list[UnitSpec]:
    return [UnitSpec(generator=g, task_id=f"t{i:02d}", tasks_dir=None, model="offline", model_args="",
                     seed=0, run_dir="/tmp/x") for g in GENS for i in range(n_tasks)]


def test_every_unit_is_handed_out_once() -> None:
    for n_tasks in (1, 3, 7, 8, 25):
        for workers in (1, 2, 4):
            specs = _specs(n_tasks)
            out = [s for chunk in hand_offs(specs, workers) for s in chunk]
            assert sorted(out, key=lambda s: (s.generator, s.task_id)) == \
                sorted(specs, key=lambda s: (s.generator, s.task_id))


def test_logicenvgen_first_when_units_go_singly() -> None:
    out = hand_offs(_specs(3), 2)
    assert all(len(c) == 1 for c in out)
    costs = [unit_cost(c[0]) for c in out]
    assert costs == sorted(costs, reverse=True) and costs[0] > costs[-1]
    assert {c[0].generator for c in out[:6]} == {"logicenvgen", "logicenvgen-exact"}


def test_tasks_travel_together_and_the_tail_is_single_short_units() -> None:
    out = hand_offs(_specs(25), 2)
    whole = [c for c in out if len(c) > 1]
    singles = [c[0] for c in out if len(c) == 1]
    assert len(whole) == 21 and all(len({s.task_id for s in c}) == 1 for c in whole)
    assert len(singles) == 4 * len(GENS)
    assert out[: len(whole)] == whole  # whole tasks before the single units
    assert singles[-1].generator in ("cot", "ifg")  # the run ends on a short unit
    assert [unit_cost(s) for s in singles] == sorted((unit_cost(s) for s in singles), reverse=True)


def test_the_schedule_is_a_function_of_the_specs() -> None:
    assert hand_offs(_specs(25), 2) == hand_offs(_specs(25), 2)
    assert hand_offs(_specs(5), 1) == [(s,) for s in _specs(5)]


def test_a_worker_parses_a_bt_once_and_again_after_an_edit(tmp_path: Path) -> None:
    from logicenveval.runner.unit import _policy

    path = tmp_path / "correct.xml"
    path.write_text("one")
    calls: list[str] = []

    def load(p: Path) -> str:
        calls.append(p.read_text())
        return p.read_text()

    assert _policy(load, path) == _policy(load, path) == "one" and calls == ["one"]
    path.write_text("two, longer")
    assert _policy(load, path) == "two, longer" and calls == ["one", "two, longer"]


def test_a_worker_reads_a_task_once_and_again_after_an_edit(tmp_path: Path) -> None:
    import json
    import shutil

    from logicenveval.benchmark import tasks_dir
    from logicenveval.errors import TaskFormatError
    from logicenveval.runner.unit import _task

    shutil.copytree(tasks_dir() / "clean_living_room", tmp_path / "clean_living_room")
    first = _task("clean_living_room", str(tmp_path))
    assert _task("clean_living_room", str(tmp_path)) is first  # units and figures share one parse
    path = tmp_path / "clean_living_room" / "task.json"
    data = json.loads(path.read_text())
    data["description"] += " Edited."
    path.write_text(json.dumps(data))
    edited = _task("clean_living_room", str(tmp_path))
    assert edited is not first and edited.description.endswith(" Edited.")
    with pytest.raises(TaskFormatError, match="not a task id"):
        _task("../clean_living_room", str(tmp_path))  # a miss is load_task's, checks included


def test_a_unit_takes_the_catalog_its_process_checked_clean(monkeypatch: pytest.MonkeyPatch) -> None:
    """Two dumps of the catalog per unit were ~0.15 s of a run: the catalog the last check found
    unchanged is taken as it is; a different catalog object (restored, reloaded) is checked."""
    from logicenveval.domain.catalog import load_catalog, reload_catalogs
    from logicenveval.runner import unit

    dumps: list[int] = []
    real = unit._digest
    monkeypatch.setattr(unit, "_digest", lambda c: dumps.append(1) or real(c))
    catalog, changed = unit.shared_catalog()  # after a generator: checked
    assert not changed and len(dumps) >= 1
    before = len(dumps)
    assert unit.unit_catalog() is catalog and len(dumps) == before  # the next unit: no dump
    reload_catalogs()  # another catalog object: checked again
    assert unit.unit_catalog() is load_catalog() and len(dumps) == before + 1
