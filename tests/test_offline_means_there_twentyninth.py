"""A case put as what a thing's contents mean ("no water in it means fill it up at the sink"),
from the twenty-ninth session (dev 51's bowls club tea rota card: "Kettle - stays on the worktop.
Give it a lift: no water in it means fill it up at the sink"): "if there is no water in it, ...",
which the reader reads as the container's fullness, as the twenty-eighth session's "Empty means
fill it" is read as a state (`sentences._MEANS_THERE` beside `_MEANS_CASE`). Rows written here in
other registers before the rule and measured then: 0 of 6; after: 6 of 6. Near miss: "No kettle
on the counter means no tea" (a thing's place, no contents of "it") asks nothing of fullness."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the condition asked)
MEANS = [
    ("Kettle - no water in it means fill it at the sink.", ("tea_hut",), "state(kettle, filled)"),
    ("Bottle on the desk. No water in it means refill it at the sink.", ("office",), "state(bottle, filled)"),
    ("Vase on the windowsill - no water in it means fill it up.", ("parlour",), "state(vase, filled)"),
    ("The bucket by the door: water in it means tip it down the sink.", ("boot_room",), "state(bucket, filled)"),
    ("Watering can. Still water in it means leave it by the door, otherwise fill it at the tap.", ("porch",),
     "state(watering_can, filled)"),
    ("Mug on the bench: coffee left in it means pour it away in the sink.", ("workshop",), "state(mug, filled)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), MEANS)
def test_contents_that_mean_a_step_ask_the_fullness(text: str, rooms: tuple[str, ...], condition: str) -> None:
    got = factors(text, rooms)
    assert any({condition, f"not {condition}"} <= values for values in got.values()), got


def test_a_things_place_that_means_something_asks_no_fullness() -> None:
    got = factors("No kettle on the counter means no tea.", ("kitchen",))
    assert not any("filled" in v for values in got.values() for v in values), got
