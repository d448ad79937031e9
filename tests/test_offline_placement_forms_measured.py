"""Stated placements in the forms `benchmarks/placement_forms.py` measures (issue 47, twelfth
session): each rule on sentences written here in at least two registers (a note to a house-sitter,
a chat message, a formal report, a story), and near misses beside each that state no current
placement and must not be read as one."""

from __future__ import annotations

from typing import Any

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.placement import described_placements
from logicenveval.offline.sentences import expand

CATALOG = load_catalog()

#: roles the sentences below speak of (role name -> catalog category)
ROLES = {
    "mug": "mug", "counter": "kitchen_counter", "towel": "towel", "laundry_basket": "laundry_basket",
    "laptop": "laptop", "desk": "desk", "wallet": "wallet", "nightstand": "nightstand", "drawer": "drawer",
    "remote_control": "remote_control", "sofa": "sofa", "book": "book", "coffee_table": "coffee_table",
    "apple": "apple", "fridge": "fridge", "cloth": "dish_cloth", "pillow": "pillow", "bed": "bed",
    "jacket": "jacket", "wardrobe": "wardrobe", "sock": "sock",
}


def _read(text: str, rooms: tuple[str, ...] = ("kitchen", "living_room", "bedroom", "office")) -> list[str]:
    brief: dict[str, Any] = {"id": "t", "description": text, "rooms": list(rooms),
                             "roles": {name: {"category": cat} for name, cat in ROLES.items() if cat in CATALOG.categories}}
    return [f.replace(" ", "") for f in described_placements(brief, CATALOG)]


def _placed(text: str, item: str, holder: str) -> bool:
    return any(f"({item},{holder})" in f for f in _read(text))


# --- "with <thing> on it" in an instruction: the noun phrase takes the place for granted --------

@pytest.mark.parametrize(("text", "fact"), [
    ("Please dust the coffee table with my book on it.", "on(book,coffee_table)"),  # a note
    ("Go and look at the desk with Sam's laptop on it.", "on(laptop,desk)"),
    ("Empty the laundry basket with the towel in it.", "inside(towel,laundry_basket)"),  # a chore list
])
def test_with_on_it_in_an_instruction(text: str, fact: str) -> None:
    assert fact in _read(text)


@pytest.mark.parametrize(("text", "item", "holder"), [
    ("Wipe the counter with a cloth.", "cloth", "counter"),  # an instrument, no "on it"
    ("Please wipe down the desk with the cloth and put the laptop back.", "cloth", "desk"),
    ("Check the coffee table, with no book on it, is clear.", "book", "coffee_table"),  # a negation
    ("If you see the sofa with the remote on it, take a photo.", "remote_control", "sofa"),  # a condition
])
def test_with_near_misses(text: str, item: str, holder: str) -> None:
    assert not _placed(text, item, holder)


# --- an active perfect of a verb of result: "we had put", "I've left" ---------------------------

@pytest.mark.parametrize(("text", "fact"), [
    ("Before the guests came, we had put the apple in the fridge.", "inside(apple,fridge)"),  # a story
    ("ok so I've left my laptop on the desk, grab it pls", "on(laptop,desk)"),  # a chat message
    ("Mum has dropped her wallet in the drawer again.", "inside(wallet,drawer)"),  # third person
])
def test_active_perfect_report(text: str, fact: str) -> None:
    assert fact in _read(text)


@pytest.mark.parametrize(("text", "item", "holder"), [
    ("Have you put the mug on the counter?", "mug", "counter"),  # a question
    ("If we had put the apple in the fridge, it would still be fresh.", "apple", "fridge"),  # a condition
    ("I haven't put the towel in the laundry basket.", "towel", "laundry_basket"),  # a negation
    ("Maybe I had put the wallet in the drawer.", "wallet", "drawer"),  # a doubt
])
def test_active_perfect_near_misses(text: str, item: str, holder: str) -> None:
    assert not _placed(text, item, holder)


# --- a third person's report: the subject names no thing of the task ----------------------------

@pytest.mark.parametrize(("text", "fact"), [
    ("Tom left my mug on the counter this morning, sorry.", "on(mug,counter)"),  # a note
    ("The night porter placed the guest's wallet in the drawer of the room.", "inside(wallet,drawer)"),  # a report
    ("Grandma put a pillow on the bed for you.", "on(pillow,bed)"),  # a letter
    ("My sister had thrown her jacket on the sofa.", "on(jacket,sofa)"),  # a story
])
def test_third_person_report(text: str, fact: str) -> None:
    assert fact in _read(text)


@pytest.mark.parametrize(("text", "item", "holder"), [
    ("If Tom left the mug on the counter, wash it.", "mug", "counter"),  # a condition
    ("Did Grandma put the pillow on the bed?", "pillow", "bed"),  # a question
    ("Maybe Tom put the jacket in the wardrobe.", "jacket", "wardrobe"),  # a doubt
    ("Tom never put the mug on the counter.", "mug", "counter"),  # a negation
    ("My husband always puts the jacket on the sofa. If it is there, hang it up.", "jacket", "sofa"),  # a habit
    ("The kids often throw a sock in the drawer.", "sock", "drawer"),
])
def test_third_person_near_misses(text: str, item: str, holder: str) -> None:
    assert not _placed(text, item, holder)


# --- what a perceiver finds or sees ("you'll find", "I spotted") --------------------------------

@pytest.mark.parametrize(("text", "fact"), [
    ("Welcome! You'll find the remote on the sofa and spare towels in the laundry basket.",
     "on(remote_control,sofa)"),  # a holiday-let note
    ("You will see a book lying on the coffee table; please do not move it.", "on(book,coffee_table)"),
    ("lol I spotted your wallet in the drawer", "inside(wallet,drawer)"),  # a chat message
    ("The laptop is charged. You can find it on the desk.", "on(laptop,desk)"),  # an object "it"
    ("My laptop: you can find it on the desk.", "on(laptop,desk)"),  # after a topic
])
def test_perceived(text: str, fact: str) -> None:
    assert fact in _read(text)


@pytest.mark.parametrize(("text", "item", "holder"), [
    ("You might find the mug on the counter.", "mug", "counter"),  # a doubt
    ("If you see the wallet in the drawer, leave it there.", "wallet", "drawer"),  # a condition
    ("Did you see my wallet in the drawer?", "wallet", "drawer"),  # a question
    ("You won't find the apple in the fridge.", "apple", "fridge"),  # a negation
])
def test_perceived_near_misses(text: str, item: str, holder: str) -> None:
    assert not _placed(text, item, holder)


# --- "'s" before a preposition of place that is also a noun -------------------------------------

@pytest.mark.parametrize(("text", "fact"), [
    ("Sam's wallet's inside the nightstand.", "inside(wallet,nightstand)"),
    ("heads up: the sock's inside the drawer", "inside(sock,drawer)"),
])
def test_contracted_is_before_inside(text: str, fact: str) -> None:
    assert fact in _read(text)


def test_possessive_inside_as_a_noun_stays() -> None:
    assert expand("The fridge's inside is dirty.") == "The fridge inside is dirty."
    assert expand("The kettle's beside the sink.") == "The kettle is beside the sink."


# --- a label and its place: a record's, a list's or a form's "Thing: place" -------------------

@pytest.mark.parametrize(("text", "fact"), [
    ("Kit handover\n- Laptop: on the desk, charging.\n- Wallet: in the drawer.", "on(laptop,desk)"),  # a record
    ("Kit handover\n- Laptop: on the desk, charging.\n- Wallet: in the drawer.", "inside(wallet,drawer)"),
    ("Where things are - remote - on the sofa, as usual", "on(remote_control,sofa)"),  # a chat
])
def test_label_and_place(text: str, fact: str) -> None:
    assert fact in _read(text)


@pytest.mark.parametrize(("text", "item", "holder"), [
    ("Laptop: on the desk?", "laptop", "desk"),  # a question
    ("Wallet: in the drawer or in the car.", "wallet", "drawer"),  # a choice of places
    ("Laptop: maybe on the desk.", "laptop", "desk"),  # a doubt
    ("Note: on the desk there might be a laptop.", "laptop", "desk"),  # the label names no thing
])
def test_label_near_misses(text: str, item: str, holder: str) -> None:
    assert not _placed(text, item, holder)


# --- the terse register's noun phrase, participle and place ("Sock left in the drawer") ---------

@pytest.mark.parametrize(("text", "fact"), [
    ("Item 3 of the claim. Old bath towel put down on the floor to soak up the leak.", "on(towel,floor)"),
    ("Night log, 02:10: sock left in the drawer. Laptop found on the desk.", "inside(sock,drawer)"),
    ("Night log, 02:10: sock left in the drawer. Laptop found on the desk.", "on(laptop,desk)"),
    ("Sam's jacket left in the wardrobe overnight.", "inside(jacket,wardrobe)"),  # a note
])
def test_headline_participle(text: str, fact: str) -> None:
    assert fact in _read(text)


@pytest.mark.parametrize(("text", "item", "holder"), [
    ("Every sock left in the drawer gets in the way.", "sock", "drawer"),  # generic, a verb follows
    ("If towel left on the floor, hang it up.", "towel", "floor"),  # a condition
    ("Pick up a sock lying in the drawer.", "sock", "drawer"),  # an instruction's indefinite thing
    ("A mug left upon the desk, if it be dirty, goes in the sink.", "mug", "desk"),  # a case, its verb later
    ("Laptop left on the desk? Put it away.", "laptop", "desk"),  # a question
])
def test_headline_near_misses(text: str, item: str, holder: str) -> None:
    assert not _placed(text, item, holder)


# --- an apposition names a place the task's names do not ("on the taburete, the little stool") --

@pytest.mark.parametrize(("text", "fact"), [
    ("Mi abuela's book is on the mesita, the coffee table, as always.", "on(book,coffee_table)"),  # code-switched
    ("The laptop sits on the bureau, the desk by the window.", "on(laptop,desk)"),  # a letter
    ("Beta, your jacket is in the almirah, the wardrobe, please don't forget it.", "inside(jacket,wardrobe)"),
])
def test_apposed_holder(text: str, fact: str) -> None:
    assert fact in _read(text)


@pytest.mark.parametrize(("text", "item", "holder"), [
    ("The mug is on its way, the desk is next.", "mug", "desk"),  # a new clause
    ("If the book is on the mesita, the coffee table, move it.", "book", "coffee_table"),  # a condition
])
def test_apposed_near_misses(text: str, item: str, holder: str) -> None:
    assert not _placed(text, item, holder)
