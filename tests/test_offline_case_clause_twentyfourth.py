"""A branch labelled by the case it is for, with a whole clause in the bracket before the colon
("Option A (the mug is dirty): wash it", a method sheet's "Plain lead (the shirt is clean): fold
it away"), from the twenty-fourth session. The reader read such a bracket only when it held a
thing and a place with no verb ("Plan B (no mug on the desk): ...", `sentences._CASE_LABEL`), so
a clause there asked nothing and its branch's instruction stood unconditioned
(`sentences._CASE_CLAUSE`). Found on dev 39's losses (the method sheet, the first row); the
other rows were written here in other registers (a decision sheet, a test card, a runbook, a
checklist, a referee's card) before the rule and measured then (the counts in each test's
docstring)."""

from __future__ import annotations

import pytest
from reading import factors, instruction_under

#: (text, rooms, the condition asked)
READ = [
    # a change-ringing method sheet (dev 39)
    ("LEAD 1 - THE SHIRT\nPlain lead (the shirt is clean): fold it away in the wardrobe.\n"
     "Bob (the shirt is dirty and the washing machine is not running): straight into the washing machine.",
     ("bedroom", "laundry_room"), "state(shirt, dirty)"),
    ("LEAD 1 - THE SHIRT\nPlain lead (the shirt is clean): fold it away in the wardrobe.\n"
     "Bob (the shirt is dirty and the washing machine is not running): straight into the washing machine.",
     ("bedroom", "laundry_room"), "state(washing_machine, toggled_on)"),
    # a decision sheet
    ("Option A (the mug is dirty): wash it in the sink.\nOption B (the mug is clean): put it in the cabinet.",
     ("kitchen",), "state(mug, dirty)"),
    # a test card
    ("Towel.\nCase 1 (the towel is wet): hang it on the rack.\nCase 2 (the towel is dry): leave it.",
     ("bathroom",), "state(towel, wet)"),
    # a runbook
    ("Scenario 2 (the fan is still running): switch it off at the wall.", ("bedroom",),
     "state(ceiling_fan, toggled_on)"),
    # a checklist's outcome, negated
    ("Outcome 3 (the lamp isn't on): turn it on before you leave.", ("living_room",),
     "state(table_lamp, toggled_on)"),
    # a referee's card, the perfect
    ("Red card (the kettle has been left on): switch it off.", ("kitchen",), "state(kettle, toggled_on)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), READ)
def test_a_case_label_with_a_clause_asks_the_clause(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """Measured before the rule: 0 of 7 asked; after: 7 of 7."""
    asked = factors(text, rooms)
    assert any({condition, f"not {condition}"} <= v for v in asked.values()), asked


def test_each_labelled_case_keeps_its_own_instruction() -> None:
    """The two options' instructions fall under their own answers (before the rule: no factor)."""
    under = instruction_under("Option A (the mug is dirty): wash it in the sink.\n"
                              "Option B (the mug is clean): put it in the cabinet.", ("kitchen",), "state(mug, dirty)")
    assert "wash" in under["yes"] and "cabinet" in under["no"], under


@pytest.mark.parametrize(("text", "rooms"), [
    # a bracket without a finite "be" or "have": a place or a description
    ("Step 2 (the kitchen): wipe the counter.", ("kitchen",)),
    ("Mug (the blue one): wash it in the sink.", ("kitchen",)),
    # a clause of no thing's state, and one of ownership
    ("Remember (it is easy to forget): the keys go in the bowl.", ("hallway",)),
    ("Note (the mug is mine): wash it in the sink.", ("kitchen",)),
])
def test_a_bracket_that_states_no_case_asks_nothing(text: str, rooms: tuple[str, ...]) -> None:
    """Near misses: 4 of 4 ask nothing, before the rule and after."""
    assert factors(text, rooms) == {}
