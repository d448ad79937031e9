"""The reader's held-out test set (tests/data/reader_holdout/, issue 47): the counterpart of the
development set, measured by benchmarks/reader_generalisation.py and never tuned to.

The honesty checks every set has (`reader_sets`), on the held-out data: rewordings that change
only the wording and still name every object, BTs byte-identical to their originals, new tasks
about objects and rooms neither the built-in tasks nor the development set use, and every task
valid (one of each kind in the default run, all in the slow run).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from reader_sets import (
    DATA,
    check_all_validate,
    check_built_from_json,
    check_ids_new,
    check_mutant_lists_current,
    check_new_tasks_are_fresh,
    check_not_templated,
    check_policies,
    check_rewording_changes_only_the_wording,
    check_rewording_names_every_object,
    check_validates,
    rewordings,
)

from logicenveval.benchmark import task_ids

HOLDOUT = DATA / "reader_holdout"
REWORDED = HOLDOUT / "tasks_reworded"
NEW = HOLDOUT / "tasks_new"
DEV = DATA / "reader_dev"
ENTRIES = rewordings(HOLDOUT)
DEV_ENTRIES = rewordings(DEV)


def test_the_set_rewords_every_builtin_task_the_dev_set_leaves_out() -> None:
    """Held out means disjoint: the dev set's 12 originals are not reworded here, the other 13 are."""
    dev_originals = {str(e["original"]) for e in DEV_ENTRIES}
    originals = {str(e["original"]) for e in ENTRIES}
    assert originals == set(task_ids()) - dev_originals
    assert len(ENTRIES) >= 20
    registers = " ".join(str(e["register"]) for e in ENTRIES)
    for register in ("terse", "chatty", "list", "question", "passive", "British", "American",
                     "text message", "instruction manual"):
        assert register in registers
    assert len(task_ids(NEW)) >= 6


def test_ids_do_not_collide_with_the_dev_set_or_the_builtin_tasks() -> None:
    check_ids_new((REWORDED, NEW), ("reader_dev",))


def test_reworded_folders_are_built_from_the_json(tmp_path: Path) -> None:
    check_built_from_json("reader_holdout", ENTRIES, REWORDED, tmp_path)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_changes_only_the_wording(entry: dict[str, str]) -> None:
    check_rewording_changes_only_the_wording(entry, REWORDED)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_still_names_every_object_its_original_names(entry: dict[str, str]) -> None:
    check_rewording_names_every_object(entry)


def test_new_tasks_are_about_objects_and_rooms_nobody_used_before() -> None:
    """Every room type is already taken, so a new room is a new id of a known type."""
    check_new_tasks_are_fresh(NEW, [DEV / "tasks_new"])


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    check_not_templated(NEW)


def test_every_task_ships_its_four_policies() -> None:
    check_policies((REWORDED, NEW))


def test_every_task_ships_a_current_mutant_list() -> None:
    check_mutant_lists_current((REWORDED, NEW))


@pytest.mark.parametrize(("folder", "task_id"), [(NEW, "den_game_night"), (REWORDED, "laundry_sorting_h1")])
def test_a_holdout_task_validates(folder: Path, task_id: str) -> None:
    check_validates(folder, task_id)


@pytest.mark.slow
@pytest.mark.parametrize("folder", [NEW, REWORDED], ids=["new", "reworded"])
def test_every_holdout_task_validates(folder: Path) -> None:
    check_all_validate(folder)
