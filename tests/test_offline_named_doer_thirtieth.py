"""A deed elided after a doer named by a name or a noun phrase ("switch it off - unless Lee from
the cafe has beaten you to it", "unless the night porter has done it already"), from the thirtieth
session (dev 51's ice rink close-down card): whether the instruction's result holds already, as
"unless someone already has" was read in the twenty-ninth (`sentences._NAMED_DOER` in
`_DONE_ALREADY`). Only with the deed said ("done it", "done so", "beaten you to it"): "unless Lee
has a key" has an object of its own. Rows written here in other registers before the rule and
measured then: 0 of 6; after: 6 of 6. Near misses: a named doer with an object of its own asks
nothing; the one told ("if you haven't done it already") still asks nothing."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the state asked)
NAMED_DOERS = [
    ("Switch the kettle off unless Priya has beaten you to it.", ("kitchen",), "state(kettle, toggled_on)"),
    ("Close the wardrobe unless the night porter has done it already.", ("guest_room",), "state(wardrobe, open)"),
    ("Shut the fridge unless Marco from the bar has done so.", ("kitchen",), "state(fridge, open)"),
    ("The television: turn it off - unless Mrs Okafor's done it, she often does.", ("staff_room",),
     "state(television, toggled_on)"),
    ("Close the curtains unless one of the cleaners has beaten you to it.", ("bedroom",), "state(curtain, open)"),
    ("Do the end-of-day report, then switch the computer off, unless Dev on the late shift has done that "
     "already.", ("office",), "state(laptop, toggled_on)"),
]


@pytest.mark.parametrize(("text", "rooms", "state"), NAMED_DOERS)
def test_a_deed_elided_after_a_named_doer_asks_the_result(text: str, rooms: tuple[str, ...], state: str) -> None:
    got = factors(text, rooms)
    assert any(state in values for values in got.values()), got


@pytest.mark.parametrize("text", ["Unless Lee has a key, leave the door shut.",
                                  "Turn the lamp off if you haven't done it already."])
def test_a_doer_with_an_object_or_the_one_told_asks_nothing(text: str) -> None:
    assert factors(text, ("hall",)) == {}
