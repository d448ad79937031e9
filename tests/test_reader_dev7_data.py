"""The reader's seventh development set (tests/data/reader_dev7/): new tasks and rewordings written
from the task format, the catalog and the built-in tasks, without reading the offline reader or
running it on them, for the next round of reader rules to be tuned on.

The honesty checks every set has (`reader_sets`): rewordings that change only the wording and
still name every object, BTs byte-identical to their originals, every object named, a current
mutant list, and every task valid (one of each kind in the default run, all in the slow run).
As in the sixth set, the weight is on new tasks (ten, against six rewordings): each new task is
in a register and a room id no other set uses, with at least one object kind no built-in task
uses, and the rewordings' registers repeat no other set's.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from reader_sets import (
    DATA,
    check_a_few_factors_and_a_stated_fact,
    check_all_validate,
    check_built_from_json,
    check_mutant_lists_current,
    check_not_templated,
    check_policies,
    check_rewording_changes_only_the_wording,
    check_rewording_names_every_object,
    check_validates,
    mentions,
    names_of,
    rewordings,
)

from logicenveval.benchmark import load_tasks, task_ids

DEV7 = DATA / "reader_dev7"
REWORDED = DEV7 / "tasks_reworded"
NEW = DEV7 / "tasks_new"
#: the other development sets (the held-out sets are never opened by a development set's test)
DEV_SETS = ("reader_dev", "reader_dev2", "reader_dev3", "reader_dev4", "reader_dev5", "reader_dev6")
ENTRIES = rewordings(DEV7)


def _folders(kind: str) -> list[Path]:
    return [DATA / s / kind for s in DEV_SETS if (DATA / s / kind).is_dir()]


def test_the_set_rewords_six_builtin_tasks_and_writes_ten_new_ones() -> None:
    originals = [str(e["original"]) for e in ENTRIES]
    assert len(ENTRIES) >= 6
    assert len(set(originals)) == len(originals)
    assert set(originals) <= set(task_ids())
    registers = [str(e["register"]) for e in ENTRIES]
    assert len(set(registers)) == len(registers)
    assert all(str(e["id"]) == f"{e['original']}_d7" for e in ENTRIES)
    assert len(task_ids(NEW)) >= 10


def test_no_register_repeats_one_of_the_other_development_sets() -> None:
    earlier = {str(e["register"]).lower() for s in DEV_SETS if (DATA / s / "rewordings.json").exists()
               for e in rewordings(DATA / s)}
    assert not {str(e["register"]).lower() for e in ENTRIES} & earlier


def test_ids_do_not_collide_with_the_builtin_tasks_or_the_other_development_sets() -> None:
    taken = set(task_ids())
    for folder in _folders("tasks_reworded") + _folders("tasks_new"):
        taken |= set(task_ids(folder))
    ours = set(task_ids(REWORDED)) | set(task_ids(NEW))
    assert not ours & taken


def test_reworded_folders_are_built_from_the_json(tmp_path: Path) -> None:
    check_built_from_json("reader_dev7", ENTRIES, REWORDED, tmp_path)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_changes_only_the_wording(entry: dict[str, str]) -> None:
    check_rewording_changes_only_the_wording(entry, REWORDED)


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_still_names_every_object_its_original_names(entry: dict[str, str]) -> None:
    check_rewording_names_every_object(entry)


def test_new_tasks_are_in_fresh_rooms_with_a_kind_no_builtin_task_uses() -> None:
    """Each new task: a room id neither the built-in tasks nor the development sets use, at least
    one object kind no built-in task uses, and every object named in the description."""
    builtin = load_tasks()
    builtin_kinds = {spec.category for t in builtin for spec in t.roles.values()}
    used_rooms = {room for t in builtin for room in t.rooms}
    for folder in _folders("tasks_reworded") + _folders("tasks_new"):
        used_rooms |= {room for t in load_tasks(folder) for room in t.rooms}
    fresh_rooms: list[str] = []
    for task in load_tasks(NEW):
        kinds = {spec.category for spec in task.roles.values()}
        assert kinds - builtin_kinds, task.id
        fresh = set(task.rooms) - used_rooms
        assert fresh, (task.id, task.rooms)
        fresh_rooms += sorted(fresh)
        for role, spec in task.roles.items():
            assert mentions(task.description, names_of(role, spec.category)), (task.id, role)
    assert len(set(fresh_rooms)) == len(fresh_rooms)


def test_new_tasks_have_a_few_independent_factors_and_a_stated_fact() -> None:
    check_a_few_factors_and_a_stated_fact(NEW, min_objects=3)


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    check_not_templated(NEW, breaks=r"[.!?\n]")


def test_every_task_ships_its_four_policies_and_a_current_mutant_list() -> None:
    check_policies((REWORDED, NEW))
    check_mutant_lists_current((REWORDED, NEW))


@pytest.mark.parametrize(("folder", "task_id"), [(NEW, "cabin_yacht_logbook"),
                                                  (REWORDED, "living_room_toy_boxes_d7")])
def test_a_dev7_task_validates(folder: Path, task_id: str) -> None:
    check_validates(folder, task_id)


@pytest.mark.slow
@pytest.mark.parametrize("folder", [NEW, REWORDED], ids=["new", "reworded"])
def test_every_dev7_task_validates(folder: Path) -> None:
    check_all_validate(folder)
