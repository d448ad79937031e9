"""Objects and placements of dev 25 and dev 26 (issue 47, fifteenth session): the structures behind
the unbound role and the broken stated placements of dev 26's new tasks, read through the offline
model's `name_objects` and `described_placements`. Every sentence is written for these tests, in
several registers (a club notice, a text message, a rule book, a kit list, a house note, a
report); none is copied from a task."""

from __future__ import annotations

from pathlib import Path

import pytest
from reading import forms_named

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.naming import name_objects
from logicenveval.offline.placement import described_placements

FORMS = Path(__file__).parent / "data" / "naming_forms" / "forms_fifteenth.tsv"
#: sentences of `FORMS` naming their row's kind: 0 of 14 before the fifteenth session's rule
#: (`_Reader.named_holder`), 14 after it (the last two once the rule also holds off
#: `modifies_next`, which took "sneaker" for a modifier of the head's own kind)
NAMED_AT_LEAST = 14


def _kinds(text: str, rooms: tuple[str, ...] = ()) -> list[str]:
    return [o["category"] for o in name_objects(text, load_catalog(), rooms=rooms)]


def _placed(text: str, roles: dict[str, str]) -> list[str]:
    brief = {"description": text, "rooms": ["room"], "roles": {r: {"category": c} for r, c in roles.items()}}
    return [f for f in described_placements(brief) if not f.startswith("in_room(")]


# -- a modifier naming a kind by another of its names before a head of several kinds names the
# kind "<that kind's own name> <head>" ("the boot rack": a shoe rack; `_Reader.named_holder`) --


def test_fifteenth_session_forms_do_not_fall() -> None:
    assert forms_named(FORMS) >= NAMED_AT_LEAST


@pytest.mark.parametrize(("text", "kind"), [
    # a club notice
    ("Members shall leave muddy footwear on the boot rack in the porch.", "shoe_rack"),
    # a text message
    ("trainers go on the sneaker rack pls not the floor", "shoe_rack"),
    # a house note
    ("Stand your brolly in the brolly stand when you come in.", "umbrella_stand"),
    # a parent's note
    ("The settee pillow is on the floor again.", "sofa_pillow"),
])
def test_a_modifier_by_another_name_names_its_holder(text: str, kind: str) -> None:
    assert kind in _kinds(text)


@pytest.mark.parametrize(("text", "kind", "not_kind"), [
    # a name of its own before a generic head stays the object (`compound`)
    ("Put the soap in the vanity cabinet.", "bathroom_vanity", "soap_bar"),
    # the holder's head alone names no holder of the modifier's kind
    ("Put the boots on the shelf.", "wall_shelf", "shoe_rack"),
])
def test_no_holder_without_its_name(text: str, kind: str, not_kind: str) -> None:
    kinds = _kinds(text)
    assert kind in kinds
    assert not_kind not in kinds or not_kind == "soap_bar"


def test_the_boots_and_their_rack_are_two_objects() -> None:
    kinds = _kinds("Check the work boots on the boot rack by the door.")
    assert "shoe" in kinds and "shoe_rack" in kinds


# -- a definite thing whose noun has one modifier that is also a verb's form ("the work boots",
# "the garden boots") is still presumed where the phrase puts it (`_resting`) --


@pytest.mark.parametrize("text", [
    # a task card
    "Inspect the work boots on the shoe rack.",
    # a chatty note
    "can u check the garden boots on the shoe rack, they might be muddy",
])
def test_a_noun_modifier_keeps_the_phrase_definite(text: str) -> None:
    assert _placed(text, {"boots": "shoe", "rack": "shoe_rack"}) == ["on(boots, rack)"]


@pytest.mark.parametrize("text", [
    "Put the work boots on the shoe rack.",  # an instruction moves it: no fact
    "If the work mug is on the desk, wash it.",  # a condition asks it
    "Tom leaves the work mug on the desk.",  # a habit
    "You might find the work mug on the desk.",  # a doubted finding
])
def test_a_noun_modifier_reads_no_moved_or_asked_place(text: str) -> None:
    assert _placed(text, {"boots": "shoe", "rack": "shoe_rack", "mug": "mug", "desk": "desk"}) == []


# -- a bracket's place followed by what tells the place apart ("(on the utility shelf above the
# sink)") or by an apposition of the thing ("(on the desk, the blue one)"): its place
# (`_place_closes`) --


@pytest.mark.parametrize(("text", "fact"), [
    # a kit list
    ("Kit list: scrub brush (on the utility shelf above the sink); water bottle.", "on(brush, shelf)"),
    # a match-day note
    ("Take the water bottle (on the desk, the blue one) to practice.", "on(bottle, desk)"),
    # a house note
    ("The brush (in the drawer under the sink) is the new one.", "inside(brush, drawer)"),
])
def test_a_bracket_place_with_its_modifier(text: str, fact: str) -> None:
    roles = {"brush": "scrub_brush", "shelf": "utility_shelf", "sink": "sink", "bottle": "water_bottle",
             "desk": "desk", "drawer": "drawer"}
    assert fact in _placed(text, roles)


@pytest.mark.parametrize("text", [
    "The brush (on the utility shelf or in the drawer) needs washing.",
    "The brush (on the utility shelf, or in the drawer) needs washing.",
])
def test_a_bracket_with_an_alternative_place_places_nothing(text: str) -> None:
    assert _placed(text, {"brush": "scrub_brush", "shelf": "utility_shelf", "drawer": "drawer"}) == []


# -- a relative clause after "<head> for/of <complement>" speaks of the head ("the basket for
# journals, which stands on the floor": the basket; `_antecedent`) --


@pytest.mark.parametrize(("text", "fact"), [
    # an inventory
    ("The study holds a desk and the wicker basket for magazines, which stands on the floor.",
     "on(basket, floor)"),
    # a report
    ("Beside the door is the cardboard box of toys, which sits on the shelf.", "on(box, shelf)"),
])
def test_a_relative_after_a_complement_speaks_of_the_head(text: str, fact: str) -> None:
    roles = {"desk": "desk", "basket": "basket", "magazine": "magazine", "box": "cardboard_box", "toy": "toy",
             "shelf": "wall_shelf"}
    facts = _placed(text, roles)
    assert fact in facts
    assert not any(f.startswith(("on(magazine,", "on(toy,")) for f in facts)


def test_a_relative_after_a_plain_list_still_speaks_of_its_last_noun() -> None:
    facts = _placed("There is a desk and a magazine, which is on the floor.", {"desk": "desk", "magazine": "magazine"})
    assert "on(magazine, floor)" in facts
