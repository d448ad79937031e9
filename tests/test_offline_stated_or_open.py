"""What a sentence asserts and what it leaves open (issue 47 item 2: a stated fact is a fact, a
condition or a question is a factor), by structure: the source of an instruction of taking, a
hedged place, a place "to be checked". Each rule on sentences of at least two texts, with near
misses where a condition or a doubt governs the same words."""

from __future__ import annotations

from reading import CATALOG, asks, brief, factors, named, placed

from logicenveval.offline.analysis import analyse

# --- the source of an instruction of taking is presupposed --------------------------------------


def test_the_source_of_an_instruction_of_taking_is_stated_not_asked() -> None:
    # issue 47's garage: "a spare fuse ... from the drawer" was a yes/no factor
    garage = "Take a spare fuse from the drawer and replace the fuse that is blown."
    assert not asks(garage, ("garage",), "inside(spare_fuse, drawer)")
    assert "inside(spare_fuse, drawer)" in placed(garage, ("garage",))
    bathroom = "Please grab a fresh towel out of the cabinet and hang it on the rail."
    assert "inside(towel, cabinet)" in placed(bathroom, ("bathroom",))
    shelf = "Just grab a towel from the shelf, then hang it on the rail."
    assert not any("on(towel, wall_shelf)" in v for v in factors(shelf, ("bathroom",)).values())


def test_a_source_under_a_condition_or_a_doubt_stays_open() -> None:
    for text in ("Take a spare fuse from the drawer if you can find one and replace the fuse that is blown.",
                 "If there's one in the drawer, take a spare fuse from the drawer.",
                 "Maybe take a spare fuse from the drawer."):
        assert asks(text, ("garage",), "inside(spare_fuse, drawer)"), text
        assert "inside(spare_fuse, drawer)" not in placed(text, ("garage",)), text
    # someone's taking in a condition is no instruction
    cond = "If you take a towel from the shelf, hang it on the rail."
    assert asks(cond, ("bathroom",), "on(towel, wall_shelf)")
    # a goal is no source
    assert not placed("Take the towel to the shelf.", ("bathroom",))


# --- a hedged place is open ---------------------------------------------------------------------


def test_a_hedged_place_in_the_one_room_asks_whether_the_thing_is_there() -> None:
    # dev 16 flatlet_tenancy_dispute_letter (a landlord's letter)
    flatlet = ("Thirdly, I believe I may have left my wristwatch in the flatlet during the gas safety visit "
               "on 12 November. If it is there, it will be on the armchair. Please put it on top of the "
               "sideboard.")
    assert asks(flatlet, ("flatlet",), "exists(watch)")
    assert "in_room(watch, flatlet)" not in placed(flatlet, ("flatlet",))
    for text in ("I think I may have left my wallet in the bathroom. If it is there, put it on the shelf.",
                 "I'm not sure my wallet is in the bathroom. If it is there, put it on the shelf.",
                 "I believe my wallet is in the bathroom; if it is, put it on the shelf."):
        assert asks(text, ("bathroom",), "exists(wallet)"), text
        assert "in_room(wallet, bathroom)" not in placed(text, ("bathroom",)), text


def test_a_plain_place_is_stated_and_a_room_among_several_is_a_place() -> None:
    plain = "My wallet is in the bathroom. Put it on the shelf."
    assert "in_room(wallet, bathroom)" in placed(plain, ("bathroom",))
    assert not factors(plain, ("bathroom",))
    # with two rooms, being in one of them is a place, not presence
    two = "I think I may have left my wallet in the bathroom. If it is there, put it on the shelf."
    assert not asks(two, ("bathroom", "hall"), "exists(wallet)")
    assert "in_room(wallet, bathroom)" not in placed(two, ("bathroom", "hall"))
    # "make sure" is no hedge
    assert "in_room(wallet, bathroom)" in placed("Make sure of this: my wallet is in the bathroom.",
                                                  ("bathroom",))


# --- a place to be checked is open --------------------------------------------------------------


def test_a_place_to_be_checked_is_asked_not_stated() -> None:
    # dev 15 laundry_drying_rack_d15 (a recipe's ingredients)
    laundry = ("INGREDIENTS\n1 towel, to be checked on the drying rack\n\nMETHOD\n1. Once the towel is dry, "
               "bring it in to the utility shelf; a wet towel stays on the rack.")
    assert asks(laundry, ("laundry_room",), "on(towel, drying_rack)")
    key = "The spare key, still to be confirmed in the drawer. If it is there, put it on the hook."
    assert asks(key, ("hall",), "inside(spare_key, drawer)")
    assert "inside(spare_key, drawer)" not in placed(key, ("hall",))


def test_a_place_said_outright_or_a_check_of_something_else_is_no_doubt() -> None:
    stated = "The towel is on the drying rack. Once it is dry, bring it in to the utility shelf."
    assert "on(towel, drying_rack)" in placed(stated, ("laundry_room",))
    assert not asks(stated, ("laundry_room",), "on(towel, drying_rack)")
    # "to be checked" before no place leaves every place as it was
    later = "The towel is to be checked on arrival. It hangs on the drying rack."
    assert "on(towel, drying_rack)" in placed(later, ("laundry_room",))


# --- a quoted report answered by "Then" is the reply's premise ----------------------------------


def test_a_quoted_report_answered_by_then_is_asked() -> None:
    # dev 15 guest_suite_email_chain (an email reply under a quoted message)
    suite = ("On Fri, Sam wrote:\n> Also the curtains were open when I walked past this morning\n\n"
             "Then could you close them? The Hendersons like it dark. If somebody has drawn them already, fine.")
    assert asks(suite, ("guest_suite",), "state(curtain, open)")
    fridge = "On Monday, Jo wrote:\n> the fridge was open when I left.\n\nThen please shut it."
    assert asks(fridge, ("kitchen",), "state(fridge, open)")
    telly = "> I think the telly was still on when I left\n\nThen switch it off please."
    assert asks(telly, ("living_room",), "state(television, toggled_on)")


def test_a_quoted_report_answered_without_then_or_a_plain_then_asks_nothing() -> None:
    assert not factors("On Monday, Jo wrote:\n> the fridge was open when I left.\n\nPlease shut it.", ("kitchen",))
    assert not factors("The fridge is open. Then close it.", ("kitchen",))


# --- a forum quote's first person speaks of another home ----------------------------------------


def test_a_forum_quotes_first_person_speaks_of_another_home() -> None:
    # dev 15 bedroom_nightstand_reset_d15 (a forum reply)
    forum = ("Quote from: nightowl_kat on November 29, 2026, 09:03:12 PM\n> Mine keeps shoving my phone in a drawer. "
             "What do you put for the phone??\n\nHonestly the phone is the whole trick. My phone may be lying on "
             "the bed. If it's switched on, it goes on the nightstand. Any other book goes into the nightstand "
             "drawer - open the drawer unless it's already open.")
    assert "drawer" not in named(forum, ("bedroom",))
    assert asks(forum, ("bedroom",), "on(cell_phone, bed)")
    assert asks(forum, ("bedroom",), "state(nightstand, open)")
    mug = ("Quote from: mossy_pete on March 3, 2026\n> My robot keeps putting my mug in the cupboard. Any tips?\n\n"
           "Sure. My mug may be on the desk. If it is dirty, it goes in the sink.")
    assert asks(mug, ("kitchen",), "on(mug, desk)")
    assert not any("inside(mug, cabinet)" in v for v in factors(mug, ("kitchen",)).values())


def test_an_email_quotes_first_person_and_a_forum_quote_in_the_third_stay() -> None:
    # an email quote between members of one household speaks of the same scene
    telly = "On Monday, Jo wrote:\n> I think the telly was still on when I left\n\nThen switch it off please."
    assert asks(telly, ("living_room",), "state(television, toggled_on)")
    third = ("Quote from: mossy_pete on March 3, 2026\n> The keys keep ending up on the sofa.\n\n"
             "If the keys are on the floor, the robot hangs them on the hook.")
    assert any("on(keys, sofa)" in values for values in factors(third, ("hall",)).values())


# --- a condition left without its consequence, answered by "Then ..." ---------------------------


def _contexts(text: str, rooms: tuple[str, ...]) -> dict[str, list[tuple[str, frozenset[str]]]]:
    return {f.id: f.context for f in analyse(brief(text, rooms), CATALOG).factors}


def test_a_sentence_opening_with_then_answers_a_condition_left_open() -> None:
    # dev 16 kitchen_breakfast_prep_d16 (a mission-control loop)
    eggs = ("EGGS are conditional: only if there are eggs in the fridge. Then the sequence is: open the fridge; "
            "put the frying pan on the stove, unless it is already there; take an egg and put it in the pan.")
    assert _contexts(eggs, ("kitchen",))["pan_on_stove"] == [("egg_inside_fridge", frozenset({"yes"}))]
    lamp = ("Only if the lamp is on. Then the steps are: switch it off; close the curtains unless they are "
            "already closed.")
    assert _contexts(lamp, ("bedroom",))["curtain_open"] == [("table_lamp_toggled_on", frozenset({"yes"}))]


def test_then_after_a_condition_with_its_own_consequence_starts_afresh() -> None:
    done = ("If the lamp is on, switch it off. Then close the curtains unless they are already closed.")
    assert _contexts(done, ("bedroom",))["curtain_open"] == []


# --- a speaker's belief hedges the factor reader too -------------------------------------------


def test_a_speakers_belief_leaves_the_place_open() -> None:
    shed = "I think I left the torch on the shelf. If it is there, put it in the box."
    assert asks(shed, ("shed",), "on(flashlight, wall_shelf)")
    kitchen = "I reckon the mug is on the desk. If it is there, put it in the sink."
    assert asks(kitchen, ("kitchen",), "on(mug, desk)")
    assert "on(mug, desk)" not in placed(kitchen, ("kitchen",))
    unsure = "I'm not sure the torch is on the shelf. If it is there, put it in the box."
    assert asks(unsure, ("shed",), "on(flashlight, wall_shelf)")


def test_a_place_said_without_a_belief_is_stated() -> None:
    plain = "The mug is on the desk. Put it in the sink."
    assert "on(mug, desk)" in placed(plain, ("kitchen",))
    assert not factors(plain, ("kitchen",))
    # "make sure" is no doubt of the speaker's
    sure = "Make sure the mug is in the sink. The mug is on the desk."
    assert "on(mug, desk)" in placed(sure, ("kitchen",))


def test_the_state_a_thing_is_taken_in_from_its_source_is_presupposed() -> None:
    towel = "Grab a clean towel from the cupboard and hang it on the rail."
    assert not asks(towel, ("bathroom",), "state(towel, dirty)")
    cloth = "Take a dry cloth out of the drawer and wipe the table."
    assert not asks(cloth, ("kitchen",), "state(cloth, wet)")
    assert "inside(cloth, drawer)" in placed(cloth, ("kitchen",))


def test_a_state_with_no_source_or_under_a_condition_is_still_asked() -> None:
    assert asks("Take a dirty towel to the hamper.", ("bathroom",), "state(towel, dirty)")
    governed = "Take a clean towel from the cupboard if there is one and hang it on the rail."
    assert asks(governed, ("bathroom",), "state(towel, dirty)")
