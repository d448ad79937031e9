"""A head of several kinds ("rack": of shoes, coats, towels, keys) told apart by the kinds its own
clause names outright ("Any boot lying about goes back on the racks": a boot is a shoe, so the shoe
rack), and the sentence before's when the clause refers back by a pronoun ("Sneakers kicked off by
the door? Line them up on the rack"), from the thirtieth session (dev 51's ice rink close-down
card, whose "racks" took the key rack from the "Keys" said two lines on): the kind's own name,
not the words written ("stand it on the dish rack" hints no other rack), counts for a kind whose
own name the head heads (`naming._Reader.kinds_said_near`). The clause, not the sentence: a first
form read whole sentences and took two development texts' torch shelves for shoe racks ("I've left
the torch on the shelf charging; if it's still on, ..." with boots a sentence before). Rows written
here in other registers before the rule and measured then: 1 of 6; after: 6 of 6. Near misses:
"Put the boots on the shelf" stays a wall shelf (the shoe rack's "shoe shelf" is only a synonym);
a name written in full hints no other kind."""

from __future__ import annotations

import pytest
from reading import kinds

#: (text, rooms, the kind the head names)
NEAR = [
    ("Sneakers kicked off by the door? Line them up on the rack. The keys go on the key rack.", ("porch",),
     "shoe_rack"),
    ("An overcoat left on a chair goes on the rack. Towels go on the towel rail.", ("cloakroom",), "coat_rack"),
    ("If a flip-flop is on the floor, put it on the rack. The key hook is by the door.", ("beach_hut",), "shoe_rack"),
    ("Any boot lying about goes back on the racks, pairs together. Spare keys hang on the key holder.",
     ("boot_room",), "shoe_rack"),
    ("Wet towel on the floor? Put it on the rack. Your shoes go on the shoe shelf.", ("bathroom",), "towel_rack"),
    ("If the overcoat is on the bed, hang it on the rack. The airer is in the utility room.",
     ("guest_room", "utility_room"), "coat_rack"),
]


@pytest.mark.parametrize(("text", "rooms", "kind"), NEAR)
def test_a_head_of_several_kinds_takes_the_kind_its_sentence_says_it_is_for(text: str, rooms: tuple[str, ...],
                                                                            kind: str) -> None:
    assert kind in kinds(text, rooms)


def test_a_name_written_in_full_hints_no_other_kind() -> None:
    got = kinds("Stand the plate on the dish rack; otherwise it goes up on the shelf.", ("kitchen",))
    assert "dish_rack" in got and not got & {"pantry_shelf", "utility_shelf"}, got
