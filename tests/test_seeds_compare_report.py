"""Seeds, bootstrap intervals, the paired compare and the merged leaderboard."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.cli import main
from logicenveval.metrics.uncertainty import (
    CI_METRICS,
    cells_of,
    ci95,
    paired_difference,
    point_metrics,
)
from logicenveval.reporting.tables import metric

REFERENCE = Path(__file__).resolve().parents[1] / "reports" / "reference" / "results.json"
TASKS = "clean_living_room,hallway_entry_tidy,kitchen_fridge_restock"


def _load(run_dir: Path) -> dict[str, Any]:
    data: dict[str, Any] = json.loads((run_dir / "results.json").read_text())
    return data


def _only_dir(parent: Path) -> Path:
    (d,) = [p for p in parent.iterdir() if p.is_dir()]
    return d


def test_point_metrics_equal_aggregate_on_the_reference_run() -> None:
    ref = json.loads(REFERENCE.read_text())
    for gen, values in ref["results"].items():
        got = point_metrics(list(cells_of(ref, gen).values()))
        optional = [p for p in [("st_ticks",), ("faudr_mut",), ("plausibility", "rate")]
                    if metric(values, p) is not None]
        for path in [*CI_METRICS, ("redundancy",), ("n_envs",), *optional]:
            assert metric(got, path) == pytest.approx(metric(values, path), abs=1e-12), (gen, path)


_cell = st.fixed_dictionaries({
    "n_envs": st.integers(0, 6), "n_failed": st.integers(0, 1),
    "logcov": st.floats(0, 1), "ld": st.floats(0, 1), "ji": st.floats(0, 1),
    "redundancy": st.floats(0, 3), "st_ms": st.floats(0, 50),
    "faudr": st.fixed_dictionaries({k: st.booleans() for k in ("counterfactual", "unreachable", "lackbranch")}),
}).flatmap(lambda c: st.fixed_dictionaries({
    "n_floor_plan_ok": st.integers(0, c["n_envs"]), "n_entity_ok": st.integers(0, c["n_envs"]),
    "n_relation_ok": st.integers(0, c["n_envs"]), "n_valid": st.integers(0, c["n_envs"]),
}).map(lambda d: {**c, **d}))


@settings(max_examples=40, deadline=None)
@given(st.lists(_cell, min_size=1, max_size=6), st.integers(1, 3))
def test_intervals_bracket_the_estimate_and_are_reproducible(cells: list[dict[str, Any]], n_seeds: int) -> None:
    keyed = {(f"t{i}", s): c for i, c in enumerate(cells) for s in range(n_seeds)}
    point = point_metrics(list(keyed.values()))
    a = ci95(keyed, np.random.default_rng(1), n=300)
    assert a == ci95(keyed, np.random.default_rng(1), n=300)
    for path in CI_METRICS:
        lo, hi = metric(a, path + ("0",)), metric(a, path + ("1",))
        if len(cells) < 2:  # one task resamples to itself: no interval
            assert lo is None and hi is None
            continue
        assert lo is not None and hi is not None and lo <= hi + 1e-12
        values = [metric(point_metrics([c]), path) for c in cells]
        assert min(v for v in values if v is not None) - 1e-9 <= lo
        assert hi <= max(v for v in values if v is not None) + 1e-9
    same = paired_difference(keyed, keyed, np.random.default_rng(2), n=200)
    assert all(max(abs(x) for x in v if x is not None) < 1e-12 for v in same.values())
    assert all((v[1] is None) == (len(cells) < 2) for v in same.values())
    assert point["n_envs"] == n_seeds * sum(c["n_envs"] for c in cells)


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    base = tmp_path_factory.mktemp("runs")
    common = ["--model", "offline", "--tasks", TASKS, "--executor", "inprocess", "--quiet"]
    assert main(["run", *common, "--generators", "logicenvgen,holodeck", "--seeds", "0,1",
                 "--output", str(base / "seeds")]) == 0
    assert main(["run", *common, "--generators", "logicenvgen", "--output", str(base / "lg")]) == 0
    lg = _only_dir(base / "lg")
    seeds = _only_dir(base / "seeds")
    # the holodeck environments of seed 0, scored under the row name logicenvgen
    assert main(["evaluate", str(seeds / "seed0" / "envs" / "holodeck"), "--name", "logicenvgen",
                 "--executor", "inprocess", "--output", str(base / "holo")]) == 0
    return {"seeds": seeds, "lg": lg, "holo": _only_dir(base / "holo")}


def test_seeds_give_one_run_per_seed_and_intervals(runs: dict[str, Path]) -> None:
    res = _load(runs["seeds"])
    assert res["seeds"] == [0, 1] and res["seed"] is None
    assert {_load(runs["seeds"] / f"seed{s}")["seed"] for s in (0, 1)} == {0, 1}
    for gen in ("logicenvgen", "holodeck"):
        values = res["results"][gen]
        assert set(res["per_task_seed"][gen]) == set(TASKS.split(","))
        assert values["n_envs"] == sum(_load(runs["seeds"] / f"seed{s}")["results"][gen]["n_envs"]
                                       for s in (0, 1))
        for path in CI_METRICS:
            lo, hi = metric(values["ci95"], path + ("0",)), metric(values["ci95"], path + ("1",))
            v = metric(values, path)
            assert lo is not None and hi is not None and v is not None and lo <= v <= hi
    single = _load(runs["lg"])["results"]["logicenvgen"]
    assert set(single["ci95"]) == {"logcov", "ld", "scevr", "ji", "phypr", "faudr"}
    assert set(single["ci95"]["phypr"]) == {"floor_plan", "entity", "relation", "avg"}


def test_stability_table_summarises_the_seed_runs(runs: dict[str, Path]) -> None:
    """benchmarks/stability.py (paper App. C): per method, mean ± sd (range) over the seed runs."""
    import statistics
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
    from llm_validity import portable_model as _model  # type: ignore[import-not-found]
    from stability import load_runs, table  # type: ignore[import-not-found]

    assert _model("llamacpp:/home/me/models/m.Q4.gguf") == "llamacpp:m.Q4.gguf"  # no machine paths
    assert _model("openai:qwen2.5-coder") == "openai:qwen2.5-coder" and _model("offline") == "offline"

    caption, header, _, *rows = table(load_runs(runs["seeds"]))
    assert "2 runs (seeds 0, 1)" in caption and header.startswith("| method | PhyPR | LogCov")
    assert header.endswith("| Valid replies | Failed attempts | Envs |")
    assert sorted(r.split(" | ")[0].removeprefix("| ") for r in rows) == ["holodeck", "logicenvgen"]
    per_seed = [_load(runs["seeds"] / f"seed{s}")["results"] for s in (0, 1)]
    for row in rows:
        gen, *cells = row.strip("| ").split(" | ")
        got = re.fullmatch(r"([\d.]+) ± ([\d.]+) \(([\d.]+)–([\d.]+)\)", cells[1])  # LogCov
        assert got is not None
        values = [100 * r[gen]["logcov"] for r in per_seed]
        mean, sd, lo, hi = map(float, got.groups())
        assert (mean, sd, lo, hi) == tuple(round(v, 1) for v in (
            statistics.fmean(values), statistics.pstdev(values), min(values), max(values)))
        failed = re.match(r"([\d.]+) ±", cells[-2])  # Failed attempts: n_failed / n_attempted
        assert failed is not None and float(failed.group(1)) == round(100 * statistics.fmean(
            r[gen]["n_failed"] / r[gen]["n_attempted"] for r in per_seed), 1)
        valid = re.match(r"([\d.]+) ±", cells[-3])  # Valid replies: the llm block's share
        llm = [_load(runs["seeds"] / f"seed{s}")["llm"][gen]["all"]["valid_share"] for s in (0, 1)]
        assert valid is not None and float(valid.group(1)) == round(100 * statistics.fmean(llm), 1)
        envs = re.match(r"([\d.]+) ±", cells[-1])
        assert envs is not None and float(envs.group(1)) == statistics.fmean(
            r[gen]["n_envs"] for r in per_seed)


def test_seeds_resume_per_seed(runs: dict[str, Path], capsys: pytest.CaptureFixture[str]) -> None:
    (runs["seeds"] / "seed1" / "units" / "holodeck" / "clean_living_room.json").unlink()
    before = _load(runs["seeds"])
    capsys.readouterr()
    assert main(["run", "--model", "offline", "--tasks", TASKS, "--executor", "inprocess", "--quiet",
                 "--generators", "logicenvgen,holodeck", "--seeds", "0,1",
                 "--output", str(runs["seeds"].parent)]) == 0
    assert "computed 1 unit(s), reused 11" in capsys.readouterr().out
    after = _load(runs["seeds"])
    assert after["per_task_seed"] == before["per_task_seed"] or all(
        {k: v for k, v in after["per_task_seed"][g][t][s].items() if k != "st_ms"}
        == {k: v for k, v in before["per_task_seed"][g][t][s].items() if k != "st_ms"}
        for g in after["per_task_seed"] for t in after["per_task_seed"][g] for s in ("0", "1"))


def test_report_merges_runs_with_intervals(runs: dict[str, Path], tmp_path: Path) -> None:
    assert main(["report", str(runs["seeds"]), str(runs["lg"]), str(runs["holo"]),
                 "--out", str(tmp_path)]) == 0
    md = (tmp_path / "leaderboard.md").read_text()
    assert "| Run | Model | Seeds | Method | n (tasks×seeds) |" in md
    assert f"| {runs['seeds'].name} | offline | 0,1 | logicenvgen | 3×2 |" in md
    assert f"| {runs['holo'].name} | external | 0 | logicenvgen | 3 |" in md
    assert re.search(r"\| \d+\.\d\d \[\d+\.\d\d, \d+\.\d\d\] \|", md) and " ± " not in md
    html = (tmp_path / "leaderboard.html").read_text()
    # every run keeps its drill-down, written into the merged folder (self-contained)
    for k in range(3):
        assert f'href="details/run{k}/' in html
    assert (tmp_path / "details" / "run0" / "seed1" / "holodeck" / "clean_living_room.html").exists()
    assert (tmp_path / "details" / "run2" / "logicenvgen" / "clean_living_room.html").exists()
    assert main(["report", str(runs["seeds"])]) == 0
    assert "[" in (runs["seeds"] / "leaderboard.md").read_text()


def test_report_refuses_mixed_task_sets(runs: dict[str, Path], tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", "--model", "offline", "--tasks", "clean_living_room", "--generators", "holodeck",
                 "--executor", "inprocess", "--quiet", "--output", str(tmp_path / "one")]) == 0
    capsys.readouterr()
    assert main(["report", str(runs["lg"]), str(_only_dir(tmp_path / "one")),
                 "--out", str(tmp_path / "m")]) == 2
    assert "covers other tasks" in capsys.readouterr().err


def test_compare_with_itself_is_no_regression(runs: dict[str, Path], capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["compare", str(runs["lg"]), str(runs["lg"])]) == 0
    assert main(["compare", str(runs["seeds"]), str(runs["seeds"])]) == 0
    assert "no regression" in capsys.readouterr().out


def test_compare_flags_holodeck_renamed_as_logicenvgen(runs: dict[str, Path],
                                                       capsys: pytest.CaptureFixture[str]) -> None:
    capsys.readouterr()
    assert main(["compare", str(runs["lg"]), str(runs["holo"])]) == 1
    out = capsys.readouterr().out
    # e.g. "REGRESSION logicenvgen LogCov: -52.38 [-66.67, -33.33]": the drop in percentage
    # points and its paired interval
    assert re.search(r"REGRESSION logicenvgen LogCov: -\d+\.\d\d \[-\d+\.\d\d, -\d+\.\d\d\]", out), out
    assert "regression(s)" in out and "LD" in out


def test_compare_refuses_other_task_sets_unless_common(runs: dict[str, Path], tmp_path: Path,
                                                       capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", "--model", "offline", "--tasks", "clean_living_room,hallway_entry_tidy",
                 "--generators", "logicenvgen", "--executor", "inprocess", "--quiet",
                 "--output", str(tmp_path)]) == 0
    two = _only_dir(tmp_path)
    capsys.readouterr()
    # a task of A that B lacks is a regression unless allowed
    assert main(["compare", str(runs["lg"]), str(two)]) == 1
    assert "task kitchen_fridge_restock of logicenvgen: missing in B" in capsys.readouterr().out
    assert main(["compare", str(runs["lg"]), str(two), "--allow-missing"]) == 0
    changed = _load(runs["lg"])
    changed["benchmark"]["task_sha256"]["clean_living_room"] = "0" * 16
    (tmp_path / "changed").mkdir()
    (tmp_path / "changed" / "results.json").write_text(json.dumps(changed))
    assert main(["compare", str(runs["lg"]), str(tmp_path / "changed")]) == 2
    assert "benchmark versions" in capsys.readouterr().err
    assert main(["compare", str(runs["lg"]), str(tmp_path / "changed"), "--common-tasks"]) == 0
    assert "2 task(s)" in capsys.readouterr().out
