"""`benchmarks/reader_generalisation.py --placements`: the reader's recall of stated placements,
measured on a tiny task folder written here (one placement the reader reads, one it cannot, one
compound fact that is not a single placement and does not count)."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import reader_generalisation as bench  # noqa: E402

SOURCE = Path(__file__).resolve().parent / "data" / "reader_dev" / "tasks_new" / "bathroom_after_bath"


def _folder(tmp_path: Path, task_id: str, extra: str, constraints: list[dict[str, str]]) -> Path:
    """A task folder holding one copy of a development task, its description extended by `extra`
    and its constraints replaced by `constraints`."""
    data: dict[str, Any] = json.loads((SOURCE / "task.json").read_text(encoding="utf-8"))
    data["id"] = task_id
    data["description"] += " " + extra
    data["constraints"] = constraints
    folder = tmp_path / "tasks" / task_id
    folder.mkdir(parents=True)
    (folder / "task.json").write_text(json.dumps(data), encoding="utf-8")
    for policy in (SOURCE / "policies").iterdir():
        (folder / "policies").mkdir(exist_ok=True)
        (folder / "policies" / policy.name).write_bytes(policy.read_bytes())
    return tmp_path / "tasks"


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    return _folder(tmp_path, "tiny_bath", "", [
        {"fact": "on(bath_mat, floor)", "says": "The bath mat lies on the floor"},
        {"fact": "inside(shampoo, wall_cabinet)", "says": "The shampoo and the soap are kept"},
        {"fact": "inside(soap, wall_cabinet) or inside(soap, bathtub)", "says": "the soap are kept in the wall cabinet"},
    ])


def test_recall_counts_single_placements(folder: Path) -> None:
    """Both single placements are stated in the text and read; the compound fact does not count."""
    recall = bench.placement_recall(folder, ["tiny_bath"])
    assert (recall.read, recall.stated, recall.missed) == (2, 2, ())
    assert recall.share == 1.0


def test_a_fact_the_reader_does_not_state_is_missed(tmp_path: Path) -> None:
    """A constraint the text does not state as a placement is a miss, listed with its `says`."""
    folder = _folder(tmp_path, "tiny_miss", "", [
        {"fact": "on(hair_dryer, bathtub)", "says": "Whoever used the hair dryer last"},
    ])
    recall = bench.placement_recall(folder, ["tiny_miss"])
    assert (recall.read, recall.stated) == (0, 1)
    assert recall.missed == (("tiny_miss", "on(hair_dryer, bathtub)", "Whoever used the hair dryer last"),)


def test_a_set_without_placements_shares_nothing(tmp_path: Path) -> None:
    """A set stating no placement reads none and misses none (printed as `-`)."""
    folder = _folder(tmp_path, "tiny_none", "", [])
    recall = bench.placement_recall(folder, ["tiny_none"])
    assert (recall.read, recall.stated, recall.missed) == (0, 0, ())


def test_why_lists_a_development_rows_misses_and_never_a_held_out_or_fresh_ones(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """`--why` names a missed fact of a development row; a held-out or fresh row prints its share
    only, so whoever tunes the reader learns nothing of those sets' facts."""
    folder = _folder(tmp_path, "tiny_miss", "", [
        {"fact": "on(hair_dryer, bathtub)", "says": "Whoever used the hair dryer last"},
    ])
    hidden = sorted(bench.UNSEEN | bench.FRESH)
    bench.print_placements([("new", folder)] + [(name, folder) for name in hidden], smoke=False, why=True)
    out = capsys.readouterr().out
    assert out.count("missed tiny_miss: on(hair_dryer, bathtub)") == 1
    assert out.count("Whoever used") == 1
    for name in hidden:
        assert any(line.split()[:len(name.split())] == name.split() and line.rstrip().endswith("0.0")
                   for line in out.splitlines())
    assert out.splitlines()[-1].startswith("placement_recall new=0.0 ")
