"""Conditions in their ordinary grammatical forms (issue 47, the eleventh session): the tables of
benchmarks/condition_forms.py (a small sample of what it composes, not its figures), and the
reader rules its matrix led to, each on sentences written here in two registers or more (none
produced by the generator, none from the task sets), with near misses that must not be read."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

import pytest
from reading import asks, factors

from logicenveval.domain.catalog import load_catalog

ROOT = Path(__file__).resolve().parents[1]


def _generator() -> ModuleType:
    spec = importlib.util.spec_from_file_location("condition_forms", ROOT / "benchmarks" / "condition_forms.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up by name
    spec.loader.exec_module(module)
    return module


FORMS = _generator()


# -- the generator's tables --------------------------------------------------------------------

def test_every_state_has_kinds_of_the_catalog_that_can_be_in_it() -> None:
    catalog = load_catalog().categories
    assert set(FORMS.KINDS) == set(FORMS.STATES)
    for name, kinds in FORMS.KINDS.items():
        state = FORMS.STATES[name]
        assert "simple" in state.verbs
        for kind, _noun, _room, _det in kinds:
            assert kind in catalog
            if state.fact.startswith("state("):
                flag = state.fact.split(", ")[1].rstrip(")")
                assert flag in catalog[kind].default_states, (kind, flag)


def test_the_matrix_forms_only_sentences_english_forms() -> None:
    cases = FORMS.cases()
    assert len(cases) > 1000
    assert len({c.text for c in cases}) == len(cases)
    for c in cases:
        assert "{" not in c.text and "  " not in c.text and c.text.endswith(".")
        verb = FORMS.STATES[c.state].verbs[c.verb]
        if c.subject == "elided":
            assert verb.elidable
        if c.connective == "should":
            assert verb.base is not None
    seen = {(c.connective, c.subject, c.verb) for c in cases}
    assert ("Is X? If so", "elided", "simple") not in seen
    assert ("should", "noun", "modal") not in seen


def test_a_small_sample_is_composed_and_read() -> None:
    catalog = load_catalog()
    by_cell = {(c.connective, c.subject, c.verb, c.state, c.kind): c for c in FORMS.cases()}
    fridge = by_cell[("if", "noun", "simple", "open", "fridge")]
    assert fridge.text == "Please go to the kitchen. If the fridge is open, close it. Then tell me when you're done."
    question = by_cell[("Is X? If so", "pronoun", "perfect", "on", "table_lamp")]
    assert "Has it been left on? If so, switch it off." in question.text
    should = by_cell[("should", "dislocated", "passive", "open", "fridge")]
    assert "The fridge - should it be left open, close it." in should.text
    for case in (fridge, question, should):
        assert FORMS.reading(case, catalog) == (True, True)  # read, and its action under the right answer


# -- the participle of a verb whose result is a state says that state --------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a friendly note, a perfect
    ("Morning! Pop into the kitchen - if the casserole dish has been washed already, stack it in the cupboard.",
     ("kitchen",), "state(plate, dirty)"),
    # a formal instruction, a passive after "where"
    ("Kindly attend to the laundry room. Where the bucket has been emptied, refill it from the tap.",
     ("laundry_room",), "state(bucket, filled)"),
    # a text message, the state in progress
    ("yo check the bathroom, if ur towel is still dripping, hang it on the rail", ("bathroom",), "state(towel, wet)"),
    # a closing checklist, a perfect of rinsing with a plural subject
    ("Closing up: if the cups have been rinsed, put them on the drying rack.", ("kitchen",), "state(cup, dirty)"),
])
def test_a_result_participle_is_its_state(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms"), [
    # the verb as an instruction, not a condition: no question
    ("Wash the mug, then put it in the cupboard.", ("kitchen",)),
    ("Empty the bucket and rinse it out.", ("laundry_room",)),
])
def test_the_verb_itself_asks_nothing(text: str, rooms: tuple[str, ...]) -> None:
    assert factors(text, rooms) == {}


# -- "the X is (not) there": whether the thing named is there at all ---------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a house-sitter's note, negated and contracted
    ("Please go to the kitchen. If the blender isn't there, let me know and I'll order one.", ("kitchen",),
     "exists(blender)"),
    # a terse office message, negated in full
    ("Nip into the office: if my laptop is not there, text me straight away.", ("office",), "exists(laptop)"),
    # positive, a possessive subject
    ("Have a look in the bedroom, and if your teddy bear is there, bring it downstairs.", ("bedroom",),
     "exists(teddy_bear)"),
])
def test_a_named_thing_there_or_not_is_its_presence(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert asks(text, rooms, condition)


def test_not_there_after_a_placement_is_still_that_place() -> None:
    # near misses: "there" points back to the place just named, noun or pronoun
    assert asks("Put the mug on the shelf. If the mug is not there, tell me.", ("kitchen",), "on(mug, wall_shelf)")
    assert asks("The remote goes on the TV stand. If it is not there, put it there.", ("living_room",),
                "on(remote_control, tv_stand)")


# -- an elided subject before a place: "if on the floor" ---------------------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # a tidy-up list, the condition after a colon
    ("Bathroom: have a look at the towel: if on the floor, pick it up and hang it on the rail.", ("bathroom",),
     "on(towel, floor)"),
    # a hurried message, the condition after its instruction, with "still"
    ("Kids room, quick one - grab the teddy bear if still on the floor and pop it in the crib.", ("kids_room",),
     "on(teddy_bear, floor)"),
])
def test_an_elided_subject_before_a_place_is_the_thing_named(text: str, rooms: tuple[str, ...],
                                                             condition: str) -> None:
    assert asks(text, rooms, condition)


def test_a_place_of_the_listener_or_a_time_is_no_condition_on_a_thing() -> None:
    # near misses: "in" the room is where the listener is; "while on the phone" is a time
    assert set(factors("When in the kitchen, check whether the fridge is open and close it.", ("kitchen",))) \
        == {"fridge_open"}
    assert factors("While on the phone, keep an eye on the kettle.", ("kitchen",)) == {}


def test_a_result_participle_before_its_noun_asks_nothing() -> None:
    # near miss: a recipe's "1 washed shirt", a list's "the rinsed cups" describe the thing
    assert factors("Ingredients: 1 washed shirt. Fold the shirt onto the shelf.", ("laundry_room",)) == {}
    assert factors("Put the rinsed cups in the cupboard, please.", ("kitchen",)) == {}
