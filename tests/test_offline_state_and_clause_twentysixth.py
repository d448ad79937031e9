"""A bare state joined by "and" / "but" to a clause about another thing, before a colon or a
question mark ("- Wet and the dryer is idle: load it into the dryer", "Dirty but the sink is full?
Stack it on the counter"), from the twenty-sixth session (dev 44's screen-print shop checklist):
the case of the thing spoken of and that clause, as "if it is wet and the dryer is idle, ..."
(`sentences._STATE_AND_CLAUSE`). Before, the line was a statement and the bare state fell on the
other clause's thing ("dryer_wet"). The rows were written here in other registers (a dash list, a
question, a bullet, a terse note, capitals) before the rule and measured then: 0 of 5; after: 5 of
5."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, (thing, state) of the bare case, (thing, state) of the clause joined to it)
CASES = [
    ("The shirt is in the laundry basket.\n- Wet and the dryer is idle: put it in the dryer.\n- Wet but the dryer "
     "is running: hang it on the drying rack.", ("laundry_room",), ("shirt", "wet"), ("dryer", "toggled_on")),
    ("Your mug's on the desk. Dirty and the dishwasher's empty? Put it in the dishwasher.", ("kitchen",),
     ("mug", "dirty"), ("dishwasher", "filled")),
    ("The towel is on the floor.\n* Wet but the radiator is on: hang it on the radiator.", ("bathroom",),
     ("towel", "wet"), ("radiator", "toggled_on")),
    ("Plate on the table. Dirty but the sink is full? Stack it on the counter.", ("kitchen",),
     ("plate", "dirty"), ("sink", "filled")),
    ("THE KETTLE is on the counter. empty and the lid is open: fill it at the sink", ("kitchen",),
     ("kettle", "filled"), ("kettle", "filled")),
]


@pytest.mark.parametrize(("text", "rooms", "case", "joined"), CASES)
def test_a_bare_state_and_a_clause_are_one_case(text: str, rooms: tuple[str, ...], case: tuple[str, str],
                                                joined: tuple[str, str]) -> None:
    asked = factors(text, rooms)
    for thing, state in (case, joined):
        assert any(thing in fid and any(f", {state})" in v for v in values) for fid, values in asked.items()), asked


def test_no_case_without_a_state_word() -> None:
    """Near miss: "Done" is no state of a thing."""
    assert factors("The door is shut. Done and the lights are off: go home.", ("hallway",)) == {}
