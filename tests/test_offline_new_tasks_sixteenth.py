"""Values never set in the new tasks, sixteenth session's second round (docs/reader.md, "Values
never set: possession, ... (sixteenth session)"). Each structure is written first as a table of
composed sentences in several registers, kinds and states (measured before its rule and after),
with near misses that must not be misread; every sentence is written for the test, none copied
from a development set."""

from __future__ import annotations

import pytest
from reading import asks, factors, named

from logicenveval.offline.lexicon import _named_things
from logicenveval.offline.sentences import expand

# -- "have got" of possession: "unless it's got water in it" ---------------------------------------
#
# British English says possession with "have got" as often as with "have": "it's got water in it",
# "the vase hasn't got any water in it". The reader read "it's" as "it is" before "got" and took
# "has ... water in it" only without "got", so a container's filling was never asked (0 of 7 of
# the table below before the rule, 7 of 7 after).

#: (text, rooms, the condition asked)
HAVE_GOT: list[tuple[str, tuple[str, ...], str]] = [
    # a kitchen card, a heading, "unless"
    ("Kettle. Unless it's got water in it, fill it at the sink.", ("kitchen",), "state(kettle, filled)"),
    # a gardener's note, a full noun subject, "otherwise"
    ("If the watering can has got water in it, leave it; otherwise fill it at the sink.", ("garden",),
     "state(watering_can, filled)"),
    # a text message, lower case, "no"
    ("the dog bowl - if it's got no water in it, top it up at the sink pls", ("kitchen",),
     "state(pet_bowl, filled)"),
    # a house-sitter's list, the negation contracted, "any"
    ("If the vase hasn't got any water in it, fill it at the sink.", ("living_room",), "state(vase, filled)"),
    # a shed checklist, "if not" after
    ("Water bottle on the bench: if it has got water in it, leave it there, if not, fill it at the sink.",
     ("garage",), "state(water_bottle, filled)"),
    # a formal notice, an inverted condition with "have got"
    ("Guests are asked to check the kettle. Should it have got water in it, it must be emptied into the sink.",
     ("kitchen",), "state(kettle, filled)"),
    # a flatmate's note, another liquid, "still" after
    ("The mug on the desk - if it's got coffee in it still, tip it into the sink.", ("study",),
     "state(mug, filled)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), HAVE_GOT)
def test_have_got_a_liquid_in_it_asks_whether_the_container_is_filled(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """`sentences._CONTRACTIONS` ("it's got" -> "it has got"), `analysis._HAS_IN` ("has got")."""
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "word"), [
    # "has got" of becoming before a state stays the state ("has been wet"), not a filling
    ("If the towel's got wet, hang it on the towel rail.", ("bathroom",), "filled"),
    # what it has got is no liquid: no filling asked
    ("If the vase has got a crack in it, put it in the bin.", ("living_room",), "filled"),
    # the speaker's "you've got", of another thing: the kettle is not asked
    ("If you've got water in your bottle, leave the kettle alone.", ("kitchen",), "kettle"),
])
def test_have_got_without_a_liquid_in_the_thing_is_no_filling(
        text: str, rooms: tuple[str, ...], word: str) -> None:
    assert not any(word in c for values in factors(text, rooms).values() for c in values), factors(text, rooms)


def test_it_is_stays_it_is_before_everything_but_got() -> None:
    assert expand("it's got water in it") == "it has got water in it"
    assert expand("it's gone") == "it is gone"
    assert expand("that's on the floor") == "that is on the floor"
    assert "towel_wet" in factors("If the towel's got wet, hang it on the towel rail.", ("bathroom",))


# -- a place asked alone: "The towel. On the floor? Hang it up." ------------------------------------
#
# A checklist or a note names a thing, then asks its place with a question that is only the place
# ("On the floor?", "Still on the bed?"): the subject and copula are elided, as in "if on the
# floor". The reader read such a question only when the sentence before had said the same place
# (2 of 7 of the table below before the rule, 7 of 7 after).

#: (text, rooms, the condition asked)
PLACE_ASKED: list[tuple[str, tuple[str, ...], str]] = [
    # a checklist, a heading sentence
    ("The remote control. On the sofa? Put it on the TV stand.", ("living_room",), "on(remote_control, sofa)"),
    # a numbered list
    ("2. The towel. On the floor? Hang it on the towel rail.", ("bathroom",), "on(towel, floor)"),
    # a note, a doubt that says no place
    ("The towel may have fallen. On the floor? Hang it on the towel rail.", ("bathroom",), "on(towel, floor)"),
    # a story-like note, the thing the object of another verb
    ("I took my hat off in a hurry. On the floor? Hang it on the coat hook.", ("hallway",), "on(hat, floor)"),
    # a chat message, lower case, "still"
    ("ok so the laptop. still on the bed? move it to the desk pls", ("bedroom",), "on(laptop, bed)"),
    # a terse card, "lying"
    ("Pillow. Lying on the floor? Put it back on the bed.", ("bedroom",), "on(pillow, floor)"),
    # a polite notice, another place said before
    ("The umbrella was last seen by the door. On the floor? Please place it in the umbrella stand.",
     ("hallway",), "on(umbrella, floor)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), PLACE_ASKED)
def test_a_place_asked_alone_is_asked_of_the_thing_named_before(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """`sentences._ELIDED_PLACE_QUESTION`: "On the floor?" -> "Is it on the floor?"."""
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "word"), [
    # an idiom of "on" that is no place: the lamp's state is still asked, no place
    ("The lamp is on the desk. On your way out? Switch it off.", ("study",), "on(desk_lamp"),
    # "in": where the listener is, not the thing
    ("In the kitchen? Switch the kettle off.", ("kitchen",), "inside(kettle"),
    # a question with a subject of its own (a tag) is not given another
    ("The mug. On the desk, is it? Put it in the sink.", ("study",), "it, desk"),
])
def test_a_question_that_is_no_elided_place_is_not_read_as_one(
        text: str, rooms: tuple[str, ...], word: str) -> None:
    assert not any(word in c for values in factors(text, rooms).values() for c in values), factors(text, rooms)


def test_an_idiom_of_on_keeps_its_thing_s_state() -> None:
    assert asks("The lamp is on the desk. On your way out? Switch it off.", ("study",),
                "state(desk_lamp, toggled_on)")


# -- a vocative after a place: "Take it to the sink, Tom, and put it in." ---------------------------
#
# A note to a named reader calls them by name after an instruction's place ("to the sink, Tom"):
# the name is the listener's, not the place's given name (as "her doll, Lady Rosabel" is the
# doll's). Read as the place's name, every later "Tom left ..." spoke of the sink and its pronouns
# after (2 of 5 of the table below were misread before the rule, 0 after; the other 3 held).

#: (text, rooms, the condition asked)
VOCATIVES: list[tuple[str, tuple[str, ...], str]] = [
    # a primer-like note, the name as subject before and as vocative after
    ("Tom left his towel on the floor. Is it on the floor now? Then hang it on the towel rail. "
     "Is the cup dirty? Take it to the sink, Tom, and put it in.", ("bathroom",), "on(towel, floor)"),
    # a parent's note, the vocative first
    ("Put the mug in the sink, Anna. Anna left her scarf on the chair. If it is on the chair, hang it on "
     "the coat hook.", ("hallway",), "on(scarf, chair)"),
    # a chat message, lower case but the name
    ("pls put the remote on the tv stand, Jo. Jo left the blanket on the sofa. if it's on the sofa fold it "
     "and put it in the basket", ("living_room",), "on(blanket, sofa)"),
    # a formal notice, a title before the name
    ("Kindly return the kettle to the counter, Mr Hale. Mr Hale left his umbrella on the floor; if it is on "
     "the floor, it should be placed in the umbrella stand.", ("kitchen",), "on(umbrella, floor)"),
    # an exclamation, the name opening the next sentence
    ("Hang your coat on the hook, Sam! Sam, your book: is it on the bed? Then put it on the shelf.",
     ("bedroom",), "on(book, bed)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), VOCATIVES)
def test_a_name_after_a_place_is_the_listener_not_the_place(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """`lexicon._VOCATIVE_PREPS`: "to the sink, Tom" names no sink "Tom"."""
    assert asks(text, rooms, condition), factors(text, rooms)


def test_a_vocative_names_nothing_and_an_apposition_still_does() -> None:
    phrases = {("sink",): {"sink"}, ("kettle",): {"kettle"}, ("doll",): {"doll"}, ("hook",): {"coat_hook"}}
    assert _named_things("Take it to the sink, Tom, and put it in.", phrases) == {}
    assert _named_things("Hang it on the hook, Anna.", phrases) == {}
    # the noun phrase no place: the name is still the thing's
    assert _named_things("Please check our kettle, Bessie.", phrases) == {("bessie",): {"kettle"}}
    assert _named_things("She went to find her doll, Lady Rosabel.", phrases) == {("lady", "rosabel"): {"doll"}}


# -- a heading's bare kind, then the thing by its colour: "3. The folder. ... the blue folder ..." --
#
# A list item opens with its topic's bare kind as a heading ("3. The folder.", "Mug:", "TOWEL -")
# and then names the thing by its colour: one thing, not a plain folder and a blue one (two
# objects, the factor asked of the blue one while the plain one stands in the scene). 0 of 6 of the
# table below named one object before the rule, 6 of 6 after.

#: (text, rooms, the kind, the one object's name, the condition asked)
HEADED: list[tuple[str, tuple[str, ...], str, str, str]] = [
    # a legal letter, a numbered paragraph
    ("3. The folder. Our client believes the blue folder has slipped off the desk. If it's lying on the "
     "floor, put it back on the desk.", ("office",), "folder", "blue_folder", "on(blue_folder, floor)"),
    # a terse card, a colon
    ("Mug: my blue mug is on the desk. If it's dirty, put it in the sink.", ("study",), "mug", "blue_mug",
     "state(blue_mug, dirty)"),
    # a notice in capitals, a dash
    ("TOWEL - the green towel is probably on the floor. If it is, hang it on the towel rail.", ("bathroom",),
     "towel", "green_towel", "on(green_towel, floor)"),
    # a numbered list, a possessive
    ("2. The mug. My blue mug is on the desk. If it's dirty, put it in the sink.", ("study",), "mug",
     "blue_mug", "state(blue_mug, dirty)"),
    # the plain kind said again after the colour
    ("The folder. Our client says the blue folder has slipped off the desk. If the folder is on the floor, "
     "put it on the desk.", ("office",), "folder", "blue_folder", "on(blue_folder, floor)"),
    # a chat message, lower case
    ("the scarf. my red scarf might be on the floor, if it is hang it on the coat hook pls", ("hallway",),
     "scarf", "red_scarf", "on(red_scarf, floor)"),
]


@pytest.mark.parametrize(("text", "rooms", "kind", "name", "condition"), HEADED)
def test_a_heading_s_kind_and_the_coloured_thing_after_it_are_one(
        text: str, rooms: tuple[str, ...], kind: str, name: str, condition: str) -> None:
    """`naming._Reader.heading_mention`: the heading names the coloured thing's topic."""
    assert [n for n, (category, _) in named(text, rooms).items() if category == kind] == [name]
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "kind", "names"), [
    # a plain mention that says something of its own is a thing of its own
    ("The folder is on the desk. The blue folder is on the shelf.", ("office",), "folder",
     {"folder", "blue_folder"}),
    # a plural heading over two coloured things
    ("Folders. The blue folder is on the desk and the red folder is on the floor.", ("office",), "folder",
     {"blue_folder", "red_folder"}),
    # a heading of the kind over two things told apart otherwise: the heading is no thing of its own
    ("Towels: the green towel is on the floor, the spare towel is in the cupboard.", ("bathroom",), "towel",
     {"green_towel", "spare_towel"}),
])
def test_a_plain_mention_that_is_no_lone_heading_keeps_its_own_thing(
        text: str, rooms: tuple[str, ...], kind: str, names: set[str]) -> None:
    assert {n for n, (category, _) in named(text, rooms).items() if category == kind} == names


# -- a proposition offered with its negation: "Either the magazine lies on the floor or it does not."
#
# "Either P or it does not", "P or it isn't", "P or not" leave P open, as "maybe P" does; the
# conditions after take it up ("If so", "If it is", or in order, "In the first case ... In the
# second case ..."). The forms with "be" and "or not" were read already (analysis's "either"); a
# lexical verb's negation ("or it does not") was not (5 of 7 of the table below before the rule,
# 7 of 7 after).

#: (text, rooms, the condition asked)
OPEN_DISJUNCTIONS: list[tuple[str, tuple[str, ...], str]] = [
    # a mathematician's note, the cases in order
    ("Either the magazine lies on the floor or it does not. In the first case, put it on the coffee table. "
     "In the second case, leave it.", ("living_room",), "on(magazine, floor)"),
    # a legal letter, "the former case"
    ("Either the umbrella is still open or it is not. In the former case, it is to be closed.", ("hallway",),
     "state(umbrella, open)"),
    # a text message, lower case, "isn't"
    ("the desk lamp is on or it isn't. if it is, switch it off pls", ("study",), "state(desk_lamp, toggled_on)"),
    # a terse card, "or not"
    ("Kettle on or not. If on, switch it off.", ("kitchen",), "state(kettle, toggled_on)"),
    # a care plan, the second case only
    ("Either the towel is wet or it isn't. In the second case, fold it and put it on the shelf.", ("bathroom",),
     "state(towel, wet)"),
    # a shed list, a semicolon
    ("Either the box is open or not; if it is, close it.", ("garage",), "state(cardboard_box, open)"),
    # a lecture-like note, "either" after the subject
    ("The remote either lies on the sofa or it does not. In the first case, put it on the TV stand.",
     ("living_room",), "on(remote_control, sofa)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), OPEN_DISJUNCTIONS)
def test_a_proposition_offered_with_its_negation_is_asked(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """`sentences._OPEN_DISJUNCTION` ("Maybe ...", its first case "If so")."""
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms"), [
    # a warning of what follows if the instruction is not done: no negation of its clause
    ("Wipe the table now or it will not dry by morning.", ("kitchen",)),
    ("Put the milk in the fridge, or it does not keep.", ("kitchen",)),
    ("Shut the fridge or it is not cold by morning.", ("kitchen",)),
])
def test_an_instruction_or_its_consequence_is_no_open_proposition(text: str, rooms: tuple[str, ...]) -> None:
    assert factors(text, rooms) == {}
