"""A frequency adverb between "is" and a participle of leaving ("The mug is sometimes left on the
desk. If so, ...") makes a habit, as "Sometimes the mug is left on the desk" did: the place is
asked. The readers test the habit's words on `lexicon.tokens`, which singularise "sometimes" to
"sometime" and "always" to "alway", so the sets hold both forms (`sentences.FREQUENCY`,
`NORM_ADVERBS`); an adverb of a norm with a participle of leaving a thing carelessly ("is always
dropped on the floor") is a habit too (`sentences.habitual`). From the thirty-first session (a
wedding venue's bridal suite card in development set 55: "the bride's bouquet gets left on the
dressing table ... If it has, ..."; while testing, "is sometimes left" read nothing at all). Rows
written here in other registers before the rule and measured then: 2 of 6; after: 5 of 6 (the
scarf "left on the hook", a holder it may live on, still reads nothing: a strict xfail). Near
misses: a home with an adverb of a norm ("is always kept on the counter", "is usually on the
shelf") stays placed."""

from __future__ import annotations

import pytest
from reading import factors, placed

#: (text, rooms, the place asked)
HABITS = [
    ("The mug is sometimes left on the desk. If so, take it to the sink.", ("office",), "on(mug, desk)"),
    ("The bouquet is sometimes forgotten on the bench. If so, put it in the vase.", ("chapel",),
     "on(flower, bench)"),
    ("The remote is always dropped on the floor by the kids. If so, back on the stand.", ("lounge",),
     "on(remote_control, floor)"),
    ("A towel is occasionally left on the floor. Hang it up if so.", ("bathroom",), "on(towel, floor)"),
    pytest.param("The scarf is sometimes left on the hook. When it is, put it in the drawer.", ("cloakroom",),
                 "on(scarf, coat_hook)", marks=pytest.mark.xfail(strict=True, reason="a hook it may live on")),
    ("Cups are often left in the sink; wash them if they are.", ("kitchen",), "inside(cup, sink)"),
]

#: (text, rooms, the home placed)
HOMES = [
    ("The kettle is always kept on the counter.", ("kitchen",), "on(kettle, kitchen_counter)"),
    ("The book is usually on the shelf.", ("study",), "on(book, bookshelf)"),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), HABITS)
def test_a_habit_with_an_adverb_after_be_asks_the_place(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in set().union(set(), *factors(text, rooms).values())


@pytest.mark.parametrize(("text", "rooms", "fact"), HOMES)
def test_a_norm_of_keeping_stays_a_home(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)
    assert fact not in set().union(set(), *factors(text, rooms).values())
