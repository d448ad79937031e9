"""The reader's fourth development set (tests/data/reader_dev4/): new tasks and rewordings written
from the task format, the catalog and the built-in tasks, without reading the offline reader or
running it on them, for work on the reader to be tuned on once the first two development sets
are saturated.

The honesty checks every set has (`reader_sets`): rewordings that change only the wording and
still name every object, BTs byte-identical to their originals, new tasks about objects and rooms
the built-in tasks and the earlier development sets do not use, every object named, a current
mutant list, and every task valid (one of each kind in the default run, all in the slow run).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from reader_sets import (
    DATA,
    check_a_few_factors_and_a_stated_fact,
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

DEV4 = DATA / "reader_dev4"
REWORDED = DEV4 / "tasks_reworded"
NEW = DEV4 / "tasks_new"
#: the earlier development sets: their new tasks' objects and rooms are not "fresh"
EARLIER_NEW = (DATA / "reader_dev" / "tasks_new", DATA / "reader_dev2" / "tasks_new")
ENTRIES = rewordings(DEV4)


def test_the_set_rewords_twelve_builtin_tasks_each_in_its_own_register() -> None:
    originals = [str(e["original"]) for e in ENTRIES]
    assert len(ENTRIES) >= 12
    assert len(set(originals)) == len(originals)
    assert set(originals) <= set(task_ids())
    registers = [str(e["register"]) for e in ENTRIES]
    assert len(set(registers)) == len(registers)
    assert all(str(e["id"]) == f"{e['original']}_d4" for e in ENTRIES)
    assert len(task_ids(NEW)) >= 6


def test_it_rewords_only_tasks_the_first_development_set_rewords() -> None:
    """A set that is tuned on rewords only built-in tasks whose rewordings are tuned on already,
    so the held-out set's reworded originals stay out of the tuning material."""
    tuned = rewordings(DATA / "reader_dev")
    assert {str(e["original"]) for e in ENTRIES} <= {str(e["original"]) for e in tuned}


def test_ids_do_not_collide_with_the_builtin_tasks_or_the_earlier_development_sets() -> None:
    check_ids_new((REWORDED, NEW), ("reader_dev", "reader_dev2"))


def test_reworded_folders_are_built_from_the_json(tmp_path: Path) -> None:
    check_built_from_json("reader_dev4", ENTRIES, REWORDED, tmp_path)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_changes_only_the_wording(entry: dict[str, str]) -> None:
    check_rewording_changes_only_the_wording(entry, REWORDED)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_still_names_every_object_its_original_names(entry: dict[str, str]) -> None:
    check_rewording_names_every_object(entry)


def test_new_tasks_are_about_objects_and_rooms_the_earlier_sets_do_not_use() -> None:
    check_new_tasks_are_fresh(NEW, EARLIER_NEW)


def test_new_tasks_have_a_few_independent_factors_and_a_stated_fact() -> None:
    check_a_few_factors_and_a_stated_fact(NEW, min_objects=3)


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    check_not_templated(NEW, breaks=r"[.!?\n]")


def test_every_task_ships_its_four_policies_and_a_current_mutant_list() -> None:
    check_policies((REWORDED, NEW))
    check_mutant_lists_current((REWORDED, NEW))


@pytest.mark.parametrize(("folder", "task_id"), [(NEW, "home_bar_email_from_jo"), (REWORDED, "dining_table_clear_d4")])
def test_a_dev4_task_validates(folder: Path, task_id: str) -> None:
    check_validates(folder, task_id)


@pytest.mark.slow
@pytest.mark.parametrize("folder", [NEW, REWORDED], ids=["new", "reworded"])
def test_every_dev4_task_validates(folder: Path) -> None:
    check_all_validate(folder)
