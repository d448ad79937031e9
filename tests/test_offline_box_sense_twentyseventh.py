"""A box the text names by a modifier no kind's name holds ("the comics box", "the lost property
box", "the props box") is a box in the general sense, a container for storing things (Oxford's
first sense): the catalog's storage box (`naming.HEAD_SENSES`), as a "card table" is a table; a
cardboard box is named for its material, a toy box for its use, and a bare "box" stays the
catalog's synonym, a cardboard box. The modifier may be a compound of two words
(`_Reader.compound_modified`: "the lost property box"). From the twenty-seventh session (dev 45's
station closing-down book, dev 46's swimming club sheet and library close: their ground truths
call such boxes storage boxes). Rows written here in other registers before the rule and measured
then: 0 of 6 (near misses held); after: 4 of 6 (a modifier the lemmatiser also knows as an
adjective, "the prize box", and a hyphenated one, "the lost-and-found box", still read a
cardboard box: `NOT_YET`).

A bracket or a comma that says which sort the thing is by "the <modifier> one" ("the lost
property box (the cardboard one under the table)", "the basket, the laundry one") names that sort
when the modifier and the thing's word are a catalog name (`_Reader.one_glossed`); "(the red one)"
says which, not what, and keeps the reading. Rows written before that rule and measured then
(after the first): 2 of 6; after: 6 of 6."""

from __future__ import annotations

import pytest
from reading import named

#: (text, rooms, the box's kind)
BOXES = [
    ('Any caps left behind go in the lost property box.', ('team_room',), 'storage_box'),
    ('Comics go back in the comics box by the beanbags.', ('library',), 'storage_box'),
    ('Leave the medals in the medal box on the shelf.', ('clubhouse',), 'storage_box'),
    ('Props go back in the props box after the show.', ('green_room',), 'storage_box'),
]
#: modifiers not read yet (still a cardboard box): an adjective too, a hyphenated compound
NOT_YET = [
    ('The raffle prizes are in the prize box under the stage.', ('hall',), 'storage_box'),
    ('Unclaimed gloves: into the lost-and-found box, please.', ('lobby',), 'storage_box'),
]
#: near misses: (text, rooms, the kind read before the rule); a box its sentence opens or shuts
#: stays an openable kind (the catalog's storage box has no lid: `naming._OPENING`)
NEAR = [
    ("If the props box is open, shut it.", ("green_room",), "cardboard_box"),
    ("An open craft box on the desk? Close it.", ("bedroom",), "cardboard_box"),
    ('Put it in the box.', ('hall',), 'cardboard_box'),
    ('Put it in the cardboard box.', ('hall',), 'cardboard_box'),
    ('Put it in the toy box.', ('hall',), 'toy_box'),
    ('Put it in the storage box.', ('hall',), 'storage_box'),
    ('Put the mug on the kitchen table.', ('kitchen',), 'dining_table'),
]
#: (text, rooms, the gloss's kind, the first reading that must not stay)
GLOSSED = [
    ('Caps go in the lost property box (the cardboard one under the table).', ('store',), 'cardboard_box', 'storage_box'),
    ('Put the scarf in the props box, the cardboard one by the door.', ('green_room',), 'cardboard_box', 'storage_box'),
    ('Spare bulbs live in the box (the storage one in the loft).', ('landing',), 'storage_box', 'cardboard_box'),
    ('Leave the mugs on the table (the coffee one, not the dining one).', ('lounge',), 'coffee_table', 'dining_table'),
    ('Stick it in the basket, the laundry one.', ('utility_room',), 'laundry_basket', 'basket'),
    ("Hang the towel over the rack (the drying one) when it's wet.", ('bathroom',), 'drying_rack', 'towel_rack'),
]
#: near misses: (text, rooms, the kind read before the rule)
NOT_GLOSSED = [
    ('Put it in the box (the red one).', ('hall',), 'cardboard_box'),
    ('Switch off the lamp, the old one by the bed.', ('bedroom',), 'table_lamp'),
]


def _kinds(text: str, rooms: tuple[str, ...]) -> set[str]:
    return {category for category, _ in named(text, rooms).values()}


@pytest.mark.parametrize(("text", "rooms", "kind"), BOXES)
def test_a_box_named_for_what_it_holds_is_a_storage_box(text: str, rooms: tuple[str, ...], kind: str) -> None:
    kinds = _kinds(text, rooms)
    assert kind in kinds and "cardboard_box" not in kinds, kinds


@pytest.mark.xfail(strict=True, reason="a modifier that is an adjective too, or hyphenated, is not read as the box's sort yet")
@pytest.mark.parametrize(("text", "rooms", "kind"), NOT_YET)
def test_modifiers_not_read_yet(text: str, rooms: tuple[str, ...], kind: str) -> None:
    kinds = _kinds(text, rooms)
    assert kind in kinds and "cardboard_box" not in kinds, kinds


@pytest.mark.parametrize(("text", "rooms", "kind"), NEAR + NOT_GLOSSED)
def test_near_misses_read_as_before(text: str, rooms: tuple[str, ...], kind: str) -> None:
    assert kind in _kinds(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "kind", "guess"), GLOSSED)
def test_the_one_gloss_names_the_sort(text: str, rooms: tuple[str, ...], kind: str, guess: str) -> None:
    kinds = _kinds(text, rooms)
    assert kind in kinds and guess not in kinds, kinds
