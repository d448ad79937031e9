"""The honesty checks every reader test set shares (tests/data/reader_*/, issue 47).

A set is rewordings of built-in tasks (`tasks_reworded/`, built from `rewordings.json`) and new
tasks (`tasks_new/`). The checks keep the data honest, not the reader's scores: nothing here runs
the offline model. Each set's own test file calls them with what differs between sets (which
earlier sets its new tasks must not repeat, its sentence breaks, its sample tasks).
"""

from __future__ import annotations

import importlib.util
import json
import re
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from logicenveval.benchmark import load_task, load_tasks, task_ids
from logicenveval.benchmark_validation import validate_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.faults.score import shipped_is_current

DATA = Path(__file__).parent / "data"
ROOT = Path(__file__).resolve().parents[1]
BUILTIN = ROOT / "benchmark_data" / "tasks"
POLICIES = {"correct", "counterfactual", "unreachable", "lackbranch"}


def rewordings(set_dir: Path) -> list[dict[str, Any]]:
    """The entries of a set's `rewordings.json` (id, original, register, description)."""
    entries: list[dict[str, Any]] = json.loads((set_dir / "rewordings.json").read_text(encoding="utf-8"))["rewordings"]
    return entries


def names_of(role: str, category: str) -> set[str]:
    """Words a text may use for a role's object: the role and category names, the catalog's
    synonyms, and the last word of each (a `toy_box` is "the box", a `wall_shelf` "the shelf")."""
    cat = load_catalog().get(category)
    phrases = {role.replace("_", " "), category.replace("_", " "), *(cat.synonyms if cat else [])}
    return phrases | {p.split()[-1] for p in phrases}


def mentions(text: str, names: set[str]) -> bool:
    words = " ".join(re.findall(r"[a-z0-9]+", text.lower()))
    return any(re.search(rf"\b{re.escape(n.lower())}(s|es)?\b", words) for n in names)


def check_built_from_json(set_name: str, entries: Sequence[dict[str, Any]], reworded: Path, out: Path) -> None:
    """The folders are exactly what `tools/build_reworded_tasks.py --set <set_name>` writes."""
    assert sorted(str(e["id"]) for e in entries) == task_ids(reworded)
    spec = importlib.util.spec_from_file_location("build_reworded_tasks", ROOT / "tools" / "build_reworded_tasks.py")
    assert spec is not None and spec.loader is not None
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    assert set_name in tool.SETS
    tool.build(entries, out)
    for entry in entries:
        built = (out / str(entry["id"]) / "task.json").read_bytes()
        assert built == (reworded / str(entry["id"]) / "task.json").read_bytes(), entry["id"]


def check_rewording_changes_only_the_wording(entry: dict[str, str], reworded_dir: Path) -> None:
    """Same rooms, roles, variables, trees, constraint facts and BTs as the original; only the
    id, the description and the constraints' quotes differ."""
    original = json.loads((BUILTIN / entry["original"] / "task.json").read_text(encoding="utf-8"))
    reworded = json.loads((reworded_dir / entry["id"] / "task.json").read_text(encoding="utf-8"))
    assert reworded["description"] == entry["description"] != original["description"]
    for key in set(original) | set(reworded):
        if key not in ("id", "description", "constraints"):
            assert reworded[key] == original[key], key
    assert [c["fact"] for c in reworded.get("constraints", [])] == [c["fact"] for c in original.get("constraints", [])]
    originals = sorted((BUILTIN / entry["original"] / "policies").glob("*.xml"))
    assert [p.name for p in originals] == sorted(p.name for p in (reworded_dir / entry["id"] / "policies").glob("*.xml"))
    for path in originals:
        assert (reworded_dir / entry["id"] / "policies" / path.name).read_bytes() == path.read_bytes()
    load_task(entry["id"], reworded_dir)  # parses: every `says` quotes the new description


def check_rewording_names_every_object(entry: dict[str, str]) -> None:
    """Every object the original's description names, the rewording names too."""
    original = load_task(entry["original"])
    for role, spec in original.roles.items():
        names = names_of(role, spec.category)
        if mentions(original.description, names):
            assert mentions(entry["description"], names), (role, sorted(names))


def check_new_tasks_are_fresh(new: Path, earlier: Sequence[Path], *, fresh_rooms: bool = True) -> None:
    """Mostly categories neither the built-in tasks nor the `earlier` sets' tasks use, (with
    `fresh_rooms`) in a room id none of them uses, and every object named in the description."""
    seen = [*load_tasks(), *(t for folder in earlier for t in load_tasks(folder))]
    used = {spec.category for t in seen for spec in t.roles.values()}
    used_rooms = {room for t in seen for room in t.rooms}
    for task in load_tasks(new):
        categories = [spec.category for spec in task.roles.values()]
        fresh = [c for c in categories if c not in used]
        assert len(fresh) * 2 >= len(categories), (task.id, fresh)
        if fresh_rooms:
            assert set(task.rooms) - used_rooms, (task.id, task.rooms)
        for role, spec in task.roles.items():
            assert mentions(task.description, names_of(role, spec.category)), (task.id, role)


def set_folders(sets: Sequence[str], kind: str) -> list[Path]:
    """The `kind` folders (`tasks_new`, `tasks_reworded`) of the named sets that have one."""
    return [DATA / s / kind for s in sets if (DATA / s / kind).is_dir()]


def check_registers_new(entries: Sequence[dict[str, Any]], sets: Sequence[str]) -> None:
    """No rewording's register repeats one of the `sets`' rewordings."""
    earlier = {str(e["register"]).lower() for s in sets if (DATA / s / "rewordings.json").exists()
               for e in rewordings(DATA / s)}
    assert not {str(e["register"]).lower() for e in entries} & earlier


def check_ids_new(folders: Sequence[Path], sets: Sequence[str]) -> None:
    """No task id of `folders` is a built-in task's or one of the `sets`' tasks'."""
    taken = set(task_ids())
    for folder in set_folders(sets, "tasks_reworded") + set_folders(sets, "tasks_new"):
        taken |= set(task_ids(folder))
    ours = {i for folder in folders for i in task_ids(folder)}
    assert not ours & taken


def check_fresh_rooms_with_a_new_kind(new: Path, sets: Sequence[str]) -> None:
    """Each new task: a room id neither the built-in tasks nor the `sets` use (and no two new
    tasks share one), at least one object kind no built-in task uses, every object named in the
    description. (Later sets promise one new kind only: the catalog's pool of unused kinds is
    nearly exhausted.)"""
    builtin = load_tasks()
    builtin_kinds = {spec.category for t in builtin for spec in t.roles.values()}
    used_rooms = {room for t in builtin for room in t.rooms}
    for folder in set_folders(sets, "tasks_reworded") + set_folders(sets, "tasks_new"):
        used_rooms |= {room for t in load_tasks(folder) for room in t.rooms}
    fresh_rooms: list[str] = []
    for task in load_tasks(new):
        assert {spec.category for spec in task.roles.values()} - builtin_kinds, task.id
        fresh = set(task.rooms) - used_rooms
        assert fresh, (task.id, task.rooms)
        fresh_rooms += sorted(fresh)
        for role, spec in task.roles.items():
            assert mentions(task.description, names_of(role, spec.category)), (task.id, role)
    assert len(set(fresh_rooms)) == len(fresh_rooms)


def check_a_few_factors_and_a_stated_fact(new: Path, *, min_objects: int = 0) -> None:
    """2-4 uncertain factors per new task (issue 47's "in any register" is about reading, not
    size), at least `min_objects` objects, and at least one fact the description states that is
    no factor."""
    for task in load_tasks(new):
        assert 2 <= len(task.variables) <= 4, (task.id, sorted(task.variables))
        assert len(task.roles) >= min_objects, task.id
        assert task.constraints, task.id


def check_not_templated(new: Path, breaks: str = "[.!?]") -> None:
    """Written as a person would, not as "If the X is Y, ..." sentences (`breaks`: the
    characters a sentence ends with; a list-like set also breaks at line ends)."""
    for task in load_tasks(new):
        sentences = [s for s in re.split(rf"(?<={breaks})\s+", task.description) if s]
        templated = [s for s in sentences if re.match(r"If the \w+( \w+)? is \w+,", s)]
        assert len(templated) * 4 < len(sentences), (task.id, templated)


def check_policies(folders: Sequence[Path]) -> None:
    for folder in folders:
        for task in load_tasks(folder):
            assert set(task.policies) == POLICIES, task.id


def check_mutant_lists_current(folders: Sequence[Path]) -> None:
    """`killable_mutants.json` is keyed by the task (its description too): a text edited without
    `tasks mutants --write` would make every run classify it afresh."""
    stale = [f"{folder.name}/{task.id}" for folder in folders for task in load_tasks(folder)
             if not shipped_is_current(task, folder, load_catalog())]
    assert not stale, f"run `python -m logicenveval tasks mutants --write --tasks-dir ...` for {stale}"


def check_validates(folder: Path, task_id: str) -> None:
    report = validate_task(task_id, folder, worlds=2)
    assert not report.problems, [str(p) for p in report.problems]


def check_all_validate(folder: Path) -> None:
    problems = [str(p) for tid in task_ids(folder) for p in validate_task(tid, folder).problems]
    assert not problems, problems[:10]
