"""A run's figures as DataFrames and CSV (`reporting.frames`, `export RUN_DIR --csv`): the frames
hold what results.json and samples.jsonl say, row for row, and the CLI writes them as CSV."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pandas as pd
import pytest

from logicenveval.reporting.frames import CSV_FILES, methods_frame, samples_frame, tasks_frame
from tests.cli_support import cli

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = ROOT / "reports" / "reference"


@pytest.fixture(scope="module")
def results() -> dict[str, object]:
    data: dict[str, object] = json.loads((REFERENCE / "results.json").read_text())
    return data


def test_samples_frame_has_one_row_per_sample_with_its_verdicts() -> None:
    lines = [json.loads(line) for line in (REFERENCE / "samples.jsonl").read_text().splitlines() if line]
    frame = samples_frame(REFERENCE)
    assert len(frame) == len(lines)
    assert list(frame.columns[:4]) == ["generator", "task_id", "env_id", "well_formed"]
    by_key = frame.set_index(["generator", "task_id", "env_id"])
    for sample in lines[::37]:
        row = by_key.loc[(sample["generator"], sample["task_id"], sample["env_id"])]
        assert bool(row["well_formed"]) == sample["well_formed"]
        assert row["verdicts.correct"] == sample["verdicts"]["correct"]
        assert bool(row["physics.entity"]) == sample["physics"]["entity"]
        assert row["n_killed_mutants"] == len(sample["killed_mutants"])
        assert row["n_covered_paths"] == len(sample["covered_paths"])
        assert row["covered_paths"] == "; ".join(sample["covered_paths"])
        assert json.loads(row["claimed_trajectory"]) == sample["claimed_trajectory"]


def test_methods_frame_holds_every_headline_figure_and_interval(results: dict[str, object]) -> None:
    frame = methods_frame(REFERENCE).set_index("generator")
    rows = results["results"]
    assert isinstance(rows, dict)
    assert list(frame.index) == results["generators"]  # the run's row order, not the file's sorted one
    for gen, values in rows.items():
        assert frame.loc[gen, "logcov"] == pytest.approx(values["logcov"])
        assert frame.loc[gen, "phypr.avg"] == pytest.approx(values["phypr"]["avg"])
        assert frame.loc[gen, "faudr.avg"] == pytest.approx(values["faudr"]["avg"])
        lo, hi = values["ci95"]["scevr"]
        assert (frame.loc[gen, "scevr.ci_lo"], frame.loc[gen, "scevr.ci_hi"]) == pytest.approx((lo, hi))
        assert frame.loc[gen, "n_envs"] == values["n_envs"]
    cols = list(frame.columns)
    assert cols.index("logcov.ci_lo") == cols.index("logcov") + 1  # each interval beside its metric


def test_tasks_frame_averages_to_the_method_rows() -> None:
    tasks = tasks_frame(REFERENCE)
    methods = methods_frame(REFERENCE).set_index("generator")
    assert len(tasks) == len(methods) * tasks["task_id"].nunique() == 125
    means = tasks.groupby("generator")["logcov"].mean()
    sums = tasks.groupby("generator")["n_envs"].sum()
    for gen in methods.index:
        assert means[gen] == pytest.approx(methods.loc[gen, "logcov"])
        assert sums[gen] == methods.loc[gen, "n_envs"] == len(samples_frame(REFERENCE).query("generator == @gen"))


def test_export_csv_writes_the_three_frames(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, out, _ = cli(capsys, "export", str(REFERENCE), "--csv", "--out", str(tmp_path / "csv"))
    assert code == 0
    for name, frame in zip(CSV_FILES, (samples_frame(REFERENCE), tasks_frame(REFERENCE),
                                       methods_frame(REFERENCE)), strict=True):
        assert f"wrote {tmp_path / 'csv' / name}" in out
        read = pd.read_csv(tmp_path / "csv" / name)
        assert read.shape == frame.shape and list(read.columns) == list(frame.columns)
    methods = pd.read_csv(tmp_path / "csv" / "methods.csv").set_index("generator")
    assert math.isclose(methods.loc["holodeck", "logcov"], methods_frame(REFERENCE).set_index("generator")
                        .loc["holodeck", "logcov"])


@pytest.mark.parametrize(("argv", "words"), [
    (["export", "--csv", "--out", "x"], "needs a RUN_DIR"),
    (["export", "NOWHERE", "--csv", "--out", "x"], "results.json not found"),
    (["export", "NOWHERE", "--out", "x"], "--format"),
])
def test_export_csv_bad_input_is_one_line(capsys: pytest.CaptureFixture[str], tmp_path: Path, argv: list[str],
                                          words: str, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, _, err = cli(capsys, *argv)
    assert code == 2 and words in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "x").exists()


def test_export_csv_refuses_a_file_as_the_folder(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    target = tmp_path / "taken.csv"
    target.write_text("kept")
    code, _, err = cli(capsys, "export", str(REFERENCE), "--csv", "--out", str(target))
    assert code == 2 and "not a folder" in err and target.read_text() == "kept"


def test_a_multi_seed_run_gets_a_seed_column(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, _, _ = cli(capsys, "run", "--model", "offline", "--tasks", "lamp_or_pillow_fetch", "--generators",
                     "holodeck", "--seeds", "0,1", "--executor", "inprocess", "--output", str(tmp_path),
                     "--run-id", "two", "--quiet", "--no-cache")
    assert code == 0
    samples = samples_frame(tmp_path / "two")
    assert list(samples.columns[:2]) == ["seed", "generator"]
    assert sorted(samples["seed"].unique()) == ["0", "1"]
    tasks = tasks_frame(tmp_path / "two")
    assert len(tasks) == 2 and set(tasks["seed"]) == {"0", "1"}
    assert len(methods_frame(tmp_path / "two")) == 1


def test_export_csv_never_writes_into_a_special_file(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    import os

    os.mkfifo(tmp_path / "samples.csv")
    code, _, err = cli(capsys, "export", str(REFERENCE), "--csv", "--out", str(tmp_path))
    assert code == 2 and "not a regular file" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["samples.csv"]  # nothing half-written beside it
