"""Explicit task constraints and optional roles (issue 34, Build 1-2): the facts a description
fixes in every situation make an environment that violates one an invalid scenario, and roles the
description lets be absent leave an environment well-formed when they are."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from logicenveval.benchmark import load_task, policy_path
from logicenveval.benchmark_validation import validate_task
from logicenveval.cli import main
from logicenveval.domain.catalog import load_catalog
from logicenveval.envfiles import env_to_json
from logicenveval.metrics.compute import task_metrics
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import Task, task_from_dict
from logicenveval.model.tree import trajectory_from_assignment
from logicenveval.runner.evaluation import evaluate_env
from logicenveval.sim.loader import load_policy
from logicenveval.sim.situations import situation_env
from logicenveval.sim.worlds import situation_worlds

CATALOG = load_catalog()
TASK = load_task("clean_living_room")
NO_WIPES = {"toy_on_floor": "yes", "toy_kind": "doll", "book_on_floor": "no", "wipe_on_table": "no"}


def _policies(task: Task) -> dict[str, Any]:
    return {k: load_policy(policy_path(task, k)) for k in task.policies}


def _without_wipes() -> EnvSpec:
    """The paper's example: the living room with no wet wipes at all, as a generator told only
    the description writes it (no object, no role entry)."""
    env = situation_env(TASK, trajectory_from_assignment(TASK, NO_WIPES), CATALOG)
    roles = {r: o for r, o in env.roles.items() if r != "wet_wipe"}
    return env.model_copy(update={"objects": [o for o in env.objects if o.id != "wet_wipe"],
                                  "roles": roles, "env_id": "no-wipes"})


def _edit(env: EnvSpec, oid: str, **update: Any) -> EnvSpec:
    return env.model_copy(update={"objects": [o.model_copy(update=update) if o.id == oid else o
                                              for o in env.objects]})


def test_an_environment_without_the_optional_wipes_is_well_formed_and_valid() -> None:
    done = evaluate_env("g", TASK, _without_wipes(), _policies(TASK), CATALOG)
    s = done.sample
    assert s.well_formed and s.problems == [] and s.violations == []
    assert "clean_mark:wipe_on_table=no" in s.covered_paths
    assert s.verdicts["correct"] == "passed"
    assert task_metrics(TASK, [s]).n_valid == 1


@pytest.mark.parametrize(("edit", "fact", "instead"), [
    ({"attributes": {"color": "blue"}}, "attr(red_box, color, red)", "red_box has color=blue"),
    ({"states": {"dirty": False}}, "state(mark, dirty)", "mark is not dirty"),
])
def test_violating_a_constraint_makes_the_environment_invalid_naming_the_fact(
        edit: dict[str, Any], fact: str, instead: str) -> None:
    oid = "red_box" if "attributes" in edit else "mark"
    env = _edit(_without_wipes(), oid, **edit)
    s = evaluate_env("g", TASK, env, _policies(TASK), CATALOG).sample
    assert s.well_formed  # judged, and its logic counted ...
    assert len(s.violations) == 1 and fact in s.violations[0] and instead in s.violations[0]
    assert task_metrics(TASK, [s]).n_valid == 0  # ... but no valid scenario
    assert s.killed_mutants == []


def test_a_constraint_must_quote_the_description_and_name_known_roles() -> None:
    data = json.loads((policy_path(TASK, "correct").parents[1] / "task.json").read_text())
    data["constraints"] = [{"fact": "attr(red_box, color, red)", "says": "a crimson box"}]
    with pytest.raises(ValueError, match="not in the task description"):
        task_from_dict(data)
    data["constraints"] = [{"fact": "attr(blue_box, color, blue)", "says": "a red one for dolls"}]
    with pytest.raises(ValueError, match="blue_box"):
        task_from_dict(data)
    data["constraints"] = [{"fact": "holding(toy)", "says": "a red one for dolls"}]
    with pytest.raises(ValueError, match="agent"):
        task_from_dict(data)


def test_a_constraint_about_an_absent_optional_role_is_vacuous() -> None:
    task = TASK.model_copy(update={"constraints": [
        *TASK.constraints, TASK.constraints[0].model_copy(update={"fact": "on(wet_wipe, table)"})]})
    env = _without_wipes()
    holds = lambda name, args: False  # noqa: E731 - nothing holds: every fact is violated ...
    violated = {c.fact for c in task.violated(holds, env.roles)}
    assert "on(wet_wipe, table)" not in violated  # ... except the one about the absent wipes
    assert "attr(red_box, color, red)" in violated


def test_validate_proves_constraints_against_every_situation() -> None:
    bad = TASK.model_copy(update={"constraints": [
        *TASK.constraints, TASK.constraints[0].model_copy(update={"fact": "not on(toy, floor)"})]})
    report = validate_task(bad, simulate=False)
    assert any(p.where == "constraints" and "not on(toy, floor)" in p.message for p in report.problems)
    unstated = TASK.model_copy(update={"constraints": TASK.constraints[1:]})
    report = validate_task(unstated, simulate=False)
    assert [p.where for p in report.problems] == ["roles.red_box.attributes.color"]


def test_situation_worlds_hold_the_constraints_and_add_absence_worlds() -> None:
    worlds = situation_worlds(TASK, trajectory_from_assignment(TASK, NO_WIPES), CATALOG)
    assert any(w.roles.get("wet_wipe") is None for w in worlds)
    for w in worlds:
        objects = {o.id: o for o in w.objects}
        assert objects["red_box"].attributes["color"] == "red"
        assert objects["mark"].states.get("dirty", True)


def test_every_benchmark_task_states_its_role_attributes_as_constraints() -> None:
    from logicenveval.benchmark import load_tasks

    for task in load_tasks():
        stated = {c.fact.replace(" ", "") for c in task.constraints}
        for role, spec in task.roles.items():
            for key, value in spec.attributes.items():
                assert f"attr({role},{key},{value})" in stated, (task.id, role)
    assert load_task("clean_living_room").roles["wet_wipe"].optional


def test_simulate_env_names_the_missing_role(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    env = _without_wipes()
    env = env.model_copy(update={"objects": [o for o in env.objects if o.id != "mop"],
                                 "roles": {r: o for r, o in env.roles.items() if r != "mop"}})
    path = tmp_path / "env.json"
    path.write_text(env_to_json(env))
    main(["simulate", "--task", TASK.id, "--policy", "correct", "--env", str(path)])
    out = capsys.readouterr().out
    assert "role mop is not bound" in out and "no object is a mop" in out


def test_task_files_stay_loadable_without_constraints() -> None:
    data = json.loads((policy_path(TASK, "correct").parents[1] / "task.json").read_text())
    data.pop("constraints")
    for spec in data["roles"].values():
        spec.pop("optional", None)
    task = task_from_dict(data)
    assert task.constraints == [] and not any(r.optional for r in task.roles.values())


def test_lint_shows_category_readings_and_constraint_problems(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    env = _edit(_without_wipes(), "red_box", attributes={"color": "blue"})
    env = env.model_copy(update={"objects": [
        o.model_copy(update={"category": "Red Toy Box"}) if o.id == "white_box" else o
        for o in env.objects]})
    folder = tmp_path / "envs" / TASK.id
    folder.mkdir(parents=True)
    (folder / "e.json").write_text(env_to_json(env))
    assert main(["lint", str(tmp_path / "envs"), "--json"]) == 1
    (report,) = json.loads(capsys.readouterr().out)
    readings = {c["object"]: (c["written"], c["read_as"]) for c in report["categories"]}
    assert readings["white_box"] == ("Red Toy Box", "toy_box") and readings["mark"] == ("floor_stain", "floor_stain")
    kinds = {p["kind"]: p["message"] for p in report["problems"]}
    assert "attr(red_box, color, red)" in kinds["constraint"]
    assert main(["lint", str(tmp_path / "envs"), "--roles", "red_box=nope"]) == 1
    assert "no object 'nope'" in capsys.readouterr().out


def test_evaluate_roles_option_binds_first(tmp_path: Path) -> None:
    env = _without_wipes()
    plain = {"red_box": "box_a", "white_box": "box_b"}
    env = env.model_copy(update={
        "roles": {r: o for r, o in env.roles.items() if r not in plain},
        "objects": [o.model_copy(update={"id": plain[o.id], "attributes": {}}) if o.id in plain
                    else o for o in env.objects]})
    folder = tmp_path / "envs" / TASK.id
    folder.mkdir(parents=True)
    (folder / "e.json").write_text(env_to_json(env).replace('"red_box"', '"box_a"')
                                   .replace('"white_box"', '"box_b"'))

    def sample(*extra: str) -> dict[str, Any]:
        out = tmp_path / f"out{len(extra)}"
        main(["evaluate", str(tmp_path / "envs"), "--executor", "inprocess", "--output", str(out), *extra])
        (run,) = list(out.iterdir())
        (line,) = (run / "samples.jsonl").read_text().splitlines()
        return dict(json.loads(line))

    unbound = sample()
    assert not unbound["well_formed"]
    assert any("role red_box is not bound" in p and "box_a has no color" in p for p in unbound["problems"])
    given = sample("--roles", "red_box=box_a,white_box=box_b")
    assert given["well_formed"] and any("attr(red_box, color, red)" in v and "has no color" in v
                                        for v in given["violations"])


def test_the_drying_rack_off_the_balcony_is_no_valid_scenario() -> None:
    """A placement the description asserts ("the drying rack out on the balcony") is a constraint:
    the rack moved into the laundry room leaves the environment judged but invalid, naming it."""
    task = load_task("laundry_drying_rack")
    assert "in_room(drying_rack, balcony)" in {c.fact for c in task.constraints}
    path = {"shirt_state": "dry", "towel_on_rack": "no", "sock_on_floor": "no"}
    env = situation_env(task, trajectory_from_assignment(task, path), CATALOG)
    assert {o.id: o.room for o in env.objects}["drying_rack"] == "balcony"
    policies = _policies(task)
    ok = evaluate_env("g", task, env, policies, CATALOG).sample
    assert ok.violations == [] and task_metrics(task, [ok]).n_valid == 1
    moved = evaluate_env("g", task, _edit(env, "drying_rack", room="laundry_room"), policies, CATALOG).sample
    assert moved.well_formed
    assert len(moved.violations) == 1 and "in_room(drying_rack, balcony)" in moved.violations[0]
    assert "the drying rack out on the balcony" in moved.violations[0]
    assert task_metrics(task, [moved]).n_valid == 0
