"""Conditions in code-switched text (English mixed with another language) from the tenth and
eleventh development sets (`tests/data/reader_dev10/`, `tests/data/reader_dev11/`), and the kinds
of sentence the reworded tasks of those sets lost. Each rule is tried on a development sentence
and on one written here in another language, room or register, and, where it must not fire, on a
near miss."""

from __future__ import annotations

import pytest
from reading import asks as _asks
from reading import factors as _factors

from logicenveval.offline.sentences import foreign, unquote


@pytest.mark.parametrize(("said", "meant"), [
    # dev11 barsati_hinglish_note (Hindi-Urdu "agar ... toh")
    ("Agar abhi bhi on hai toh band kar dena.", "If abhi bhi on hai, then band kar dena."),
    # dev6 kitchen_fridge_restock_d6 (Spanish "si no")
    ("la puerta might already be open, si no, you open it", "la puerta might already be open, if not, you open it"),
    # written here: German "wenn ... dann", Tagalog "kung", Malay "kalau"
    ("Wenn the heater is still on, dann switch it off.", "If the heater is still on, then switch it off."),
    ("Kung marumi pa, wash it.", "If marumi pa, wash it."),
    ("kalau the kettle is empty, fill it.", "if the kettle is empty, fill it."),
])
def test_another_languages_conditional_conjunction_is_if(said: str, meant: str) -> None:
    """A conditional conjunction of another language (`sentences.NATIVE_IF`) opens a condition
    as "if" does, its "then" word answering it as ", then"; "si no" is "if not"."""
    assert unquote(said) == meant


@pytest.mark.parametrize("said", [
    "Agar plates go in the incubator.",  # "agar", an English noun too, in an English sentence
    "Agar plates go in the fridge.",  # one word lemminflect does not list ("fridge") is no language
    "Si no cup is on the desk, fetch one.",  # "no" before an English noun is English's "no"
    "The wenner box stays on the shelf.",  # no conjunction: a word that only begins like one
])
def test_a_conjunction_english_also_has_stays_in_english_text(said: str) -> None:
    """"agar" opens a condition only in a clause with a word of no English after it; "si no"
    before an English noun keeps its "no"."""
    assert unquote(said).split()[:2] == said.split()[:2] or unquote(said).startswith("If no cup")


@pytest.mark.parametrize(("word", "other"), [
    ("abhi", True), ("naka", True), ("deh", True), ("madumi", True),
    ("on", False), ("floor", False), ("dirty", False), ("the", False), ("if", False), ("Nani", False),
])
def test_a_word_of_no_english(word: str, other: bool) -> None:
    """`sentences.foreign`: neither an English closed-class word nor a form lemminflect lists."""
    assert foreign(word) is other


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev11 barsati_hinglish_note: "on" of the item's topic (the ceiling fan)
    ("1. Pankha, the ceiling fan. Kal raat se chal raha hai shayad. Agar abhi bhi on hai toh band kar dena, "
     "bijli ka bill dekha hai?", ("barsati",), "state(ceiling_fan, toggled_on)"),
    # dev10 dirty_kitchen_tita_taglish: "naka-on", the topic named by "it" before
    ("1. Yung stove, the kalan sa labas, I think I forgot to turn it off. If naka-on pa, pakipatay lang.",
     ("dirty_kitchen",), "state(stove, toggled_on)"),
    # dev10 dirty_kitchen_tita_taglish: a gloss in brackets, of the thing that is no place
    ("2. The kaldero is still on the stove, yung big pot na ginamit ko for the sinigang. If madumi pa (dirty), "
     "pakihugas sa sink tapos ilagay mo sa dish rack para matuyo.", ("dirty_kitchen",), "state(pot, dirty)"),
    # dev10 dirty_kitchen_tita_taglish: a place noun with no English preposition
    ("3. Baka may sibuyas na nahulog sa floor, the onion, kasi butas yung plastic. If nasa floor siya, "
     "put it back in the basket.", ("dirty_kitchen",), "on(onion, floor)"),
    # dev10 verandah_patois_note (Jamaican Patois): "it deh pon di floor" (since the merge with
    # r2, `sentences._creole` spells the creole's words out first; the factor is the same)
    ("An di cushion, it always drop off a di armchair. If it deh pon di floor, put it back pon di armchair fi mi.",
     ("verandah",), "on(sofa_pillow, floor)"),
    # written here: Spanglish, a lamp in a bedroom
    ("The lamp on the nightstand, creo que la dejé prendida. Si todavía está on, apágala porfa.",
     ("bedroom",), "state(table_lamp, toggled_on)"),
    # written here: Singlish-like Malay, a towel in a bathroom
    ("The towel, my son always leaves it somewhere. Kalau atas floor, hang it on the towel rail lah.",
     ("bathroom",), "on(towel, floor)"),
    # written here: Franglais, a mug; the gloss of a state
    ("La tasse, the mug, est sur la table. Si elle est sale (dirty), mets-la dans le sink.",
     ("kitchen",), "state(mug, dirty)"),
])
def test_a_code_switched_condition_asks_what_its_english_words_say(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """A condition in another language's grammar whose reading gave nothing still asks what its
    English words say (`analysis._Reader.code_switched`): a state word, a place noun with no
    English preposition before it; of a carried thing it names, else of the item's topic."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms"), [
    # all English, a condition the reader reads as nothing: no state or place is guessed
    ("The lamp on the nightstand stays. If you have time, dust the shelf.", ("bedroom",)),
    # another language, but no English state or place word in the condition
    ("The mug, la tasse. Si elle est sale, mets-la dans le lave-vaisselle.", ("kitchen",)),
])
def test_no_english_state_or_place_asks_nothing(text: str, rooms: tuple[str, ...]) -> None:
    """Near misses: an English condition without a state, and a foreign one with no English
    state or place word in it, ask nothing."""
    assert _factors(text, rooms) == {}


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev11 kitchen_dish_cleanup_d11 (limericks): a condition broken over two lines of verse
    ("Then the counter: if dirty, don't dodge,\nwipe it down with the sponge, if the sponge\nis lying on the counter;\n"
     "if not, use the dish cloth, old flounder,", ("kitchen",), "on(sponge, kitchen_counter)"),
    # written here: a wrapped line in a note, "is" opening the next line
    ("Have a look at the kettle. If the kettle\nis still on, switch it off.", ("kitchen",), "state(kettle, toggled_on)"),
    # written here: "and" opening the next line of a poem
    ("If the towel is on the floor\nand wet, hang it on the rail.", ("bathroom",), "state(towel, wet)"),
])
def test_a_line_broken_inside_a_sentence_is_joined(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """A line ending in a word, before a line opening with a conjunction or a finite "be" that
    asks nothing, goes on with the same sentence (`sentences._BROKEN_LINE`)."""
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize("text", [
    # a chat's lines open with a sentence's own words, and a question on the next line is its own
    "can you check the bath mat if not just leave it there\nis the fan on? if so turn it off",
    "the fan is probably on, switch it off\npls feed the cat",
])
def test_a_line_that_opens_a_sentence_or_asks_is_not_joined(text: str) -> None:
    """Near misses: a line asking a question ("is the fan on?") or opening with a word that
    opens a sentence ("pls") stays a sentence of its own."""
    from logicenveval.offline.sentences import split_sentences
    assert split_sentences(text)[0] == text.split("\n")[0]


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev10 hallway_entry_tidy_d10 (Cockney): "sat" for "sitting"
    ("Your shoes. Wet ones go on the drying rack by the door, dry ones belong on the shoe rack. "
     "If they're already sat on the shoe rack, leave 'em be.", ("hallway",), "on(shoe, shoe_rack)"),
    # written here: a study, a laptop
    ("The laptop. If it's sat on the sofa again, put it back on the desk.", ("study",), "on(laptop, sofa)"),
])
def test_the_british_sat_is_sitting(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"is sat on": the British progressive of resting says where the thing is
    (`analysis.DESCRIPTIVE`, `SITUATION_PARTICIPLES`)."""
    assert _asks(text, rooms, condition)


def test_stood_somewhere_is_a_goal_not_a_place() -> None:
    """Near miss: "it is stood in the umbrella stand when it is wet" is the passive of standing a
    thing somewhere (an instruction), so "stood" is left out: the umbrella's place is not asked."""
    text = "If an umbrella has been left, it is stood in the umbrella stand when it is wet."
    assert not _asks(text, ("hallway",), "inside(umbrella, umbrella_stand)")


@pytest.mark.parametrize(("said", "meant"), [
    # dev10 study_plant_and_light_d10 (Early Modern English)
    ("a novel goeth onto the bookshelf", "a novel goes onto the bookshelf"),
    ("a desk whereon a desk lamp doth sit", "a desk whereon a desk lamp does sit"),
    ("Soil that is moist needeth nothing.", "Soil that is moist needs nothing."),
    ("should a book lie upon the desk", "should a book lie on the desk"),
    # written here: a kettle, "hath", "maketh", "sitteth"
    ("The kettle sitteth upon the stove and maketh noise; it hath boiled.",
     "The kettle sits on the stove and makes noise; it has boiled."),
    # near misses: words of today's English ending in "eth"
    ("Beneath the shelf, a comb with broken teeth.", "Beneath the shelf, a comb with broken teeth."),
])
def test_early_modern_verb_forms_read_as_todays(said: str, meant: str) -> None:
    """"-eth" on a verb's stem is "-s", "doth" and "hath" are "does" and "has" (`sentences._modern`),
    "upon" is "on" (`sentences.VARIANTS`)."""
    assert unquote(said) == meant


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev10 study_plant_and_light_d10
    ("The third: should a book lie upon the desk, a novel goeth onto the bookshelf, and any other book into "
     "the storage box.", ("study",), "attr(book, kind, novel)"),
    # written here: a kitchen, "needeth"
    ("If the kettle upon the stove be empty, it needeth filling at the sink.", ("kitchen",), "state(kettle, filled)"),
])
def test_an_early_modern_condition_is_read(text: str, rooms: tuple[str, ...], condition: str) -> None:
    assert _asks(text, rooms, condition)


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev11 kitchen_dish_cleanup_d11 (limericks)
    ("There's a plate on the counter - go look:\nif it's dirty, the dishwasher's its nook,\nbut if that's running "
     "already,\nput it into the sink, steady;\nand no plate there at all? Skip this hook.", ("kitchen",),
     "on(plate, kitchen_counter)"),
    # written here: a study, a mug taken elsewhere before "there" points back
    ("There is a mug on the desk; if it is dirty, put it in the sink. No mug there at all? Skip it.",
     ("study", "kitchen"), "on(mug, desk)"),
])
def test_there_after_a_thing_is_where_the_text_said_it_is(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"no plate there at all?": "there" after a thing named is the place the text said the
    thing is, not a place it was since told to go (`analysis._there_named`); the statement of
    that place is then doubted, its factor kept (`_settle_stated`)."""
    assert _asks(text, rooms, condition)


def test_a_stated_place_not_asked_stays_a_fact() -> None:
    """Near miss: "put it back there" asks nothing; the mug stated on the desk is no factor."""
    assert _factors("There is a mug on the desk. Wash it and put it back there.", ("study", "kitchen")) == {}


@pytest.mark.parametrize(("sentence", "condition", "consequence"), [
    # dev11 multi_room_trash_run_d11 (a press release)
    ("Under the plan, if the kitchen trash can is full, the full bag will be taken out and left on the hallway "
     "floor by the door.", " the kitchen trash can is full",
     "the full bag will be taken out and left on the hallway floor by the door."),
    # written here: minutes of a meeting, "is to be"
    ("As agreed, if the desk lamp is on, the lamp is to be switched off by the last to leave.",
     " the desk lamp is on", "the lamp is to be switched off by the last to leave."),
])
def test_a_passive_instruction_after_a_conditions_comma_is_its_main_clause(
        sentence: str, condition: str, consequence: str) -> None:
    """After a lead-in and a condition, a clause with a subject of its own, a modal and a passive
    ("the full bag will be taken out") is the condition's main clause, not more of the condition
    (`clauses._PASSIVE_INSTRUCTION`)."""
    from logicenveval.offline.clauses import split_clauses
    pieces = [(p.text, p.role) for p in split_clauses(sentence)]
    assert (condition, "condition") in pieces and (consequence, "consequence") in pieces


def test_a_condition_after_its_main_clause_keeps_its_comma() -> None:
    """Near miss: a condition after its main clause, a comma and a clause in the active ("if the
    can is full, the bag, which is by the door, goes out") stays one condition as before."""
    from logicenveval.offline.clauses import split_clauses
    pieces = [(p.text, p.role) for p in split_clauses("Take the bag out, if the can is full, the bag that is by the door.")]
    assert pieces[0] == ("Take the bag out", "consequence") and pieces[1][1] == "condition"


def test_an_english_clause_with_a_word_lemminflect_lacks_is_not_code_switched() -> None:
    """Near miss (a paraphrase of a built-in task): "fridge" is no word lemminflect lists, but a
    clause of English with it is not code-switched; its "turn on the stove" asks no egg on the
    stove, and "it isn't" still points back to the pan on the stove."""
    text = ("Eggs: should there be eggs in the fridge, open the fridge, make sure the frying pan is on the stove "
            "(put it there if it isn't), move an egg into the pan, shut the fridge and turn on the stove.")
    assert not _asks(text, ("kitchen",), "on(egg, stove)")
    assert _asks(text, ("kitchen",), "on(pan, stove)")
