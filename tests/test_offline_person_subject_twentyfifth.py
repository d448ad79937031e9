"""A word that is the head of a kind's longer name but also means people ("cleaner" of "vacuum
cleaner"), as the subject of a deed only people do to a thing ("If the cleaners have left it on
overnight", "the cleaner always leaves them open"), names the people, no thing; from the
twenty-fifth session. The
reader named a vacuum cleaner there, and the condition's "it" went to it: dev 42's usher's notes
("If the cleaners have left it on overnight, switch it off") asked whether a vacuum cleaner was on,
not the standing lamp. The deeds are a table (`naming.PERSON_DEEDS`: leaving and forgetting; a thing
"drops", "comes on" and "says" a time too), read after an auxiliary or an adverb of frequency and
before their object (`naming._Reader.person_subject`): without one, "left" is the thing's own
participle ("Was the lamp left on?", which the first version of the rule misread, caught by the
condition grid's floor). The rows were written here in other registers (a
note, a heading's dash, an office memo, a reminder) before the rule and measured then (the counts
in each test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors, named

#: (text, rooms, the state the condition asks, or None)
PEOPLE = [
    ("Standing lamp by the armchair: she can't bear it on. If the cleaners have left it on overnight, "
     "switch it off.", ("robing_room",), "state(floor_lamp, toggled_on)"),
    ("The lamp is by the bed. If the cleaner left it on, switch it off.", ("bedroom",), "state(table_lamp, toggled_on)"),
    ("The dryer: the cleaners forgot it was on last week. If it's running, switch it off.", ("laundry_room",),
     "state(dryer, toggled_on)"),
    ("Curtains in the office - the cleaner always leaves them open. If they're open, close them.", ("office",), None),
]


@pytest.mark.parametrize(("text", "rooms", "state"), PEOPLE)
def test_a_person_doing_a_deed_is_no_thing(text: str, rooms: tuple[str, ...], state: str | None) -> None:
    """Measured before the rule: 0 of 4 without a vacuum cleaner (and the three conditions asked of
    the vacuum cleaner); after: 4 of 4, each condition of its own thing."""
    assert "vacuum_cleaner" not in named(text, rooms)
    if state is not None:
        asked = factors(text, rooms)
        assert any({state, f"not {state}"} <= v for v in asked.values()), asked


@pytest.mark.parametrize(("text", "rooms"), [
    # the machine itself: its own names, or its head word doing what a machine does
    ("If the vacuum cleaner is on, switch it off.", ("living_room",)),
    ("The hoover is on the floor. If it's on, switch it off.", ("living_room",)),
    ("The cleaner is still running? Switch it off at the wall.", ("living_room",)),
    # "come" and "say" are no deeds of people only: the machine comes on
    ("The cleaner comes on by itself at nine. If it's on, switch it off.", ("living_room",)),
])
def test_the_machine_is_still_named(text: str, rooms: tuple[str, ...]) -> None:
    """Near misses, named so before and after the rule."""
    assert "vacuum_cleaner" in named(text, rooms)


def test_a_things_own_participle_left_is_no_deed() -> None:
    """"Was the lamp left on?": "left" with no object is the lamp's participle; the lamp is named
    and its state asked (the condition grid's rows, kept)."""
    asked = factors("Please go to the living room. Was the lamp left on? If so, switch it off.", ("living_room",))
    assert any("state(table_lamp, toggled_on)" in v for v in asked.values()), asked
