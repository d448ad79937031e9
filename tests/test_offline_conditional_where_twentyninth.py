""""Where" as a condition of presence after "only", a bracket or a comma ("UMBRELLA (only where
one is present)", "Kettle, where there is one: ..."), from the twenty-ninth session (dev 49's
chilled desserts hygiene lobby procedure): a procedure's "where" of a case (Oxford, "where": "in
or to a situation in which") asks whether the thing is there, as "if there is one" does; a
sentence's opening "Where" already did (`sentences._CASE_WHERE` in `unquote`). Rows written here
in other registers before the rule and measured then: 0 of 6; after: 6 of 6. Near miss: "where"
of a place a thing is put ("put the umbrella where there is room") asks nothing."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the thing whose presence is asked)
WHERE = [
    ("Hand towel (only where one is present): if damp, hang it on the towel rail.", ("cloakroom",), "hand_towel"),
    ("Kettle, where there is one: switch it off if it's on.", ("bedsit",), "kettle"),
    ("Spare blanket - only where there is one - fold it onto the bed.", ("bunk_room",), "spare_blanket"),
    ("Laptop (only where one is present in the room): if on, shut it down.", ("study",), "laptop"),
    ("Desk lamp, only where there is one. Switch it off if it's on.", ("reading_room",), "desk_lamp"),
    ("UMBRELLA (where one is present)\n- Wet: stand it in the umbrella stand.\n- Dry: on the console table.",
     ("vestibule",), "umbrella"),
]


@pytest.mark.parametrize(("text", "rooms", "thing"), WHERE)
def test_where_of_a_case_asks_whether_the_thing_is_there(text: str, rooms: tuple[str, ...], thing: str) -> None:
    got = factors(text, rooms)
    assert any({f"exists({thing})", f"not exists({thing})"} <= values for values in got.values()), got


def test_where_of_a_place_asks_nothing() -> None:
    got = factors("Put the umbrella where there is room.", ("hallway",))
    assert not any("exists(umbrella)" in values for values in got.values()), got
