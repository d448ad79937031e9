"""A place whose name begins with a word of state ("on the open shelves": the catalog's name of a
shelving unit), from the twenty-seventh session (dev 46's Scout kit store): the state word begins
the name, so it is not skipped as a modifier before the place (`placement._holder_after`). Rows
written here in other registers before the rule and measured then: 0 of 6; after: 6 of 6 (three
first drafts named things the catalog has no kind for, a radio and a ledger, and were replaced by
things it names). Near misses: a state word before a name it does not begin ("the open box", "the
clean table") still reads the place as before."""

from __future__ import annotations

import pytest
from reading import placed

#: (text, rooms, the placement read)
HOLDERS = [
    ('The brush is on the open shelves, second shelf down.', ('store_room',), 'on(scrub_brush, shelving_unit)'),
    ('Spare bulbs sit on the open shelves by the door.', ('garage',), 'on(spare_bulb, shelving_unit)'),
    ('A pile of towels is lying on the open shelf in the corner.', ('changing_room',), 'on(towel, shelving_unit)'),
    ('Our kettle lives on the open shelves next to the cooker.', ('galley',), 'on(kettle, shelving_unit)'),
    ('The book has been left on the open shelves again.', ('office',), 'on(book, shelving_unit)'),
    ("FYI the mug's on the open shelves rn", ('workshop',), 'on(mug, shelving_unit)'),
]

#: near misses: what they read before the rule
NEAR = [
    ('The cup is in the open box.', ('store_room',), 'inside(cup, cardboard_box)'),
    ('The book is on the wooden shelf.', ('store_room',), 'on(book, bookshelf)'),
    ('The mug is on the clean table.', ('kitchen',), 'on(mug, dining_table)'),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), HOLDERS)
def test_the_place_is_read(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), NEAR)
def test_near_misses_read_as_before(text: str, rooms: tuple[str, ...], fact: str | None) -> None:
    got = placed(text, rooms)
    assert fact in got if fact is not None else not got
