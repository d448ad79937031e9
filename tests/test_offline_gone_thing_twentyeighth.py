"""What a pronoun says has gone after an instruction that put a thing somewhere ("pop it in the
fridge and close the door. Gone? She's been."), from the twenty-eighth session (dev 48's
florist's order book): the pronoun's nearest referent is the fridge whose door was closed last,
but what may have gone is the thing carried about that the instruction put there
(`analysis._Reader._gone_thing`). Rows written here in other registers before the rule and
measured then: 1 of 6; after: 6 of 6. Near misses: a pronoun that points to furniture with no
such instruction before keeps its referent, and one that points to a carried thing is unchanged."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the thing whose absence is asked)
GONE = [
    ("Mrs Okafor's bouquet is on the bench. If she hasn't been by the time you shut, pop it in the fridge "
     "and close the door. Gone? She's been.", ("wrapping_room",), "flower"),
    ("Dad's phone is on the counter. If he forgets it, put it in the drawer and shut the drawer. Gone? Then "
     "he remembered.", ("kitchen",), "cell_phone"),
    ("There's a lunch box on the bench. If nobody claims it by 3, put it in the fridge and shut the door. If "
     "it's gone by then, fine.", ("staff_room",), "lunch_box"),
    ("Jo's laptop: on the desk. Not collected by 6? Lock it in the safe and close the safe door. Gone? Good.",
     ("office",), "laptop"),
    ("The spare towel is on the rail; if nobody uses it, fold it into the cabinet and shut the cabinet. Gone "
     "-> nothing to do.", ("washroom",), "spare_towel"),
    ("Umbrella by the door (a customer's). Still here at close? Stand it in the cabinet and shut the cabinet "
     "door. Gone? All good.", ("shop_floor",), "umbrella"),
]
#: near misses: (text, rooms, the thing whose absence is asked)
KEPT = [
    ("The kettle is on the counter. The old fridge was collected today; if it's gone, sweep the floor.",
     ("kitchen",), "fridge"),
    ("The mug was on the desk. If it's gone, fine; if not, wash it.", ("study",), "mug"),
]


@pytest.mark.parametrize(("text", "rooms", "thing"), GONE + KEPT)
def test_what_has_gone_is_the_thing_put_away(text: str, rooms: tuple[str, ...], thing: str) -> None:
    got = factors(text, rooms)
    assert any(f"not exists({thing})" in values for values in got.values()), got
