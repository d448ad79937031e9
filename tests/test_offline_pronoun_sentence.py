"""A pronoun standing for the subject of an earlier sentence (offline.placement, issue 47): the
subject's words are read in its own sentence. Found by a helper on a dev 16 text, where "it" after
a long sentence raised IndexError in `placement._roles`; two texts of other rooms and registers
reproduce it without the fix."""

from __future__ import annotations

import pytest
from reading import placed


@pytest.mark.parametrize(("text", "rooms", "things"), [
    ("We have a blue mug and a green mug. Our long weekend at the coast is finally over and the mugs are on the "
     "counter. They're kept in the cabinet.", ("kitchen",), ("blue_mug", "green_mug")),
    ("There's a red towel and a white towel, right? So after my shower this morning, as per usual, both of the towels "
     "are lying on the floor. They're kept in the cabinet.", ("bathroom",), ("red_towel", "white_towel")),
])
def test_a_pronoun_for_an_earlier_plural_subject_reads_that_subject_in_its_own_sentence(
        text: str, rooms: tuple[str, ...], things: tuple[str, ...]) -> None:
    """"They're kept in ..." with no thing of its own takes the last statement's subject, a mention
    of an earlier, longer sentence: its words are read in that sentence (they indexed the short one
    and raised IndexError), and the stated place of each thing stands."""
    facts = placed(text, rooms)
    assert all(any(f.startswith(("on(" + t + ",", "inside(" + t + ",")) for f in facts) for t in things)
