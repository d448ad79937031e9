"""The reader's second unseen set (tests/data/reader_dev3/): new tasks and rewordings written after
the development sets had been tuned on, without reading the offline reader or running it on them.

The honesty checks every set has (`reader_sets`): rewordings that change only the wording and
still name every object, BTs byte-identical to their originals, new tasks about objects and rooms
the built-in tasks and both development sets do not use, every object named, a current mutant
list, and every task valid (one of each kind in the default run, all in the slow run).
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

DEV3 = DATA / "reader_dev3"
REWORDED = DEV3 / "tasks_reworded"
NEW = DEV3 / "tasks_new"
#: the sets tuned on: their new tasks' objects and rooms are not "fresh"
TUNED_NEW = (DATA / "reader_dev" / "tasks_new", DATA / "reader_dev2" / "tasks_new")
ENTRIES = rewordings(DEV3)


def test_the_set_rewords_twelve_builtin_tasks_each_in_its_own_register() -> None:
    originals = [str(e["original"]) for e in ENTRIES]
    assert len(ENTRIES) >= 12
    assert len(set(originals)) == len(originals)
    assert set(originals) <= set(task_ids())
    registers = [str(e["register"]) for e in ENTRIES]
    assert len(set(registers)) == len(registers)
    assert all(str(e["id"]).endswith("_d3") for e in ENTRIES)
    assert len(task_ids(NEW)) >= 5


def test_ids_do_not_collide_with_the_builtin_tasks_or_the_development_sets() -> None:
    check_ids_new((REWORDED, NEW), ("reader_dev", "reader_dev2"))


def test_reworded_folders_are_built_from_the_json(tmp_path: Path) -> None:
    check_built_from_json("reader_dev3", ENTRIES, REWORDED, tmp_path)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_changes_only_the_wording(entry: dict[str, str]) -> None:
    check_rewording_changes_only_the_wording(entry, REWORDED)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_still_names_every_object_its_original_names(entry: dict[str, str]) -> None:
    check_rewording_names_every_object(entry)


def test_new_tasks_are_about_objects_and_rooms_the_tuned_sets_do_not_use() -> None:
    check_new_tasks_are_fresh(NEW, TUNED_NEW)


def test_new_tasks_have_a_few_independent_factors_and_a_stated_fact() -> None:
    check_a_few_factors_and_a_stated_fact(NEW)


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    check_not_templated(NEW, breaks=r"[.!?\n]")


def test_every_task_ships_its_four_policies_and_a_current_mutant_list() -> None:
    check_policies((REWORDED, NEW))
    check_mutant_lists_current((REWORDED, NEW))


@pytest.mark.parametrize(("folder", "task_id"), [(NEW, "dining_room_party_texts"), (REWORDED, "laundry_sorting_d3")])
def test_a_dev3_task_validates(folder: Path, task_id: str) -> None:
    check_validates(folder, task_id)


@pytest.mark.slow
@pytest.mark.parametrize("folder", [NEW, REWORDED], ids=["new", "reworded"])
def test_every_dev3_task_validates(folder: Path) -> None:
    check_all_validate(folder)
