"""`evaluate ENVS_DIR`: scoring environments made elsewhere reproduces a run, file by file."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import pytest

from logicenveval.cli import main

TASKS = "clean_living_room,hallway_entry_tidy,kitchen_fridge_restock"


def _only_dir(parent: Path) -> Path:
    (d,) = [p for p in parent.iterdir() if p.is_dir()]
    return d


def _results(run_dir: Path) -> dict[str, Any]:
    data: dict[str, Any] = json.loads((run_dir / "results.json").read_text())
    return data


#: what only the generator that built an environment can say (`Attempt.realised`: does it
#: realise the trajectory of its own plan it claims); `evaluate` scores files without it
GENERATOR_SAID = ("realised_share", "n_claimed", "n_realised")


def _untimed(values: dict[str, Any]) -> dict[str, Any]:
    return {k: v for k, v in values.items() if k != "st_ms" and k not in GENERATOR_SAID}


def _samples(run_dir: Path) -> dict[tuple[str, str], dict[str, Any]]:
    out = {}
    for line in (run_dir / "samples.jsonl").read_text().splitlines():
        s = json.loads(line)
        s.pop("sim_ms")
        out[(s["task_id"], s["env_id"])] = s
    return out


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("run")
    assert main(["run", "--model", "offline", "--tasks", TASKS, "--generators", "logicenvgen,holodeck",
                 "--executor", "inprocess", "--output", str(out), "--quiet"]) == 0
    return _only_dir(out)


def _evaluate(envs: Path, out: Path, *extra: str) -> Path:
    assert main(["evaluate", str(envs), "--executor", "inprocess", "--output", str(out), *extra]) == 0
    return _only_dir(out)


def test_scoring_a_runs_envs_reproduces_its_metrics(run_dir: Path, tmp_path: Path) -> None:
    ev = _evaluate(run_dir / "envs" / "logicenvgen", tmp_path)
    a, b = _results(run_dir), _results(ev)
    assert list(b["results"]) == ["logicenvgen"] and b["tasks"] == TASKS.split(",")
    assert _untimed(a["results"]["logicenvgen"]) == _untimed(b["results"]["logicenvgen"])
    for task in TASKS.split(","):
        assert (_untimed(a["per_task"]["logicenvgen"][task])
                == _untimed(b["per_task"]["logicenvgen"][task]))
    mine = {k: v for k, v in _samples(run_dir).items() if v["generator"] == "logicenvgen"}
    assert mine == _samples(ev)
    assert "| logicenvgen |" in (ev / "leaderboard.md").read_text()
    assert b["failures"]["logicenvgen"] == []


def test_without_roles_the_binding_gives_the_same_coverage(run_dir: Path, tmp_path: Path) -> None:
    envs = tmp_path / "stripped"
    for gen in ("logicenvgen", "holodeck"):
        for src in (run_dir / "envs" / gen).glob("*/*.json"):
            if src.name == "plan.json":
                continue
            data = json.loads(src.read_text())
            data.pop("roles")
            dst = envs / gen / src.parent.name / src.name
            dst.parent.mkdir(parents=True, exist_ok=True)
            dst.write_text(json.dumps(data))
    original = _samples(run_dir)
    compared = 0
    for gen in ("logicenvgen", "holodeck"):
        ev = _evaluate(envs / gen, tmp_path / f"out-{gen}")
        for key, s in _samples(ev).items():
            if any("is ambiguous" in p for p in s["problems"]):
                continue
            compared += 1
            before = original[key]
            assert before["generator"] == gen
            assert s["covered_paths"] == before["covered_paths"], key
            assert s["well_formed"] == before["well_formed"], key
            assert s["verdicts"] == before["verdicts"], key
    assert compared >= 10
    print(f"compared {compared} environments")


def test_bad_files_are_per_file_failures(run_dir: Path, tmp_path: Path) -> None:
    envs = tmp_path / "envs"
    shutil.copytree(run_dir / "envs" / "logicenvgen", envs)
    clr = envs / "clean_living_room"
    (clr / "broken.json").write_text("{not json")
    (clr / "norooms.json").write_text(json.dumps({"task_id": "clean_living_room", "env_id": "x"}))
    other = json.loads((envs / "kitchen_fridge_restock" / "logicenvgen-00.json").read_text())
    (clr / "elsewhere.json").write_text(json.dumps(other | {"env_id": "elsewhere"}))
    (envs / "not_a_task").mkdir()
    ev = _evaluate(envs, tmp_path / "out", "--name", "mine")
    res = _results(ev)
    base = _results(run_dir)
    mine, theirs = res["results"]["mine"], base["results"]["logicenvgen"]
    assert mine["n_envs"] == theirs["n_envs"]
    # each bad file is one failed attempt: it fails PhyPR and SceVR, coverage counts what was built
    assert (mine["n_failed"], mine["n_attempted"]) == (3, theirs["n_attempted"] + 3)
    assert res["per_task"]["mine"]["clean_living_room"]["n_failed"] == 3
    assert mine["phypr"]["avg"] == pytest.approx(theirs["phypr"]["avg"] * theirs["n_attempted"]
                                                 / mine["n_attempted"])
    assert mine["scevr"] < theirs["scevr"]
    for key in ("logcov", "ld", "ji", "faudr", "n_envs"):
        assert mine[key] == theirs[key]
    fails = {f["env_id"]: f["message"] for f in res["failures"]["mine"]}
    assert set(fails) == {"broken", "norooms", "elsewhere"}
    assert "invalid JSON" in fails["broken"] and "broken.json" in fails["broken"]
    assert "rooms" in fails["norooms"]
    assert "kitchen_fridge_restock" in fails["elsewhere"] and "fix:" in fails["elsewhere"]


def test_resume_and_empty_task_folder(run_dir: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    envs = tmp_path / "envs"
    shutil.copytree(run_dir / "envs" / "logicenvgen", envs)
    ev = _evaluate(envs, tmp_path / "out", "--name", "logicenvgen")
    first = _results(ev)
    (ev / "units" / "logicenvgen" / "hallway_entry_tidy.json").unlink()
    capsys.readouterr()
    _evaluate(envs, tmp_path / "out", "--name", "logicenvgen")
    assert "scored 1 task folder(s), reused 2" in capsys.readouterr().out
    assert _untimed(_results(ev)["results"]["logicenvgen"]) == _untimed(first["results"]["logicenvgen"])
    for p in (envs / "kitchen_fridge_restock").glob("*.json"):
        p.unlink()
    res = _results(_evaluate(envs, tmp_path / "out2", "--name", "logicenvgen"))
    (fail,) = [f for f in res["failures"]["logicenvgen"] if f["task"] == "kitchen_fridge_restock"]
    assert "no valid EnvSpec" in fail["message"]
    assert res["per_task"]["logicenvgen"]["kitchen_fridge_restock"]["logcov"] == 0.0


def test_not_a_folder_exits_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["evaluate", str(tmp_path / "nope"), "--output", str(tmp_path)]) == 2
    assert "not a folder" in capsys.readouterr().err
    (tmp_path / "empty").mkdir()
    assert main(["evaluate", str(tmp_path / "empty"), "--output", str(tmp_path)]) == 2
    assert "no folder named after a task" in capsys.readouterr().err


def test_edited_files_score_into_a_new_run_folder(run_dir: Path, tmp_path: Path) -> None:
    envs = tmp_path / "envs"
    shutil.copytree(run_dir / "envs" / "logicenvgen", envs)
    first = _evaluate(envs, tmp_path / "a")
    (envs / "clean_living_room" / "logicenvgen-00.json").unlink()
    assert main(["evaluate", str(envs), "--executor", "inprocess", "--output", str(tmp_path / "a")]) == 0
    folders = sorted(p for p in (tmp_path / "a").iterdir() if p.is_dir())
    assert len(folders) == 2 and first in folders
    second = next(p for p in folders if p != first)
    assert _results(second)["results"]["envs"]["n_envs"] == _results(first)["results"]["envs"]["n_envs"] - 1


def test_every_file_bad_exits_1_with_the_reasons(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    envs = tmp_path / "envs"
    for task in ("clean_living_room", "hallway_entry_tidy"):
        (envs / task).mkdir(parents=True)
        (envs / task / "broken.json").write_text("{not json")
    code = main(["evaluate", str(envs), "--name", "mine", "--executor", "inprocess",
                 "--output", str(tmp_path / "out")])
    err = capsys.readouterr().err
    assert code == 1
    assert "mine: 2 of 2 unit(s) failed" in err and "no valid EnvSpec" in err
