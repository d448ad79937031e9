"""Forms found while composing in the eighteenth session, not read before (docs/reader.md, "What it
still misreads"). Each structure is a table of sentences written here, in several registers, rooms
and kinds, with near misses that must stay as they are; the tables were measured before the rule
(the counts in each test's docstring).

- a note's thanks or plea ("thx", "ta", "cheers", "thanks", "pls") after an elided condition
  ("unless they're there already, thx"): the condition is read as without it."""

from __future__ import annotations

import pytest
from reading import asks, factors

#: an elided "unless ... already" condition followed by a sign-off: (text, rooms, the condition
#: asked). Before the rule 1 of 7 were asked (only "ta" after "already there")
SIGNED_OFF_ALREADY = [
    # a flatmate's text message
    ("Towels in the basket unless they're there already, thx", ("bathroom",), "inside(towel, basket)"),
    # a house-sitter's note, British thanks
    ("Towels in the basket unless they're there already, cheers", ("bathroom",), "inside(towel, basket)"),
    # a kitchen rota, a full instruction and a full stop after the thanks
    ("Put the cups in the cupboard unless they are there already, thanks.", ("kitchen",), "inside(cup, cabinet)"),
    # a parent's sticky note, the subject dropped
    ("Books on the shelf unless already there, ta", ("bedroom",), "on(book, bookshelf)"),
    # a lodger's chat message, a plea
    ("Keys on the hook unless they are already, pls", ("hallway",), "on(keys, key_hook)"),
    # a café closing list, "thx" after "now"
    ("Mugs in the sink unless they're there now, thx", ("kitchen",), "inside(mug, sink)"),
    # an office note in capitals
    ("LAPTOP IN THE DRAWER UNLESS IT IS THERE ALREADY, CHEERS", ("office",), "inside(laptop, drawer)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), SIGNED_OFF_ALREADY)
def test_a_sign_off_after_an_elided_condition_is_no_part_of_it(text: str, rooms: tuple[str, ...],
                                                                condition: str) -> None:
    assert asks(text, rooms, condition)


#: near misses: a sign-off after an instruction with no elided condition reads as the same
#: instruction without it (nothing asked is added): (with the sign-off, without it, rooms)
SIGNED_OFF_NEAR_MISSES = [
    ("Towels in the basket, thx", "Towels in the basket.", ("bathroom",)),
    ("Put the cups in the cupboard, cheers.", "Put the cups in the cupboard.", ("kitchen",)),
    ("Put the mug in the sink if it is dirty, ta", "Put the mug in the sink if it is dirty.", ("kitchen",)),
]


@pytest.mark.parametrize(("signed", "plain", "rooms"), SIGNED_OFF_NEAR_MISSES)
def test_a_sign_off_elsewhere_changes_nothing(signed: str, plain: str, rooms: tuple[str, ...]) -> None:
    assert factors(signed, rooms) == factors(plain, rooms)
