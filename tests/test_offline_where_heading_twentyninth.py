"""A heading that is a free relative ("Where things are: in the kitchen - the rubbish bin, the
recycling bin and the fridge"), from the twenty-ninth session (dev 50's good neighbours visit
card): a line opened by "where" whose verb ends it at a colon or a dash names a topic and asks
nothing, so it is dropped and the list after it places its things; a clause-opening "where" with a
predicate after its verb is still "if" (`sentences._WHERE_HEADING` in `unquote`). Rows written
here in other registers before the rule and measured then: 1 of 6 (the dash); after: 6 of 6. Near miss: "Where the bin is full, empty it, ..." still
asks whether the bin is full."""

from __future__ import annotations

import pytest
from reading import factors, placed

#: (text, rooms, a placement the list states)
HEADINGS = [
    ("Where things are: in the kitchen - the kettle, the toaster and the fridge.", ("kitchen", "hall"),
     "in_room(toaster, kitchen)"),
    ("Where everything lives: in the study - the desk, the lamp and the bookshelf.", ("study", "landing"),
     "in_room(bookshelf, study)"),
    ("Where stuff is: in the bathroom, the towel rail, the laundry basket and the mirror.", ("bathroom", "bedroom"),
     "in_room(laundry_basket, bathroom)"),
    ("Where the bins are: in the utility room, the trash can and the recycling bin.", ("utility_room", "kitchen"),
     "in_room(recycling_bin, utility_room)"),
    ("Where it all is - in the lounge: the sofa, the armchair and the TV.", ("lounge", "kitchen"),
     "in_room(armchair, lounge)"),
    ("Where the furniture is: in the bedroom, the bed, the wardrobe and the dresser.", ("bedroom", "landing"),
     "in_room(wardrobe, bedroom)"),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), HEADINGS)
def test_a_free_relative_heading_asks_nothing(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms), (placed(text, rooms), factors(text, rooms))
    assert not factors(text, rooms), factors(text, rooms)


def test_where_with_a_predicate_is_still_a_condition() -> None:
    got = factors("Where the bin is full, empty it, then wash your hands.", ("kitchen",))
    assert any("state(trash_can, filled)" in values for values in got.values()), got
