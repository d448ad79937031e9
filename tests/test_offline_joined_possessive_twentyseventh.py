"""A room that "has" things in a clause joined to another ("your dining room opens onto the
kitchen, and the kitchen has a sink"), from the twenty-seventh session (dev 45's removal firm's
e-mail): the subject is the noun before "has" in its own clause, after the joining word, when a
verb stands before that word (`placement._joined_clause`). Rows written here in other registers
before the rule and measured then: 2 of 6; after: 6 of 6. Near misses: a subject joined by "and"
with no verb before it ("the kitchen and the pantry have ...") and two "has" clauses read as
before."""

from __future__ import annotations

import pytest
from reading import placed

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
NEAR = [
    ('The kitchen and the pantry have a shelf.', ('kitchen', 'pantry'), None),
    ('The bedroom has a bed and a wardrobe.', ('bedroom', 'hall'), 'in_room(bed, bedroom)'),
    ('The desk has a lamp and the shelf has a book.', ('study',), 'on(book, bookshelf)'),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), JOINED)
def test_the_place_is_read(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), NEAR)
def test_near_misses_read_as_before(text: str, rooms: tuple[str, ...], fact: str | None) -> None:
    got = placed(text, rooms)
    assert fact in got if fact is not None else not got
