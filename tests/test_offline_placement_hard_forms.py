"""Stated placements in the harder forms `benchmarks/placement_forms.py` measures since the
thirteenth session (issue 47): a standing rule ("should be on ... at all times"), the predictive
"will be on", a place at a part of its holder ("at the far end of the table"), and the near misses
beside them (a hedge, "neither ... nor", a choice of places, a time of completion). Sentences are
written here, in several registers (a care plan, a hotel notice, a chat, a museum's house rules, a
lab sheet, a holiday let's welcome book); none is copied from a development set."""

from __future__ import annotations

import pytest

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.offline.placement import described_placements


@pytest.fixture(scope="module")
def catalog() -> Catalog:
    return load_catalog()


def _read(text: str, roles: dict[str, str], catalog: Catalog, room: str = "living_room") -> list[str]:
    brief = {"id": "t", "description": text, "rooms": [room],
             "roles": {name: {"category": kind} for name, kind in roles.items()}}
    return described_placements(brief, catalog)


# --- a standing rule: a modal with a time covering every moment ----------------------------------

@pytest.mark.parametrize("text, roles, fact", [
    # a care plan
    ("Care notes for the night staff. The call bell must be on the nightstand at all times so she can reach it.",
     {"bell": "bell", "nightstand": "nightstand"}, "on(bell, nightstand)"),
    # a lab's house rules
    ("LAB RULES. The fire blanket should always be in the cabinet by the door.",
     {"fire_blanket": "blanket", "cabinet": "cabinet"}, "inside(fire_blanket, cabinet)"),
    # a chat, with the thing taken up by "it"
    ("ok so the remote should be on the sofa, day and night lol. dont lose it again",
     {"remote": "remote_control", "sofa": "sofa"}, "on(remote, sofa)"),
])
def test_a_standing_rule_states_where_the_thing_is(text: str, roles: dict[str, str], fact: str,
                                                   catalog: Catalog) -> None:
    assert fact in _read(text, roles, catalog)


@pytest.mark.parametrize("text", [
    "The call bell should be on the nightstand when you leave the room.",  # a goal
    "The call bell must never be on the nightstand at all times.",  # negated
    "The call bell should be on the nightstand by this evening, always remember that.",  # a deadline
    "Before you go, make sure the call bell is on the nightstand.",
])
def test_a_modal_without_a_standing_time_places_nothing(text: str, catalog: Catalog) -> None:
    assert not any("(bell, nightstand)" in f for f in _read(text, {"bell": "bell", "nightstand": "nightstand"}, catalog))


# --- the predictive "will be" -------------------------------------------------------------------

@pytest.mark.parametrize("text, roles, fact", [
    # a holiday let's welcome book
    ("Welcome to Sea View! The spare key will be in the drawer of the hall table when you arrive.",
     {"key": "key", "drawer": "drawer"}, "inside(key, drawer)"),
    # an office notice: a case the sentence opens with
    ("NOTICE TO CLEANERS. Where a laptop was issued, the laptop will be on the desk nearest the window.",
     {"laptop": "laptop", "desk": "desk"}, "on(laptop, desk)"),
    ("Your laptop will be on the desk next to the printer when you get in.",
     {"laptop": "laptop", "desk": "desk"}, "on(laptop, desk)"),
])
def test_the_predictive_will_be_states_where_the_thing_is(text: str, roles: dict[str, str], fact: str,
                                                          catalog: Catalog) -> None:
    assert fact in _read(text, roles, catalog)


@pytest.mark.parametrize("text", [
    "The laptop will be on the desk once you have finished setting it up.",  # a goal
    "The laptop will be on the desk later, when Jo brings it.",
    "The laptop will not be on the desk.",
    "The laptop will go on the desk.",
    "The laptop will be on the desk. Wipe it down.",  # said alone: a goal (dev 12's near miss)
    "The laptop will be on the desk when you get there if Jo remembers.",  # a condition
])
def test_a_will_of_completion_or_motion_places_nothing(text: str, catalog: Catalog) -> None:
    assert not any("(laptop, desk)" in f for f in _read(text, {"laptop": "laptop", "desk": "desk"}, catalog))


# --- hedges, correlative negation and a choice of places -------------------------------------------

@pytest.mark.parametrize("text", [
    "I doubt the book is on the coffee table.",
    "Hopefully the book is on the coffee table, I'm not certain.",
    "The book is neither on the coffee table nor under the sofa.",
    "The book is on the coffee table or in my bag.",
    "The book is on the coffee table, or maybe on the shelf.",
])
def test_a_hedged_negated_or_offered_place_places_nothing(text: str, catalog: Catalog) -> None:
    placed = _read(text, {"book": "book", "coffee_table": "coffee_table"}, catalog)
    assert not any("(book, coffee_table)" in f for f in placed)


@pytest.mark.parametrize("text, fact", [
    ("The book is on the coffee table and the mug or the plate is on the shelf.", "on(book, coffee_table)"),
    ("Neither of us moved it: the book is on the coffee table.", "on(book, coffee_table)"),
])
def test_an_or_elsewhere_leaves_a_stated_place(text: str, fact: str, catalog: Catalog) -> None:
    assert fact in _read(text, {"book": "book", "coffee_table": "coffee_table"}, catalog)


# --- a place at a part of its holder: "at the head of the table", "at the bottom of the basket" -----

@pytest.mark.parametrize("text, roles, fact, room", [
    # a museum's house rules
    ("The visitors' book sits at the far end of the reception desk, by the donations box.",
     {"book": "book", "desk": "desk"}, "on(book, desk)", "office"),
    # a wedding run sheet
    ("Table plan: the cake knife is at the head of the dining table, next to the bride's glass.",
     {"knife": "knife", "table": "dining_table"}, "on(knife, table)", "dining_room"),
    # a chat
    ("ur sock is right at the bottom of the laundry basket btw",
     {"sock": "sock", "laundry_basket": "laundry_basket"}, "inside(sock, laundry_basket)", "laundry_room"),
    # a landlord's inventory
    ("Inventory, bedroom 2. The spare pillow lies at the back of the wardrobe, under two blankets.",
     {"pillow": "pillow", "wardrobe": "wardrobe"}, "inside(pillow, wardrobe)", "bedroom"),
])
def test_a_place_at_a_part_of_its_holder(text: str, roles: dict[str, str], fact: str, room: str,
                                         catalog: Catalog) -> None:
    assert fact in _read(text, roles, catalog, room)


@pytest.mark.parametrize("text", [
    "The stool is at the side of the dining table.",  # beside it
    "The stool is at the foot of the dining table.",
    "Put the stool at the end of the dining table.",  # an instruction: where it goes
    "If the stool is at the end of the dining table, move it.",
    "The stool is not at the end of the dining table.",
])
def test_a_part_beside_or_a_goal_places_nothing(text: str, catalog: Catalog) -> None:
    placed = _read(text, {"stool": "stool", "table": "dining_table"}, catalog, "dining_room")
    assert not any("(stool, table)" in f for f in placed)


# --- a reduced relative after a name's possessive: "Sam's mug left on the counter needs a wipe" ----

@pytest.mark.parametrize("text, roles, fact, room", [
    # a flatmate's note
    ("Kitchen rota. Priya's mug left on the counter needs a proper scrub, it's been there since Friday.",
     {"mug": "mug", "kitchen_counter": "kitchen_counter"}, "on(mug, kitchen_counter)", "kitchen"),
    # a boarding-house matron's list
    ("Dormitory inspection. Hughes's towel lying in the laundry basket is not his own; return it to the store.",
     {"towel": "towel", "laundry_basket": "laundry_basket"}, "inside(towel, laundry_basket)", "laundry_room"),
])
def test_a_reduced_relative_after_a_possessor(text: str, roles: dict[str, str], fact: str, room: str,
                                             catalog: Catalog) -> None:
    assert fact in _read(text, roles, catalog, room)


@pytest.mark.parametrize("text", [
    "Every mug left on the counter gets washed at six.",  # a kind of thing, no mug of the scene
    "Any mug left on the counter goes in the sink.",
    "If Priya's mug is left on the counter, wash it.",
])
def test_a_quantified_or_conditional_reduced_relative_places_nothing(text: str, catalog: Catalog) -> None:
    placed = _read(text, {"mug": "mug", "kitchen_counter": "kitchen_counter"}, catalog, "kitchen")
    assert not any("(mug, kitchen_counter)" in f for f in placed)


# --- a place named by a word of another language, glossed in brackets: "on wersalka (sofa)" -------

@pytest.mark.parametrize("text, roles, fact, room", [
    # a Polish grandmother's note
    ("Kochanie, the blanket is on wersalka (sofa), please fold it nicely.",
     {"blanket": "blanket", "sofa": "sofa"}, "on(blanket, sofa)", "living_room"),
    # a Japanese host's welcome card
    ("Welcome! The vase stands on the chabudai (the coffee table) - please do not move it.",
     {"vase": "vase", "coffee_table": "coffee_table"}, "on(vase, coffee_table)", "living_room"),
    # a German flatmate's chat
    ("btw my laptop is on the Schreibtisch (desk) if u need it",
     {"laptop": "laptop", "desk": "desk"}, "on(laptop, desk)", "office"),
])
def test_a_bracketed_gloss_names_the_place(text: str, roles: dict[str, str], fact: str, room: str,
                                           catalog: Catalog) -> None:
    placed = _read(text, roles, catalog, room)
    item, holder = fact[fact.index("(") + 1:-1].split(", ")
    assert any(f"({item}, {holder})" in f for f in placed), placed


@pytest.mark.parametrize("text", [
    "The blanket is not on wersalka (sofa).",
    "If the blanket is on wersalka (sofa), fold it.",
    "The blanket is on the left (sofa side).",
    "Put the blanket on wersalka (sofa).",
])
def test_a_bracketed_gloss_in_a_negation_condition_or_instruction_places_nothing(text: str,
                                                                                 catalog: Catalog) -> None:
    placed = _read(text, {"blanket": "blanket", "sofa": "sofa"}, catalog)
    assert not any("(blanket, sofa)" in f for f in placed)


# --- a time clause of the reader's arrival frames what they will find ------------------------------

@pytest.mark.parametrize("text, roles, fact, room", [
    # a holiday let's welcome message
    ("Hi both! When you arrive, the spare key will be in the drawer by the door.",
     {"key": "key", "drawer": "drawer"}, "inside(key, drawer)", "hallway"),
    # a hotel housekeeping sheet
    ("Room 12. When the guests check in, the hair dryer is on the desk and the kettle next to it.",
     {"hair_dryer": "hair_dryer", "desk": "desk"}, "on(hair_dryer, desk)", "bedroom"),
])
def test_an_arrival_frames_what_the_reader_will_find(text: str, roles: dict[str, str], fact: str, room: str,
                                                     catalog: Catalog) -> None:
    assert fact in _read(text, roles, catalog, room)


@pytest.mark.parametrize("text", [
    "When the key is dirty, it will be in the drawer.",  # a condition on the thing
    "When you arrive, put the key in the drawer.",  # an instruction
    "When you arrive, the key may be in the drawer.",  # a doubt
    "When you arrive, the key will be in the drawer once Jo has locked up.",  # a goal
])
def test_an_arrival_frame_places_no_condition_instruction_doubt_or_goal(text: str, catalog: Catalog) -> None:
    placed = _read(text, {"key": "key", "drawer": "drawer"}, catalog, "hallway")
    assert not any("(key, drawer)" in f for f in placed)


# --- the present passive of "leave" says where a thing stays: "the bowl is left at the head of" ----

@pytest.mark.parametrize("text, roles, fact, room", [
    # a gym's closing checklist
    ("Closing up: the spare towel is left on the bench overnight for the early class.",
     {"towel": "towel", "bench": "bench"}, "on(towel, bench)", "laundry_room"),
    # a car-hire welcome card
    ("For your safety a torch is left in the drawer of the dashboard, with spare batteries.",
     {"torch": "flashlight", "drawer": "drawer"}, "inside(torch, drawer)", "garage"),
])
def test_the_present_passive_of_leave_states_where_a_thing_stays(text: str, roles: dict[str, str], fact: str,
                                                                 room: str, catalog: Catalog) -> None:
    assert fact in _read(text, roles, catalog, room)


@pytest.mark.parametrize("text", [
    "Nothing is left on the bench.",
    "The towel is to be left on the bench.",
    "If the towel is left on the bench, wash it.",
    "The towel must not be left on the bench.",
    "The towel should be left on the bench.",
    "Make sure the towel is left on the bench.",
])
def test_a_left_in_a_norm_condition_or_negation_places_nothing(text: str, catalog: Catalog) -> None:
    placed = _read(text, {"towel": "towel", "bench": "bench"}, catalog, "laundry_room")
    assert not any("(towel, bench)" in f for f in placed)
