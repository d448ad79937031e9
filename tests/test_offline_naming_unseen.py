"""Naming as people name things (issue 47, twelfth session): the kinds of naming the losses of
dev 19 and dev 20 show, read through the offline model's `name_objects` answer. Sentences are
written for these tests, in several registers; none is copied from a task."""

from __future__ import annotations

from pathlib import Path

import pytest
from reading import forms_named

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.naming import name_objects

FORMS = Path(__file__).parent / "data" / "naming_forms" / "forms_twelfth.tsv"
#: sentences of `FORMS` naming their row's kind: 17 of 35 before the twelfth session's rules, 23
#: after the sort-named and hint rules, 24 after the vessel rule ("her bottle of water"), 27 after
#: the thirteenth session's ("the long table", "a bottle of claret", "the merlot bottle")
NAMED_AT_LEAST = 27


def _kinds(text: str, rooms: tuple[str, ...] = ()) -> list[str]:
    return [o["category"] for o in name_objects(text, load_catalog(), rooms=rooms)]


def test_twelfth_session_forms_do_not_fall() -> None:
    assert forms_named(FORMS) >= NAMED_AT_LEAST


# -- a sort named by a noun before a head several kinds share is the head's sense in general use
# (`HEAD_SENSES`, `_Reader.sort_named`) --


@pytest.mark.parametrize("text", [
    # a bridge club's newsletter
    "After bridge night, members are asked to take the cloth off the card table.",
    # a text message
    "ur keys r on the games table lol",
    # a village-hall notice
    "All tools to be returned to the trestle table by 5pm.",
    # a decorator's note to himself
    "Who left the torch on the pasting table overnight?",
    # a family WhatsApp
    "The board games live on the poker table in the den.",
])
def test_a_sort_named_by_a_noun_is_the_table_in_general_use(text: str) -> None:
    assert "dining_table" in _kinds(text)


@pytest.mark.parametrize(("text", "kind", "not_kind"), [
    # a modifier a kind's name holds still names that kind
    ("Put the post on the hall table.", "console_table", "dining_table"),
    ("The remote is on the glass-topped low table.", "coffee_table", "dining_table"),
    ("Her alarm clock is on the bedside table.", "nightstand", "dining_table"),
    # an adjective says what it is like, not what sort it is
    ("Leave the glass on the small table by the bed.", "drinking_glass", "dining_table"),
    ("The little table next to the sofa has a lamp on it.", "sofa", "dining_table"),
    # a value of the kinds' attributes (a material) is no sort either
    ("Your phone is on the metal table.", "cell_phone", "dining_table"),
])
def test_a_modifier_that_names_no_sort_is_no_general_table(text: str, kind: str, not_kind: str) -> None:
    kinds = _kinds(text)
    assert kind in kinds
    assert not_kind not in kinds


# -- the words elsewhere that hint a short name's kind: the modifiers it dropped, never a time, a
# part said of another thing or another name's head (`_Reader.dropped_modifiers`) --


@pytest.mark.parametrize(("text", "not_kind"), [
    # a diary: "night" is the time, no night table
    ("We got back late last night. The keys are on the table.", "nightstand"),
    # a cleaning rota: "the end of the day" is no end table
    ("At the end of the day, clear the table.", "side_table"),
    # a note: "cabinet" names the cabinet, no bedside cabinet
    ("The mugs are in the cabinet and the jug is on the table.", "nightstand"),
    # an instruction: "the top of the fridge" is a part, and "stand" a verb, no night stand
    ("Stand the jug on the table, then wipe the top of the fridge.", "nightstand"),
])
def test_a_time_a_part_or_another_head_is_no_hint(text: str, not_kind: str) -> None:
    assert not_kind not in _kinds(text)


@pytest.mark.parametrize(("text", "kind"), [
    # the dropped modifier said elsewhere still tells the kind
    ("Her bedside lamp is off. The glass on the table is empty.", "nightstand"),
    ("The pantry has two shelves; the tins go on the top shelf.", "pantry_shelf"),
])
def test_a_dropped_modifier_said_elsewhere_still_hints(text: str, kind: str) -> None:
    assert kind in _kinds(text)


# -- "<vessel> of <contents>" is the catalog's "<contents> <vessel>" (`_Reader.vessel_of`) --


@pytest.mark.parametrize(("text", "kind"), [
    # a gym's lost-property list
    ("Item 4: a bottle of water, blue lid, found in the changing room.", "water_bottle"),
    # a dinner-party host's note
    ("A bottle of red wine is breathing on the sideboard - leave it be.", "wine_bottle"),
    ("The bottle of vermouth goes back in the drinks cabinet.", "wine_bottle"),
    # a nurse's handover
    ("Pt's bottle of pills is on the bedside table.", "medicine_bottle"),
    # a child's tidy-up chart
    ("the box of tissues goes on the shelf", "tissue_box"),
    ("Put the box of toys under the bed.", "toy_box"),
])
def test_a_vessel_of_its_contents_is_the_contents_vessel(text: str, kind: str) -> None:
    kinds = _kinds(text)
    assert kind in kinds
    assert "bottle" not in kinds  # one object, not a bottle beside it


@pytest.mark.parametrize(("text", "kinds"), [
    # contents whose kind is named for no such vessel: a vessel and its contents, as before
    ("A box of books is waiting in the hall.", {"cardboard_box", "book"}),
    ("The bottle of dish soap is by the sink.", {"bottle", "dish_soap"}),
    # "of" after a vessel is not always its contents: a part of it
    ("The lid of the bottle is on the floor.", {"bottle"}),
])
def test_other_vessels_of_things_stay_as_they_were(text: str, kinds: set[str]) -> None:
    assert kinds <= set(_kinds(text))
