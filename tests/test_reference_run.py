"""The default run reproduces the committed reference run (`reports/reference/`): a speed-up
or a refactoring that moves any figure fails here, and a change meant to move figures comes with
the reference regenerated (`python tools/docs_figures.py --rerun`)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from logicenveval.cli import main

REFERENCE = Path(__file__).resolve().parents[1] / "reports" / "reference" / "results.json"


def _judged(results: dict[str, Any]) -> dict[str, Any]:
    """What the run judged: every figure, per task and failure; timings (`st_ms` included) are
    the machine's."""
    out = {key: json.loads(json.dumps(results[key])) for key in ("results", "per_task", "failures", "brief", "seed")}
    for values in out["results"].values():
        values.pop("st_ms", None)
        values.get("ci95", {}).pop("st_ms", None)
    for per in out["per_task"].values():
        for values in per.values():
            values.pop("st_ms", None)
    return out


def test_the_default_run_reproduces_the_reference_run(tmp_path: Path) -> None:
    reference = json.loads(REFERENCE.read_text(encoding="utf-8"))
    assert main(["run", "--model", "offline", "--workers", "2", "--output", str(tmp_path), "--run-id", "r",
                 "--quiet"]) == 0
    results = json.loads((tmp_path / "r" / "results.json").read_text(encoding="utf-8"))
    assert results["config"]["generators"] == reference["config"]["generators"]
    assert _judged(results) == _judged(reference)
