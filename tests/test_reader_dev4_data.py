"""The reader's fourth development set (tests/data/reader_dev4/): new tasks and rewordings written
from the task format, the catalog and the built-in tasks, without reading the offline reader or
running it on them, for work on the reader to be tuned on once the first two development sets
are saturated.

The same honesty checks as the other sets' (tests/test_reader_dev_data.py,
tests/test_reader_holdout_data.py): rewordings that change only the wording and still name every
object, BTs byte-identical to their originals, new tasks about objects and rooms the built-in
tasks and the earlier development sets do not use, every object named, a current mutant list,
and every task valid (one of each kind in the default run, all in the slow run). Nothing here
runs the offline model: these tests keep the data honest, not the reader's scores.
"""

from __future__ import annotations

import importlib.util
import json
import re
from pathlib import Path

import pytest
from test_reader_dev_data import _mentions, _names

from logicenveval.benchmark import load_task, load_tasks, task_ids
from logicenveval.benchmark_validation import validate_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.faults.score import shipped_is_current

DATA = Path(__file__).parent / "data"
DEV4 = DATA / "reader_dev4"
REWORDED = DEV4 / "tasks_reworded"
NEW = DEV4 / "tasks_new"
#: the earlier development sets: their new tasks' objects and rooms are not "fresh"
EARLIER_NEW = (DATA / "reader_dev" / "tasks_new", DATA / "reader_dev2" / "tasks_new")
ROOT = Path(__file__).resolve().parents[1]
BUILTIN = ROOT / "benchmark_data" / "tasks"
ENTRIES: list[dict[str, object]] = json.loads((DEV4 / "rewordings.json").read_text(encoding="utf-8"))["rewordings"]


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
    tuned = json.loads((DATA / "reader_dev" / "rewordings.json").read_text(encoding="utf-8"))["rewordings"]
    assert {str(e["original"]) for e in ENTRIES} <= {str(e["original"]) for e in tuned}


def test_ids_do_not_collide_with_the_builtin_tasks_or_the_earlier_development_sets() -> None:
    taken = set(task_ids()) | set(task_ids(DATA / "reader_dev" / "tasks_reworded"))
    for folder in EARLIER_NEW:
        taken |= set(task_ids(folder))
    assert not (set(task_ids(REWORDED)) | set(task_ids(NEW))) & taken


def test_reworded_folders_are_built_from_the_json(tmp_path: Path) -> None:
    """The folders are exactly what `tools/build_reworded_tasks.py --set reader_dev4` writes."""
    assert sorted(str(e["id"]) for e in ENTRIES) == task_ids(REWORDED)
    spec = importlib.util.spec_from_file_location("build_reworded_tasks", ROOT / "tools" / "build_reworded_tasks.py")
    assert spec is not None and spec.loader is not None
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    assert "reader_dev4" in tool.SETS
    tool.build(ENTRIES, tmp_path)
    for entry in ENTRIES:
        built = (tmp_path / str(entry["id"]) / "task.json").read_bytes()
        assert built == (REWORDED / str(entry["id"]) / "task.json").read_bytes(), entry["id"]


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_changes_only_the_wording(entry: dict[str, str]) -> None:
    """Same rooms, roles, variables, trees, constraint facts and BTs as the original; only the
    id, the description and the constraints' quotes differ."""
    original = json.loads((BUILTIN / entry["original"] / "task.json").read_text(encoding="utf-8"))
    reworded = json.loads((REWORDED / entry["id"] / "task.json").read_text(encoding="utf-8"))
    assert reworded["description"] == entry["description"] != original["description"]
    for key in set(original) | set(reworded):
        if key not in ("id", "description", "constraints"):
            assert reworded[key] == original[key], key
    assert [c["fact"] for c in reworded.get("constraints", [])] == [c["fact"] for c in original.get("constraints", [])]
    originals = sorted((BUILTIN / entry["original"] / "policies").glob("*.xml"))
    assert [p.name for p in originals] == sorted(p.name for p in (REWORDED / entry["id"] / "policies").glob("*.xml"))
    for path in originals:
        assert (REWORDED / entry["id"] / "policies" / path.name).read_bytes() == path.read_bytes()
    load_task(entry["id"], REWORDED)  # parses: every `says` quotes the new description


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_still_names_every_object_its_original_names(entry: dict[str, str]) -> None:
    original = load_task(entry["original"])
    for role, spec in original.roles.items():
        names = _names(role, spec.category)
        if _mentions(original.description, names):
            assert _mentions(entry["description"], names), (role, sorted(names))


def test_new_tasks_are_about_objects_and_rooms_the_earlier_sets_do_not_use() -> None:
    """Mostly categories neither the built-in tasks nor the earlier development sets' new tasks
    use, in room ids none of them uses, and every object named in the description."""
    seen = [*load_tasks(), *(t for folder in EARLIER_NEW for t in load_tasks(folder))]
    used = {spec.category for t in seen for spec in t.roles.values()}
    used_rooms = {room for t in seen for room in t.rooms}
    for task in load_tasks(NEW):
        categories = [spec.category for spec in task.roles.values()]
        fresh = [c for c in categories if c not in used]
        assert len(fresh) * 2 >= len(categories), (task.id, fresh)
        assert set(task.rooms) - used_rooms, (task.id, task.rooms)
        for role, spec in task.roles.items():
            assert _mentions(task.description, _names(role, spec.category)), (task.id, role)


def test_new_tasks_have_a_few_independent_factors_and_a_stated_fact() -> None:
    """2-4 uncertain factors and 3 or more objects per task, and at least one fact the
    description states that is no factor."""
    for task in load_tasks(NEW):
        assert 2 <= len(task.variables) <= 4, (task.id, sorted(task.variables))
        assert len(task.roles) >= 3, task.id
        assert task.constraints, task.id


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    """Written as a person would, not as "If the X is Y, ..." sentences."""
    for task in load_tasks(NEW):
        sentences = [s for s in re.split(r"(?<=[.!?\n])\s+", task.description) if s]
        templated = [s for s in sentences if re.match(r"If the \w+( \w+)? is \w+,", s)]
        assert len(templated) * 4 < len(sentences), (task.id, templated)


def test_every_task_ships_its_four_policies_and_a_current_mutant_list() -> None:
    """`killable_mutants.json` is keyed by the task (its description too): a text edited without
    `tasks mutants --write` would make every run classify it afresh."""
    for folder in (REWORDED, NEW):
        for task in load_tasks(folder):
            assert set(task.policies) == {"correct", "counterfactual", "unreachable", "lackbranch"}, task.id
    stale = [f"{folder.name}/{task.id}" for folder in (REWORDED, NEW) for task in load_tasks(folder)
             if not shipped_is_current(task, folder, load_catalog())]
    assert not stale, f"run `python -m logicenveval tasks mutants --write --tasks-dir ...` for {stale}"


@pytest.mark.parametrize(("folder", "task_id"), [(NEW, "home_bar_email_from_jo"), (REWORDED, "dining_table_clear_d4")])
def test_a_dev4_task_validates(folder: Path, task_id: str) -> None:
    report = validate_task(task_id, folder, worlds=2)
    assert not report.problems, [str(p) for p in report.problems]


@pytest.mark.slow
@pytest.mark.parametrize("folder", [NEW, REWORDED], ids=["new", "reworded"])
def test_every_dev4_task_validates(folder: Path) -> None:
    problems = [str(p) for tid in task_ids(folder) for p in validate_task(tid, folder).problems]
    assert not problems, problems[:10]
