"""A room named in a condition's subject or beside its state, in a task of that one room ("If the
lamp in the bedroom is on", "Kettle in the kitchen still on?", "if the light is still on in the
hallway"), asks the state alone; from the twenty-fifth session. The reader turned a place in a
condition that is the task's only room into a question of presence (right for "If the lamp is in
the bedroom": being in the one room is being there at all), also where the clause asks a state of
the thing, so every such sentence planned a world without the thing (an ill-formed environment
where the thing is required). Found on the twenty-first session's written condition grid (its radio
log's "the fan in bedroom two", a letter's "the curtains in the sitting room": other losses of
those rows remain); the rows were written here in other registers (a note, a question, a radio
log, a heading's question, a house rule, a text message) before the rule and measured then (the
counts in each test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the state asked)
ROOM_PHRASES = [
    ("If the lamp in the bedroom is on, turn it off.", ("bedroom",), "state(table_lamp, toggled_on)"),
    ("Is the heater in the lounge still running? Switch it off.", ("lounge",), "state(radiator, toggled_on)"),
    ("Kettle in the kitchen still on? Then switch it off.", ("kitchen",), "state(kettle, toggled_on)"),
    ("If the light is still on in the hallway, switch it off.", ("hallway",), "state(ceiling_lamp, toggled_on)"),
    ("When the tv in the den is on after ten, turn it off.", ("den",), "state(television, toggled_on)"),
    ("if the towel in the bathroom is wet hang it on the rail", ("bathroom",), "state(towel, wet)"),
]


@pytest.mark.parametrize(("text", "rooms", "state"), ROOM_PHRASES)
def test_a_room_phrase_beside_a_state_asks_the_state_alone(text: str, rooms: tuple[str, ...], state: str) -> None:
    """Measured before the rule: 0 of 7 (with the radio log's row below); after: 6 of 7."""
    asked = factors(text, rooms)
    assert any({state, f"not {state}"} <= v for v in asked.values()), asked
    assert not any("exists(" in " ".join(v) for v in asked.values()), asked


@pytest.mark.xfail(strict=True, reason="a radio log's time opening the sentence ('2226 Should ...') hides the inverted condition")
def test_a_radio_logs_inverted_condition() -> None:
    asked = factors("2226 Should the fan in the bedroom be on, switch it off. Over.", ("bedroom",))
    assert any("state(ceiling_fan, toggled_on)" in v for v in asked.values()), asked


@pytest.mark.parametrize(("text", "rooms", "thing"), [
    # a place asked with no state: whether the thing is there at all
    ("If the lamp is in the bedroom, turn it off.", ("bedroom",), "table_lamp"),
    ("If the mug is not in the kitchen, look for it.", ("kitchen",), "mug"),
    ("If my phone is in the bedroom, bring it to me.", ("bedroom",), "cell_phone"),
])
def test_a_room_asked_alone_still_asks_presence(text: str, rooms: tuple[str, ...], thing: str) -> None:
    """Near misses, asked so before and after the rule."""
    assert any(f"exists({thing})" in v for v in factors(text, rooms).values())
