"""Objects of the fourteenth session's second round (issue 47): the naming structures the unbound
roles of dev 23 and dev 24 show, composed across several registers, kinds and rooms before any rule
and read through the offline model's `name_objects` answer. Every sentence is written for these
tests; none is copied from a task."""

from __future__ import annotations

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.analysis import analyse
from logicenveval.offline.naming import name_objects
from logicenveval.offline.placement import described_placements


def _kinds(text: str, rooms: tuple[str, ...] = ()) -> list[str]:
    return [o["category"] for o in name_objects(text, load_catalog(), rooms=rooms)]


# -- a head several kinds share, placed on the floor by its own phrase, is the kind the catalog
# stands on the floor: a bowl on the floor is a pet's bowl, a lamp on the floor a floor lamp
# (`_Reader.floor_stood`) --

#: (rooms, sentence, the kind the head names): a neighbour's note, a text message, a listing, an
#: inventory, a child's dictated message
FLOOR_KIND: tuple[tuple[tuple[str, ...], str, str], ...] = (
    (("kitchen",), "Pepper's bowl, on the floor by the back door, needs a rinse.", "pet_bowl"),
    (("kitchen", "hallway"), "the water bowl on the floor by the radiator is empty again lol", "pet_bowl"),
    (("living_room",), "Item: one bowl on the floor beside the hearth (the cat's).", "pet_bowl"),
    (("kitchen",), "Mr Whiskers has a bowl which sits on the floor next to the fridge.", "pet_bowl"),
    (("living_room",), "The lamp on the floor behind the sofa is on, switch it off.", "floor_lamp"),
    (("bedroom",), "Inventory: a lamp, which stands on the floor in the corner.", "floor_lamp"),
)

#: near misses: a place on a surface, or the floor said of another thing or as where it fell
FLOOR_KIND_NEAR: tuple[tuple[tuple[str, ...], str, str], ...] = (
    (("kitchen",), "The fruit bowl on the counter needs filling.", "bowl"),
    (("kitchen",), "Put the bowl on the table and mop the floor.", "bowl"),
    (("kitchen",), "Wash the bowl; the dog's lead is on the floor.", "bowl"),
    (("living_room",), "The lamp on the side table is on, switch it off.", "table_lamp"),
)


@pytest.mark.parametrize(("rooms", "text", "kind"), FLOOR_KIND + FLOOR_KIND_NEAR)
def test_a_head_placed_on_the_floor_is_the_floor_kind(rooms: tuple[str, ...], text: str, kind: str) -> None:
    assert kind in _kinds(text, rooms)


# -- a place stated with a corrective tail (", not on the desk") after a pronoun subject: the tail
# denies another place, not the statement (`placement._corrective_not`) --

#: (sentence, the placement): a correction column, a text message, a handover note, a landlord's
#: reply
CORRECTED: tuple[tuple[str, str], ...] = (
    ("Correction: the item is a cup, and it was left on top of the filing cabinet, not on the desk.",
     "on(cup, filing_cabinet)"),
    ("its a cup not a mug, and it's on the filing cabinet, not the desk!!", "on(cup, filing_cabinet)"),
    ("Handover: Mrs Patel's cup is blue; it was left in the filing cabinet, not on the desk.",
     "inside(cup, filing_cabinet)"),
    ("As to the cup you asked about, it is on the desk, not in the filing cabinet.", "on(cup, desk)"),
)

#: near misses: the negated place comes first, or the tail negates the verb
CORRECTED_NEAR: tuple[str, ...] = (
    "The cup, it was left, not on the filing cabinet, but somewhere upstairs.",
    "It is a cup, and it was not left on the filing cabinet, not on the desk either.",
    "It is a cup, and it may be on the filing cabinet, not on the desk.",
)

_STUDY_ROLES = {"cup": {"category": "cup"}, "filing_cabinet": {"category": "filing_cabinet"},
                "desk": {"category": "desk"}}


def _placed(text: str) -> list[str]:
    brief = {"id": "t", "description": text, "rooms": ["study"], "roles": _STUDY_ROLES}
    return described_placements(brief, load_catalog())


@pytest.mark.parametrize(("text", "fact"), CORRECTED)
def test_a_corrective_tail_leaves_the_place_stated(text: str, fact: str) -> None:
    assert fact in _placed(text)


@pytest.mark.parametrize("text", CORRECTED_NEAR)
def test_a_negated_or_hedged_place_is_not_read(text: str) -> None:
    assert "on(cup, filing_cabinet)" not in _placed(text)


# -- one list item's "or anywhere else" speaks of its own thing, not of another item's home: the
# home another item states ("the bottle lives on the bench") stays settled, no question of where it
# is (`analysis._elsewhere_cued`) --

#: a bulleted jobs note, a starred chore chart, a paragraphed house-sitter's email: the
#: cue in the first block, a home and an instruction to put the thing back in the second
HOME_AFTER_CUE: tuple[str, ...] = (
    "Jobs:\n- Hat. If the hat is on the floor, hang it on the coat hook. On the hook or anywhere else, "
    "leave it.\n- Bottle. The water bottle lives on the bench. If it's empty, fill it at the sink and "
    "stand it back on the bench.",
    "CHORE CHART\n* If the hat is on the floor, hang it on the coat hook; if it's somewhere else, leave it.\n"
    "* The water bottle lives on the bench. If it's empty, fill it at the sink and put it back on the bench.",
    "Hi! If the hat is on the floor, hang it on the coat hook; elsewhere, don't worry.\n\n"
    "The water bottle lives on the bench. When it's empty, fill it at the sink and put it back on the bench.",
)

#: near misses: the cue in the bottle's own block, or in a text of one block after the bottle's
#: home, still asks where it is (since the thirty-first session a cue looks back: in a text of one
#: block, "...; anywhere else, leave it. The water bottle lives on the bench." leaves the home
#: settled, tests/test_offline_cue_looks_back_thirtyfirst.py)
HOME_AFTER_CUE_NEAR: tuple[str, ...] = (
    "Jobs:\n- Hat. If the hat is on the floor, hang it on the coat hook.\n- Bottle. The water bottle "
    "lives on the bench. If it's on the bench and empty, fill it at the sink and stand it back on the "
    "bench; if it's anywhere else, leave it.",
    "The water bottle lives on the bench. If the hat is on the floor, hang it on the coat hook; anywhere "
    "else, leave it. If it's on the bench and empty, fill it at the sink and stand it back on the bench.",
)

_HUT_ROLES = {"hat": {"category": "hat"}, "coat_hook": {"category": "coat_hook"},
              "water_bottle": {"category": "water_bottle"}, "bench": {"category": "bench"},
              "sink": {"category": "sink"}}


def _bottle_asked(text: str) -> bool:
    brief = {"id": "t", "description": text, "rooms": ["hut"], "roles": _HUT_ROLES}
    return any(f.kind == "location" and f.subject == "water_bottle" for f in analyse(brief, load_catalog()).factors)


@pytest.mark.parametrize("text", HOME_AFTER_CUE)
def test_another_items_cue_leaves_a_home_settled(text: str) -> None:
    assert not _bottle_asked(text)


@pytest.mark.parametrize("text", HOME_AFTER_CUE_NEAR)
def test_a_cue_of_the_things_own_block_still_asks(text: str) -> None:
    assert _bottle_asked(text)


# -- a verbless statement whose subject carries a possessor or a noun modifier its name does not
# cover ("Biscuit's water bowl, on the floor by the door") still places it (`placement._premodifiers`) --

#: (sentence, roles, the placement): a listing's item, an inventory line, a sitter's note, a memo
LOOSE_SUBJECT: tuple[tuple[str, dict[str, str], str], ...] = (
    ("Item 2 - Rex's water bowl, on the floor by the back door. Fill it if it's empty.",
     {"pet_bowl": "pet_bowl"}, "on(pet_bowl, floor)"),
    ("Inventory: the guest towel, in the laundry basket. Nothing else to note.",
     {"towel": "towel", "laundry_basket": "laundry_basket"}, "inside(towel, laundry_basket)"),
    ("Dad's work laptop, on the desk. Leave it there.", {"laptop": "laptop", "desk": "desk"}, "on(laptop, desk)"),
    ("The staff kettle, on the counter by the sink. Switch it off at night.",
     {"kettle": "kettle", "counter": "kitchen_counter"}, "on(kettle, counter)"),
)

#: near misses: a verb opens the clause, or a hedge does
LOOSE_SUBJECT_NEAR: tuple[tuple[str, dict[str, str], str], ...] = (
    ("Fill Rex's bowl, on the floor by the back door.", {"pet_bowl": "pet_bowl"}, "on(pet_bowl, floor)"),
    ("Maybe Rex's water bowl, on the floor by the door.", {"pet_bowl": "pet_bowl"}, "on(pet_bowl, floor)"),
    ("Put the staff kettle, on the counter.", {"kettle": "kettle", "counter": "kitchen_counter"},
     "on(kettle, counter)"),
)


def _placed_roles(text: str, roles: dict[str, str]) -> list[str]:
    brief = {"id": "t", "description": text, "rooms": ["kitchen"],
             "roles": {r: {"category": c} for r, c in roles.items()}}
    return described_placements(brief, load_catalog())


@pytest.mark.parametrize(("text", "roles", "fact"), LOOSE_SUBJECT)
def test_a_verbless_subject_with_loose_modifiers_is_placed(text: str, roles: dict[str, str], fact: str) -> None:
    assert fact in _placed_roles(text, roles)


@pytest.mark.parametrize(("text", "roles", "fact"), LOOSE_SUBJECT_NEAR)
def test_a_verb_or_hedge_before_the_subject_places_nothing(text: str, roles: dict[str, str], fact: str) -> None:
    assert fact not in _placed_roles(text, roles)
