"""Values never set and paths not combined, sixteenth session (docs/reader.md, "Elided conditions
and offered alternatives (sixteenth session)"). Each structure is written first as a table of
composed sentences in several registers, kinds and states (measured before its rule and after),
with near misses that must not be misread; every sentence is written for the test, none copied
from a development set."""

from __future__ import annotations

import pytest
from reading import CATALOG, asks, brief, factors

from logicenveval.offline.analysis import analyse

# -- a condition whose predicate is elided: "close the microwave if it isn't already" -------------
#
# "if it isn't already", "unless it already is", "if it's not yet": the condition says no state of
# its own; its predicate is the one the instruction it goes with would set (VP ellipsis), so it
# asks whether the thing is already in the state the instruction's verb leaves it in.

#: (text, rooms, the condition asked)
ELIDED: list[tuple[str, tuple[str, ...], str]] = [
    # a flatmate's text, a bare verb of result after its object
    ("close the microwave if it isn't already pls", ("kitchen",), "state(microwave, open)"),
    # a formal notice, "unless ... already is", a verb with its particle before the object
    ("Residents are asked to switch off the desk lamp unless it already is.", ("study",),
     "state(desk_lamp, toggled_on)"),
    # a checklist, the condition put first (a cataphor)
    ("Fridge. If it isn't already, shut the fridge.", ("kitchen",), "state(fridge, open)"),
    # a parent's note, "yet", emptying a container
    ("Empty the bin in the kitchen if it's not yet, love.", ("kitchen",), "state(trash_can, filled)"),
    # a workshop card, the particle after the object, a plural
    ("Turn the lights off unless they already are.", ("garage",), "state(ceiling_lamp, toggled_on)"),
    # a host's message, switching on, "done" left out
    ("When you arrive, please switch the kettle on if it isn't already.", ("kitchen",),
     "state(kettle, toggled_on)"),
    # a caretaker's rota, opening, a perfect tense
    ("Open the wardrobe unless it has been already.", ("bedroom",), "state(wardrobe, open)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), ELIDED)
def test_an_elided_condition_asks_the_state_its_instruction_sets(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """`analysis._elided`: the state the instruction's verb (or its particle) leaves the thing in."""
    assert asks(text, rooms, condition), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "word"), [
    # the elided predicate is a place: it stays the place, not a state
    ("Put the mug in the sink unless it already is.", ("kitchen",), "state(mug"),
    # a condition with its own state word asks that state, not the instruction's
    ("Close the microwave if it's dirty.", ("kitchen",), "open"),
    # no "already" / "yet": nothing is elided ("if you can" asks nothing)
    ("Shut the fridge if you can.", ("kitchen",), "fridge"),
    # the agent, not the thing: "if you haven't already" says nothing of the lamp
    ("Switch off the desk lamp if you haven't already.", ("study",), "desk_lamp"),
])
def test_a_condition_not_elided_is_not_read_as_the_instructions_state(
        text: str, rooms: tuple[str, ...], word: str) -> None:
    assert not any(word in c for values in factors(text, rooms).values() for c in values), factors(text, rooms)


# -- a question offering alternatives: "Bread anywhere else, or none left?" ------------------------
#
# After a question of where a thing is, a verbless question (or condition) offering the other
# places and its absence ("X anywhere else, or none left?", "elsewhere, or none at all?") asks the
# place's other value and whether there is one at all: "or none" is an elided "or there is none".

#: (text, rooms, the location asked, the presence asked)
ALTERNATIVES: list[tuple[str, tuple[str, ...], str, str]] = [
    # a cook's card, terse questions, "none left"
    ("Bread on the counter? Slice it. Bread anywhere else, or none left? No toast then.", ("kitchen",),
     "on(bread, kitchen_counter)", "exists(bread)"),
    # a chat message, lower case, "somewhere else ... none at all", no comma
    ("towel on the towel rail? hang it straight. towel somewhere else or none at all? grab a fresh one",
     ("bathroom",), "on(towel, towel_rack)", "exists(towel)"),
    # a formal instruction, the question after "if so"
    ("Is the remote control on the sofa? If so, place it on the TV stand. The remote control elsewhere, "
     "or none at all? No action is required.", ("living_room",), "on(remote_control, sofa)",
     "exists(remote_control)"),
    # a Q&A sheet, a condition with "if" and the elided alternative
    ("Q: Where's the mug? A: If the mug is on the desk, wash it; if it is elsewhere, or none, leave it.",
     ("study",), "on(mug, desk)", "exists(mug)"),
]


@pytest.mark.parametrize(("text", "rooms", "place", "presence"), ALTERNATIVES)
def test_an_elided_none_among_alternatives_asks_the_things_presence(
        text: str, rooms: tuple[str, ...], place: str, presence: str) -> None:
    """`analysis._Reader.facts`: "or none" after an alternative of place is "or there is none"."""
    assert asks(text, rooms, place) and asks(text, rooms, presence), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "thing"), [
    # "none of them": a choice among things, not an absence
    ("Wash the mugs on the desk, or none of them if you're short of time.", ("study",), "exists(mug)"),
    # "or none" as an amount of an instruction ("one biscuit or none") asks nothing
    ("Put one cushion on the sofa or none, as you like.", ("living_room",), "exists(pillow)"),
])
def test_none_as_an_amount_asks_no_presence(text: str, rooms: tuple[str, ...], thing: str) -> None:
    assert not any(thing in c for values in factors(text, rooms).values() for c in values), factors(text, rooms)


# -- a thing named with its place, then "if it's there": "the sponge on the shelf, if it's there" --
#
# An instruction names a thing (a tool, mostly) with the place it should be at ("wipe it with the
# sponge on the shelf", "the wet wipes on the table"), then a condition asks only "if it's
# there": "there" is that place and "it" that thing (not the topic the instruction works on), so
# the condition asks whether the thing is at the place. Not after a verb of putting, whose place
# is a goal ("put the mug on the shelf").

#: (text, rooms, the location asked)
NAMED_THERE: list[tuple[str, tuple[str, ...], str]] = [
    # a cleaning rota, a plural tool, a comma before the condition
    ("The floor is stained. Clean the stain with the wet wipes on the coffee table, if they are there. "
     "Otherwise use the mop.", ("living_room",), "on(wet_wipe, coffee_table)"),
    # a flatmate's note, the topic spoken of by "it" too
    ("The mirror is dirty. Wipe it with the sponge on the shelf if it's there; if not, use a towel.",
     ("bathroom",), "on(sponge, wall_shelf)"),
    # a terse card, a container, a dash
    ("Dust the desk with the cloth in the drawer, if it's there - otherwise use a tissue.", ("study",),
     "inside(cloth, drawer)"),
    # a verbless method line
    ("The sink is grimy. Best method: the sponge on the counter, if it is still there. Not there? "
     "Then a cloth.", ("kitchen",), "on(sponge, kitchen_counter)"),
]


@pytest.mark.parametrize(("text", "rooms", "place"), NAMED_THERE)
def test_there_after_a_thing_named_with_its_place_asks_that_place(
        text: str, rooms: tuple[str, ...], place: str) -> None:
    """`analysis._named_with_place`: "if it's there" asks the thing at the place it was named at."""
    f = factors(text, rooms)
    assert any(place in c and "exists" not in c for values in f.values() for c in values), f


@pytest.mark.parametrize(("text", "rooms", "word"), [
    # a place after a verb of putting is a goal: "if it's there" is not asked of the mug's goal
    ("Put the mug on the shelf if it's there.", ("kitchen",), "on(mug, wall_shelf)"),
    # no place named with the thing: "there" is presence, as before
    ("Wipe the table with the sponge if it's there; otherwise the cloth.", ("kitchen",), "on(sponge"),
])
def test_there_without_a_thing_named_at_a_place_is_not_read_as_one(
        text: str, rooms: tuple[str, ...], word: str) -> None:
    assert not any(word in c for values in factors(text, rooms).values() for c in values), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms"), [
    # things listed, then "or none": no alternative of place, so no absence of the first thing
    ("The sofa may have a cushion, the remote control or a mug on it, or any of them, or none. Put the "
     "mug in the sink if it is on the sofa.", ("living_room",)),
    ("On the desk: a book, a mug, or none. If the book is on the desk, shelve it.", ("study",)),
])
def test_or_none_after_listed_things_asks_no_absence(text: str, rooms: tuple[str, ...]) -> None:
    assert not any(c.startswith("exists") for values in factors(text, rooms).values() for c in values), \
        factors(text, rooms)


# -- a part named again bare: "the plant's soil ... If the soil is dry" -----------------------------
#
# A part named with its thing ("the plant's soil", "the soil of the potted plant", "the washing
# machine's door") and named again bare later ("if the soil is dry", "Soil dry ->") is still that
# thing's part, whatever thing the clauses between spoke of (a book, a mug): the state is the
# thing's, not the topic's.

#: (text, rooms, the condition asked, a factor that must not be made)
PART_AGAIN: list[tuple[str, tuple[str, ...], str, str]] = [
    # a numbered check list, a question between
    ("Check whether the plant's soil is dry. Then look at the book on the desk: is it a novel? If the soil "
     "is dry, water the plant.", ("study",), "state(potted_plant, wet)", "book_wet"),
    # a chat message, lower case, "soil's"
    ("the plant's soil might be dry lol. also is the mug on the desk dirty?? if the soil's dry give the "
     "plant some water", ("study",), "state(potted_plant, wet)", "mug_wet"),
    # a formal inspection, "the soil of the potted plant"
    ("Inspect the soil of the potted plant. Is the book on the shelf a novel? If the soil is wet, leave the "
     "plant alone.", ("living_room",), "state(potted_plant, wet)", "book_wet"),
    # a laundry note, a door (read before as the nearest thing that opens)
    ("The washing machine's door may be open. Is the towel on the floor wet? If the door is open, shut it.",
     ("laundry_room",), "state(washing_machine, open)", "towel_open"),
]


@pytest.mark.parametrize(("text", "rooms", "condition", "wrong"), PART_AGAIN)
def test_a_part_named_again_is_its_things(text: str, rooms: tuple[str, ...], condition: str, wrong: str) -> None:
    """`analysis._Reader.part_of`: the thing the part was last named of."""
    f = factors(text, rooms)
    assert any(condition in c for values in f.values() for c in values) and wrong not in f, f


def test_a_part_named_of_a_later_thing_is_that_things() -> None:
    text = "The washing machine's door is shut. The dryer's door may be open. If the door is open, shut it."
    f = factors(text, ("laundry_room",))
    assert "dryer_open" in f and "washing_machine_open" not in f, f


#: a heading that names the part bare ("Soil dry ->", "soil dry ="): (text, rooms, a factor that
#: must not be made, the factors one subtask must hold)
PART_HEADING: list[tuple[str, tuple[str, ...], str, list[str]]] = [
    # a dispatcher's card, questions first, then arrows
    ("Questions: is the plant's soil dry? Is the mug on the desk dirty? Answers: Soil dry -> bring the plant "
     "the watering can. If the can is empty, fill it at the sink first.", ("study",), "mug_wet",
     ["potted_plant_wet", "watering_can_filled"]),
    # a chat message with "=" for "then"
    ("check the plant's soil pls. and is the book on the desk a novel? soil dry = water the plant with the "
     "watering can, and if the can's empty fill it first", ("study",), "book_wet",
     ["potted_plant_wet", "watering_can_filled"]),
]


@pytest.mark.parametrize(("text", "rooms", "wrong", "group"), PART_HEADING)
def test_a_part_heading_is_its_things(text: str, rooms: tuple[str, ...], wrong: str, group: list[str]) -> None:
    """`analysis._read_heading`: a heading opening with a part named of a thing is that thing's."""
    a = analyse(brief(text, rooms), CATALOG)
    assert wrong not in factors(text, rooms) and any(set(group) <= set(g) for g in a.groups), a.groups
