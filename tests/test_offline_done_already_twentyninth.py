"""A condition whose verb phrase is elided after a doer ("Switch it off unless someone already
has", "put the mug in the dishwasher if no one has yet"), from the twenty-ninth session (dev 49's
gin distillery e-mail: "Telly: ... Switch it off unless someone already has."): whether the
instruction's result already holds, read as "unless it already is" of the thing the instruction
acts on (`sentences._DONE_ALREADY` in `unquote`), as "unless it is already off" already was. Rows
written here in other registers before the rule and measured then: 0 of 6; after: 6 of 6; the
idiom "beat someone to it" (three rows, added later in the session): 0 of 3 -> 3 of 3. Near
misses: a doer with an object of its own ("unless someone has a key") asks nothing of the thing."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the condition asked: the instruction's result)
DONE = [
    ("Switch the telly off unless someone already has.", ("lounge",), "state(television, toggled_on)"),
    ("Ceiling fan: turn it off, unless somebody's done it already.", ("snug",), "state(ceiling_fan, toggled_on)"),
    ("Put the mug in the dishwasher if no one has yet.", ("staff_kitchen",), "inside(mug, dishwasher)"),
    ("Shut the fridge door unless someone else already did - it doesn't catch.", ("galley",), "state(fridge, open)"),
    ("Turn the oven off if somebody hasn't already.", ("bakehouse",), "state(oven, toggled_on)"),
    ("The desk lamp, pls switch it off unless anyone has already done so.", ("study",), "state(desk_lamp, toggled_on)"),
    # the idiom "beat someone to it" (dev 51's valet's notes: "if nobody's beaten you to it")
    ("Switch the telly off if nobody's beaten you to it.", ("lounge",), "state(television, toggled_on)"),
    ("Empty the bin, unless somebody's beaten you to it.", ("kitchen",), "state(trash_can, filled)"),
    ("Shut the fridge door unless someone has beaten me to it.", ("galley",), "state(fridge, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), DONE)
def test_an_elided_deed_asks_whether_its_result_holds(text: str, rooms: tuple[str, ...], condition: str) -> None:
    got = factors(text, rooms)
    assert any({condition, f"not {condition}"} <= values for values in got.values()), got


def test_a_doer_with_an_object_of_its_own_asks_nothing_of_the_thing() -> None:
    got = factors("Leave the desk lamp on unless someone has a headache.", ("study",))
    assert not any("desk_lamp" in v for values in got.values() for v in values), got
