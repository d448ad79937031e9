"""Naming rules of the seventeenth session (issue 47): a bracket naming a thing again by a compound
written as one word, a thing one picks up before a head noun of one kind. Every sentence here was
written for this file (none copied from a task); docs/reader.md, "Naming: closed compounds in a
bracket and a modifier one picks up (seventeenth session)"."""

from __future__ import annotations

from pathlib import Path

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.naming import name_objects

CATALOG = load_catalog()
FORMS = Path(__file__).parent / "data" / "naming_forms" / "forms_seventeenth.tsv"
#: sentences of `FORMS` naming their row's kind and not the kind the row says they must not name:
#: 1 of 15 before the session's rules, 15 after
READ_AT_LEAST = 15


def _kinds(text: str) -> set[str]:
    return {o["category"] for o in name_objects(text, CATALOG)}


def _forms_read(path: Path) -> int:
    """Rows (kind, the kind it must not name, form, sentence) whose sentence names the kind and
    not the other."""
    count = 0
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            kind, wrong, _, sentence = line.split("\t")
            got = _kinds(sentence)
            count += kind in got and wrong not in got
    return count


def test_seventeenth_session_forms_do_not_fall() -> None:
    assert _forms_read(FORMS) >= READ_AT_LEAST


# -- a bracket right after a thing's only reading, naming it again by a compound written as one
# word that ends in the word it was called by ("the field book (yellow notebook)"): one thing, of
# the bracket's kind (`naming._Reader.glossed`) --

@pytest.mark.parametrize(("text", "kind", "not_kind"), [
    # a site diary
    ("Day 3: the level book (green notebook) got soaked, dry it on the heater.", "notebook", "book"),
    # a teenager's message
    ("ur book (the notebook lol) is under my bed", "notebook", "book"),
    # a care home's notice
    ("Please return the reading chair (armchair) to the lounge after use.", "armchair", "chair"),
    # a camp's kitchen rota
    ("Rinse the large pan (saucepan) before you hang it up.", "pot", "pan"),
    # a cleaner's note
    ("The little pan (the dustpan) is behind the bin.", "dustpan", "pan"),
])
def test_a_bracketed_closed_compound_names_the_thing_again(text: str, kind: str, not_kind: str) -> None:
    kinds = _kinds(text)
    assert kind in kinds
    assert not_kind not in kinds


@pytest.mark.parametrize(("text", "kinds"), [
    # the bracket is a clause of its own about another thing
    ("The chair is wet (the armchair is dry).", {"chair", "armchair"}),
    ("The pan is dirty (the saucepan was washed up).", {"pan", "pot"}),
    # the bracket adds a second thing
    ("Put the book (and the notebook) on the desk.", {"book", "notebook"}),
    # no bracket: two things
    ("The chair and the armchair are both wet.", {"chair", "armchair"}),
])
def test_a_bracket_that_names_another_thing_keeps_both(text: str, kinds: set[str]) -> None:
    assert kinds <= _kinds(text)


# -- a thing one picks up, by its own name, before a head noun that names one kind says what the
# head is for ("the dish cloth" is a cloth for dishes, no plate: `naming._Reader.modifies_next`) --

@pytest.mark.parametrize(("text", "kind", "not_kind"), [
    # a shared kitchen's sign
    ("Whoever used the dish cloth last: it stinks, wash it.", "cloth", "plate"),
    # a café's closing list
    ("Polish the rims with the cup cloth and hang it to dry.", "cloth", "cup"),
    # a parent's text
    ("the pan cloth is in the bucket, dont use it on the table", "cloth", "pan"),
    # a museum volunteer's handbook
    ("Only the book cloth may touch the bindings.", "cloth", "book"),
])
def test_a_picked_up_modifier_before_a_one_kind_head_names_no_thing(text: str, kind: str, not_kind: str) -> None:
    kinds = _kinds(text)
    assert kind in kinds
    assert not_kind not in kinds


@pytest.mark.parametrize(("text", "kinds"), [
    # a vessel's contents are there
    ("The detergent bottle is empty, get another.", {"laundry_detergent"}),
    # a piece of furniture before its part is the furniture
    ("The socks go in the nightstand drawer.", {"nightstand"}),
    # a compound the catalog names
    ("Leave the phone charger in the drawer.", {"phone_charger"}),
    # two things with a comma or "and"
    ("Wash the plate, the cloth and the cup.", {"plate", "cloth", "cup"}),
    ("Put the book and the cloth on the shelf.", {"book", "cloth"}),
])
def test_a_modifier_that_is_a_thing_or_a_list_stays_named(text: str, kinds: set[str]) -> None:
    assert kinds <= _kinds(text)


# -- a piece of furniture's part, once named as its own ("goes into the nightstand drawer"), said
# again further on by "the drawer", or by "a drawer" opening a clause of sound or sight ("A DRAWER
# SLIDES SHUT"), is that part: no drawer of its own (`naming._Reader.part_said_again`) --

@pytest.mark.parametrize(("text", "holder"), [
    # a radio play's sound effects
    ("ANNA: The socks go in the nightstand drawer.\nSFX: RAIN. FOOTSTEPS.\nANNA: Is that the kettle?\n"
     "SFX: A DRAWER SLIDES SHUT.", "nightstand"),
    # a caretaker's log
    ("Spare fuses live in the dresser drawers. Tea break at eleven. Boiler checked. Later a drawer bangs; "
     "is it open?", "dresser"),
    # an office memo
    ("Signed forms go in the filing cabinet drawer. The printer is fixed. Lunch is at one. Please check "
     "the drawer is shut before you leave.", "filing_cabinet"),
])
def test_a_part_said_again_is_the_named_furnitures(text: str, holder: str) -> None:
    kinds = _kinds(text)
    assert holder in kinds
    assert "drawer" not in kinds


@pytest.mark.parametrize("text", [
    # "a drawer" as a goal or after "there is": another drawer
    "The socks go into the nightstand drawer. The phone rings. Put the pens in a drawer.",
    "Spare fuses live in the dresser drawers. The phone rings. There is a drawer under the stairs.",
    # "a drawer" a place follows
    "The socks go into the nightstand drawer. The phone rings. A drawer in the hall is open.",
    # no furniture was named with the part
    "The phone rings. The kettle boils. The drawer is open.",
])
def test_another_drawer_stays_a_drawer(text: str) -> None:
    assert "drawer" in _kinds(text)


# -- a spare named right before such a bracket is a thing of the bracket's kind ("the spare sketch
# book (the blue notebook)": `naming._Reader.glossed_spare`) --

@pytest.mark.parametrize(("text", "kind", "not_kind"), [
    # a field team's kit list
    ("Take the spare level book (green notebook) in case it rains.", "notebook", "book"),
    # a scout leader's text
    ("the spare pan (saucepan) is in the van, grab it if the big one is dirty", "pot", "pan"),
])
def test_a_spare_renamed_in_a_bracket_is_of_the_brackets_kind(text: str, kind: str, not_kind: str) -> None:
    kinds = _kinds(text)
    assert kind in kinds
    assert not_kind not in kinds


def test_a_spare_beside_the_thing_in_use_keeps_both() -> None:
    # the thing in use is named apart from the spare: it stays
    kinds = _kinds("The book is on the desk. Take the spare book (the notebook) as well.")
    assert {"book", "notebook"} <= kinds
