"""Request protocol 6 (issue 46): a `name_objects` reply's category is retrieved by the object's
name where the two contradict each other, as the paper retrieves an asset from an object's
description; attribute keys no catalog domain knows are dropped. Calibrated on the replies
Qwen2.5-Coder-1.5B gave under protocol 5 (the committed pack), and checked on other names."""

from __future__ import annotations

import json
import sqlite3
from pathlib import Path

import pytest
from scripted import Scripted

from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.generators.brief import NamedObject, Retrieved, named_brief, retrieve

ROOT = Path(__file__).resolve().parents[1]
TASKS = ROOT / "benchmark_data" / "tasks"
PACK = ROOT / "reports" / "real" / "qwen2.5-coder-1.5b-description" / "llm_cache.sqlite"


def _recorded(task_word: str) -> str:
    """The valid `name_objects` reply the pack recorded for the task whose objects include
    `task_word` (the real reply, not a paraphrase of it)."""
    with sqlite3.connect(PACK) as db:
        rows = [r for (r,) in db.execute("select reply from replies where kind = 'name_objects'")]
    for reply in rows:
        try:
            objects = json.loads(reply)["objects"]
        except (json.JSONDecodeError, KeyError):
            continue
        if any(o["name"] == task_word for o in objects) and all(o["category"] in load_catalog()
                                                                 for o in objects):
            return reply
    raise AssertionError(f"no valid recorded name_objects reply names {task_word!r}")


def test_the_recorded_living_room_reply_gets_the_kinds_its_names_say() -> None:
    """Qwen named all seven things of clean_living_room `filing_cabinet` and put the schema's
    words in their attributes; every environment built on it left a role unbound."""
    reply = _recorded("wet_mop")
    old = named_brief(load_task("clean_living_room", TASKS), "description",
                      Scripted([reply], reply_protocol=5))
    assert {r.category for r in old.brief.roles.values()} == {"filing_cabinet"} and not old.retrieved
    new = named_brief(load_task("clean_living_room", TASKS), "description",
                      Scripted([reply], reply_protocol=6))
    assert {n: r.category for n, r in new.brief.roles.items()} == {
        "sofa": "sofa", "table": "filing_cabinet",  # "table" names no one kind: the reply's stands
        "wet_mop": "mop", "book": "book", "toy": "toy", "dirty_mark": "floor_stain", "wet_wipe": "wet_wipe"}
    assert all(r.attributes == {} for r in new.brief.roles.values())
    assert Retrieved("book", "category", "filing_cabinet", "book") in new.retrieved
    assert Retrieved("book", "attributes", "additionalProperties, description, type", "") in new.retrieved


def test_the_recorded_kitchen_reply_keeps_a_counter_and_fixes_a_plate() -> None:
    reply = _recorded("sponge")
    new = named_brief(load_task("kitchen_dish_cleanup", TASKS), "description",
                      Scripted([reply], reply_protocol=6))
    kinds = {n: r.category for n, r in new.brief.roles.items()}
    assert kinds["plate"] == "plate" and kinds["sponge"] == "sponge"
    assert kinds["counter"] == "kitchen_counter"  # "counter" is a name of the kind: it stands
    # `dirty` is a state, not an attribute: no task reads attr(plate, dirty, true)
    assert all("dirty" not in r.attributes for r in new.brief.roles.values())


@pytest.mark.parametrize(("name", "said", "kept"), [
    ("towels", "filing_cabinet", "towel"),          # a plural names its kind
    ("kettle", "plate", "kettle"),
    ("tv_remote", "television", "remote_control"),  # a synonym names it; "tv" is no head
    ("laptops", "desk", "laptop"),
    ("dog_bowl", "pet_bowl", "pet_bowl"),           # agrees already
    ("water_bowl", "pet_bowl", "pet_bowl"),         # names no kind, and shares the head "bowl"
    ("counter", "kitchen_counter", "kitchen_counter"),
    ("gizmo", "toaster", "toaster"),                # names nothing: the reply's choice stands
])
def test_a_reply_whose_kinds_its_names_contradict_gets_the_named_kinds(name: str, said: str, kept: str) -> None:
    """Beside two contradicted objects, contradictions are most of the reply: every contradicted
    name is retrieved, and an agreeing or unknown one keeps its category."""
    catalog = load_catalog()
    objects = [NamedObject(name=name, category=said), NamedObject(name="armchair", category="oven"),
               NamedObject(name="bathtub", category="desk")]
    roles, changes = retrieve(objects, catalog)
    assert roles[name].category == kept
    assert (roles["armchair"].category, roles["bathtub"].category) == ("armchair", "bathtub")
    assert len([c for c in changes if c.field == "category"]) == (3 if kept != said else 2)


def test_one_contradiction_among_agreeing_names_is_a_reading_and_stands() -> None:
    """A New Zealander's kitchen "bench" is its counter: a model that read it so named it by the
    text's word and chose the kind it meant; the reply's other kinds agree with their names."""
    catalog = load_catalog()
    objects = [NamedObject(name="bench", category="kitchen_counter"), NamedObject(name="kettle", category="kettle"),
               NamedObject(name="mug", category="mug"), NamedObject(name="dish_rack", category="dish_rack")]
    roles, changes = retrieve(objects, catalog)
    assert roles["bench"].category == "kitchen_counter" and not changes


def test_a_kind_generators_are_not_offered_is_never_retrieved() -> None:
    """A kind without rooms exists only to read houses made elsewhere (docs/catalog.md)."""
    catalog = load_catalog()
    assert not catalog.categories["spatula"].rooms
    roles, changes = retrieve([NamedObject(name="spatula", category="pan")], catalog)
    assert roles["spatula"].category == "pan" and not changes


def test_catalog_attribute_keys_and_purpose_stand_and_the_first_of_a_name_counts() -> None:
    catalog = load_catalog()
    objects = [NamedObject(name="box", category="toy_box",
                           attributes={"color": "red", "purpose": "toys", "running": "false"}),
               NamedObject(name="box", category="oven")]
    roles, changes = retrieve(objects, catalog)
    assert roles == {"box": roles["box"]} and roles["box"].category == "toy_box"
    assert roles["box"].attributes == {"color": "red", "purpose": "toys"}
    assert changes == [Retrieved("box", "attributes", "running", "")]


def test_protocol_7_is_the_default_and_a_later_one_is_refused() -> None:
    from logicenveval.errors import ConfigError
    from logicenveval.llm.registry import request_protocol

    assert request_protocol(None) == 7 == request_protocol("protocol=7")
    assert request_protocol("protocol=6") == 6
    with pytest.raises(ConfigError, match="use one of 1, 2, 3, 4, 5, 6, 7"):
        request_protocol("protocol=8")
