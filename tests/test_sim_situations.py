"""Situation environments and the paper's Clean Living Room policies, end to end."""

from __future__ import annotations

import itertools
import json
from pathlib import Path

import pytest
from sim_support import POLICIES, TASKS, living_room_task, small_catalog

from logicenveval.cli import main
from logicenveval.errors import TrajectoryError
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.tree import (
    Trajectory,
    evaluate_task,
    task_paths,
    trajectory_from_assignment,
)
from logicenveval.sim.loader import load_policy
from logicenveval.sim.simulator import simulate, simulate_file
from logicenveval.sim.situations import situation_env
from logicenveval.sim.world import holds_initial

CAT = small_catalog()
TASK = living_room_task()
TRAJECTORIES = [Trajectory(tuple(c)) for c in itertools.product(*task_paths(TASK))]
POLICY = {k: load_policy(POLICIES / f"{k}.xml", roles=TASK.roles, rooms=TASK.rooms)
          for k in ("correct", "counterfactual", "unreachable", "lackbranch")}


@pytest.fixture(scope="module")
def envs() -> dict[str, EnvSpec]:
    return {t.key: situation_env(TASK, t, CAT) for t in TRAJECTORIES}


def test_twelve_situations_reach_exactly_their_leaves(envs: dict[str, EnvSpec]) -> None:
    assert len(TRAJECTORIES) == 12
    for t in TRAJECTORIES:
        env = envs[t.key]
        reached = [o.path for o in evaluate_task(TASK, holds_initial(env, CAT))]
        assert [p.key if p else None for p in reached] == [p.key for p in t.paths]
        assert all(o.position is None for o in env.objects)
        assert env.roles == {r: r for r in TASK.roles}  # well-formed: every role bound
        assert EnvSpec.model_validate_json(env.model_dump_json(by_alias=True)) == env


def test_natural_defaults(envs: dict[str, EnvSpec]) -> None:
    env = envs[TRAJECTORIES[0].key]
    for furniture in ("sofa", "table", "red_box", "white_box"):
        assert env.obj(furniture).support == "floor"
    for small in ("wet_wipe", "mop", "book", "toy"):
        assert env.obj(small).container is None
        assert env.obj(small).support not in ("wet_wipe", "mop", "book", "toy")


def test_deterministic() -> None:
    from logicenveval.sim.situations import _situation_env

    t = TRAJECTORIES[5]
    fresh = [_situation_env(TASK, t, CAT) for _ in range(2)]  # bypass the memo
    assert fresh[0] == fresh[1] == situation_env(TASK, t, CAT)


def test_correct_passes_everywhere_and_faulty_fail_where_the_paper_says(
        envs: dict[str, EnvSpec]) -> None:
    for t in TRAJECTORIES:
        a = t.assignment()
        got = {k: simulate(p, envs[t.key], TASK, CAT).status for k, p in POLICY.items()}
        assert got["correct"] == "passed", t.key
        bad_toy = a["toy_on_floor"] == "yes" and a.get("toy_kind") == "other"
        assert got["counterfactual"] == ("precondition_violation" if bad_toy else "passed")
        doll = a["toy_on_floor"] == "yes" and a.get("toy_kind") == "doll"
        assert got["unreachable"] == ("goal_unmet" if doll else "passed")
        assert got["lackbranch"] == ("tree_failure" if a["wipe_on_table"] == "no" else "passed")


def test_counterfactual_fault_is_at_putin(envs: dict[str, EnvSpec]) -> None:
    t = trajectory_from_assignment(TASK, {"toy_on_floor": "yes", "toy_kind": "other",
                                          "book_on_floor": "no", "wipe_on_table": "yes"})
    v = simulate(POLICY["counterfactual"], envs[t.key], TASK, CAT)
    assert v.status == "precondition_violation" and v.fault_node == "PutIn"
    assert v.fault_path == ("CleanLivingRoom/Sequence/SubTree(TidyToy)[0]/Fallback/"
                            "IfThenElse[1]/Sequence[2]/PutIn[1]")


def test_unsatisfiable_trajectory_names_the_variable() -> None:
    data = json.loads((TASKS / "clean_living_room" / "task.json").read_text())
    data["variables"]["toy_kind"]["values"]["doll"] = "attr(toy, kind, doll) and inside(toy, sofa)"
    from logicenveval.model.task import task_from_dict
    task = task_from_dict(data)
    t = trajectory_from_assignment(task, {"toy_on_floor": "yes", "toy_kind": "doll",
                                          "book_on_floor": "no", "wipe_on_table": "yes"})
    with pytest.raises(TrajectoryError, match="toy_kind"):
        situation_env(task, t, CAT)


def test_cli_must_show(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    cat = tmp_path / "catalog.json"
    cat.write_text(CAT.model_dump_json(by_alias=True))
    base = ["simulate", "--task", "clean_living_room", "--catalog", str(cat), "--situation",
            "toy_on_floor=yes,toy_kind=other,book_on_floor=no,wipe_on_table=yes", "--json"]
    assert main([*base, "--policy", "counterfactual"]) == 1
    out = json.loads(capsys.readouterr().out)
    assert out["status"] == "precondition_violation" and out["fault_node"] == "PutIn"
    assert main([*base, "--policy", "correct"]) == 0
    assert json.loads(capsys.readouterr().out)["status"] == "passed"
    assert main([*base[:-1], "--policy", "correct", "--trace"]) == 0
    assert "passed" in capsys.readouterr().out


def test_cli_bad_situation(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    cat = tmp_path / "catalog.json"
    cat.write_text(CAT.model_dump_json(by_alias=True))
    assert main(["simulate", "--task", "clean_living_room", "--policy", "correct",
                 "--catalog", str(cat), "--situation", "toy_on_floor=maybe"]) == 2
    err = capsys.readouterr().err
    assert "--situation" in err and "'maybe'" in err


def test_cli_env_file_and_policy_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    cat = tmp_path / "catalog.json"
    cat.write_text(CAT.model_dump_json(by_alias=True))
    env = situation_env(TASK, TRAJECTORIES[0], CAT)
    env_file = tmp_path / "env.json"
    env_file.write_text(json.dumps(env.to_json_dict()))
    bad = tmp_path / "bad.xml"
    bad.write_text('<root BTCPP_format="4"><BehaviorTree ID="M">\n<Fly obj="toy"/>'
                   '</BehaviorTree></root>')
    args = ["simulate", "--task", "clean_living_room", "--catalog", str(cat), "--env",
            str(env_file), "--json", "--policy"]
    assert main([*args, "unreachable"]) == 1
    assert json.loads(capsys.readouterr().out)["status"] == "goal_unmet"
    # a policy that cannot be loaded is bad input: exit 2 naming file:line and a fix; the
    # Python API `simulate_file` judges it instead (an `unknown_node` verdict)
    assert main([*args, str(bad)]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and f"{bad}:2" in captured.err and "unknown node <Fly>" in captured.err
    assert "fix:" in captured.err
    verdict = simulate_file(bad, env, TASK, CAT)
    assert verdict.status == "unknown_node" and ":2" in verdict.message
