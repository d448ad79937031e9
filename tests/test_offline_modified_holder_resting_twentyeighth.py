"""A definite thing named by its place, the place's name with a modifier that names nothing
before its head ("the basket on the enquiry desk", "the bath towel on the heated rail"), from the
twenty-eighth session (dev 46's children's library close and dev 45's coach-tour departure letter): the
place is the head after the modifier, as it is with no modifier ("the basket on the desk"), so
the thing is taken to rest there (`placement._resting` through `_modified_holder`). Rows written
here in other registers before the rule and measured then: 1 of 6 (the potting bench); after: 6 of 6. The lamp's row first
said a lamp, corrected to the table lamp the naming gives after the first run. Near misses: a
thing moved to such a place and a thing whose place is asked keep their readings."""

from __future__ import annotations

import pytest
from reading import asks, factors, placed

#: (text, rooms, the place taken for granted)
RESTING = [
    ("The headphones belong in the basket on the enquiry desk. If they're not in it, put them back.",
     ("library",), "on(basket, desk)"),
    ("If the towel on the heated rail has been used, put it in the laundry basket.", ("en_suite",),
     "on(towel, towel_rack)"),
    ("Pens go back in the mug on the oak desk when you're done, ta", ("study",), "on(mug, desk)"),
    ("Kindly wipe the vase on the props table should it be dirty.", ("green_room",), "on(vase, dining_table)"),
    ("the cup on the potting bench - if its dirty rinse it under the tap", ("potting_shed",), "on(cup, bench)"),
    ("Lamp on the bedside table: is the bulb in the lamp on the pine nightstand broken? Replace it.",
     ("guest_room",), "on(table_lamp, nightstand)"),
]
#: near misses: (text, rooms, the place, asked or not)
KEPT = [
    ("Put the basket on the enquiry desk before you go.", ("library",), "on(basket, desk)"),
    ("Is the mug on the oak desk? If it is, wash it.", ("study",), "on(mug, desk)"),
]


@pytest.mark.parametrize(("text", "rooms", "place"), RESTING)
def test_a_thing_named_by_a_modified_place_rests_there(text: str, rooms: tuple[str, ...], place: str) -> None:
    assert place in placed(text, rooms), factors(text, rooms)
    assert not asks(text, rooms, place), factors(text, rooms)


def test_a_thing_moved_to_a_modified_place_is_not_placed_there() -> None:
    text, rooms, place = KEPT[0]
    assert place not in placed(text, rooms), factors(text, rooms)


def test_a_modified_place_asked_is_still_asked() -> None:
    text, rooms, place = KEPT[1]
    assert asks(text, rooms, place), factors(text, rooms)
