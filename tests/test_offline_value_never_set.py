"""Values a task's trees ask that the offline reader never set (`--losses`: "a value never set"),
from the built-in tasks that lost paths in the eleventh session and their rewordings: a state said
of a thing's part. Each rule is tried on sentences written here, in at least two texts of other
registers and rooms, and on near misses it must not misread."""

from __future__ import annotations

import pytest
from reading import asks as _asks
from reading import factors as _factors


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # an instruction with a trailing "unless", a possessive pronoun
    ("The reading lamp should be on; if it's off, switch it on, unless its bulb is broken - then "
     "light a candle instead.", ("study",), "state(desk_lamp, broken)"),
    # a workshop note, the thing named by a genitive, a part in the plural, a perfect tense
    ("Torch goes back in the drawer. If the torch's batteries have blown, leave it on the bench.",
     ("garage",), "state(flashlight, broken)"),
    # a terse checklist, "cracked" said of a part
    ("Check the flashlight: lens cracked? Then put it in the bin.", ("garage",), "state(flashlight, broken)"),
])
def test_a_state_of_a_part_is_its_things(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """A part whose failure is its thing's (`analysis.PARTS`: "bulb", "battery", "wick", "lens"):
    "unless its bulb is broken" asks whether the lamp is broken."""
    assert _asks(text, rooms, condition), _factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms"), [
    # a spare bulb is a thing of its own, not a part of anything
    ("We might have a new light bulb lying around; put it in the drawer.", ("garage",)),
    # batteries named as things to put away: no state is asked
    ("Put the torch in the drawer and the batteries on the shelf.", ("garage",)),
])
def test_a_part_named_as_a_thing_asks_no_broken_state(text: str, rooms: tuple[str, ...]) -> None:
    assert not any("broken" in c for values in _factors(text, rooms).values() for c in values)
