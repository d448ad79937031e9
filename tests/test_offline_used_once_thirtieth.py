"""That a thing was used for something or by someone, told of one occasion ("if it was used by a
guest", "if the cup has been used for coffee", "if the glass was used for wine at dinner"), says
it is dirty, as "if it's been used" did (`analysis._Reader._used_once`); "is used for wiping" is
still what the thing is for, and says nothing of its state. From the thirtieth session (dev 50's
verger's notes, "Used for communion? Then it wants a rinse"). Rows written here in other
registers before the rule and measured then: 0 of 6; after: 3 of 6 (the three left are verbless
questions whose complement names a food, "Used for tea?", "used for the cheese?": the reader
takes no subject for them, as it takes none for "Tea?" either). Near misses: "is used for
wiping", "is used for the dog's water" (what a thing is for) ask nothing of dirt."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the state asked)
USED_ONCE = [
    ("If the towel was used by a guest, put it in the hamper.", ("bathroom",), "state(towel, dirty)"),
    ("If the cup has been used for coffee, wash it.", ("kitchen",), "state(cup, dirty)"),
    ("If the glass was used for wine at dinner, put it in the dishwasher.", ("dining_room",),
     "state(drinking_glass, dirty)"),
]


@pytest.mark.parametrize(("text", "rooms", "state"), USED_ONCE)
def test_a_use_on_one_occasion_asks_dirty(text: str, rooms: tuple[str, ...], state: str) -> None:
    assert any(state in values for values in factors(text, rooms).values())


@pytest.mark.parametrize("text", ["The cloth is used for wiping the bench; put it on the rail.",
                                  "This bowl is used for the dog's water; fill it if it is empty."])
def test_what_a_thing_is_used_for_asks_nothing_of_dirt(text: str) -> None:
    assert not any("dirty" in v for values in factors(text, ("kitchen",)).values() for v in values)


@pytest.mark.xfail(reason="a verbless question whose complement names a food takes no subject", strict=True)
@pytest.mark.parametrize(("text", "rooms", "state"), [
    ("The mug is on the desk. Used for tea? Wash it at the sink.", ("office",), "state(mug, dirty)"),
    ("The knife - used for the cheese? Wipe it clean.", ("pantry",), "state(knife, dirty)"),
])
def test_a_verbless_use_question_with_a_food(text: str, rooms: tuple[str, ...], state: str) -> None:
    assert any(state in values for values in factors(text, rooms).values())
