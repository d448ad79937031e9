"""How the offline reader links the parts of a clause (issue 47 item 2): list items and the places
between them, gapped verbs, pronouns within a clause, alternatives after "if there are any", the
spare of a kind, homes said in passing, and placements the catalog rules out. Each rule is tested
on a sentence written for this file and one of the reader's development set
(tests/data/reader_dev/), so on at least two different texts."""

from __future__ import annotations

from typing import Any

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.analysis import analyse
from logicenveval.offline.lexicon import Lexicon
from logicenveval.offline.naming import name_objects
from logicenveval.scene.compat import can_hold

CATALOG = load_catalog()


def brief(description: str, roles: dict[str, str], rooms: tuple[str, ...] = ("living_room",)) -> dict[str, Any]:
    return {"id": "t", "description": description, "rooms": list(rooms),
            "roles": {name: {"category": cat, "attributes": {}} for name, cat in roles.items()}}


def asked(description: str, roles: dict[str, str]) -> set[str]:
    """Every condition a factor of the reading may take."""
    return {v for f in analyse(brief(description, roles), CATALOG).factors for v in f.values.values()}


LIVING = {"book": "book", "sofa": "sofa", "toy": "toy", "toy_box": "toy_box", "coffee_table": "coffee_table",
          "mop": "mop", "wet_wipe": "wet_wipe", "mug": "mug", "desk": "desk", "ball": "ball"}


# ----- a place named before a new list item is no item of the list ------------------------------

@pytest.mark.parametrize("text", [
    # development set (clean_living_room_r2)
    "I think a book or a toy might be lying on the floor somewhere. So: anything on the floor should go where "
    "it belongs - the book on the couch, a toy in the toy box.",
    "A mug or a ball may be on the floor. Put away whatever is down there - the mug on the desk, a ball in the "
    "toy box.",
])
def test_a_verbless_list_after_a_moving_clause_says_where_things_go(text: str) -> None:
    got = asked(text, LIVING)
    assert not any(c.startswith(("inside(sofa", "inside(desk", "on(book, sofa)", "on(mug, desk)"))
                   or "toy_box)" in c for c in got), got
    assert {"on(book, floor)", "on(toy, floor)"} <= got or {"on(mug, floor)", "on(ball, floor)"} <= got


@pytest.mark.parametrize("text", [
    # development set (clean_living_room_r4)
    "A book or a toy may have been dropped on the floor. Anything lying on the floor is to be put away: a book "
    "is placed on the sofa and a toy in its toy box.",
    "A mug or a ball may have been dropped on the floor. The mug is put on the desk and a ball in the toy box.",
])
def test_a_gapped_item_shares_the_goal_of_the_first(text: str) -> None:
    got = asked(text, LIVING)
    assert not any("toy_box)" in c or c.startswith("inside(sofa") for c in got), got


# ----- the catalog rules out a placement a reading proposes -------------------------------------

def test_can_hold_follows_the_catalogs_kinds_and_sizes() -> None:
    cat = CATALOG.categories
    assert not can_hold(cat["sofa"], cat["toy_box"], "inside")  # too big
    assert not can_hold(cat["cell_phone"], cat["book"], "on")  # a book is no surface
    assert can_hold(cat["toy"], cat["toy_box"], "inside")
    assert can_hold(cat["cell_phone"], cat["desk"], "on")


@pytest.mark.parametrize(("text", "roles", "ruled_out"), [
    ("Maybe the sofa ended up inside the toy box.", {"sofa": "sofa", "toy_box": "toy_box"}, "inside(sofa, toy_box)"),
    ("The phone might be lying on the book.", {"phone": "cell_phone", "book": "book"}, "on(phone, book)"),
])
def test_a_placement_the_catalog_rules_out_is_no_factor(text: str, roles: dict[str, str], ruled_out: str) -> None:
    assert ruled_out not in asked(text, roles)


# ----- possessive determiners inside a list ------------------------------------------------------

@pytest.mark.parametrize(("text", "roles", "place"), [
    # development set (bedroom_bookshelf_sorting_r2)
    ("Could you clear off my bed? There might be a book, my alarm clock or my phone lying on it.",
     {"bed": "bed", "book": "book", "alarm_clock": "alarm_clock", "phone": "cell_phone"}, "bed"),
    ("Please tidy the desk. Your pen, your notebook or your mug may be lying on it.",
     {"desk": "desk", "pen": "pen", "notebook": "notebook", "mug": "mug"}, "desk"),
])
def test_a_list_with_possessives_is_one_list(text: str, roles: dict[str, str], place: str) -> None:
    got = asked(text, roles)
    things = [r for r in roles if r != place]
    assert {f"on({t}, {place})" for t in things} <= got, got


# ----- "if there are any, else ...": the alternative is no absence ------------------------------

@pytest.mark.parametrize(("text", "roles", "absent"), [
    # development set (clean_living_room_r1)
    ("Possibly a pack of wet wipes on the table. Clean the mark with the wet wipes from the table if there are "
     "any, else with the wet mop.", {"wet_wipe": "wet_wipe", "coffee_table": "coffee_table", "mop": "mop"}, "mop"),
    ("There may be a sponge on the desk. Wipe the mug with the sponge if there is one, otherwise with the cloth.",
     {"sponge": "sponge", "desk": "desk", "mug": "mug", "cloth": "cloth"}, "cloth"),
])
def test_the_alternative_of_if_there_are_any_is_not_asked(text: str, roles: dict[str, str], absent: str) -> None:
    got = asked(text, roles)
    assert f"exists({absent})" not in got, got
    assert any(c.startswith("on(") for c in got), got


# ----- a spare role is meant only where a spare word says so -------------------------------------

@pytest.mark.parametrize(("text", "roles", "meant"), [
    # development set (bathroom_towel_refresh_r1)
    ("No toilet roll by the toilet? Take the spare roll out of the vanity cabinet and put it on the toilet tank.",
     {"roll": "toilet_paper", "spare_roll": "toilet_paper", "toilet": "toilet", "vanity": "bathroom_vanity"},
     "roll"),
    ("If there is no trash bag in the trash can, put the spare bag in.",
     {"bag": "trash_bag", "spare_bag": "trash_bag", "trash_can": "trash_can"}, "bag"),
])
def test_a_plain_name_is_not_the_spare(text: str, roles: dict[str, str], meant: str) -> None:
    lex = Lexicon.build(brief(text, roles), CATALOG)
    assert lex._disambiguate(["spare_" + meant, meant], ["no", "toilet"], 2) == (meant,)
    assert lex._disambiguate(["spare_" + meant, meant], ["the", "spare"], 2) == ("spare_" + meant,)
    assert not any(c.startswith(f"exists(spare_{meant}") for c in asked(text, roles))


# ----- a pronoun after a pronoun; a home said in passing asks nothing ----------------------------

@pytest.mark.parametrize(("text", "roles", "thing"), [
    # development set (bathroom_towel_refresh_r1)
    ("Mirror dirty? Clean it with the microfibre cloth if there is one (it is kept in the vanity; return it "
     "there and close the vanity); if not, use the hand towel.",
     {"mirror": "mirror", "cloth": "cloth", "vanity": "bathroom_vanity", "hand_towel": "hand_towel"}, "cloth"),
    ("Is the desk dusty? Wipe it with the sponge if there is one (it lives in the cupboard; put it back "
     "afterwards); if not, use the cloth.",
     {"desk": "desk", "sponge": "sponge", "cupboard": "cabinet", "cloth": "cloth"}, "sponge"),
])
def test_a_pronoun_after_a_pronoun_means_the_same_thing(text: str, roles: dict[str, str], thing: str) -> None:
    got = asked(text, roles)
    assert f"exists({thing})" in got, got
    assert not any(c.startswith(("inside(mirror", "inside(desk", f"inside({thing}")) for c in got), got


@pytest.mark.parametrize(("text", "roles", "thing"), [
    # development set (bathroom_towel_refresh_r3)
    ("No roll by the toilet: spare roll out of the vanity (spares are kept there) onto the toilet tank, close "
     "the vanity.", {"roll": "toilet_paper", "spare_roll": "toilet_paper", "toilet": "toilet",
                     "vanity": "bathroom_vanity"}, "spare_roll"),
    ("Mug on the floor: mug out of the cabinet (mugs are kept there) onto the desk.",
     {"mug": "mug", "cabinet": "cabinet", "desk": "desk"}, "mug"),
])
def test_a_home_said_in_an_instruction_is_not_asked(text: str, roles: dict[str, str], thing: str) -> None:
    got = asked(text, roles)
    assert not any(c.startswith(f"on({thing}, {'toilet' if thing == 'spare_roll' else 'desk'})") for c in got), got


# ----- a guess at what has happened is a situation -----------------------------------------------

@pytest.mark.parametrize(("text", "roles", "condition"), [
    # development set (clean_living_room_r4)
    ("A packet of wet wipes may have been put on the table. The mark is cleaned with them.",
     {"wet_wipe": "wet_wipe", "table": "coffee_table"}, "on(wet_wipe, table)"),
    ("The remote might have been put on the sofa; bring it back to the TV stand.",
     {"remote": "remote_control", "sofa": "sofa", "tv_stand": "tv_stand"}, "on(remote, sofa)"),
])
def test_may_have_been_put_is_a_situation(text: str, roles: dict[str, str], condition: str) -> None:
    assert condition in asked(text, roles)


# ----- a bare plural that is a value of another named kind's attribute is a class --------------

@pytest.mark.parametrize(("text", "values"), [
    # development set (kids_room_toy_cleanup_r1)
    ("If there's a toy on the floor, it goes in a toy box depending on what it is: dolls in the red toy box, toy "
     "cars in the blue box, and everything else in the green box.", {"doll", "car"}),
    ("A toy may be lying under the bed. Balls go in the basket and dolls on the shelf; leave other toys.",
     {"ball", "doll"}),
])
def test_a_bare_plural_kind_of_a_named_thing_is_a_class_not_an_object(text: str, values: set[str]) -> None:
    named = name_objects(text, CATALOG, rooms=["kids_room"])
    cats = {o["category"] for o in named}
    assert "toy" in cats and not cats & {"doll", "toy_car", "ball"}, named
    roles = {o["name"]: o["category"] for o in named}
    got = {v for f in analyse(brief(text, roles, ("kids_room",)), CATALOG).factors if f.kind == "attr"
           for v in f.values.values()}
    assert {f"attr(toy, kind, {v})" for v in values} <= got, got


def test_a_determined_kind_is_still_an_object() -> None:
    named = name_objects("A toy and a doll are on the floor.", CATALOG, rooms=["kids_room"])
    assert {"toy", "doll"} <= {o["category"] for o in named}


# ----- a place heading with a doubt asks where the listed things are ----------------------------

@pytest.mark.parametrize(("text", "roles", "conditions"), [
    # development set (bedroom_bookshelf_sorting_r1)
    ("Bedroom: bed, nightstand. On the bed, maybe: a book, an alarm clock, a phone. Clear the bed.",
     {"bed": "bed", "nightstand": "nightstand", "book": "book", "alarm_clock": "alarm_clock", "phone": "cell_phone"},
     {"on(book, bed)", "on(alarm_clock, bed)", "on(phone, bed)"}),
    ("On the desk, possibly: a mug, a pen. Put them away.", {"desk": "desk", "mug": "mug", "pen": "pen"},
     {"on(mug, desk)", "on(pen, desk)"}),
])
def test_a_place_heading_with_a_doubt_asks_where_things_are(text: str, roles: dict[str, str],
                                                             conditions: set[str]) -> None:
    assert conditions <= asked(text, roles)


# ----- a verb and its particle that say a state ---------------------------------------------------

@pytest.mark.parametrize("text", [
    # development set (study_desk_cleanup_r1)
    "Document on the desk? A bill goes into the filing cabinet (open the drawer unless it's already pulled out, "
    "and shut it afterwards).",
    "File the bill in the filing cabinet: open the drawer, unless it has already been pulled out.",
])
def test_pulled_out_is_open(text: str) -> None:
    assert "state(filing_cabinet, open)" in asked(text, {"document": "document", "desk": "desk",
                                                         "filing_cabinet": "filing_cabinet"})


# ----- a place per state; "- else ..." as a later part; "if any" with no place said --------------

BATH = {"towel": "towel", "laundry_basket": "laundry_basket", "towel_rack": "towel_rack", "mirror": "mirror",
        "cloth": "cloth", "vanity": "bathroom_vanity", "hand_towel": "hand_towel", "shirt": "shirt",
        "hamper": "hamper", "wardrobe": "wardrobe"}


@pytest.mark.parametrize(("text", "thing", "state"), [
    # development set (bathroom_towel_refresh_r3)
    ("Bath towel on the floor: wet to the laundry basket, dry to the towel rack.", "towel", "wet"),
    ("Shirt on the floor: dirty into the hamper, clean back in the wardrobe.", "shirt", "dirty"),
])
def test_a_place_per_state_asks_the_state(text: str, thing: str, state: str) -> None:
    a = analyse(brief(text, BATH), CATALOG)
    by_id = {f.id: f for f in a.factors}
    assert by_id[f"{thing}_{state}"].context == [(f"{thing}_on_floor", frozenset({"yes"}))]


@pytest.mark.parametrize(("text", "thing"), [
    # development set (bathroom_towel_refresh_r3)
    ("Dirty mirror: clean with the microfibre cloth if any - the cloth lives in the vanity; return it, close the "
     "vanity - else with the hand towel, then hang it on the towel rack.", "cloth"),
    ("Mirror dirty: wipe it with the hand towel if any; put it back - otherwise with the cloth.", "hand_towel"),
])
def test_if_any_asks_whether_there_is_one(text: str, thing: str) -> None:
    a = analyse(brief(text, BATH), CATALOG)
    by_id = {f.id: f for f in a.factors}
    assert by_id[f"{thing}_present"].context == [("mirror_dirty", frozenset({"yes"}))], by_id


# ----- a participle after "been" belongs to the verb group ---------------------------------------

@pytest.mark.parametrize(("text", "roles", "condition"), [
    # development set (bedroom_morning_tidy_r4)
    ("If the pillow has been knocked onto the floor, it is put back on the bed.", {"pillow": "pillow", "bed": "bed"},
     "on(pillow, floor)"),
    ("Should the mug have been pushed onto the desk, bring it back to the sofa.",
     {"mug": "mug", "desk": "desk", "sofa": "sofa"}, "on(mug, desk)"),
])
def test_a_participle_after_been_is_part_of_the_verb(text: str, roles: dict[str, str], condition: str) -> None:
    assert condition in asked(text, roles)


# ----- a room's name before a thing's name; a gapped item with its adjective ---------------------

@pytest.mark.parametrize(("text", "roles", "goal"), [
    # development set (study_desk_cleanup_r3)
    ("The mug may also have been left on the desk; it is taken to the kitchen, where a dirty mug goes in the "
     "kitchen sink and a clean one on the kitchen worktop.",
     {"mug": "mug", "desk": "desk", "sink": "sink", "counter": "kitchen_counter"}, "on(mug, counter)"),
    ("A plate might be on the desk. It is carried to the kitchen: a dirty plate goes in the kitchen sink and a "
     "clean one on the kitchen counter.",
     {"plate": "plate", "desk": "desk", "sink": "sink", "counter": "kitchen_counter"}, "on(plate, counter)"),
])
def test_a_room_word_before_a_thing_names_the_thing(text: str, roles: dict[str, str], goal: str) -> None:
    a = analyse({**brief(text, roles), "rooms": ["study", "kitchen"]}, CATALOG)
    said = {f.condition: f.goal for cl in a.clauses for f in cl.facts}
    assert said.get(goal) is True, said
    assert not any(c.startswith("in_room(") and not g for c, g in said.items()), said
    assert not any("counter" in v or "in_room" in v for f in a.factors for v in f.values.values())


# ----- "lives" is a verb of a home, whatever the noun lemmatiser makes of it ----------------------

@pytest.mark.parametrize(("text", "roles", "condition"), [
    # development set (living_room_evening_reset_r2)
    ("The TV remote lives on the TV stand, so if it's anywhere else, put it back.",
     {"remote": "remote_control", "tv_stand": "tv_stand"}, "on(remote, tv_stand)"),
    ("The mug lives on the desk; if it is anywhere else, bring it back.", {"mug": "mug", "desk": "desk"},
     "on(mug, desk)"),
])
def test_lives_is_a_home_asked_against_elsewhere(text: str, roles: dict[str, str], condition: str) -> None:
    assert condition in asked(text, roles)


@pytest.mark.parametrize(("text", "roles", "absent"), [
    # issue-22 paraphrase set (living_room_toy_boxes)
    ("The stain on the floor has to be cleaned: use the wet wipes from the tea table in case there are some, and "
     "otherwise the wet mop leaning against the wall.", {"wet_wipe": "wet_wipe", "table": "coffee_table",
                                                          "mop": "mop", "stain": "floor_stain"}, "mop"),
    ("Wipe the desk with the sponge if there is one, and otherwise with the cloth.",
     {"sponge": "sponge", "desk": "desk", "cloth": "cloth"}, "cloth"),
])
def test_and_otherwise_is_the_alternative(text: str, roles: dict[str, str], absent: str) -> None:
    a = analyse(brief(text, roles), CATALOG)
    assert any(cl.role == "else" for cl in a.clauses), a.clauses
    assert f"exists({absent})" not in {v for f in a.factors for v in f.values.values()}


def test_a_home_in_an_instruction_keeps_the_sentence_under_the_conditions_before() -> None:
    """issue-22 paraphrase set (bathroom_towel_refresh) and a sentence written for the test."""
    for text, thing in (
            ("The mirror: clean it if it is dirty. Use the microfibre cloth, which lives in the vanity, if we still "
             "have it; if there is no cloth, use the hand towel.", "cloth"),
            ("The mirror: clean it if it is dirty. Use the sponge, which is kept in the vanity, if we still have "
             "it; otherwise use the hand towel.", "sponge")):
        roles = {"mirror": "mirror", thing: thing, "vanity": "bathroom_vanity", "hand_towel": "hand_towel"}
        by_id = {f.id: f for f in analyse(brief(text, roles), CATALOG).factors}
        assert by_id[f"{thing}_present"].context == [("mirror_dirty", frozenset({"yes"}))], by_id


@pytest.mark.parametrize(("text", "roles", "rooms", "factor", "instruction"), [
    # dev2 (a kitchenette checklist): an arrow after a question, past the question mark
    ("[ ] Coffee machine: still on? -> switch OFF.", {"coffee_maker": "coffee_maker"}, ("kitchenette",),
     "coffee_maker_toggled_on", "switch OFF."),
    # written here: a study, an arrow between a verbless heading and its instruction
    ("Desk lamp on? -> switch it off. Laptop on the floor -> put it on the desk.",
     {"desk_lamp": "desk_lamp", "laptop": "laptop", "desk": "desk"}, ("study",),
     "laptop_on_floor", "put it on the desk."),
])
def test_an_arrow_is_then(text: str, roles: dict[str, str], rooms: tuple[str, ...], factor: str,
                          instruction: str) -> None:
    """"still on? -> switch OFF.", "Laptop on the floor -> put it on the desk" (`ARROW`): what
    follows the arrow is the instruction of the condition before it, in the same sentence (a
    question mark before an arrow ends no sentence)."""
    found = {f.id: f.consequences for f in analyse(brief(text, roles, rooms), CATALOG).factors}
    assert instruction in found[factor], found
