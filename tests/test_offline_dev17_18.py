"""Reader rules from the seventeenth and eighteenth development sets (docs/reader.md, "From dev 17
and dev 18"). Each rule is a kind of sentence, tried on sentences written for the test in at least
two registers, with near misses the rule must leave alone; no sentence is copied from the sets."""

from __future__ import annotations

from reading import asks, factors, kinds, named, placed

from logicenveval.offline.sentences import unquote

# -- a ranked part said "of" a piece of furniture heads no list of shelves -------------------------


def test_a_ranked_part_said_of_furniture_heads_no_list() -> None:
    # a holiday-let welcome book: "the next guests" later in the sentence is no second shelf
    text = "The spare remote lives on the top shelf of the bookcase, so please leave it there for the next visitors."
    got = named(text, ("living_room",))
    assert [n for n, (c, _) in got.items() if c == "bookshelf"] == ["bookshelf"]
    # a terse handover note
    text = "Charger: bottom shelf of the bookcase - keep it there for the next shift."
    assert [n for n, (c, _) in named(text, ("office",)).items() if c == "bookshelf"] == ["bookshelf"]


def test_levels_told_apart_by_rank_are_still_shelves_of_their_own() -> None:
    # near miss: a list of ranked levels with no "of <furniture>" still names one shelf per level
    text = "The bookshelf has three levels: novels go on the first level, essays on the second."
    got = named(text, ("study",))
    assert len([n for n, (c, _) in got.items() if c != "bookshelf"]) == 2


# -- a first-person past act of putting says where the thing is ------------------------------------


def test_i_put_reports_where_the_speaker_left_a_thing() -> None:
    # a mother's chat message, without articles
    assert "on(basket, dresser)" in placed("I put basket on top of dresser, the fruit one.", ("bedroom",))
    # a formal handover
    assert "on(vase, sideboard)" in placed("We set the vase on the sideboard before we left.", ("dining_room",))


def test_you_put_or_a_doubted_put_states_no_place() -> None:
    # "you put ..." is an instruction or a generic "you"; "maybe I left" is the task's question
    assert "on(vase, sideboard)" not in placed("You put the vase on the sideboard.", ("dining_room",))
    assert "on(vase, sideboard)" not in placed("Perhaps I put the vase on the sideboard.", ("dining_room",))
    assert "on(vase, sideboard)" not in placed("I'll put the vase on the sideboard.", ("dining_room",))


# -- a name ending in a modal's word is no auxiliary ------------------------------------------------


def test_a_name_ending_in_can_is_no_modal() -> None:
    # a gardener's note and an office memo
    assert "on(watering_can, bench)" in placed("The watering can is on the bench. Fill it if it is empty.",
                                               ("garden_shed",))
    assert "on(watering_can, wall_shelf)" in placed("Our watering can sits on the shelf by the ferns.",
                                                    ("office",))


def test_a_modal_can_still_says_no_place() -> None:
    assert "on(mug, bench)" not in placed("The mug can go on the bench.", ("garden_shed",))


# -- dictated punctuation ---------------------------------------------------------------------------


def test_spoken_marks_of_a_dictated_text_are_marks() -> None:
    # voice typing on a phone
    text = "hi jo comma the watering can is on the bench full stop new paragraph if it's empty fill it full stop"
    assert unquote(text).startswith("hi jo, the watering can is on the bench.")
    assert "on(watering_can, bench)" in placed(text, ("garden_shed",))
    # a dictated memo with question and exclamation marks
    text = "is the heater on question mark if it is comma switch it off exclamation mark thanks full stop"
    assert unquote(text).startswith("is the heater on? If it is, switch it off!")


def test_one_spoken_word_of_punctuation_is_the_texts_own_word() -> None:
    assert unquote("Put a comma after the date. The lamp is on.") == "Put a comma after the date. The lamp is on."
    assert "period" in unquote("After the lunch period, the lamp is on the desk.")


# -- a dropped subject pronoun ----------------------------------------------------------------------


def test_a_condition_with_a_dropped_subject_reads_its_pronoun() -> None:
    # a Spanish speaker's note and a hasty text message
    assert unquote("If is lighted when you arrive, blow it out.").startswith("If it is lighted")
    assert unquote("unless are dry leave them on the line").startswith("unless they are dry")
    assert asks("The candle is on the stool. If is lit when you go up, blow it out.", ("balcony",),
                "state(candle, toggled_on)")


def test_an_existential_question_keeps_its_word_order() -> None:
    assert unquote("If is there a mug, wash it.") == "If is there a mug, wash it."
    assert unquote("If it is open, shut it.") == "If it is open, shut it."


def test_lighted_is_the_state_of_being_lit() -> None:
    # the older participle of "light" (a lighted candle), in a note and in a house manual
    assert asks("The candle is on the stool. If it is lighted, blow it out.", ("balcony",), "state(candle, toggled_on)")
    assert asks("Should the candle on the mantel be lighted, extinguish it.", ("living_room",),
                "state(candle, toggled_on)")


# -- a perfect of moving with "to" says where the thing came to rest -------------------------------


def test_a_perfect_of_moving_to_a_place_is_where_the_thing_is() -> None:
    # a Spanish speaker's note and a nanny's handover
    text = "Blanket: if the wind has thrown it to the floor, hang it on the drying rack."
    assert asks(text, ("balcony",), "on(blanket, floor)")
    text = "If the dog has dragged the cushion to the floor, put it back on the sofa."
    assert asks(text, ("living_room",), "on(sofa_pillow, floor)")
    text = "Should the towel have been blown to the floor, hang it on the drying rack."
    assert asks(text, ("balcony",), "on(towel, floor)")


def test_an_instruction_to_take_a_thing_somewhere_is_still_a_goal() -> None:
    text = "Take the cushion to the sofa."
    assert not asks(text, ("living_room",), "on(sofa_pillow, sofa)")
    assert "sofa_pillow" in kinds(text, ("living_room",))
    assert not asks("If you want to, move the cushion to the sofa.", ("living_room",), "on(sofa_pillow, sofa)")


# -- a list item's label opens its item: the word after it is no given name ------------------------


def test_a_word_after_an_item_label_is_no_given_name() -> None:
    # a safety notice with lettered items, and a numbered chore list
    text = "a) On the desk, next to the tray, stands the kettle. If it is on, switch it off."
    assert asks(text, ("hotel_room",), "state(kettle, toggled_on)")
    text = "Intro.\n2) On the counter, beside the toaster, sits the kettle. If it is on, turn it off."
    assert asks(text, ("kitchen",), "state(kettle, toggled_on)")


def test_a_given_name_in_apposition_still_names_its_thing() -> None:
    text = "First, the princess had to find Lady Rosabel, her doll. If Lady Rosabel had fallen on the floor, put her on the bed."
    assert asks(text, ("bedroom",), "on(doll, floor)")


# -- "the room" in a task of one room, and a finding in it -----------------------------------------


def test_found_in_the_room_asks_whether_the_thing_is_there() -> None:
    # a recall notice and a cleaner's rota
    assert asks("Where a hair dryer is found in the room, put it in the box.", ("hotel_room",), "exists(hair_dryer)")
    assert asks("If a phone charger is found in this room, put it on the desk.", ("office",), "exists(charger)") \
        or asks("If a phone charger is found in this room, put it on the desk.", ("office",), "exists(phone_charger)")


def test_find_any_in_the_named_room_asks_presence_not_the_place_said_before() -> None:
    # a chatbot's answer and a house-sitter's note
    text = "Borrowed the headphones from the hall cupboard? If you find any in the media room, put them in the basket."
    got = factors(text, ("media_room",))
    assert {"exists(headphones)", "not exists(headphones)"} in got.values()
    assert not any("cabinet" in v for values in got.values() for v in values)
    text = "We took a few towels from the linen cupboard. If you find any in this room, hang them on the rail."
    assert asks(text, ("bathroom",), "exists(towel)")


def test_the_room_after_another_word_is_no_task_room() -> None:
    # near miss: "the living room" in a bedroom task names no place of the bedroom
    assert not asks("If the mug is in the living room, bring it to the desk.", ("bedroom",), "exists(mug)")


# -- a participle of situation after an instruction's object ---------------------------------------


def test_a_situation_participle_after_an_object_says_where_it_is() -> None:
    # a residents' notice and a parent's note
    text = "Return any board game found lying on the floor to the bookcase."
    assert asks(text, ("common_room",), "on(board_game, floor)")
    text = "Bring any mug left on the desk to the sink."
    assert asks(text, ("office",), "on(mug, desk)")
    text = "Put any toy found on the sofa in the toy box."
    assert asks(text, ("living_room",), "on(toy, sofa)")


def test_an_instructions_goal_stays_a_goal() -> None:
    # near miss: no participle, the place is where the object goes
    assert not asks("Put the board game back on the bookcase.", ("common_room",), "on(board_game, bookshelf)")


# -- an imperative's object follows it directly ----------------------------------------------------


def test_a_bracket_after_a_state_word_opens_no_instruction() -> None:
    # a residents' notice and a lab rule
    assert asks("Close the curtains, if they have been left open (the caretaker has had complaints).",
                ("common_room",), "state(curtain, open)")
    assert asks("Shut the fridge if it has been left open (the samples spoil otherwise).", ("laboratory",),
                "state(fridge, open)")


def test_a_condition_typed_without_a_comma_still_ends_at_its_instruction() -> None:
    assert asks("if the lamp is still on turn it off", ("bedroom",), "state(floor_lamp, toggled_on)") \
        or asks("if the lamp is still on turn it off", ("bedroom",), "state(lamp, toggled_on)") \
        or any("toggled_on" in v for values in factors("if the lamp is still on turn it off", ("bedroom",)).values()
               for v in values)


# -- verbs of posture before a state, and states of light ------------------------------------------


def test_hang_before_a_state_is_a_copula() -> None:
    # a Gothic tale and a facilities checklist
    assert asks("The wardrobe looms in the corner. Should its door hang open, close it.", ("bedroom",),
                "state(wardrobe, open)")
    assert asks("If the cupboard door hangs open, shut it.", ("kitchen",), "state(cabinet, open)") or any(
        "open)" in v for values in factors("If the cupboard door hangs open, shut it.", ("kitchen",)).values()
        for v in values)


def test_hang_as_an_instruction_is_still_a_goal() -> None:
    assert not asks("Hang the towel on the rail.", ("bathroom",), "on(towel, towel_rack)")


def test_a_glowing_screen_or_lamp_is_on() -> None:
    # a captain's log and a shop's closing list
    assert asks("The computer sits on the desk. If its screen is still glowing, power it down.", ("study",),
                "state(laptop, toggled_on)")
    assert asks("If the desk lamp is glowing when you lock up, switch it off.", ("office",),
                "state(desk_lamp, toggled_on)")


# -- an elliptic state question with a time clause -------------------------------------------------


def test_an_elliptic_state_before_a_time_clause_is_asked() -> None:
    # an Instagram caption and a shift handover
    assert asks("The ceiling fan keeps the air moving. Spinning when you come in? Switch it off.", ("orangery",),
                "state(ceiling_fan, toggled_on)")
    assert asks("The kettle is by the sink. Still running when we get back? Switch it off.", ("kitchen",),
                "state(kettle, toggled_on)")


# -- a home said with the thing's pronoun as subject -----------------------------------------------


def test_it_lives_in_is_a_home_not_where_the_thing_is() -> None:
    # a TV presenter and a kitchen rota: "if we still have one" is still asked
    text = ("The mirror: if it's dirty, clean it. With what? With the microfibre cloth, if we still have one. It "
            "lives in the vanity, so it goes back in there afterwards and you close the vanity. No cloth? Use the "
            "hand towel.")
    assert asks(text, ("bathroom",), "exists(cloth)")
    text = ("The table: if it's sticky, wipe it. With what? With the sponge, if we still have one. It lives in the "
            "cabinet, so it goes back in there afterwards. No sponge? Use a cloth.")
    assert asks(text, ("kitchen",), "exists(sponge)")


# -- a cataphor skips an instrument and the main clause's own pronoun ------------------------------


def test_a_conditions_pronoun_is_not_the_instrument_of_its_main_clause() -> None:
    # parliamentary answers and a cleaning rota
    text = ("The TV screen tends to collect dust. I can give that assurance. If it is dusty, it will be wiped with the "
            "microfibre cloth.")
    assert asks(text, ("living_room",), "state(television, dirty)")
    assert not asks(text, ("living_room",), "state(cloth, dirty)")
    text = "The shelf gathers dust. Noted. If it is dusty, wipe it with the duster."
    assert not any("duster" in v or "cloth" in v for values in factors(text, ("study",)).values() for v in values)


def test_a_cataphor_still_finds_the_thing_its_main_clause_names() -> None:
    assert asks("If it is still on, switch off the lamp on the desk.", ("study",), "state(desk_lamp, toggled_on)") \
        or any("toggled_on" in v and "desk)" not in v
               for values in factors("If it is still on, switch off the lamp on the desk.", ("study",)).values()
               for v in values)


# -- a list said before a dash is no heading; a line that runs on ----------------------------------


def test_a_counted_list_before_a_dash_keeps_its_items() -> None:
    # a sonnet's list with its ranks glossed after a dash, and a plain sentence
    got = named("The bookshelf's three levels hold novels, essays, and all other books - top, middle, bottom.",
                ("bedroom",))
    assert {"novel_shelf", "essay_shelf", "other_shelf"} <= set(got)
    got = named("The rack's three tiers hold mugs, plates, and bowls - top to bottom.", ("kitchen",))
    assert not any(n.startswith(("top", "bottom")) for n in got)


def test_a_heading_before_a_dash_still_opens_its_list() -> None:
    got = named("We have three bins by the back door - one for paper, one for glass, one for cans.", ("kitchen",))
    assert len([c for c, _ in got.values() if c == "trash_can"]) == 3


def test_a_line_that_runs_on_is_one_sentence() -> None:
    # verse and a wrapped form field
    text = "The bookshelf's three levels hold novels, essays, and\nall other books - top, middle, bottom."
    assert {"novel_shelf", "essay_shelf", "other_shelf"} <= set(named(text, ("bedroom",)))
    assert unquote("Clear the desk of the pen, the mug and\nthe phone.") == "Clear the desk of the pen, the mug and the phone."


def test_lines_ending_on_a_content_word_stay_apart() -> None:
    # a list's lines, a chat's messages and a YAML file's keys each end their line
    assert unquote("Shopping:\nmug\nplate\nspoon") == "Shopping:\nmug\nplate\nspoon"
    assert unquote("ok the mug is on the desk\nthe towel is still on the rail") == \
        "ok the mug is on the desk\nthe towel is still on the rail"
    assert unquote("- put the mug in the sink\n- wipe the table") == "- put the mug in the sink\n- wipe the table"


# -- "there is water in it": a filling in the pronoun's container ----------------------------------


def test_a_filling_in_it_says_the_container_is_filled() -> None:
    # courtroom testimony and a kitchen note
    text = "The watering can. Whenever it was empty I filled it at the sink. If there was water in it already, I left it."
    got = factors(text, ("greenhouse",))
    assert {"state(watering_can, filled)", "not state(watering_can, filled)"} in got.values()
    assert not any("exists(watering_can)" in values for values in got.values())
    assert asks("The vase is on the bench. If there is no water in it, fill it at the sink.", ("hallway",),
                "state(vase, filled)")
    # a terse note: the filling alone says it
    assert {"state(bottle, filled)", "not state(bottle, filled)"} in \
        factors("The jug. If there was water in it already, leave it alone.", ("kitchen",)).values()


def test_a_thing_in_it_asks_nothing_of_the_containers_presence() -> None:
    text = "The box is on the shelf. If there is a toy in it, leave it."
    assert not any("exists(box)" in values for values in factors(text, ("bedroom",)).values())
