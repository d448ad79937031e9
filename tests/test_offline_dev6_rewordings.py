"""Rules from the sixth development set's rewordings (`tests/data/reader_dev6/tasks_reworded/`): each
is a kind of sentence (a telegram's punctuation words, a pronoun or "there" for a place, a
possessive list per room, ...), tried on the development set's sentence and on one written here in
another room with other objects."""

from __future__ import annotations

import pytest
from reading import brief as _brief
from reading import factors as _factors
from reading import placed as _placed

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.analysis import analyse
from logicenveval.offline.placement import described_placements
from logicenveval.offline.sentences import unquote

# ----- placements ----------------------------------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "placed"), [
    # dev6 (a landlady's house rules)
    ("The room is let furnished with a bed, a nightstand (the lamp stands on it), a wardrobe and a "
     "laundry hamper.", ("bedroom",), "on(table_lamp, nightstand)"),
    # written here: another room, the holder in the sentence before
    ("There is a kitchen counter by the window. The kettle sits on it.", ("kitchen",),
     "on(kettle, kitchen_counter)"),
])
def test_on_it_after_a_verb_of_resting_is_the_holder_named_before(text: str, rooms: tuple[str, ...],
                                                                   placed: str) -> None:
    """"a nightstand (the lamp stands on it)": "on it" is the nearest thing named before that
    holds things (in the sentence, else the last statement's subject)."""
    assert placed in _placed(text, rooms)


def test_on_it_after_a_doubt_places_nothing() -> None:
    """"A book ... may have been left on it": the pronoun's holder is no statement when doubted."""
    text = "The bed in the bedroom is to be cleared. A book or a phone may have been left on it."
    assert not {"on(book, bed)", "on(cell_phone, bed)"} & _placed(text, ("bedroom",))


@pytest.mark.parametrize(("text", "rooms", "placed", "not_placed"), [
    # dev6 (a newsletter column)
    ("In their house the kitchen holds the trash can, the recycling bin and the fridge, the living room has "
     "a sofa and a coffee table, and the front door sits at the end of the hallway.",
     ("kitchen", "living_room", "hallway"),
     {"in_room(fridge, kitchen)", "in_room(sofa, living_room)", "in_room(coffee_table, living_room)"},
     {"in_room(sofa, kitchen)"}),
    # written here
    ("The bedroom has a wardrobe and a bed, and the study contains a desk and an office chair.",
     ("bedroom", "study"), {"in_room(bed, bedroom)", "in_room(desk, study)", "in_room(office_chair, study)"},
     {"in_room(desk, bedroom)"}),
])
def test_a_possessive_list_ends_at_the_next_owner_and_its_verb(text: str, rooms: tuple[str, ...],
                                                               placed: set[str], not_placed: set[str]) -> None:
    """"the kitchen holds the bin and the fridge, the living room has a sofa": each room holds the
    list after its own verb, not the next room's."""
    got = _placed(text, rooms)
    assert placed <= got
    assert not not_placed & got


@pytest.mark.parametrize(("text", "rooms", "placed"), [
    # dev6 (a restaurant's closing duties)
    ("Back of house is the kitchen, straight through from the dining room: dish machine (the dishwasher), "
     "sink, fridge, a cabinet and the recycling bin are all back there.", ("dining_room", "kitchen"),
     {"in_room(sink, kitchen)", "in_room(cabinet, kitchen)", "in_room(recycling_bin, kitchen)"}),
    # written here
    ("The laundry room is at the end of the hallway; the washing machine and the dryer are out there.",
     ("laundry_room", "hallway"), {"in_room(washing_machine, laundry_room)", "in_room(dryer, laundry_room)"}),
])
def test_a_statement_ending_in_there_is_in_the_room_named_before(text: str, rooms: tuple[str, ...],
                                                                  placed: set[str]) -> None:
    """"... are all back there": the nearest room named before the subject, not one named as a
    source ("from the dining room")."""
    assert placed <= _placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "placed"), [
    # dev6 (a telegram)
    ("NO ROLL BY TOILET STOP THEN TAKE SPARE ROLL FROM VANITY CABINET WHERE SPARES KEPT STOP PUT IT ON "
     "TOILET TANK STOP", ("bathroom",), "inside(spare_roll, bathroom_vanity)"),
    # written here
    ("No fuse in the lamp? Then take a spare fuse from the drawer where the spares are kept.",
     ("study",), "inside(spare_fuse, drawer)"),
])
def test_a_home_in_a_relative_clause_of_an_instruction(text: str, rooms: tuple[str, ...], placed: str) -> None:
    """"take a spare roll from the vanity cabinet where spares are kept": an instruction's
    relative clause with a verb of keeping says where the thing lives."""
    assert placed in _placed(text, rooms)


# ----- normalising the text -------------------------------------------------------------------------

@pytest.mark.parametrize(("text", "read"), [
    # dev6
    ("BATH TOWEL ON FLOOR QUERY IF WET INTO LAUNDRY BASKET STOP IF DRY HANG BACK ON TOWEL RACK STOP",
     "BATH TOWEL ON FLOOR? IF WET INTO LAUNDRY BASKET. IF DRY HANG BACK ON TOWEL RACK."),
    # written here
    ("ARRIVING MONDAY STOP BOOTS IN HALL QUERY PUT THEM ON SHOE RACK STOP", "ARRIVING MONDAY. BOOTS IN HALL? "
     "PUT THEM ON SHOE RACK."),
    # one "stop" is a word
    ("Stop the dryer when the towel is dry.", "Stop the dryer when the towel is dry."),
])
def test_a_telegrams_stop_and_query_are_its_punctuation(text: str, read: str) -> None:
    assert unquote(text) == read


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6
    ("BATHROOM REFRESH STOP BATH TOWEL ON FLOOR QUERY IF WET INTO LAUNDRY BASKET STOP IF DRY HANG BACK ON "
     "TOWEL RACK STOP LASTLY MIRROR DIRTY QUERY CLEAN IT STOP", ("bathroom",),
     {"on(towel, floor)", "state(towel, wet)", "state(mirror, dirty)"}),
    # written here
    ("HALL CHECK STOP BOOTS ON SHOE RACK QUERY IF MUDDY INTO SINK STOP", ("hallway",),
     {"on(shoe, shoe_rack)", "state(shoe, dirty)"}),
])
def test_a_telegram_reads_as_its_sentences(text: str, rooms: tuple[str, ...], asked: set[str]) -> None:
    """With its punctuation words read, a telegram's questions ("ON FLOOR QUERY") and terse
    conditions ("IF WET INTO LAUNDRY BASKET": the bare state, then where it goes) are factors."""
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert asked <= values
    assert not any("laundry_basket, wet" in v or "sink, dirty" in v for v in values)


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6 (the telegram, punctuated)
    ("No roll by toilet then take spare roll from vanity cabinet. Put it on toilet tank.", ("bathroom",),
     "exists(toilet_paper)"),
    # written here
    ("No soap by the sink then take a new bar of soap from the cabinet.", ("bathroom",), "exists(soap_bar)"),
])
def test_no_thing_then_an_instruction_asks_whether_there_is_one(text: str, rooms: tuple[str, ...],
                                                                asked: str) -> None:
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert asked in values
    assert unquote("No need to fold it then put it away.") == "No need to fold it then put it away."


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6 (a Yorkshire note)
    ("That plate on the counter - if it's mucky it goes in the dishwasher, unless the dishwasher's already "
     "going, then just stick it in the sink.", ("kitchen",), "state(dishwasher, toggled_on)"),
    # written here
    ("If the washing machine is still going, put the shirt in the hamper.", ("laundry_room",),
     "state(washing_machine, toggled_on)"),
])
def test_going_as_a_predicate_is_running(text: str, rooms: tuple[str, ...], asked: str) -> None:
    """"the dishwasher's already going": running; "it is going in the bin" stays a verb."""
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert asked in values
    assert not any(v.startswith("inside(dishwasher") for v in values)
    assert unquote("It is going in the bin.") == "It is going in the bin."


@pytest.mark.parametrize(("text", "rooms", "goal"), [
    # dev6
    ("If the plate is dirty it goes in the dishwasher, unless the dishwasher is running, then just stick it "
     "in the sink.", ("kitchen",), "dishwasher"),
    # written here
    ("If the towel is wet, just stick it in the laundry basket.", ("bathroom",), "towel"),
])
def test_stick_is_a_verb_of_putting(text: str, rooms: tuple[str, ...], goal: str) -> None:
    """"just stick it in the sink" says where the thing goes: no factor asks whether it is there."""
    assert not any("inside" in v for vs in _factors(text, rooms).values() for v in vs)


# ----- conditions and factors --------------------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6 (the telegram, punctuated)
    ("Bath towel on floor? If wet, into laundry basket. If dry, hang back on towel rack.", ("bathroom",),
     "on(towel, floor)"),
    # written here
    ("Jacket on the chair? If wet, onto the drying rack.", ("hallway",), "on(jacket, chair)"),
])
def test_a_question_heading_before_a_condition_is_asked(text: str, rooms: tuple[str, ...], asked: str) -> None:
    """"Towel on the floor? If wet, ...": a heading ending in "?" asks where the thing is, even when
    a condition answers it (a heading with a colon would state it)."""
    assert asked in {v for vs in _factors(text, rooms).values() for v in vs}


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6 (the telegram, punctuated)
    ("Mirror dirty? Clean it. Use microfibre cloth if we still have one. Cloth lives in vanity.",
     ("bathroom",), "exists(cloth)"),
    # written here
    ("Wipe the counter with the sponge if we still have one. The sponge lives in the cabinet.", ("kitchen",),
     "exists(sponge)"),
])
def test_a_home_stated_on_its_own_still_asks_whether_there_is_one(text: str, rooms: tuple[str, ...],
                                                                  asked: str) -> None:
    """"The cloth lives in the vanity" says where it belongs, not that it is there now: "if we still
    have one" is still asked."""
    assert asked in {v for vs in _factors(text, rooms).values() for v in vs}


@pytest.mark.parametrize(("text", "rooms", "asked", "not_asked"), [
    # dev6 (a newsletter column)
    ("On trash day, whoever is up first checks the kitchen trash can. If it's full, take the bag out.",
     ("kitchen",), "state(trash_can, filled)", "state(trash_bag, filled)"),
    # written here
    ("On laundry day, look at the hamper. If it's full, empty it into the washing machine.",
     ("laundry_room",), "state(hamper, filled)", "state(laundry_basket, filled)"),
])
def test_a_name_before_day_is_a_time(text: str, rooms: tuple[str, ...], asked: str, not_asked: str) -> None:
    """"On trash day": a time, no mention of a trash bag for "it" to take up."""
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert asked in values
    assert not_asked not in values


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6 (a Canadian note)
    ("If there's an umbrella: wet, stand it in the umbrella stand; dry, lay it on the console table.",
     ("hallway",), "state(umbrella, wet)"),
    # written here
    ("Check the towel on the floor. Damp, hang it on the towel rack; dry, fold it into the cabinet.",
     ("bathroom",), "state(towel, wet)"),
])
def test_a_bare_state_and_a_comma_before_an_instruction_is_its_condition(text: str, rooms: tuple[str, ...],
                                                                         asked: str) -> None:
    """"wet, stand it in the umbrella stand": the case of the thing spoken of ("stand" names no
    umbrella stand's state)."""
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert asked in values
    assert not any("umbrella_stand, wet" in v or "towel_rack, wet" in v for v in values)
    assert unquote("Towels: damp, hang them on the rail.") == "Towels: if they are damp, hang them on the rail."


@pytest.mark.parametrize(("text", "rooms", "kinds"), [
    # dev6 (a game-show host)
    ("Toys on the floor! Every doll goes into the red toy box, every toy car into the blue box, and any other "
     "kind of toy into the green box! A toy that's NOT on the floor? It stays where it is.", ("kids_room",),
     {"attr(toy, kind, doll)", "attr(toy, kind, car)"}),
    # written here
    ("Books on the desk! Every novel goes onto the bookshelf, and any other sort of book into the drawer.",
     ("study",), {"attr(book, kind, novel)"}),
])
def test_every_one_of_a_kind_and_any_other_kind_of_it_are_classes(text: str, rooms: tuple[str, ...],
                                                                  kinds: set[str]) -> None:
    """"Every doll goes into the red box, ... any other kind of toy into the green box": the
    toy's kind is asked, no doll or toy car object; a bare plural heading ("Toys on the floor!")
    states no placement, so where the toy is stays asked."""
    brief = _brief(text, rooms)
    assert not {"doll", "toy_car", "novel"} & set(brief["roles"])
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert kinds <= values
    assert "on(toy, floor)" not in described_placements(brief, load_catalog())


def test_a_bare_plural_heading_places_nothing() -> None:
    assert _placed("Toys on the floor!", ("kids_room",)) == set()
    assert _placed("Books on the desk!", ("study",)) == set()
    assert "on(floor_stain, floor)" in _placed("Dirty mark on the floor.", ("study",))


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6 (house rules)
    ("Pillows are not to be left on the floor. Should a pillow have fallen there, it is to be put back on the bed.",
     ("bedroom",), "on(pillow, floor)"),
    # written here
    ("The blanket is not to be left on the armchair. If the blanket has been left there, fold it onto the sofa.",
     ("living_room",), "on(blanket, armchair)"),
])
def test_there_in_a_condition_is_the_place_named_before(text: str, rooms: tuple[str, ...], asked: str) -> None:
    """"Should a pillow have fallen there": the place of the clause before."""
    assert asked in {v for vs in _factors(text, rooms).values() for v in vs}


@pytest.mark.parametrize(("text", "rooms", "absent"), [
    # dev6 (a how-to)
    ("Check the shirt on the floor. If it's dirty and white, put it in the washing machine: open the machine, "
     "load the shirt and close the door. If it's dirty and coloured, put it in the hamper.", ("laundry_room",),
     "state(washing_machine, dirty)"),
    # written here
    ("Look at the mug on the desk. If it's dirty and chipped, put it in the trash can: open the lid of the trash "
     "can first. If it's dirty and whole, put it in the sink.", ("kitchen",), "state(trash_can, dirty)"),
])
def test_a_parallel_condition_speaks_of_the_thing_the_one_before_asked(text: str, rooms: tuple[str, ...],
                                                                       absent: str) -> None:
    """"If it's dirty and white, put it in the washing machine: open the machine ... If it's dirty
    and coloured, ...": the second "it" is the shirt asked before, not the machine named between."""
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert absent not in values


@pytest.mark.parametrize(("text", "rooms", "first", "then"), [
    # dev6 (the telegram, punctuated)
    ("Mirror dirty? Clean it. Use microfibre cloth if we still have one.", ("bathroom",), "mirror_dirty",
     "cloth_present"),
    # written here
    ("Counter sticky? Wipe it. Use the sponge if we still have one.", ("kitchen",), "kitchen_counter_dirty",
     "sponge_present"),
])
def test_an_instruction_alone_after_a_question_passes_its_condition_on(text: str, rooms: tuple[str, ...],
                                                                       first: str, then: str) -> None:
    """"Mirror dirty? Clean it. Use the cloth if we still have one.": whether there is a cloth is
    asked only when the mirror is dirty."""
    factors = {f.id: f for f in analyse(_brief(text, rooms), load_catalog()).factors}
    assert (first, frozenset({"yes"})) in factors[then].context


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6, in English ("si no" in the text)
    ("Also maybe there's a tomato on the counter: if it's ripe, to the fridge; if not, it goes in the fruit "
     "bowl.", ("kitchen",), "attr(tomato, ripeness, ripe)"),
    # written here
    ("If the banana is ripe, put it on the dining table; otherwise leave it in the fruit bowl.", ("dining_room",),
     "attr(banana, ripeness, ripe)"),
])
def test_an_adjective_answered_by_an_alternative_is_asked(text: str, rooms: tuple[str, ...], asked: str) -> None:
    """"if it's ripe, ...; otherwise ...": an adjective the catalog has no domain for is asked when
    an alternative answers its condition (as when it is said both ways)."""
    assert asked in {v for vs in _factors(text, rooms).values() for v in vs}


def test_a_pronoun_after_its_thing_in_the_same_sentence_is_that_thing() -> None:
    """The parallel-condition rule reads only a condition opening its sentence: "turn off the table
    lamp if it's on" after a condition on the TV is still the lamp."""
    text = "Switch the TV off unless it's already off. In the bedroom, turn off the table lamp if it's on."
    assert "table_lamp_toggled_on" in _factors(text, ("living_room", "bedroom"))


def test_an_adjective_beside_a_state_in_a_condition_is_not_asked_for_its_alternative() -> None:
    """"if it's wet and the dryer is free, ..., but when ...": an adjective joined to a state the
    catalog reads is not made a factor by the alternative."""
    text = ("If the shirt is wet and the dryer is free, dry it in the dryer, but when the dryer is already running, "
            "hang the shirt on the drying rack instead.")
    assert not any(k.endswith("freeness") for k in _factors(text, ("laundry_room",)))


@pytest.mark.parametrize(("text", "rooms", "asked"), [
    # dev6 (a how-to)
    ("Check the shirt on the floor. If it's dirty and white, put it in the washing machine. If it's dirty and "
     "coloured, put it in the hamper.", ("laundry_room",), "attr(shirt, color, white)"),
    # written here
    ("If the towel is wet and white, hang it on the towel rack.", ("bathroom",), "attr(towel, color, white)"),
])
def test_a_value_joined_to_a_state_is_asked(text: str, rooms: tuple[str, ...], asked: str) -> None:
    """"if it's dirty and white": the colour after the state is asked as well."""
    assert asked in {v for vs in _factors(text, rooms).values() for v in vs}


@pytest.mark.parametrize(("text", "rooms"), [
    # dev6's sentence with a verb the reader does not know as one of putting
    ("If the mug is dirty it goes in the dishwasher, unless the dishwasher is running, then just chuck it in the "
     "sink.", ("kitchen",)),
    # written here
    ("If the towel is dirty it goes in the washing machine, unless the washing machine is running, then just dump "
     "it in the bathtub.", ("bathroom", "laundry_room")),
    ("If the mug is clean it goes in the cabinet, unless the cabinet is full, then just dump it on the kitchen "
     "counter.", ("kitchen",)),
])
def test_no_piece_of_furniture_is_asked_in_another(text: str, rooms: tuple[str, ...]) -> None:
    """A piece of furniture (a surface or container nobody carries) is never on or in another role,
    whatever the sizes allow: such a reading is dropped, not planned (it left no layout)."""
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert not any(v.startswith(("inside(dishwasher", "inside(washing_machine", "on(cabinet")) for v in values)


@pytest.mark.parametrize(("text", "rooms", "thing"), [
    # dev6's construction ("then just stick it in the sink") with another verb
    ("If the mug is dirty, just chuck it in the sink.", ("kitchen",), "mug"),
    # written here
    ("If the sock is dirty, just dump it in the laundry basket.", ("bedroom",), "sock"),
])
def test_just_before_an_instruction_keeps_it_an_instruction(text: str, rooms: tuple[str, ...], thing: str) -> None:
    """"just chuck it in the sink": a softener before the verb; the place is where it goes, not a
    condition on where it is."""
    values = {v for vs in _factors(text, rooms).values() for v in vs}
    assert not any(v.startswith(("inside(", "on(")) for v in values)


@pytest.mark.parametrize(("text", "rooms", "inside", "state"), [
    # dev6 (a how-to)
    ("Step 3: Check the dryer. If there's a towel inside and the dryer has stopped, take the towel out, put it on "
     "the shelf and close the dryer door.", ("laundry_room",), "inside(towel, dryer)", "state(dryer, toggled_on)"),
    # written here
    ("Look in the fridge. If there's a milk carton inside and the fridge is open, take the milk carton out.",
     ("kitchen",), "inside(milk_carton, fridge)", "state(fridge, open)"),
])
def test_inside_with_no_object_is_the_holder_spoken_of(text: str, rooms: tuple[str, ...], inside: str,
                                                       state: str) -> None:
    """"If there's a towel inside and the dryer has stopped": "inside" before "and" does not make
    the dryer after it a place, so the clause after "and" says the dryer's state, and the towel's
    place in the dryer and the dryer's state are one subtask."""
    a = analyse(_brief(text, rooms), load_catalog())
    by_value = {v: f.id for f in a.factors for v in f.values.values()}
    assert inside in by_value and state in by_value
    assert any(by_value[inside] in g and by_value[state] in g for g in a.groups)
