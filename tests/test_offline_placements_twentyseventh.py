"""Three placement rules of the twenty-seventh session, one table each, written in other
registers before its rule and measured then, with near misses that must read as before.

A place whose name begins with a word of state ("on the open shelves": the catalog's name of a
shelving unit), from the twenty-seventh session (dev 46's Scout kit store): the state word begins
the name, so it is not skipped as a modifier before the place (`placement._holder_after`). Rows
written here in other registers before the rule and measured then: 0 of 6; after: 6 of 6 (three
first drafts named things the catalog has no kind for, a radio and a ledger, and were replaced by
things it names). Near misses: a state word before a name it does not begin ("the open box", "the
clean table") still reads the place as before.

Supplies "are stocked in" a place, as a shop or a store room says where they are kept, from the
twenty-seventh session (dev 45's sleeper train card): "stock" joins the verbs of keeping
(`placement.KEEP_VERBS`). Rows written here in other registers before the rule and measured then: 2
of 6; after: 6 of 6. Near misses: a condition ("if the cabinet is stocked") places nothing, and
"stock the fridge with milk" reads as before.

A room that "has" things in a clause joined to another ("your dining room opens onto the kitchen,
and the kitchen has a sink"), from the twenty-seventh session (dev 45's removal firm's e-mail): the
subject is the noun before "has" in its own clause, after the joining word, when a verb stands
before that word (`placement._joined_clause`). Rows written here in other registers before the rule
and measured then: 2 of 6; after: 6 of 6. Near misses: a subject joined by "and" with no verb
before it ("the kitchen and the pantry have ...") and two "has" clauses read as before."""

from __future__ import annotations

import pytest
from reading import placed

#: (text, rooms, the placement read)
NAMED_HOLDERS = [
    ('The brush is on the open shelves, second shelf down.', ('store_room',), 'on(scrub_brush, shelving_unit)'),
    ('Spare bulbs sit on the open shelves by the door.', ('garage',), 'on(spare_bulb, shelving_unit)'),
    ('A pile of towels is lying on the open shelf in the corner.', ('changing_room',), 'on(towel, shelving_unit)'),
    ('Our kettle lives on the open shelves next to the cooker.', ('galley',), 'on(kettle, shelving_unit)'),
    ('The book has been left on the open shelves again.', ('office',), 'on(book, shelving_unit)'),
    ("FYI the mug's on the open shelves rn", ('workshop',), 'on(mug, shelving_unit)'),
]

#: near misses: what they read before the rule
NAMED_HOLDER_NEAR = [
    ('The cup is in the open box.', ('store_room',), 'inside(cup, cardboard_box)'),
    ('The book is on the wooden shelf.', ('store_room',), 'on(book, bookshelf)'),
    ('The mug is on the clean table.', ('kitchen',), 'on(mug, dining_table)'),
]

#: (text, rooms, the placement read)
STOCKED = [
    ('Spare rolls are stocked in the vanity unit under the basin.', ('bathroom',), 'inside(spare_roll, bathroom_vanity)'),
    ('Spare bulbs are stocked in the hall cupboard.', ('hall',), 'inside(spare_bulb, cabinet)'),
    ('The tins are stocked in the pantry cupboard, top shelf.', ('kitchen',), 'inside(food_can, cabinet)'),
    ('We stock the spare candles in the desk drawer.', ('office',), 'inside(spare_candle, drawer)'),
    ('Spare candles are stocked on the wall shelf above the altar.', ('chapel',), 'on(spare_candle, wall_shelf)'),
    ('The first aid kit is always kept stocked and lives in the cabinet.', ('office',), 'inside(first_aid_kit, cabinet)'),
]

#: near misses: None when nothing is placed
STOCKED_NEAR = [
    ('If the cabinet is stocked, close it.', ('kitchen',), None),
    ('Stock the fridge with milk.', ('kitchen',), 'inside(milk_carton, fridge)'),
]

#: (text, rooms, a placement read)
JOINED = [
    ('Your dining room opens onto the kitchen, and the kitchen has a sink.', ('dining_room', 'kitchen'), 'in_room(sink, kitchen)'),
    ('We painted the study last year and the study has a desk by the window.', ('study', 'hall'), 'in_room(desk, study)'),
    ('Guests come in through the porch and the lounge has a sofa and a coffee table.', ('porch', 'lounge'), 'in_room(sofa, lounge)'),
    ('Mum sleeps downstairs now, so the bedroom has a wardrobe and a bed.', ('bedroom', 'hall'), 'in_room(wardrobe, bedroom)'),
    ('The flat is tiny but the bathroom has a bathtub and a towel rack.', ('bathroom', 'hall'), 'in_room(bathtub, bathroom)'),
    ('I tidied the hall yesterday, and the bedroom has a dresser.', ('bedroom', 'hall'), 'in_room(dresser, bedroom)'),
]

#: near misses: None when nothing is placed
JOINED_NEAR = [
    ('The kitchen and the pantry have a shelf.', ('kitchen', 'pantry'), None),
    ('The bedroom has a bed and a wardrobe.', ('bedroom', 'hall'), 'in_room(bed, bedroom)'),
    ('The desk has a lamp and the shelf has a book.', ('study',), 'on(book, bookshelf)'),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), NAMED_HOLDERS + STOCKED + JOINED)
def test_the_place_is_read(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), NAMED_HOLDER_NEAR + STOCKED_NEAR + JOINED_NEAR)
def test_near_misses_read_as_before(text: str, rooms: tuple[str, ...], fact: str | None) -> None:
    got = placed(text, rooms)
    assert fact in got if fact is not None else not got
