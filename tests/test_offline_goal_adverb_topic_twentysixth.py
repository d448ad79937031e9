"""A verbless goal led by an adverb of going ("Dirty? Straight in the laundry basket. Clean, just
fold it ..."), from the twenty-sixth session (dev 43's night nanny's log). The goal's place became
the topic, so the next bare case ("Clean, ...") asked whether the laundry basket was clean. A place
opened by "straight", "right", "back", "directly" is still only the thing's goal
(`analysis._bare_place`, `analysis._GOING_LEADS`). The rows were written here in other registers
before the rule and measured then: 2 of 5; after: 5 of 5."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, a word of the thing's role, the state its cases ask)
CASES = [
    ("The tea towel hangs on the oven door. Dirty? Straight in the laundry basket. Clean, fold it and put it back "
     "on the oven door.", ("kitchen",), "towel", "dirty"),
    ("His shirt is on the chair. Wet? Right into the washing machine. Dry, back in the drawer.", ("bedroom",),
     "shirt", "wet"),
    ("The mug lives on the desk. Dirty? straight into the sink. Clean - leave it on the desk.", ("office",),
     "mug", "dirty"),
    ("Her blanket is on the high chair. Sicked on? Straight in the laundry basket. Clean, just fold it and leave it "
     "on the high chair.", ("kitchen",), "blanket", "dirty"),
    ("The cloth is on the counter. Dirty? Back in the bucket. Clean, leave it on the counter.", ("kitchen",),
     "cloth", "dirty"),
]
_GOALS = ("basket", "machine", "sink", "bucket", "drawer")


@pytest.mark.parametrize(("text", "rooms", "thing", "state"), CASES)
def test_the_case_after_a_led_goal_is_the_things(text: str, rooms: tuple[str, ...], thing: str, state: str) -> None:
    asked = factors(text, rooms)
    assert any(thing in fid and any(f", {state})" in v for v in values) for fid, values in asked.items()), asked
    assert not any(goal in fid for fid in asked for goal in _GOALS), asked
