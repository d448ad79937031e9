"""Values a development task's trees ask that the offline reader never set (`--losses`: "a value
never set"), from the twenty-first session. Each form is a table of sentences written here, in
several registers (text messages, notices, checklists, transcripts, learner English, a method),
rooms and kinds, with near misses that must stay as they are; the tables were measured before each
rule (the counts in each test's docstring).

- a clause of result after its reason ("We need light at the desk, so the desk lamp should be on.
  If it's off, ..."): a pronoun after it means the result's subject, not the reason's first thing;
- a condition or a question whose predicate is a room ("If the book is in the bedroom, bring it to
  the sofa", "Book in the bedroom? If so, ..."): the placement reader took the room as stated, so
  the factor the condition asks was settled and dropped;
- an alternative condition set off by dashes or a bracket, or closed by a colon or an arrow ("If
  it is anywhere else - or we have none at all - leave it"): read as with commas, its pronoun
  the subject of the condition before "or"."""

from __future__ import annotations

import pytest
from reading import asks, factors, placed

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


#: a condition, or a question without a verb before its thing, whose predicate is a room: (text,
#: rooms, the placement asked). Before the rule 1 of 22 were asked (the "Is ... ?" question)
ROOM_CONDITIONS = [
    # a note on the fridge
    ("If the book is in the bedroom, bring it to the sofa.", ("living_room", "bedroom"), "in_room(book, bedroom)"),
    ("If the kettle is still in the kitchen, bring it to the dining table.", ("dining_room", "kitchen"),
     "in_room(kettle, kitchen)"),
    ("If the blanket is in the living room, fold it and take it to the bed.", ("bedroom", "living_room"),
     "in_room(blanket, living_room)"),
    ("If the toy is in the living room, put it in the toy box in the bedroom.", ("bedroom", "living_room"),
     "in_room(toy, living_room)"),
    # text messages
    ("if the laptop's in the study, bring it down to the kitchen", ("kitchen", "study"), "in_room(laptop, study)"),
    ("if ur phone is in the bathroom pls bring it to the bed", ("bedroom", "bathroom"),
     "in_room(cell_phone, bathroom)"),
    ("Book in the bedroom? If so, bring it to the sofa.", ("living_room", "bedroom"), "in_room(book, bedroom)"),
    ("Laptop still in the study? Bring it to the kitchen.", ("kitchen", "study"), "in_room(laptop, study)"),
    ("Remote in the bedroom? Bring it back to the coffee table.", ("living_room", "bedroom"),
     "in_room(remote_control, bedroom)"),
    # house rules and formal notices
    ("Should the umbrella be in the hallway, put it in the wardrobe.", ("bedroom", "hallway"),
     "in_room(umbrella, hallway)"),
    ("If the vacuum cleaner is in the hallway, return it to the bedroom.", ("bedroom", "hallway"),
     "in_room(vacuum_cleaner, hallway)"),
    ("Should the laptop be in the office, it shall be placed on the desk in the study.", ("study", "office"),
     "in_room(laptop, office)"),
    ("If the plate is in the dining room, carry it to the kitchen sink.", ("kitchen", "dining_room"),
     "in_room(plate, dining_room)"),
    ("If the bowl is still in the dining room, it goes into the kitchen sink.", ("kitchen", "dining_room"),
     "in_room(bowl, dining_room)"),
    ("When the mug is in the office, take it to the kitchen sink.", ("kitchen", "office"), "in_room(mug, office)"),
    ("If the watering can is on the balcony, bring it to the kitchen.", ("kitchen", "balcony"),
     "in_room(watering_can, balcony)"),
    # checklists
    ("- Mug in the study? -> take it to the kitchen sink", ("kitchen", "study"), "in_room(mug, study)"),
    ("Pan in kitchen? If YES: bring it to the sofa. If NO: bring the pillow.", ("living_room", "kitchen"),
     "in_room(pan, kitchen)"),
    ("Is the pillow in the bedroom? If yes, bring it to the sofa.", ("living_room", "bedroom"),
     "in_room(pillow, bedroom)"),
    # learner English and transcripts
    ("If towel is in bathroom, you bring to the bedroom.", ("bedroom", "bathroom"), "in_room(towel, bathroom)"),
    ("MUM: If your coat's in the hallway, hang it in the wardrobe.", ("bedroom", "hallway"), "in_room(coat, hallway)"),
    ("Q: The book is in the bedroom? A: Then bring it to the sofa.", ("living_room", "bedroom"),
     "in_room(book, bedroom)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), ROOM_CONDITIONS)
def test_a_room_a_condition_asks_is_asked(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Found while reading dev 30 lamp_or_pillow_fetch_d30's "Pan in kitchen" (whose check item
    and layout are left): `placement._in_room` took a thing named right before "in <room>" as
    there whatever the mood, so "If the book is in the bedroom" settled the book's room and the
    factor it asks was dropped; only "Is the book in the bedroom?" was asked. Now a condition whose
    room follows a form of "be", and a question with no verb before its thing (verbless, or in a
    statement's order) ending at the room, leave it open. Measured before the rule: 1 of 22;
    after: 22 of 22."""
    assert asks(text, rooms, condition), factors(text, rooms)
    assert condition not in placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a statement, and a room that is a noun's modifier in a condition or a question
    ("The pan is in the kitchen. If it is dirty, wash it.", ("living_room", "kitchen"), "in_room(pan, kitchen)"),
    ("If the lamp in the bedroom is on, switch it off.", ("living_room", "bedroom"), "in_room(desk_lamp, bedroom)"),
    ("Is the lamp in the bedroom on? If so, switch it off.", ("living_room", "bedroom"), "in_room(desk_lamp, bedroom)"),
    ("If the mug in the office is dirty, take it to the kitchen sink.", ("kitchen", "office"), "in_room(mug, office)"),
    ("The laptop in the study: if it's on, shut it down.", ("kitchen", "study"), "in_room(laptop, study)"),
    ("The book in the bedroom is mine. If it is on the floor, put it on the shelf.", ("living_room", "bedroom"),
     "in_room(book, bedroom)"),
    ("The towel is in the bathroom, so if it is wet hang it up.", ("bedroom", "bathroom"), "in_room(towel, bathroom)"),
    # a goal
    ("Put the book in the bedroom if it is on the floor.", ("living_room", "bedroom"), "in_room(book, bedroom)"),
])
def test_a_room_stated_or_naming_which_thing_is_not_asked(text: str, rooms: tuple[str, ...],
                                                          condition: str) -> None:
    """Near misses: a statement's room, a room that says which thing is meant (in a condition, a
    question or a heading) and a goal ask no room (8 of 8 before the rule and after)."""
    assert not asks(text, rooms, condition), factors(text, rooms)


def _asked(text: str, rooms: tuple[str, ...], condition: str) -> bool:
    """Whether some factor of `text` has `condition` among its values (a yes/no factor's or a
    location factor's of several places)."""
    return any(condition in values for values in factors(text, rooms).values())


#: a condition with an alternative after "or" and a subject, set off by dashes or a bracket or
#: closed by a colon or an arrow: (text, rooms, the alternative's condition). Before the rule 6 of
#: 21 were asked (four of the places, as a location factor's other place)
SET_OFF_ALTERNATIVES = [
    # a quiz (dev 14 laundry_sorting_d14's form, another room) and a house-sitter's note
    ("Q5. The detergent has ended up on the floor. What do you do?\n  a) Put it back on the shelf.  b) Leave it.\n"
     "Q6. The detergent is anywhere else - or we have none at all. What do you do?\n  a) Put it on the shelf.  "
     "b) Leave it.\nANSWER KEY: 5 a, 6 b.", ("laundry_room",), "exists(laundry_detergent)"),
    ("If the detergent is on the floor, put it on the shelf. If it is anywhere else - or we have none at all - leave "
     "it.", ("laundry_room",), "exists(laundry_detergent)"),
    ("If your phone is on the sofa - or you have no phone at all - just leave it.", ("living_room",),
     "exists(cell_phone)"),
    # dashes: notes and text messages
    ("If the mug is on the desk - or it's on the floor - take it to the kitchen sink.", ("office", "kitchen"),
     "on(mug, floor)"),
    ("if the towel's on the floor - or it's wet - put it in the laundry basket", ("bathroom",), "state(towel, wet)"),
    ("If the remote is on the sofa - or if it's on the floor - put it on the coffee table.", ("living_room",),
     "on(remote_control, floor)"),
    ("When the blanket is on the floor - or it's wet - hang it over the armchair.", ("living_room",),
     "state(blanket, wet)"),
    ("If the plate is on the table - or there's one in the sink - wash it.", ("kitchen",), "inside(plate, sink)"),
    pytest.param("If the bottle is empty - or it is on the floor - put it in the recycling bin.", ("kitchen",),
                 "on(bottle, floor)",
                 marks=pytest.mark.xfail(strict=True, reason="a place after a state's alternative is not read, "
                                                             "with commas either")),
    ("if the cup is dirty - or if it's on the floor - put it in the sink pls", ("kitchen",), "on(cup, floor)"),
    ("If the lamp is on - or it's broken - tell me.", ("bedroom",), "state(table_lamp, broken)"),
    # a notice in capitals, formal "should"
    ("IF THE MUG IS ON THE DESK - OR IT IS ON THE FLOOR - TAKE IT TO THE SINK.", ("office", "kitchen"),
     "on(mug, floor)"),
    ("Should the kettle be on the counter - or should it be on the stove - fill it at the sink.", ("kitchen",),
     "on(kettle, stove)"),
    ("Should the laptop be open - or should it be on - shut it down and close it.", ("office",),
     "state(laptop, toggled_on)"),
    # a bracket
    ("If the book is on the sofa (or it's on the floor), put it on the bookshelf.", ("living_room",), "on(book, floor)"),
    ("If the sponge is not by the sink (or there isn't one), use the cloth.", ("kitchen",), "exists(sponge)"),
    ("If the towel is on the floor (or it is wet), put it in the laundry basket.", ("bathroom",), "state(towel, wet)"),
    # a checklist's colon or arrow (dev 5 laundry_sorting_d5's form, other things)
    ("If the soap is anywhere else, or we have none: leave it.", ("bathroom",), "exists(soap_bar)"),
    ("If the laptop is on the bed, or it is on the floor: put it on the desk.", ("bedroom",), "on(laptop, floor)"),
    ("If the pillow is on the floor, or it is dirty -> put it in the hamper.", ("bedroom",), "state(pillow, dirty)"),
    ("If the keys are on the table, or if they are on the floor: hang them on the key hook.", ("hallway",),
     "on(keys, floor)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), SET_OFF_ALTERNATIVES)
def test_an_alternative_set_off_is_asked(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """dev 14 laundry_sorting_d14 "Q6. The detergent is anywhere else - or we have none at all"
    (as a condition from its answer key, "If the detergent is anywhere else - or we have none at
    all, leave it") never asked whether there is detergent: the dash cut "or we have none at all"
    off as an instruction, where "..., or we have none, ..." is read (`sentences._SET_OFF_ALTERNATIVE`);
    and "or it's on the floor" took "it" for the place before it (`analysis.CONJOINED_SUBJECT`).
    Measured before the rule: 6 of 21; after: 20 of 21 (the bottle's "empty - or it is on the
    floor" is not read with commas either: expected to fail)."""
    assert _asked(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # "or" before an instruction or a place: an alternative action or goal, no condition
    ("If the towel is wet, hang it on the rail - or put it in the laundry basket.", ("bathroom",),
     "on(towel, rail)"),
    ("Put the book on the shelf - or on the desk. If it's on the floor, pick it up.", ("living_room",),
     "on(book, desk)"),
    ("If the lamp is on, switch it off - or ask me to.", ("bedroom",), "state(table_lamp, broken)"),
    # "or" with no subject after it
    ("If the mug is dirty - or rather, put it in the sink anyway.", ("kitchen",), "on(mug, floor)"),
    ("The mug is on the desk - or was, this morning. If it's dirty, wash it.", ("office",), "on(mug, floor)"),
])
def test_or_before_no_clause_asks_nothing_more(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Near misses: "or" before an instruction, a place or no subject is no alternative condition
    (5 of 5 before the rule and after)."""
    assert not _asked(text, rooms, condition), factors(text, rooms)
