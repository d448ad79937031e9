"""A definite thing named by its place, then asked of a state through a perfect or a verb of
becoming ("if the bath towel on the heated rail has been used", "should the mug on the desk have
got dirty", "when the cloth in the bucket goes dry"), from the twenty-eighth session (dev 45's
coach-tour departure letter): the place names which thing is meant and is taken for granted, as
it is after "is" ("if the mug on the desk is dirty"); the condition asks the state only
(`placement._described_subject`, `placement.BECOMING`). Rows written here in other registers
before the rule and measured then: 0 of 6; after: 5 of 6 (one xfail: a conditional "where"). Near misses: a place in the predicate
("has been left on the rail"), an indefinite thing ("a towel on the rail that has been used") and
a question of the place itself are still asked."""

from __future__ import annotations

import pytest
from reading import asks, factors, placed

#: (text, rooms, the place taken for granted, the state asked)
TAKEN = [
    ("Towels. If the bath towel on the towel rail has been used, it goes in the bath.", ("guest_room",),
     "on(towel, towel_rack)", "state(towel, dirty)"),
    ("Should the mug on the desk have got dirty, give it a wash at the sink.", ("study", "kitchen"),
     "on(mug, desk)", "state(mug, dirty)"),
    ("when the cloth in the bucket goes dry - wet it again at the tap", ("scullery",),
     "inside(cloth, bucket)", "state(cloth, wet)"),
    pytest.param("Where the towel on the drying rack has become soiled, it is to be placed in the laundry basket.",
                 ("utility_room",), "on(towel, drying_rack)", "state(towel, dirty)",
                 marks=pytest.mark.xfail(reason="a conditional \"where\" asks the place it names, after \"is\" too",
                                         strict=True)),
    ("if the shirt in the basket has got wet again hang it on the drying rack pls", ("box_room",),
     "inside(shirt, basket)", "state(shirt, wet)"),
    ("In case the plate on the counter has been used: dishwasher.", ("galley",),
     "on(plate, kitchen_counter)", "state(plate, dirty)"),
]
#: near misses: (text, rooms, the place still asked)
ASKED = [
    ("If the towel has been left on the towel rail, fold it.", ("guest_room",), "on(towel, towel_rack)"),
    ("If there is a mug on the desk that has been used, wash it.", ("study",), "on(mug, desk)"),
    ("Has the mug been put on the desk? If not, put it there.", ("study",), "on(mug, desk)"),
]


@pytest.mark.parametrize(("text", "rooms", "place", "state"), TAKEN)
def test_the_place_naming_a_thing_is_taken_for_granted(text: str, rooms: tuple[str, ...], place: str,
                                                        state: str) -> None:
    assert place in placed(text, rooms), factors(text, rooms)
    assert not asks(text, rooms, place), factors(text, rooms)
    assert asks(text, rooms, state), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "place"), ASKED)
def test_a_place_in_the_predicate_or_of_an_indefinite_thing_is_asked(text: str, rooms: tuple[str, ...],
                                                                      place: str) -> None:
    assert asks(text, rooms, place), factors(text, rooms)


#: a state a thing comes to be in, after a verb of becoming (`analysis._Reader._state` with
#: `placement.BECOMING`): (text, rooms, the state asked). Written before the rule and measured
#: then: 0 of 6; after: 5 of 6 (one xfail: "turn" as an instruction verb). A water bowl with no pet
#: named is a bowl (the catalog's pet bowl is a "dog bowl", "cat bowl"): the row first said a pet
#: bowl, corrected after the first run (as the shirt's "basket" above, first a laundry basket).
BECOMES = [
    ("If the cloth gets wet, hang it on the drying rack.", ("scullery",), "state(cloth, wet)"),
    ("In the event that the bucket becomes empty, it is to be refilled at the sink.", ("yard_store",),
     "state(bucket, filled)"),
    ("when ur towel gets soaked chuck it in the laundry basket", ("box_room",), "state(towel, wet)"),
    ("Once the water bowl goes empty, fill it up at the tap.", ("boot_room",), "state(bowl, filled)"),
    ("Bin. If it gets full, take the bag out to the wheelie bin.", ("back_kitchen",), "state(trash_can, filled)"),
    pytest.param("Should the mug turn dirty over the day, wash it at the sink.", ("office",), "state(mug, dirty)",
                 marks=pytest.mark.xfail(reason="a bare \"turn\" after an inverted subject reads as an instruction",
                                         strict=True)),
]
#: near misses: a verb of motion before a place is a goal, no state ("the towel goes in the
#: basket"); a thing going off sounds, it is not switched off (below)
MOVES = [
    ("The towel goes in the laundry basket if it is dirty.", ("box_room",), "state(towel, dirty)",
     "inside(towel, laundry_basket)"),
]


@pytest.mark.parametrize(("text", "rooms", "state"), BECOMES)
def test_a_state_after_a_verb_of_becoming_is_asked(text: str, rooms: tuple[str, ...], state: str) -> None:
    assert asks(text, rooms, state), factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "state", "goal"), MOVES)
def test_a_verb_of_motion_before_a_place_is_a_goal(text: str, rooms: tuple[str, ...], state: str,
                                                    goal: str) -> None:
    assert asks(text, rooms, state), factors(text, rooms)
    assert not asks(text, rooms, goal), factors(text, rooms)


def test_a_thing_going_off_is_not_switched_off() -> None:
    text = "If the smoke alarm goes off, open the window and wave a tea towel at it."
    assert not asks(text, ("kitchen",), "state(smoke_detector, toggled_on)"), factors(text, ("kitchen",))
