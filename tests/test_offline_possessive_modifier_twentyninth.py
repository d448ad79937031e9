"""A noun phrase opened by a possessive and a modifier ("Today's brew sheet", "the chef's prep
sheet"), from the twenty-ninth session (dev 49's microbrewery handover: "Today's brew sheet, the
one with my gravities on. Should it still be lying on the desk, file it"): a possessive stands
where an article does, so a head that names a kind only by one of its names ("sheet" of "paper
sheet") is a noun phrase's head after it and one modifier, as after "the job" (`naming._Reader.
modified`, `_possessives`: the words written as possessives, since `expand` drops the "'s").
Rows written here in other registers before the rule and measured then: 0 of 6; after: 6 of 6. Near misses: a contraction of "is" ("the kettle's still on") names
nothing new; a head that names a kind itself was named before and still is."""

from __future__ import annotations

import pytest
from reading import factors, named, placed

#: (text, rooms, a fact the sheet's reading gives: a factor's value or a stated placement)
SHEETS = [
    ("Today's job sheet: if it's still on the desk, file it in the cabinet.", ("site_office",),
     "on(document, desk)"),
    ("Yesterday's delivery sheet is on the counter.", ("goods_in",), "on(document, kitchen_counter)"),
    ("The chef's prep sheet lies on the counter by the fridge.", ("prep_kitchen",),
     "on(document, kitchen_counter)"),
    ("Mum's shopping sheet - if it's on the table, put it in the drawer.", ("scullery",), "on(document, dining_table)"),
    ("Tonight's rota sheet? On the desk. If it's there, pin it up on the board.", ("staff_room",), None),
    ("The vet's dosing sheet is on the shelf; if it's still there, file it in the cabinet.", ("feed_room",),
     "on(document, wall_shelf)"),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), SHEETS)
def test_a_possessive_and_a_modifier_open_a_noun_phrase(text: str, rooms: tuple[str, ...], fact: str | None) -> None:
    assert "document" in {category for category, _ in named(text, rooms).values()}, named(text, rooms)
    read = placed(text, rooms) | {v for values in factors(text, rooms).values() for v in values}
    assert fact is None or fact in read, read


def test_a_contraction_of_is_names_nothing_new() -> None:
    text = "The kettle's still on. If it's on, switch it off."
    assert {category for category, _ in named(text, ("tea_room",)).values()} == {"kettle"}


def test_a_head_that_names_a_kind_itself_is_named_as_before() -> None:
    text = "Our caretaker's step stool is in the cupboard."
    assert "inside(step_stool, cabinet)" in placed(text, ("lobby",))
