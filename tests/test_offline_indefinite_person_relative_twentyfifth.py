"""A thing taken up by a relative clause whose subject is an indefinite pronoun ("the plate someone
put in the sink", "the towel somebody dropped on the floor"), from the twenty-fifth session. The
dictionary lists "someone", "somebody", "anyone", "everyone" and "nobody" as nouns too, so the
namer read "plate someone" as a noun compound whose head is "someone", and named no plate
(`lexicon.INDEFINITE_PERSONS`, now among `lexicon.FUNCTION_WORDS`, which never head a compound).
Found while probing the previous session's left items ("the plate someone put in the sink"); the
rows were written here in several registers (a note, a dash list, an instruction, a rule, a
heading with a bracket, a text message) before the rule and measured then (the counts in the
test's docstring)."""

from __future__ import annotations

import pytest
from reading import factors, named

#: (text, rooms, the kind the relative clause's head names)
RELATIVES = [
    ("If the plate someone put in the sink is dirty, wash it.", ("kitchen",), "plate"),
    ("The towel somebody dropped on the floor - hang it on the rail.", ("bathroom",), "towel"),
    ("Bin the bottle somebody left on the bench.", ("kitchen",), "bottle"),
    ("Any cup anyone left out goes in the dishwasher.", ("kitchen",), "cup"),
    ("That jacket everyone keeps leaving on the sofa - if it's on the floor, hang it up.", ("living_room",), "jacket"),
    ("Pls check the lamp nobody ever switches off!! if its on turn it off", ("living_room",), "table_lamp"),
    # read before the rule too: "the one" before the pronoun
    ("MUG (the one somebody always leaves by the kettle): wash it if dirty.", ("kitchen",), "mug"),
]


@pytest.mark.parametrize(("text", "rooms", "kind"), RELATIVES)
def test_a_noun_before_an_indefinite_pronoun_is_named(text: str, rooms: tuple[str, ...], kind: str) -> None:
    """Measured before the rule: 1 of 7 named; after: 7 of 7."""
    assert kind in named(text, rooms)


def test_the_named_thing_carries_its_condition() -> None:
    """Before the rule the condition fell on the sink, the only thing named."""
    asked = factors("If the plate someone put in the sink is dirty, wash it.", ("kitchen",))
    assert any("state(plate, dirty)" in v for v in asked.values()), asked
