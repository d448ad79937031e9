"""Naming and placement rules from the seventh development set's new tasks (docs/reader.md, "Naming"
and "Placements"): the head of an English noun compound, a reading's label, which one a thing
is by its colour, parts of furniture said "of" it, relative clauses of place in an instruction,
"on top of". Each rule is tried on a development sentence and on one written for the test in
another room with other objects; each test fails without its rule."""

from __future__ import annotations

from reading import factors, kinds, named, placed

# -- the head of a noun compound is its last noun --------------------------------------------------


def test_the_last_noun_of_a_compound_is_its_head() -> None:
    # dev 7 (a museum checklist, a yacht's log): "collection" and "table" name a kind only as the
    # head of a longer name ("essay collection", "bedside table"); before a noun they modify it
    assert kinds("Audio guide headphones left on the bench: into the collection basket by the door",
                 ("gallery",)) == {"headphones", "bench", "basket"}
    assert kinds("Torch found on the port bunk again. Belongs in the chart table drawer; if on bunk, stow it there.",
                 ("cabin",)) == {"flashlight", "bunk_bed", "drawer"}
    # written for the test
    assert kinds("Put the pens in the table drawer.") == {"pen", "drawer"}
    # (a box named for its use is a storage box since the twenty-seventh session: `naming.HEAD_SENSES`;
    # this test reads the head, whichever sort of box it is)
    assert kinds("Drop the coins in the collection box by the door.", ("hall",)) == {"storage_box"}


def test_a_name_of_its_own_before_a_generic_head_stays_the_thing() -> None:
    assert kinds("Tidy the towel into the vanity cabinet.", ("bathroom",)) == {"towel", "bathroom_vanity"}
    # the drawer of a piece named with it is its part ("the dresser drawers")
    assert kinds("Should the dresser drawers be open, close them. Open drawers are a fail.",
                 ("dorm_room",)) == {"dresser"}


def test_a_state_after_a_place_without_an_article_is_the_things() -> None:
    # dev 7: "Desk lamp over chart table left on" asks whether the lamp is on
    assert set(factors("- Desk lamp over chart table left on last night - batteries low. Check, OFF if on.",
                       ("cabin",))) == {"desk_lamp_toggled_on"}
    # written for the test: the sink is a place, not the thing left on
    assert set(factors("Kettle beside sink still on? Switch it off.", ("kitchen",))) == {"kettle_toggled_on"}
    assert set(factors("Is the kettle beside the sink still on? Switch it off.", ("kitchen",))) == {
        "kettle_toggled_on"}


# -- a reading's label -----------------------------------------------------------------------------


def test_a_word_and_a_number_alone_are_a_reading_not_a_thing() -> None:
    # dev 7: "bar 1016" is the barometer, no soap bar
    assert "soap_bar" not in kinds("Sat 0700  Slipped, Hamble. Wind SW 3, bar 1016, vis good.", ("cabin",))
    # written for the test: a clock's time read off in a weather note
    assert kinds("Weather at noon: wind NW 4, clock 0815, temp 14.", ("porch",)) == set()


def test_a_numbered_thing_is_still_a_thing() -> None:
    assert kinds("Put the jar in drawer 3.") == {"drawer"}
    assert kinds("Make up tonight: bed 2, bed 5.", ("dormitory",)) == {"bed"}


# -- which one a thing is, by its colour -----------------------------------------------------------


def test_a_bracket_saying_which_one_gives_its_colour() -> None:
    # dev 7: "(the grey plastic one)": the catalog spells it "gray"
    assert named("into the collection basket by the door (the grey plastic one)", ("gallery",))["basket"] == (
        "basket", {"color": "gray"})
    # written for the test
    assert named("Put the towels in the laundry basket by the stairs (the blue wicker one).")[
        "laundry_basket"] == ("laundry_basket", {"color": "blue"})
    assert named("Stand it in the bucket (the red one by the tap).")["bucket"] == ("bucket", {"color": "red"})
    # a bracket that is a clause of its own says no more of the thing
    assert named("Put the mug in the bucket (the red one is mine).")["bucket"] == ("bucket", {})


def test_a_colour_before_a_modifier_naming_nothing_is_the_heads() -> None:
    # dev 7: "The black music folders"
    text = ("The black music folders do tend to end up on the floor under the chairs - if you find one "
            "there, would you put it back in the cardboard box?")
    assert ("folder", {"color": "black"}) in named(text, ("vestry",)).values()
    # written for the test
    assert named("The red plastic bucket is by the door.") == {"red_bucket": ("bucket", {"color": "red"})}


def test_the_british_spelling_of_a_colour_is_the_catalogs() -> None:
    assert named("A grey basket sits on the bench.")["gray_basket"] == ("basket", {"color": "gray"})


# -- parts of furniture said "of" it ---------------------------------------------------------------


def test_a_part_said_of_a_piece_of_furniture_names_that_piece() -> None:
    # dev 7: a rack with shelves, for no use the text says (not a pantry's, not for shoes)
    text = "Developer kept in the brown bottle on the lower shelf of the metal rack; never on the counter."
    assert kinds(text, ("darkroom",)) == {"bottle", "utility_shelf", "kitchen_counter"}
    assert placed(text, ("darkroom",)) == {"on(brown_bottle, utility_shelf)"}
    # written for the test
    assert kinds("The spray bottle is on the lower shelf of the rack.") == {"spray_bottle", "utility_shelf"}
    text = "The first aid kit lives on the top shelf of the bookcase."
    assert kinds(text) == {"first_aid_kit", "bookshelf"}
    assert placed(text, ("studio",)) == {"on(first_aid_kit, bookshelf)"}
    # the part is inside a piece that holds things inside, whatever the preposition
    assert placed("The spray bottle is on the lower shelf of the wardrobe.", ("bedroom",)) == {
        "inside(spray_bottle, wardrobe)"}
    assert placed("Check the spray bottle on the lower shelf of the wardrobe.", ("bedroom",)) == {
        "inside(spray_bottle, wardrobe)"}
    text = "The sock is in the top drawer of the dresser."
    assert kinds(text, ("bedroom",)) == {"sock", "dresser"}
    assert placed(text, ("bedroom",)) == {"inside(sock, dresser)"}


# -- relative clauses of place, "on top of" --------------------------------------------------------


def test_a_relative_clause_of_place_in_an_instruction_states_the_place() -> None:
    # dev 7 (a choir secretary's email): a home, said in a request
    text = ("if you find one there, would you put it back in the cardboard box that lives on top of the "
            "piano?")
    assert placed(text, ("vestry",)) == {"on(cardboard_box, piano)"}
    # written for the test
    assert placed("Put the pen back in the mug that sits on the desk.", ("study",)) == {"on(mug, desk)"}


def test_the_subject_of_a_relative_clause_of_keeping_is_the_thing_before_it() -> None:
    assert placed("Fold the blanket into the basket which is kept on the shelving unit.", ("studio",)) == {
        "on(basket, shelving_unit)"}
    assert placed("Stand the umbrella in the bucket that is kept in the hallway.", ("hallway",)) == {
        "in_room(bucket, hallway)"}


def test_on_top_of_is_on() -> None:
    assert placed("The cardboard box is on top of the piano.", ("vestry",)) == {"on(cardboard_box, piano)"}
    assert placed("Your alarm clock is on top of the dresser.", ("dorm_room",)) == {"on(alarm_clock, dresser)"}


# -- from dev 7's rewordings -----------------------------------------------------------------------


def test_and_or_is_the_inclusive_or() -> None:
    # dev 7 (a babysitting job sheet)
    assert set(factors("A sofa pillow and/or a toy may be on the floor.", ("living_room",))) == {
        "sofa_pillow_on_floor", "toy_on_floor"}
    # written for the test
    assert set(factors("A mug and/or a plate might be on the desk.", ("study",))) == {"mug_on_desk", "plate_on_desk"}


def test_a_place_before_an_arrow_is_the_situation_its_instruction_answers() -> None:
    # dev 7: "Pillow on the floor -> back on the sofa." states nothing: it asks
    text = "Tasks:\n1. Pillow on the floor -> back on the sofa."
    assert placed(text, ("living_room",)) == set()
    assert set(factors(text, ("living_room",))) == {"pillow_on_floor"}
    # written for the test
    assert placed("Mug on the desk -> into the sink.", ("study",)) == set()


def test_bare_singular_headings_sorting_by_kind_are_classes() -> None:
    # dev 7 (a hotel's turndown card): "Novel:" is a kind of book, no novel of its own
    text = ("Nightstand: a book may be on the nightstand. Novel: to the bookshelf. Textbook: to the desk. "
            "Any other book: into the nightstand drawer.")
    assert "novel" not in kinds(text, ("bedroom",))
    assert factors(text, ("bedroom",))["book_kind"] == {
        "attr(book, kind, novel)", "attr(book, kind, textbook)",
        "not attr(book, kind, novel) and not attr(book, kind, textbook)"}
    # written for the test
    text = "Toy on the floor? Doll: into the red toy box. Ball: into the basket. Any other toy: into the green toy box."
    assert kinds(text, ("kids_room",)) == {"toy", "toy_box", "basket"}
