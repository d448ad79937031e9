"""Two dictionary names the catalog and WordNet's table lacked, from the twenty-ninth session:
"shelving" (Oxford: "shelves collectively"; in dev 47's mountain rescue kit room and dev 49's
coffee roastery and cheesemaker's make sheet) for the shelving unit, and "standard lamp" (Oxford,
British: "a tall lamp set on the floor") for the floor lamp (dev 50's Quaker meeting house): the
reader's own vocabulary (`vocabulary.DICTIONARY_NAMES`), appended to the reading catalog's synonyms
beside WordNet's names (but lending their heads, as the catalog's own names do); catalog.json,
the judge and the prompts keep the catalog's names (a synonym there would change the catalog's
fingerprint, which keys every shipped mutant list). Rows written here in other registers before
the change and measured then: 1 of 6; after: 6 of 6. "Wash basket" (British for a laundry basket)
was tried too and withdrawn: it made "the basket for the wash" a laundry basket where dev 31's
site diary means a basket (a development task fell)."""

from __future__ import annotations

import pytest
from reading import kinds

#: (text, rooms, the kind named)
NAMES = [
    ("Put the paint tins back on the shelving in the garage.", ("garage",), "shelving_unit"),
    ("Boots go on the bottom of the shelving, helmets on top.", ("drying_room",), "shelving_unit"),
    ("If a box is on the floor, lift it up onto the shelving.", ("stockroom",), "shelving_unit"),
    ("Standard lamp in the corner: switch it off if it's on.", ("parlour",), "floor_lamp"),
    ("Gran's standard lamp is by the sofa; leave it on for her.", ("front_room",), "floor_lamp"),
    ("The standard lamps by the piano - are they on? Off they go.", ("music_room",), "floor_lamp"),
]


@pytest.mark.parametrize(("text", "rooms", "kind"), NAMES)
def test_a_dictionary_name_names_its_kind(text: str, rooms: tuple[str, ...], kind: str) -> None:
    assert kind in kinds(text, rooms), kinds(text, rooms)
