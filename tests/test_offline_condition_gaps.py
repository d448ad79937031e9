"""Conditions in the forms the condition-forms matrix showed unread (issue 47, the twelfth session):
a thing gone as a predicate ("has been taken", "has disappeared", "is nowhere to be seen"), a
predicate with its subject elided after a connective ("if washed", "if missing"), a predicate state
before an adverbial of time ("was emptied overnight", "if off right now"), an inverted question's
participle ("Was the bowl washed?"), a pronoun's "if it isn't there" with no place to point back
to, "should" inverted before "his" / "her", a supposition ("Suppose the lamp is on. Then ..."), a
note's doubt with its subject dropped ("May have fallen on the floor"), a comment aside between
subject and verb ("The remote, as ever, belongs on the stand") and a whole question in quotes.
Each rule on sentences written here in two registers or more (none produced by the generator,
none from the task sets), with near misses that must not be read."""

from __future__ import annotations

import pytest
from reading import asks, factors


def _no_factor_of(text: str, rooms: tuple[str, ...], fact: str) -> bool:
    return not any(fact in values or f"not {fact}" in values for values in factors(text, rooms).values())


# -- a thing gone, as a predicate (`sentences.ABSENCE_PREDICATES`) -----------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a flatmate's note, the perfect passive
    ("Back late tonight. If my laptop has been taken, ring me straight away.", ("office",), "exists(laptop)"),
    # a museum's closing checklist, the simple passive
    ("Closing round: walk through the study. Should the desk lamp have been removed, log it in the book.",
     ("study",), "exists(desk_lamp)"),
    # a text message, an intransitive verb of going in the perfect
    ("omg if the kettle has disappeared again text me", ("kitchen",), "exists(kettle)"),
    # a formal handover, an idiom of absence
    ("Where the vacuum cleaner is nowhere to be found, the duty officer is to be informed. In the event "
     "that the vacuum cleaner is nowhere to be seen, report it.", ("hallway",), "exists(vacuum_cleaner)"),
    # a question with its auxiliary first
    ("Quick one before you go: has the remote vanished? If so, tell me.", ("living_room",), "exists(remote_control)"),
])
def test_a_thing_gone_as_a_predicate_asks_whether_it_is_there(text: str, rooms: tuple[str, ...],
                                                               condition: str) -> None:
    assert asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "fact"), [
    # where it went, not whether it is there
    ("If the kettle was taken out of the cupboard, put it back.", ("kitchen",), "exists(kettle)"),
    # someone's act, with its object
    ("If Sam has taken the kettle, that's fine.", ("kitchen",), "exists(kettle)"),
])
def test_a_participle_of_taking_with_a_place_or_an_object_is_no_absence(text: str, rooms: tuple[str, ...],
                                                                        fact: str) -> None:
    assert _no_factor_of(text, rooms, fact)


# -- a predicate with its subject elided after a connective (`sentences._ELIDED_PREDICATE`) -----

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a kitchen rota, a result participle
    ("Have a look at the bowl: if washed, put it in the cupboard.", ("kitchen",), "state(bowl, dirty)"),
    # a laundry notice, "when" and a result participle
    ("The bucket by the machine - when emptied, fill it again from the tap.", ("laundry_room",),
     "state(bucket, filled)"),
    # a hotel checklist, an absence word
    ("Check the hairdryer; if missing, note it on the sheet.", ("bathroom",), "exists(hair_dryer)"),
])
def test_an_elided_predicate_after_a_connective_speaks_of_the_thing_just_named(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


def test_once_and_a_participle_after_its_action_is_a_step_not_a_question() -> None:
    # "once washed" after the instruction that washes it: no elided predicate is spelled out
    from logicenveval.offline.sentences import unquote
    assert unquote("Wash the bowl and once washed, put it in the cupboard.") == \
        "Wash the bowl and once washed, put it in the cupboard."
    assert unquote("If needed, use the towel.") == "If needed, use the towel."


# -- a predicate state before an adverbial of time (`sentences.TRAILING_ADVERBIALS`) ------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a house-sitter's note, a passive before "overnight"
    ("If the water bucket was emptied overnight, fill it before the dog wakes up.", ("laundry_room",),
     "state(bucket, filled)"),
    # a terse checklist, an elided subject before "right now"
    ("Bedside lamp: if off right now, switch it on.", ("bedroom",), "state(table_lamp, toggled_on)"),
    # an office memo, a condition after its instruction, before "this morning"
    ("Kindly close the fridge if it was left open this morning.", ("kitchen",), "state(fridge, open)"),
    # a chat message, an elided participle and particle before "in there"
    ("have a look at the telly: if switched on in there, turn it off", ("bedroom",),
     "state(television, toggled_on)"),
])
def test_a_predicate_state_before_an_adverbial_of_time_is_still_the_predicate(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


def test_a_participle_before_a_place_is_still_a_verb() -> None:
    # "emptied into the sink" says where it went: the verb's place, not an adverbial of time
    assert "state(sink, filled)" not in {c for v in factors(
        "If the bucket was emptied into the sink, rinse the sink.", ("kitchen",)).values() for c in v}


# -- an inverted question's participle (`sentences._QUESTION_PREDICATE`) ------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    ("Was the bowl washed? If so, put it away.", ("kitchen",), "state(bowl, dirty)"),
    ("Morning! Were the plates washed? If so, stack them on the shelf.", ("kitchen",), "state(plate, dirty)"),
    # a dislocated subject and an adverbial of time before the question mark
    ("The bucket - was it emptied overnight? Then fill it at the tap.", ("laundry_room",), "state(bucket, filled)"),
])
def test_an_inverted_questions_participle_is_its_state(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


# -- a pronoun's "if it isn't there" with no place before (`analysis._place_before`) ------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    ("Go to the kitchen and have a look at the kettle. If it isn't there, let me know.", ("kitchen",),
     "exists(kettle)"),
    ("Dear Ann, would you check on my laptop? If it is not there, please call me.", ("study",),
     "exists(laptop)"),
    ("Have a look at the towel. If it's not there, let me know.", ("bathroom",), "exists(towel)"),
])
def test_a_pronouns_not_there_with_no_place_before_asks_whether_the_thing_is_there(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


def test_a_pronouns_not_there_after_a_place_still_points_back_to_it() -> None:
    text = "The kettle lives on the counter. If it is not there, put it back."
    assert asks(text, ("kitchen",), "on(kettle, kitchen_counter)")
    assert _no_factor_of(text, ("kitchen",), "exists(kettle)")


# -- "should" inverted before "his" / "her" (`clauses._INVERTING`) ------------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    ("Should his mug be full, empty it into the sink.", ("living_room",), "state(mug, filled)"),
    ("The nursery: should her lamp still be on, kindly switch it off.", ("bedroom",), "state(table_lamp, toggled_on)"),
])
def test_should_inverted_before_a_possessive_pronoun_is_a_condition(text: str, rooms: tuple[str, ...],
                                                                    condition: str) -> None:
    assert asks(text, rooms, condition)


# -- a supposition as "if" (`sentences._SUPPOSED_IF`) --------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a proof's register, its consequence in the next sentence
    ("Suppose the floor lamp is on. Then switch it off.", ("living_room",), "state(floor_lamp, toggled_on)"),
    # a puzzle's register
    ("Supposing the bin is full, empty it before bed.", ("kitchen",), "state(trash_can, filled)"),
    # a lawyer's register
    ("Assuming that the kettle is empty, the tenant shall fill it.", ("kitchen",), "state(kettle, filled)"),
    # a dislocated subject, a tutor's register
    ("The kettle - suppose it is empty. Then fill it at the sink.", ("kitchen",), "state(kettle, filled)"),
    # a chat: "let's say"
    ("let's say the towel is wet: hang it up", ("bathroom",), "state(towel, wet)"),
])
def test_a_supposition_is_a_condition(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


def test_a_belief_with_its_subject_is_no_supposition() -> None:
    from logicenveval.offline.sentences import unquote
    assert unquote("I suppose the lamp is on.") == "I suppose the lamp is on."
    assert unquote("Suppose so.") == "Suppose so."


# -- a note's doubt with its subject dropped (`sentences._DROPPED_DOUBT`) ------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    ("Toothbrush (the blue one). May have fallen on the floor. If so, rinse it.", ("bathroom",),
     "on(toothbrush, floor)"),
    ("Spare towel: might be in the hamper. If so, take it out and fold it.", ("bathroom",),
     "inside(spare_towel, hamper)"),
])
def test_a_doubt_with_its_subject_dropped_speaks_of_the_thing_named(text: str, rooms: tuple[str, ...],
                                                                     condition: str) -> None:
    assert asks(text, rooms, condition)


def test_a_request_keeps_its_subject() -> None:
    from logicenveval.offline.sentences import unquote
    assert unquote("Could you check the towel?") == "Could you check the towel?"
    assert unquote("May I ask you a favour?") == "May I ask you a favour?"


# -- a comment aside between subject and verb (`sentences.COMMENT_ASIDES`) ----------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    ("The TV remote, as ever, belongs on the TV stand, so if it's lying anywhere else, take it back.",
     ("living_room",), "on(remote_control, tv_stand)"),
    ("The kettle, as usual, lives on the counter; if it is anywhere else, put it back.", ("kitchen",),
     "on(kettle, kitchen_counter)"),
])
def test_a_comment_aside_does_not_hide_a_home(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


def test_an_aside_word_that_says_something_stays() -> None:
    from logicenveval.offline.sentences import unquote
    # "naturally" with no commas of its own is a manner, not an aside
    assert "naturally" in unquote("Let the towel dry naturally, then fold it.")


# -- a whole sentence in quotes (`sentences._QUOTED_WHOLE`) --------------------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a call script
    ('Ask: "Is the kettle on the counter?" NO: skip it. YES: switch it on.', ("kitchen",),
     "on(kettle, kitchen_counter)"),
    # a story's reported speech
    ('He asked me: "Is the fridge open?" YES: close it.', ("kitchen",), "state(fridge, open)"),
    # a hotel's guest script
    ('Say to the guest: "Is the towel wet?" YES: hang it up. NO: leave it.', ("bathroom",), "state(towel, wet)"),
])
def test_a_quoted_question_is_a_question(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


def test_quoted_words_that_end_no_sentence_keep_their_marks() -> None:
    from logicenveval.offline.sentences import unquote
    assert '"good"' in unquote('Put the "good" mug on the shelf.')


# -- a second predicate sharing the condition's subject (`sentences._SHARED_SUBJECT`) -----------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a witness statement's reported instruction, a contracted pluperfect
    ("The flowers. The dog goes for them. If they'd been knocked over and were lying on the floor, "
     "I was to put them back in the vase.", ("garden",), "on(flower, floor)"),
    # a plain note
    ("If the mug had fallen and was lying on the floor, pick it up.", ("kitchen",), "on(mug, floor)"),
])
def test_a_second_predicate_without_its_subject_speaks_of_the_conditions_subject(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


def test_a_second_predicate_of_the_listener_is_left_alone() -> None:
    from logicenveval.offline.sentences import unquote
    assert unquote("If you are home and are tired, leave it.") == "If you are home and are tired, leave it."
