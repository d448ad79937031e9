"""A condition that whoever should have done the deed forgot it, the deed elided ("switch it off if
I forgot to", "in case we forgot", "if the kids forgot - they usually do"), from the thirtieth
session (dev 47's coastwatch log: "Switch it off if we forgot, leave it off if we didn't"):
whether the instruction's result is still to come about, as "unless it already is" asks
(`sentences._FORGOT`, beside `_DONE_ALREADY`). Rows written here in other registers before the rule
and measured then: 0 of 6; after: 6 of 6. Near misses: a forgetting with an object of its own
("if you forgot the keys", "if I forgot anything") asks nothing."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the state asked)
FORGOTTEN = [
    ("The desk lamp: switch it off if I forgot to.", ("study",), "state(desk_lamp, toggled_on)"),
    ("Switch the kettle off if we forgot, leave it if we didn't.", ("kitchen",), "state(kettle, toggled_on)"),
    ("Close the fridge if the kids forgot to.", ("kitchen",), "state(fridge, open)"),
    ("Turn the television off in case I forgot.", ("lounge",), "state(television, toggled_on)"),
    ("Shut the wardrobe doors if Sam forgot - he usually does.", ("bedroom",), "state(wardrobe, open)"),
    ("The ceiling fan. Turn it off if the last group forgot to, otherwise leave it.", ("hall",),
     "state(ceiling_fan, toggled_on)"),
]


@pytest.mark.parametrize(("text", "rooms", "state"), FORGOTTEN)
def test_a_forgotten_deed_asks_the_result(text: str, rooms: tuple[str, ...], state: str) -> None:
    assert any(state in values for values in factors(text, rooms).values())


@pytest.mark.parametrize("text", ["If you forgot the keys, ring me.", "If I forgot anything, text me."])
def test_a_forgetting_with_an_object_asks_nothing(text: str) -> None:
    assert factors(text, ("hall",)) == {}
