"""The offline analyser on varied phrasings written for these tests (not the benchmark's)."""

from __future__ import annotations

from typing import Any

import pytest

from logicenveval.domain.catalog import Catalog
from logicenveval.offline.analysis import analyse, nest

CATALOG = Catalog.model_validate({"categories": {
    name: {"size_min": [0.1, 0.1, 0.1], "size_max": [1, 1, 1], "placement": ["floor"], **extra}
    for name, extra in {
        "toy": {"pickable": True, "attributes": {"kind": ["doll", "car", "ball"], "color": ["red", "blue"]}},
        "toy_box": {"container": True, "attributes": {"color": ["red", "white", "blue"]}, "synonyms": ["toy chest"]},
        "book": {"pickable": True, "attributes": {"kind": ["novel", "essay", "comic"]}},
        "bookshelf": {"surface": True, "synonyms": ["shelf"]},
        "sofa": {"surface": True, "synonyms": ["couch"]},
        "fridge": {"container": True, "openable": True, "synonyms": ["refrigerator"]},
        "milk_carton": {"pickable": True, "synonyms": ["milk"]},
        "table_lamp": {"toggleable": True, "synonyms": ["lamp"]},
        "dining_table": {"surface": True, "synonyms": ["table"]},
        "plate": {"pickable": True},
        "dishwasher": {"container": True, "openable": True, "toggleable": True},
        "umbrella": {"pickable": True},
        "shoe": {"pickable": True, "synonyms": ["shoes"]},
        "shoe_rack": {"surface": True, "synonyms": ["rack"]},
        "sponge": {"pickable": True},
        "banana": {"pickable": True},
        "letter": {"pickable": True},
        "bowl": {"container": True},
        "cabinet": {"container": True, "openable": True},
    }.items()}})


def brief(description: str, roles: dict[str, Any], rooms: list[str] | None = None) -> dict[str, Any]:
    return {"id": "t", "description": description, "rooms": rooms or ["living_room"],
            "roles": {k: {"category": v[0], "attributes": v[1] if len(v) > 1 else {}} for k, v in roles.items()}}


def factor_values(description: str, roles: dict[str, Any]) -> dict[str, set[str]]:
    a = analyse(brief(description, roles), CATALOG)
    return {f.id: set(f.values.values()) for f in a.factors}


@pytest.mark.parametrize("text", [
    "If there is a toy on the floor, put it into the toy chest.",
    "Put the toy in the toy chest in case it is lying on the floor.",
    "A toy may have been left on the floor; tidy it away.",
    "Check the floor: should there be a toy on it, it goes into the toy chest.",
    "Any toy lying on the floor goes into the toy chest.",
    "Depending on whether the toy is on the floor, put it away or leave it.",
])
def test_location_factor_from_varied_cues(text: str) -> None:
    values = factor_values(text, {"toy": ("toy",), "box": ("toy_box",)})
    assert {"on(toy, floor)", "not on(toy, floor)"} in values.values()
    assert not any("inside(toy, box)" in v for vs in values.values() for v in vs)  # a goal, not a factor


@pytest.mark.parametrize(("text", "cond"), [
    ("If the fridge is open, close it.", "state(fridge, open)"),
    ("Close the refrigerator unless it is already shut.", "state(fridge, open)"),
    ("Turn the lamp off when it is on.", "state(lamp, toggled_on)"),
    ("Wipe the table if it looks dirty; a clean table needs nothing.", "state(table, dirty)"),
    ("Bring the milk back to the fridge if it isn't empty.", "state(milk, filled)"),
])
def test_state_factors(text: str, cond: str) -> None:
    values = factor_values(text, {"fridge": ("fridge",), "lamp": ("table_lamp",), "table": ("dining_table",),
                                  "milk": ("milk_carton",)})
    assert {cond, f"not {cond}"} in values.values()


def test_attribute_classes_and_nesting() -> None:
    text = ("Toys on the floor must be sorted: dolls go into the red box, cars into the blue one, "
            "anything else into the white box.")
    a = analyse(brief(text, {"toy": ("toy",), "red_box": ("toy_box", {"color": "red"}),
                             "blue_box": ("toy_box", {"color": "blue"}),
                             "white_box": ("toy_box", {"color": "white"})}), CATALOG)
    by_id = {f.id: f for f in a.factors}
    assert by_id["toy_kind"].values == {
        "doll": "attr(toy, kind, doll)", "car": "attr(toy, kind, car)",
        "other": "not attr(toy, kind, doll) and not attr(toy, kind, car)"}
    assert "toy_color" not in by_id  # colour words describe the boxes, which are fixed
    tree = nest([by_id["toy_on_floor"], by_id["toy_kind"]])
    assert tree["var"] == "toy_on_floor"
    assert tree["branches"]["yes"]["var"] == "toy_kind"
    assert "plan" in tree["branches"]["no"]  # not on the floor: the kind does not matter


def test_multi_valued_location_and_pronouns() -> None:
    text = ("Shoes: wet ones stay by the door, dry ones belong on the rack. Books lying on the "
            "floor or on the sofa go back on the shelf; anywhere else, leave them.")
    values = factor_values(text, {"shoes": ("shoe",), "rack": ("shoe_rack",), "book": ("book",),
                                  "sofa": ("sofa",), "shelf": ("bookshelf",)})
    assert {"state(shoes, wet)", "not state(shoes, wet)"} in values.values()
    assert {"on(book, floor)", "on(book, sofa)", "not on(book, floor) and not on(book, sofa)"} in values.values()


def test_dependent_conditions_share_a_subtask_and_lists_do_not() -> None:
    text = ("There may be a book or a toy on the floor. A dirty plate goes into the dishwasher, "
            "but when the dishwasher is running put it in the sink instead.")
    a = analyse(brief(text, {"book": ("book",), "toy": ("toy",), "plate": ("plate",),
                             "dishwasher": ("dishwasher",)}), CATALOG)
    groups = [{f.split("_")[0] for f in g} for g in a.groups]
    assert {"plate", "dishwasher"} in groups
    assert {"book"} in groups and {"toy"} in groups


def test_absence_and_certain_scene_facts() -> None:
    text = ("There is a sofa in the room and a toy on the floor. Clean the table with the sponge; "
            "if there is no sponge, use a towel.")
    values = factor_values(text, {"sofa": ("sofa",), "toy": ("toy",), "table": ("dining_table",),
                                  "sponge": ("sponge",)})
    assert values == {"sponge_present": {"exists(sponge)", "not exists(sponge)"}}


def test_analysis_is_memoised_per_brief_and_callers_get_copies() -> None:
    from logicenveval.offline import analysis

    b = brief("If there is a toy on the floor, put it into the toy chest.", {"toy": ["toy"]})
    first = analyse(b, CATALOG)
    first.factors[0].values.clear()  # a caller changing its copy does not change the next answer
    first.factors.clear()
    second = analyse(dict(b), CATALOG)
    assert second.factors and second == analysis._analyse(b, CATALOG)
    assert analyse(b, CATALOG) is not second


def test_reply_schema_is_built_once_per_class() -> None:
    from pydantic import BaseModel

    from logicenveval.llm.ask import reply_schema

    class Reply(BaseModel):
        answer: str

    assert reply_schema(Reply) is reply_schema(Reply)
    # pydantic's schema without its `title` keys (prompt tokens that constrain nothing)
    assert reply_schema(Reply) == {"properties": {"answer": {"type": "string"}}, "required": ["answer"],
                                   "type": "object"}


# ----- phrasings added for issue 22 (generalisation to reworded descriptions) -----------------

def _conditions(description: str, roles: dict[str, Any]) -> set[str]:
    return {c for vs in factor_values(description, roles).values() for c in vs}


def test_a_question_asks_about_the_situation() -> None:
    got = _conditions("Is the milk on the dining table? Then put it in the fridge.",
                      {"milk": ("milk_carton",), "table": ("dining_table",), "fridge": ("fridge",)})
    assert "on(milk, table)" in got


def test_absence_words_and_fronted_places() -> None:
    got = _conditions("Wipe the plate with the sponge. When the sponge is missing, use the cloth.",
                      {"plate": ("plate",), "sponge": ("sponge",)})
    assert "exists(sponge)" in got
    got = _conditions("On the sofa there might be a book or a toy. Put them away.",
                      {"book": ("book",), "toy": ("toy",), "sofa": ("sofa",)})
    assert {"on(book, sofa)", "on(toy, sofa)"} <= got


def test_relative_clauses_ellipses_and_passive_goals() -> None:
    roles = {"toy": ("toy",), "box": ("toy_box",), "umbrella": ("umbrella",), "rack": ("shoe_rack",)}
    got = _conditions("Any toy that is on the sofa gets put into the box. If there is an umbrella: "
                      "when wet, it is laid on the rack.", {**roles, "sofa": ("sofa",)})
    assert "on(toy, sofa)" in got and "state(umbrella, wet)" in got
    assert not any(c.startswith(("on(umbrella, rack)", "inside(toy, box)")) for c in got)  # goals


def test_somewhere_else_is_not_an_else_branch() -> None:
    a = analyse(brief("The book is returned to the bookshelf when it is lying somewhere else.",
                      {"book": ("book",), "shelf": ("bookshelf",)}), CATALOG)
    assert [c.role for c in a.clauses] == ["consequence", "condition"]
    assert "somewhere else" in a.clauses[-1].text


def test_already_refers_to_the_previous_instruction() -> None:
    got = _conditions("Put the plate on the dining table unless it is already there.",
                      {"plate": ("plate",), "table": ("dining_table",)})
    assert "on(plate, table)" in got
    got = _conditions("Switch the lamp on unless it is already on.", {"lamp": ("table_lamp",)})
    assert "state(lamp, toggled_on)" in got


def test_coordinated_instructions_keep_their_own_conditions() -> None:
    a = analyse(brief("Turn off the lamp if it is on, and close the fridge if it is open.",
                      {"lamp": ("table_lamp",), "fridge": ("fridge",)}), CATALOG)
    by_id = {f.id: f for f in a.factors}
    assert "fridge_open" in by_id and "lamp_toggled_on" in by_id
    assert by_id["fridge_open"].context == []  # asked whatever the lamp's state


# ----- issue 22, follow-up: attributes without a domain, absences as alternatives, appositions ---

def test_contrasted_adjective_becomes_an_attribute_without_a_catalog_domain() -> None:
    roles = {"banana": ("banana",), "table": ("dining_table",), "bowl": ("bowl",), "fridge": ("fridge",)}
    got = factor_values("If the banana on the table is overripe, put it in the fridge; a banana that "
                        "is not overripe belongs in the bowl.", roles)
    assert got["banana_overripeness"] == {"attr(banana, overripeness, overripe)",
                                          "not attr(banana, overripeness, overripe)"}
    got = factor_values("A peeled banana goes in the fridge and an unpeeled one goes in the bowl.", roles)
    assert got["banana_peeledness"] == {"attr(banana, peeledness, peeled)", "not attr(banana, peeledness, peeled)"}
    # an adjective the text never contrasts decides nothing
    assert not any("attr(" in c for vs in factor_values(
        "Put a fresh plate on the table and move the soft banana into the bowl.",
        {**roles, "plate": ("plate",)}).values() for c in vs)


def test_a_kind_named_in_a_condition_belongs_to_the_subject_not_the_place() -> None:
    got = factor_values("If there is a letter on the table and it is an invoice, put it in the cabinet; "
                        "any other letter goes into the bowl.",
                        {"letter": ("letter",), "table": ("dining_table",), "cabinet": ("cabinet",),
                         "bowl": ("bowl",)})
    assert got["letter_kind"] == {"attr(letter, kind, invoice)", "not attr(letter, kind, invoice)"}
    assert not any(k.startswith("table_") for k in got)


def test_an_absence_stated_as_an_alternative_is_its_own_question() -> None:
    roles = {"sponge": ("sponge",), "plate": ("plate",), "table": ("dining_table",)}
    a = analyse(brief("When the sponge is on the table, wipe the plate with it. If it is somewhere "
                      "else, or we have none, leave the plate.", roles), CATALOG)
    tree = nest(a.factors)
    assert tree["var"] == "sponge_present"  # asked first; where it is only when it exists
    assert tree["branches"]["yes"]["var"] == "sponge_on_table" and "plan" in tree["branches"]["no"]
    a = analyse(brief("There may be a plate. If it is on the table, put it in the dishwasher.",
                      {**roles, "dishwasher": ("dishwasher",)}), CATALOG)
    assert {"plate_present", "plate_on_table"} <= {f.id for f in a.factors}
    # "if there is none" right after a location only says where it is expected: no extra question
    got = factor_values("Wipe the plate with the sponge from the table if available; if there is none, "
                        "use a towel.", roles)
    assert "sponge_present" not in got and "sponge_on_table" in got
    got = factor_values("Put the plate in the dishwasher; if there is no plate on the table at all, skip this.",
                        {**roles, "dishwasher": ("dishwasher",)})
    assert "plate_present" not in got and "plate_on_table" in got


def test_listed_apposition_takes_the_generic_words_place() -> None:
    got = _conditions("Everything lying on the sofa - a toy, a book or a plate - has to be put away.",
                      {"toy": ("toy",), "book": ("book",), "plate": ("plate",), "sofa": ("sofa",)})
    assert {"on(toy, sofa)", "on(book, sofa)", "on(plate, sofa)"} <= got


def test_sibling_conditions_and_relative_clauses_after_adjectives() -> None:
    roles = {"plate": ("plate",), "dishwasher": ("dishwasher",), "table": ("dining_table",),
             "shelf": ("bookshelf",)}
    a = analyse(brief("About the plate: when it is dirty, load it into the dishwasher; when it is clean and "
                      "wet, leave it on the table; when it is clean and dry, put it on the shelf.", roles), CATALOG)
    by_id = {f.id: f for f in a.factors}
    assert by_id["plate_wet"].context == []  # not only asked when the plate is dirty
    tree = nest(a.factors)
    assert tree["var"] == "plate_dirty" and tree["branches"]["no"]["var"] == "plate_wet"
    got = factor_values("A dirty plate goes into the dishwasher. A clean plate that is wet stays on the table.",
                        roles)
    assert got["plate_wet"] == {"state(plate, wet)", "not state(plate, wet)"}


def test_an_empty_it_is_not_a_reference() -> None:
    got = factor_values("Close the fridge if it is open. It is likely that a toy has fallen on the floor: "
                        "put it into the toy chest when it is dirty.",
                        {"fridge": ("fridge",), "toy": ("toy",), "box": ("toy_box",)})
    assert got["toy_on_floor"] == {"on(toy, floor)", "not on(toy, floor)"}
    assert "toy_dirty" in got and "fridge_dirty" not in got


def test_fronted_conditions_on_unrelated_things_and_without() -> None:
    a = analyse(brief("Should the fridge be open, close it; should the lamp be on, switch it off.",
                      {"fridge": ("fridge",), "lamp": ("table_lamp",)}), CATALOG)
    assert {f.id: f.context for f in a.factors}["lamp_toggled_on"] == []
    a = analyse(brief("Wipe the table when it is dirty. Without a sponge, use a towel and bin it.",
                      {"table": ("dining_table",), "sponge": ("sponge",)}), CATALOG)
    by_id = {f.id: f for f in a.factors}
    assert by_id["sponge_present"].values == {"yes": "exists(sponge)", "no": "not exists(sponge)"}
    assert "table_dirty" in by_id
