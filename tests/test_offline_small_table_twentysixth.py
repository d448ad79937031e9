"""Two readings of "small table", from the twenty-sixth session (dev 43's carer's note, "His water
bottle is on small table near his chair"):

- the sort the dictionary describes by an adjective of a `HEAD_SENSES` head ("side table: a small
  table", "coffee table: a low table"; Oxford) is the kind the head names, before the kinds of the
  task's known rooms (`naming.SORT_SENSES`); measured on its table before the rule: 2 of 5, after:
  5 of 5;
- after a preposition, an adjective with the article left out ("on small table", "on low table in
  front of sofa"), as learners' English and notes write it, opens a noun phrase as "the small
  table" does (`naming._Reader.modified`); before: 2 of 5, after: 4 of 5 (a shelf left, xfail).
The rows were written here in other registers before the rules."""

from __future__ import annotations

import pytest
from reading import named, placed

#: (text, rooms, the kind the described head names)
SORTS = [
    ("His water bottle is on the small table near his chair.", ("front_room",), "side_table"),
    ("The keys are on the little table by the door.", ("living_room",), "side_table"),
    ("Leave the remote on the low table in front of the sofa.", ("den",), "coffee_table"),
    ("Grandma's glasses are on the tiny table next to her bed.", ("bedroom",), "side_table"),
    ("Put the plant on the small table by the window.", ("study",), "side_table"),
]


@pytest.mark.parametrize(("text", "rooms", "kind"), SORTS)
def test_an_adjective_names_the_sort_it_defines(text: str, rooms: tuple[str, ...], kind: str) -> None:
    assert kind in {category for category, _ in named(text, rooms).values()}


@pytest.mark.parametrize(("text", "rooms", "kind"), [
    ("The small table in the kitchen has the fruit bowl on it.", ("kitchen",), "dining_table"),
    ("The post is on a sturdy table by the stairs.", ("hallway",), "console_table"),
])
def test_other_tables_are_read_as_before(text: str, rooms: tuple[str, ...], kind: str) -> None:
    """Near misses, read as before the rules: the kitchen's table, and an adjective that defines
    no sort (the hallway's own kind)."""
    assert kind in {category for category, _ in named(text, rooms).values()}


#: (text, rooms, the thing placed, the kind it is placed on)
DROPPED = [
    ("His water bottle is on small table near his chair.", ("front_room",), "water_bottle", "side_table"),
    ("Keys are on little table by door, always.", ("hall",), "keys", "side_table"),
    ("Phone is on big desk in the office.", ("office",), "cell_phone", "desk"),
    ("Remote is on low table in front of sofa, please leave there.", ("lounge",), "remote_control", "coffee_table"),
    pytest.param("Her book is on wooden shelf above the bed.", ("bedroom",), "book", "shelf",
                 marks=pytest.mark.xfail(strict=True, reason="the shelf's kinds are not told apart here")),
]


@pytest.mark.parametrize(("text", "rooms", "thing", "kind"), DROPPED)
def test_an_adjective_without_its_article_opens_a_noun_phrase(text: str, rooms: tuple[str, ...], thing: str,
                                                              kind: str) -> None:
    objects = named(text, rooms)
    holders = [name for name, (category, _) in objects.items() if kind in category]
    assert holders and f"on({thing}, {holders[0]})" in placed(text, rooms), (objects, placed(text, rooms))
