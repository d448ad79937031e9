"""`compare` says what it knows: declared directions, "inconclusive", the same words in text,
JSON and HTML, and a failure never reads as "improved" (issue 36)."""

from __future__ import annotations

import copy
import json
import re
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from logicenveval.cli import main
from logicenveval.reporting.compare import (
    IMPROVED,
    INCONCLUSIVE,
    INFO,
    REGRESSION,
    UNCHANGED,
    compare_results,
    direction,
    verdict,
)
from logicenveval.reporting.tables import COLUMNS

REFERENCE = Path(__file__).resolve().parents[1] / "reports" / "reference" / "results.json"
TOL = 0.02


def _reference() -> dict[str, Any]:
    data: dict[str, Any] = json.loads(REFERENCE.read_text())
    return data


def test_directions_are_declared() -> None:
    none = {h for h, p, _ in COLUMNS if direction(p) is None}
    assert none == {"ST (ms)", "ST (ticks)", "Redundancy", "Envs"}
    assert direction(("st_ms",), judge_timing=True) == "lower"
    assert direction(("logcov",)) == direction(("faudr", "counterfactual")) == "higher"


def test_the_issue_examples() -> None:
    # FauDR CF 40.00 -> 0.00, CI [-80.00, +0.00]: not "unchanged" but inconclusive
    assert verdict(-0.4, (-0.8, 0.0), TOL, "higher") == INCONCLUSIVE
    # Redundancy 0.58 -> 0.29 is under-coverage, not an improvement: reported only
    assert verdict(-0.29, (-0.4, -0.2), TOL, direction(("redundancy",))) == INFO
    assert verdict(0.1, (0.05, 0.15), TOL, "higher") == IMPROVED
    assert verdict(-0.1, (-0.15, -0.05), TOL, "higher") == REGRESSION
    assert verdict(0.005, (-0.01, 0.015), TOL, "higher") == UNCHANGED
    assert verdict(-0.1, None, TOL, "higher") == REGRESSION  # one task: the tolerance alone


@given(st.floats(-1, 1), st.floats(-1, 1), st.floats(-1, 1), st.floats(0, 0.2),
       st.sampled_from(["higher", "lower", None]))
def test_verdict_properties(diff: float, x: float, y: float, tol: float, way: str | None) -> None:
    ci = (min(x, y), max(x, y))
    word = verdict(diff, ci, tol, way)
    if way is None:
        assert word == INFO
        return
    spans_zero = ci[0] <= 0 <= ci[1]
    if word in (IMPROVED, REGRESSION):
        assert abs(diff) > tol and not spans_zero
        gain = diff if way == "higher" else -diff
        assert (word == IMPROVED) == (gain > 0)
    elif word == INCONCLUSIVE:
        assert spans_zero and (ci[0] < -tol or ci[1] > tol)
    else:
        assert word == UNCHANGED and not (spans_zero and (ci[0] < -tol or ci[1] > tol))
    # the mirror image of a change gets the mirror verdict
    mirror = verdict(-diff, (-ci[1], -ci[0]), tol, way)
    swap = {IMPROVED: REGRESSION, REGRESSION: IMPROVED}
    assert mirror == swap.get(word, word)


def test_a_generator_that_fails_is_never_improved() -> None:
    """B's logicenvgen built nothing on half the tasks: fewer environments must not make ST,
    Redundancy or the counts "improved"."""
    a = _reference()
    b = copy.deepcopy(a)
    per = b["per_task"]["logicenvgen"]
    for task in list(per)[::2]:
        cell = per[task]
        attempted = int(cell.get("n_envs", 0)) + int(cell.get("n_failed", 0))
        for key, value in list(cell.items()):
            if isinstance(value, int | float) and not isinstance(value, bool):
                cell[key] = 0
            elif isinstance(value, dict):
                cell[key] = {k: (0 if isinstance(v, int | float) and not isinstance(v, bool) else v)
                             for k, v in value.items()}
        cell["n_failed"] = max(1, attempted)
    c = compare_results(a, b, gen_a="logicenvgen", gen_b="logicenvgen")
    assert not c.improvements, [(d.metric, d.verdict) for d in c.improvements]
    judged = {d.metric: d.verdict for d in c.deltas}
    assert judged["Redundancy"] in (INFO, UNCHANGED) and judged["ST (ticks)"] in (INFO, UNCHANGED)
    assert judged["LogCov"] == REGRESSION


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("cmp")
    assert main(["run", "--tasks", "clean_living_room,kitchen_dish_cleanup,hallway_entry_tidy",
                 "--generators", "cot,holodeck", "--executor", "inprocess", "--quiet",
                 "--output", str(out)]) == 0
    (d,) = [p for p in out.iterdir() if p.is_dir()]
    return d


def test_same_words_in_text_json_and_html(run_dir: Path, tmp_path: Path,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    page = tmp_path / "cmp" / "comparison.html"
    args = ["compare", str(run_dir), "--gen-a", "cot", "--gen-b", "holodeck", "--html", str(page)]
    main(args)
    text = capsys.readouterr().out
    main([*args, "--json"])
    data = json.loads(capsys.readouterr().out)
    html = page.read_text(encoding="utf-8")
    for d in data["pairs"][0]["metrics"]:
        word = {"regression": "REGRESSION"}.get(d["verdict"], d["verdict"])
        assert re.search(rf"{re.escape(d['metric'])}( \(%\))? .*{word}", text), (d, text)
        assert re.search(rf">{re.escape(d['metric'])}.*?>{word}</td>", html), d
        assert d["direction"] in ("higher", "lower", None)
    assert {d["metric"]: d["verdict"] for d in data["pairs"][0]["metrics"]}["Redundancy"] == "not judged"
    for gen in ("cot", "holodeck"):  # per-task rows link to both runs' detail pages
        link = re.search(rf'href="([^"]*details/{gen}/kitchen_dish_cleanup\.html)"', html)
        assert link is not None and (page.parent / link.group(1)).resolve().is_file()
