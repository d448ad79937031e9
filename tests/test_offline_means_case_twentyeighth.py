"""A case put as what a state means ("still burning means it gets blown out", "Empty means fill it
at the sink"), from the twenty-eighth session (dev 48's bridal showroom handbook; the form is in
seven texts of five sets, mostly for the case that needs nothing: "Already off means no problem"):
a state word opening a clause, then "means", is "if it is <state>, ..." of the thing just spoken
of (`sentences._MEANS_CASE`). Rows written here in other registers before the rule and measured
then: 0 of 6; after: 5 of 6 (the sixth names a window, no catalog kind: xfail). Near misses: "means" after a noun phrase or in a definition asks
nothing new."""

from __future__ import annotations

import pytest
from reading import asks, factors

#: (text, rooms, the state asked)
MEANS = [
    ("The candle stands on the side table. Check it: still burning means it gets blown out.", ("showroom",),
     "state(candle, toggled_on)"),
    ("The desk lamp: still on means switch it off at the wall.", ("study",), "state(desk_lamp, toggled_on)"),
    ("Kettle. Empty means fill it at the sink, full means leave it.", ("galley",), "state(kettle, filled)"),
    pytest.param("The window - open means close it before you lock up.", ("back_office",), "state(window, open)",
                 marks=pytest.mark.xfail(reason="no catalog kind names a window (\"if the window is open\" asks "
                                                "nothing either)", strict=True)),
    ("Bath towel on the rail. Wet means it goes in the laundry basket; dry means leave it.", ("bathroom",),
     "state(towel, wet)"),
    ("Check the pet bowl - empty means top it up from the tap.", ("utility_room",), "state(pet_bowl, filled)"),
]
#: near misses: (text, rooms)
NOTHING = [
    ("Green means go, red means stop.", ("garage",)),
    ("In this note \"tidy\" means everything put away.", ("bedroom",)),
]


@pytest.mark.parametrize(("text", "rooms", "state"), MEANS)
def test_a_state_that_means_a_step_is_a_case(text: str, rooms: tuple[str, ...], state: str) -> None:
    assert asks(text, rooms, state), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms"), NOTHING)
def test_means_of_no_state_asks_nothing(text: str, rooms: tuple[str, ...]) -> None:
    assert factors(text, rooms) == {}
