"""Values a development task's trees ask that the offline reader never set (`--losses`: "a value
never set"), from the twenty-first session. Each form is a table of sentences written here, in
several registers (text messages, notices, checklists, transcripts, learner English, a method),
rooms and kinds, with near misses that must stay as they are; the tables were measured before each
rule (the counts in each test's docstring).

- a clause of result after its reason ("We need light at the desk, so the desk lamp should be on.
  If it's off, ..."): a pronoun after it means the result's subject, not the reason's first thing."""

from __future__ import annotations

import pytest
from reading import asks, factors

#: a reason, then "so" / "therefore" / "hence" and a result whose subject is a thing, then a
#: condition with a pronoun: (text, rooms, the condition asked of the result's subject). Before the
#: rule 11 of 22 were asked (those whose state only the result's subject can take)
RESULT_CLAUSES = [
    # text messages
    ("the kids are in the bathtub, so the towel should be dry. if it's wet, hang it on the rail.", ("bathroom",),
     "state(towel, wet)"),
    ("grandma sleeps on the sofa tonight, so the blanket has to be clean. if it's dirty, put it in the laundry basket.",
     ("living_room",), "state(blanket, dirty)"),
    ("the desk is where I work, so the desk lamp should be on. if it's off, switch it on.", ("study",),
     "state(desk_lamp, toggled_on)"),
    ("the cat hides under the bed so the wardrobe should be shut. if it's open, close it", ("bedroom",),
     "state(wardrobe, open)"),
    # a residents' notice
    ("The counter is used for food preparation, so the kettle must be switched off after use. If it is on, switch it "
     "off.", ("kitchen",), "state(kettle, toggled_on)"),
    ("The sink is shared by all residents, so the mug should not be left dirty. If it is dirty, wash it.", ("kitchen",),
     "state(mug, dirty)"),
    ("Residents relax on the sofa in the evening, so the television should be off by ten. If it is on, switch it off.",
     ("living_room",), "state(television, toggled_on)"),
    ("The bookshelf stands by the window, so the curtain must be closed at night. If it is open, close it.",
     ("bedroom",), "state(curtain, open)"),
    ("Guests use the shower, so the toilet must be clean. If it is dirty, clean it.", ("bathroom",),
     "state(toilet, dirty)"),
    # formal: "therefore", "hence"
    ("The stove remains in use; therefore the pot must be clean. If it is dirty, wash it.", ("kitchen",),
     "state(pot, dirty)"),
    ("The bathtub is being cleaned, hence the towel should be dry. If it is wet, hang it up.", ("bathroom",),
     "state(towel, wet)"),
    # a checklist or briefing, verbless reasons
    ("Bed made up for guests, so the pillow must be clean. If it is dirty, put it in the hamper.", ("bedroom",),
     "state(pillow, dirty)"),
    ("- Sofa for movie night, so the remote must be on the coffee table. If it's on the floor, put it back.",
     ("living_room",), "on(remote_control, floor)"),
    ("The fridge is being defrosted, so the bottle should be empty. If it's full, pour it into the sink.",
     ("kitchen",), "state(bottle, filled)"),
    ("The microwave is out of order, so the kettle will be needed. If it is empty, fill it at the sink.",
     ("kitchen",), "state(kettle, filled)"),
    # learner English
    ("My mother will sit on the armchair, so the cushion must be clean. If it is dirty, please wash it.",
     ("living_room",), "state(sofa_pillow, dirty)"),
    ("Baby sleep in the crib, so the lamp must be off. If it is on, you switch off.", ("nursery",),
     "state(desk_lamp, toggled_on)"),
    # transcripts
    ("DAD: We're eating at the dining table, so the plate should be clean. If it's dirty, put it in the sink.",
     ("dining_room",), "state(plate, dirty)"),
    ("ME: The printer is by the window, so the laptop needs to be closed. If it's open, close it.", ("office",),
     "state(laptop, open)"),
    # a method (a recipe's or a gardener's)
    ("The oven is preheating, so the pan must be clean. If it is dirty, wash it in the sink.", ("kitchen",),
     "state(pan, dirty)"),
    ("The bench is in the sun, so the watering can should be full. If it's empty, fill it at the sink.", ("garden",),
     "state(watering_can, filled)"),
    # a dance sheet (dev 36 study_plant_and_light_d36's form, another room and lamp)
    ("We need light at the desk, so the floor lamp should be on. If it's off, switch it on.", ("living_room",),
     "state(floor_lamp, toggled_on)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), RESULT_CLAUSES)
def test_a_pronoun_after_a_result_means_its_subject(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """dev 36 study_plant_and_light_d36 "We need light at the desk, so the desk lamp should be on.
    If it's off, switch it on - unless its bulb is broken" took "it" and "its bulb" for the ceiling
    lamp ("light" is its synonym's head and the sentence's first thing), so the desk lamp's state
    and bulb were never asked (`analysis._result_subject`). Measured before the rule: 11 of 22;
    after: 22 of 22."""
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # "so" of degree: no result clause
    ("The kettle is so dirty. If it's full, empty it into the sink.", ("kitchen",), "state(kettle, filled)"),
    # "so" before an instruction: its thing is the statement's
    ("The mug is on the desk, so bring it to the sink if it's dirty.", ("office",), "state(mug, dirty)"),
    ("The towel is on the floor, so pick it up. If it's wet, hang it on the rail.", ("bathroom",),
     "state(towel, wet)"),
    # "so" before a condition
    ("The blanket is on the sofa, so if it's wet, hang it on the rail.", ("living_room",), "state(blanket, wet)"),
    # an inversion: "and so is the mug"
    ("The laptop is on the desk and so is the mug. If it's open, close it.", ("office",), "state(laptop, open)"),
    # a result whose subject is no thing of the task
    ("Put the pillow on the bed, so the room looks tidy. If it's dirty, put it in the hamper.", ("bedroom",),
     "state(pillow, dirty)"),
    ("The kettle is in the sink, so the water is running. If it's full, switch it on.", ("kitchen",),
     "state(kettle, filled)"),
])
def test_so_opening_no_result_clause_keeps_the_first_thing(text: str, rooms: tuple[str, ...],
                                                           condition: str) -> None:
    """Near misses: "so" of degree, before an instruction or a condition, in an inversion, or
    before a subject that names no thing leaves the pronoun to the sentence's first thing (7 of 7
    before the rule and after)."""
    assert asks(text, rooms, condition), factors(text, rooms)

