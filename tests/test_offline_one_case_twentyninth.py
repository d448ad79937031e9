"""A verbless case opened by "one" and a place, then a comma and an instruction ("Skull
caps - the lads drop them all over. One on the floor, you pick it up and it goes up on the shelf"),
from the twenty-ninth session (dev 51's valet's notes): "if there is one on the floor, ...", as
the same words asked with a question mark already were (`sentences._ONE_CASE` in `unquote`; the
instruction after the comma is told by "you" or a verb with "it"/"them"). Rows written here in
other registers before the rule and measured then: 0 of 6; after: 6 of 6. Near miss: an inventory
("One on the floor, two on the shelf") instructs nothing and asks nothing."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the place asked)
ONE = [
    ("Mugs get left everywhere. One on the desk, you take it to the sink.", ("office",), "on(mug, desk)"),
    ("Socks: one on the floor, pop it in the laundry basket.", ("nursery",), "on(sock, floor)"),
    ("The kids' cups. One on the table, you wash it in the sink.", ("playroom",), "on(cup, dining_table)"),
    ("Books. One on the sofa, put it back on the bookshelf.", ("snug",), "on(book, sofa)"),
    ("Towels - one in the sink, hang it on the towel rail.", ("washroom",), "inside(towel, sink)"),
    ("Hats get dropped all over. One on the bench, you hang it on the coat hook.", ("locker_room",),
     "on(hat, bench)"),
]


@pytest.mark.parametrize(("text", "rooms", "place"), ONE)
def test_one_and_a_place_before_an_instruction_ask_the_place(text: str, rooms: tuple[str, ...], place: str) -> None:
    got = factors(text, rooms)
    assert any({place, f"not {place}"} <= values for values in got.values()), got


def test_an_inventory_asks_nothing() -> None:
    got = factors("Cushions: one on the floor, two on the sofa.", ("lounge",))
    assert not got, got
