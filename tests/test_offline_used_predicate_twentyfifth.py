"""That a thing "has been used", said as its clause's predicate ("Used? Then it goes in the laundry
basket", "if it's been used, wash it", "if it was used last night"), asks whether it is dirty, as "a
used towel" says it is; from the twenty-fifth session. The reader read "used" after "be" as the
passive of "use" ("the cloth is used for wiping") and asked nothing, so a barber's close-down
card's towel (dev 40: "Used? Then it goes in the laundry basket") kept no factor. Now "used" is a
state where it ends its clause (its end, a comma, "then"/"and"/"or", an adverbial of time:
`analysis._Reader._used_ends`) and said of a thing one picks up; with a complement ("used for",
"used by", "used as", "used in") it stays the verb. The rows were written here in other registers
(a note, a dash list, a checklist question, a menu card's either-or, an arrow list) before the
rule and measured then (the counts in each test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, the thing asked dirty)
USED = [
    ("There'll be a hot towel on the counter by the basin. Used? Then it goes in the laundry basket.",
     ("shop_floor",), "towel"),
    ("The mug is on the desk. If it's been used, wash it in the sink.", ("study",), "mug"),
    ("Cup on the tray - if it is used, put it in the dishwasher; if not, back in the cabinet.", ("kitchen",), "cup"),
    ("Check the towel on the rail. Has it been used? Into the laundry basket with it.", ("bathroom",), "towel"),
    ("If the cloth has been used, it goes in the wash.", ("kitchen",), "cloth"),
    # read before the rule too: "If used" and an arrow's "Used ->"
    ("The plate on the table: used or clean? If used, into the sink.", ("dining_room",), "plate"),
    ("GLASS (bar end). Used -> glasswasher. Unused -> back on the shelf.", ("kitchen",), "drinking_glass"),
]


@pytest.mark.parametrize(("text", "rooms", "thing"), USED)
def test_used_as_a_predicate_asks_whether_the_thing_is_dirty(text: str, rooms: tuple[str, ...], thing: str) -> None:
    """Measured before the rule: 2 of 7 asked; after: 7 of 7."""
    asked = factors(text, rooms)
    assert any({f"state({thing}, dirty)", f"not state({thing}, dirty)"} <= v for v in asked.values()), asked


@pytest.mark.xfail(strict=True, reason="'it' is taken up by the nearest noun, the bath, which a use does not dirty")
def test_used_of_a_pronoun_after_a_place() -> None:
    asked = factors("The flannel on the bath: if it was used last night, pop it in the laundry basket.", ("bathroom",))
    assert any("state(washcloth, dirty)" in v for v in asked.values()), asked


@pytest.mark.parametrize(("text", "rooms"), [
    # the passive of "use" with its complement: what a thing is for, by whom, as what, where
    ("The cloth is used for wiping the table. If it's wet, hang it on the rail.", ("kitchen",)),
    ("The basket is used to carry the towels. If the towel is wet, hang it on the rail.", ("bathroom",)),
    ("The mug is used by the night staff only. If the lamp is on, switch it off.", ("study",)),
    ("The old towel is used as a mat. If the lamp is on, switch it off.", ("bathroom",)),
    ("The sponge is used in the kitchen only. If the lamp is on, switch it off.", ("kitchen",)),
])
def test_the_passive_of_use_asks_nothing_of_dirt(text: str, rooms: tuple[str, ...]) -> None:
    """Near misses, none asked before or after the rule."""
    assert not any("dirty" in " ".join(v) for v in factors(text, rooms).values())
