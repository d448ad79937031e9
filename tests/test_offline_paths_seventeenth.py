"""Paths not combined: how a text nests one condition under another over several sentences,
seventeenth session (docs/reader.md, "A condition's scope over the sentences after it
(seventeenth session)"). Each structure is written first as a table of composed texts in several
registers (measured before its rule and after), with near misses whose second condition is not
nested and must stay independent; every text is written for the test, none copied from a
development set."""

from __future__ import annotations

import pytest
from reading import CATALOG, brief, placed

from logicenveval.offline.analysis import analyse


def _nested(text: str, rooms: tuple[str, ...], inner: str, outer: str) -> bool:
    """Whether the factor asking `inner` is asked under the factor asking `outer` (its context)."""
    fs = analyse(brief(text, rooms), CATALOG).factors
    outer_ids = {f.id for f in fs if outer in f.values.values()}
    return any(inner in f.values.values() and any(c in outer_ids for c, _ in f.context) for f in fs)


def _together(text: str, rooms: tuple[str, ...], inner: str, outer: str) -> bool:
    """Whether the two conditions are asked in one subtask (so their values are combined)."""
    a = analyse(brief(text, rooms), CATALOG)
    ids = {f.id: set(f.values.values()) for f in a.factors}
    return any(any(inner in ids[i] for i in g) and any(outer in ids[i] for i in g) for g in a.groups)


def _asked(text: str, rooms: tuple[str, ...]) -> dict[str, set[str]]:
    return {f.id: set(f.values.values()) for f in analyse(brief(text, rooms), CATALOG).factors}


# -- a framing condition: "If X:" or a sentence that is only a condition -------------------------
#
# "If the laptop is on the desk: put it on the shelf. The cabinet may be open or shut; ..." - a
# condition closed by a colon frames what follows it on its line (or, alone on its line, the list
# under it), as a heading does; "Only if X." said as a sentence of its own has no instruction of its
# own and frames the sentences after it on its line. A condition those sentences raise is asked
# under the frame.

#: (text, rooms, the inner condition, the outer condition it is asked under)
FRAMED: list[tuple[str, tuple[str, ...], str, str]] = [
    # an office handover: a colon frame, a doubt in the next sentence
    ("If the laptop is on the desk: put it on the shelf. The cabinet may be open or shut; either way "
     "make sure the cabinet is closed.", ("office",), "state(cabinet, open)", "on(laptop, desk)"),
    # a recipe card: a heading, "Only if X." as a sentence of its own, the steps after it
    ("SMOOTHIE - Only if there are apples in the fruit bowl. Get the knife, put the cutting board on the "
     "counter unless it is there already, and slice an apple.", ("kitchen",),
     "on(cutting_board, kitchen_counter)", "inside(apple, bowl)"),
    # a chat message in small letters: "only when", the condition in the next sentence
    ("only when the laptop is on the bed. take it to the desk, and close the drawer if it is open.",
     ("bedroom",), "state(drawer, open)", "on(laptop, bed)"),
    # a house-sitter's list: a colon frame alone on its line, the list under it
    ("If the towel is on the floor:\n- pick it up\n- open the hamper if it is closed\n- put the towel in "
     "the hamper", ("bathroom",), "state(hamper, open)", "on(towel, floor)"),
    # a formal notice: "In case X:", a remark on another thing after the first instruction
    ("In case the book is on the sofa: return it to the bookshelf. The lamp might still be on; switch it "
     "off.", ("living_room",), "state(table_lamp, toggled_on)", "on(book, sofa)"),
    # a cleaner's note: "Only if X." about a state, the next sentence's postposed condition
    ("Only if the cereal box is in the cupboard. Take it out, put the bowl on the table unless it is "
     "there already, and pour the cereal.", ("kitchen",), "on(bowl, dining_table)",
     "inside(cereal_box, cabinet)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), FRAMED)
def test_a_framing_condition_covers_the_sentences_after_it(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    assert _nested(text, rooms, inner, outer), _asked(text, rooms)
    assert _together(text, rooms, inner, outer)


#: near misses: (text, rooms, a condition, another that must stay independent of it)
NOT_FRAMED: list[tuple[str, tuple[str, ...], str, str]] = [
    # a comma, not a colon: the condition is its own instruction's, the next sentence stands alone
    ("If the laptop is on the desk, put it on the shelf. The cabinet may be open; close it.",
     ("office",), "state(cabinet, open)", "on(laptop, desk)"),
    # the frame ends with its line
    ("Only if the cereal box is in the cupboard. Take it out and pour the cereal.\nThe bowl may be on the "
     "table; put it in the sink.", ("kitchen",), "on(bowl, dining_table)", "inside(cereal_box, cabinet)"),
    # a colon frame, the next line a step of its own
    ("If the towel is on the floor: pick it up.\nIf the lamp is on, switch it off.", ("bathroom", "bedroom"),
     "state(table_lamp, toggled_on)", "on(towel, floor)"),
    # a list under a colon frame ends at the blank line
    ("If the towel is on the floor:\n- pick it up\n- put it in the hamper\n\nIf the mirror is dirty, clean it.",
     ("bathroom",), "state(mirror, dirty)", "on(towel, floor)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), NOT_FRAMED)
def test_a_condition_outside_the_frame_stays_independent(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    asked = _asked(text, rooms)
    assert any(inner in v for v in asked.values()) and any(outer in v for v in asked.values()), asked
    assert not _nested(text, rooms, inner, outer), asked


# -- a question answered by the instruction after it -------------------------------------------------
#
# "Laptop on the bed? Over to the desk with it, and check that the lamp is switched off - it may
# still be on." The question stands alone; the sentence after it, taking up its thing, is the
# instruction for its "yes", so a doubt that instruction raises is asked under that answer.

ANSWERED: list[tuple[str, tuple[str, ...], str, str]] = [
    # a card: a verbless question, a verbless directive with "it", a doubt after a dash
    ("Laptop on the bed? Over to the desk with it, and check that the lamp is switched off - it may "
     "still be on.", ("bedroom",), "state(desk_lamp, toggled_on)", "on(laptop, bed)"),
    # a text message in small letters: a full question, the doubt in the answer's own words
    ("is the towel on the floor? pick it up and put it in the hamper, the hamper might be closed so open "
     "it first", ("bathroom",), "state(hamper, open)", "on(towel, floor)"),
    # a landlady's note: a question, the answer's postposed condition on another thing
    ("Is the mug on the desk? Take it to the kitchen and put it in the sink, and open the dishwasher if "
     "it is closed.", ("study", "kitchen"), "state(dishwasher, open)", "on(mug, desk)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), ANSWERED)
def test_a_questions_answer_is_asked_under_it(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    assert _nested(text, rooms, inner, outer), _asked(text, rooms)


NOT_ANSWERED: list[tuple[str, tuple[str, ...], str, str]] = [
    # the next sentence does not take up the question's thing: a step of its own
    ("Is the mug on the desk? Switch the lamp off if it is on.", ("study",), "state(desk_lamp, toggled_on)",
     "on(mug, desk)"),
    # a request put as a question frames nothing: its places are stated, not asked
    ("Someone left the laptop and the book in the study - can you tidy them away? A laptop that is open is "
     "closed first. Should the book be on the floor, put it on the desk.", ("study", "bedroom"),
     "state(laptop, open)", "in_room(book, study)"),
    # the question has its own answer in its sentence; the next sentence is another step
    ("Is the laptop on the bed? Then put it on the desk. Switch the lamp off if it is on.", ("bedroom",),
     "state(desk_lamp, toggled_on)", "on(laptop, bed)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), NOT_ANSWERED)
def test_a_step_after_a_question_that_does_not_answer_it_stays_independent(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    asked = _asked(text, rooms)
    assert any(inner in v for v in asked.values()) and any(outer in v for v in asked.values()), asked
    assert not _nested(text, rooms, inner, outer), asked


# -- the alternative to an instruction carried on ----------------------------------------------------
#
# "If the desk is dirty, wipe it down. Use the cloth, and afterwards hang it on the rack. If there is
# no cloth, use a paper towel." The second sentence goes on with the first's instruction (under its
# condition); the third, on the thing the second uses, is that instruction's alternative, so the
# thing's absence is asked under the first condition too.

ALTERNATIVE: list[tuple[str, tuple[str, ...], str, str]] = [
    # a voice note
    ("If the desk is dirty, wipe it down. Use the cloth, and afterwards hang it on the rack. If there is "
     "no cloth, use a paper towel.", ("study",), "exists(cloth)", "state(desk, dirty)"),
    # house rules, "should" for the condition, "have no" for the absence
    ("Should the stove be dirty, clean it. Grab the sponge and rinse it after. If you have "
     "no sponge, use a dish towel.", ("kitchen",), "exists(sponge)", "state(stove, dirty)"),
    # a terse note, the condition after its instruction
    ("Wipe the table if it is sticky. Take the sponge and leave it by the sink after. No sponge? Use a "
     "paper towel.", ("kitchen",), "exists(sponge)", "state(dining_table, dirty)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), ALTERNATIVE)
def test_an_alternative_to_a_carried_instruction_is_asked_under_its_condition(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    assert _nested(text, rooms, inner, outer), _asked(text, rooms)


NOT_ALTERNATIVE: list[tuple[str, tuple[str, ...], str, str]] = [
    # the third sentence's thing is not the one the second uses
    ("If the desk is dirty, wipe it down. Use the cloth, and afterwards hang it on the rack. If there is "
     "no paper towel, buy some.", ("study",), "exists(paper_towel)", "state(desk, dirty)"),
    # no instruction carried on between: the absence is a step of its own
    ("If the desk is dirty, wipe it down. If there is no cloth, use a paper towel.", ("study",),
     "exists(cloth)", "state(desk, dirty)"),
]


@pytest.mark.parametrize(("text", "rooms", "inner", "outer"), NOT_ALTERNATIVE)
def test_a_condition_on_another_thing_after_a_carried_instruction_stays_independent(
        text: str, rooms: tuple[str, ...], inner: str, outer: str) -> None:
    asked = _asked(text, rooms)
    assert any(inner in v for v in asked.values()) and any(outer in v for v in asked.values()), asked
    assert not _nested(text, rooms, inner, outer), asked


# -- a yes/no question asking whether a thing is in a room ------------------------------------------
#
# "Is there a towel in the bathroom? If so, ..." asks the room presence the branch turns on; the
# placement reader took the room as the thing's stated place (a noun phrase's own room, whatever
# the mood), which settled the factor away. A question that goes on to ask something else ("Is the
# lamp in the bedroom on?") still names which thing is meant by its room.

ROOMS = ("living_room", "kitchen", "study", "bedroom", "bathroom")

ROOM_ASKED: list[tuple[str, str]] = [
    # a house-sitter's note: "is there", "if so"
    ("Is there a towel in the bathroom? If so, hang it on the rack.", "in_room(towel, bathroom)"),
    # a parent's text: a definite thing, both answers
    ("Is the laptop in the study? If it is, bring it to the sofa; if not, bring the book.",
     "in_room(laptop, study)"),
    # a chat message: a greeting first, "still", the condition after its instruction
    ("Hi! Is the laptop still in the study? bring it to the sofa if it is.", "in_room(laptop, study)"),
    # a checklist: a plural, "any"
    ("Are there any apples in the kitchen? If yes, put one on the plate.", "in_room(apple, kitchen)"),
]


@pytest.mark.parametrize(("text", "condition"), ROOM_ASKED)
def test_a_question_whether_a_thing_is_in_a_room_asks_it(text: str, condition: str) -> None:
    assert any(condition in v for v in _asked(text, ROOMS).values()), _asked(text, ROOMS)
    assert condition not in placed(text, ROOMS)


@pytest.mark.parametrize(("text", "condition"), [
    # the room says which lamp the question asks about
    ("Is the lamp in the bedroom on? If so, switch it off.", "in_room(table_lamp, bedroom)"),
    # a statement, then a question of the thing's state
    ("The towel is in the bathroom. Is it wet? If so, hang it on the rack.", "in_room(towel, bathroom)"),
    # a question of a state after the room, in small letters
    ("is the towel in the bathroom still wet? if so hang it on the rack", "in_room(towel, bathroom)"),
])
def test_a_room_that_names_which_thing_is_meant_stays_stated(text: str, condition: str) -> None:
    assert condition in placed(text, ROOMS)
