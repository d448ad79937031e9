"""A bare "No" and a thing opening its sentence before a comma, a colon or a dash ("No flowers
brought, nothing to do here", "No mug, nothing to do", "No bucket out: tick the box"), from the
twenty-sixth session (dev 43's chapel of rest checklist): the case of the thing's absence, as "if
there is no mug, ..." (`sentences._NO_CASE`; "No mug? ..." was read before). A place after the thing
makes it a rule ("No shoes on the carpet, please"), left as it was. The rows were written here in
other registers before the rule and measured then: 2 of 5; after: 4 of 5 (toys, a class no kind
names, left as an xfail)."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, a word of the thing's role)
CASES = [
    ("Guests sometimes leave a mug on the desk. Wash it. No mug, nothing to do.", ("office",), "mug"),
    ("Sometimes the cleaner leaves a bucket out. Put it in the cupboard. No bucket out: tick the box.",
     ("utility_room",), "bucket"),
    ("Dad might drop his glasses off. Put them on the shelf. No glasses today, fine.", ("hallway",), "glasses"),
    ("Families often bring flowers in. Put the flowers in the vase. No flowers - nothing to do here.", ("chapel",),
     "flower"),
    pytest.param("Kids bring toys in from the garden. Put the toys in the toy box. No toys brought in, nothing to do.",
                 ("playroom",), "toy", marks=pytest.mark.xfail(strict=True, reason="toys name a class, no kind")),
]


@pytest.mark.parametrize(("text", "rooms", "thing"), CASES)
def test_no_and_a_thing_asks_its_absence(text: str, rooms: tuple[str, ...], thing: str) -> None:
    asked = factors(text, rooms)
    assert any(thing in fid and "not exists(" in " ".join(values) for fid, values in asked.items()), asked


@pytest.mark.parametrize("text", ["No shoes on the carpet, please. If the rug is dirty, vacuum it.",
                                  "No, leave the lamp on.", "No need, thanks. The lamp is on the desk."])
def test_a_rule_or_a_reply_asks_no_absence(text: str) -> None:
    """Near misses: a rule with a place, and "No" as a reply."""
    assert not any("exists(" in " ".join(v) for v in factors(text, ("hallway",)).values())
