"""A "Still there?" question with the time to look said after it ("Still there at six?", "...
by lunchtime?", "... tonight?") asks, as a bare "Still there?" does, whether the thing spoken of is
still where it was said to be (`sentences._TIME_ADJUNCT` in `_STILL_THERE_QUESTION`, the time kept
in the question). From the thirty-first session (a flower farm's Saturday note in development set
56: "Still there when you finish? Fridge, door shut."). Rows written here in other registers before
the rule and measured then: 0 of 6; after: 3 of 6 (left: a plural thing, "the sweet peas", whose
name the reader does not place; "after your shower"; a windowsill no kind names). Near miss: a time
on an instruction ("Wash it at six") asks nothing."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the place asked)
STILL_THERE = [
    ("The mug on the desk is Sam's. Still there at six? Wash it.", ("office",), "on(mug, desk)"),
    pytest.param("The sweet peas on the bench are for Mrs Patel. Still there when you finish? Into the fridge.",
                 ("shed",), "on(flower, bench)", marks=pytest.mark.xfail(strict=True, reason="sweet peas unplaced")),
    ("The remote was on the sofa this morning. Still there by lunchtime? Put it on the stand.", ("lounge",),
     "on(remote_control, sofa)"),
    ("Somebody's umbrella is on the floor by the door. Still there tonight? Hang it on the hook.", ("hall",),
     "on(umbrella, floor)"),
    pytest.param("The towel's on the floor. Still there after your shower? Hang it up.", ("bathroom",),
                 "on(towel, floor)", marks=pytest.mark.xfail(strict=True, reason="'after' read as a clause")),
    pytest.param("The water bottle on the windowsill is Priya's. Still there at home time? Lost property box.",
                 ("classroom",), "water_bottle", marks=pytest.mark.xfail(strict=True, reason="no windowsill kind")),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), STILL_THERE)
def test_still_there_with_a_time_asks_the_place(text: str, rooms: tuple[str, ...], fact: str) -> None:
    conditions = set().union(set(), *factors(text, rooms).values())
    assert fact in conditions or any(fact in c for c in conditions if "(" not in fact)


def test_a_time_on_an_instruction_asks_nothing() -> None:
    assert factors("The mug on the desk is Sam's. Wash it at six.", ("office",)) == {}
