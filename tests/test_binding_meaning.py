"""One judge for every method: roles bound by meaning, checked maps, the binding on record
(`domain.roles`; issue 45). Environments are the committed reference ones with their objects
renamed as a user or a real model would name them, and synthetic ones on categories and names
that no built-in task uses."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest

from logicenveval.baselines.drafts import env_from_draft
from logicenveval.baselines.replies import WrittenEnvironment
from logicenveval.benchmark import load_task, policy_path
from logicenveval.domain.catalog import load_catalog
from logicenveval.domain.roles import bind_roles, parse_role_map, prepare_env
from logicenveval.envfiles import env_from_dict
from logicenveval.errors import ConfigError
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import Role
from logicenveval.runner.evaluation import evaluate_env
from logicenveval.sim.loader import load_policy

CATALOG = load_catalog()
ENVS = Path(__file__).resolve().parents[1] / "reports" / "reference" / "envs"
SHELVES = ("shelf_novels", "shelf_essays", "shelf_other")


def _reference(task_id: str, generator: str = "logicenvgen") -> str:
    return (ENVS / generator / task_id / f"{generator}-00.json").read_text(encoding="utf-8")


def _bookshelf() -> str:
    """The reference bookshelf environment with its shelves' ids the task's role names (the
    offline model names them by purpose first, `novel_shelf`; the tests below rename from roles)."""
    text = _reference("bedroom_bookshelf_sorting")
    for named, role in (("novel_shelf", "shelf_novels"), ("essay_shelf", "shelf_essays"),
                        ("other_shelf", "shelf_other")):
        text = text.replace(f'"{named}"', f'"{role}"')
    return text


def _renamed(text: str, names: dict[str, str], *, attributes: dict[str, dict[str, str]] | None = None,
             keep_roles: bool = False) -> EnvSpec:
    """The environment of `text` with object ids renamed (everywhere they are written), its role
    map dropped (unless `keep_roles`) and `attributes` stated on the renamed objects."""
    for old, new in names.items():
        text = re.sub(rf'"{old}"', f'"{new}"', text)
    data: dict[str, Any] = json.loads(text)
    if not keep_roles:
        data["roles"] = {}
    for o in data["objects"]:
        o.setdefault("attributes", {}).update((attributes or {}).get(o["id"], {}))
    return env_from_dict(data)


def _judge(task_id: str, env: EnvSpec) -> Any:
    task = load_task(task_id)
    policies = {k: load_policy(policy_path(task, k)) for k in ("correct", "counterfactual", "unreachable",
                                                               "lackbranch")}
    return evaluate_env("t", task, env, policies, CATALOG).sample


def test_reference_bookshelf_environment_with_role_named_shelves_binds_by_id() -> None:
    sample = _judge("bedroom_bookshelf_sorting", _renamed(_bookshelf(), {}))
    assert sample.well_formed, sample.problems
    assert {r: sample.binding[r].object for r in SHELVES} == {r: r for r in SHELVES}
    assert {sample.binding[r].reason for r in SHELVES} == {"id"}


def test_shelves_named_in_plain_english_bind_by_their_name_words() -> None:
    """novel_shelf = shelf_novels: the words of the name, lemmatised, in any order."""
    env = _renamed(_bookshelf(),
                   {"shelf_novels": "novel_shelf", "shelf_essays": "essay_shelf", "shelf_other": "other_shelf"})
    sample = _judge("bedroom_bookshelf_sorting", env)
    assert sample.well_formed, sample.problems
    assert {r: sample.binding[r].object for r in SHELVES} == {
        "shelf_novels": "novel_shelf", "shelf_essays": "essay_shelf", "shelf_other": "other_shelf"}
    assert {sample.binding[r].reason for r in SHELVES} == {"name words"}


def test_shelves_that_state_their_purpose_bind_by_attribute() -> None:
    env = _renamed(_bookshelf(),
                   {"shelf_novels": "shelf_a", "shelf_essays": "shelf_b", "shelf_other": "shelf_c"},
                   attributes={"shelf_a": {"purpose": "novels"}, "shelf_b": {"purpose": "Essays"},
                               "shelf_c": {"purpose": "other books"}})
    sample = _judge("bedroom_bookshelf_sorting", env)
    assert sample.well_formed and not sample.violations, (sample.problems, sample.violations)
    assert {r: sample.binding[r].object for r in SHELVES} == {
        "shelf_novels": "shelf_a", "shelf_essays": "shelf_b", "shelf_other": "shelf_c"}
    assert {sample.binding[r].reason for r in SHELVES} == {"attribute"}


def test_shelves_named_only_by_position_stay_unbound_the_judge_never_guesses() -> None:
    env = _renamed(_bookshelf(),
                   {"shelf_novels": "top_shelf", "shelf_essays": "middle_shelf", "shelf_other": "bottom_shelf"})
    sample = _judge("bedroom_bookshelf_sorting", env)
    assert not sample.well_formed
    assert all(sample.binding[r].object is None for r in SHELVES)
    text = " ".join(sample.problems)
    assert "top_shelf has no purpose" in text and "state purpose on the object meant" in text
    # the same shelves for roles without attributes: every shelf qualifies, the role is ambiguous
    roles = {r: Role(category="wall_shelf") for r in SHELVES}
    b = bind_roles(env, roles, CATALOG)
    assert not b.well_formed and set(b.candidates) == set(SHELVES)
    assert all("3 objects qualify" in p for p in b.problems)


def test_an_object_whose_id_is_the_role_name_plays_it_for_every_method() -> None:
    """CoT and IFG drafts leave a role out of the map when no object gives it: the judge binds it
    by id as for LogicEnvGen's replies (they wrote null, which read as 'absent', before)."""
    task_id = "kitchen_dish_cleanup"
    reference = EnvSpec.model_validate_json(_reference(task_id))
    brief = load_task(task_id).brief()
    objects = []
    for o in reference.objects:
        placement = ("floor" if o.support == "floor" else "wall" if o.support == "wall"
                     else f"on:{o.support}" if o.support else f"inside:{o.container}")
        objects.append({"id": o.id, "category": o.category, "room": o.room, "placement": placement,
                        "position": o.position, "size": o.size, "yaw": o.yaw,
                        "attributes": dict(o.attributes), "states": dict(o.states)})
    draft = WrittenEnvironment.model_validate({
        "rooms": [{"id": r.id, "type": r.type, "polygon": r.polygon} for r in reference.rooms],
        "doors": [{"rooms": list(d.rooms), "segment": d.segment} for d in reference.doors],
        "windows": [], "objects": objects})
    drafted = env_from_draft(brief, env_id="cot-00", generator="cot", draft=draft)
    assert drafted.roles == {}
    as_cot = _judge(task_id, drafted)
    as_logicenvgen = _judge(task_id, reference)
    assert as_cot.well_formed == as_logicenvgen.well_formed
    assert as_cot.covered_paths == as_logicenvgen.covered_paths
    assert as_cot.verdicts == as_logicenvgen.verdicts
    assert {r: c.object for r, c in as_cot.binding.items()} == {
        r: c.object for r, c in as_logicenvgen.binding.items()}


def test_a_forged_map_is_refused_and_the_honest_binding_judged() -> None:
    """`"table": "sofa", "sofa": "sofa"`: one object for two roles, one of them of another
    category: that entry is refused and the role bound by meaning."""
    task_id = "clean_living_room"
    honest = EnvSpec.model_validate_json(_reference(task_id))
    roles = dict(honest.roles)
    sofa = next(o.id for o in honest.objects if o.category == "sofa")
    forged = honest.model_copy(update={"roles": {**roles, "table": sofa, "sofa": sofa}})
    task = load_task(task_id)
    b = prepare_env(forged, task.roles, CATALOG).binding
    assert [m.split(",")[0] for m in b.refused] == [f"table is mapped to {sofa}"]
    assert "but the task's table is a" in b.refused[0]
    assert b.roles["sofa"] == sofa and b.roles["table"] != sofa
    judged, fair = _judge(task_id, forged), _judge(task_id, honest)
    assert judged.verdicts == fair.verdicts and judged.well_formed == fair.well_formed
    assert judged.refused_roles and not fair.refused_roles
    assert judged.binding["table"].reason != "explicit map"


def test_a_map_to_an_object_of_another_category_is_refused() -> None:
    env = env_from_dict({"task_id": "t", "env_id": "e", "rooms": [{"id": "r"}],
                         "objects": [{"id": "s", "category": "sofa", "room": "r"},
                                     {"id": "t1", "category": "coffee_table", "room": "r"}],
                         "roles": {"table": "s"}})
    b = bind_roles(env, {"table": Role(category="coffee_table"), "sofa": Role(category="sofa")}, CATALOG)
    assert b.roles == {"table": "t1", "sofa": "s"}
    assert b.reasons == {"table": "category", "sofa": "category"}  # the one object of its category
    assert b.refused and "a sofa, but the task's table is a coffee_table" in b.refused[0]


def test_given_roles_are_checked_like_the_map() -> None:
    task = load_task("clean_living_room")
    env = EnvSpec.model_validate_json(_reference("clean_living_room"))
    sofa = next(o.id for o in env.objects if o.category == "sofa")
    with pytest.raises(ConfigError, match="table is mapped to .*a sofa"):
        prepare_env(env, task.roles, CATALOG, {"table": sofa})
    with pytest.raises(ConfigError, match="given twice"):
        parse_role_map("sofa=a,sofa=b", task.roles)


def test_an_explicit_null_says_what_is_there() -> None:
    """Not 'role counter is not bound to an object' when an object `counter` of its category
    exists: the message names it and the way to let the harness bind it."""
    env = env_from_dict({"task_id": "t", "env_id": "e", "rooms": [{"id": "r"}],
                         "objects": [{"id": "counter", "category": "kitchen_counter", "room": "r"}],
                         "roles": {"counter": None}})
    b = bind_roles(env, {"counter": Role(category="kitchen_counter")}, CATALOG)
    assert b.roles == {"counter": None} and b.reasons == {"counter": "absent"}
    assert "counter is a kitchen_counter" in b.why["counter"]


# Generalisation: roles sharing a category, names used by no built-in task.
CUPS = {"cup_coffee": Role(category="cup", attributes={"purpose": "coffee"}),
        "cup_tea": Role(category="cup", attributes={"purpose": "tea"})}
PILLOWS = {"pillow_sofa": Role(category="pillow"), "pillow_bed": Role(category="pillow")}
TOWELS = {"towel_guest": Role(category="towel", attributes={"color": "green"}),
          "towel_kids": Role(category="towel", attributes={"color": "yellow"})}


def _objects(*objs: tuple[str, str, dict[str, str]]) -> EnvSpec:
    return env_from_dict({"task_id": "t", "env_id": "e", "rooms": [{"id": "r"}],
                          "objects": [{"id": i, "category": c, "room": "r", "attributes": a}
                                      for i, c, a in objs]})


@pytest.mark.parametrize(("roles", "objects", "expected", "reason"), [
    (CUPS, [("coffee_mug", "Cup", {}), ("mug_for_tea", "cups", {})],
     {"cup_coffee": "coffee_mug", "cup_tea": "mug_for_tea"}, "name words"),
    (CUPS, [("c1", "cup", {"purpose": "Tea"}), ("c2", "cup", {"purpose": "coffee"})],
     {"cup_coffee": "c2", "cup_tea": "c1"}, "attribute"),
    (CUPS, [("cup_tea", "cup", {}), ("cup_2", "cup", {"purpose": "coffee"})],
     {"cup_coffee": "cup_2", "cup_tea": "cup_tea"}, None),
    (PILLOWS, [("bed_pillow", "pillow", {}), ("sofa_pillows", "Pillow", {})],
     {"pillow_sofa": "sofa_pillows", "pillow_bed": "bed_pillow"}, None),  # "bed pillow" is a synonym
    (TOWELS, [("t1", "towel", {"color": "yellow"}), ("green_towel", "towel", {})],
     {"towel_guest": "green_towel", "towel_kids": "t1"}, None),
])
def test_unseen_names_bind_by_meaning(roles: dict[str, Role], objects: list[tuple[str, str, dict[str, str]]],
                                      expected: dict[str, str], reason: str | None) -> None:
    b = bind_roles(_objects(*objects), roles, CATALOG)
    assert b.well_formed and b.roles == expected, (b.problems, b.why)
    if reason is not None:
        assert set(b.reasons.values()) == {reason}


@pytest.mark.parametrize(("roles", "objects"), [
    (PILLOWS, [("pillow_left", "pillow", {}), ("pillow_right", "pillow", {})]),
    (CUPS | {"cup_spare": Role(category="cup")}, [("cup_coffee", "cup", {}), ("a", "cup", {}), ("b", "cup", {})]),
])
def test_unseen_objects_that_nothing_tells_apart_stay_ambiguous(
        roles: dict[str, Role], objects: list[tuple[str, str, dict[str, str]]]) -> None:
    b = bind_roles(_objects(*objects), roles, CATALOG)
    assert not b.well_formed and b.candidates


HOUSES = Path(__file__).parent / "fixtures" / "houses"


@pytest.mark.parametrize(("roles", "says"), [
    ("pann=a", "'pann' is not a role of the task"),
    ("pan=a,pan=b", "role 'pan' is given twice"),
    ("pan", "'pan' is not ROLE=ID"),
])
@pytest.mark.parametrize("command", ["lint", "evaluate", "import-house"])
def test_bad_roles_option_is_one_clear_error_with_exit_2_in_every_command(
        command: str, roles: str, says: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Unknown, repeated or malformed ROLEs are bad input for all three commands alike: never
    ignored, never last-wins, never a per-file finding (issue 50, item 4)."""
    from tests.cli_support import cli

    task = "kitchen_breakfast_prep"
    assert "pan" in load_task(task).roles
    folder = tmp_path / "envs" / task
    folder.mkdir(parents=True)
    (folder / "e.json").write_text(_reference(task))
    argv = {"lint": ["lint", str(tmp_path / "envs")],
            "evaluate": ["evaluate", str(tmp_path / "envs"), "--output", str(tmp_path / "out")],
            "import-house": ["import-house", str(HOUSES / "kitchen_breakfast.json"), "--task", task,
                             "--out", str(tmp_path / "house.json")]}[command]
    code, out, err = cli(capsys, *argv, "--roles", roles)
    assert code == 2, (out, err)
    assert says in err and err.count("error") == 1
    assert not (tmp_path / "out").exists() and not (tmp_path / "house.json").exists()


def test_lint_refuses_a_forged_roles_option(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """`lint --roles table=<the sofa>` said ok (issue 50, item 2): the map is checked."""
    from tests.cli_support import cli

    task = "clean_living_room"
    env = EnvSpec.model_validate_json(_reference(task))
    sofa = next(o.id for o in env.objects if o.category == "sofa")
    folder = tmp_path / "envs" / task
    folder.mkdir(parents=True)
    (folder / "e.json").write_text(_reference(task))
    code, out, _ = cli(capsys, "lint", str(tmp_path / "envs"), "--roles", f"table={sofa}")
    assert code == 1 and f"table={sofa}: table is mapped to {sofa}, a sofa, but the task's table is a" in out
