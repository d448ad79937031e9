"""A bare state and a comma before a goal with no verb ("Your tea cup is on the bench. Dirty, in
the sink. Clean, back on the shelf over the sink"), from the twenty-fifth session: a note's cases,
as "Dirty? In the sink." and "If dirty, in the sink." already were. The reader read the bare state's
case only before a verb of putting ("Wet, hang it on the rack": `sentences._STATE_CASE`); now also
before a verbless goal (`sentences._VERBLESS_GOAL`: "into"/"onto"/"back in" and the like before a
determiner, a plain "in"/"on"/"to" before "the" only, so "Clean, in my opinion" is none). Found on
dev 41's lock cottage; the rows were written here in other registers (a bathroom note, a desk
memo, a heading's bracket, a dash list) before the rule and measured then (the counts in each
test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors, instruction_under

#: (text, rooms, the condition, a word of the goal under "yes")
CASES = [
    ("Your tea cup is on the bench. Dirty, in the sink. Clean, back on the shelf over the sink.",
     ("lock_cottage",), "state(cup, dirty)", "sink"),
    ("The towel is on the rail. Wet, on the radiator. Dry, in the cupboard.", ("bathroom",),
     "state(towel, wet)", "radiator"),
    ("Mug on desk. Dirty, into the dishwasher; clean, onto the shelf.", ("study",), "state(mug, dirty)",
     "dishwasher"),
    ("SHIRT (on the chair): dirty, into the hamper. Clean, back in the wardrobe.", ("bedroom",),
     "state(shirt, dirty)", "hamper"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "goal"), CASES)
def test_a_bare_state_before_a_verbless_goal_is_a_case(text: str, rooms: tuple[str, ...], condition: str,
                                                        goal: str) -> None:
    """Measured before the rule: 0 of 5 (with the dash list below); after: 4 of 5, each goal under
    its own answer."""
    asked = factors(text, rooms)
    assert any({condition, f"not {condition}"} <= v for v in asked.values()), asked
    assert goal in instruction_under(text, rooms, condition)["yes"]


@pytest.mark.xfail(strict=True, reason="the case's 'it' is taken up by the rail its own goal names")
def test_a_dash_item_with_its_goal() -> None:
    asked = factors("Tea towel by the hob - wet, on the rail; dry, in the drawer.", ("kitchen",))
    assert any("state(hand_towel, wet)" in v for v in asked.values()), asked


@pytest.mark.parametrize(("text", "rooms"), [
    ("The sponge is on the sink. Clean, in my opinion.", ("kitchen",)),
    ("Dry, in the end, the towel went on the rail.", ("bathroom",)),
    ("Wet, cold and tired, we got home.", ("hallway",)),
])
def test_a_state_before_a_phrase_that_is_no_goal_asks_nothing(text: str, rooms: tuple[str, ...]) -> None:
    """Near misses, nothing asked before or after the rule."""
    assert factors(text, rooms) == {}
