"""End to end through the CLI: the offline pipeline on 3 tasks, determinism, resume, compare."""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from logicenveval.cli import main

TASKS = "clean_living_room,hallway_entry_tidy,kitchen_fridge_restock"
GENERATORS = "logicenvgen,cot,ifg,holodeck"
KEYS = {"phypr", "logcov", "ld", "scevr", "faudr", "st_ms", "st_ticks", "ji", "ji_fixed", "redundancy", "n_envs",
        "plausibility", "faudr_mut", "faudr_mut_by_class", "ci95", "n_attempted", "n_failed", "measured",
        "not_measured_tasks", "budget_hit_tasks", "realised_share"}


def _run(out: Path, *extra: str) -> int:
    return main(["run", "--model", "offline", "--tasks", TASKS, "--generators", GENERATORS,
                 "--executor", "inprocess", "--output", str(out), "--quiet", *extra])


def _stable(results: dict[str, Any]) -> dict[str, Any]:
    """results.json without its timing fields."""
    out = json.loads(json.dumps(results))
    out.pop("timing")
    for section in ("results",):
        for values in out[section].values():
            values.pop("st_ms")
    for per in out["per_task"].values():
        for values in per.values():
            values.pop("st_ms")
    return out


@pytest.fixture(scope="module")
def first_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("runs")
    assert _run(out) == 0
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    return run_dir


def test_outputs_and_result_keys(first_run: Path) -> None:
    results = json.loads((first_run / "results.json").read_text())
    assert set(results["results"]) == set(GENERATORS.split(","))
    for values in results["results"].values():
        assert set(values) == KEYS
        assert set(values["phypr"]) == {"floor_plan", "entity", "relation", "avg"}
        assert set(values["faudr"]) == {"counterfactual", "unreachable", "lackbranch", "avg"}
        assert 0.0 < values["faudr_mut"] <= 1.0
        assert set(values["faudr_mut_by_class"]) == {"counterfactual", "unreachable", "lackbranch"}
    assert results["tasks"] == TASKS.split(",")
    lines = (first_run / "samples.jsonl").read_text().splitlines()
    assert len(lines) == sum(v["n_envs"] for v in results["results"].values())
    samples = [json.loads(line) for line in lines]
    assert any(s["killed_mutants"] for s in samples)
    assert all(not s["killed_mutants"] for s in samples if s["verdicts"].get("correct") != "passed")
    assert "FauDR-mut" in (first_run / "leaderboard.md").read_text()
    assert list((first_run / "envs" / "logicenvgen" / "clean_living_room").glob("*.json"))
    assert "| logicenvgen |" in (first_run / "leaderboard.md").read_text()
    html = (first_run / "leaderboard.html").read_text()
    page = (first_run / "details" / "logicenvgen" / "clean_living_room.html").read_text()
    assert "<table" in html and 'href="details/logicenvgen/clean_living_room.html"' in html
    # renders are written once and linked (relative: the folder can move whole), with the EnvSpec
    assert 'src="../../renders/logicenvgen/clean_living_room/' in page and "data:image" not in page
    assert 'href="../../envs/logicenvgen/clean_living_room/' in page
    # the paper's setup by default; with the roles the full method covers every decision path of
    # the paper's example with the minimum 3 envs (test_task_sets_outside_the_repository)
    assert results["brief"] == "description"
    clr = results["per_task"]["logicenvgen"]["clean_living_room"]
    assert clr["logcov"] >= 0.8 and clr["n_envs"] >= 2
    # what each method cost per task, to plan a run on a slow model (issue 46)
    cost = results["timing"]["per_task"]
    assert set(cost) == set(GENERATORS.split(",")) and set(cost["logicenvgen"]) == set(TASKS.split(","))
    assert set(cost["logicenvgen"]["clean_living_room"]) == {
        "generation_seconds", "requests", "cache_hits", "reasks", "prompt_tokens", "completion_tokens", "latency_s",
        "recorded_replies", "recorded_prompt_tokens", "recorded_completion_tokens", "recorded_seconds"}
    assert results["protocol"] == 7 and results["results"]["logicenvgen"]["realised_share"] == 1.0


def test_same_command_same_results_and_resume(first_run: Path, tmp_path: Path) -> None:
    first = json.loads((first_run / "results.json").read_text())
    assert _run(tmp_path) == 0
    (second_dir,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    second = json.loads((second_dir / "results.json").read_text())
    assert _stable(first) == _stable(second)
    # lose one unit and corrupt another: a re-run recomputes exactly those two
    (second_dir / "units" / "cot" / "clean_living_room.json").unlink()
    unit = second_dir / "units" / "ifg" / "hallway_entry_tidy.json"
    unit.write_text(unit.read_text()[:100])
    before = {p: p.stat().st_mtime_ns for p in (second_dir / "units").rglob("*.json")}
    assert _run(tmp_path) == 0
    after = {p: p.stat().st_mtime_ns for p in (second_dir / "units").rglob("*.json")}
    changed = sorted(p.relative_to(second_dir).as_posix() for p in after if before.get(p) != after[p])
    assert changed == ["units/cot/clean_living_room.json", "units/ifg/hallway_entry_tidy.json"]
    third = json.loads((second_dir / "results.json").read_text())
    assert _stable(third) == _stable(first)


def test_z3_layout_backend_gives_the_same_evaluation(first_run: Path, tmp_path: Path) -> None:
    assert main(["run", "--model", "offline", "--tasks", TASKS, "--generators", "logicenvgen", "--layout-solver",
                 "z3", "--executor", "inprocess", "--output", str(tmp_path), "--quiet"]) == 0
    (run_dir,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    assert run_dir.name != first_run.name
    z3_run = json.loads((run_dir / "results.json").read_text())
    assert z3_run["config"]["layout_solver"] == "z3"
    assert json.loads((first_run / "results.json").read_text())["config"]["layout_solver"] == "cpsat"
    default = _stable(json.loads((first_run / "results.json").read_text()))
    assert _stable(z3_run)["per_task"]["logicenvgen"] == default["per_task"]["logicenvgen"]
    envs = sorted((run_dir / "envs" / "logicenvgen").rglob("*-0*.json"))
    assert envs and any(p.read_bytes() != (first_run / p.relative_to(run_dir)).read_bytes() for p in envs)


def test_compare_and_report(first_run: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["compare", str(first_run), str(first_run)]) == 0
    assert main(["report", str(first_run)]) == 0
    worse = first_run.parent / "worse"
    worse.mkdir(exist_ok=True)
    results = json.loads((first_run / "results.json").read_text())
    results["results"]["logicenvgen"]["logcov"] -= 0.1
    for per in results["per_task"]["logicenvgen"].values():  # compare pairs the per-task figures
        per["logcov"] -= 0.1
    (worse / "results.json").write_text(json.dumps(results))
    assert main(["compare", str(first_run), str(worse)]) == 1
    assert "REGRESSION" in capsys.readouterr().out


def test_report_only_reads(first_run: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """`report` rebuilds the leaderboards from the units: no simulation, physics or solving."""
    import logicenveval.physics as physics
    import logicenveval.physics.check as check
    import logicenveval.scene.construct as construct
    import logicenveval.sim.simulator as simulator

    def forbidden(*args: object, **kwargs: object) -> None:
        raise AssertionError("report must not recompute")

    for module, name in ((simulator, "simulate"), (simulator.CompiledPolicy, "run"), (physics, "check_env"),
                         (check, "check_env"), (construct, "construct_environment")):
        monkeypatch.setattr(module, name, forbidden)
    pages = sorted((first_run / "details").rglob("*.html"))
    before = {p: p.read_text() for p in [first_run / "leaderboard.html", *pages]}
    svg = sorted((first_run / "renders").rglob("*.svg"))[0]
    drawn = svg.read_text()
    svg.unlink()  # renders are derived files: a lost one is re-drawn from stored data
    assert main(["report", str(first_run)]) == 0
    assert {p: p.read_text() for p in before} == before
    assert svg.read_text() == drawn
    page = before[first_run / "details" / "logicenvgen" / "clean_living_room.html"]
    assert 'data-trace="0"' in page and re.search(r'id="ticks">\{"paths":\["[^"]+"', page)  # recorded traces


def test_unit_with_a_lost_env_file_is_recomputed(first_run: Path, tmp_path: Path) -> None:
    assert _run(tmp_path, "--generators", "cot") == 0
    (run_dir,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    env = sorted((run_dir / "envs" / "cot" / "hallway_entry_tidy").glob("*.json"))[0]
    kept = env.read_bytes()
    env.unlink()  # what a power loss can do to a file written without fsync
    before = {p: p.stat().st_mtime_ns for p in (run_dir / "units").rglob("*.json")}
    assert _run(tmp_path, "--generators", "cot") == 0
    changed = [p.name for p in before if p.stat().st_mtime_ns != before[p]]
    assert changed == ["hallway_entry_tidy.json"] and env.read_bytes() == kept


def test_unreachable_endpoint_is_one_error_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", "--model", "openai:x", "--model-args", "base_url=http://127.0.0.1:9/v1",
                 "--tasks", "clean_living_room", "--output", str(tmp_path), "--quiet"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2
    assert len(err) == 1 and err[0].startswith("error: ") and "127.0.0.1:9" in err[0]


def test_generate_writes_envs_plan_and_renders(tmp_path: Path) -> None:
    assert main(["generate", "--generator", "logicenvgen", "--task", "clean_living_room",
                 "--model", "offline", "--out", str(tmp_path)]) == 0
    out = tmp_path / "clean_living_room"  # one folder per task: what `evaluate` scores
    plan = json.loads((out / "plan.json").read_text())
    assert plan["selector"] == "mtsa" and len(plan["trajectories"]) == 3
    assert len(list(out.glob("logicenvgen-*.json"))) == 3
    assert len(list(out.glob("logicenvgen-*.svg"))) == 3


@pytest.mark.slow
def test_sigkill_midway_then_resume(tmp_path: Path) -> None:
    cmd = [sys.executable, "-m", "logicenveval", "run", "--model", "offline", "--output", str(tmp_path),
           "--workers", "2", "--quiet"]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.time() + 120
    while time.time() < deadline and len(list(tmp_path.rglob("units/*/*.json"))) < 10:
        time.sleep(0.2)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    done = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("units/*/*.json")}
    assert 10 <= len(done) < 100
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    for p, mtime in done.items():
        assert p.stat().st_mtime_ns == mtime  # no finished unit computed twice
    (run_dir,) = [p for p in tmp_path.iterdir() if p.is_dir()]
    resumed = json.loads((run_dir / "results.json").read_text())
    fresh = tmp_path / "fresh"
    subprocess.run([*cmd[:-3], "--output", str(fresh), "--workers", "2", "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    (fresh_dir,) = [p for p in fresh.iterdir() if p.is_dir()]
    assert _stable(resumed) == _stable(json.loads((fresh_dir / "results.json").read_text()))


def test_task_sets_outside_the_repository(tmp_path: Path) -> None:
    """`--tasks-dir` runs the same pipeline on a task folder kept elsewhere, without code changes."""
    import shutil

    from logicenveval.benchmark import DEFAULT_TASKS_DIR

    tasks = tmp_path / "my_tasks"
    shutil.copytree(DEFAULT_TASKS_DIR / "clean_living_room", tasks / "tidy_lounge")
    data = json.loads((tasks / "tidy_lounge" / "task.json").read_text())
    data["id"] = "tidy_lounge"
    (tasks / "tidy_lounge" / "task.json").write_text(json.dumps(data))
    out = tmp_path / "out"
    assert main(["run", "--model", "offline", "--tasks-dir", str(tasks), "--generators", "logicenvgen",
                 "--brief", "roles", "--executor", "inprocess", "--output", str(out), "--quiet"]) == 0
    (run_dir,) = [p for p in out.iterdir() if p.is_dir()]
    results = json.loads((run_dir / "results.json").read_text())
    assert results["tasks"] == ["tidy_lounge"] and results["results"]["logicenvgen"]["logcov"] == 1.0
    assert results["per_task"]["logicenvgen"]["tidy_lounge"]["n_envs"] == 3  # the minimum cover


def test_run_export_writes_houses_that_pass_check_house(first_run: Path) -> None:
    assert _run(first_run.parent, "--export", "procthor,glb") == 0  # resumes: units reused
    envs = [p for p in (first_run / "envs").rglob("*.json")
            if p.name not in ("plan.json", "brief.json") and not p.name.endswith(".house.json")]
    houses = sorted((first_run / "envs").rglob("*.house.json"))
    assert len(houses) == len(envs) == len(list((first_run / "envs").rglob("*.glb")))
    assert main(["check-house", *map(str, houses)]) == 0
    assert _run(first_run.parent, "--export", "procthor") == 0  # nothing left to write
    assert sorted((first_run / "envs").rglob("*.house.json")) == houses
