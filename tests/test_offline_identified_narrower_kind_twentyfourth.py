"""A thing named outright by one word and identified by an "is" with a fuller kind whose name ends
in its kind's name ("The key cupboard is the little wall cabinet by the door", a tower captain's
note: a cupboard is a cabinet, a wall cabinet is one), from the twenty-fourth session. The reader
renamed a thing by a fuller name only when its word was a head several kinds share ("the box is
the blue toy box") and the "is" stood right after that word, so the cupboard and the wall cabinet
were two objects and "if it's open" asked the plain cabinet (`naming._Reader.renamed_fuller`:
the narrower kind, and a place said between the thing and its "is"). Found on dev 39's losses (the
first row); the other rows were written here in other registers (a cleaner's card, an office
note with a heading) before the rule and measured then (the counts in each test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors, named

#: (text, rooms, the one kind named, the condition asked)
READ = [
    # a tower captain's note (dev 39)
    ("The key cupboard is the little wall cabinet by the door, tower keys and the clock key in it. That has to "
     "be shut when we leave. Should it be open, close it; if it's already shut, good.", ("bell_tower",),
     "wall_cabinet", "state(wall_cabinet, open)"),
    ("The cupboard is the wall cabinet by the door. If it is open, close it.", ("hallway",),
     "wall_cabinet", "state(wall_cabinet, open)"),
    # a cleaner's card, a place between the thing and its "is"
    ("The cupboard in the bathroom is the medicine cabinet. If it's open, close it.", ("bathroom",),
     "medicine_cabinet", "state(medicine_cabinet, open)"),
    # an office note with a heading and a dash
    ("Paperwork: the cupboard by the window is the filing cabinet - if it is open, shut it.", ("office",),
     "filing_cabinet", "state(filing_cabinet, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "kind", "condition"), READ)
def test_a_thing_identified_by_a_narrower_kind_is_one_object(
        text: str, rooms: tuple[str, ...], kind: str, condition: str) -> None:
    """Measured before the rule: 0 of 4 named one object (each named a cabinet beside the fuller
    kind and asked the cabinet); after: 4 of 4."""
    kinds = {category for category, _ in named(text, rooms).values()}
    assert kind in kinds and "cabinet" not in kinds, kinds
    assert any({condition, f"not {condition}"} <= v for v in factors(text, rooms).values())


@pytest.mark.parametrize("text", [
    # beside, not identified
    "The cupboard is next to the wall cabinet. If it is open, close it.",
    # identified by "the one", no kind
    "The cupboard under the sink is the one with the bin in it. If it is open, close it.",
])
def test_a_cupboard_not_identified_by_a_narrower_kind_stays_a_cabinet(text: str) -> None:
    """Near misses: the plain cabinet is still named and asked (2 of 2 before the rule and after)."""
    assert "cabinet" in {category for category, _ in named(text, ("kitchen",)).values()}
    assert any({"state(cabinet, open)", "not state(cabinet, open)"} <= v for v in factors(text, ("kitchen",)).values())
