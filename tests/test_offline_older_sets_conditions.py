"""Rules for the conditions the older development sets' new tasks lost (docs/reader.md, "Conditions
in older sets' new tasks (eleventh session)"). Every sentence here is written for these tests, in at
least two registers per rule, with near misses that must not be read so."""

from __future__ import annotations

from reading import asks, factors, named, placed

# -- a stranded "on" / "off" is the state of an elided subject -------------------------------------


def test_a_bare_on_or_off_after_if_is_the_topics_switch_state() -> None:
    # a caretaker's terse log, a heading with a colon, a dash and an arrow
    assert asks("Ceiling fan. Staff leave it going. If on -> off.", ("classroom",),
                "state(ceiling_fan, toggled_on)")
    assert asks("Heater: if on, switch it off.", ("office",), "state(radiator, toggled_on)")
    # a chatty note: "if still off", the topic named in the sentence before
    assert asks("The desk lamp is a pain. If still off, turn it on for Gran.", ("study",),
                "state(desk_lamp, toggled_on)")


def test_a_particle_with_an_object_or_a_bare_out_stays_a_place() -> None:
    # "if on the desk" is where the mug is, never whether it is switched on
    values = factors("Mug: if on the desk, put it in the sink.", ("study",))
    assert not any(v.startswith("state(mug, toggled_on)") for vs in values.values() for v in vs)
    # "if out": left out, no switch
    assert not any("toggled_on" in v for vs in factors("The mug. If out, put it away.", ("kitchen",)).values()
                   for v in vs)


# -- a two-word name written closed names the role in a condition too ------------------------------


def test_a_closed_compound_names_the_thing_the_condition_asks_of() -> None:
    # an SMS and a shop's procedure: "aircon" is the air conditioner's "air con" written closed
    assert asks("If the aircon is on, switch it off pls", ("office",), "state(air_conditioner, toggled_on)")
    assert asks("5. Aircon off, if it's still running.", ("office",), "state(air_conditioner, toggled_on)")


# -- a compound's modifier names no thing of its own -----------------------------------------------


def test_a_modifier_naming_another_thing_is_not_that_thing_placed() -> None:
    # a checklist: the bread knife is on the counter, the loaf is not said to be
    text = "Bread knife, on the counter by the slicer. Loaf left on the counter? It goes in the basket."
    assert "on(bread, kitchen_counter)" not in placed(text, ("kitchen",))
    assert "on(knife, kitchen_counter)" in placed(text, ("kitchen",))
    assert asks(text, ("kitchen",), "on(bread, kitchen_counter)")
    # a letter: the coffee mug on the desk, the coffee in the cupboard
    text = "The coffee mug is on the desk, and the coffee is in the cupboard."
    assert "on(mug, desk)" in placed(text, ("office",))


def test_a_verb_after_a_name_is_no_compound_head() -> None:
    # "a lamp stands on it": the lamp stands, no lamp stand
    assert "on(table_lamp, nightstand)" in placed("The bedroom has a nightstand; a lamp stands on it.", ("bedroom",))
    assert "on(vase, wall_shelf)" in placed("Above the sofa hangs a shelf; a vase sits on it.", ("living_room",))


# -- a place said alone is an answer, not a new topic ----------------------------------------------


def test_a_bare_place_answer_leaves_the_topic_for_the_next_pronoun() -> None:
    # a stand-up set: a question, its place answer, then "it"
    text = ("The remote. Where does it live? On the TV stand. If it's lying on the floor, "
            "put it back on the TV stand.")
    assert asks(text, ("living_room",), "on(remote_control, floor)")
    # a house-sitter's note, the answer with an adverb of habit
    text = "Then the mug. Where does it go? In the cupboard, normally. If it's dirty, wash it."
    assert asks(text, ("kitchen",), "state(mug, dirty)")


def test_a_place_with_a_verb_or_a_pronoun_is_no_bare_answer() -> None:
    # "On the shelf sits the vase. If it's dusty ...": a clause with its verb speaks of the vase
    assert asks("On the shelf sits the vase. If it's dusty, wipe it.", ("living_room",), "state(vase, dirty)")


# -- another language's state words and a conditional after a dash ---------------------------------


def test_a_code_switched_condition_asks_its_own_languages_state_word() -> None:
    # Hindi-English: the state word is Hindi, the subject the item's topic
    text = "Tiffin box, the lunch box on the table. Agar ganda hai toh sink mein rakh do."
    assert asks(text, ("kitchen",), "state(lunch_box, dirty)")
    # Spanish-English and Malay-English
    assert asks("The towel, en el suelo. Si está mojado, hang it on the rack.", ("bathroom",), "state(towel, wet)")
    assert asks("The water bottle - kalau kosong, fill it at the sink.", ("kitchen",),
                "state(water_bottle, filled)")


def test_a_conditional_after_a_dash_opens_the_condition() -> None:
    # German-English: "wenn" after a dash; the German "an" of "noch an ist"
    assert asks("Der Ventilator, the ceiling fan - wenn er noch an ist, bitte ausmachen.", ("bedroom",),
                "state(ceiling_fan, toggled_on)")
    assert asks("The desk lamp - wenn es noch on ist, turn it off.", ("study",), "state(desk_lamp, toggled_on)")


def test_an_english_word_in_the_table_is_read_only_before_another_languages_word() -> None:
    # "an" before an English noun is the article, no state
    values = factors("If you find an apple on the floor, put it in the bin.", ("kitchen",))
    assert not any("toggled_on" in v for vs in values.values() for v in vs)


# -- a light said before its switch's whole name is the switch -------------------------------------


def test_the_lights_before_the_light_switch_are_the_switch() -> None:
    # a quest log and a club's closing notice: the condition asks the switch the instruction flicks
    assert asks("If the lights are still on, flick the light switch off.", ("studio",),
                "state(light_switch, toggled_on)")
    assert asks("Last out? The light may be on - if so, press the light switch by the door.", ("hall",),
                "state(light_switch, toggled_on)")


def test_a_lamp_named_for_itself_stays_a_lamp_beside_the_switch() -> None:
    values = factors("If the lamp is on, turn it off at the light switch.", ("study",))
    assert not any("light_switch" in v for vs in values.values() for v in vs)


def test_a_switching_verb_after_the_light_is_no_switch() -> None:
    # a numbered notice and a text message: the verb opening the next item is no light switch
    text = "The neighbours mind the light.\n3. Switch off the ceiling fan should it still be spinning."
    assert asks(text, ("hall",), "state(ceiling_fan, toggled_on)")
    assert "light_switch" not in {c for c, _ in named(text, ("hall",)).values()}
    text = "sorry about the light!! switch off the telly if its still on x"
    assert "light_switch" not in {c for c, _ in named(text, ("hall",)).values()}
