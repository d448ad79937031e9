"""The placement reader (offline.placement) by grammatical form (issue 47): each form on sentences
of at least two different texts, sentences written here in varied wording next to sentences of the
development set (tests/data/reader_dev/), and what must not be placed (conditions, doubts,
instructions, generic noun phrases)."""

from __future__ import annotations

from typing import Any

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.placement import described_placements
from logicenveval.offline.realise import realise

CATALOG = load_catalog()
ROOMS = ["kitchen", "living_room", "bedroom", "study", "hallway", "garage", "bathroom", "pantry", "dining_room"]

#: roles the sentences below speak of (role name -> catalog category)
ROLES = {
    "jacket": "jacket", "chair": "chair", "cardboard_box": "cardboard_box", "stool": "stool",
    "dishwasher": "dishwasher", "sink": "sink", "cabinet": "cabinet", "fridge": "fridge",
    "handbag": "handbag", "kettle": "kettle", "counter": "kitchen_counter", "bath_mat": "bath_mat",
    "bathtub": "bathtub", "tablet": "tablet", "mark": "floor_stain", "trash_can": "trash_can",
    "sofa": "sofa", "coffee_table": "coffee_table", "basket": "basket", "cereal": "cereal_box",
    "bucket": "bucket", "bed": "bed", "wardrobe": "wardrobe", "nightstand": "nightstand",
    "lamp": "table_lamp", "vase": "vase", "shelf": "wall_shelf", "book": "book", "desk": "desk",
    "laptop": "laptop", "pen": "pen", "keys": "keys", "key_hook": "key_hook", "wet_wipe": "wet_wipe",
    "table": "dining_table", "spare_roll": "toilet_paper", "vanity": "bathroom_vanity",
    "shampoo": "shampoo", "wall_cabinet": "wall_cabinet", "flashlight": "flashlight", "coat": "coat",
    "newspaper": "newspaper", "plate": "plate", "mug": "mug",
}


def _read(text: str, *roles: str, kinds: frozenset[str] | None = None) -> list[str]:
    brief: dict[str, Any] = {"id": "t", "description": text, "rooms": ROOMS,
                             "roles": {r: {"category": ROLES[r]} for r in roles}}
    missing = [r for r in roles if CATALOG.get(ROLES[r]) is None]
    if missing:
        pytest.skip(f"the catalog lacks {missing}")
    if kinds is None:
        return described_placements(brief, CATALOG)
    return described_placements(brief, CATALOG, kinds=kinds)


@pytest.mark.parametrize(("text", "roles", "facts"), [
    # "the X is/lies/sits on the Y": the subject before the verb, whatever is named after the place
    ("The jacket is on the chair.", ("jacket", "chair"), {"on(jacket, chair)"}),
    ("The cardboard box is on the floor next to the stool; it's where the flashlight lives.",
     ("cardboard_box", "stool", "flashlight"), {"on(cardboard_box, floor)"}),
    ("My handbag is on the floor by the door.", ("handbag",), {"on(handbag, floor)"}),
    ("The kettle usually sits on the counter.", ("kettle", "counter"), {"on(kettle, counter)"}),
    ("The bath mat lies on the floor in front of the bathtub; when it's wet, put it in the tub.",
     ("bath_mat", "bathtub"), {"on(bath_mat, floor)"}),
    ("The tablet is lying on the chair. It needs to go on the desk.", ("tablet", "chair", "desk"),
     {"on(tablet, chair)"}),
    ("A dirty mark has been left on the floor, and a packet of wet wipes may have been put on the table.",
     ("mark", "wet_wipe", "table"), {"on(mark, floor)"}),
    # a list before the verb, and later lists sharing the verb (gapping)
    ("The dishwasher, the sink, the fridge and a cabinet are in the kitchen, which opens off the dining room.",
     ("dishwasher", "sink", "fridge", "cabinet"),
     {"in_room(dishwasher, kitchen)", "in_room(sink, kitchen)", "in_room(fridge, kitchen)",
      "in_room(cabinet, kitchen)"}),
    ("The trash can and the fridge are found in the kitchen, a sofa and a coffee table in the living room.",
     ("trash_can", "fridge", "sofa", "coffee_table"),
     {"in_room(trash_can, kitchen)", "in_room(fridge, kitchen)", "in_room(sofa, living_room)",
      "in_room(coffee_table, living_room)"}),
    ("The bed is in the bedroom, the desk in the study.", ("bed", "desk"),
     {"in_room(bed, bedroom)", "in_room(desk, study)"}),
    # the floor of a room places the object on the floor and in the room
    ("I've just come back, and the shopping basket is on the kitchen floor.", ("basket",),
     {"on(basket, floor)", "in_room(basket, kitchen)"}),
    # an active past with a subject that is no object: the object after the verb
    ("Someone also left a dirty mark on the floor.", ("mark",), {"on(mark, floor)"}),
    ("Could you sort out the coat the kids dumped in the hallway?", ("coat",), {"in_room(coat, hallway)"}),
])
def test_copular_and_locative_clauses(text: str, roles: tuple[str, ...], facts: set[str]) -> None:
    assert facts <= set(_read(text, *roles))


@pytest.mark.parametrize(("text", "roles", "facts"), [
    ("The kitchen, next door to the dining room, has the dishwasher, the sink and a cabinet.",
     ("dishwasher", "sink", "cabinet"),
     {"in_room(dishwasher, kitchen)", "in_room(sink, kitchen)", "in_room(cabinet, kitchen)"}),
    ("The garage contains a bucket and a stool.", ("bucket", "stool"),
     {"in_room(bucket, garage)", "in_room(stool, garage)"}),
    ("The bedroom is to be tidied. It contains a bed, a wardrobe and a nightstand on which a lamp stands.",
     ("bed", "wardrobe", "nightstand", "lamp"),
     {"in_room(bed, bedroom)", "in_room(wardrobe, bedroom)", "on(lamp, nightstand)"}),
    ("The basket also holds a box of cereal, which belongs on the lower shelf.", ("basket", "cereal"),
     {"inside(cereal, basket)"}),
    ("There is a dirty mark on the floor.", ("mark",), {"on(mark, floor)"}),
    ("There's a jacket on the chair and a pen on the desk.", ("jacket", "chair"), {"on(jacket, chair)"}),
    ("There's the bed, a wardrobe and the nightstand with a lamp on it.", ("bed", "nightstand", "lamp"),
     {"on(lamp, nightstand)"}),
    ("Bedroom: bed, wardrobe, nightstand with lamp.", ("bed", "nightstand", "lamp"), {"on(lamp, nightstand)"}),
])
def test_possessive_existential_and_with(text: str, roles: tuple[str, ...], facts: set[str]) -> None:
    assert facts <= set(_read(text, *roles))


@pytest.mark.parametrize(("text", "roles", "facts"), [
    ("The bedroom has a nightstand on which a lamp stands.", ("nightstand", "lamp"), {"on(lamp, nightstand)"}),
    ("Above the sofa hangs a shelf, on which the vase sits.", ("shelf", "vase"), {"on(vase, shelf)"}),
    ("Put it in the bucket, which stands on the floor as well.", ("bucket",), {"on(bucket, floor)"}),
    ("Look at the kettle, which is on the counter.", ("kettle", "counter"), {"on(kettle, counter)"}),
    ("The dining room opens onto the kitchen - that's where the dishwasher and the sink are.",
     ("dishwasher", "sink"), {"in_room(dishwasher, kitchen)", "in_room(sink, kitchen)"}),
    ("The kitchen's just through from the dining room - that's where the fridge and a cabinet are.",
     ("fridge", "cabinet"), {"in_room(fridge, kitchen)", "in_room(cabinet, kitchen)"}),
])
def test_relative_clauses(text: str, roles: tuple[str, ...], facts: set[str]) -> None:
    assert facts <= set(_read(text, *roles))


@pytest.mark.parametrize(("text", "roles", "facts"), [
    ("Bedroom: the table lamp off if it is on; the wardrobe closed if its doors are open.",
     ("lamp", "wardrobe"), {"in_room(lamp, bedroom)", "in_room(wardrobe, bedroom)"}),
    ("Study: the laptop goes on the desk if it is on the chair.", ("laptop", "desk"), {"in_room(desk, study)"}),
    ("On the floor: a dirty mark, and possibly a book.", ("mark", "book"), {"on(mark, floor)"}),
    ("On the desk: a laptop and a pen.", ("desk", "laptop", "pen"), {"on(laptop, desk)", "on(pen, desk)"}),
    ("Dirty mark on the floor.", ("mark",), {"on(mark, floor)"}),
    ("Jacket on the chair, keys on the hook.", ("jacket", "chair"), {"on(jacket, chair)"}),
    ("In the kitchen there is a fridge next to the sink.", ("fridge", "sink"), {"in_room(fridge, kitchen)"}),
    ("A dirty mug goes into the kitchen sink; check the bedroom wardrobe too.", ("mug", "sink", "wardrobe"),
     {"in_room(sink, kitchen)", "in_room(wardrobe, bedroom)"}),
])
def test_headings_fragments_and_room_words(text: str, roles: tuple[str, ...], facts: set[str]) -> None:
    assert facts <= set(_read(text, *roles))


@pytest.mark.parametrize(("text", "roles", "fact"), [
    ("Grab the spare roll - we store the spares in the vanity cabinet - and put it on the counter.",
     ("spare_roll", "vanity", "counter"), "inside(spare_roll, vanity)"),
    ("Take the spare roll out of the vanity cabinet, where the spares are kept, and close it.",
     ("spare_roll", "vanity"), "inside(spare_roll, vanity)"),
    ("Fetch a spare roll from the vanity (that's where the spares are kept).", ("spare_roll", "vanity"),
     "inside(spare_roll, vanity)"),
    ("The shampoo is kept in the wall cabinet. It has probably been left in the bathtub again.",
     ("shampoo", "wall_cabinet", "bathtub"), "inside(shampoo, wall_cabinet)"),
    ("The cardboard box is on the floor; it's where the flashlight lives.", ("cardboard_box", "flashlight"),
     "inside(flashlight, cardboard_box)"),
])
def test_a_home_is_read_apart_from_where_a_thing_is(text: str, roles: tuple[str, ...], fact: str) -> None:
    assert fact in _read(text, *roles, kinds=frozenset({"kept"}))
    assert fact not in _read(text, *roles, kinds=frozenset({"settled"}))


@pytest.mark.parametrize(("text", "roles"), [
    # a condition or a question: where the thing is, is in question
    ("If the jacket is on the chair, hang it up.", ("jacket", "chair")),
    ("Is the kettle on the counter? Then switch it on.", ("kettle", "counter")),
    ("Bath mat on the floor? Hang it over the bathtub.", ("bath_mat", "bathtub")),
    ("Tablet on the chair: onto the desk.", ("tablet", "chair", "desk")),
    # a doubt
    ("The jacket may be on the chair.", ("jacket", "chair")),
    ("A book may have been dropped on the floor.", ("book",)),
    ("The shampoo has probably been left in the bathtub again.", ("shampoo", "bathtub")),
    ("I think a book might be lying on the floor somewhere.", ("book",)),
    # a habit: what keeps happening may be so, it is not said of this scene
    ("My jacket keeps ending up on the chair.", ("jacket", "chair")),
    ("The tablet tends to end up on the chair.", ("tablet", "chair")),
    ("The keys are often lying on the floor.", ("keys",)),
    ("The laptop usually gets left on the sofa.", ("laptop", "sofa")),
    # an instruction, or the passive voice of one: where it goes
    ("The plate is put into the cabinet.", ("plate", "cabinet")),
    ("A newspaper on the floor or on the sofa goes in the trash can.", ("newspaper", "sofa", "trash_can")),
    ("Put the pen on the desk.", ("pen", "desk")),
    # a generic noun phrase with a participle: "whenever there is one"
    ("A book found on the floor is placed on the sofa.", ("book", "sofa")),
    ("Keys lying on the floor get hung on the key hook.", ("keys", "key_hook")),
    ("A dirty mug goes into the kitchen sink.", ("mug",)),
])
def test_nothing_is_placed_from_a_condition_a_doubt_an_instruction_or_a_generic_phrase(
        text: str, roles: tuple[str, ...]) -> None:
    facts = _read(text, *roles)
    assert not [f for f in facts if f.split("(")[1].split(",")[0] in roles[:1]], facts


def test_a_definite_phrase_with_a_participle_is_presumed_not_stated() -> None:
    text = "Pick up the keys lying on the floor."
    assert _read(text, "keys") == ["on(keys, floor)"]
    assert _read(text, "keys", kinds=frozenset({"settled", "kept"})) == []


def test_furniture_is_never_placed_on_or_in_another_piece() -> None:
    """"Take the spare roll out of the vanity, where the spares are kept, put it on the toilet"
    read with the vanity as the thing kept would put a vanity on a toilet."""
    facts = _read("The sofa is in the cabinet. There's the wardrobe on the bed.", "sofa", "cabinet", "wardrobe", "bed")
    assert not [f for f in facts if f.startswith(("on(", "inside("))]


def test_the_realiser_drops_a_placement_the_scene_grammar_rules_out() -> None:
    """A misread fact ("the sofa inside the toy box") cannot be written under the request's
    grammar: the object goes to its typical place instead."""
    brief = {"id": "t", "description": "", "rooms": ["living_room"],
             "roles": {"sofa": {"category": "sofa"}, "toy_box": {"category": "toy_box"},
                       "book": {"category": "book"}, "phone": {"category": "cell_phone"}}}
    choice = realise(brief, ["inside(sofa, toy_box)", "on(phone, book)", "inside(book, toy_box)"], CATALOG)
    assert choice["sofa"].placement == "floor"
    assert choice["phone"].placement != "on:book"
    assert choice["book"].placement == "inside:toy_box"


@pytest.mark.parametrize(("text", "roles", "placed", "left_out"), [
    ("The bedroom has a bed, possibly with a book or a pen on it, along with a nightstand and a desk.",
     ("bed", "book", "pen", "nightstand", "desk"), {"nightstand", "desk", "bed"}, {"book", "pen"}),
    ("The study contains a desk, maybe a laptop or a tablet, and a chair.",
     ("desk", "laptop", "tablet", "chair"), {"desk", "chair"}, {"laptop", "tablet"}),
    ("On the floor: a dirty mark, and possibly a book or a pen.", ("mark", "book", "pen"), {"mark"}, {"book", "pen"}),
])
def test_a_doubt_in_a_list_covers_its_or_chain_only(text: str, roles: tuple[str, ...], placed: set[str],
                                                     left_out: set[str]) -> None:
    subjects = {f.split("(")[1].split(",")[0] for f in _read(text, *roles)}
    assert placed <= subjects and not left_out & subjects


@pytest.mark.parametrize(("text", "roles"), [
    ("The mug should be on the counter.", ("mug", "counter")),
    ("The plate should be in the cabinet; if it isn't, put it there.", ("plate", "cabinet")),
    ("The tablet needs to go on the desk.", ("tablet", "desk")),
    ("Otherwise use the plate, which you then put on the counter.", ("plate", "counter")),
    ("Take the mug, which we then leave on the counter.", ("mug", "counter")),
])
def test_a_norm_a_goal_or_what_someone_does_places_nothing(text: str, roles: tuple[str, ...]) -> None:
    assert not [f for f in _read(text, *roles) if f.startswith(("on(", "inside("))]


def test_a_home_with_other_places_keeps_the_factor_exhaustive() -> None:
    """"The shampoo is kept in the wall cabinet. It has probably been left in the bathtub": where
    it may be is asked (tub or its home), and the home takes every other case, so the responses
    cover every environment; the realiser then puts it in its home unless it is in the tub."""
    from logicenveval.offline.analysis import analyse

    brief = {"id": "t", "rooms": ["bathroom"],
             "description": "The shampoo is kept in the wall cabinet. The shampoo has probably been left in "
                            "the bathtub again - if it has, put it back in the cabinet.",
             "roles": {"shampoo": {"category": "shampoo"}, "wall_cabinet": {"category": "wall_cabinet"},
                       "bathtub": {"category": "bathtub"}}}
    factor = next(f for f in analyse(brief).factors if f.subject == "shampoo")
    assert "elsewhere" not in factor.values
    assert sorted(factor.values.values()) == ["inside(shampoo, bathtub)", "not inside(shampoo, bathtub)"]
    assert realise(brief, ["not inside(shampoo, bathtub)"], CATALOG)["shampoo"].placement == "inside:wall_cabinet"
    assert realise(brief, ["inside(shampoo, bathtub)"], CATALOG)["shampoo"].placement == "inside:bathtub"


@pytest.mark.parametrize(("text", "roles", "facts"), [
    ("The kitchen has a counter: a kettle and a mug on it.", ("counter", "kettle", "mug"),
     {"on(kettle, counter)", "on(mug, counter)"}),
    ("The bedroom has a nightstand - a lamp on it.", ("nightstand", "lamp"), {"on(lamp, nightstand)"}),
    ("The living room has a coffee table: a vase and a newspaper on it.", ("coffee_table", "vase", "newspaper"),
     {"on(vase, coffee_table)", "on(newspaper, coffee_table)"}),
])
def test_a_verbless_list_on_it_after_a_colon_is_on_the_holder_named_before(
        text: str, roles: tuple[str, ...], facts: set[str]) -> None:
    assert facts <= set(_read(text, *roles))


@pytest.mark.parametrize(("text", "roles"), [
    # the owner of a possessive is its head noun, not a noun modifying it
    ("The bookshelf's three levels hold novels, essays and other books respectively.", ("shelf", "book")),
    ("The desk's drawer has a pen in it.", ("desk", "pen")),
    # a bare plural is a kind of thing
    ("The cabinet holds plates and mugs.", ("cabinet", "plate")),
    # a verbless part after a dash goes on with the goal before it
    ("Anything on the floor should go where it belongs - the book on the sofa, the pen on the desk.",
     ("book", "sofa")),
    ("Put things back: the pen on the desk, the book on the sofa.", ("pen", "desk")),
    # a heading naming a thing without a preposition is the thing spoken of, not a place
    ("Two toy boxes: a red one for dolls, a white one for the other toys.", ("wardrobe", "book")),
])
def test_what_only_looks_like_a_placement(text: str, roles: tuple[str, ...]) -> None:
    assert not [f for f in _read(text, *roles) if f.startswith(("on(", "inside("))]


def test_a_list_goes_on_after_along_with() -> None:
    facts = _read("The study has a desk, possibly with a pen or a book on it, along with a chair and a lamp.",
                  "desk", "pen", "book", "chair", "lamp")
    assert {"in_room(desk, study)", "in_room(chair, study)", "in_room(lamp, study)"} <= set(facts)
