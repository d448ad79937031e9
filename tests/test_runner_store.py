"""Crash-safe unit storage, run identity and regression comparison."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import ConfigError, RunStoreError
from logicenveval.metrics.records import EnvSample, PhysicsSummary, UnitRecord
from logicenveval.reporting.compare import compare_results
from logicenveval.runner.config import RunConfig
from logicenveval.runner.store import RunStore


def _record(task: str = "t1") -> UnitRecord:
    sample = EnvSample(generator="g", task_id=task, env_id="e0", covered_paths=["s:v=yes"],
                       well_formed=True, physics=PhysicsSummary(floor_plan=True, entity=False, relation=True),
                       verdicts={"correct": "passed"}, sim_ms={"correct": 0.5})
    return UnitRecord(generator="g", task_id=task, samples=[sample], gen_seconds=1.5)


def test_save_load_round_trip(tmp_path: Path) -> None:
    store = RunStore(tmp_path)
    assert store.load("g", "t1") is None
    store.save(_record())
    assert store.load("g", "t1") == _record()
    assert not list(tmp_path.rglob("*.tmp"))


def test_save_meanwhile_writes_what_save_writes_and_raises_at_wait(tmp_path: Path) -> None:
    """The background commit: the same bytes as `save`, durable when `wait` returns; a write
    that fails (here the unit's path is a folder) raises from `wait`, naming the path."""
    RunStore(tmp_path / "a").save(_record())
    wait = RunStore(tmp_path / "b").save_meanwhile(_record())
    wait()
    same = [RunStore(tmp_path / x).unit_path("g", "t1").read_bytes() for x in ("a", "b")]
    assert same[0] == same[1]
    blocked = RunStore(tmp_path / "c")
    blocked.unit_path("g", "t1").mkdir(parents=True)
    wait = blocked.save_meanwhile(_record())
    with pytest.raises(ConfigError, match="not a regular file"):
        wait()


@pytest.mark.parametrize("damage", ["truncate", "edit", "garbage", "wrong_unit"])
def test_corrupt_units_are_detected(tmp_path: Path, damage: str) -> None:
    store = RunStore(tmp_path)
    store.save(_record())
    path = store.unit_path("g", "t1")
    text = path.read_text()
    if damage == "truncate":
        path.write_text(text[: len(text) // 2])
    elif damage == "edit":
        path.write_text(text.replace('"passed"', '"goal_unmet"'))
    elif damage == "garbage":
        path.write_bytes(b"\x00\xff")
    else:
        other = RunStore(tmp_path / "x")
        other.save(_record("t2"))
        path.write_text(other.unit_path("g", "t2").read_text())
    assert store.load("g", "t1") is None


def test_atomic_write_replaces_whole_file(tmp_path: Path) -> None:
    p = tmp_path / "a" / "f.txt"
    atomic_write_text(p, "one")
    atomic_write_text(p, "two")
    assert p.read_text() == "two"


def test_config_identity_and_folder_binding(tmp_path: Path) -> None:
    a = RunConfig(output=str(tmp_path), workers=1)
    b = RunConfig(output=str(tmp_path), workers=2, executor="inprocess")
    assert a.resolved_run_id() == b.resolved_run_id()  # speed settings do not change identity
    c = RunConfig(output=str(tmp_path), seed=1)
    assert c.resolved_run_id() != a.resolved_run_id()
    secret = RunConfig(model="openai:x", model_args="base_url=http://h/v1,api_key=sk-123,api_key_env=K")
    assert "sk-123" not in json.dumps(secret.identity())
    store = RunStore(a.run_dir())
    store.bind_config(a.identity())
    store.bind_config(a.identity())
    with pytest.raises(RunStoreError, match="different configuration"):
        store.bind_config(c.identity())


def _results(logcov: float, st: float, redundancy: float) -> dict[str, object]:
    return {"results": {"g": {"phypr": {"floor_plan": 1, "entity": 1, "relation": 1, "avg": 1},
                              "logcov": logcov, "ld": 1, "scevr": 1,
                              "faudr": {"counterfactual": 1, "unreachable": 1, "lackbranch": 1, "avg": 1},
                              "st_ms": st, "ji": 1, "redundancy": redundancy, "n_envs": 4}}}


def test_compare_directions_and_tolerance() -> None:
    base = _results(0.9, 10.0, 1.0)
    assert not compare_results(base, _results(0.89, 50.0, 1.01)).regressions
    regs = {d.metric for d in compare_results(base, _results(0.85, 50.0, 1.5)).regressions}
    assert regs == {"LogCov"}  # Redundancy has no direction (issue 36): reported, not judged
    timing = {d.metric for d in compare_results(base, _results(0.9, 50.0, 1.0), judge_timing=True).regressions}
    assert timing == {"ST (ms)"}
    better = compare_results(base, _results(0.95, 10.0, 0.5))
    assert {d.metric for d in better.improvements} == {"LogCov"} and not better.failed
    assert {d.metric: d.verdict for d in better.deltas}["Redundancy"] == "not judged"


def test_files_intact_checks_the_files_a_unit_wrote(tmp_path: Path) -> None:
    from logicenveval.runner.store import text_digest

    store = RunStore(tmp_path)
    atomic_write_text(tmp_path / "envs" / "g" / "t1" / "e0.json", "{}\n", durable=False)
    record = _record().model_copy(update={"files": {"envs/g/t1/e0.json": text_digest("{}\n")}})
    store.save(record)
    loaded = store.load("g", "t1")
    assert loaded == record and store.files_intact(loaded)
    (tmp_path / "envs" / "g" / "t1" / "e0.json").write_text("{ }\n")
    assert not store.files_intact(loaded)
    (tmp_path / "envs" / "g" / "t1" / "e0.json").unlink()
    assert not store.files_intact(loaded)


def test_results_rows_follow_the_runs_order_whatever_the_file_lists() -> None:
    from logicenveval.runner.results import in_run_order

    rows = {"a": {}, "b": {}, "c": {}}
    assert list(in_run_order({"results": rows, "generators": ["c", "a", "b"]})["results"]) == ["c", "a", "b"]
    # edited by hand: a name no row has is skipped, rows it does not name follow in file order
    assert list(in_run_order({"results": rows, "generators": ["x", "b"]})["results"]) == ["b", "a", "c"]
    assert list(in_run_order({"results": rows})["results"]) == ["a", "b", "c"]
    # written before `generators`: the generators the config asked for (a plug-in's ref matches no row)
    older = {"results": rows, "config": {"generators": ["c", "pkg.mod:Gen", "b"]}}
    assert list(in_run_order(older)["results"]) == ["c", "b", "a"]
