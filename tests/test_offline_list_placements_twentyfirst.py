"""Placements given as lists, read since the twenty-first session (docs/reader.md, "Places as
headings, ticked lists and a thing's activity (twenty-first session)"): forms "What it still misreads" listed as left
("Contents, counter: 2 x mugs"; "On display on the counter: a mug"; an unticked box's item read as
placed) and their family in ordinary English. Each structure is a table of sentences written here
in several registers (an inventory, a packing list, a lost-property list, a museum label, an
inspection note, a hotel housekeeping sheet, a text message, a learner's note), rooms and kinds,
with near misses; every table was measured on main before the rule (counts in each table's comment).
The placements are read with the offline model's own naming (`reading.placed`).

- a holder's bare name heading a list of things ("DESK: laptop, desk lamp", "Fridge: milk, two
  apples"), also after a document's label ("Contents, counter: 2 x mugs", "Room 12 - Nightstand:
  ..."): the things are on or in the holder;
- a participle of where a thing is, or "on display", before a heading's place ("Found on the floor:
  a sock", "On display in the cabinet: a vase", "Noted on the desk: a cup"): the things are there;
- a box after an item's label mark ("Mug - [x] on the counter", "Lamp: [ ] on the desk"): ticked,
  the line holds; unticked, it states nothing."""

from __future__ import annotations

import pytest
from reading import placed

#: a holder's bare name before a list of things: (text, rooms, placements it states). Before the
#: rule 0 of 22 were read, after 17 of 22 (`HOLDER_HEADINGS_LEFT` are the five left)
HOLDER_HEADINGS = [
    # a landlord's check-in inventory
    ("INVENTORY\nDESK: laptop, desk lamp.\nBED: pillow, blanket.", ("bedroom",),
     {"on(laptop, desk)", "on(desk_lamp, desk)", "on(pillow, bed)", "on(blanket, bed)"}),
    ("Kitchen counter: kettle, toaster, 2 x mugs.", ("kitchen",),
     {"on(kettle, kitchen_counter)", "on(toaster, kitchen_counter)", "on(mug, kitchen_counter)"}),
    # a holiday let's welcome book
    ("What you will find. Coffee table: the remote and a book. Sofa: two cushions.", ("living_room",),
     {"on(remote_control, coffee_table)", "on(book, coffee_table)"}),
    # a removals list
    ("Box 3 contents -> bin: none. Laundry basket: towel, sock.", ("laundry_room",),
     {"inside(towel, laundry_basket)", "inside(sock, laundry_basket)"}),
    # a stage manager's props preset
    ("PROPS PRESET\nSide table: a candle, the red book.\nArmchair: a cushion.", ("living_room",),
     {"on(candle, side_table)", "on(red_book, side_table)"}),
    # text messages
    ("desk: laptop + charger. if the laptop is on switch it off pls", ("office",), {"on(laptop, desk)"}),
    ("shelf: the teddy, the board game. bed: pillow", ("kids_room",),
     {"on(teddy_bear, wall_shelf)", "on(board_game, wall_shelf)", "on(pillow, bed)"}),
    # a learner's note
    ("In your room. Table: the lamp and the vase. If the lamp is on, you switch off.", ("bedroom",),
     {"on(table_lamp, side_table)", "on(vase, side_table)"}),
    # a lab bench list
    ("Bench: the beaker, a notebook. Sink: a sponge.", ("lab",), {"inside(sponge, sink)"}),
    # a house-sitter's notes
    ("Drawer: keys, scissors.", ("office",), {"inside(keys, drawer)", "inside(scissors, drawer)"}),
    ("Dining table: plate, bowl, a blue mug.", ("dining_room",),
     {"on(plate, dining_table)", "on(bowl, dining_table)", "on(blue_mug, dining_table)"}),
    ("Sink: dirty pan. Stove: kettle.", ("kitchen",), {"on(kettle, stove)"}),
    ("TV stand: the remote. Sofa: a pillow.", ("living_room",),
     {"on(remote_control, tv_stand)", "on(pillow, sofa)"}),
    ("Toy box: doll, toy car.", ("kids_room",), {"inside(doll, toy_box)", "inside(toy_car, toy_box)"}),
    ("Coat rack: my hat and my scarf.", ("hallway",), {"on(hat, coat_rack)", "on(scarf, coat_rack)"}),
    ("Bookshelf: three books, a candle.", ("living_room",), {"on(book, bookshelf)", "on(candle, bookshelf)"}),
    ("Bedside table: glasses, phone, a book.", ("bedroom",),
     {"on(cell_phone, nightstand)", "on(book, nightstand)"}),
    # a document's label before the holder (the placement grid's "Contents, counter: 2 x mugs")
    ("Contents, counter: 2 x mugs.", ("kitchen",), {"on(mug, kitchen_counter)"}),
]

#: left: a heading line with no mark of its own runs into the holder ("Moving day list\nWardrobe:"),
#: a list word the catalog does not name ("butter", "glasses case"), a room word before the holder
#: ("Bathroom shelf": two heads), a holder the catalog lacks ("Windowsill")
HOLDER_HEADINGS_LEFT = [
    ("Moving day list\nWardrobe: jacket, scarf\nNightstand: alarm clock", ("bedroom",), "inside(jacket, wardrobe)"),
    ("Room 12 - Nightstand: phone, glasses case. Luggage rack: suitcase.", ("bedroom",), "on(cell_phone, nightstand)"),
    ("Fridge: milk, butter, two apples.", ("kitchen",), "inside(apple, fridge)"),
    ("Bathroom shelf: shampoo, soap, a towel.", ("bathroom",), "on(towel, wall_shelf)"),
    ("Windowsill: the plant, the watering can.", ("living_room",), "on(watering_can, windowsill)"),
]


@pytest.mark.parametrize(("text", "rooms", "facts"), HOLDER_HEADINGS)
def test_a_holders_bare_name_heads_the_things_on_it(text: str, rooms: tuple[str, ...], facts: set[str]) -> None:
    assert facts <= placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), HOLDER_HEADINGS_LEFT)
def test_holder_headings_left(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact not in placed(text, rooms)


#: near misses: the heading is the thing spoken of, or its body says more than a list of things:
#: (text, rooms, the heading's holder, on or in which nothing may be placed). All held before
HOLDER_NEAR_MISSES = [
    ("Plate: clean - into the cabinet; dirty - into the dishwasher.", ("kitchen",), "plate"),
    ("Lamp: switch it off.", ("bedroom",), "desk_lamp"),
    ("Bed: pillow on the floor? put it back.", ("bedroom",), "bed"),
    ("Desk: tidy it, then wipe it with the cloth.", ("office",), "desk"),
    ("Fridge: put the milk in.", ("kitchen",), "fridge"),
    ("Sink: if the mug is dirty, wash it.", ("kitchen",), "sink"),
    ("Counter: maybe a mug.", ("kitchen",), "kitchen_counter"),
    ("Laptop: the charger is in the drawer.", ("office",), "laptop"),
    ("Desk: no laptop, no lamp.", ("office",), "desk"),
    ("If dirty, sink: the mug.", ("kitchen",), "sink"),
]


@pytest.mark.parametrize(("text", "rooms", "holder"), HOLDER_NEAR_MISSES)
def test_a_heading_that_is_no_holders_list_places_nothing_there(text: str, rooms: tuple[str, ...],
                                                                 holder: str) -> None:
    assert not any(f.endswith(f", {holder})") for f in placed(text, rooms))


#: a participle of where a thing is, or "on display", before a heading's place: (text, rooms,
#: placements it states). Before the rule 0 of 22 were read, after 21 of 22 (the learner's "on
#: table in kitchen", with no article, is left: `PARTICIPLE_HEADINGS_LEFT`)
PARTICIPLE_HEADINGS = [
    # a lost-property list
    ("LOST PROPERTY, Sunday\nFound on the floor: a sock, a book.", ("living_room",),
     {"on(sock, floor)", "on(book, floor)"}),
    ("Found on the sofa: the remote and a pillow. Found in the basket: a scarf.", ("living_room",),
     {"on(remote_control, sofa)", "on(pillow, sofa)", "inside(scarf, basket)"}),
    # museum labels
    ("GALLERY 3\nOn display on the bookshelf: a vase, a candle.", ("living_room",),
     {"on(vase, bookshelf)", "on(candle, bookshelf)"}),
    ("On display in the cabinet: a vase (Delft, about 1700).", ("dining_room",), {"inside(vase, cabinet)"}),
    ("On show on the side table: the red book.", ("living_room",), {"on(red_book, side_table)"}),
    ("On view on the dresser: a candle and a teddy bear, both about 1920.", ("bedroom",),
     {"on(candle, dresser)", "on(teddy_bear, dresser)"}),
    # inspection and audit notes
    ("Inspection 12/3. Noted on the desk: a cup, a laptop. Action: none.", ("office",),
     {"on(cup, desk)", "on(laptop, desk)"}),
    ("Observed on the counter: two mugs and the kettle.", ("kitchen",),
     {"on(mug, kitchen_counter)", "on(kettle, kitchen_counter)"}),
    ("Recorded in the sink: a plate, a bowl.", ("kitchen",), {"inside(plate, sink)", "inside(bowl, sink)"}),
    # a hotel housekeeping sheet
    ("Room 4. Left on the bed: a towel and a pillow. Please check.", ("bedroom",),
     {"on(towel, bed)", "on(pillow, bed)"}),
    ("Left in the wardrobe: a jacket.", ("bedroom",), {"inside(jacket, wardrobe)"}),
    # an evidence log and a formal inventory
    ("Item log. Found on the coffee table: the phone, the wallet.", ("living_room",),
     {"on(cell_phone, coffee_table)", "on(wallet, coffee_table)"}),
    ("Located on the nightstand: an alarm clock.", ("bedroom",), {"on(alarm_clock, nightstand)"}),
    ("Positioned on the desk: a desk lamp, a laptop.", ("office",), {"on(desk_lamp, desk)", "on(laptop, desk)"}),
    ("Situated on the dining table: a bowl and a plate.", ("dining_room",),
     {"on(bowl, dining_table)", "on(plate, dining_table)"}),
    ("Mounted on the wall shelf: a clock.", ("living_room",), {"on(wall_clock, wall_shelf)"}),
    # a text message and notes
    ("found on the floor: ur scarf and a sock lol", ("hallway",), {"on(scarf, floor)", "on(sock, floor)"}),
    ("Stashed in the drawer: the keys and the phone.", ("bedroom",),
     {"inside(keys, drawer)", "inside(cell_phone, drawer)"}),
    ("Tucked in the basket: a towel.", ("bathroom",), {"inside(towel, basket)"}),
    ("Hidden in the toy box: a doll.", ("kids_room",), {"inside(doll, toy_box)"}),
    ("Spotted on the armchair: a blanket.", ("living_room",), {"on(blanket, armchair)"}),
]

PARTICIPLE_HEADINGS_LEFT = [
    ("Left on table in kitchen: the kettle.", ("kitchen",), "kettle"),
]


@pytest.mark.parametrize(("text", "rooms", "facts"), PARTICIPLE_HEADINGS)
def test_a_participle_before_a_headings_place_states_the_list_there(text: str, rooms: tuple[str, ...],
                                                                     facts: set[str]) -> None:
    assert facts <= placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "thing"), PARTICIPLE_HEADINGS_LEFT)
def test_participle_headings_left(text: str, rooms: tuple[str, ...], thing: str) -> None:
    assert not any(f.startswith(("on(" + thing, "inside(" + thing)) for f in placed(text, rooms))


#: near misses: a base form that may be an instruction ("Put", "Set", "Place"), a participle of
#: wanting, a negation, a norm, where things belong ("Kept in"), a condition, an absence: (text,
#: rooms, the holder nothing may be placed at). All held before
PARTICIPLE_NEAR_MISSES = [
    ("Put on the counter: a mug.", ("kitchen",), "kitchen_counter"),
    ("Set on the counter: a mug.", ("kitchen",), "kitchen_counter"),
    ("Place on the desk: a lamp, a laptop.", ("office",), "desk"),
    ("Wanted on the desk: a lamp.", ("office",), "desk"),
    ("Needed in the kitchen sink: a plate.", ("kitchen",), "sink"),
    ("Not found on the desk: the laptop.", ("office",), "desk"),
    ("To be left on the bed: a towel.", ("bedroom",), "bed"),
    ("Kept in the drawer: keys, scissors.", ("office",), "drawer"),
    ("Found on the floor: if a sock, put it in the basket.", ("bedroom",), "floor"),
    ("Missing from the shelf: the vase.", ("living_room",), "wall_shelf"),
]


@pytest.mark.parametrize(("text", "rooms", "holder"), PARTICIPLE_NEAR_MISSES)
def test_a_heading_of_no_participle_of_place_places_nothing(text: str, rooms: tuple[str, ...],
                                                            holder: str) -> None:
    assert not any(f.endswith(f", {holder})") for f in placed(text, rooms))


#: a box after an item's label mark, ticked: (text, rooms, placements it states). Before the rule
#: 2 of 20 were read, after 14 of 20 (`LABELLED_TICKS_LEFT`: the same lines without a box are not
#: read either)
LABELLED_TICKS = [
    # a cleaner's checklist
    ("Checklist.\nMug - [x] on the counter\nKettle - [x] on the stove", ("kitchen",),
     {"on(mug, kitchen_counter)", "on(kettle, stove)"}),
    ("Laptop: [x] on the desk.", ("office",), {"on(laptop, desk)"}),
    ("Laptop: \u2713 on the desk.", ("office",), {"on(laptop, desk)"}),
    ("Book \u2013 [X] on the shelf.", ("living_room",), {"on(book, bookshelf)"}),
    # a hotel housekeeping form
    ("Room 7 check.\nPillow: [x] on the bed.\nTowel: [x] on the rail.", ("bedroom",), {"on(pillow, bed)"}),
    ("Alarm clock: \u2611 on the nightstand.", ("bedroom",), {"on(alarm_clock, nightstand)"}),
    # a museum invigilator's closing list
    ("Vase - [x] on the side table. Candle - [x] on the dresser.", ("gallery",),
     {"on(vase, side_table)", "on(candle, dresser)"}),
    # a packing list
    ("Scarf - [x] in the basket", ("hallway",), {"inside(scarf, basket)"}),
    # text messages
    ("phone - [x] on the dining table lol", ("dining_room",), {"on(cell_phone, dining_table)"}),
    # learner's notes
    ("Teddy bear: [x] on the bed. Doll: [x] in the toy box.", ("kids_room",),
     {"on(teddy_bear, bed)", "inside(doll, toy_box)"}),
    ("The plate: [x] in the sink. The bowl: [x] in the sink.", ("kitchen",),
     {"inside(plate, sink)", "inside(bowl, sink)"}),
    ("My mug - [x] on the desk", ("office",), {"on(mug, desk)"}),
    ("Apple: [x] in the fridge. Milk: [x] in the fridge.", ("kitchen",),
     {"inside(apple, fridge)", "inside(milk_carton, fridge)"}),
    ("Sponge - [x] in the sink", ("kitchen",), {"inside(sponge, sink)"}),
    ("Notebook: [x] on the bookshelf", ("study",), {"on(notebook, bookshelf)"}),
]

LABELLED_TICKS_LEFT = [
    ("Remote \u2014 [x] on the TV stand.", ("living_room",), "on(remote_control, tv_stand)"),
    ("Hair dryer: \u2714 in the drawer.", ("bedroom",), "inside(hair_dryer, drawer)"),
    ("Keys: [x] in the bowl. Wallet: [x] in the drawer.", ("hallway",), "inside(keys, bowl)"),
    ("laptop: [x] on the desk, lamp: [x] on the desk", ("office",), "on(laptop, desk)"),
    ("Watering can: [x] on the floor", ("living_room",), "on(watering_can, floor)"),
]


@pytest.mark.parametrize(("text", "rooms", "facts"), LABELLED_TICKS)
def test_a_ticked_box_after_a_label_states_the_line(text: str, rooms: tuple[str, ...], facts: set[str]) -> None:
    assert facts <= placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "fact"), LABELLED_TICKS_LEFT)
def test_labelled_ticks_left(text: str, rooms: tuple[str, ...], fact: str) -> None:
    assert fact not in placed(text, rooms)


#: near misses: an unticked box says the line does not hold (yet), a ticked box before an
#: instruction, a condition or a negation: (text, rooms, the holder nothing may be placed at).
#: Before the rule 4 of 8 were read as placements (every unticked line), after none
LABELLED_TICK_NEAR_MISSES = [
    ("Lamp: [ ] on the desk", ("office",), "desk"),
    ("Mug - [ ] on the counter", ("kitchen",), "kitchen_counter"),
    ("Pillow: \u2610 on the bed", ("bedroom",), "bed"),
    ("Towel: [ ] in the basket. Sock: [ ] in the drawer.", ("bedroom",), "drawer"),
    ("Keys: [ ] in the bowl", ("hallway",), "bowl"),
    ("Book - [x] put it on the shelf tomorrow", ("living_room",), "wall_shelf"),
    ("Mug: [x] if dirty, in the sink", ("kitchen",), "sink"),
    ("Laptop: [x] not on the desk", ("office",), "desk"),
]


@pytest.mark.parametrize(("text", "rooms", "holder"), LABELLED_TICK_NEAR_MISSES)
def test_an_unticked_box_states_nothing(text: str, rooms: tuple[str, ...], holder: str) -> None:
    assert not any(f.endswith(f", {holder})") for f in placed(text, rooms))


def test_an_en_or_em_dash_ends_a_label_as_a_hyphen_does() -> None:
    """" — " and " – " set off by spaces are the label's dash (`placement._DASHES`): before, "Mug —
    on the counter" placed nothing while "Mug - on the counter" was read."""
    for dash in ("-", "\u2013", "\u2014"):
        assert placed(f"Mug {dash} on the counter. Kettle {dash} on the stove.", ("kitchen",)) >= {
            "on(mug, kitchen_counter)", "on(kettle, stove)"}
    assert not placed("The mug\u2014the blue one\u2014is clean.", ("kitchen",)) & {"on(mug, kitchen_counter)"}
