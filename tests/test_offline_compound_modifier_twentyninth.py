"""A word of order in a name ("first" of "first aid box", which says what aid, not what box),
from the twenty-ninth session (dev 48's charity shop day book: "Any box sitting on the floor ... so
we can get at it first thing" named a first aid kit). Said alone elsewhere in the text ("first
thing", "do that first") or before the head ("the first box on the trolley") it is an order or a
time and hints nothing of a kind whose name holds it (`lexicon.ORDER_WORDS`,
`naming._Reader.dropped_modifiers` and `bare_noun`'s scoring). Rows written here in other registers
before the rule and measured then: 3 of 6; after: 6 of 6. Near misses: the whole name, or "first
aid" said before "the box", still names the kit."""

from __future__ import annotations

import pytest
from reading import named

#: (text, rooms): a box that is no first aid kit, with "first" said as an order or a time
ORDINAL = [
    ("First thing tomorrow, check the box by the door. If it's open, close it.", ("storeroom",)),
    ("Any box left on the floor - put it on the shelf. Do that first, before the till.", ("back_office",)),
    ("The box of leaflets is on the desk. If it is open, shut it first.", ("parish_office",)),
    ("1st job: the first box on the trolley goes on the counter.", ("goods_in",)),
    ("The box is on the bench. First of all, if it's open, close it.", ("potting_shed",)),
    ("Please, first you check the box on the table: if open, you close it.", ("tack_room",)),
]


@pytest.mark.parametrize(("text", "rooms"), ORDINAL)
def test_first_alone_names_no_first_aid_kit(text: str, rooms: tuple[str, ...]) -> None:
    kinds = {category for category, _ in named(text, rooms).values()}
    assert "first_aid_kit" not in kinds and kinds & {"cardboard_box", "storage_box", "box"}, kinds


@pytest.mark.parametrize("text", [
    "The first aid box is in the van. If the box is open, close it.",
    "First aid: the box is on the shelf by the sink. If it's open, shut it.",
])
def test_the_whole_modifier_still_names_the_kit(text: str) -> None:
    assert "first_aid_kit" in {category for category, _ in named(text, ("storeroom",)).values()}
