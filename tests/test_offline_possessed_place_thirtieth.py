"""A thing's place named by a possessed noun and said with a preposition ("the kettle's usual spot
is on the worktop", "the books' place is on the bookshelf"), from the thirtieth session (dev 51's
stewards' briefing: "the laptop's position is on the desk in the study"): the owner is the
subject, read as "the kettle lives on the worktop" (`sentences._HOME_OF`). With the possessive
dropped the noun of place was the subject: "position" named nothing, so the laptop went unnamed
and its later condition fell on the desk; "spot" named a floor stain placed on the worktop. Rows
written here in other registers before the rule and measured then: 3 of 6 (a pronoun's "its place"
and two plain "place"s already read); after: 6 of 6. Near misses: a place noun with no preposition
after its verb ("the laptop's position is unknown") places nothing; one before its own phrase
("the dog's spot on the rug is dirty") is still a stain."""

from __future__ import annotations

import pytest
from reading import factors, named, placed

#: (text, rooms, the owner's kind, the condition asked of it)
OWNED_PLACES = [
    ("Put the stapler away when you're done. Its place is in the top drawer of the desk. If it's on the chair, "
     "move it to the drawer.", ("study",), "stapler", "on(stapler, chair)"),
    ("The kettle's usual spot is on the worktop. Found on the floor? Put it back on the worktop.", ("kitchen",),
     "kettle", "on(kettle, floor)"),
    ("The torch's proper place is on the shelf in the hall. If it is lying on the floor, pick it up and put it on "
     "the shelf.", ("hallway",), "flashlight", "on(flashlight, floor)"),
    ("The books' place is on the bookshelf. If a book is on the bed, put it back on the shelf.", ("bedroom",),
     "book", "on(book, bed)"),
    ("the laptop's position is on the desk; if found on the sofa move it to the desk", ("living_room",), "laptop",
     "on(laptop, sofa)"),
    ("The remote's normal location is on the coffee table. Should it have slipped down onto the floor, put it back.",
     ("living_room",), "remote_control", "on(remote_control, floor)"),
]


@pytest.mark.parametrize(("text", "rooms", "kind", "asked"), OWNED_PLACES)
def test_the_owner_of_a_place_is_named_and_asked_about(text: str, rooms: tuple[str, ...], kind: str,
                                                        asked: str) -> None:
    got = named(text, rooms)
    assert "floor_stain" not in got, got
    names = [name for name, (category, _) in got.items() if category == kind]
    assert names, got
    conditions = set().union(*factors(text, rooms).values())
    assert any(asked.replace(kind, name) in conditions for name in names), conditions


def test_a_place_noun_with_no_preposition_after_its_verb_places_nothing() -> None:
    assert not placed("The laptop's position is unknown, so check the desk.", ("study",))


def test_a_spot_before_its_own_phrase_is_still_a_stain() -> None:
    assert "floor_stain" in {c for c, _ in named("The dog's spot on the rug is dirty; clean it.",
                                                 ("living_room",)).values()}
