"""A control's head said as a verb ("If the light is on, switch it off"), from the twenty-third
session: the naming took "the light" for the light switch whenever its sentence or the next said
"switch", the verb included, so the light itself was never named and its state never asked
(`naming._Reader.controls_ahead`). Only the head as a noun (after the thing's word, "the light
switch", or after a determiner, "the switch", "the main switch") makes the thing the control. The
table was written here in several registers (a text message, a notice, a landlord's note, a
checklist, learner English, a formal letter), with near misses where the switch is a noun; it was
measured before the rule (the counts in each test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors, kinds

LAMPS = {"ceiling_lamp", "desk_lamp", "table_lamp", "floor_lamp"}

#: (text, rooms): "switch" a verb; the light is a lamp, never the switch
VERB = [
    # a note
    ("If the light is on, switch it off.", ("bedroom",)),
    ("The light in the hall is on. Switch it off before you go to bed.", ("living_room",)),
    # a text message
    ("if the hall light's still on pls switch it off", ("living_room",)),
    ("light on in the study? switch it off x", ("study",)),
    # a formal notice
    ("Should the light be on when you leave, kindly switch it off.", ("office",)),
    # a checklist
    ("- Bedroom light on? Switch it off.", ("bedroom",)),
    # learner English
    ("If the porch light is burning please switch off.", ("living_room",)),
    ("When you are going out, if the light is on, you switch it off.", ("bedroom",)),
    # a landlord's note, plural
    ("If the lights are on in the lounge, switch them off before bed.", ("living_room",)),
    # a time clause before the condition
    ("When you leave, if the night light is on, switch it off.", ("bedroom",)),
]


@pytest.mark.parametrize(("text", "rooms"), VERB)
def test_a_switch_said_as_a_verb_names_no_switch(text: str, rooms: tuple[str, ...]) -> None:
    """Measured before the rule: 0 of 10 named a lamp and no light switch; after: 10 of 10."""
    named = kinds(text, rooms)
    assert "light_switch" not in named and named & LAMPS, (named, factors(text, rooms))


@pytest.mark.parametrize(("text", "rooms"), [
    ("If the lights are still on, flick the light switch off.", ("living_room",)),
    ("And the light - is it on? Then flick off the switch.", ("bedroom",)),
    ("If the light is on, press the switch by the door.", ("hallway",)),
    ("The light is on. Hit the main switch on your way out.", ("garage",)),
])
def test_a_switch_said_as_a_noun_is_the_control(text: str, rooms: tuple[str, ...]) -> None:
    """Near misses: the switch as a noun (after the thing's word or a determiner) is the control
    the text works the light by, as before (4 of 4 before the rule and after)."""
    assert "light_switch" in kinds(text, rooms), factors(text, rooms)
