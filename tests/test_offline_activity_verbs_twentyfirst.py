"""A thing's steady activity as a condition's finite verb, read since the twenty-first session
(docs/reader.md, "Places as headings, ticked lists and a thing's activity (twenty-first
session)", and "What it still misreads": "if the lamp still shines" asked nothing). "hum",
"shine" and "whistle" join `sentences.SOUNDS` (their forms by the lemmatiser) and their "-ing"
forms `analysis.OPERATION_WORDS`, so the state is read only of a thing that switches on. The
table was written here in several registers (house rules, a text message, a caretaker's notice, a
learner's note, a night-shift checklist, verse) and measured on main before the rule: 3 of 20
asked, after 11 of 20 (the nine left, `ACTIVITY_LEFT`, are read no better with "is on" in the
verb's place); the near misses held before and after."""

from __future__ import annotations

import pytest
from reading import asks, factors

#: (text, rooms, the condition asked)
ACTIVITY = [
    # house rules
    ("If the ceiling fan still hums, switch it off.", ("living_room",), "state(ceiling_fan, toggled_on)"),
    ("If the lamp still shines, switch it off.", ("bedroom",), "state(table_lamp, toggled_on)"),
    ("If the kettle whistles, switch it off.", ("kitchen",), "state(kettle, toggled_on)"),
    ("When the kettle is whistling, switch it off and pour the water.", ("kitchen",), "state(kettle, toggled_on)"),
    # a text message
    ("if the tv still hums turn it off at the wall pls", ("living_room",), "state(television, toggled_on)"),
    # a learner's note
    ("If the lamp already not shines, is OK. If it shines, you switch off.", ("bedroom",),
     "state(table_lamp, toggled_on)"),
    ("When the kettle whistle, please you switch it off.", ("kitchen",), "state(kettle, toggled_on)"),
    # a night-shift checklist
    ("Desktop computer - if it still hums, shut it down.", ("office",), "state(desktop_computer, toggled_on)"),
    ("Table lamp: if it is still shining, off.", ("living_room",), "state(table_lamp, toggled_on)"),
    ("Kettle: unless it whistles, leave it.", ("kitchen",), "state(kettle, toggled_on)"),
    ("If the television is humming, switch it off at the plug.", ("living_room",), "state(television, toggled_on)"),
]

#: left: read no better with "is on" or "is humming" in the verb's place (a word of operation is
#: read only at its clause's end; a comma-less condition; "should" before the verb; a report)
ACTIVITY_LEFT = [
    # house rules, a text message, a caretaker's notice, a learner's note, verse
    ("If the desk lamp is still shining when you leave, turn it off.", ("office",), "state(desk_lamp, toggled_on)"),
    ("if the floor lamp still shines just switch it off x", ("living_room",), "state(floor_lamp, toggled_on)"),
    ("if it whistles its done, switch the kettle off", ("kitchen",), "state(kettle, toggled_on)"),
    ("Should the laptop still hum at the end of the day, it is to be shut down.", ("office",),
     "state(laptop, toggled_on)"),
    ("If the ceiling light no longer shines, report it.", ("hallway",), "state(ceiling_lamp, toggled_on)"),
    ("If the fridge hums loudly, leave it alone.", ("kitchen",), "state(fridge, toggled_on)"),
    ("If the fan is humming still, please to stop it.", ("bedroom",), "state(ceiling_fan, toggled_on)"),
    ("And if the lamp still shines at night,\nthen switch it off and close it tight.", ("bedroom",),
     "state(table_lamp, toggled_on)"),
    ("If the ceiling fan hums above the bed, switch it off.", ("bedroom",), "state(ceiling_fan, toggled_on)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), ACTIVITY)
def test_a_things_activity_asks_whether_it_is_going(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition), factors(text, rooms)


#: near misses: a thing that cannot be switched on (its shine is its cleanness), a person's or the
#: sun's activity, an imperative, a particle after the verb, "until": (text, rooms, a condition
#: that must not be asked)
NEAR_MISSES = [
    ("If the floor is shining, leave it.", ("kitchen",), "state(floor, toggled_on)"),
    ("If the mirror still shines, leave it.", ("bathroom",), "state(mirror, toggled_on)"),
    ("If the sun shines, open the curtains.", ("bedroom",), "state(curtains, toggled_on)"),
    ("Shine the torch under the bed and look for the sock.", ("bedroom",), "state(flashlight, toggled_on)"),
    ("Polish the mug until it shines, then put it away.", ("kitchen",), "state(mug, toggled_on)"),
    ("If the kids hum along, turn the radio up.", ("living_room",), "state(radio, toggled_on)"),
    ("If the plate shines up nicely, put it on the shelf.", ("kitchen",), "state(plate, toggled_on)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), ACTIVITY_LEFT)
def test_activity_left(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert not asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), NEAR_MISSES)
def test_no_going_state_where_nothing_switches_on(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert not asks(text, rooms, condition)
