"""Role binding for environments that carry no `roles` map (logicenveval.domain.roles)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import hypothesis.strategies as st
from hypothesis import given, settings

from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.domain.roles import RoleBinding, bind_roles, category_names, matches
from logicenveval.envfiles import env_from_dict
from logicenveval.model.envspec import EnvObject, EnvSpec
from logicenveval.model.task import Role

CATALOG = load_catalog()
REFERENCE = Path(__file__).resolve().parents[1] / "reports" / "reference" / "envs" / "logicenvgen"


def _env(objects: list[dict[str, Any]], roles: dict[str, str | None] | None = None) -> EnvSpec:
    return env_from_dict({
        "task_id": "t", "env_id": "e", "rooms": [{"id": "living_room"}],
        "objects": [{"room": "living_room", **o} for o in objects],
        **({"roles": roles} if roles is not None else {}),
    })


BOXES = {"red_box": Role(category="toy_box", attributes={"color": "red"}),
         "white_box": Role(category="toy_box", attributes={"color": "white"})}


def test_category_and_attributes_bind_each_role_to_its_object() -> None:
    env = _env([{"id": "b1", "category": "toy_box", "attributes": {"color": "white"}},
                {"id": "b2", "category": "toy_box", "attributes": {"color": "red"}},
                {"id": "s", "category": "sofa"}])
    b = bind_roles(env, BOXES | {"sofa": Role(category="sofa")}, CATALOG)
    assert b.roles == {"red_box": "b2", "white_box": "b1", "sofa": "s"}
    assert b.well_formed and b.problems == [] and b.candidates == {}
    assert b.apply(env).roles == b.roles


def test_synonyms_and_spelling_variants_name_the_category() -> None:
    names = category_names("toy_box", CATALOG)
    assert {"toy_box", "toy_chest", "toy_bin"} <= names
    role = Role(category="toy_box")
    for spelled in ("Toy Chest", "toy-chests", "ToyBin", "toy_box"):
        assert matches(EnvObject(id="x", category=spelled, room="r"), role, CATALOG), spelled
    assert not matches(EnvObject(id="x", category="laundry_basket", room="r"), role, CATALOG)


def test_an_object_lacking_the_role_attribute_does_not_agree() -> None:
    env = _env([{"id": "b", "category": "toy_box"}])
    b = bind_roles(env, BOXES, CATALOG)
    assert b.roles == {"red_box": None, "white_box": None} and b.well_formed


def test_several_candidates_is_ill_formed_naming_role_and_candidates() -> None:
    env = _env([{"id": "bag_1", "category": "trash_bag"}, {"id": "bag_2", "category": "trash bag"}])
    b = bind_roles(env, {"full_bag": Role(category="trash_bag")}, CATALOG)
    assert not b.well_formed
    assert b.roles == {"full_bag": None}
    assert b.candidates == {"full_bag": ["bag_1", "bag_2"]}
    (msg,) = b.problems
    assert "role full_bag" in msg and "bag_1" in msg and "bag_2" in msg and "roles" in msg


def test_two_roles_contesting_one_object_are_both_ambiguous() -> None:
    env = _env([{"id": "tp", "category": "toilet_paper"}])
    roles = {"roll": Role(category="toilet_paper"), "spare_roll": Role(category="toilet_paper")}
    b = bind_roles(env, roles, CATALOG)
    assert b.roles == {"roll": None, "spare_roll": None}
    assert b.candidates == {"roll": ["tp"], "spare_roll": ["tp"]}
    assert len(b.problems) == 2 and "spare_roll" in b.problems[0]


def test_evidence_binds_before_the_category_alone() -> None:
    """The one roll named `spare_roll` plays spare_roll (id); roll, which only its category
    speaks for, is left without one instead of both being ambiguous."""
    env = _env([{"id": "spare_roll", "category": "toilet_paper"}])
    roles = {"roll": Role(category="toilet_paper"), "spare_roll": Role(category="toilet_paper")}
    b = bind_roles(env, roles, CATALOG)
    assert b.roles == {"roll": None, "spare_roll": "spare_roll"} and b.well_formed
    assert b.reasons == {"roll": "absent", "spare_roll": "id"}
    assert "spare_roll plays spare_roll" in b.why["roll"]


def test_forced_choices_propagate() -> None:
    env = _env([{"id": "a", "category": "wall_shelf", "attributes": {"color": "red"}},
                {"id": "b", "category": "wall_shelf", "attributes": {"color": "blue"}}])
    roles = {"shelf": Role(category="wall_shelf"),
             "red_shelf": Role(category="wall_shelf", attributes={"color": "red"})}
    b = bind_roles(env, roles, CATALOG)
    assert b.roles == {"shelf": "b", "red_shelf": "a"} and b.well_formed


def test_roles_given_by_the_env_are_kept_and_their_objects_taken() -> None:
    env = _env([{"id": "b1", "category": "toy_box", "attributes": {"color": "red"}},
                {"id": "b2", "category": "toy_box", "attributes": {"color": "red"}}],
               roles={"red_box": "b2", "white_box": None})
    b = bind_roles(env, BOXES | {"other": Role(category="toy_box")}, CATALOG)
    assert b.roles == {"red_box": "b2", "white_box": None, "other": "b1"}
    assert b.bound == {"other": "b1"}
    assert bind_roles(env, BOXES, CATALOG).apply(env) is env


def test_binding_round_trips_as_json() -> None:
    env = _env([{"id": "bag_1", "category": "trash_bag"}, {"id": "bag_2", "category": "trash_bag"}])
    b = bind_roles(env, {"full_bag": Role(category="trash_bag")}, CATALOG)
    assert RoleBinding.model_validate_json(b.model_dump_json()) == b


def test_reference_envs_without_roles_rebind_where_unique() -> None:
    """LogicEnvGen's own environments: the rule recovers its role map wherever it is unique.
    In the reference run (the paper's description brief) the generator's map names its own
    reading of the description (`red_toy_box`); binding the stripped environment agrees with every
    task role it did map and binds the rest."""
    env_path = REFERENCE / "clean_living_room" / "logicenvgen-00.json"
    data = json.loads(env_path.read_text())
    task = load_task("clean_living_room")
    stripped = env_from_dict({k: v for k, v in data.items() if k != "roles"})
    b = bind_roles(stripped, task.roles, CATALOG)
    assert b.well_formed
    assert None not in b.roles.values() and set(b.roles) == set(task.roles)
    own = {k: v for k, v in data["roles"].items() if k in task.roles and v is not None}
    assert own.items() <= b.roles.items()


_CATS = ["toy", "toy_box", "book", "sofa"]
_COLORS = ["red", "white", "blue"]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(_CATS), st.sampled_from(_COLORS)), max_size=8),
       st.dictionaries(st.sampled_from(["r1", "r2", "r3", "r4"]),
                       st.tuples(st.sampled_from(_CATS), st.none() | st.sampled_from(_COLORS)),
                       min_size=1))
def test_binding_never_guesses(objs: list[tuple[str, str]], spec: dict[str, tuple[str, str | None]]) -> None:
    env = _env([{"id": f"o{i}", "category": c, "attributes": {"color": col}}
                for i, (c, col) in enumerate(objs)])
    roles = {n: Role(category=c, attributes={"color": col} if col else {}) for n, (c, col) in spec.items()}
    b = bind_roles(env, roles, CATALOG)
    assert set(b.roles) == set(roles)
    chosen = [o for o in b.roles.values() if o is not None]
    assert len(chosen) == len(set(chosen)), "two roles bound to one object"
    for name, oid in b.roles.items():
        if oid is not None:
            assert matches(env.obj(oid), roles[name], CATALOG)
    for name, cands in b.candidates.items():
        assert b.roles[name] is None and cands
        assert any(f"role {name} " in p for p in b.problems)
    # every role with one qualifying object and no rival for it is bound to that object
    for name, role in roles.items():
        qual = [o.id for o in env.objects if matches(o, role, CATALOG)]
        rivals = [m for m, r in roles.items() if m != name and any(matches(env.obj(q), r, CATALOG) for q in qual)]
        if len(qual) == 1 and not rivals:
            assert b.roles[name] == qual[0]
        if not qual:
            assert b.roles[name] is None and name not in b.candidates


def test_the_name_says_what_the_attributes_do_not() -> None:
    from logicenveval.domain.roles import prepare_env

    env = _env([{"id": "box_a", "category": "red toy box"},
                {"id": "white_box", "category": "toy_box"}])
    prepared = prepare_env(env, BOXES, CATALOG)
    assert prepared.binding.roles == {"red_box": "box_a", "white_box": "white_box"}
    colours = {o.id: o.attributes.get("color") for o in prepared.env.objects}
    assert colours == {"box_a": "red", "white_box": "white"}  # read from the names, kept
    other = _env([{"id": "b1", "category": "toy_box", "attributes": {"color": "blue"}},
                  {"id": "b2", "category": "toy_box", "attributes": {"color": "blue"}}])
    assert prepare_env(other, BOXES, CATALOG).binding.roles == {"red_box": None, "white_box": None}


def test_the_role_name_chooses_among_candidates_of_one_kind() -> None:
    roles = {"food_bowl": Role(category="pet_bowl"), "water_bowl": Role(category="pet_bowl")}
    env = _env([{"id": "water_bowl", "category": "pet_bowl"}, {"id": "Food Bowl 1", "category": "pet_bowl"}])
    b = bind_roles(env, roles, CATALOG)
    assert b.roles == {"food_bowl": "Food Bowl 1", "water_bowl": "water_bowl"} and b.well_formed


def test_two_boxes_without_colour_name_the_missing_color_once_per_role() -> None:
    env = _env([{"id": "b1", "category": "toy_box"}, {"id": "b2", "category": "toy_box"}])
    b = bind_roles(env, BOXES, CATALOG)
    assert b.problems == [] and b.candidates == {}
    for role in BOXES:
        assert "b1 has no color" in b.why[role] and "b2 has no color" in b.why[role]
        assert "state color" in b.why[role]


def test_an_unbound_role_blames_only_related_objects() -> None:
    env = _env([{"id": "Teddy Bear", "category": "Teddy Bear"}, {"id": "Lamp", "category": "Lamp"},
                {"id": "thing", "category": "flux_capacitor"}])
    b = bind_roles(env, {"toy": Role(category="toy"), "sofa": Role(category="sofa")}, CATALOG)
    assert "Teddy Bear is a teddy_bear, not a toy" in b.why["toy"] and "a toy would bind" in b.why["toy"]
    assert "Lamp" not in b.why["toy"] and "flux" not in b.why["toy"]
    assert b.why["sofa"] == "no object is a sofa (a sofa would bind)"


def test_an_ambiguous_role_gets_exactly_one_message() -> None:
    from logicenveval.metrics.evaluate import coverage
    from logicenveval.sim.world import holds_initial

    task = load_task("clean_living_room")
    env = _env([{"id": "t1", "category": "toy"}, {"id": "t2", "category": "toy"}])
    b = bind_roles(env, task.roles, CATALOG)
    bound = b.apply(env)
    cov = coverage(task, holds_initial(bound, CATALOG), bound.roles, b)
    messages = [m for m in [*b.problems, *cov.problems] if "role toy " in m]
    assert len(messages) == 1 and "ambiguous" in messages[0]
    mop = [m for m in cov.problems if "role mop " in m]
    assert mop == ["role mop is not bound to an object and no reached path allows it: "
                   "no object is a mop (a mop would bind)"]
    assert not any("role wet_wipe" in m for m in cov.problems)  # optional: may be absent


def test_given_roles_bind_first_and_bad_ids_are_bad_input() -> None:
    import pytest

    from logicenveval.domain.roles import parse_role_map, prepare_env
    from logicenveval.errors import ConfigError

    env = _env([{"id": "b1", "category": "toy_box"}, {"id": "b2", "category": "toy_box"}])
    given = parse_role_map("red_box=b2, white_box=b1", BOXES)
    assert prepare_env(env, BOXES, CATALOG, given).binding.roles == {"red_box": "b2", "white_box": "b1"}
    with pytest.raises(ConfigError, match="no object 'b9'"):
        prepare_env(env, BOXES, CATALOG, {"red_box": "b9"})
    with pytest.raises(ConfigError, match="not a role"):
        parse_role_map("blue_box=b1", BOXES)
    with pytest.raises(ConfigError, match="ROLE=ID"):
        parse_role_map("red_box", BOXES)
    assert parse_role_map("blue_box=b1,red_box=b2", BOXES, strict=False) == {"red_box": "b2"}


_IDS = st.from_regex(r"[A-Za-z][A-Za-z0-9_.-]{0,8}", fullmatch=True)


@settings(max_examples=60, deadline=None)
@given(st.dictionaries(st.sampled_from(sorted(BOXES)), _IDS, min_size=1))
def test_role_map_text_round_trips(mapping: dict[str, str]) -> None:
    from logicenveval.domain.roles import parse_role_map

    text = ",".join(f" {r} = {o} " for r, o in mapping.items())
    assert parse_role_map(text, BOXES) == mapping


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["red_box", "white_box", "box", "red box 1", "toy"]),
                          st.sampled_from(["toy_box", "Red Toy Box", "toy"]),
                          st.none() | st.sampled_from(_COLORS)), max_size=6, unique_by=lambda t: t[0]))
def test_names_never_bind_a_disagreeing_object(objs: list[tuple[str, str, str | None]]) -> None:
    from logicenveval.domain.roles import prepare_env

    env = _env([{"id": i, "category": c, "attributes": {"color": col} if col else {}}
                for i, c, col in objs])
    prepared = prepare_env(env, BOXES, CATALOG)
    by_id = {o.id: o for o in prepared.env.objects}
    for role, oid in prepared.binding.roles.items():
        if oid is not None:  # bound: it has (or its name gave it) the role's colour
            assert by_id[oid].attributes.get("color") == BOXES[role].attributes["color"]
            assert matches(by_id[oid], BOXES[role], CATALOG)
        else:
            assert role in prepared.binding.candidates or role in prepared.binding.why


def test_name_words_are_immutable_so_they_can_be_shared() -> None:
    """The words of a name are computed once per name (binding reads them for every role and
    environment): what is handed out cannot be changed by a caller."""
    from logicenveval.domain.roles import name_words
    from logicenveval.model.envspec import EnvObject

    obj = EnvObject(id="red_toy_boxes_2", category="ToyBox", room="r")
    words = name_words(obj)
    assert isinstance(words, frozenset) and {"red", "toy", "box"} <= words  # lemmas: boxes -> box
    assert name_words(obj) is words


def test_the_object_the_environment_lists_as_a_task_object_settles_a_tie() -> None:
    """A generator told only the description names roles its own way and may add clutter of the
    same kind (Qwen2.5-Coder-1.5B's living room: `dirty_mark` in its roles map, `dirty_mark_1`
    beside it; a kitchen whose map lists `mug_b` as its `coffee_mug`, with `mug_a` unmapped): the one its own map
    lists as a task object plays the task's role. Two listed, or none, stay ambiguous."""
    from logicenveval.domain.roles import prepare_env
    mark = {"mark": Role(category="floor_stain")}
    env = _env([{"id": "dirty_mark", "category": "floor_stain"}, {"id": "dirty_mark_1", "category": "floor_stain"}],
               roles={"dirty_mark": "dirty_mark"})
    prepared = prepare_env(env, mark, CATALOG)
    assert prepared.binding.roles["mark"] == "dirty_mark" and prepared.binding.well_formed
    assert prepared.binding.reasons["mark"] == "task object"
    mugs = _env([{"id": "mug_a", "category": "mug"}, {"id": "mug_b", "category": "mug"}],
                roles={"coffee_mug": "mug_b"})
    assert prepare_env(mugs, {"mug": Role(category="mug")}, CATALOG).binding.roles["mug"] == "mug_b"
    both = _env([{"id": "m1", "category": "mug"}, {"id": "m2", "category": "mug"}],
                roles={"tea_mug": "m1", "coffee_mug": "m2"})
    assert not prepare_env(both, {"mug": Role(category="mug")}, CATALOG).binding.well_formed
    unmapped = _env([{"id": "m1", "category": "mug"}, {"id": "m2", "category": "mug"}])
    assert prepare_env(unmapped, {"mug": Role(category="mug")}, CATALOG).binding.candidates == {"mug": ["m1", "m2"]}
