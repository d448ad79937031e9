"""Rules from the sixth development set's new tasks (`tests/data/reader_dev6/tasks_new/`): kinds of
sentence that imply a fact or a factor without saying it in the benchmark's words (a regional word,
"make sure it's off", "used the towel?", a relative clause inside a question, a room's name or a
modifier before a place, a purpose after a bare goal, "it" after a plural). Each is tried on the
development sentence and on one written here in another room with other objects."""

from __future__ import annotations

import pytest
from reading import asks as _asks
from reading import brief as _brief
from reading import factors as _factors
from reading import named as _named
from reading import placed as _placed

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.analysis import _ensured, analyse
from logicenveval.offline.placement import described_placements

# ----- naming: a regional word's sense, a dictionary synonym, "it's the red one" ------------------

@pytest.mark.parametrize(("text", "rooms"), [
    # dev6 bach_note_from_kiwi_mate (a New Zealand note)
    ("Sweet as to stay till Sunday arvo. And the sunscreen, if you've left it out on the bench, chuck it "
     "back in the cupboard under the sink.", ("bach",)),
    # written here: an Australian kitchen note
    ("Back this arvo. If the mug is on the bench, pop it in the dishwasher.", ("kitchen",)),
])
def test_a_word_of_a_regional_variety_takes_its_sense_there(text: str, rooms: tuple[str, ...]) -> None:
    """"bench" is a kitchen worktop in Australian and New Zealand English (`REGIONAL_SENSES`),
    named by the word the text uses; without a word of that variety it is a bench."""
    named = _named(text, rooms)
    assert named["bench"][0] == "kitchen_counter"
    assert "bench" in next(iter(_factors(text, rooms)))  # asked of the worktop, under its word
    plain = text.replace("Sweet as to stay till Sunday arvo. ", "").replace("Back this arvo. ", "")
    assert _named(plain, rooms)["bench"][0] == "bench"


@pytest.mark.parametrize(("text", "rooms", "category"), [
    # dev6 bach_note_from_kiwi_mate, games_room_operation_briefing
    ("Sandy jandals on the floor? Biff them in the bucket.", ("bach",), "shoe"),
    ("The jigsaw on the coffee table is a work in progress. Do not touch.", ("games_room",), "puzzle_box"),
    # written here: flip-flops in a hallway, a jigsaw in a study
    ("If the flip-flops are on the doormat, put them on the shoe rack.", ("hallway",), "shoe"),
    ("A half-done jigsaw lies on the desk; leave it there.", ("study",), "puzzle_box"),
])
def test_dictionary_names_of_catalog_kinds(text: str, rooms: tuple[str, ...], category: str) -> None:
    """Catalog synonyms by dictionary sense: "jandal" (New Zealand English) and "flip-flop" are
    shoes, "a jigsaw" a jigsaw puzzle (docs/reader.md, the lexicon)."""
    assert category in {c for c, _ in _named(text, rooms).values()}


@pytest.mark.parametrize(("text", "rooms", "name", "color"), [
    # dev6 bach_note_from_kiwi_mate
    ("Sandy jandals on the floor? Biff them in the bucket. It's the red one by the slider, it stays on the "
     "floor there.", ("bach",), "bucket", "red"),
    # written here: a garage's storage box
    ("Put the drill in the storage box. It's the blue one under the bench.", ("garage",), "storage_box", "blue"),
])
def test_a_predicate_saying_which_one_a_thing_is_gives_its_colour(text: str, rooms: tuple[str, ...],
                                                                   name: str, color: str) -> None:
    assert _named(text, rooms)[name][1] == {"color": color}


# ----- links: "it" after a topic named in the plural ---------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "fact"), [
    # dev6 bach_note_from_kiwi_mate: the bucket, not the jandals
    ("Sandy jandals on the floor? Biff them in the bucket. It's the red one by the slider, it stays on the "
     "floor there.", ("bach",), "on(bucket, floor)"),
    # written here: the towels and the hamper
    ("Wet towels on the floor? Put them in the hamper. It is the blue one, it stays on the floor.",
     ("bathroom",), "on(hamper, floor)"),
])
def test_it_after_a_plural_topic_is_the_nearest_singular_thing(text: str, rooms: tuple[str, ...],
                                                                fact: str) -> None:
    said = {f.condition for c in analyse(_brief(text, rooms), load_catalog()).clauses for f in c.facts}
    assert fact in said


# ----- conditions implied by an instruction or a question ---------------------------------------

@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev6 loft_holiday_let_checkout
    ("* The ceiling fan. Guests nearly always forget this one - please make sure it's switched off before "
     "you leave.", ("loft",), "state(ceiling_fan, toggled_on)"),
    # written here: a study's desk lamp, a garage's door
    ("Before bed, make sure the desk lamp is turned off.", ("study",), "state(desk_lamp, toggled_on)"),
    ("The wardrobe: ensure it is closed.", ("bedroom",), "state(wardrobe, open)"),
])
def test_make_sure_a_thing_is_in_a_state_asks_whether_it_is(text: str, rooms: tuple[str, ...],
                                                            condition: str) -> None:
    """"make sure / ensure / see that X is S" (`analysis._ENSURE`): as "if X is not S, ..."."""
    assert _asks(text, rooms, condition), _factors(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev6 loft_holiday_let_checkout
    ("Used the bath towel? Then pop it in the laundry basket. If you didn't use it, fold it and put it on the "
     "bed.", ("loft",), "state(towel, dirty)"),
    # written here: a kitchen's mug, a study's cloth
    ("Have you used the mug? Put it in the sink.", ("kitchen",), "state(mug, dirty)"),
    ("If you used the cloth, put it in the laundry basket.", ("study",), "state(cloth, dirty)"),
])
def test_that_someone_used_a_thing_says_it_is_dirty(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert _asks(text, rooms, condition), _factors(text, rooms)


def test_using_a_thing_in_an_instruction_says_nothing_of_its_dirt() -> None:
    assert not _asks("Use the cloth to wipe the desk if the desk is dirty.", ("study",), "state(cloth, dirty)")
    # nor using a machine: a used dishwasher is no dirty one
    assert not _asks("If you used the dishwasher, empty it.", ("kitchen",), "state(dishwasher, dirty)")


def test_then_before_an_imperative_keeps_its_goal() -> None:
    """"Used the towel? Then pop it in the basket": the instruction's place is a goal, no place
    the towel is asked about (dev6 loft_holiday_let_checkout; a kitchen written here)."""
    assert not _asks("Used the bath towel? Then pop it in the laundry basket.", ("loft",),
                     "inside(towel, laundry_basket)")
    assert not _asks("Mug dirty? Then pop it in the sink.", ("kitchen",), "inside(mug, sink)")


# ----- placements ----------------------------------------------------------------------------

@pytest.mark.parametrize(("text", "rooms", "placed"), [
    # dev6 loft_holiday_let_checkout
    ("Used the bath towel that was hanging on the towel rail? Then pop it in the laundry basket.", ("loft",),
     "on(towel, towel_rack)"),
    # written here: a kitchen, a bedroom
    ("If the mug that is sitting on the desk is dirty, put it in the sink.", ("kitchen", "study"), "on(mug, desk)"),
    ("Did you read the book that was lying on the nightstand? Put it on the shelf.", ("bedroom",),
     "on(book, nightstand)"),
])
def test_a_relative_clause_of_place_in_a_question_states_the_place(text: str, rooms: tuple[str, ...],
                                                                   placed: str) -> None:
    assert placed in _placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "placed"), [
    # dev6 cloakroom_wedding_run_sheet
    ("The lost-property basket sits on the cloakroom counter.", ("cloakroom", "venue_office"),
     "on(basket, kitchen_counter)"),
    # written here: a bedroom's dresser
    ("The alarm clock is on the bedroom dresser.", ("bedroom", "bathroom"), "on(alarm_clock, dresser)"),
])
def test_a_rooms_name_before_a_place_names_which_one(text: str, rooms: tuple[str, ...], placed: str) -> None:
    assert placed in _placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "placed"), [
    # dev6 green_room_stage_manager_report
    ("- Kettle lives on the props table, as per. Off if it's been left on.", ("green_room",),
     "on(kettle, {table})"),
    # written here: a hallway's wooden box
    ("The keys live in the wooden box, so leave them.", ("hallway",), "inside(keys, {box})"),
])
def test_a_modifier_that_names_nothing_before_a_place_keeps_the_place(text: str, rooms: tuple[str, ...],
                                                                      placed: str) -> None:
    """"on the props table", "in the wooden box": one modifier naming no kind between the article
    and a head noun of several kinds names a thing of one of them (`naming.modified`), and the
    place is that thing (`placement._holder_after`)."""
    brief = _brief(text, rooms)
    holder = next(r for r in brief["roles"] if r.endswith(("table", "box")) and r != "keys")
    assert placed.format(table=holder, box=holder) in described_placements(brief, load_catalog())
    assert not any(len(v) == 2 and "kettle" in k and "table" in k for k, v in _factors(text, rooms).items())


@pytest.mark.parametrize(("text", "rooms", "goal"), [
    # dev6 green_room_stage_manager_report
    ("- Darcy's jacket: check for make-up. Dirty -> laundry basket for wardrobe dept. Clean -> back on the "
     "coat rack.", ("green_room",), "on(jacket, coat_rack)"),
    # written here: a kitchen's tea towel
    ("Towel: dirty -> laundry basket for the wash. Clean -> back on the towel rail.", ("bathroom",),
     "on(towel, towel_rack)"),
])
def test_a_purpose_after_a_bare_goal_names_no_thing_spoken_of(text: str, rooms: tuple[str, ...], goal: str) -> None:
    """"Dirty -> laundry basket for wardrobe dept.": the basket is where the thing goes, and the
    next heading ("Clean ->") is still said of the thing, not of the basket."""
    clauses = analyse(_brief(text, rooms), load_catalog()).clauses
    assert goal in {f.condition for c in clauses for f in c.facts if f.goal}
    assert not any(f.subject == "laundry_basket" and f.kind == "state" for c in clauses for f in c.facts)


@pytest.mark.parametrize(("text", "rooms", "goal"), [
    # dev6 bach_note_from_kiwi_mate (New Zealand English)
    ("Sandy jandals on the floor? Biff them in the bucket.", ("bach",), "inside(shoe, bucket)"),
    # written here: British English in a kitchen
    ("Dirty mug on the desk? Plonk it in the sink.", ("kitchen", "study"), "inside(mug, sink)"),
])
def test_an_informal_verb_of_putting_says_where_the_thing_goes(text: str, rooms: tuple[str, ...], goal: str) -> None:
    """"biff", "plonk", "bung" (`sentences.ACTIONS`): the place after the object is a goal, not a
    place the thing is asked about."""
    clauses = analyse(_brief(text, rooms), load_catalog()).clauses
    assert goal in {f.condition for c in clauses for f in c.facts if f.goal}
    assert not _asks(text, rooms, goal)


def test_it_after_a_plural_topic_taken_up_as_it_stays_the_topic() -> None:
    """dev1 hallway_entry_tidy_r2: the reader's own "it" of a heading ("dry:" read as "it is dry")
    after "Shoes - wet: on the drying rack" is the shoes, not the rack; and a text that takes a
    plural topic up as "it" keeps it (a hallway's and a bedroom's sentences)."""
    text = "Shoes - wet: on the drying rack by the door; dry: on the shoe rack."
    assert not any("drying_rack" in k for k in _factors(text, ("hallway",)))
    said = {f.condition for c in analyse(_brief("Clean sheets are on the bed. Fold it and put it in the wardrobe. "
                                                "It is dirty? Wash it.", ("bedroom",)), load_catalog()).clauses
            for f in c.facts}
    assert not any("wardrobe, dirty" in f for f in said)


def test_make_sure_of_a_place_or_seeing_a_state_asks_no_state() -> None:
    """"make sure the book is on the shelf" says where it goes, "see that the TV is on?" points a
    thing out: neither reads as "if it is not on" (`analysis._ENSURE`)."""
    assert _ensured("Make sure the book is on the shelf.") == "Make sure the book is on the shelf."
    assert _ensured("See that the TV is on? Switch it off.") == "See that the TV is on? Switch it off."
    assert _ensured("Make sure the lamp is off.").startswith("if the lamp is not off")
