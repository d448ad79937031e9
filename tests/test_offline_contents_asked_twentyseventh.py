"""A container's contents asked as questions ("Is there still water in the kettle?", "Has the
watering can still got water in it?") and in a note's shorthand with the subject left out
("Still got water in? Leave it.", "got water in?"), and a bare "in" ending its clause ("if the
kettle's got water in, ..."), from the twenty-seventh session (dev 46's Scout kit store): read as
"is the kettle full?" as the statement forms were (`analysis._contents`, `_CONTENTS_ASKED`,
`_HAS_IN_ASKED`, `_GOT_IN`, `_IN_END`). Rows written here in other registers before the rule and
measured then: 0 of 6 (near misses held); after: 6 of 6. Near misses: a thing in a container and
"Got your keys?" ask no filling."""

from __future__ import annotations

import pytest
from reading import factors

#: (text, rooms, a word of the container's role)
ASKED = [
    ("WATER BUCKET - it's on the floor by the door. Still got water in? Leave it. Otherwise, up on the shelves.",
     ("store",), "bucket"),
    ("Is there still water in the kettle? Pour it away into the sink.", ("kitchen",), "kettle"),
    ("Has the watering can still got water in it? Leave it by the door.", ("conservatory",), "watering_can"),
    ("The vase - got water in? Top it up. If not, fill it at the sink.", ("hall",), "vase"),
    ("If the kettle's got water in, empty it into the sink.", ("kitchen",), "kettle"),
    ("Is there any water left in the bucket? Tip it out.", ("yard",), "bucket"),
]


@pytest.mark.parametrize(("text", "rooms", "thing"), ASKED)
def test_the_contents_asked_are_its_filling(text: str, rooms: tuple[str, ...], thing: str) -> None:
    asked = factors(text, rooms)
    assert any(thing in fid and any("filled)" in v for v in values) for fid, values in asked.items()), asked


@pytest.mark.parametrize("text", ["Is there a mug in the sink? Wash it.", "Got your keys? Lock the door."])
def test_no_filling_without_a_liquid(text: str) -> None:
    assert not any("filled)" in v for values in factors(text, ("kitchen",)).values() for v in values)
