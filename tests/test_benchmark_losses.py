"""`benchmarks/reader_generalisation.py --losses`: the classifier of where a task loses, on small
synthetic per-task metrics and recorded messages (no run), and its print, which for a held-out or
fresh row holds counts only."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import reader_generalisation as bench  # noqa: E402


def _m(logcov: float = 1.0, n_envs: int = 2, n_valid: int = 2, n_failed: int = 0,
       faudr: tuple[bool, ...] = (True, True, True), n_claimed: int = 2, n_realised: int = 2) -> dict[str, Any]:
    """A task's metrics as `results["per_task"]` holds them (the fields the classifier reads)."""
    return {"logcov": logcov, "n_envs": n_envs, "n_valid": n_valid, "n_failed": n_failed,
            "faudr": {k: v for k, v in zip(("counterfactual", "unreachable", "lackbranch"), faudr, strict=True)},
            "n_claimed": n_claimed, "n_realised": n_realised}


UNBOUND = ("problem", "role spare_fuse is not bound to an object and no reached path allows it: no fuse")
PLACED = ("violation", "violates the task's constraint on(jacket, chair) (the description: \"The jacket is on "
          "the chair\"); jacket (jacket_1) is on floor")
STATE = ("violation", "violates the task's constraint is(plate, dirty) (the description: \"a dirty plate\")")
LAYOUT = ("failure", "construct: logicenvgen-01: no layout for the selected objects: overlap")
UNREALISED = ("failure", "construct: logicenvgen-00 does not realise its trajectory in subtasks ['s1']")


def test_a_perfect_task_is_none() -> None:
    assert bench.loss_classes(_m(), []) == {"none"}


@pytest.mark.parametrize(("record", "cls"), [
    (UNBOUND, "unbound role"),
    (PLACED, "fact violated: placement"),
    (STATE, "fact violated: other fact"),
    (("violation", "violates the task's constraint on(a, b) or inside(a, c) (the description: \"x\")"),
     "fact violated: other fact"),
    (LAYOUT, "no layout"),
    (UNREALISED, "not realised"),
    (("failure", "construct: an object category the catalog lacks"), "construction"),
    (("problem", "subtask s1: variable v reaches no leaf (no value holds)"), "ill-formed: no leaf"),
    (("problem", "objects overlap"), "ill-formed: other"),
    (("verdict", "correct BT: failed"), "correct BT fails"),
    (("elsewhere", "anything"), "unclassified"),
])
def test_each_record_has_its_class(record: bench.Record, cls: str) -> None:
    """Each `MESSAGE_CLASSES` row on a message of its shape; a compound fact is no placement."""
    assert bench.record_class(record) == cls


def test_missed_paths_only_when_every_environment_is_valid() -> None:
    """LogCov < 1 with every environment valid is a missed path; with an invalid one it is not."""
    assert "missed paths" in bench.loss_classes(_m(logcov=0.5), [])
    assert bench.loss_classes(_m(logcov=0.5, n_valid=1), [PLACED]) == {"fact violated: placement"}
    assert bench.loss_classes(_m(logcov=0.5, n_failed=1), [LAYOUT]) == {"no layout"}


def test_faulty_bt_not_revealed_only_when_logcov_and_scevr_are_full() -> None:
    assert bench.loss_classes(_m(faudr=(True, False, True)), []) == {"faulty BT not revealed only"}
    assert "faulty BT not revealed only" not in bench.loss_classes(
        _m(logcov=0.5, faudr=(True, False, True)), [])


def test_not_realised_from_the_figures_and_several_classes_at_once() -> None:
    """A claim not realised counts from `n_realised` alone; a task counts in every class it shows."""
    assert bench.loss_classes(_m(n_realised=1), []) == {"not realised", "none"}
    got = bench.loss_classes(_m(logcov=0.5, n_valid=0, n_realised=1), [UNBOUND, STATE, UNREALISED])
    assert got == {"unbound role", "fact violated: other fact", "not realised"}


def test_a_loss_nothing_explains_is_unclassified() -> None:
    assert bench.loss_classes(_m(n_valid=1), []) == {"unclassified"}


def test_sample_records_read_problems_violations_and_the_correct_verdict() -> None:
    sample = {"well_formed": True, "problems": [], "violations": [], "verdicts": {"correct": "failed"}}
    assert bench.sample_records(sample) == [("verdict", "correct BT: failed")]
    sample = {"well_formed": False, "problems": ["p"], "violations": ["v"], "verdicts": {"correct": "failed"}}
    assert bench.sample_records(sample) == [("problem", "p"), ("violation", "v")]
    assert bench.sample_records({"well_formed": True, "verdicts": {"correct": "passed"}}) == []


def test_the_print_shows_counts_only_for_held_out_and_fresh_rows(capsys: pytest.CaptureFixture[str]) -> None:
    """`--why` lists a development row's task ids per class; a held-out or fresh row prints its
    counts only, no task id."""
    per = {"task_alpha": _m(logcov=0.5), "task_beta": _m(), "task_gamma": _m(n_valid=1)}
    recs = {"task_gamma": [PLACED, UNBOUND]}
    hidden = sorted(bench.UNSEEN | bench.FRESH)
    rows = ["new", *hidden]
    table = bench.losses({r: per for r in rows}, {r: recs for r in rows})
    assert table["new"]["missed paths"] == ["task_alpha"]
    assert table["new"]["none"] == ["task_beta"]
    assert table["new"]["unbound role"] == table["new"]["fact violated: placement"] == ["task_gamma"]
    bench.print_losses(table, why=True)
    out = capsys.readouterr().out
    assert "a task may count in several" in out.splitlines()[0]
    assert out.count("task_alpha") == out.count("task_gamma") == 2  # missed paths and its split
    assert "task_beta" not in out  # the "none" class lists no ids
    for name in hidden:
        line = next(x for x in out.splitlines() if x.split()[:len(name.split())] == name.split())
        assert line.split(":", 1)[1].strip() == ("unbound role 1, fact violated: placement 1, "
                                                 "missed paths 1, none 1, "
                                                 "missed paths: values set, paths not combined 1")
    assert out.splitlines()[-1].startswith(f"reader_losses unbound_role={len(rows)} ")


def test_missed_paths_split_by_whether_a_value_was_never_set() -> None:
    """A GT condition no environment realises (an `unset` record) marks a factor not read or not
    varied; without one, every value was set and the paths were not combined."""
    unset = ("unset", "mat_wet=wet")
    assert bench.loss_classes(_m(logcov=0.5), [unset]) == {"missed paths", "missed paths: a value never set"}
    assert bench.loss_classes(_m(logcov=0.5), []) == {"missed paths", "missed paths: values set, paths not combined"}
    assert bench.loss_classes(_m(), [unset]) == {"none"}  # only splits missed paths


def test_unset_records_name_each_gt_condition_no_environment_realises() -> None:
    folder = Path(__file__).resolve().parent / "data" / "reader_dev" / "tasks_new"
    task = bench.load_tasks(folder, ["bathroom_after_bath"])[0]
    every = [f"{v}={x}" for v, x in bench.atomic_conditions(task)]
    assert len(every) >= 2
    assert bench.unset_records(task, set(every)) == []
    assert bench.unset_records(task, set(every[1:])) == [("unset", every[0])]


def test_a_fresh_rows_first_loss_is_never_printed(capsys: pytest.CaptureFixture[str],
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    """`--fresh --why` measures a fresh row: its figures show, its first-loss reasons do not (they
    would be a tuning signal); a development row's do. (A row of its own is made fresh here: between
    sets, `FRESH` may be empty.)"""
    fresh = "dev99 new"
    monkeypatch.setattr(bench, "FRESH", frozenset({fresh}))
    results = {fresh: {"t_fresh": _m(logcov=0.5)}, "dev2 new": {"t_dev": _m(logcov=0.5)}}
    why = {fresh: {"t_fresh": "secret reason"}, "dev2 new": {"t_dev": "shown reason"}}
    bench.print_tasks(results, why, True)
    out = capsys.readouterr().out
    assert "t_fresh" in out and "secret reason" not in out and "shown reason" in out
