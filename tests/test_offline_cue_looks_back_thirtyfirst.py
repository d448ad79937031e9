"""A cue of somewhere else ("anywhere else", "elsewhere", "somewhere else") speaks of the things
named up to the end of its sentence, never of one named only after it: "Torch on the desk? Hang it
up. Anywhere else, leave it. The first aid kit is kept on the shelf." keeps the kit's home a
settled fact instead of asking whether the kit is on the shelf (`analysis._elsewhere_cued`). A role
said by some of its words only ("the soap" of soap_bar) is found by them. From the thirty-first
session (a youth hostel's handover note in development set 55, whose first aid kit was asked and
placed at once, so half of its environments broke the placement). Rows written here in other
registers before the rule and measured then: 1 of 6; after: 6 of 6. Near misses: a home said
before its cue ("The remote is kept on the stand. If it is anywhere else, put it back.") is still
asked."""

from __future__ import annotations

import pytest
from reading import factors, placed

#: (text, rooms, the home stated after the cue)
AFTER_THE_CUE = [
    ("If the torch is on the desk, hang it on its hook. Anywhere else, leave it. The first aid kit is "
     "kept on the shelf.", ("reception",), "on(first_aid_kit, wall_shelf)"),
    ("Remote on the sofa? Back on the stand. Elsewhere - don't bother.\nThe soap lives in the cabinet.",
     ("lounge",), "inside(soap_bar, cabinet)"),
    ("Should the mug be on the desk, wash it; if it's somewhere else, leave it. The kettle is kept on "
     "the counter.", ("office",), "on(kettle, kitchen_counter)"),
    ("Book on the armchair = shelf it. Anywhere else: ignore. Our scarf is kept in the drawer.",
     ("den",), "inside(scarf, drawer)"),
    ("Hat on the floor? Hang it up. If it's anywhere else, fine. The key usually stays in the bowl.",
     ("hall",), "inside(keys, bowl)"),
    ("If the remote is on the sofa, put it on the stand. Anywhere else, leave it. The first aid kit "
     "lives in the cabinet.", ("lounge",), "inside(first_aid_kit, cabinet)"),
]

#: (text, rooms, the home stated before the cue, still asked)
BEFORE_THE_CUE = [
    ("The remote is kept on the stand. If it is anywhere else, put it back.", ("lounge",),
     "on(remote_control, tv_stand)"),
    ("The towel lives on the rail; if you find it anywhere else, hang it back.", ("bathroom",),
     "on(towel, towel_rack)"),
    ("The soap lives in the cabinet; if you find it anywhere else, put it back.", ("bathroom",),
     "inside(soap_bar, cabinet)"),
]


@pytest.mark.parametrize(("text", "rooms", "home"), AFTER_THE_CUE)
def test_a_home_said_after_the_cue_stays_settled(text: str, rooms: tuple[str, ...], home: str) -> None:
    assert home in placed(text, rooms)
    conditions = set().union(*factors(text, rooms).values())
    assert home not in conditions, conditions


@pytest.mark.parametrize(("text", "rooms", "home"), BEFORE_THE_CUE)
def test_a_home_said_before_its_cue_is_asked(text: str, rooms: tuple[str, ...], home: str) -> None:
    assert home in set().union(*factors(text, rooms).values())
