"""Condition forms from the unread cells of `benchmarks/condition_forms.py` (nineteenth session,
issue 47), each grouped by its structure, not by one text. Each structure is a table of sentences
written here, in several registers, rooms, kinds and presences, with near misses that must stay
as they are; each table was measured before its rule (the counts in each test's docstring).

- a presence followed by an adverbial of time ("if the mug is there right now", "should the keys
  be here at the moment"): its rule was withdrawn at the merge (an unseen row fell), so these
  cases are strict xfails (`WITHDRAWN`);
- a presence asked as a question whose subject is a pronoun or whose finite word is a modal of
  likelihood ("Is it there? If so, ...", "Might the keys still be here?"): read as the statement
  "if it is there" (`clauses.presence_asked`);
- a presence guessed ("Maybe the mug is there. If that's the case, ...", "It will probably be
  here. If so, ...") or asked by a tag ("The mug is there, isn't it? Then ..."): read as the
  presence the guess or the statement says (`analysis._doubted_presence`, `analysis._unbiased`);
- a condition with a modal before "be" typed without its comma before its instruction ("If the
  mug might still be missing let me know"): "be" is a copula, so the condition ends before the
  instruction as after "is" (`clauses._PREDICATES`)."""

from __future__ import annotations

import pytest
from reading import asks, factors, instruction_under

#: a presence followed by an adverbial of time ("if the mug is there right now") is not read: the
#: rule that read it (`clauses.PRESENCE_TIMES`, 282 of the grid's 409 unread cells) was withdrawn
#: at its merge, because the held-out 2 set's new tasks fell with it (LogCov 78.1 -> 74.0, SceVR
#: 68.0 -> 64.0, FauDR 75.0 -> 66.7); docs/reader.md, "What it still misreads"
WITHDRAWN = pytest.mark.xfail(strict=True, reason="presence before an adverbial of time: rule withdrawn")

#: a presence condition whose "there"/"here" is followed by an adverbial of time: (text, rooms,
#: the condition asked). Before the rule 1 of 8 was asked (the chat message's "now")
PRESENCE_THEN_TIME = [
    # a flatmate's note: "right now", a pronoun after the thing named
    pytest.param("Have a look at my mug. If it is there right now, put it in the sink.", ("kitchen",), "exists(mug)", marks=WITHDRAWN),
    # an office rota: the noun, "at the moment"
    pytest.param("If the stapler is here at the moment, leave it on the desk.", ("office",), "exists(stapler)", marks=WITHDRAWN),
    # a formal register: an inverted "should", "this morning"
    pytest.param("Should the umbrella be there this morning, hang it by the door.", ("hallway",), "exists(umbrella)", marks=WITHDRAWN),
    # a chat message in small letters: a contraction, "now"
    ("if the remote's there now can u put it on the table", ("living_room",), "exists(remote_control)"),
    # a negated presence, "by now": the answer is the negation
    pytest.param("Unless the laptop is there by now, let me know.", ("office",), "exists(laptop)", marks=WITHDRAWN),
    # a carer's note: "again"
    pytest.param("If the blanket is there again, fold it.", ("bedroom",), "exists(blanket)", marks=WITHDRAWN),
    # a time of day after "still" ("still" asks nothing more)
    pytest.param("If the towel is still there tonight, put it in the laundry basket.", ("bathroom",), "exists(towel)", marks=WITHDRAWN),
    # a negated presence said outright
    pytest.param("If the book isn't here today, tell me.", ("living_room",), "exists(book)", marks=WITHDRAWN),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), PRESENCE_THEN_TIME)
def test_presence_before_a_time_adverbial_is_asked(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"If the mug is there right now, ..." (the grid's "trailing" cells of "there", 282 of its
    409 unread cells): an adverbial of time after the presence says when it is asked, not where,
    so the condition still asks only whether the thing is there (`clauses._presence`)."""
    assert asks(text, rooms, condition), factors(text, rooms)


def test_presence_then_a_place_or_already_stays_apart() -> None:
    """"already there" presupposes an instruction's goal (`analysis._Reader._already`), a place
    named after "there" ("there on the shelf") or before it ("Put the mug on the shelf. If it is
    there now, ...") is the place asked, and "you"/"we" there is the reader's or speaker's own
    presence: none is read as the thing's bare presence."""
    kitchen = ("kitchen",)
    assert asks("Put the mug on the shelf unless it is there already.", kitchen, "on(mug, wall_shelf)")
    assert not asks("Put the mug on the shelf unless it is there already.", kitchen, "exists(mug)")
    assert asks("If the mug is there on the shelf, wash it.", kitchen, "on(mug, wall_shelf)")
    assert asks("Put the mug on the shelf. If it is there now, wipe the counter.", kitchen, "on(mug, wall_shelf)")
    assert not asks("Put the mug on the shelf. If it is there now, wipe the counter.", kitchen, "exists(mug)")
    assert not asks("If you are there right now, put the mug in the sink.", kitchen, "exists(mug)")
    assert not asks("If we are here tonight, wash the mug.", kitchen, "exists(mug)")


#: a presence asked as a question, its subject a pronoun or its finite word a modal of
#: likelihood, then "If so"/"If yes"/"If not": (text, rooms, the condition asked). Before the rule
#: 0 of 8 were asked
PRESENCE_QUESTIONS = [
    # a flatmate's note: the thing named, then "Is it there?"
    ("Pop into the living room and look for my glasses. Are they there? If so, bring them to me.",
     ("living_room",), "exists(glasses)"),
    # an office handover: a plural pronoun, "If yes"
    ("Have a look for the scissors. Are they there? If yes, put them in the drawer.", ("office",),
     "exists(scissors)"),
    # a formal register: a modal of likelihood, the noun
    ("Might the umbrella still be here? If so, hang it by the door.", ("hallway",), "exists(umbrella)"),
    # a chat message in small letters: "could", a pronoun after a dislocated noun
    ("the charger - could it be there?? if so grab it pls", ("office",), "exists(phone_charger)"),
    # a negative question: the asker's expectation, the proposition is the positive one
    ("Go and look at the teddy bear. Isn't it there? If so, put it on the bed.", ("bedroom",),
     "exists(teddy_bear)"),
    # a future "will" asked
    pytest.param("Will the laptop be here tonight? If not, let me know.", ("office",), "exists(laptop)", marks=WITHDRAWN),
    # a carer's note: "still" and a time after the presence
    pytest.param("Have a look at the blanket. Is it still there this evening? If so, fold it.", ("living_room",),
                 "exists(blanket)", marks=WITHDRAWN),
    # a house-sitter's note: a dislocated noun, "If not"
    ("The cat's bowl - is it there? If not, put out a new one.", ("kitchen",), "exists(pet_bowl)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), PRESENCE_QUESTIONS)
def test_presence_question_with_a_pronoun_or_modal_is_asked(text: str, rooms: tuple[str, ...],
                                                            condition: str) -> None:
    """"Is it there? If so, ..." and "Might the mug still be there? If so, ..." (the grid's "Is X?
    If so" cells of "there" with a pronoun, a dislocated noun or a modal): the question asks what
    the statement "if it is there" asks (`clauses.presence_asked`)."""
    assert asks(text, rooms, condition), factors(text, rooms)


def test_presence_question_near_misses_stay_apart() -> None:
    """A question of the place ("Is it there on the shelf?") asks the place, a question of the
    reader ("Are you there?") asks nothing of the thing, and a place said before ("Check the desk
    for the scissors. Are they there?") is the place asked."""
    kitchen = ("kitchen",)
    assert not asks("Look at the mug. Is it there on the shelf? If so, wash it.", kitchen, "exists(mug)")
    assert asks("Check the desk for the scissors. Are they there? If yes, put them in the drawer.", ("office",),
                "on(scissors, desk)")
    # a place said two sentences before the pronoun's question is still the place asked
    assert not asks("I might have left my keys on the shelf. I looked everywhere. Are they there? If so, bring them.",
                    ("hallway",), "exists(keys)")
    assert not asks("Are you there? If so, wash the mug.", kitchen, "exists(mug)")


#: a presence guessed with an adverb or a modal of doubt, or stated and tagged, then taken up by
#: "If that's the case"/"If so"/"Then": (text, rooms, the condition asked). Before the rules 0 of
#: 8 were asked
PRESENCE_GUESSED = [
    # a flatmate's note: "maybe", the noun, "If that's the case"
    ("Maybe the laptop is here. If that's the case, put it on the desk.", ("office",), "exists(laptop)"),
    # a formal register: "will probably", "If so"
    ("The umbrella will probably be there. If so, hang it by the door.", ("hallway",), "exists(umbrella)"),
    # a chat message in small letters: "prob", a contraction, a pronoun after the thing named
    ("look at my glasses. maybe they're there. if so bring them down", ("bedroom",), "exists(glasses)"),
    # a carer's note: "perhaps" and "still", a dislocated noun
    ("The blanket - perhaps it is still there. If that is the case, fold it.", ("living_room",), "exists(blanket)"),
    # a tag question, the noun
    ("The remote is there, isn't it? Then put it on the table.", ("living_room",), "exists(remote_control)"),
    # a tag question, a contracted pronoun after the thing named
    ("Have a look at the mug. It's there, isn't it? Then wash it.", ("kitchen",), "exists(mug)"),
    # a plural tag after a guess of time
    pytest.param("The scissors are here right now, aren't they? Then put them in the drawer.", ("office",), "exists(scissors)", marks=WITHDRAWN),
    # a modal guess with "possibly"
    ("The charger might possibly be there. If so, plug it in.", ("office",), "exists(phone_charger)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), PRESENCE_GUESSED)
def test_guessed_or_tagged_presence_is_asked(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"Maybe the mug is there. If that's the case, ..." and "The mug is there, isn't it? Then
    ..." (the grid's "if that's the case", "will be; if so" and "X, isn't it? Then" cells of
    "there"): the guess guesses a presence, as the condition "if it is there" asks one, and a tag
    asks for agreement with the statement, not more (`analysis._doubted_presence`, `_unbiased`)."""
    assert asks(text, rooms, condition), factors(text, rooms)


def test_guessed_presence_near_misses_stay_apart() -> None:
    """A guess of a place ("Maybe the mug is there on the shelf") asks the place; a guess after a
    place said ("The mug goes on the shelf. It will probably be there.") is left to that place; a
    guess of the reader's or the speaker's presence ("Maybe we'll be there") asks nothing of a
    thing; an existential guess with a place ("Maybe there is a mug in the sink") asks the place."""
    kitchen = ("kitchen",)
    assert not asks("Maybe the mug is there on the shelf. If so, wash it.", kitchen, "exists(mug)")
    assert not asks("The mug goes on the shelf. It will probably be there. If not, put it there.", kitchen,
                    "exists(mug)")
    assert not asks("Maybe we will be there tonight. If so, wash the mug.", kitchen, "exists(mug)")
    assert asks("Maybe there is a mug in the sink. If so, wash it.", kitchen, "inside(mug, sink)")


#: a condition whose verb group is a modal and "be", typed without its comma before an
#: instruction: (text, rooms, the condition, the value the instruction falls under, the
#: instruction's first words). Before the rule 3 of 8 put the instruction under its value (a
#: state word before the instruction cut it, and an inverted "should"; an absence did not)
MODAL_BE_NO_COMMA = [
    # a flatmate's note: an absence, "let me know"
    ("If the mug might still be missing let me know.", ("kitchen",), "exists(mug)", "no", "let me know"),
    # an office rule: "could be gone", "tell me"
    ("If your keys could be gone tell me straight away.", ("hallway",), "exists(keys)", "no", "tell me"),
    # a chat message in small letters: "may be", an absence, "text me"
    ("if the laptop may be missing text me pls", ("office",), "exists(laptop)", "no", "text me"),
    # a formal register: an inverted "should ... be"
    ("Should the remote be missing inform us at once.", ("living_room",), "exists(remote_control)", "no",
     "inform us"),
    # a parent's note: "might be" and a state word (already cut)
    ("If the towel might be wet hang it up.", ("bathroom",), "state(towel, wet)", "yes", "hang it"),
    # a caretaker's card: "could still be" and a participle
    ("If the fridge could still be left open shut it.", ("kitchen",), "state(fridge, open)", "yes", "shut it"),
    # a house-sitter's text: "will be" of an absence
    ("If the cat bowl will be gone by tonight buy a new one.", ("kitchen",), "exists(pet_bowl)", "no", "buy"),
    # a neighbour's note: "might have been taken", then an instruction
    ("If the bucket might have been taken call me.", ("garage",), "exists(bucket)", "no", "call me"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "value", "words"), MODAL_BE_NO_COMMA)
def test_modal_be_without_comma_ends_the_condition(text: str, rooms: tuple[str, ...], condition: str,
                                                   value: str, words: str) -> None:
    """"If the mug might still be missing let me know" (the grid's "if, no comma" cells of
    "missing" with a modal: the instruction fell under neither value): "be" after a modal is the
    condition's copula (`clauses._PREDICATES`), so the instruction after it is cut off as after
    "is" (`clauses._imperative_cut`)."""
    under = instruction_under(text, rooms, condition)
    other = "no" if value == "yes" else "yes"
    assert words in under.get(value, "") and words not in under.get(other, ""), under


def test_be_of_a_wish_or_a_duty_stays_apart() -> None:
    """"to be" of a wish or a duty ("If you want to be useful wash the mug", "If the bin has to be
    emptied take it out") asks no state of a thing: no factor is read."""
    assert not factors("If you want to be useful wash the mug.", ("kitchen",))
    assert not factors("If the bin has to be emptied take it out.", ("kitchen",))
