"""A spare word before a modifier that names no kind and a noun that does ("the spare club
towel", "a spare guest pillow"), from the twenty-seventh session (dev 46's swimming club
pack-down sheet): "spare" is the noun's adjective, so the noun names a spare of its own kind
(`naming._Reader.spare_word_before`, `spare_before_head`), not a spare of the thing named before
it, as "fetch a spare" does. Rows written here in other registers before the rule and measured
then: 1 of 6 (the torch, by its own kind); after: 6 of 6. Near misses: a spare as a noun still
takes up the thing named before it."""

from __future__ import annotations

import pytest
from reading import named

#: (text, rooms, the spare's kind, a kind that must have no spare (None: any))
SPARES = [
    ("The laptop is on the table. The spare club towel is on the bench.", ("team_room",), "towel", "laptop"),
    ("Mug by the sink. There's a spare guest pillow on the sofa bed.", ("den",), "pillow", "mug"),
    ("Leave the kettle on. The spare staff mug lives in the cupboard.", ("staff_room",), "mug", "kettle"),
    ("Phone charger in the drawer; a spare gym towel hangs on the hook.", ("locker_room",), "towel", "charger"),
    ("The torch is on the shelf, the spare emergency torch in the drawer.", ("cellar",), "flashlight", None),
    ("Cup's on the desk. A spare loan laptop sits in the cabinet.", ("office",), "laptop", "cup"),
]
#: near misses: "a spare" as a noun, the spare of the thing named before it
NOUN_SPARES = [
    ("The bulb has blown. Fetch a spare from the drawer.", ("hall",), "light_bulb"),
    ("The toilet roll is nearly gone; a spare is in the vanity.", ("bathroom",), "toilet_paper"),
]


@pytest.mark.parametrize(("text", "rooms", "kind", "unspared"), SPARES)
def test_the_spare_is_of_the_noun_after_the_modifier(text: str, rooms: tuple[str, ...], kind: str,
                                                      unspared: str | None) -> None:
    got = named(text, rooms)
    spares = {name: category for name, (category, _) in got.items() if name.startswith("spare_")}
    assert kind in spares.values(), got
    assert unspared is None or not any(unspared in name for name in spares), got


@pytest.mark.parametrize(("text", "rooms", "kind"), NOUN_SPARES)
def test_a_spare_as_a_noun_takes_up_the_thing_before(text: str, rooms: tuple[str, ...], kind: str) -> None:
    got = named(text, rooms)
    assert any(name.startswith("spare_") and category == kind for name, (category, _) in got.items()), got
