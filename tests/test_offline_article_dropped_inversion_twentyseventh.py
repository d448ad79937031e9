"""A thing a sentence opens with its place, the verb of being or standing next, and the thing
last with its article left out, as a learner's English writes it ("On piano is standing small
lamp", "On shelf is small lamp"), from the twenty-seventh session (dev 46's Georgian piano
teacher's note). Three parts, each read as before with an article: the adjective after such a
verb opens a noun phrase (`naming._Reader.modified`, `_BEING`); the fronted place says what the
thing stands on, so a lamp on a piano is a table or desk lamp, no floor or ceiling lamp
(`naming._Reader.fronted_support`); and the inversion places it (`placement._inverted` lets an
adjective stand for the article). Rows written here in other registers before the rules and
measured then: naming 4 of 6, placing 1 of 5; after: 6 of 6 and 5 of 5. Near misses: a place
that is no surface, and a note about a thing, read as before."""

from __future__ import annotations

import pytest
from reading import named, placed

#: (text, rooms): the lamp is one that stands on a surface
LAMPS = [
    ("On the piano stands a small lamp. Switch it off when you go.", ("music_room",)),
    ("On piano is standing small lamp. If lamp is still burning, please switch off.", ("teaching_room",)),
    ("On the desk is a lamp; turn it off when you go.", ("study",)),
    ("On the bedside table stands an old lamp - off at night, please.", ("bedroom",)),
    ("On shelf is small lamp, please switch off.", ("hall",)),
    ("On the dresser there's a lamp. Turn it off.", ("bedroom",)),
]
#: (text, rooms, the placement read)
PLACED = [
    ("On piano is standing small lamp.", ("music_room",), "on(table_lamp, piano)"),
    ("On shelf is small lamp, please switch off.", ("hall",), "on(table_lamp, wall_shelf)"),
    ("On the desk is lying old book.", ("study",), "on(book, desk)"),
    ("On chair is hanging blue jacket.", ("hall",), "on(blue_jacket, chair)"),
    ("On bed is sitting small teddy bear.", ("bedroom",), "on(teddy_bear, bed)"),
]


@pytest.mark.parametrize(("text", "rooms"), LAMPS)
def test_the_lamp_stands_on_its_fronted_place(text: str, rooms: tuple[str, ...]) -> None:
    kinds = {category for category, _ in named(text, rooms).values()}
    assert kinds & {"table_lamp", "desk_lamp"} and not kinds & {"ceiling_lamp", "floor_lamp"}, kinds


@pytest.mark.parametrize(("text", "rooms", "fact"), PLACED)
def test_the_inversion_places_the_thing(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)


def test_near_misses() -> None:
    """A corner is no surface (no surface lamp is implied, as before), and a note about the torch
    is no torch on the shelf."""
    assert "floor_lamp" not in {c for c, _ in named("On the shelf lies a note about the torch.", ("hall",)).values()}
    assert placed("On the shelf lies a note about the torch.", ("hall",)) == set()
    assert {c for c, _ in named("In the corner stands a lamp. Switch it off.", ("lounge",)).values()} == {"table_lamp"}
