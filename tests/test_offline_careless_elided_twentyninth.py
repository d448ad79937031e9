"""A condition with its subject and verb elided before a participle of careless leaving and a
place ("Pencil -> desk, only if dropped on the floor", "into the hamper if thrown on the floor"),
from the twenty-ninth session (dev 49's confectionery line clearance checklist): "if it is dropped
on the floor", as "if found on the floor" and "if left on the floor" already were
(`sentences._ELIDED_SUBJECT` with `CARELESS`, moved down from `placement`, before a place
preposition); and every such participle is one of a situation between a subject and its place
("if it is dumped on the sofa", `analysis.DESCRIPTIVE`), as "dropped" and "thrown" were. Rows written here in other registers before the rule and measured then: 0 of 6;
after: 6 of 6. Near misses: a careless participle with no place after it ("if dropped, ...") asks
no place; "if left open" still asks the state."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the place asked)
ELIDED = [
    ("Towels: into the laundry hamper if thrown on the floor.", ("guest_suite",), "on(towel, floor)"),
    ("Put the remote back on the TV stand if dumped on the sofa.", ("den",), "on(remote_control, sofa)"),
    ("Jacket - onto the coat hook, but only when tossed on the chair.", ("porch",), "on(jacket, chair)"),
    ("Mug to the sink if knocked onto the floor.", ("snug",), "on(mug, floor)"),
    ("Put the scissors in the drawer if dropped on the armchair.", ("craft_room",), "on(scissors, armchair)"),
    ("Keys -> key hook if chucked on the console table.", ("entrance",), "on(keys, console_table)"),
]


@pytest.mark.parametrize(("text", "rooms", "place"), ELIDED)
def test_a_careless_participle_before_a_place_asks_the_place(text: str, rooms: tuple[str, ...], place: str) -> None:
    got = factors(text, rooms)
    assert any({place, f"not {place}"} <= values for values in got.values()), got


def test_a_careless_participle_with_no_place_asks_no_place() -> None:
    got = factors("Put the vase on the shelf; if dropped, sweep up the pieces.", ("hall",))
    assert not any("on(vase" in v for values in got.values() for v in values), got


def test_left_open_still_asks_the_state() -> None:
    got = factors("Close the fridge if left open.", ("kitchen",))
    assert any("state(fridge, open)" in values for values in got.values()), got
