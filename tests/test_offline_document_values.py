"""Values set by conditions that documents lay out in their own ways (issue 47, eighteenth session).

A troubleshooting table, a fault card or a maintenance log writes a rule as labelled lines: the
fault it supposes ("Possible cause: desktop computer left switched on.", "Fault: kettle left
on.") and what to do about it ("Remedy: shut the desktop computer down."). The supposed fault is
the rule's condition, as "If the kettle is left on, switch it off" would say it. The documents
below are composed for these tests, each in a register of its own (a service manual, an IT
helpdesk sheet, a café's fault card, a landlord's maintenance log, a caravan handbook, a lab's
equipment notice), with near misses that must not be read as a condition.
"""

from __future__ import annotations

from typing import Any

import pytest

from logicenveval.offline.analysis import analyse
from logicenveval.offline.sentences import dealias, derecord


def _brief(text: str, roles: list[str], room: str) -> dict[str, Any]:
    return {"id": "t", "description": text, "rooms": [room], "roles": {r: {"category": r} for r in roles}}


def _values(text: str, roles: list[str], room: str) -> set[str]:
    return {v for f in analyse(_brief(text, roles, room)).factors for v in f.values.values()}


#: (document, roles, room, the value its supposed fault sets)
TROUBLESHOOTING = [
    # a service manual's troubleshooting table
    ("Symptom: no picture after the end of the shift.\nProbable cause: monitor left switched on.\n"
     "Remedy: switch the monitor off.", ["monitor", "desk"], "office", "state(monitor, toggled_on)"),
    # a café's fault card by the kettle
    ("FAULT CARD - COUNTER\nFault: kettle left on.\nAction: switch the kettle off at the wall.",
     ["kettle", "countertop"], "kitchen", "state(kettle, toggled_on)"),
    # a landlord's maintenance log
    ("Flat 3, bedroom\nProblem: window left open overnight.\nFix: close the window and check the catch.",
     ["window", "bed"], "bedroom", "state(window, open)"),
    # an IT helpdesk sheet
    ("Ticket 4411\nIssue: laptop left running in the meeting room.\nSolution: shut the laptop down.",
     ["laptop", "table"], "office", "state(laptop, toggled_on)"),
    # a caravan handbook
    ("Likely cause: fridge door left open.\nCorrective action: shut the fridge firmly.",
     ["fridge"], "kitchen", "state(fridge, open)"),
    # a lab's equipment notice, its cause a full clause
    ("Suspected cause: the microwave is still on.\nRemedy: switch the microwave off.",
     ["microwave", "countertop"], "kitchen", "state(microwave, toggled_on)"),
    # a housekeeping card: a thing where it should not be
    ("Problem: towel on the floor.\nFix: hang it on the towel rack.",
     ["towel", "towel_rack"], "bathroom", "on(towel, floor)"),
]


@pytest.mark.parametrize(("text", "roles", "room", "value"), TROUBLESHOOTING)
def test_a_supposed_fault_is_the_remedys_condition(text: str, roles: list[str], room: str, value: str) -> None:
    """A labelled fault ("Possible cause:", "Fault:", "Problem:", "Issue:") before its labelled
    remedy ("Remedy:", "Fix:", "Solution:", "Action:") asks the state the fault supposes."""
    assert value in _values(text, roles, room)


#: near misses: labelled lines that suppose no fault, or a remedy with no fault before it
NEAR_MISSES = [
    # a cause that names no state of a thing
    ("Cause: unknown.\nRemedy: call the landlord.", ["kettle", "countertop"], "kitchen"),
    # a remedy alone: an instruction, no condition
    ("Remedy: leave the kettle on.", ["kettle", "countertop"], "kitchen"),
    # a fault with no remedy after it is a report, not a rule
    ("Fault: kettle left on.\nReported by: Sam.", ["kettle", "countertop"], "kitchen"),
]


@pytest.mark.parametrize(("text", "roles", "room"), NEAR_MISSES)
def test_no_fault_no_condition(text: str, roles: list[str], room: str) -> None:
    assert not analyse(_brief(text, roles, room)).factors


def test_the_record_reads_as_its_conditional() -> None:
    """The hedge before a label ("Possible", "Likely") keeps it the label it hedges; the symptom,
    what is seen, is a label the conditional leaves out (the cause says the thing's state)."""
    said = derecord("Symptom: fan noise.\nPossible cause: computer left on.\nRemedy: shut the computer down.")
    assert said == "If computer left on, shut the computer down."


def test_a_label_of_more_words_is_no_field() -> None:
    """Only a known hedge opens a label of two words: "Porthole curtain:" or "Kitchen door:"
    stay the headings they are, inside a record or out of one."""
    text = "Kitchen door: if it is open, shut it.\nWhen: you leave\nDo: lock up"
    assert derecord(text).startswith("Kitchen door: if it is open, shut it.")


#: (notice in capitals, roles, room, the value its doubted place sets): a bracketed gloss in a line
#: of capitals ("HEADSET (HEADPHONES) ON COFFEE TABLE") goes on with the sentence, as it does in
#: small letters; a notice, a telegram, a sign on a door
CAPITALS = [
    ("GUESTS MAY HAVE LEFT PORTABLE COMPUTER (LAPTOP) ON DESK. IF FOUND, LOCK IN SAFE.",
     ["laptop", "desk", "safe"], "bedroom", "on(laptop, desk)"),
    ("CLEANER MAY HAVE LEFT BUCKET (PAIL) ON FLOOR. IF PRESENT, PUT IN CLOSET. IF NOT, NIL.",
     ["bucket", "closet"], "hallway", "on(bucket, floor)"),
    ("KIDS MAY HAVE LEFT FOOTBALL (BALL) ON BED. IF THERE, PUT IN TOY BOX.",
     ["ball", "bed", "toy_box"], "bedroom", "on(ball, bed)"),
]


@pytest.mark.parametrize(("text", "roles", "room", "value"), CAPITALS)
def test_a_bracket_in_capitals_ends_no_sentence(text: str, roles: list[str], room: str, value: str) -> None:
    assert value in _values(text, roles, room)


def test_a_bracket_before_a_sentence_in_small_letters_still_ends_it() -> None:
    """The near miss: in small letters a capital after ")" opens a new sentence ("(the tall one)
    Then switch it off"), as before."""
    from logicenveval.offline.sentences import split_sentences
    assert split_sentences("Check the lamp (the tall one) Then switch it off.") == [
        "Check the lamp (the tall one)", "Then switch it off."]


#: (text, roles, room, the doubted place asked): an anecdote of an earlier occasion ("last time",
#: "the time before") tells where a thing was then, not where it is, so the doubt stays a question
EARLIER = [
    # a club notice with the secretary's remarks
    ("A member may have left an umbrella on the bench. If present, hang it on the coat hook. Please check, "
     "folks: the heater ran all night last time and somebody's umbrella lay on that bench for a month.",
     ["umbrella", "bench", "coat_hook", "heater"], "hallway", "on(umbrella, bench)"),
    # a flatmate's note
    ("Might be a mug on the desk - if so, wash it. The time before, somebody's mug sat on that desk for a week!",
     ["mug", "desk", "sink"], "office", "on(mug, desk)"),
    # a housekeeper's card
    ("Guests may have left a towel on the floor. If there, hang it on the rail. On the previous occasion a "
     "towel lay on the floor all weekend.", ["towel", "towel_rack"], "bathroom", "on(towel, floor)"),
]


@pytest.mark.parametrize(("text", "roles", "room", "value"), EARLIER)
def test_an_earlier_occasion_settles_no_place(text: str, roles: list[str], room: str, value: str) -> None:
    assert value in _values(text, roles, room)


def test_the_present_after_an_earlier_occasion_is_still_read() -> None:
    """Near misses: a place said of now ("now", "today") beside an earlier occasion, and the
    same anecdote with no earlier occasion named, are stated as before."""
    from logicenveval.offline.placement import described_placements
    text = "Last time the lamp was on the shelf; now the lamp is on the desk."
    assert described_placements(_brief(text, ["floor_lamp", "shelf", "desk"], "office")) == ["on(floor_lamp, desk)"]
    text = "Please check, folks: somebody's umbrella lay on that bench for a month."
    assert described_placements(_brief(text, ["umbrella", "bench"], "hallway")) == ["on(umbrella, bench)"]


#: (text, roles, room, the values its letters' conditions set): a thing named by a capital letter
#: in apposition ("a floor lamp L", "a towel T") is that thing wherever the letter is used again,
#: as in a proof, a puzzle, a specification or an exam question
LETTERS = [
    # a logic puzzle
    ("Puzzle for the night porter. The lobby holds a desk D, a mug G and a lamp L. If L is on, switch it "
     "off. If G is dirty, wash it in the sink.", ["desk", "mug", "floor_lamp", "sink"], "office",
     ["state(floor_lamp, toggled_on)", "state(mug, dirty)"]),
    # a specification
    ("3.1 Objects. The bathroom contains a towel T and a towel rack R.\n3.2 Behaviour. If T is on the floor, "
     "the operator SHALL hang T on R. If T is already on R, no action is required.",
     ["towel", "towel_rack"], "bathroom", ["on(towel, floor)"]),
    # an exam question
    ("Question 4. A kitchen has a kettle K and a window W. (a) If K is on, switch it off. (b) If W is open, "
     "close it.", ["kettle", "window"], "kitchen", ["state(kettle, toggled_on)", "state(window, open)"]),
]


@pytest.mark.parametrize(("text", "roles", "room", "values"), LETTERS)
def test_a_letter_names_the_thing_it_follows(text: str, roles: list[str], room: str, values: list[str]) -> None:
    got = _values(text, roles, room)
    assert all(v in got for v in values)


@pytest.mark.parametrize("text", [
    "Plan B: if the kettle is on, switch it off. Take vitamin C with your tea.",  # no article before it
    "Buy a size M towel. Dr F. Okoye left it here.",  # a word after the letter; an initial
    "The beach path is at the end of row C, past the shop.",  # never used again: the name's end
    "There is a mug M and a cup M. Wash M.",  # one letter for two things
])
def test_a_letter_that_names_nothing_stays(text: str) -> None:
    assert dealias(text) == text


def test_a_letter_is_dropped_where_it_is_given() -> None:
    assert dealias("The lobby holds a mug G and a lamp L. If L is on, switch it off.") == \
        "The lobby holds a mug G and a lamp. If the lamp is on, switch it off."
