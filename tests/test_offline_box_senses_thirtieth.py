"""The storage box means WordNet's box ("a (usually rectangular) container; may have a lid"), so the
kinds of box WordNet lists under it name a storage box ("crate", "toolbox", "cashbox", "strongbox",
"packing case", "tea chest"), from the thirtieth session (dev 48's market stall texts, "Any empty
crate left on the floor", and dev 52's teaching lab's lost property crate named nothing): the
sense is added to `benchmark_data/wordnet_senses.json` and `tools/wordnet_names.py` rebuilt
`offline/wordnet_names.json` (31 words; the carton stays the cardboard box's, whose own sense the
walk does not enter). Rows written here in other registers before the change and measured then: 0
of 6; after: 6 of 6."""

from __future__ import annotations

import pytest
from reading import factors, kinds

from logicenveval.offline.wordnet import wordnet_names

#: (text, rooms, the condition asked of the box)
BOXES = [
    ("Any empty crate left on the floor goes on the shelf.", ("store",), "on(storage_box, floor)"),
    ("The toolbox lives under the bench; if it's open, shut it.", ("workshop",), "state(storage_box, open)"),
    ("Lock the cashbox in the drawer if it's on the counter.", ("shop",), "on(storage_box, kitchen_counter)"),
    ("If the strongbox is open, close it.", ("office",), "state(storage_box, open)"),
    ("Is the packing case still on the floor? Push it against the wall.", ("hall",), "on(storage_box, floor)"),
    ("A tea chest sits by the door; if it's open, close the lid.", ("attic",), "state(storage_box, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "asked"), BOXES)
def test_a_kind_of_box_names_a_storage_box(text: str, rooms: tuple[str, ...], asked: str) -> None:
    assert "storage_box" in kinds(text, rooms)
    assert any(asked in values for values in factors(text, rooms).values())


def test_a_carton_stays_the_cardboard_box() -> None:
    assert wordnet_names().get("carton", "cardboard_box") == "cardboard_box"
    assert "cardboard_box" in kinds("Flatten the carton and put it by the door.", ("hall",))
