"""A kind's word modifying a noun no kind names, in a preposition's object ("for bar staff on the
late", "For the bath team on Saturdays"), from the twenty-fifth session. Such a noun is often also a
verb ("to staff", "to team", "to crew"), and the reader took it for one when a preposition
followed ("my racket go in the ..."), so the first word named a thing: a soap bar for "bar staff",
whose wetness a pub's close-down card then asked instead of its bar cloth's (dev 28's taproom).
A preposition's object holds no subject, so there the word is a compound's head
(`naming._Reader.prepositional_object`). The rows were written here in other registers (a rota,
a handover, a spa notice, a council bin round) before the rule and measured then (the counts in
each test's docstring)."""

from __future__ import annotations

import pytest
from reading import named

#: (text, rooms, the kind the modifier must not name)
MODIFIERS = [
    ("Reminder for the bar staff on nights - the cloth is on the stool.", ("kitchen",), "soap_bar"),
    ("For the bath team on Saturdays: the towel is on the rail.", ("bathroom",), "bathtub"),
    ("Handover to the bed crew at six: the pillow is on the sofa.", ("bedroom",), "bed"),
    ("Message from the sink man at the door: the tap drips.", ("kitchen",), "sink"),
    ("From the bin team on Mondays: the mug on the desk is dirty.", ("study",), "trash_can"),
    ("A word about bath staff in the spa - the towel is on the bench.", ("bathroom",), "bathtub"),
    ("Instructions for the sofa crew at the back: the pillow is on the bed.", ("bedroom",), "sofa"),
]


@pytest.mark.parametrize(("text", "rooms", "kind"), MODIFIERS)
def test_a_modifier_in_a_prepositions_object_names_nothing(text: str, rooms: tuple[str, ...], kind: str) -> None:
    """Measured before the rule: 0 of 7 read so; after: 7 of 7."""
    assert kind not in named(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "kind"), [
    # a verb's object then a bare infinitive: the noun is the thing, the word its verb
    ("Let the towel hang on the rail to dry.", ("bathroom",), "towel"),
    ("Let the cloth soak in the sink for an hour.", ("kitchen",), "cloth"),
    ("Leave the mug drain on the rack.", ("kitchen",), "mug"),
    # a compound whose head is a kind's own name
    ("Ask about the towel rack in the hall.", ("hallway",), "towel_rack"),
    # a clause after the object, no comma
    ("If you're looking for the bucket mop it up.", ("kitchen",), "bucket"),
])
def test_a_verb_after_a_verbs_object_still_leaves_the_thing(text: str, rooms: tuple[str, ...], kind: str) -> None:
    """Near misses, read before and after the rule."""
    assert kind in named(text, rooms)
