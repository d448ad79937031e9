"""The seventeenth session's rules for invalid environments and broken stated facts (dev 3 to dev
22): each rule tested on sentences written for the test, in several registers, with near misses
that must not be misread. docs/reader.md, "Broken machines and stated facts (seventeenth session)"."""

from __future__ import annotations

import pytest
from reading import CATALOG, brief

from logicenveval.offline.analysis import analyse


def _stated(text: str, rooms: tuple[str, ...]) -> set[str]:
    return {f.condition for c in analyse(brief(text, rooms), CATALOG).clauses for f in c.facts}


def _asked(text: str, rooms: tuple[str, ...]) -> set[str]:
    return {v for f in analyse(brief(text, rooms), CATALOG).factors for v in f.values.values()}


# -- a machine out of order, said in the words of a variety or a register ------------------------
# Structure: a predicate of breakage said of a thing that switches on, in a word standard English
# lists under another sense ("spoil": Singapore, Malaysian, Indian, Nigerian English; "kaput",
# "bust", "knackered": informal British/American English; Malay "rosak" in a code-switched chat).
# Before the rule each of these was an attribute (`spoilness`, `bustness`) or nothing, so a
# task's stated `state(x, broken)` was never realised (dev 8's chat: every environment invalid).
BREAKAGE = [
    # Singlish chat, completive "already" (written for the test)
    ("eh the kettle in there spoil already, dun use", ("kitchen",), "state(kettle, broken)"),
    # Indian English office note
    ("Sir, the microwave is spoilt.", ("kitchen",), "state(microwave, broken)"),
    # a British flatmate's note
    ("Heads up: the desk lamp is bust.", ("bedroom",), "state(desk_lamp, broken)"),
    # a Manglish chat with a Malay word
    ("Don't spoil the rug; the vacuum is rosak.", ("living_room",), "state(vacuum_cleaner, broken)"),
    # a hotel handover, informal
    ("Room 4: the television is kaput.", ("bedroom",), "state(television, broken)"),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), BREAKAGE)
def test_a_word_of_breakage_states_a_machine_broken(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in _stated(text, rooms)
    assert fact not in _asked(text, rooms)  # said, not doubted


def test_a_word_of_breakage_in_a_condition_is_asked() -> None:
    assert "state(kettle, broken)" in _asked("If the kettle is spoilt, boil water in the pan.", ("kitchen",))
    assert "state(toaster, broken)" in _asked("If the toaster is kaput, use the grill.", ("kitchen",))


@pytest.mark.parametrize(("text", "rooms"), [
    ("The milk is spoiled, pour it away.", ("kitchen",)),  # food gone off is no machine broken
    ("The chair is bust.", ("kitchen",)),  # not a thing that switches on: not read
    ("I'm knackered, so the kettle stays where it is.", ("kitchen",)),  # the speaker, tired
    ("Please don't spoil the kettle's lid.", ("kitchen",)),  # the verb, not a state
])
def test_a_word_of_breakage_not_said_of_a_machine_breaks_nothing(text: str, rooms: tuple[str, ...]) -> None:
    assert not any(c.endswith(", broken)") for c in _stated(text, rooms) | _asked(text, rooms))
    assert not any("spoil" in c or "bust" in c or "knacker" in c for c in _stated(text, rooms))

