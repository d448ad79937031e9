"""A bare "already" and a state before a comma, opening its sentence ("Already off, great.",
"Already shut, nothing to do", "already closed, leave it"), from the twenty-sixth session (dev
43's night nanny's log): the case of the thing spoken of, as "if it is already off, ..."
(`sentences._ALREADY_CASE`). The dash and question forms ("Already off - fine", "Already off?
Great") were read before. The rows were written here in other registers before the rule and
measured then: 0 of 5; after: 5 of 5."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, a word of the thing's role, the state flag asked)
CASES = [
    ("The lamp by the bed. Once she's asleep, switch it off. Already off, great.", ("bedroom",), "lamp", "toggled_on"),
    ("The kitchen cabinet. Shut it before you go. Already shut, nothing to do.", ("kitchen",), "cabinet", "open"),
    ("Close the laptop when you leave. already closed, leave it", ("office",), "laptop", "open"),
    ("Dishwasher: empty it before breakfast. Already empty, brilliant.", ("kitchen",), "dishwasher", "filled"),
    ("TV - turn it off at the wall when you go up. Already off, cheers.", ("living_room",), "television", "toggled_on"),
]


@pytest.mark.parametrize(("text", "rooms", "thing", "state"), CASES)
def test_already_and_a_state_is_a_case(text: str, rooms: tuple[str, ...], thing: str, state: str) -> None:
    asked = factors(text, rooms)
    assert any(thing in fid and any(f", {state})" in v for v in values) for fid, values in asked.items()), asked


@pytest.mark.parametrize("text", ["It's already off, great.", "Phone the office. Already done, thanks."])
def test_no_case_without_a_bare_state(text: str) -> None:
    """Near misses: a clause with its own subject, and "done", which is no state of a thing."""
    assert factors(text, ("living_room",)) == {}
