"""A question answered apart from where it is asked (the eighteenth session): forms where a
condition and what answers it are parted, or what the condition takes up is said before it, that
the offline reader misread (docs/reader.md "What it still misreads"). Each structure is a table of
sentences written here, in several registers, rooms, kinds and states, with near misses that must
stay as they are; each table was measured before its rule (the counts in each table's comment).

- a condition typed without its comma before an instruction to call or message the speaker ("if
  the lamp is on ring me", "if the towel is wet text me"): the sound verbs were read as the
  thing sounding ("the lamp is on is ringing"), and the verbs of messaging the lemma table knows
  only as nouns ("text", "whatsapp", "msg") opened no instruction;
- a question, or an instruction, with a time clause told by other people ("Is the desk lamp still
  on when they have gone? If so, ...", "Switch the lamp off when they have gone"): the time
  clause was cut off as a condition of its own, whose "they" took up the thing and whose "gone"
  asked the thing's absence;
- a doubt said with a false friend ("Eventually my mug is also on the desk. Bring it to the
  kitchen", French "éventuellement", German "eventuell"): the open statement the instruction after
  it answers was read as a settled one ("in the end"), so its condition was never asked;
- a quiz whose answer key is given apart from its questions ("Q1. <case>. What do you do? a) ...
  b) ..." and "ANSWER KEY: 1 b, 2 a" at the bottom): the cases were read as questions with no
  answer, the key not at all;
- a trailing presence condition after a thing named by a place of nearness ("Wipe the table with
  the sponge by the sink, if it is still there"): "it" took up the thing worked on, not the thing
  the place was said of."""

from __future__ import annotations

import pytest
from reading import asks, factors, instruction_under

from logicenveval.offline.sentences import keyed_answers

#: a condition typed without its comma, then an instruction to call or message the speaker:
#: (text, rooms, the condition, the value the instruction falls under, its words). Before the
#: rule 2 of 8 put the instruction under its value ("ring us" after an inverted "should", "ping
#: me"); "ring me" / "buzz me" made the condition "... is ringing me", "text me" / "whatsapp me" /
#: "msg me" ran on as the condition's words
CALL_THE_SPEAKER = [
    # a house-sitter's note: a lamp's state, "ring me"
    ("If the lamp is on ring me.", ("bedroom",), "state(table_lamp, toggled_on)", "yes", "ring me"),
    # a parent's text in small letters: wet, "text me"
    ("if the towel is wet text me", ("bathroom",), "state(towel, wet)", "yes", "text me"),
    # an office rule: an opening state, "buzz me"
    ("If the fridge is open buzz me.", ("kitchen",), "state(fridge, open)", "yes", "buzz me"),
    # a chat message: "whatsapp me" and a softener after it
    ("if the kettle is still on whatsapp me pls", ("kitchen",), "state(kettle, toggled_on)", "yes", "whatsapp me"),
    # a flatmate's note: an absence, "text us"
    ("If the mug is missing text us.", ("kitchen",), "exists(mug)", "no", "text us"),
    # a formal register: an inverted "should", "ring us"
    ("Should the heater be on ring us at once.", ("living_room",), "state(radiator, toggled_on)", "yes", "ring us"),
    # a carer's note in a texting register: a place, "msg me"
    ("if the blanket is on the floor msg me", ("bedroom",), "on(blanket, floor)", "yes", "msg me"),
    # a lab note: "ping me"
    ("If the laptop is open ping me.", ("office",), "state(laptop, open)", "yes", "ping me"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "value", "words"), CALL_THE_SPEAKER)
def test_calling_the_speaker_ends_a_condition(text: str, rooms: tuple[str, ...], condition: str, value: str,
                                              words: str) -> None:
    """"If the lamp is on ring me": a sound verb with the speaker as its object is an instruction
    to call, not the thing sounding (`sentences._SOUNDING`: no copula in the subject, no "me" /
    "us" after the verb), and a verb of messaging before the speaker opens an instruction
    (`clauses.MESSAGING`), which ends a condition typed without its comma."""
    under = instruction_under(text, rooms, condition)
    other = "no" if value == "yes" else "yes"
    assert words in under.get(value, "") and words not in under.get(other, ""), under


def test_a_device_sounding_is_still_its_state() -> None:
    """Near misses: a device's own sound after a condition's cue is still its state ("if the
    alarm clock rings", "if my phone buzzes"), and the form with its comma is read as before."""
    assert "switch it off" in instruction_under("If the alarm clock rings switch it off.", ("bedroom",),
                                     "state(alarm_clock, toggled_on)").get("yes", "")
    assert "put it on the desk" in instruction_under("if my phone buzzes put it on the desk", ("office",),
                                          "state(cell_phone, toggled_on)").get("yes", "")
    assert "text me" in instruction_under("If the towel is wet, text me.", ("bathroom",), "state(towel, wet)").get("yes", "")


#: a question (or an instruction) with a time clause told by other people, then its answer:
#: (text, rooms, the condition asked, the presence that must not be asked). Before the rule 2 of
#: 8 asked the condition alone (the laptop's "she", the fridge's "after"); the others asked the
#: thing's presence ("they" the thing, "gone" its absence), or nothing
PEOPLE_TIMES = [
    # a party host's note: "when they have gone", "If so"
    ("Is the desk lamp still on when they have gone? If so, switch it off.", ("office",),
     "state(desk_lamp, toggled_on)", "exists(desk_lamp)"),
    # a B&B owner's card: "when the last of them has gone", "If it is"
    ("Is the kettle still on when the last of them has gone? If it is, switch it off.", ("kitchen",),
     "state(kettle, toggled_on)", "exists(kettle)"),
    # a holiday-let checklist: a place, "once they have gone", "If yes"
    ("Is the towel on the floor once they have gone? If yes, hang it up.", ("bathroom",), "on(towel, floor)",
     "exists(towel)"),
    # an office closing rule: "once everyone has left"
    ("Is the heater on once everyone has left? If yes, turn it off.", ("office",), "state(radiator, toggled_on)",
     "exists(radiator)"),
    # a lodger's note: "when she has left"
    ("Is the laptop open when she has left? If so, close it.", ("office",), "state(laptop, open)", "exists(laptop)"),
    # a caretaker's chat: "after they've left"
    ("Is the fridge open after they've left? If so, shut it.", ("kitchen",), "state(fridge, open)", "exists(fridge)"),
    # an instruction with the time clause after it: no condition but the time's
    ("Switch the desk lamp off when they have gone.", ("office",), "", "exists(desk_lamp)"),
    ("Put the kettle away when the last of them has gone.", ("kitchen",), "", "exists(kettle)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "not_asked"), PEOPLE_TIMES)
def test_a_time_told_by_people_asks_nothing_of_the_thing(text: str, rooms: tuple[str, ...], condition: str,
                                                         not_asked: str) -> None:
    """"Is the desk lamp still on when they have gone? If so, ...": the time clause of a question
    told by people (`clauses.PEOPLE`, as the agent's `AGENTS`) stays the question's; one cut off
    after an instruction reads "they" as the people (`analysis._Reader.timed`)."""
    assert not asks(text, rooms, not_asked), factors(text, rooms)
    if condition:
        assert asks(text, rooms, condition), factors(text, rooms)


def test_they_after_a_plural_thing_is_the_thing() -> None:
    """Near miss: after a question naming a thing in the plural, "when they are dry" is said of
    the things, and is still asked."""
    assert asks("Are the towels on the floor when they are dry? If so, fold them.", ("bathroom",),
                "state(towel, wet)")


#: an instruction naming a tool by a place of nearness, then "if it is still there": (text,
#: rooms, the presence asked, the presence that must not be asked). Before the rule 1 of 5 asked
#: the tool's presence (the dog's towel, the one thing named); the others asked the presence of
#: the thing worked on
NEAR_THING_THERE = [
    # a kitchen rota
    ("Wipe the table with the sponge by the sink, if it is still there.", ("kitchen",), "exists(sponge)",
     "exists(dining_table)"),
    # a cafe's closing card, no comma, "next to"
    ("Dry the cup with the towel next to the kettle if it is still there.", ("kitchen",), "exists(towel)",
     "exists(cup)"),
    # an office note: a place the catalog does not know
    ("Wipe the desk with the cloth near the printer, if it's still there.", ("office",), "exists(cloth)",
     "exists(desk)"),
    # a dog-sitter's text: "by the door"
    ("dry the dog with the towel by the door if its still there", ("hallway",), "exists(towel)", ""),
    # a hotel housekeeping sheet: "beside"
    ("Polish the mirror with the cloth beside the basin, if it is still there.", ("bathroom",), "exists(cloth)",
     "exists(mirror)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "not_asked"), NEAR_THING_THERE)
def test_still_there_takes_up_the_thing_named_by_its_place(text: str, rooms: tuple[str, ...], condition: str,
                                                           not_asked: str) -> None:
    """"the sponge by the sink, if it is still there": "there" is the place the tool was named
    by, so "it" is the tool (`analysis._named_with_place`, `_NEAR_PREPS`), and the condition asks
    whether it is there at all (nearness is no place the conditions read)."""
    assert asks(text, rooms, condition), factors(text, rooms)
    if not_asked:
        assert not asks(text, rooms, not_asked), factors(text, rooms)


def test_near_misses_of_a_thing_named_by_its_place() -> None:
    """A place the conditions read is still asked ("the sponge on the counter"), and a thing put
    by a place is the thing put ("Put the mug by the sink, if it is still there")."""
    assert asks("Wipe the table with the sponge on the counter, if it is still there.", ("kitchen",),
                "on(sponge, kitchen_counter)")
    assert asks("Put the mug by the sink, if it is still there.", ("kitchen",), "exists(mug)")


#: "eventually" with a present-tense state of the scene, the false friend of "possibly", then what
#: to do about it: (text, rooms, the condition asked). Before the rule 0 of 6 were asked
EVENTUALLY_POSSIBLY = [
    # a French speaker's email: "also", an instruction after it
    ("Eventually my mug is also on the desk. Bring it to the kitchen.", ("office", "kitchen"), "on(mug, desk)"),
    # a German speaker's note: an existential, "If so"
    ("Eventually there is a towel on the bathroom floor. If so, hang it up.", ("bathroom",), "on(towel, floor)"),
    # a Dutch speaker's chat: after the copula
    ("The remote is eventually on the sofa. Put it on the coffee table.", ("living_room",),
     "on(remote_control, sofa)"),
    # an Italian speaker's house rules: a comma after it, plural
    ("Eventually, the keys are in the bowl. Leave them there and lock the door.", ("hallway",), "inside(keys, bowl)"),
    # a Spanish speaker's text: the instruction in the same sentence
    ("Hi! Eventually the book is on the floor, then put it back on the shelf please.", ("bedroom",),
     "on(book, floor)"),
    # a Polish speaker's list: a semicolon, "you" and the steps
    ("Eventually the blanket is on the couch; you fold it and put it in the basket.", ("living_room",),
     "on(blanket, sofa)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), EVENTUALLY_POSSIBLY)
def test_eventually_with_a_present_state_is_a_doubt(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"Eventually my mug is also on the desk" (dev 14 study_desk_cleanup_d14): English "eventually"
    says "in the end" only of an event, so with a state said now it is the hedge of French
    "éventuellement" (`sentences._EVENTUAL_BEFORE`, `_EVENTUAL_AFTER`)."""
    assert asks(text, rooms, condition), factors(text, rooms)


def test_eventually_of_an_event_or_an_instruction_asks_nothing() -> None:
    """Near misses: a future ("Eventually the kettle will boil"), an instruction ("Eventually, put
    the mug in the sink") and a passive's participle ending a procedure ("Eventually the kettle is
    switched off") keep "in the end"."""
    assert not factors("Eventually the kettle will boil; then switch it off.", ("kitchen",))
    assert not factors("Eventually, put the mug in the sink.", ("kitchen",))
    assert not factors("Wash up. Eventually the kettle is switched off.", ("kitchen",))


#: a quiz: numbered cases asking what to do, lettered options, and an answer key given apart:
#: (text, rooms, the condition asked, the keyed option's words under its "yes"). Before the rule
#: 0 of 4 put the keyed option under the case (the cases were asked as questions with no answer)
FIRE_WARDEN_QUIZ = """FIRE WARDEN REFRESHER
Question 1: The kettle in the staff kitchen is still on at the end of the day. What should you do?
(a) Leave it, someone will come back. (b) Switch it off.
Question 2: The fridge door is open. What should you do?
(a) Close it. (b) Leave it.

Answers: 1-b, 2-a"""
CHORE_QUIZ = """Chore Quiz!
1) Your teddy bear is on the floor. What do you do?
   a. Put it on the bed
   b. Kick it under the bed
2) The towel is wet. What do you do?
   a. Leave it on the floor
   b. Hang it on the towel rail
Key: 1 a 2 b"""
QUIZZES = [
    # a workplace training quiz: "Question N:", bracketed letters, "Answers: 1-b"
    (FIRE_WARDEN_QUIZ, ("kitchen",), "state(kettle, toggled_on)", "switch it off"),
    (FIRE_WARDEN_QUIZ, ("kitchen",), "state(fridge, open)", "close it"),
    # a child's chore quiz: "1)", options one a line, "Key: 1 a 2 b"
    (CHORE_QUIZ, ("bedroom",), "on(teddy_bear, floor)", "put it on the bed"),
    (CHORE_QUIZ, ("bathroom",), "state(towel, wet)", "hang it on the towel rail"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "words"), QUIZZES)
def test_a_quiz_answer_key_gives_the_branch(text: str, rooms: tuple[str, ...], condition: str, words: str) -> None:
    """dev 14 laundry_sorting_d14's structure: "Q1. <case>. What do you do? a) ... b) ..." and an
    answer key at the bottom; the keyed option is what to do in the case
    (`sentences.keyed_answers`), and the others are not."""
    under = instruction_under(text, rooms, condition)
    assert words in under.get("yes", ""), under
    assert "kick" not in under.get("yes", "") and "leave it, someone" not in under.get("yes", ""), under


def test_a_quiz_without_its_key_is_left_as_it_is() -> None:
    """Near misses: without a key (or a key of one answer) which option is right is not said, and
    a "Key:" line that keys nothing ("Key: in the drawer") is no answer key."""
    unkeyed = CHORE_QUIZ.rsplit("\n", 1)[0]
    assert keyed_answers(unkeyed) == unkeyed
    assert keyed_answers(unkeyed + "\nKey: 1 a") == unkeyed + "\nKey: 1 a"
    steps = "1. Lock the door.\n2. Water the plant.\nKey: in the drawer by the door."
    assert keyed_answers(steps) == steps
