"""Values the older rewordings of built-in tasks never set (issue 47, eighteenth session, `--losses`:
"a value never set"), by the structure in which the rewording said what its original said plainly:
an enumeration whose last item follows "or else" ("a book, an alarm clock, or else a phone" in a
sonnet's rewording); a verbless instruction, a thing and its place, with "unless it's (already)
there" (a chef's list: "frying pan on the stove unless it's there already"); a sentence of verse or
of hard-wrapped prose going on after a line that ends on a comma, a semicolon or a colon (a
sonnet's "put each thing in the place where it should go: / ... / the phone upon the desk"); a
holder "for" a bare plural set against one "for other <kind>" (a list's "a red toy box for dolls and
a white toy box for other toys", where the original said "a red one for dolls"). Each structure is written here as
composed sentences in several registers, rooms and kinds, with near misses that must stay apart
(none copied from the task sets)."""

from __future__ import annotations

import pytest
from reading import asks as _asks
from reading import factors as _factors
from reading import kinds

from logicenveval.offline.sentences import unquote

# -- (a) "or else" before an enumeration's last item -------------------------------------------

#: a list of two or more things, each with "a"/"an", whose last item follows ", or else": the items
#: are alternatives of one list, each a thing that may be where the list says
OR_ELSE_LISTS = [
    # a hotel card, a relative "where there may lie"
    ("The bed, where there may lie a book, an alarm clock, or else a phone. Put the phone on the desk, "
     "the clock on the nightstand and the book on the shelf.", ("bedroom",), "on(cell_phone, bed)"),
    # an office memo, "there might sit"
    ("The office has a desk, where there might sit a mug, a stapler, or else a pen. Put the mug in the "
     "sink and the pen in the drawer.", ("office",), "on(pen, desk)"),
    # a plain note, the place after the list
    ("There may be a mug, a stapler, or else a pen on the desk. Put the mug in the sink and the pen in "
     "the drawer.", ("office",), "on(pen, desk)"),
    # a verse, a line break inside the list
    ("On the sofa there may lie a remote,\na cushion, or else a book;\nput the book on the shelf and the "
     "remote on the table.", ("living_room",), "on(book, sofa)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), OR_ELSE_LISTS)
def test_an_enumerations_last_item_after_or_else_is_one_of_its_items(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert _asks(text, rooms, condition), _factors(text, rooms)


#: "or else" after one thing, no list: the alternative of an instruction, kept as "else"
OR_ELSE_ALTERNATIVES = [
    # a workshop note: wipe with the sponge if it's there, else with a towel
    ("If the bench is dirty, wipe it with the sponge if the sponge is on the shelf, or else a towel.",
     ("garage",), "on(sponge, wall_shelf)"),
    # a chatty note, "or else" before an instruction
    ("If the kettle is on the counter, switch it on, or else fill a pan.", ("kitchen",), "on(kettle, kitchen_counter)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), OR_ELSE_ALTERNATIVES)
def test_or_else_after_a_single_thing_stays_an_alternative(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert _asks(text, rooms, condition), _factors(text, rooms)


# -- (b) a verbless instruction with "unless it's (already) there" ------------------------------

#: a thing and a place with no verb, then "unless it's there already" / "unless they're already
#: there": an instruction to put the thing there, whose condition asks whether it is there
VERBLESS_UNLESS_THERE = [
    # a chef's list, after a comma
    ("Eggs: open the fridge, frying pan on the stove unless it's there already, one egg into the pan.",
     ("kitchen",), "on(pan, stove)"),
    # a checklist line, "already there"
    ("Before bed:\n- Lamp on the desk unless it's already there.\n- Lights off.", ("study",), "on(desk_lamp, desk)"),
    # a text message, plural, "they're"
    ("Leaving now. Towels in the basket unless they're there already. Thanks!", ("bathroom",),
     "inside(towel, basket)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), VERBLESS_UNLESS_THERE)
def test_a_verbless_instruction_unless_already_there_asks_the_place(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert _asks(text, rooms, condition), _factors(text, rooms)


#: near misses: a statement with its verb ("is"), and a place with no "unless": nothing is asked of
#: the place by this rule
VERBLESS_NEAR_MISSES = [
    ("The frying pan is on the stove. Crack an egg into it.", ("kitchen",), "on(pan, stove)"),
    ("Lamp on the desk, lights off, door shut.", ("study",), "on(desk_lamp, desk)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), VERBLESS_NEAR_MISSES)
def test_a_stated_or_unconditioned_place_asks_nothing(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert not _asks(text, rooms, condition), _factors(text, rooms)



@pytest.mark.parametrize("text", [
    # a terse list of cases, a bare state then a dash: the state is the case, no thing
    "Blanket: dirty - into the laundry basket; clean - onto the armchair, unless it's already there.",
    # a bare state without a dash, after a question
    "Towel: wet? On the rack. Dry onto the shelf unless it's there already.",
    # a bare state as a subject
    "Mug: dirty in the sink, clean in the cupboard unless it's already there.",
])
def test_a_bare_state_before_the_place_gets_no_verb_of_putting(text: str) -> None:
    """The state stays the case's condition ("clean - onto the armchair"): no "put" is added
    before it, which would make the state a thing."""
    assert unquote(text).lower().count("put ") == 0, unquote(text)


# -- (c) verse and wrapped prose: a line in lower case after ",", ";" or ":" goes on -----------

#: texts that end their lines with marks (verse, hard-wrapped prose), a sentence going on over a
#: line ending in a comma, semicolon or colon: a list of goals after "put each ... where it goes:"
#: stays that instruction's, and a condition broken over two lines stays whole
RUN_ON_TEXTS = [
    # a ballad: the goals after a colon, one a line
    ("Upon the desk there may lie a mug, a pen, or a stapler;\nand by the wall a cabinet stands, as ever.\n"
     "So tidy up the desk, and put each thing where it belongs:\na mug in the sink;\nthe pen in the drawer;\n"
     "the stapler on the shelf, and then you're done.", ("office",), "on(pen, desk)"),
    # a hard-wrapped email, a condition broken after a comma (read so before the rule too: kept)
    ("Hi Sam, thanks for feeding the cat this week. A couple of things,\nif the lamp on the desk is still on "
     "when you leave,\nplease switch it off; and if the blanket is on the floor,\nput it back on the sofa. "
     "Thanks again, see you Sunday.", ("living_room",), "on(blanket, floor)"),
    # a nursery rhyme: the goal list after a colon
    ("On the bed there may lie a sock, a shirt, or a towel;\nand by the door there stands a laundry basket;\n"
     "so clear the bed and put each thing away:\nthe sock in the basket;\nthe towel on the chair,\n"
     "and then the bed is clear once more.", ("bedroom",), "on(towel, bed)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), RUN_ON_TEXTS)
def test_a_line_in_lower_case_after_a_comma_semicolon_or_colon_goes_on(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert _asks(text, rooms, condition), _factors(text, rooms)


@pytest.mark.parametrize(("text", "joined"), [
    # verse: the lower-case line after a colon is the sentence's
    ("The shelf has three levels,\nand each level holds a kind:\nthe top one novels, the lower one essays,\n"
     "and every other book below.", True),
    # a checklist whose lines open in capitals: each line stays a line
    ("Before you leave:\nLamp off;\nWindow shut;\nBlanket on the sofa.", False),
    # a chat, its lines mostly unmarked (no verse): each line ends a message
    ("ok so\nlamp off pls,\nwindow too\nand blanket on sofa\nthx", False),
])
def test_only_a_text_marking_its_line_ends_runs_on_and_only_into_lower_case(text: str, joined: bool) -> None:
    """The lines run on only in a text most of whose lines end on a mark (`_punctuated_lines`) and
    only into a line that opens in lower case."""
    assert (unquote(text).count("\n") < text.count("\n")) == joined, unquote(text)


# -- (d) a holder "for" a class, set against one "for other <kind>" ------------------------------

#: holders each for a class of things, one of them for "other <kind>": the classes are that kind's
#: kinds (a toy's doll, ball; a book's novel), asked of the thing, no objects of their own
PURPOSE_CLASSES = [
    # a room list, the kind named only after the holders
    ("In the room: a sofa; a red toy box for dolls and a white toy box for other toys. A toy found on the "
     "floor is put into the matching toy box.", ("living_room",), "attr(toy, kind, doll)"),
    # a terse heading, crates
    ("Den: a blue crate for balls and a green crate for other toys. If there's a toy on the rug, it goes "
     "in the matching crate.", ("living_room",), "attr(toy, kind, ball)"),
    # a house description, shelves for books
    ("The study has a low shelf for novels and a high shelf for other books. A book left on the desk goes "
     "on the right shelf.", ("study",), "attr(book, kind, novel)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), PURPOSE_CLASSES)
def test_a_holder_for_a_class_against_other_kind_asks_the_kind(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert _asks(text, rooms, condition), _factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "kind"), [
    # no "other": the plural after "for" may be the things themselves
    ("There is a red box for dolls. Put the dolls from the floor in it.", ("kids_room",), "doll"),
    ("There is a basket for towels by the door. Put the towels from the floor in it.", ("bathroom",), "towel"),
])
def test_a_holder_for_things_with_no_other_kind_keeps_the_things(text: str, rooms: tuple[str, ...], kind: str) -> None:
    assert kind in kinds(text, rooms)
