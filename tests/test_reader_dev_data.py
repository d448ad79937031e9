"""The reader's development set (tests/data/reader_dev/, issue 47): reworded built-in tasks and
new tasks written from scratch, measured by benchmarks/reader_generalisation.py.

Nothing here runs the offline model: these tests keep the data honest (valid tasks, rewordings
that change only the wording and still name every object), not the reader's scores.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from reader_sets import (
    DATA,
    check_all_validate,
    check_new_tasks_are_fresh,
    check_not_templated,
    check_rewording_changes_only_the_wording,
    check_rewording_names_every_object,
    check_validates,
    rewordings,
)

from logicenveval.benchmark import task_ids

DEV = DATA / "reader_dev"
REWORDED = DEV / "tasks_reworded"
NEW = DEV / "tasks_new"
ENTRIES = rewordings(DEV)


def test_the_set_is_as_large_and_varied_as_issue_47_asks() -> None:
    assert len(ENTRIES) >= 40
    assert len({e["original"] for e in ENTRIES}) >= 10
    registers = " ".join(str(e["register"]) for e in ENTRIES)
    for register in ("terse", "chatty", "list", "question", "passive", "British", "American"):
        assert register in registers
    assert len(task_ids(NEW)) >= 6


def test_reworded_folders_are_built_from_the_json() -> None:
    assert sorted(e["id"] for e in ENTRIES) == task_ids(REWORDED)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_changes_only_the_wording(entry: dict[str, str]) -> None:
    check_rewording_changes_only_the_wording(entry, REWORDED)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_still_names_every_object_its_original_names(entry: dict[str, str]) -> None:
    check_rewording_names_every_object(entry)


def test_new_tasks_are_about_objects_the_builtin_tasks_do_not_use() -> None:
    check_new_tasks_are_fresh(NEW, [], fresh_rooms=False)


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    check_not_templated(NEW)


@pytest.mark.parametrize(("folder", "task_id"), [(NEW, "garage_lock_up"), (REWORDED, "clean_living_room_r3")])
def test_a_dev_task_validates(folder: Path, task_id: str) -> None:
    check_validates(folder, task_id)


@pytest.mark.slow
@pytest.mark.parametrize("folder", [NEW, REWORDED], ids=["new", "reworded"])
def test_every_dev_task_validates(folder: Path) -> None:
    check_all_validate(folder)


@pytest.mark.slow
def test_the_benchmark_aggregates_as_the_library_does(tmp_path: Path) -> None:
    """benchmarks/reader_generalisation.py recomputes the rows from per-task figures; they must be
    the run's own LogCov, SceVR and FauDR."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
    import reader_generalisation as bench

    per_task, why = bench.run_set(NEW, ["bathroom_after_bath", "garage_lock_up"], 0, 1, tmp_path)
    (results_file,) = tmp_path.glob("*/results.json")
    got = json.loads(results_file.read_text(encoding="utf-8"))["results"][bench.GENERATOR]
    assert bench.aggregate(per_task) == pytest.approx((got["logcov"], got["scevr"], got["faudr"]["avg"]))
    assert set(why) <= set(per_task)


def test_the_benchmarks_compare_lists_every_moved_task_and_counts_the_falls() -> None:
    """`--compare OLD.json` (the per-task check before a reader rule is merged): a task that fell
    in any figure is a fall, one that only rose a gain, an unmoved task or one of a set the old
    file lacks says nothing."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
    import reader_generalisation as bench

    def fig(lc: float, sv: float, fd: float) -> dict[str, float]:
        return {"logcov": lc, "scevr": sv, "faudr": fd}

    old = {"per_task": {"new": {"a": fig(1, 1, 1), "b": fig(0.5, 1, 0.5), "c": fig(1, 1, 1)}}}
    new = {"per_task": {"new": {"a": fig(1, 0.5, 1), "b": fig(1, 1, 0.5), "c": fig(1, 1, 1)},
                        "dev10 new": {"d": fig(0, 0, 0)}}}
    lines, fell = bench.compare(old, new)
    assert fell == 1
    assert [line.split()[:3] for line in lines] == [["FALL", "new", "a"], ["gain", "new", "b"]]
    assert "scevr 100.0 -> 50.0" in lines[0] and "logcov 50.0 -> 100.0" in lines[1]


def test_skip_names_a_set_of_the_benchmark_or_stops_before_running() -> None:
    """`--skip` keeps a fresh set unseen while others tune; a misspelt set must not silently run
    it (nothing runs before the check, so this is quick)."""
    import subprocess
    import sys

    script = Path(__file__).resolve().parents[1] / "benchmarks" / "reader_generalisation.py"
    done = subprocess.run([sys.executable, str(script), "--dev-only", "--skip", "dev10 new,dev 10 new"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and "no set named dev 10 new" in done.stderr


def test_only_keeps_the_rows_it_names_and_refuses_a_name_no_row_has() -> None:
    """`--only` (bisecting an unseen row's move on its aggregate) leaves out every other row, and
    like `--skip` stops on a misspelt row rather than run the wrong sets."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
    import reader_generalisation as bench

    names = {name for name, _ in bench.SETS}
    kept = {name for name, _ in bench.selected(False, False, bench.skipped_rows("", "held-out reworded,dev9 new"))}
    assert kept == {"held-out reworded", "dev9 new"}
    assert bench.skipped_rows("dev9 new", "") == {"dev9 new"}
    assert bench.skipped_rows("", "") == set() and len(names) > 2
    # --dev-only still wins: a held-out row named by --only is not run for a tuner
    tuning = {name for name, _ in bench.selected(True, False, bench.skipped_rows("", "held-out reworded,dev9 new"))}
    assert tuning == {"dev9 new"}
    with pytest.raises(ValueError, match="--only: no set named held out"):
        bench.skipped_rows("", "held out")


def test_dev_only_leaves_out_the_held_out_and_the_fresh_sets() -> None:
    """A tuner runs `--dev-only`: neither the held-out nor the fresh sets may show in it."""
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
    import reader_generalisation as bench

    def names(dev_only: bool, fresh: bool, skipped: set[str]) -> set[str]:
        return {name for name, _ in bench.selected(dev_only, fresh, skipped)}

    tuning = names(True, False, set())
    assert "dev9 new" in tuning and not tuning & (bench.UNSEEN | bench.FRESH)
    measuring = names(True, True, set())
    assert measuring >= bench.FRESH and not measuring & bench.UNSEEN
    everything = names(False, False, {"dev9 new"})
    assert everything >= bench.UNSEEN | bench.FRESH and "dev9 new" not in everything
