"""A state word before a compound name whose modifier the task has no name for ("a dirty dish
towel", "a full mop bucket", "an open craft box"), from the twenty-third session: the reader
walked back from the head noun for a state and stopped at the modifier, so the condition the
sentence asks was never read (`analysis._Reader._past_modifiers`). The table was written here, in
five registers (terse notes, chat, formal notices, checklists, learner English) and several
rooms and kinds, with near misses that must stay as they are; it was measured before the rule
(0 of 10 asked) and after (10 of 10)."""

from __future__ import annotations

import pytest
from reading import asks, factors

#: (text, rooms, the condition asked of the compound's thing)
READ = [
    # terse notes
    ("A full mop bucket by the door? Empty it into the bathtub.", ("bathroom",), "state(bucket, filled)"),
    ("Dirty dish towel on the counter? Into the laundry basket.", ("kitchen",), "state(hand_towel, dirty)"),
    # chat
    ("if u see an open craft box on the desk close it", ("bedroom",), "state(cardboard_box, open)"),
    ("if there's a dirty dish towel on the counter pls put it in the laundry basket", ("kitchen",),
     "state(hand_towel, dirty)"),
    # formal notices
    ("Should a full mop bucket be found in the hallway, it shall be emptied into the bathtub.",
     ("bathroom", "hallway"), "state(bucket, filled)"),
    ("In the event of an open craft box on the shelf, close it.", ("bedroom",), "state(cardboard_box, open)"),
    # checklists
    ("- Full mop bucket by the door? -> empty it into the bathtub", ("bathroom",), "state(bucket, filled)"),
    ("[ ] dirty dish towel on the counter? put it in the laundry basket", ("kitchen",),
     "state(hand_towel, dirty)"),
    # learner English
    ("If you find a dirty dish towel on counter, you put it to laundry basket.", ("kitchen",),
     "state(hand_towel, dirty)"),
    ("When there is open craft box on desk, please you close it.", ("bedroom",), "state(cardboard_box, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), READ)
def test_a_state_before_a_modifier_is_the_things(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Measured before the rule: 0 of 10 asked; after: 10 of 10."""
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition", "asked"), [
    # the modifier named plainly: the state already read
    ("if the mop bucket is full, empty it in the bathtub", ("bathroom",), "state(bucket, filled)", True),
    ("A dirty coffee mug on the desk? Wash it.", ("office",), "state(mug, dirty)", True),
    # a state word before an instruction's verb, not a thing's name
    ("Open craft box and take out the scissors.", ("bedroom",), "state(cardboard_box, open)", False),
    # taken from its source: the state is presupposed with the source, not asked
    ("Grab a clean dish towel from the drawer and dry the plate.", ("kitchen",), "state(hand_towel, dirty)",
     False),
    # a stated fact is kept, never asked
    ("There is a full mop bucket by the door.", ("bathroom",), "state(bucket, filled)", False),
    # a place noun between the state word and the thing: the state is not the thing's
    ("Empty kitchen bin? Put the dish towel in it.", ("kitchen",), "state(hand_towel, filled)", False),
    # the state stated of the thing after it
    ("The mop bucket is full. Empty it into the bathtub.", ("bathroom",), "state(bucket, filled)", False),
])
def test_near_misses_stay(text: str, rooms: tuple[str, ...], condition: str, asked: bool) -> None:
    """Near misses (7 of 7 as below before the rule and after): a plainly named thing, an
    imperative, a thing taken from its source, stated facts, a state word before a place noun."""
    assert asks(text, rooms, condition) == asked, factors(text, rooms)
