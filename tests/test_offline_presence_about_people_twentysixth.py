"""Presence conditions beside what people do, from the twenty-sixth session (dev 44's bicycle
workshop: "If she hasn't and the bag's still here, lock it in the cupboard under the till and shut
the door. Gone - great, nothing to do."). Two rules, each written with a table in other registers
before it and measured then:

- a condition of two conjuncts, one about people ("she hasn't come back", "we're done", "nobody's
  collected it") and one asking whether a thing is there, asks what that conjunct asks alone
  (`analysis._conjunct_presence`): 4 of 7 read as their conjunct alone before, 7 after;
- an absence that names nothing ("Gone - great", "Gone? Fine.") right after a condition asking a
  thing's presence is that thing's absence, not the absence of what the instruction handled last
  (`analysis._absence_of_asked`): 2 of 5 before, 4 after (a modal presence with a time clause left).
"""

from __future__ import annotations

import pytest
from reading import factors

#: (text with two slots for the people's conjunct, rooms, the conjunct, whether it comes after)
CONJUNCTS = [
    ("The handbag is on the counter. If {}the bag's still here{}, lock it in the cupboard.", ("shop",),
     "she hasn't come back", False),
    ("Mr Reyes left his scarf on the bench. If {}the scarf is still there{}, hang it on the coat hook.", ("hallway",),
     "he's gone home", False),
    ("Somebody's umbrella was by the door earlier. If {}the umbrella's still here{}, put it in the umbrella stand.",
     ("hallway",), "you leave before six", False),
    ("A box came for flat 3, it's on the table. if {}the box is still there{}, put it in the cupboard", ("hallway",),
     "nobody's collected it", True),
    ("The kettle is on the counter. When {}the kettle's still here{}, put it in the cabinet.", ("kitchen",),
     "we're done", False),
    ("The laptop was left on the desk. If {}the laptop is still there{}, lock it in the drawer.", ("study",),
     "I haven't rung you", True),
    ("Her phone is on the sofa. If {}it's still there{}, put it on the charger.", ("living_room",),
     "she hasn't come for it", False),
]


@pytest.mark.parametrize(("text", "rooms", "people", "after"), CONJUNCTS)
def test_a_conjunct_about_people_asks_nothing(text: str, rooms: tuple[str, ...], people: str, after: bool) -> None:
    alone = factors(text.format("", ""), rooms)
    joined = factors(text.format("", f" and {people}") if after else text.format(f"{people} and ", ""), rooms)
    assert alone and joined == alone


def test_two_things_conditions_are_read_as_before() -> None:
    """Near miss: both conjuncts about things; the lamp's state is asked, as before the rule."""
    asked = factors("The bag is on the counter. If the lamp is on and the bag's still here, switch the lamp off.",
                    ("shop",))
    assert any("toggled_on" in fid for fid in asked), asked


#: (text, rooms, the thing whose presence is asked)
ABSENCES = [
    ("The handbag is on the counter. If the bag's still here, lock it in the cupboard and shut the door. "
     "Gone - great, nothing to do.", ("shop",), "handbag"),
    ("If the umbrella's still here, put it in the cabinet and close the door. Gone? Fine.", ("hallway",), "umbrella"),
    ("if the keys are still here, put them in the drawer and shut it. missing - ring me", ("hallway",), "keys"),
    ("If you find the remote, put it on the shelf next to the lamp. Gone again? Leave it.", ("living_room",),
     "remote_control"),
    pytest.param("Should the laptop still be here when you lock up, put it in the cabinet and lock the cabinet. "
                 "Not here: nothing to do.", ("study",), "laptop",
                 marks=pytest.mark.xfail(strict=True, reason="a modal presence with a time clause asks nothing")),
]


@pytest.mark.parametrize(("text", "rooms", "thing"), ABSENCES)
def test_a_bare_absence_answers_the_presence_asked(text: str, rooms: tuple[str, ...], thing: str) -> None:
    assert set(factors(text, rooms)) == {f"{thing}_present"}


def test_a_bare_absence_with_no_presence_asked_is_read_as_before() -> None:
    """Near miss: no presence asked before it, so the rule leaves the absence as it was read."""
    text = "If the towel is on the floor, hang it on the drying rack. Gone? Fine."
    assert "towel_present" not in factors(text, ("bathroom",))
