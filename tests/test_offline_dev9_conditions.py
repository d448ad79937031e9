"""Conditions and factors from the ninth development set (`tests/data/reader_dev9/`) and the
eighth set's tasks that still lost a factor (`tests/data/reader_dev8/`): "wound up" for "ended
up", "ain't got" and "we haven't got one", an inverted "should" after its main clause with no
comma, a verb of becoming in the perfect before a state ("has run empty"), a participle clause set
off by a dash, a bare state before a closing aside in brackets, "if you find it / one" after a
clause that only says the thing was left, and where others habitually leave a thing as where a
condition pointing back asks it may be. Each is tried on the development sentence and on one
written here in another room with other objects."""

from __future__ import annotations

import pytest
from reading import CATALOG, brief
from reading import asks as _asks
from reading import factors as _factors
from reading import placed as _placed

from logicenveval.offline.analysis import analyse
from logicenveval.offline.implied import implied
from logicenveval.offline.sentences import expand


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev9 laundry_sorting_d9 (a Southern US note)
    ("If that detergent bottle has wound up on the floor, put it back on the shelf.", ("laundry_room",),
     "on(laundry_detergent, floor)"),
    # written here: a hallway, a present tense
    ("If the umbrella winds up on the floor again, stand it back in the umbrella stand.", ("hallway",),
     "on(umbrella, floor)"),
])
def test_wound_up_is_ended_up(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"wind up" is "end up" (`analysis.DESCRIPTIVE`, `SITUATION_PARTICIPLES`): where the thing
    wound up is the situation asked."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("said", "meant"), [
    ("or we ain't got one", "or we have not got one"),
    ("if it ain't on", "if it is not on"),
    ("they ain't there", "they are not there"),
    ("if she ain't got any", "if she has not got any"),
])
def test_aint_is_spelled_out_by_its_subject(said: str, meant: str) -> None:
    """"ain't" is "have not" before "got", else the copula its subject takes (`sentences._CONTRACTIONS`)."""
    assert expand(said) == meant


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev9 laundry_sorting_d9
    ("If that detergent bottle has wound up on the floor, put it back on the shelf; if it's anywhere else, "
     "or we ain't got one, just leave it be.", ("laundry_room",), "exists(laundry_detergent)"),
    # written here: a bathroom, "haven't got"
    ("If the soap is on the floor, put it back on the sink; if it's anywhere else, or we haven't got one, "
     "leave it.", ("bathroom",), "exists(soap_bar)"),
])
def test_we_have_not_got_one_asks_whether_there_is_one(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"we haven't got one" puts the negation after "have" ("we have not got"), as "we don't
    have one" puts it before (`analysis._WE_HAVE`): whether the household has the thing."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev9 multi_room_lights_off_d9 (a captain's announcement)
    ("In the bedroom, please turn off the table lamp if it is on, and close the wardrobe should its doors be open.",
     ("bedroom",), "state(wardrobe, open)"),
    # written here: a study, "should anyone have"
    ("Turn the heater off should anyone have left it on.", ("study",), "state(radiator, toggled_on)"),
    # written here: a kitchen, a pronoun subject
    ("Put the lid back on the bin should it be full.", ("kitchen",), "state(trash_can, filled)"),
])
def test_an_inverted_should_after_its_main_clause_is_a_condition(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"close the wardrobe should its doors be open": an inverted "should" (a subject, then "be",
    "have" or "ever" within a few words) opens a condition after its main clause with no comma
    before it (`clauses._LATE_SHOULD`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms"), [
    ("The shirt should be in the hamper.", ("bedroom",)),
    ("Where should the box go?", ("attic",)),
])
def test_a_modal_should_or_a_question_opens_no_condition(text: str, rooms: tuple[str, ...]) -> None:
    """Only the inverted form is a condition: "should be" after its subject is a modal, and "where
    should the box go?" a question."""
    assert _factors(text, rooms) == {}


@pytest.mark.parametrize(("said", "meant"), [
    ("filling the mister at the sink first if it has run empty", "filling the mister at the sink first if it has been empty"),
    ("once the flannel has already got wet", "once the flannel has already been wet"),
    ("the milk has gone off", "the milk has gone off"),  # a particle: no state word
    ("the cat has gone", "the cat has gone"),  # absence, read elsewhere
])
def test_a_verb_of_becoming_in_the_perfect_before_a_state_is_the_copula(said: str, meant: str) -> None:
    """"has run empty", "has gone dry", "has got wet" say the thing is so now (`sentences._BECOME`)."""
    assert expand(said) == meant


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev8 living_room_plant_care_d8 (an agony-aunt column)
    ("Next, the potted plant. If its leaves are dusty, she mists them clean with the plant mister - filling the "
     "mister at the sink first if it has run empty - and afterwards simply sets the mister down next to the plant.",
     ("living_room",), "state(plant_mister, filled)"),
    # written here: a kitchen, a kettle
    ("Fill the kettle at the tap if it has run empty.", ("kitchen",), "state(kettle, filled)"),
])
def test_a_thing_that_has_run_empty_is_asked_whether_it_is_filled(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """The dev sentence also needs its dash read as a comma (below): the mister, not the topic."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition", "not_asked"), [
    # dev8 living_room_plant_care_d8, with the built-in "is empty"
    ("Next, the potted plant. If its leaves are dusty, she mists them clean with the plant mister - filling the "
     "mister at the sink first if it is empty - and afterwards simply sets the mister down next to the plant.",
     ("living_room",), "state(plant_mister, filled)", "state(potted_plant, filled)"),
    # written here: a garden room, a bird bath and a watering can
    ("Then the bird bath. If its water is dirty, rinse it with the watering can - filling the watering can at "
     "the sink first if it is empty.", ("conservatory",), "state(watering_can, filled)", "state(bird_bath, filled)"),
])
def test_a_participle_clause_after_a_dash_is_what_a_later_pronoun_means(
        text: str, rooms: tuple[str, ...], condition: str, not_asked: str) -> None:
    """"... with the plant mister - filling the mister at the sink first if it is empty": a
    participle clause set off by a dash, as by a comma (`analysis._later_object`, `_DASHES`), is
    what the condition after it speaks of, not the topic named before."""
    assert _asks(text, rooms, condition)
    assert not _asks(text, rooms, not_asked)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev8 tack_room_yard_whiteboard (a stables whiteboard)
    ("Before you go:\n * kettle OFF if on (nearly had a fire Sat!!)", ("tack_room",), "state(kettle, toggled_on)"),
    # written here: a living room, a television
    ("Telly off if on (the neighbours complained).", ("living_room",), "state(television, toggled_on)"),
])
def test_a_bare_state_before_an_aside_in_brackets_is_the_things(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"kettle OFF if on (nearly had a fire)": an aside in brackets closing the clause leaves the
    bare state the condition of the thing the instruction acts on (`sentences._ELIDED_END_STATE`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev8 reading_room_porter_round (a night porter's round)
    ("Stop 4 - Carrels. Laptops get left behind. If you find one, lock it in the filing cabinet behind the issue "
     "desk and log it on the lost property sheet.", ("reading_room",), "exists(laptop)"),
    # dev9 hospitality_tent_radio_log (a radio log)
    ("Three, somebody's reported a wallet left in there. If you find it, put it in the lost property basket by "
     "the entrance. Over.", ("hospitality_tent",), "exists(wallet)"),
    # written here: a hallway, umbrellas
    ("Umbrellas get left behind after the meeting. If you find one, put it in the umbrella stand.", ("hallway",),
     "exists(umbrella)"),
])
def test_finding_a_thing_only_said_to_be_left_asks_whether_it_is_there(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"If you find it / one" points back; when the clause it points to says nothing of where or
    how the thing is, only that it was left, what is in doubt is whether it is there
    (`analysis._come_upon`)."""
    assert _asks(text, rooms, condition)


def test_finding_one_after_a_habit_with_a_place_still_asks_the_place() -> None:
    """With a place in the clause pointed to, "if you find one" (no "there") asks that place, as
    "if you find one there" does (`analysis._anaphoric`), not whether there is one."""
    text = "The cushions tend to end up on the floor - if you find one, put it back on the sofa."
    assert _asks(text, ("living_room",), "on(sofa_pillow, floor)")
    assert not _asks(text, ("living_room",), "exists(sofa_pillow)")


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev9 art_room_supply_cover_notes (a teacher's cover notes)
    ("- The Y7s always manage to leave a pair of scissors on the floor. Any you find down there go in the grey "
     "storage box on the side.", ("art_room",), "on(scissors, floor)"),
    # dev8 control_room_studio_booking (a studio booking email)
    ("- The red headphones are the client pair. The band kept dumping them on the floor last night - if they're "
     "still down there, hang them back on the hook by the door.", ("control_room",), "on(red_headphones, floor)"),
    # written here: a hallway, shoes
    ("The kids always leave their shoes on the floor by the door. If you find any there, put them on the shoe rack.",
     ("hallway",), "on(shoe, floor)"),
])
def test_where_others_habitually_leave_a_thing_is_where_it_may_be(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"The band kept dumping them on the floor - if they're still down there, ...": where someone
    other than the reader habitually puts a thing is where a condition pointing back asks it may
    be (`analysis._habit_of_others`), not a goal of the reader's; "down there" is "there"
    (`implied._DIRECTED_THERE`), "if they're still there" points back to the place
    (`analysis._there_named`), and "Any you find there go in ..." is "if you find any there,
    they go in ..." (`implied._ANY_FOUND`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("said", "meant"), [
    ("Any you find down there go in the grey storage box.", "If you find any there, they go in the grey storage box."),
    ("if they're still up there, hang them back", "if they're still there, hang them back"),
])
def test_any_found_there_and_down_there_are_spelled_out(said: str, meant: str) -> None:
    """The factor reader's rewrites of the two forms (`offline.implied`)."""
    assert implied(said) == meant


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev9 wendy_house_pirate_note (a dad's note in pirate speak)
    ("The ship's lantern (that be the torch, ye landlubbers) - if she be still burnin', switch her off, or the "
     "batteries be goin' to Davy Jones.", ("wendy_house",), "state(flashlight, toggled_on)"),
    # written here: a kitchen, a kettle
    ("The old kettle in the kitchen: if she's still on, switch her off.", ("kitchen",), "state(kettle, toggled_on)"),
])
def test_she_in_a_state_only_a_thing_can_be_in_is_the_thing(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"if she be still burning, switch her off": "she" as the subject of an on/open/full state
    is the nearest thing named that can take it, as people speak of a lamp or an engine
    (`analysis._Reader._machine`)."""
    assert _asks(text, rooms, condition)


def test_she_who_acts_is_no_thing() -> None:
    """"Lena thinks she left the desktop on": "she" before a verb is a person; the state is the
    desktop's, asked by the condition that follows."""
    text = "Lena thinks she left the desktop on. If it's still running, shut it down."
    assert set(_factors(text, ("control_room",))) == {"desktop_computer_toggled_on"}


@pytest.mark.parametrize(("text", "rooms", "conditions"), [
    # dev8 multi_room_laundry_collect_d8 (a dad's texts), given an "if"
    ("Bath towel: if dirty, into the laundry basket; if clean but wet, hang it on the towel rack.", ("bathroom",),
     ("state(towel, dirty)", "state(towel, wet)")),
    # written here: a bedroom, a duvet cover
    ("The duvet cover: if clean and dry, fold it onto the shelf; if dirty, into the hamper.", ("bedroom",),
     ("state(blanket, dirty)", "state(blanket, wet)")),
])
def test_an_elliptic_condition_of_two_states_asks_both(
        text: str, rooms: tuple[str, ...], conditions: tuple[str, ...]) -> None:
    """"if clean but wet": each state joined by "and" / "but" in a condition with no subject is
    asked of the topic, not only the first."""
    for condition in conditions:
        assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev8 multi_room_laundry_collect_d8, as written
    ("Bath towel... a dirty one goes in the laundry basket... clean but wet, hang it on the towel rack... clean "
     "and dry, leave it where it is... Love, Dad", ("bathroom",), "state(towel, wet)"),
    # written here: a hallway, an umbrella
    ("The umbrella: dirty and wet, stand it in the umbrella stand. Clean and dry, put it on the hook.", ("hallway",),
     "state(umbrella, wet)"),
])
def test_two_bare_states_before_an_instruction_are_its_case(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"clean but wet, hang it on the towel rack": two bare states joined by "and" / "but" and a
    comma before a verb of putting are one case of the thing spoken of, as one state is
    (`sentences._STATE_CASE`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "thing", "place"), [
    # dev7 vestry_choir_secretary_email, and a written one (`test_offline_compound_heads`)
    ("Put it back in the cardboard box that lives on top of the piano.", ("vestry",), "cardboard_box", "piano"),
    ("Your alarm clock is on top of the dresser.", ("dorm_room",), "alarm_clock", "dresser"),
])
def test_on_top_of_is_on_for_every_reader(text: str, rooms: tuple[str, ...], thing: str, place: str) -> None:
    """"on top of" is read as "on" once, where the text is expanded (`sentences._ON_TOP`), so the
    factor reader, the placement reader and the naming see the same words."""
    assert expand(text) == text.replace("on top of", "on")
    assert f"on({thing}, {place})" in _placed(text, rooms)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev8 laundry_drying_rack_d8 (a bullet journal)
    ("• hang up the laundry\n   – washed shirt should be in the laundry basket in the laundry room\n"
     "   – shirt not in the basket = nothing to do", ("laundry_room",), "inside(shirt, laundry_basket)"),
    # written here: a study, "=" before an instruction
    ("Desk lamp on = switch it off.", ("study",), "state(desk_lamp, toggled_on)"),
    # written here: a kitchen, a door left open
    ("Fridge open = close it.", ("kitchen",), "state(fridge, open)"),
])
def test_a_spaced_equals_sign_is_an_arrow(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"shirt not in the basket = nothing to do": a spaced "=" between a verbless case and its
    answer reads as "->" does (`implied._EQUALS`), and an en dash opening a line is a bullet as
    "-" is (`implied._DASH_BULLET`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition", "not_asked"), [
    # dev8 bakehouse_closing_checklist (a bakery's closing checklist)
    ("2. Bread knife, on the counter by the slicer: if it's dirty, wash it and put it away on the magnetic strip. "
     "3. Unsold loaf left on the counter? It goes in the basket.", ("bakehouse",),
     "state(knife, dirty)", "state(bread, dirty)"),
    # written here: a kitchen, a cereal bowl
    ("Cereal bowl on the table: if it's dirty, wash it. The cereal box goes back in the cabinet.", ("kitchen",),
     "state(bowl, dirty)", "state(cereal_box, dirty)"),
    # written here: a study, a laptop desk
    ("Laptop desk by the window: if it's dusty, wipe it. The laptop goes in the drawer.", ("study",),
     "state(desk, dirty)", "state(laptop, dirty)"),
])
def test_a_things_name_before_anothers_is_the_compounds_modifier(
        text: str, rooms: tuple[str, ...], condition: str, not_asked: str) -> None:
    """"Bread knife ...: if it's dirty": a thing's name right before another's, only a space
    between, is the modifier of a compound whose head is the thing spoken of, so a pronoun after
    it is the knife, not the bread (`analysis._Reader.mentions`)."""
    assert _asks(text, rooms, condition)
    assert not _asks(text, rooms, not_asked)


def test_a_two_word_name_before_a_generic_head_keeps_its_reading() -> None:
    """"Air con unit ........ OFF, if running": a name of two words before "unit" is the thing
    itself, not the modifier of a shelving unit."""
    text = "3. Air con unit ........ OFF, if running\n5. First aid kit ....... The kit stays on the shelving unit."
    assert _asks(text, ("clubhouse",), "state(air_conditioner, toggled_on)")
    assert not _asks(text, ("clubhouse",), "state(shelving_unit, toggled_on)")


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev9 clubhouse_gliding_club_checklist (a challenge / response checklist)
    ("4. Tech log ............ ON BRIEFING DESK. It's the blue binder - if it's been knocked onto the floor again, "
     "pick it up and put it back on the desk", ("clubhouse",), "on(blue_folder, floor)"),
    # written here: a hallway, a backpack
    ("Jo's stuff is on the sofa. It's the blue backpack - if it's been knocked onto the floor, hang it on the hook.",
     ("hallway",), "on(blue_backpack, floor)"),
])
def test_it_is_the_x_says_which_thing_is_spoken_of(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"It's the blue binder - if it's been knocked onto the floor": "it is the X" names the thing
    spoken of, and a pronoun after it is X, not the place named before (`analysis._IDENTIFYING`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev8 granny_flat_neighbour_note (a neighbour's note)
    ("There's been a light on in there every night since Sunday. I think it's the standing lamp by her armchair. "
     "If it is still on, please switch it off, she worries about the bill.", ("granny_flat",),
     "state(floor_lamp, toggled_on)"),
    # written here: a kitchen, a guess with "reckon"
    ("The kettle was making a noise all night. I reckon it's the coffee maker on the counter. If it's still on, "
     "switch it off.", ("kitchen",), "state(coffee_maker, toggled_on)"),
])
def test_a_guess_which_thing_it_is_says_which_thing_is_spoken_of(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"I think it's the standing lamp": a guess before "it is the X" (`analysis._HEDGE_LEADS`)
    still names the thing a later pronoun means."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition", "not_asked"), [
    # dev9 hospitality_tent_radio_log (a radio exchange, the job said again in clipped form)
    ("CONTROL: Wallet. If it's there, lost property basket, by the entrance. Over.", ("hospitality_tent",),
     "exists(wallet)", "exists(basket)"),
    # written here: a hallway, an umbrella
    ("Your umbrella. If it's there, umbrella stand, by the door.", ("hallway",), "exists(umbrella)",
     "exists(umbrella_stand)"),
])
def test_if_its_there_asks_whether_the_thing_is_there(
        text: str, rooms: tuple[str, ...], condition: str, not_asked: str) -> None:
    """"If it's there" is no "if there are any" (`clauses._THING_PRONOUNS`): it asks whether the
    thing its pronoun means is there (`analysis._THERE_ONLY`), not whether the holder named after
    it exists."""
    assert _asks(text, rooms, condition)
    assert not _asks(text, rooms, not_asked)


@pytest.mark.parametrize(("text", "rooms", "condition", "not_asked"), [
    # dev8 kitchen_fridge_restock_d8 (a note on the back of a receipt)
    ("Might be a tomato on the counter too: ripe one → fridge, not ripe yet → fruit bowl.", ("kitchen",),
     "attr(tomato, ripeness, ripe)", ""),
    # written here: a study, a mug
    ("There may be a mug on the desk: dirty one -> sink, clean one -> shelf.", ("study",), "state(mug, dirty)",
     "state(sink, dirty)"),
])
def test_the_cases_of_an_arrow_list_are_told_apart(
        text: str, rooms: tuple[str, ...], condition: str, not_asked: str) -> None:
    """"ripe one -> fridge, not ripe yet -> fruit bowl": a comma before a one-word case and its
    arrow ends the answer before it (`sentences._CASE_AFTER_COMMA`), and a case said as "<adjective>
    one" is "a <adjective> one", the thing spoken of (`implied._BARE_ONE`), not the place named
    just before."""
    assert _asks(text, rooms, condition)
    assert not not_asked or not _asks(text, rooms, not_asked)


@pytest.mark.parametrize(("text", "rooms", "group"), [
    # dev8 multi_room_laundry_collect_d8 (a dad's texts)
    ("Your shirt... if it's clean fold it away in the wardrobe in your bedroom... if it's dirty straight into the "
     "washing machine... unless the machine's already running, then into the hamper... and if the hamper's full, "
     "into the laundry basket instead... Love, Dad", ("bedroom", "laundry_room"),
     ["shirt_dirty", "washing_machine_toggled_on", "hamper_filled"]),
    # written here: a kitchen, a mug
    ("Your mug... if it is dirty into the sink... unless the sink is full, then onto the counter... Love, Mum",
     ("kitchen",), ["mug_dirty", "sink_filled"]),
])
def test_a_trailing_ellipsis_before_a_lower_case_word_goes_on_with_the_sentence(
        text: str, rooms: tuple[str, ...], group: list[str]) -> None:
    """"if it's dirty straight into the washing machine... unless the machine's already running":
    a trailing ellipsis before a lower-case word is a pause, so the conditions after it depend on
    those before it and LogicEnvGen plans their combinations (`analysis._TRAILING`)."""
    assert group in analyse(brief(text, rooms), CATALOG).groups
