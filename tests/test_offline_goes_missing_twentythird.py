"""A thing gone missing said with the inchoative "go" in a simple tense ("If the remote goes
missing", "Should the keys go missing", "if the scissors went missing again"), from the
twenty-third session: the reader read the perfect ("has gone missing") and the copula ("is
missing") as the thing's absence, but not the simple tenses, so nothing was asked
(`sentences._GOES_MISSING`). The table was written here in several registers (a note, a text
message, a house rule, a formal notice, a checklist, learner English), with near misses; it was
measured before the rule (the counts in each test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the thing whose presence is asked)
READ = [
    # a note
    ("If the remote goes missing, look under the sofa cushions.", ("living_room",), "remote_control"),
    ("If the remote ever goes missing, it's usually under the sofa.", ("living_room",), "remote_control"),
    # a text message
    ("if the scissors went missing again check the drawer", ("kitchen",), "scissors"),
    # a house rule
    ("Should the keys go missing, check the bowl by the door first.", ("hallway",), "keys"),
    # a formal notice
    ("In the event that the torch goes missing, a spare is kept in the cabinet.", ("hallway",), "flashlight"),
    # a checklist
    ("- Laptop goes missing? Tell the office at once.", ("office",), "laptop"),
    # learner English
    ("When the towel go missing, you take the spare one from the cupboard.", ("bathroom",), "towel"),
    # a parent's note, plural
    ("If my glasses go missing, they are usually on the bedside table.", ("bedroom",), "glasses"),
]


@pytest.mark.parametrize(("text", "rooms", "thing"), READ)
def test_goes_missing_asks_whether_it_is_there(text: str, rooms: tuple[str, ...], thing: str) -> None:
    """Measured before the rule: 0 of 8 asked; after: 8 of 8."""
    asked = factors(text, rooms)
    assert any({f"exists({thing})", f"not exists({thing})"} <= v for v in asked.values()), asked


@pytest.mark.parametrize(("text", "rooms"), [
    # said of no thing of the task, or as an instruction
    ("Things go missing in this house. If the remote is on the floor, put it on the coffee table.",
     ("living_room",)),
    ("Don't let the remote go missing. If it is on the floor, put it on the coffee table.", ("living_room",)),
])
def test_goes_missing_of_no_thing_asks_no_presence(text: str, rooms: tuple[str, ...]) -> None:
    """Near misses: a generic subject and a prohibition ask no presence (2 of 2 before the rule
    and after)."""
    assert not any(any(v.startswith(("exists(", "not exists(")) for v in vs) for vs in factors(text, rooms).values())
