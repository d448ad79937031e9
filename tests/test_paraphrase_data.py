"""The reworded descriptions used by benchmarks/paraphrase_coverage.py cover every benchmark task."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from logicenveval.benchmark import load_tasks

DATA = Path(__file__).parent / "data"


@pytest.mark.parametrize(("folder", "count"), [("paraphrases", 2), ("paraphrases_heldout", 1)])
def test_every_task_has_its_rewordings(folder: str, count: int) -> None:
    tasks = {t.id: t for t in load_tasks(None, None)}
    files = {p.stem: p for p in (DATA / folder).glob("*.json")}
    assert set(files) == set(tasks)
    for task_id, path in files.items():
        data = json.loads(path.read_text(encoding="utf-8"))
        assert data["task_id"] == task_id
        texts = data["paraphrases"]
        assert len(texts) == count and all(isinstance(t, str) and len(t) > 100 for t in texts)
        assert tasks[task_id].description not in texts


def test_heldout_rewordings_differ_from_the_tuned_ones() -> None:
    for path in (DATA / "paraphrases_heldout").glob("*.json"):
        held = json.loads(path.read_text(encoding="utf-8"))["paraphrases"]
        tuned = json.loads((DATA / "paraphrases" / path.name).read_text(encoding="utf-8"))["paraphrases"]
        assert not set(held) & set(tuned)
