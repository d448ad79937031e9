"""A heading line of one or two words whose noun is also a verb ("MUG", "BUCKET", "Bin"), the next
line opening a sentence ("It stands on the floor by the anvil."), from the twenty-sixth session
(dev 44's forge card, "QUENCH BUCKET / It stands on the floor ..."). The namer joined the lines and
read "bucket it", "mug it" as a verb and its object, and named nothing: the condition that followed
fell on the floor or the desk. Now a word ending such a line is a noun (`naming._Reader.
line_of_its_own`); a next line in lower case may still go on with it. The rows were written here in
other registers (a numbered list, a sign, a note) before the rule and measured then: 1 of 6; after:
6 of 6."""

from __future__ import annotations

import pytest
from reading import factors, named

#: (text, rooms, a word of the kind the heading names)
HEADINGS = [
    ("MUG\nIt is on the desk. Dirty? Wash it at the sink.", ("office",), "mug"),
    ("BUCKET\nIt stands on the floor. Empty? Fill it at the sink.", ("shed",), "bucket"),
    ("Mop bucket\nIt's on the floor by the door. If it's empty, fill it at the sink.", ("utility_room",), "bucket"),
    ("Towel\nIt ends up on the floor most days. If it's on the floor, hang it on the rail.", ("bathroom",), "towel"),
    ("Bin\nIt's by the back door. Full? Empty it into the big bin outside.", ("kitchen",), "trash_can"),
    ("3) FAN\nIt gets left running. If it's on, switch it off.", ("bedroom",), "fan"),
]


@pytest.mark.parametrize(("text", "rooms", "kind"), HEADINGS)
def test_a_heading_line_names_its_thing_and_the_next_line_asks_of_it(text: str, rooms: tuple[str, ...],
                                                                      kind: str) -> None:
    assert any(kind in category for category, _ in named(text, rooms).values())
    assert any(kind in fid for fid in factors(text, rooms))


def test_a_line_going_on_in_lower_case_keeps_its_verb() -> None:
    """Near miss: "Mop\\nthe floor" goes on with the line before it; "mop" is its verb, no mop."""
    assert "mop" not in named("Mop\nthe floor when you're done, then put the bucket away.", ("kitchen",))
