"""A thing at rest said with a participle of resting ("lying", "standing", "sitting", British
"sat"), from the twenty-fourth session. Two forms the reader read only with the bare place or
with "lying": a condition with its subject elided before such a participle and a surface place
("IF STANDING ON THE VANITY, PUT IT AWAY", a dispensing label's, `sentences._ELIDED_PLACE`), and
the participle between a thing's copula and "there" ("If it's still lying there", a tower
captain's note, `sentences._RESTING_THERE`), which asked nothing where "if it's still there"
asks where the thing was said to be; and, composed with it, "Still there?" as a question of its
own (`sentences._STILL_THERE_QUESTION`). Found on dev 39's losses (the first row of the first two tables); the
other rows were written here in other registers (a house rule, a text message, a cook's note, a
formal notice, British speech, a list heading) before the rule and measured then (the counts in
each test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the placement asked)
ELIDED = [
    # a dispensing label's capitals (dev 39)
    ("THE MEDICINE BOTTLE BELONGS IN THE MEDICINE CABINET. IF STANDING ON THE VANITY, PUT IT AWAY.",
     ("bathroom",), "on(medicine_bottle, bathroom_vanity)"),
    # a house rule
    ("The mug lives in the cupboard. If sitting on the desk, wash it and put it back.", ("office",),
     "on(mug, desk)"),
    # a terse note with a semicolon
    ("Vase goes on the shelf; if standing on the floor, lift it up there.", ("living_room",), "on(vase, floor)"),
    # "when" and "resting"
    ("The laptop should be in its bag. When resting on the sofa, put it away.", ("living_room",),
     "on(laptop, sofa)"),
    # British "sat" after a heading
    ("Bottle of wine: if sat on the counter, pop it in the fridge.", ("kitchen",),
     "on(wine_bottle, kitchen_counter)"),
    # "unless" with "already" after the place
    ("The kettle is kept in the cupboard. Unless standing on the stove already, leave it.", ("kitchen",),
     "on(kettle, stove)"),
    # a plural heading
    ("Glasses: if sitting on the coffee table, put them in the cabinet.", ("living_room",),
     "on(glasses, coffee_table)"),
]

THERE = [
    # a tower captain's note (dev 39)
    ("Mary's scarf. It's been on the floor under the ropes for two weeks. If it's still lying there, "
     "hang it on the coat hook.", ("hallway",), "on(scarf, floor)"),
    # a plain note
    ("The towel was on the floor this morning. If it is still lying there, put it in the hamper.",
     ("bathroom",), "on(towel, floor)"),
    # chatty, "sitting"
    ("The remote was on the armchair earlier. If it's still sitting there, put it back on the TV stand.",
     ("living_room",), "on(remote_control, armchair)"),
    # a text message with a dropped subject and a dash
    ("Left my phone on the bench in the hall - if it's still lying there, bring it in.", ("hallway",),
     "on(cell_phone, bench)"),
]


#: "Still there?" as a question of its own (`sentences._STILL_THERE_QUESTION`), with or without a
#: resting participle: (text, rooms, the placement asked)
STILL_THERE = [
    ("The mug has been on the desk all week. Still there? Wash it.", ("office",), "on(mug, desk)"),
    ("The mug has been on the desk all week. Still sitting there? Wash it.", ("office",), "on(mug, desk)"),
    ("The towel was on the floor this morning. Still lying there? Hang it on the rail.", ("bathroom",),
     "on(towel, floor)"),
    # a text message in lower case, over two lines
    ("left my scarf on the bench this morning\nstill there? pls hang it on the hook", ("hallway",),
     "on(scarf, bench)"),
    # a note in capitals
    ("REMOTE ON THE ARMCHAIR AT 6PM. STILL THERE? PUT IT ON THE TV STAND.", ("living_room",),
     "on(remote_control, armchair)"),
]

def _asked(text: str, rooms: tuple[str, ...], condition: str) -> bool:
    return any({condition, f"not {condition}"} <= v for v in factors(text, rooms).values())


@pytest.mark.parametrize(("text", "rooms", "condition"), ELIDED)
def test_an_elided_subject_before_a_resting_participle_asks_the_place(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Measured before the rule: 0 of 7 asked; after: 7 of 7."""
    assert _asked(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition"), THERE)
def test_a_resting_participle_before_there_asks_the_place_said_before(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Measured before the rule: 0 of 4 asked; after: 4 of 4."""
    assert _asked(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition"), STILL_THERE)
def test_still_there_as_a_question_asks_the_place_said_before(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Measured before the rule: 0 of 5 asked; after: 5 of 5. A bare "There at six?" (no "still")
    is left alone. ("Still there at six?", a time after it, was left alone too until the
    thirty-first session, which reads it as "Is it still there at six?" is read:
    tests/test_offline_still_there_time_thirtyfirst.py.)"""
    assert _asked(text, rooms, condition), factors(text, rooms)
    assert factors("The mug is on the desk. There at six? Ring me.", ("office",)) == {}


@pytest.mark.parametrize(("text", "rooms"), [
    # the listener's posture, with no thing for the elided subject
    ("When standing on the ladder, hold the rail.", ("garage",)),
    ("If sitting on the sofa, do not eat crisps.", ("living_room",)),
])
def test_the_listeners_posture_asks_nothing(text: str, rooms: tuple[str, ...]) -> None:
    """Near misses: a posture of the listener's, with no thing spoken of before it, asks nothing
    (2 of 2 before the rule and after)."""
    assert factors(text, rooms) == {}


def test_a_participle_of_rest_after_there_is_is_left_alone() -> None:
    """"There's a towel lying there": an existential, not a copula before the participle; it asks
    whether a towel is there at all, before the rule and after."""
    text = "Check the bathroom floor. If there's a towel lying there, hang it on the rail."
    assert factors(text, ("bathroom",)) == {"towel_present": {"exists(towel)", "not exists(towel)"}}
