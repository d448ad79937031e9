"""A request with no verb ("Mugs on the shelf please", "Cups in the dishwasher pls, not in the
sink", "Please: coats on the hooks") says where things go, not where they are: its place is a goal,
not a factor (`analysis._verbless_request`, `_PLEA`: a plea closing the piece, with at most thanks or
a place it must not go after it, or opening it). A state its noun phrase names ("Wet towels in the
basket please") still picks the things the request is for. From the thirty-first session (a youth
hostel's handover note in development set 55: "boots on the racks by the boiler please, not on the
pipes" asked whether the boots were on the racks). Rows written here in other registers before the
rule and measured then: 2 of 6; after: 6 of 6. Near misses: a question ("Towel on the floor? Please
hang it up"), a plea opening an instruction of its own ("Plates on the table please clear them
away") and a verbless line without a plea ("Mugs in the sink.") still ask."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the place that must not be asked)
REQUESTS = [
    ("Wet towels in the laundry basket please.", ("bathroom",), "inside(towel, laundry_basket)"),
    ("Cups in the dishwasher please, not in the sink.", ("kitchen",), "inside(cup, dishwasher)"),
    ("Mugs on the shelf please.", ("staff_room",), "on(mug, wall_shelf)"),
    ("Dirty plates in the sink please and thank you.", ("kitchen",), "inside(plate, sink)"),
    ("Library books on the cart please!", ("library",), "on(book, cart)"),
    ("Please: coats on the hooks.", ("hall",), "on(coat, coat_hook)"),
]

#: (text, rooms, the place still asked)
NEAR = [
    ("Towel on the floor? Please hang it up.", ("bathroom",), "on(towel, floor)"),
    ("Plates on the table please clear them away.", ("dining_room",), "on(plate, dining_table)"),
    ("Mugs in the sink.", ("kitchen",), "inside(mug, sink)"),
]


@pytest.mark.parametrize(("text", "rooms", "place"), REQUESTS)
def test_a_verbless_request_asks_no_place(text: str, rooms: tuple[str, ...], place: str) -> None:
    assert place not in set().union(*factors(text, rooms).values())


@pytest.mark.parametrize(("text", "rooms", "place"), NEAR)
def test_a_question_or_an_instruction_still_asks(text: str, rooms: tuple[str, ...], place: str) -> None:
    assert place in set().union(*factors(text, rooms).values())


def test_a_state_named_in_a_request_still_picks_the_things() -> None:
    assert "state(towel, wet)" in set().union(*factors("Wet towels in the laundry basket please.", ("bathroom",)).values())
