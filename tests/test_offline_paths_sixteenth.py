"""Values never set and paths not combined, sixteenth session (docs/reader.md, "Elided conditions
and offered alternatives (sixteenth session)"). Each structure is written first as a table of
composed sentences in several registers, kinds and states (measured before its rule and after),
with near misses that must not be misread; every sentence is written for the test, none copied
from a development set."""

from __future__ import annotations

import pytest
from reading import asks, factors

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
