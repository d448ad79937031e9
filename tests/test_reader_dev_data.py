"""The reader's development set (tests/data/reader_dev/, issue 47): reworded built-in tasks and
new tasks written from scratch, measured by benchmarks/reader_generalisation.py.

Nothing here runs the offline model: these tests keep the data honest (valid tasks, rewordings
that change only the wording and still name every object), not the reader's scores.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from logicenveval.benchmark import load_task, load_tasks, task_ids
from logicenveval.benchmark_validation import validate_task
from logicenveval.domain.catalog import load_catalog

DEV = Path(__file__).parent / "data" / "reader_dev"
REWORDED = DEV / "tasks_reworded"
NEW = DEV / "tasks_new"
BUILTIN = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks"
ENTRIES: list[dict[str, object]] = json.loads((DEV / "rewordings.json").read_text(encoding="utf-8"))["rewordings"]


def _names(role: str, category: str) -> set[str]:
    """Words a text may use for a role's object: the role and category names, the catalog's
    synonyms, and the last word of each (a `toy_box` is "the box", a `wall_shelf` "the shelf")."""
    cat = load_catalog().get(category)
    phrases = {role.replace("_", " "), category.replace("_", " "), *(cat.synonyms if cat else [])}
    return phrases | {p.split()[-1] for p in phrases}


def _mentions(text: str, names: set[str]) -> bool:
    words = " ".join(re.findall(r"[a-z0-9]+", text.lower()))
    return any(re.search(rf"\b{re.escape(n.lower())}(s|es)?\b", words) for n in names)


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
    """Same rooms, roles, variables, trees, constraint facts and BTs as the original; only the
    id, the description and the constraints' quotes differ."""
    original = json.loads((BUILTIN / entry["original"] / "task.json").read_text(encoding="utf-8"))
    reworded = json.loads((REWORDED / entry["id"] / "task.json").read_text(encoding="utf-8"))
    assert reworded["description"] == entry["description"] != original["description"]
    for key in set(original) | set(reworded):
        if key not in ("id", "description", "constraints"):
            assert reworded[key] == original[key], key
    facts = [(c["fact"], c.get("says")) for c in original.get("constraints", [])]
    assert [c["fact"] for c in reworded.get("constraints", [])] == [f for f, _ in facts]
    for path in sorted((BUILTIN / entry["original"] / "policies").glob("*.xml")):
        assert (REWORDED / entry["id"] / "policies" / path.name).read_bytes() == path.read_bytes()
    load_task(entry["id"], REWORDED)  # parses: every `says` quotes the new description


@pytest.mark.parametrize("entry", ENTRIES, ids=[str(e["id"]) for e in ENTRIES])
def test_a_rewording_still_names_every_object_its_original_names(entry: dict[str, str]) -> None:
    original = load_task(entry["original"])
    for role, spec in original.roles.items():
        names = _names(role, spec.category)
        if _mentions(original.description, names):
            assert _mentions(entry["description"], names), (role, sorted(names))


def test_new_tasks_are_about_objects_the_builtin_tasks_do_not_use() -> None:
    used = {spec.category for t in load_tasks() for spec in t.roles.values()}
    for task in load_tasks(NEW):
        categories = [spec.category for spec in task.roles.values()]
        fresh = [c for c in categories if c not in used]
        assert len(fresh) * 2 >= len(categories), (task.id, fresh)
        for role, spec in task.roles.items():
            assert _mentions(task.description, _names(role, spec.category)), (task.id, role)


def test_new_tasks_are_not_written_in_the_benchmark_template() -> None:
    """Written as a person would, not as "If the X is Y, ..." sentences."""
    for task in load_tasks(NEW):
        sentences = [s for s in re.split(r"(?<=[.!?])\s+", task.description) if s]
        templated = [s for s in sentences if re.match(r"If the \w+( \w+)? is \w+,", s)]
        assert len(templated) * 4 < len(sentences), (task.id, templated)


@pytest.mark.parametrize(("folder", "task_id"), [(NEW, "garage_lock_up"), (REWORDED, "clean_living_room_r3")])
def test_a_dev_task_validates(folder: Path, task_id: str) -> None:
    report = validate_task(task_id, folder, worlds=2)
    assert not report.problems, [str(p) for p in report.problems]


@pytest.mark.slow
@pytest.mark.parametrize("folder", [NEW, REWORDED], ids=["new", "reworded"])
def test_every_dev_task_validates(folder: Path) -> None:
    problems = [str(p) for tid in task_ids(folder) for p in validate_task(tid, folder).problems]
    assert not problems, problems[:10]


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
