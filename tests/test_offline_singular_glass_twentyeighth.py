"""A singular "glass" after spectacles were named ("Glasses: everyone's water glass ends up on the
coffee table. Dirty glass - in the sink."), from the twenty-eighth session (dev 47's ambulance
station day-room card): the plurale tantum "glasses" (spectacles) is never meant by a singular
"glass", so a later "glass" is a drinking glass of its own, not the spectacles named before
(`naming._Reader.bare_noun`, `_plural_kind_name`), as it already was when no spectacles came first.
Rows written here in other registers before the rule and measured then: 0 of 6; after: 6 of 6.
Near miss: "they", the spectacles, is still the spectacles."""

from __future__ import annotations

import pytest
from reading import factors, named

#: (text, rooms, the drinking glass's state asked, or None: only that one is named)
GLASS = [
    ("My glasses are on the nightstand. If the glass on the desk is dirty, take it to the sink.", ("bedroom",),
     "state(drinking_glass, dirty)"),
    ("Reading glasses on the bedside table. A glass is by the sink; if it's dirty, wash it.", ("annexe",),
     "state(drinking_glass, dirty)"),
    ("Glasses - a glass left on the bar goes in the dishwasher if it's dirty.", ("function_room",),
     "state(drinking_glass, dirty)"),
    ("My glasses are on the desk and my glass of water is on the nightstand.", ("guest_room",), None),
    ("GLASSES. One glass per guest on the table. Dirty glass? Into the sink.", ("dining_hall",),
     "state(drinking_glass, dirty)"),
    ("Dad's glasses: on the armchair. Dad's glass: on the side table, if it's empty fill it.", ("sitting_room",),
     "state(drinking_glass, filled)"),
]


@pytest.mark.parametrize(("text", "rooms", "state"), GLASS)
def test_a_singular_glass_is_a_drinking_glass(text: str, rooms: tuple[str, ...], state: str | None) -> None:
    assert "drinking_glass" in {category for category, _ in named(text, rooms).values()}, named(text, rooms)
    got = factors(text, rooms)
    assert state is None or any({state, f"not {state}"} <= values for values in got.values()), got


def test_they_the_spectacles_are_still_the_spectacles() -> None:
    text = "My glasses are on the nightstand. If they are dirty, clean them with the cloth."
    assert any({"state(glasses, dirty)", "not state(glasses, dirty)"} <= v for v in factors(text, ("bedroom",)).values())
