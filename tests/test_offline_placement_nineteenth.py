"""Placements in forms no grid had before the nineteenth session (offline.placement, issue 47):
participles of putting away ("tucked", "stashed", "stowed", "hidden"), a person's possessive
holder ("on Sam's desk"), a past placement its sentence ends ("until this morning", "formerly",
"but Sam moved it") and a wish's place ("Sam wants the mug on the counter"). Each rule on
sentences written here in several registers (a note, a letter, a listing, a museum label, a
child's text, a learner's note), with near misses that must not be read. The grid they were
measured on is `benchmarks/placement_forms.py`'s nineteenth section."""

from __future__ import annotations

from typing import Any

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.placement import described_placements

CATALOG = load_catalog()
ROOMS = ["living_room", "bedroom", "kitchen", "hallway"]
#: role name -> catalog category
ROLES = {
    "apple": "apple", "fridge": "fridge", "keys": "keys", "bowl": "bowl", "scarf": "scarf",
    "basket": "basket", "laptop": "laptop", "desk": "desk", "jacket": "jacket", "wardrobe": "wardrobe",
    "candle": "candle", "dresser": "dresser", "teddy": "teddy_bear", "bed": "bed", "mug": "mug",
    "counter": "kitchen_counter", "book": "book", "coffee_table": "coffee_table", "sock": "sock",
    "drawer": "drawer", "phone": "cell_phone", "table": "dining_table",
}


def _read(text: str, *roles: str) -> set[str]:
    missing = [r for r in roles if CATALOG.get(ROLES[r]) is None]
    if missing:
        pytest.skip(f"the catalog lacks {missing}")
    brief: dict[str, Any] = {"id": "t", "description": text, "rooms": ROOMS,
                             "roles": {r: {"category": ROLES[r]} for r in roles}}
    return set(described_placements(brief, CATALOG))


# --- participles of putting away (`STOWED`) ---------------------------------------------------

STOWED_READ = [
    ("Note for the sitter: the spare keys are tucked in the blue bowl.", "keys", "bowl", "inside(keys, bowl)"),
    ("Fridge check. An apple was stashed in the fridge by one of the kids.", "apple", "fridge",
     "inside(apple, fridge)"),
    ("Hall inventory - scarf stowed in the wicker basket, hat on the peg.", "scarf", "basket",
     "inside(scarf, basket)"),
    ("Dear Ana, your old jacket is hidden in the wardrobe, behind the coats.", "jacket", "wardrobe",
     "inside(jacket, wardrobe)"),
    ("My sock has been tucked away in the drawer all week.", "sock", "drawer", "inside(sock, drawer)"),
    ("the apple is stowed away in the fridge so nobody eats it", "apple", "fridge",
     "inside(apple, fridge)"),
]


@pytest.mark.parametrize(("text", "item", "holder", "fact"), STOWED_READ)
def test_participles_of_putting_away_state_a_place(text: str, item: str, holder: str, fact: str) -> None:
    assert fact in _read(text, item, holder)


STOWED_NEAR_MISSES = [
    ("Tuck the spare keys in the bowl before you go.", "keys", "bowl"),
    ("If the apple is stashed in the fridge, leave it there.", "apple", "fridge"),
    ("The scarf should be stowed in the basket when you are done.", "scarf", "basket"),
    ("Is the jacket hidden in the wardrobe?", "jacket", "wardrobe"),
    ("Put the sock away in the drawer.", "sock", "drawer"),
    ("If the sock has been put away in the drawer, fine.", "sock", "drawer"),
]


@pytest.mark.parametrize(("text", "item", "holder"), STOWED_NEAR_MISSES)
def test_putting_away_as_a_goal_or_question_places_nothing(text: str, item: str, holder: str) -> None:
    assert not any(f"({item}, {holder})" in f for f in _read(text, item, holder))


# --- a person's possessive holder (`_owned_holder`) --------------------------------------------

OWNED_READ = [
    ("The mug is on Sam's counter, next to the kettle.", "mug", "counter", "on(mug, counter)"),
    ("Grandma's wardrobe is huge. My jacket hangs in Grandma's wardrobe.", "jacket", "wardrobe",
     "inside(jacket, wardrobe)"),
    ("Estate listing. A candle sits proudly on Dad's dresser.", "candle", "dresser",
     "on(candle, dresser)"),
    ("my teddy is on Mia's bed and i like it", "teddy", "bed", "on(teddy, bed)"),
]


@pytest.mark.parametrize(("text", "item", "holder", "fact"), OWNED_READ)
def test_a_persons_possessive_holder_is_the_holder(text: str, item: str, holder: str, fact: str) -> None:
    assert fact in _read(text, item, holder)


OWNED_NEAR_MISSES = [
    ("Put the laptop on Sam's desk.", "laptop", "desk"),
    ("If the laptop is on Sam's desk, bring it here.", "laptop", "desk"),
    ("The laptop is not on Sam's desk.", "laptop", "desk"),
]


@pytest.mark.parametrize(("text", "item", "holder"), OWNED_NEAR_MISSES)
def test_a_persons_holder_in_an_instruction_or_negation_places_nothing(text: str, item: str, holder: str) -> None:
    assert not any(f"({item}, {holder})" in f for f in _read(text, item, holder))


# --- a past placement its sentence ends (`_ended_past`) ----------------------------------------

ENDED = [
    ("The mug was on the counter until this morning.", "mug", "counter"),
    ("Museum note: the book was formerly kept on the coffee table.", "book", "coffee_table"),
    ("The laptop sat on the desk yesterday, but Sam moved it.", "laptop", "desk"),
    ("Keys were in the bowl till lunch.", "keys", "bowl"),
    ("The phone was on the dining table last night, but it's gone now.", "phone", "table"),
]


@pytest.mark.parametrize(("text", "item", "holder"), ENDED)
def test_an_ended_past_placement_places_nothing(text: str, item: str, holder: str) -> None:
    assert not any(f"({item}, {holder})" in f for f in _read(text, item, holder))


STILL_HOLDS = [
    ("The mug was left on the counter, but it is clean.", "mug", "counter", "on(mug, counter)"),
    ("The mug is on the counter until Sam comes home.", "mug", "counter", "on(mug, counter)"),
    ("The laptop was on the desk, but Sam moved the lamp.", "laptop", "desk", "on(laptop, desk)"),
    ("The laptop sat on the desk till lunch; now it is on the bed.", "laptop", "bed", "on(laptop, bed)"),
]


@pytest.mark.parametrize(("text", "item", "holder", "fact"), STILL_HOLDS)
def test_a_past_placement_nothing_ends_is_still_read(text: str, item: str, holder: str, fact: str) -> None:
    assert fact in _read(text, item, holder)


# --- a wish's place (`_wished`) ----------------------------------------------------------------

WISHED = [
    ("Sam wants the mug on the counter.", "mug", "counter"),
    ("Imagine the candle on the dresser, glowing.", "candle", "dresser"),
    ("I'd prefer the laptop on the desk.", "laptop", "desk"),
    ("We need the teddy on the bed before bedtime.", "teddy", "bed"),
]


@pytest.mark.parametrize(("text", "item", "holder"), WISHED)
def test_a_wish_places_nothing(text: str, item: str, holder: str) -> None:
    assert not any(f"({item}, {holder})" in f for f in _read(text, item, holder))


DESCRIBED = [
    ("Sam wants the mug on the counter washed.", "mug", "counter", "on(mug, counter)"),
    ("Wash the mug on the counter.", "mug", "counter", "on(mug, counter)"),
    ("I need the book on the coffee table clean.", "book", "coffee_table", "on(book, coffee_table)"),
]


@pytest.mark.parametrize(("text", "item", "holder", "fact"), DESCRIBED)
def test_a_definite_thing_with_its_place_is_still_presumed_there(text: str, item: str, holder: str,
                                                                fact: str) -> None:
    assert fact in _read(text, item, holder)


# --- counts, a place before its list after a dash, a checklist's boxes --------------------------

COUNTED_READ = [
    ("Packing list: 1 x mug - on the counter.", "mug", "counter", "on(mug, counter)"),
    ("Shipping manifest, crate 4: 2x books - on the coffee table, 1 candle - on the dresser.", "book",
     "coffee_table", "on(book, coffee_table)"),
    ("Inventory of the flat. 3 socks in the drawer.", "sock", "drawer", "inside(sock, drawer)"),
    ("On the counter - 1 mug.", "mug", "counter", "on(mug, counter)"),
    ("In the drawer - two socks, clean.", "sock", "drawer", "inside(sock, drawer)"),
    ("Checklist:\n[x] my phone on the dining table\n[x] lights off", "phone", "table", "on(phone, table)"),
    ("Before we left:\n\u2713 candle on the dresser\n\u2713 windows shut", "candle", "dresser",
     "on(candle, dresser)"),
]


@pytest.mark.parametrize(("text", "item", "holder", "fact"), COUNTED_READ)
def test_counted_items_and_list_lines_state_a_place(text: str, item: str, holder: str, fact: str) -> None:
    assert fact in _read(text, item, holder)


COUNTED_NEAR_MISSES = [
    ("Mugs on the counter!", "mug", "counter"),  # a heading about a class: no count
    ("To do:\n[ ] put the mug on the counter", "mug", "counter"),
    ("On the counter - if there is a mug, wash it.", "mug", "counter"),
    ("Packing list: 1 x mug - on the counter or in the car?", "mug", "counter"),
]


@pytest.mark.parametrize(("text", "item", "holder"), COUNTED_NEAR_MISSES)
def test_uncounted_classes_tasks_and_questions_place_nothing(text: str, item: str, holder: str) -> None:
    assert not any(f"({item}, {holder})" in f for f in _read(text, item, holder))


# --- a result participle after a verbless noun phrase and a comma (`_result_participle`) ---------

ADJUNCT_READ = [
    ("The mug, left on the counter by Sam.", "mug", "counter", "on(mug, counter)"),
    ("Hall log, Tuesday. My scarf, tucked in the basket, is still damp.", "scarf", "basket",
     "inside(scarf, basket)"),
    ("Exhibit 12. The candle, placed on the dresser by the maid in 1890.", "candle", "dresser",
     "on(candle, dresser)"),
]


@pytest.mark.parametrize(("text", "item", "holder", "fact"), ADJUNCT_READ)
def test_a_result_participle_after_a_comma_states_a_place(text: str, item: str, holder: str, fact: str) -> None:
    assert fact in _read(text, item, holder)


ADJUNCT_NEAR_MISSES = [
    ("If the mug, left on the counter, is dirty, wash it.", "mug", "counter"),
    ("Is the scarf, tucked in the basket, dry?", "scarf", "basket"),
    ("The candle, which should be placed on the dresser, is new.", "candle", "dresser"),
]


@pytest.mark.parametrize(("text", "item", "holder"), ADJUNCT_NEAR_MISSES)
def test_a_participle_in_a_condition_question_or_norm_places_nothing(text: str, item: str, holder: str) -> None:
    assert not any(f"({item}, {holder})" in f for f in _read(text, item, holder))


def test_an_instruction_after_a_label_comma_places_nothing() -> None:
    assert not any("(mug, counter)" in f for f in _read("The mug, put it on the counter later.", "mug", "counter"))
