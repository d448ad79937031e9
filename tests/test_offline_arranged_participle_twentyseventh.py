"""A participle of how a thing lies between the verb and its place ("A towel is left folded on the
bench", "The scarf was found scrunched in the basket", "is lying folded on the sofa"), from the
twenty-seventh session (dev 42's cleanroom gowning notice): read as the verb group's adverb, so
the verb before it places the thing (`placement.ARRANGED`, `_verb_group`, `_verb_kind`). After a
plain "is" / "are" alone it is still what is done to things, a rule ("Towels are folded on the
bench by size", as the fallback's near miss "Books are stacked on the shelf by colour"). Rows
written here in other registers before the rule and measured then: 1 of 6 (near misses held);
after: 6 of 6."""

from __future__ import annotations

import pytest
from reading import placed

#: (text, rooms, the placement read)
ARRANGED = [
    ('A towel is left folded on the bench.', ('changing_room',), 'on(towel, bench)'),
    ('The blanket is lying folded on the sofa.', ('lounge',), 'on(blanket, sofa)'),
    ('Two towels were left crumpled on the floor.', ('bathroom',), 'on(towel, floor)'),
    ('The newspapers have been left stacked on the chair.', ('study',), 'on(newspaper, chair)'),
    ('The scarf was found scrunched in the basket.', ('hall',), 'inside(scarf, basket)'),
    ('His jacket sits folded on the armchair.', ('lounge',), 'on(jacket, armchair)'),
]
#: near misses: an instruction, a rule, a norm (text, rooms, a placement not read)
NEAR = [
    ('Fold the towel on the bench.', ('changing_room',), 'on(towel, bench)'),
    ('Towels are folded on the bench by size.', ('changing_room',), 'on(towel, bench)'),
    ('The towel should be folded on the bench.', ('changing_room',), 'on(towel, bench)'),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), ARRANGED)
def test_how_it_lies_does_not_hide_where(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), NEAR)
def test_near_misses_place_nothing(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact not in placed(text, rooms)
