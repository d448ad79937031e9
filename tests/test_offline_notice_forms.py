"""Kinds of sentence of notices, minutes, postcards, verse and chat (the sixth development set's
new tasks `workshop_leaving_sign`, `scullery_house_meeting_minutes`, `spare_room_postcard_from_crete`,
`walk_in_closet_rhyming_note`, `staff_room_chat_corrections`), each rule tried on the development
sentence and on one written here for another room with other objects (docs/reader.md, the
catalogue of rules)."""

from __future__ import annotations

import pytest
from reading import brief as _brief
from reading import factors as _factors
from reading import placed as _placed

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.analysis import analyse
from logicenveval.offline.lexicon import Lexicon, tokens
from logicenveval.offline.naming import name_objects
from logicenveval.offline.sentences import unquote

CATALOG = load_catalog()


def _named(text: str, rooms: tuple[str, ...] = ()) -> dict[str, str]:
    """name -> category of the objects the reader names."""
    return {o["name"]: o["category"] for o in name_objects(text, CATALOG, rooms)}


# ----- naming ---------------------------------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "kind", "names"), [
    # dev6 workshop_leaving_sign: a rule for the spare, said in the plural
    ("THE SPARE BULB IS KEPT ON THE RACK TOO. CHECK IT: BROKEN BULBS GO IN THE RECYCLING BIN.", ("workshop",),
     "light_bulb", ["spare_bulb"]),
    # written here: a kitchen's fuse
    ("The spare fuse lives in the kitchen drawer. Blown fuses go in the bin.", ("kitchen",), "fuse", ["spare_fuse"]),
])
def test_a_bare_plural_after_the_spare_is_a_rule_for_it_not_another_thing(
        text: str, rooms: tuple[str, ...], kind: str, names: list[str]) -> None:
    """A kind named only as the spare and by a bare plural ("broken bulbs go in ...") is the one
    spare: the plural says what to do with such things."""
    assert [n for n, c in _named(text, rooms).items() if c == kind] == names


def test_the_one_in_use_named_beside_the_spare_is_still_its_own_thing() -> None:
    assert [n for n, c in _named("Replace the fuse if it is blown; a spare fuse is in the drawer. Blown fuses go "
                                 "in the bin.", ("kitchen",)).items() if c == "fuse"] == ["fuse", "spare_fuse"]


@pytest.mark.parametrize(("text", "rooms", "meant", "not_named"), [
    # dev6 workshop_leaving_sign
    ("SCISSORS ARE NOT TO BE LEFT ON THE WORKBENCH. IF THEY ARE ON THE BENCH, PUT THEM AWAY.", ("workshop",),
     "desk", "bench"),
    # written here: a living room's armchair
    ("Grandpa's armchair is by the window. If the cushion is on the floor, put it back on the chair.",
     ("living_room",), "armchair", "chair"),
])
def test_the_tail_of_a_closed_compound_named_before_is_that_thing(
        text: str, rooms: tuple[str, ...], meant: str, not_named: str) -> None:
    """"the workbench ... the bench", "the armchair ... the chair": the same thing said short."""
    named = set(_named(text, rooms).values())
    assert meant in named and not_named not in named, named


def test_the_lexicon_finds_a_role_by_its_closed_compounds_tail() -> None:
    brief = {"id": "t", "description": "", "rooms": ["workshop"],
             "roles": {"workbench": {"category": "desk"}, "scissors": {"category": "scissors"}}}
    lex = Lexicon.build(brief, CATALOG)
    found = lex.find_mentions(tokens("if they are on the bench"))
    assert [m.roles for m in found if m.kind == "role"] == [("workbench",)]
    # a role named so keeps the word: a bench that is a bench
    brief["roles"]["bench"] = {"category": "bench"}
    lex = Lexicon.build(brief, CATALOG)
    assert [m.roles for m in lex.find_mentions(tokens("on the bench"))] == [("bench",)]


@pytest.mark.parametrize(("text", "rooms", "category"), [
    ("THE SHOP VAC MUST NOT BE LEFT RUNNING.", ("workshop",), "vacuum_cleaner"),  # dev6
    ("Run the vac round the hallway.", ("hallway",), "vacuum_cleaner"),
    ("Tools go back on the workbench.", ("garage",), "desk"),
])
def test_vac_and_workbench_are_catalog_names(text: str, rooms: tuple[str, ...], category: str) -> None:
    """Collins: "vac", informal, a vacuum cleaner; WordNet: "workbench", a strong worktable (the
    catalog's work table is the desk)."""
    assert category in _named(text, rooms).values()


@pytest.mark.parametrize(("text", "rooms"), [
    # dev6 walk_in_closet_rhyming_note
    ("And the light - is it on when you're done for the day?\nThen flick off the switch as you go on your way.",
     ("walk_in_closet",)),
    # written here: a hallway
    ("Is the light still on in the hall? Press the switch by the door.", ("hallway",)),
])
def test_a_light_whose_switch_is_said_next_is_the_switch(text: str, rooms: tuple[str, ...]) -> None:
    """"the light ... the switch": one thing, the switch (as "Light switch: if the light is on"),
    whose state the question asks."""
    assert set(_named(text, rooms).values()) == {"light_switch"}
    assert _factors(text, rooms) == {"light_switch_toggled_on": {"state(light_switch, toggled_on)",
                                                                 "not state(light_switch, toggled_on)"}}


def test_a_light_without_a_switch_is_still_a_lamp() -> None:
    assert "light_switch" not in _named("Is the light still on in the hall? Turn it off.", ("hallway",)).values()


@pytest.mark.parametrize(("text", "rooms", "names"), [
    # dev6 scullery_house_meeting_minutes
    ("Tea towels. There are two, a green one and a white one.", ("scullery",),
     {"green_hand_towel": "hand_towel", "white_hand_towel": "hand_towel"}),
    # written here: an office's mugs
    ("Mugs on the desk: there are three - a red one, a blue one and a white one.", ("office",),
     {"red_mug": "mug", "blue_mug": "mug", "white_mug": "mug", "desk": "desk"}),
])
def test_a_count_standing_alone_counts_the_plural_just_named(text: str, rooms: tuple[str, ...],
                                                            names: dict[str, str]) -> None:
    assert _named(text, rooms) == names


@pytest.mark.parametrize(("text", "rooms", "table"), [
    # dev6 staff_room_chat_corrections: a staff room with a microwave, a toaster, a fridge
    ("microwave door was left open. theres a coffee mug on the table. the toaster sits on the counter. "
     "oh and the fridge, if someone's left it open shut it", ("staff_room",), "dining_table"),
    # written here: a break area with a fridge and a microwave, and a den with a sofa and a television
    ("Wipe the table by the fridge and put the plate from the microwave in the sink.", ("break_area",),
     "dining_table"),
    ("The remote is on the table next to the sofa; switch the television off.", ("den_corner",), "coffee_table"),
])
def test_a_room_of_no_known_type_is_told_by_the_things_named_in_it(text: str, rooms: tuple[str, ...],
                                                                    table: str) -> None:
    assert table in _named(text, rooms).values()


# ----- placements -----------------------------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "fact"), [
    # dev6 workshop_leaving_sign
    ("IF EITHER IS ON THE BENCH, RETURN IT TO THE STORAGE BOX (BOTTOM SHELF OF THE METAL RACK).", ("workshop",),
     "on(storage_box, utility_shelf)"),
    # written here: a kitchen cupboard (a shelf inside it) and a hallway shelf
    ("If the cereal is on the counter, return it to the cardboard box (bottom shelf of the cupboard).",
     ("kitchen",), "inside(cardboard_box, cabinet)"),
    ("Put the keys in the basket (on the shelf) when you come in.", ("hallway",), "on(basket, wall_shelf)"),
])
def test_a_bracket_that_is_only_a_place_says_where_the_thing_before_it_is(
        text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in _placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), [
    # dev6 scullery_house_meeting_minutes
    ("Broom. Ben asked whether it could live somewhere else. Not agreed; it stays standing on the floor by the "
     "back door.", ("scullery",), "on(broom, floor)"),
    # written here: a dining room's mug
    ("The vase is chipped. It is on the table, so mind it.", ("dining_room",), "on(vase, dining_table)"),
])
def test_it_as_a_statements_subject_is_the_last_statements_subject(text: str, rooms: tuple[str, ...],
                                                                  fact: str) -> None:
    assert fact in _placed(text, rooms)
    assert not _factors(text, rooms), "a stated place is no factor"


def test_it_in_a_condition_places_nothing() -> None:
    assert not _placed("The mug is chipped. If it is on the table, wash it.", ("dining_room",))


@pytest.mark.parametrize(("text", "rooms", "fact"), [
    # dev6 scullery_house_meeting_minutes
    ("3. Washing powder. Stays on the shelf above the machine; Tom to stop moving it.", ("scullery",),
     "on(laundry_detergent, wall_shelf)"),
    # written here: a bathroom
    ("Bath mat. Hangs on the towel rail after use.", ("bathroom",), "on(bath_mat, towel_rack)"),
])
def test_a_heading_ended_by_a_full_stop_is_the_subject_of_a_verb_with_none(
        text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in _placed(text, rooms)


# ----- chat corrections and time stamps -------------------------------------------------------

def test_a_starred_chat_correction_is_made_in_the_line_it_corrects() -> None:
    # dev6 staff_room_chat_corrections
    text = ("[08:03] Dana: if its dirty put it in the dishwasher, if not in the cupboard\n"
            "[08:03] Dana: *sink not dishwasher, dishwasher's broken\n"
            "[08:05] Dana: oh and the fridge, if someone's left it open shut it pls\n"
            "[08:05] Dana: *the fridge door")
    assert unquote(text) == ("Dana: if its dirty put it in the sink, if not in the cupboard\n"
                             "Dana: dishwasher's broken.\n"
                             "Dana: oh and the fridge door, if someone's left it open shut it pls")
    # written here: a bathroom thread, with a bullet that is no correction
    assert unquote("Mia: can you put the blue towel in the hamper\nMia: *basket not hamper\nMia: * also the rug") \
        == "Mia: can you put the blue towel in the basket\nMia: * also the rug"
    assert "hamper" not in _named("14:02 Mia: put the towel in the hamper\n14:03 Mia: *basket not hamper",
                                  ("bathroom",))


# ----- conditions -----------------------------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "factor"), [
    # dev6 walk_in_closet_rhyming_note
    ("And the lamp - is it on when you're done for the day? Then flick it off.", ("bedroom",), "table_lamp_toggled_on"),
    # written here
    ("Is the television on when you leave? Then switch it off.", ("living_room",), "television_toggled_on"),
])
def test_a_time_clause_of_the_reader_leaves_a_question_a_question(text: str, rooms: tuple[str, ...],
                                                                 factor: str) -> None:
    """"is it on when you're done for the day?": when the reader acts says when to ask, no
    situation of its own; the question is the condition."""
    assert factor in _factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "factor"), [
    # dev6 spare_room_postcard_from_crete
    ("Ken will have left the standing lamp on, he always does - if so, off please.", ("spare_room",),
     "floor_lamp_toggled_on"),
    # written here
    ("Dad left the telly on again, he always does - if so, off at the wall please.", ("living_room",),
     "television_toggled_on"),
    ("The kids probably left the fan running - if so, off please.", ("living_room",), "ceiling_fan_toggled_on"),
])
def test_if_so_takes_what_follows_its_comma_as_its_instruction(text: str, rooms: tuple[str, ...],
                                                              factor: str) -> None:
    analysis = analyse(_brief(text, rooms), CATALOG)
    found = {f.id: f for f in analysis.factors}
    assert factor in found and any("off" in str(c) for c in found[factor].consequences), found


@pytest.mark.parametrize(("text", "rooms", "factor"), [
    # dev6 staff_room_chat_corrections
    ("microwave door was left open again yesterday, if it still is can you shut it", ("staff_room",),
     "microwave_open"),
    # written here
    ("The heater was left on last night, if it still is could you switch it off", ("bedroom",),
     "radiator_toggled_on"),
])
def test_a_request_after_a_copula_opens_the_instruction_of_a_condition_typed_without_a_comma(
        text: str, rooms: tuple[str, ...], factor: str) -> None:
    analysis = analyse(_brief(text, rooms), CATALOG)
    found = {f.id: f for f in analysis.factors}
    assert factor in found and [str(c).strip() for c in found[factor].consequences][:1] in (
        ["can you shut it"], ["could you switch it off"]), found


@pytest.mark.parametrize(("text", "rooms", "thing", "goals"), [
    # dev6 staff_room_chat_corrections (after its correction)
    ("and theres a coffee mug on the table - if its dirty put it in the sink, if not in the cupboard",
     ("staff_room",), "mug", ("sink", "cupboard")),
    # written here: a kitchen's plate
    ("There's a plate on the counter - if it's dirty put it in the sink, if not in the cabinet.", ("kitchen",),
     "plate", ("sink", "cabinet")),
])
def test_if_not_and_a_place_after_an_instruction_is_its_alternative(
        text: str, rooms: tuple[str, ...], thing: str, goals: tuple[str, str]) -> None:
    """"put it in the sink, if not in the cupboard" sorts by the condition before (no question
    whether it is in the cupboard), and the thing the scene has is stated, not asked."""
    factors = _factors(text, rooms)
    assert list(factors) == [f"{thing}_dirty"], factors
    analysis = analyse(_brief(text, rooms), CATALOG)
    stated = [c for c in analysis.clauses if "on the" in c.text and c.cue != "if"]
    assert stated and stated[0].role == "scene", analysis.clauses  # no instruction of the condition
    said = " | ".join(str(c) for f in analysis.factors for c in f.consequences)
    assert goals[0] in said and goals[1] in said, said


def test_if_not_before_its_own_instruction_still_asks_where_the_thing_is() -> None:
    # dev 1's "Knife - if not in the dish rack, put it in": an instruction follows the comma
    factors = _factors("Knife - if not in the dish rack, put it in.", ("kitchen",))
    assert any("inside(knife, dish_rack)" in v or "on(knife, dish_rack)" in v
               for values in factors.values() for v in values), factors


@pytest.mark.parametrize(("text", "rooms"), [
    # dev6 workshop_leaving_sign
    ("IF EITHER IS ON THE WORKBENCH, RETURN IT TO THE STORAGE BOX (BOTTOM SHELF OF THE METAL RACK).", ("workshop",)),
    # written here: a study
    ("Put the pens in the metal storage box on the desk.", ("study",)),
])
def test_an_attribute_value_right_before_another_things_name_is_that_things(text: str,
                                                                          rooms: tuple[str, ...]) -> None:
    """"the metal rack", "the metal storage box": the material describes the thing it precedes
    (which has no material to ask), not the desk named elsewhere in the text."""
    assert "desk_material" not in _factors(text, rooms)
