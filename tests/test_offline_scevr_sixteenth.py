"""Invalid environments, sixteenth session (docs/reader.md, "Existence and places asked of no
doubted thing (sixteenth session)"): a thing whose being there, or whose place, nothing doubts
gets no existence or location factor, so no path leaves out a role the scene needs or moves a
thing off its stated place; and a thing of the floor ruled off it goes on a free surface, so the
layout stays possible. Each structure is written as composed sentences in several registers,
kinds and rooms, with near misses that must still be read as before; every sentence is written
for the test, none copied from a development set."""

from __future__ import annotations

import pytest
from reading import CATALOG, factors

from logicenveval.offline.realise import task_objects

# -- a holder identified by its room ("the lamp on the nightstand in the bedroom may be on") -----
#
# "in the ROOM" after the holder of a thing's place says which holder is meant; in a task of one
# room it is no doubt about the holder. The doubt or the condition of the clause is about the
# thing on or in the holder (its state, its place), so the holder gets no existence factor.

#: (text, rooms, the holder that must get no existence factor, a factor that must still be asked)
HOLDER_BY_ROOM: list[tuple[str, tuple[str, ...], str, str]] = [
    # a parent's note, a doubt with "may"
    ("The lamp on the nightstand in the bedroom may be on. If it is, switch it off.", ("bedroom",),
     "nightstand_present", "table_lamp_toggled_on"),
    # an office notice, a habit read as a doubt
    ("The desktop computer on the desk in the study is left running more often than not. If it is on, "
     "shut it down.", ("study",), "desk_present", "desktop_computer_toggled_on"),
    # a chatty text, "might still"
    ("the kettle on the counter in the kitchen might still be on, can u check and switch it off",
     ("kitchen",), "kitchen_counter_present", "kettle_toggled_on"),
    # a formal checklist, a condition of its own
    ("Should the television on the stand in the living room be on, it is to be switched off.",
     ("living_room",), "tv_stand_present", "television_toggled_on"),
]


@pytest.mark.parametrize(("text", "rooms", "holder", "asked"), HOLDER_BY_ROOM)
def test_a_holder_named_with_its_room_is_not_doubted(text: str, rooms: tuple[str, ...], holder: str,
                                                     asked: str) -> None:
    found = factors(text, rooms)
    assert holder not in found
    assert asked in found


#: near misses: a thing itself said to be in the task's one room, under a doubt, is asked whether
#: it is there at all (as before), and a holder doubted in its own right keeps its factor
THING_IN_ROOM: list[tuple[str, tuple[str, ...], str]] = [
    ("I may have left my watch in the bedroom. If it is there, put it on the nightstand.", ("bedroom",),
     "watch_present"),
    ("The laptop might be in the study; if so, plug it in.", ("study",), "laptop_present"),
]


@pytest.mark.parametrize(("text", "rooms", "asked"), THING_IN_ROOM)
def test_a_thing_in_the_one_room_is_still_asked_whether_it_is_there(text: str, rooms: tuple[str, ...],
                                                                    asked: str) -> None:
    assert asked in factors(text, rooms)


# -- a thing had somewhere ("maybe I have it in my bag") -----------------------------------------
#
# "have" before a definite pronoun and a place ("I have it in my bag", "we might have them in
# the drawer") says where the thing the sentence doubts may be, the alternative to its other
# place: not whether it (or, read as the nearest thing, its other holder) is there at all. Said
# with no place ("if we still have it"), or of an indefinite thing ("if we still have a spare"),
# "have" still asks whether there is one.

#: (text, rooms, existence factors that must not be asked, the factor that must be)
HAD_SOMEWHERE: list[tuple[str, tuple[str, ...], set[str], str]] = [
    # a flatmate's note
    ("My wallet maybe is on the sofa, I think I have it in my bag.", ("living_room",),
     {"sofa_present", "wallet_present", "handbag_present"}, "wallet_location"),
    # a chat message, a plural pronoun
    ("The keys could be on the desk - or maybe I have them in the drawer.", ("office",),
     {"desk_present", "keys_present", "drawer_present"}, "keys_location"),
    # a voice note, another holder and kind
    ("The remote might be on the sofa, or maybe I have it in the basket.", ("living_room",),
     {"sofa_present", "remote_control_present", "basket_present"}, "remote_control_location"),
    # a formal register, "on" as the other place
    ("The charger is possibly on the nightstand; it is also possible that we have it on the desk.",
     ("bedroom",), {"nightstand_present", "phone_charger_present", "desk_present"}, "phone_charger_location"),
]


@pytest.mark.parametrize(("text", "rooms", "absent", "asked"), HAD_SOMEWHERE)
def test_a_thing_had_somewhere_is_no_doubt_of_being_there(text: str, rooms: tuple[str, ...],
                                                          absent: set[str], asked: str) -> None:
    found = factors(text, rooms)
    assert not absent & set(found)
    assert asked in found


#: near misses: "have" with no place, or of an indefinite thing, still asks whether there is one
HAD_AT_ALL: list[tuple[str, tuple[str, ...], str]] = [
    ("If we still have a spare bulb, put it in the lamp.", ("living_room",), "spare_bulb_present"),
    ("The lamp is on the desk. If we still have it, switch it on.", ("office",), "desk_lamp_present"),
    ("do we even have a mop?? if we do, mop the floor", ("kitchen",), "mop_present"),
]


@pytest.mark.parametrize(("text", "rooms", "asked"), HAD_AT_ALL)
def test_a_thing_had_at_all_is_still_asked(text: str, rooms: tuple[str, ...], asked: str) -> None:
    assert asked in factors(text, rooms)


# -- a permission's "may" ("Guests may use the kettle in the kitchenette") ------------------------
#
# A rule or a notice that lets people do something ("Guests may use ...", "A member may open ...")
# grants; it doubts nothing of the scene, so the thing it names gets no existence factor from a
# doubt (in a task of one room, "in the ROOM" under a doubt would ask whether it is there at
# all). After a thing, or before a perfect, a "be" or a verb of finding, "may" still doubts.

#: (text, rooms, the factor that must not be asked, a factor that must still be)
PERMITTED: list[tuple[str, tuple[str, ...], str, str]] = [
    # a holiday let's notice
    ("Guests may use the kettle in the kitchenette. If the kettle is still on at night, switch it off.",
     ("kitchenette",), "kettle_present", "kettle_toggled_on"),
    # club rules, a thing put on a holder
    ("Members may hang a wet coat on the rack in the cloakroom. If the heater is on, switch it off.",
     ("cloakroom",), "coat_rack_present", "radiator_toggled_on"),
    # an office policy
    ("Staff may leave the laptop in the office overnight. If the laptop is on, shut it down.", ("office",),
     "laptop_present", "laptop_toggled_on"),
    # a school's rules, a negated permission
    ("Pupils may not take the laptop in the classroom home. If the desk lamp is on, switch it off.",
     ("classroom",), "laptop_present", "desk_lamp_toggled_on"),
]


@pytest.mark.parametrize(("text", "rooms", "absent", "asked"), PERMITTED)
def test_a_permission_doubts_nothing(text: str, rooms: tuple[str, ...], absent: str, asked: str) -> None:
    found = factors(text, rooms)
    assert absent not in found
    assert asked in found


#: near misses: a thing's "may", a person's "may have", "may find" still doubt
STILL_DOUBTED: list[tuple[str, tuple[str, ...], str]] = [
    ("The laptop may be in the office. If so, shut it down.", ("office",), "laptop_present"),
    ("Visitors may have left the laptop in the office. If so, shut it down.", ("office",), "laptop_present"),
    ("You may find the laptop in the office. If so, shut it down.", ("office",), "laptop_present"),
    ("the kettle may still be on - switch it off if so", ("kitchen",), "kettle_toggled_on"),
]


@pytest.mark.parametrize(("text", "rooms", "asked"), STILL_DOUBTED)
def test_a_doubt_after_may_is_still_asked(text: str, rooms: tuple[str, ...], asked: str) -> None:
    assert asked in factors(text, rooms)


# -- a thing of the floor ruled off it goes on a free surface ("the mug lives on the bedside table")
#
# A thing the catalog keeps on the floor (scrubs, a shoe, a toy) that a path rules off the floor
# ("not on(scrubs, floor)") goes on a surface of its room nothing else rests on yet; where every
# surface already holds something (the mug the text puts on the bedside table), on a side table
# added for it: a small holder seldom takes two things, and the layout then fails. A thing that
# belongs on surfaces (a book) still goes on the room's surface, taken or not.

#: (text, rooms, roles, facts, the role ruled off the floor, the holder it must not be put on)
FREE_SURFACE: list[tuple[str, list[str], dict[str, str], list[str], str, str]] = [
    # a doctor's handover: a mug on the bedside table, scrubs off the floor, a hamper
    ("The mug lives on the bedside table. Scrubs on the floor go into the hamper.", ["on_call_room"],
     {"mug": "mug", "bedside_table": "nightstand", "scrubs": "dirty_clothes", "hamper": "hamper"},
     ["not on(scrubs, floor)"], "scrubs", "on:bedside_table"),
    # a hallway note: keys on the bench, a shoe off the floor
    ("The keys are always on the bench. If the shoe is on the floor, put it on the rack.", ["hallway"],
     {"keys": "keys", "bench": "bench", "shoe": "shoe"}, ["not on(shoe, floor)"], "shoe", "on:bench"),
    # a nursery chat: a lamp on the desk, a toy off the floor, a free shelf unit
    ("lamp's on the desk. toy on the floor? pick it up x", ["kids_room"],
     {"lamp": "desk_lamp", "desk": "desk", "toy": "toy", "table": "side_table"},
     ["not on(toy, floor)"], "toy", "on:desk"),
]


def _placements(text: str, rooms: list[str], roles: dict[str, str], facts: list[str]) -> dict[str, str]:
    brief = {"id": "t", "description": text, "rooms": rooms,
             "roles": {name: {"category": cat} for name, cat in roles.items()}}
    return {o["id"]: o["placement"] for o in task_objects(brief, facts, CATALOG)}


@pytest.mark.parametrize(("text", "rooms", "roles", "facts", "role", "taken"), FREE_SURFACE)
def test_a_floor_thing_off_the_floor_goes_on_a_free_surface(text: str, rooms: list[str], roles: dict[str, str],
                                                            facts: list[str], role: str, taken: str) -> None:
    placement = _placements(text, rooms, roles, facts)[role]
    assert placement not in (taken, "floor") and placement.startswith("on:")


def test_a_surface_thing_still_goes_on_the_taken_surface() -> None:
    placed = _placements("The lamp is on the nightstand. Pick the book up off the floor.", ["bedroom"],
                         {"lamp": "table_lamp", "nightstand": "nightstand", "book": "book"},
                         ["not on(book, floor)"])
    assert placed["book"] == "on:nightstand"


# -- a place that names the thing in a doubt about its state ("the lamp on the nightstand may be on")
#
# A place said in the subject's phrase, before the predicate ("the lamp on the nightstand", "the
# desktop computer on the desk"), says which thing is meant; when the doubt's predicate is the
# thing's state ("may be on", "is left running more often than not"), the place is not doubted:
# no location factor (whose "elsewhere" path would move the thing off a place the text states).
# A place in the predicate ("the towel might be on the floor and wet") is still doubted.

#: (text, rooms, the location factor that must not be asked, the state factor that must be)
NAMED_BY_PLACE: list[tuple[str, tuple[str, ...], str, str]] = [
    ("The lamp on the nightstand may be on. If it is, switch it off.", ("bedroom",),
     "table_lamp_on_nightstand", "table_lamp_toggled_on"),
    # a bank statement's note: a habit read as a doubt
    ("The desktop computer on the desk is left running more often than not. If it is still on, shut it "
     "down.", ("study",), "desktop_computer_on_desk", "desktop_computer_toggled_on"),
    # a chat message
    ("the kettle on the counter might still be on lol", ("kitchen",), "kettle_on_kitchen_counter",
     "kettle_toggled_on"),
    # a fronted adverb, a room as the place, two rooms
    ("Possibly the heater in the hallway is still on.", ("hallway", "bedroom"), "radiator_in_room_hallway",
     "radiator_toggled_on"),
]


@pytest.mark.parametrize(("text", "rooms", "place", "state"), NAMED_BY_PLACE)
def test_a_place_that_names_the_thing_is_not_doubted(text: str, rooms: tuple[str, ...], place: str,
                                                     state: str) -> None:
    found = factors(text, rooms)
    assert place not in found
    assert state in found


#: near misses: a place in the doubt's predicate is still asked, with the state or alone
PLACE_DOUBTED: list[tuple[str, tuple[str, ...], str]] = [
    ("The towel might be on the floor and wet.", ("bathroom",), "towel_on_floor"),
    ("I think the towel is on the floor, probably wet.", ("bathroom",), "towel_on_floor"),
    ("The mug may be on the desk, and it may be dirty.", ("office",), "mug_on_desk"),
    ("The book may be on the floor. If so, shelve it.", ("study",), "book_on_floor"),
]


@pytest.mark.parametrize(("text", "rooms", "place"), PLACE_DOUBTED)
def test_a_place_in_the_predicate_is_still_doubted(text: str, rooms: tuple[str, ...], place: str) -> None:
    assert place in factors(text, rooms)


@pytest.mark.parametrize(("text", "names_by_place"), [
    # a doubt of the place itself, no predicate before which a subject phrase could name the thing
    ("Maybe I forgot my torch on the bench", False),
    ("Possibly left the radio in the shed", False),
    # the place in the subject's phrase, before the predicate: it names which thing is meant
    ("The torch on the bench may be on", True),
    ("The radio in the shed is often left playing", True),
])
def test_a_place_names_the_thing_only_before_a_predicate(text: str, names_by_place: bool) -> None:
    """`analysis._identifying_place`: a place names the thing only when it stands in the subject's
    phrase, before a predicate opener ("is", "may", ...). A clause with no such opener ("Maybe I
    forgot my torch on the bench") doubts the place itself, even when a state of the thing was
    also read in it (a development text's untranslated holder name made "on" read as switched on,
    and the place stopped being asked: the coordinator's narrowing at the merge)."""
    from logicenveval.offline.analysis import Clause, Fact, _identifying_place
    thing, holder = ("flashlight", "bench") if "torch" in text else ("radio", "shed")
    place = Fact(thing, f"on({thing}, {holder})", "location", holder)
    state = Fact(thing, f"state({thing}, toggled_on)", "state", "toggled_on")
    clause = Clause(text, 0, None, "uncertain", (place, state), (thing,))
    assert _identifying_place(place, clause) is names_by_place
