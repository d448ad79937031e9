"""The seventeenth session's rules for invalid environments and broken stated facts (dev 3 to dev
22): each rule tested on sentences written for the test, in several registers, with near misses
that must not be misread. docs/reader.md, "Broken machines and stated facts (seventeenth session)"."""

from __future__ import annotations

import pytest
from reading import CATALOG, brief, placed

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


# -- a thing called by its kind's word in the writer's language ----------------------------------
# Structure: a learner's or code-switched note names a thing by the word of the writer's own
# language, a cognate of the English kind's word spelt by that language's letters ("Telewizor"
# in a Polish note, "televisor" in a Spanish one, "televisi" in an Indonesian one), or by a
# slip of the English spelling. Before the rule the word named no role, so a placement stated of
# it was never read and the realiser put the thing where its kind usually goes (dev 22: the
# television on the wall, every environment invalid).
COGNATES = [
    # a Polish speaker's note (the role named elsewhere as "TV")
    ("Telewizor stands on the chest of drawers. If the TV is on, switch it off.", ("living_room",),
     "on(television, dresser)"),
    # a Spanish speaker's email
    ("Hola! The televisor is on the cabinet, and the remote is next to it. If the TV is on, turn it off.",
     ("living_room",), "on(television, cabinet)"),
    # an Indonesian speaker's chat
    ("the televisi is on the cabinet ya. if TV still on, pls turn off", ("living_room",),
     "on(television, cabinet)"),
    # a hurried text with a slip
    ("the televsion is on the shelf, if the television is on pls turn it off", ("living_room",),
     "on(television, wall_shelf)"),
]


@pytest.mark.parametrize(("text", "rooms", "fact"), COGNATES)
def test_a_cognate_of_a_kinds_word_names_its_role(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact in placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), [
    # a name or a place like no kind's word
    ("Tomek stands on the chest of drawers. If the TV is on, switch it off.", ("living_room",),
     "on(television, dresser)"),
    # an English word of its own sense, however like a kind's name ("lamps" is no cognate; "lame"
    # and "tell" are English)
    ("The lame dog sleeps on the sofa. If the lamp is on, switch it off.", ("living_room",), "on(lamp, sofa)"),
    # a cognate of another kind's word ("telefon", a phone) is not the television it half resembles
    ("The telefon is on the desk. If the television is on, switch it off.", ("office",),
     "on(television, desk)"),
])
def test_a_word_like_no_one_kinds_word_names_nothing(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact not in placed(text, rooms)


# -- a rule's quantified subject with a state, then a modal passive -------------------------------
# Structure: club rules, notices, procedures and house rules state a condition as a quantified
# subject described by its state, then "must / should / is to be <done>" ("Any umbrella still open
# when the last four-ball is in must be closed", dev 21's scorecard). Before the rule none of
# these asked the state (a value never set); "Any open umbrella must be closed" already did.
QUANTIFIED = [
    # a golf club's local rule
    ("Any umbrella still open when the last four-ball is in must be closed.", ("locker_room",),
     "state(umbrella, open)"),
    # an office closing notice
    ("Every desk lamp left on overnight must be switched off.", ("office",), "state(desk_lamp, toggled_on)"),
    # a staff-room procedure
    ("Any kettle that is still on is to be switched off.", ("kitchen",), "state(kettle, toggled_on)"),
    # a meeting room's house rules
    ("Each mug found dirty after the meeting must be washed.", ("office",), "state(mug, dirty)"),
    # a hostel's rules, with a time phrase and "should"
    ("Any lamp still on at closing time should be switched off.", ("bedroom",), "state(table_lamp, toggled_on)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), QUANTIFIED)
def test_a_quantified_subject_with_a_state_asks_the_state(text: str, rooms: tuple[str, ...],
                                                           condition: str) -> None:
    assert {condition, f"not {condition}"} <= _asked(text, rooms)


@pytest.mark.parametrize(("text", "rooms"), [
    ("Any plate still on the table must be cleared.", ("kitchen",)),  # a place, not a state
    ("Every window must be shut.", ("bedroom",)),  # no state said of the subject
    ("Any mug must be washed before it is put away.", ("kitchen",)),  # the state is the goal's
])
def test_a_quantified_subject_without_a_state_asks_no_state(text: str, rooms: tuple[str, ...]) -> None:
    assert not any(v.startswith("state(") for v in _asked(text, rooms))


# -- a state the text gives a thing outright is kept by the realiser ------------------------------
# Structure: a plain statement of a thing's state no factor asks ("the ceiling fan in there spoil
# already", "the kettle in the shed is broken"): the realiser set the places the text states but
# never its states, so dev 8's fan was not broken in any environment (a constraint violated).
STATED_STATES = [
    ("the ceiling fan in there spoil already, no need to on it. if the light is on pls off it",
     ("household_shelter",), "ceiling_fan", "broken", True),
    ("Just so you know, the kettle in the kitchen is broken. If the lamp is on, switch it off.",
     ("kitchen",), "kettle", "broken", True),
]


@pytest.mark.parametrize(("text", "rooms", "role", "flag", "value"), STATED_STATES)
def test_a_stated_state_is_realised(text: str, rooms: tuple[str, ...], role: str, flag: str,
                                    value: bool) -> None:
    from logicenveval.offline.realise import realise
    b = brief(text, rooms)
    assert realise(b, [], CATALOG)[role].states.get(flag) is value


def test_a_state_a_situation_fact_speaks_of_is_the_facts() -> None:
    from logicenveval.offline.realise import realise
    b = brief("The desk lamp is on. If the lamp is on, switch it off.", ("office",))
    assert realise(b, ["not state(desk_lamp, toggled_on)"], CATALOG)["desk_lamp"].states.get("toggled_on") is False
    # a state asked by a factor is no stated state, and a goal's state is none either
    b = brief("If the kettle is broken, use the pan. Make sure the lamp is off.", ("kitchen",))
    from logicenveval.offline.analysis import stated_states
    assert stated_states(b, CATALOG) == []


def test_a_state_said_both_ways_states_cases_not_the_scene() -> None:
    # a quiz's questions and a trainer's scenarios state each case in turn (written for the test)
    from logicenveval.offline.analysis import stated_states
    for text, rooms in [("Q1. The mug on the desk is dirty. What do you do? Q2. The mug on the desk is clean. "
                         "What do you do?", ("office",)),
                        ("Scenario A: the kettle is on. Scenario B: the kettle is off. Say what you would do.",
                         ("kitchen",))]:
        assert stated_states(brief(text, rooms), CATALOG) == []


# -- a state given to a thing named later, or one its kind cannot take, is no stated state ------
# Found at the merge: the built-in laundry task's "dirty whites go into the washing machine (open
# it, load the shirt, close the door)" gave the washing machine "dirty" and "open" in every
# environment of every method (the clause's words, not a statement of the machine), and a cup or a
# cardboard box was "switched on". The statement's subject is the thing it names first, and a
# switched, open or filled state must be one its kind takes. Texts written for the test.
NOT_STATED = [
    ("Muddy boots go into the shoe cabinet (open it first, then close it again).", ("hallway",)),
    ("Wet towels belong in the washing machine - open it, load them, shut the door.", ("laundry_room",)),
    ("The cup on the counter is on. If the lamp is on, switch it off.", ("kitchen",)),
    ("The cardboard box by the door is switched on, apparently. Please take it to the garage.", ("hallway",)),
]


@pytest.mark.parametrize(("text", "rooms"), NOT_STATED)
def test_a_state_of_a_thing_named_later_or_not_its_kinds_is_not_stated(text: str, rooms: tuple[str, ...]) -> None:
    from logicenveval.offline.analysis import stated_states
    assert stated_states(brief(text, rooms), CATALOG) == []
