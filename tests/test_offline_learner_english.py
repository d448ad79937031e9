"""Forms of learner English that leave a value never set (issue 47, docs/reader.md "Learner
English (eighteenth session)"): structures the English of speakers of other languages shares,
each written here as composed sentences in the English of several language backgrounds (none
from the task sets), with near misses that must stay apart:

- (a) a yes/no question, a condition or a doubt with its subject after its predicate, the order
  of Greek, Spanish, Italian, Portuguese, Romanian and Arabic ("Is on the floor again the board
  game? Then ...", "If is open the laptop, close it", `sentences._subject_last`,
  `sentences._subject_last_if`);
- (b) a request with its "you" dropped after a condition typed without its comma, as speakers of
  languages that drop a known subject ask (Singapore/Malaysian English, Chinese, Indonesian,
  Thai: "if the fan still on can help me off it", `clauses._subjectless_request`);
- (c) "connected"/"disconnected" for a machine's on and off, the Portuguese and Spanish calque
  ("if the air conditioner is connected, please disconnect it", `sentences.connected_as_on`);
- (d) a condition that puts the place before an existential, the order of Chinese, Russian,
  Polish, Hungarian, Turkish and Korean ("If on the desk there is a mug,", "if on the table got a
  mug,"), before the rule misread as the place's own "on" (`sentences._place_first_existential`).

Measured on the tables below on the tree before the rules: (a) 0 of 6 asked in questions and 0 of
6 in conditions and doubts, (b) 4 of 6, (c) 0 of 6, (d) 1 of 6 (two misread as the place
switched on); after: all of them, and every near miss as
before."""

from __future__ import annotations

import pytest
from reading import asks, factors

from logicenveval.offline.clauses import split_clauses
from logicenveval.offline.sentences import (
    _PLACE_FIRST_EXISTENTIAL,
    _SUBJECT_LAST,
    _SUBJECT_LAST_IF,
    _place_first_existential,
    _subject_last,
    _subject_last_if,
    connected_as_on,
)

# -- (a) the subject after its predicate in a yes/no question ---------------------------------

SUBJECT_LAST = [
    # (background, text, room, condition asked)
    ("Greek", "The blanket. Is on the sofa again the blanket? Then fold it and put it on the shelf.",
     "living room", "on(blanket, sofa)"),
    ("Italian", "Is still open the laptop? Then close it please, the battery dies.", "office", "state(laptop, open)"),
    ("Portuguese", "Are on the floor the towels? Then hang them on the towel rail.", "bathroom", "on(towel, floor)"),
    ("Romanian", "Is on the desk my mug? Then you put it in the sink.", "office", "on(mug, desk)"),
    ("Arabic", "Is dirty the plate? Then put it in the sink, habibi.", "kitchen", "state(plate, dirty)"),
    ("Spanish", "Is still on the lamp? Then switch it off, the light is expensive.", "bedroom",
     "state(table_lamp, toggled_on)"),
]


@pytest.mark.parametrize(("background", "text", "room", "condition"), SUBJECT_LAST)
def test_a_question_with_its_subject_last_asks_its_condition(background: str, text: str, room: str,
                                                              condition: str) -> None:
    assert asks(text, (room,), condition), background


@pytest.mark.parametrize(("question", "english"), [
    ("Is on the floor again the board game?", "Is the board game on the floor again?"),
    ("Is still open the laptop?", "Is the laptop still open?"),
    ("Are on the coffee table the cups?", "Are the cups on the coffee table?"),
])
def test_the_question_is_read_in_english_order(question: str, english: str) -> None:
    assert _SUBJECT_LAST.sub(_subject_last, question) == english


@pytest.mark.parametrize("question", [
    "Is the lamp on?",                      # already in English order
    "Is there a mug on the desk?",          # "there": no subject to move
    "Is on the floor?",                     # no subject after the place
    "Is on the floor in the hall the bag?",  # a second place: left alone, not misread
    "Is it on?",                            # a pronoun subject in its place
    "Is open on Sundays?",                  # a shop's hours: no subject after the state
])
def test_other_questions_stay_as_they_are(question: str) -> None:
    assert _SUBJECT_LAST.sub(_subject_last, question) == question


SUBJECT_LAST_CLAUSE = [
    # the same order in a condition or a doubt, up to its comma or full stop
    ("Spanish", "If is open the laptop, close it, the battery is old.", "office", "state(laptop, open)"),
    ("Portuguese", "In case are on the floor the towels, hang them on the towel rail.", "bathroom",
     "on(towel, floor)"),
    ("Greek", "When is still on the kettle, switch it off, is dangerous.", "kitchen", "state(kettle, toggled_on)"),
    ("Italian", "Maybe is still on the lamp. If yes, switch it off.", "bedroom", "state(table_lamp, toggled_on)"),
    ("Romanian", "Perhaps is on the sofa again my scarf. If yes, hang it on the coat hook.", "living room",
     "on(scarf, sofa)"),
    ("Arabic", "If is dirty the mug, put it in the sink.", "kitchen", "state(mug, dirty)"),
]


@pytest.mark.parametrize(("background", "text", "room", "condition"), SUBJECT_LAST_CLAUSE)
def test_a_condition_with_its_subject_last_asks_it(background: str, text: str, room: str, condition: str) -> None:
    assert asks(text, (room,), condition), background


@pytest.mark.parametrize("text", [
    "If is on, close it.",                       # the subject dropped: read as before, of the thing spoken of
    "if is on the floor, pick it up",            # the same with a place
    "Maybe is better to leave it.",              # no state or place after the copula
    "If are on the floor any towels, hang them.",  # a quantifier, not a determiner: left alone
])
def test_a_condition_with_no_subject_after_its_predicate_stays(text: str) -> None:
    assert _SUBJECT_LAST_IF.sub(_subject_last_if, text) == text


# -- (b) a request with its "you" dropped ------------------------------------------------------

SUBJECTLESS_REQUEST = [
    ("Singapore", "i think i never off the fan this morning. if still on can help me off it, the remote on the table",
     "bedroom", "state(ceiling_fan, toggled_on)"),
    ("Malaysian", "the towel in bathroom, if on the floor can hang it on the hook", "bathroom", "on(towel, floor)"),
    ("Chinese", "The laptop in the office, if still open can close it for me", "office", "state(laptop, open)"),
    ("Indonesian", "my kettle, if still on could switch it off, thank you", "kitchen", "state(kettle, toggled_on)"),
    ("Thai", "if the lamp still on can turn it off na, the switch is by the door", "bedroom",
     "state(table_lamp, toggled_on)"),
    ("Vietnamese", "if the TV still on can turn it off, the remote is near the sofa", "living room",
     "state(television, toggled_on)"),
]


@pytest.mark.parametrize(("background", "text", "room", "condition"), SUBJECTLESS_REQUEST)
def test_a_request_without_its_you_ends_the_condition(background: str, text: str, room: str,
                                                      condition: str) -> None:
    asked = {c for values in factors(text, (room,)).values() for c in values}
    assert condition in asked, (background, asked)


@pytest.mark.parametrize(("text", "condition"), [
    ("if still on can help me off it", " still on "),
    ("if the laptop open can close it pls", " the laptop open "),
])
def test_the_condition_ends_before_the_modal(text: str, condition: str) -> None:
    pieces = split_clauses(text)
    assert [p.text for p in pieces if p.role == "condition"] == [condition]


@pytest.mark.parametrize("text", [
    "if the lamp is on it can overheat",     # the modal has a subject of its own
    "if the lamp is on can overheat",        # no imperative after the modal
    "if the heater can be moved, move it",   # the modal is the condition's own verb
])
def test_a_modal_with_a_subject_or_no_imperative_cuts_nothing(text: str) -> None:
    assert not any(p.text.lstrip().startswith(("can", "could")) for p in split_clauses(text))


# -- (c) "connected" for on -------------------------------------------------------------------

CONNECTED = [
    ("Brazilian", "The air conditioner - if it is connected, please disconnect it, the bill is expensive.",
     "bedroom", "state(air_conditioner, toggled_on)"),
    ("Spanish", "If the heater is still connected, disconnect it, please.", "office", "state(radiator, toggled_on)"),
    ("Portuguese", "The TV in the living room, if is connected, disconnect.", "living room",
     "state(television, toggled_on)"),
    ("Catalan", "If the fan is already disconnected, perfect. If not, disconnect it.", "bedroom",
     "state(ceiling_fan, toggled_on)"),
    ("Galician", "The kettle: if it stays connected all night, disconnect it.", "kitchen", "state(kettle, toggled_on)"),
    ("Brazilian, an inverted question", "Is still connected the lamp? Then disconnect it.", "bedroom",
     "state(table_lamp, toggled_on)"),
]


@pytest.mark.parametrize(("background", "text", "room", "condition"), CONNECTED)
def test_connected_is_on(background: str, text: str, room: str, condition: str) -> None:
    assert asks(text, (room,), condition), background


@pytest.mark.parametrize("text", [
    "If the printer is connected to the laptop, print the list.",
    "If the speaker is disconnected from the phone, leave it.",
    "Connect the charger to the socket by the desk.",
    "If the hose is connected with the tap, close the tap.",
])
def test_connected_to_a_thing_is_a_link_not_on(text: str) -> None:
    assert connected_as_on(text) == text


def test_a_link_asks_no_on_state() -> None:
    asked = {c for values in factors("If the printer is connected to the laptop, print the list.", ("office",)).values()
             for c in values}
    assert not any("toggled_on" in c for c in asked)


# -- (d) the place before an existential in a condition ----------------------------------------

PLACE_FIRST = [
    ("Chinese", "If on the table got a mug, put it in the sink lah.", "kitchen", "on(mug, dining_table)"),
    ("Russian", "If on the desk there is a mug, put it in the sink.", "office", "on(mug, desk)"),
    ("Polish", "When on the sofa is a blanket, fold it and put it on the shelf.", "living room", "on(blanket, sofa)"),
    ("Hungarian", "If on the floor are some towels, hang them on the hook.", "bathroom", "on(towel, floor)"),
    ("Korean", "If on the floor have towel, hang on hook please.", "bathroom", "on(towel, floor)"),
    ("Turkish", "If in the sink there are cups, wash them.", "kitchen", "inside(cup, sink)"),
]


@pytest.mark.parametrize(("background", "text", "room", "condition"), PLACE_FIRST)
def test_a_place_before_an_existential_asks_the_thing_there(background: str, text: str, room: str,
                                                            condition: str) -> None:
    asked = {c for values in factors(text, (room,)).values() for c in values}
    assert condition in asked and not any("toggled_on" in c for c in asked), (background, asked)


@pytest.mark.parametrize("text", [
    "When in the kitchen is the kettle still on, switch it off.",  # a state asked, not an existential
    "If on the desk is my laptop open, close it.",
    "If on the desk the lamp is on, switch it off.",               # the subject before its verb
    "On the desk there is a mug. Put it in the sink.",             # no condition
])
def test_a_place_before_a_state_or_outside_a_condition_stays(text: str) -> None:
    assert _PLACE_FIRST_EXISTENTIAL.sub(_place_first_existential, text) == text
