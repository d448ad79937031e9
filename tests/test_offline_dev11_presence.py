"""Presence asked in the condition itself, and placements said as possible (hedged) rather than
stated, from the tenth and eleventh development sets (docs/reader.md, "From dev 10 and 11
(presence and hedged placements)"): "if you find a wallet", "if a watch has been left behind", "a
pillow may have tumbled to the floor", "On the floor we may find the game controller", "if its
door is hanging open", a toy called by its given name, a rule written as a YAML record. Each rule
is a kind of sentence, tried on a development sentence and on sentences written for the test in
other rooms, registers and objects; near misses say where it must not fire."""

from __future__ import annotations

import pytest
from reading import asks, factors, placed

from logicenveval.offline.lexicon import _named_things
from logicenveval.offline.sentences import derecord, unquote

# -- coming upon a thing named, nowhere in particular, asks whether it is there ----------------------


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev 11 parlour_noir_monologue (a noir monologue)
    ("And the wallet. There's a chance the dame who came calling at midnight left one behind. Maybe she did, "
     "maybe she didn't. If you find a wallet, put it on the side table and don't look inside.", ("parlour",),
     "exists(wallet)"),
    # dev 10 garden_office_bug_report (a bug report): a place that is the whole room
    ("If you find a credit card anywhere in the office, put it on the desk next to the laptop so she sees it.",
     ("garden_office",), "exists(credit_card)"),
    # written here: a bedroom, "come across", an inverted "should"
    ("Should you come across a sock, put it in the hamper.", ("bedroom",), "exists(sock)"),
    # written here: a terse note, "happen to spot", a phone
    ("If you happen to spot a phone, put it on the shelf.", ("living_room",), "exists(cell_phone)"),
])
def test_coming_upon_a_named_thing_asks_whether_it_is_there(text: str, rooms: tuple[str, ...],
                                                            condition: str) -> None:
    """An agent, then a verb of discovery, then a thing named with no place or state of its own
    (`analysis._FIND_NAMED`): whether the thing is there at all."""
    assert asks(text, rooms, condition)


def test_coming_upon_a_thing_somewhere_or_coming_upon_no_thing_asks_no_presence() -> None:
    # a place said of the thing found is the question, not its presence
    found = factors("If you find a sock on the floor, put it in the hamper.", ("bedroom",))
    assert {"on(sock, floor)", "not on(sock, floor)"} in found.values()
    assert "sock_present" not in found
    # "find time" finds no thing; "find it" points back (nothing before it here)
    assert not factors("If you find time, put the book on the shelf.", ("bedroom",))
    assert not factors("If you find it, put the book on the shelf.", ("bedroom",))


# -- "if it isn't there" after a presence asked is its absence --------------------------------------


@pytest.mark.parametrize(("text", "rooms", "thing", "goal"), [
    # dev 10 garden_office_bug_report
    ("If you find a credit card anywhere in the office, put it on the desk next to the laptop so she sees it. "
     "If it isn't there, not reproducible, nothing to do.", ("garden_office",), "credit_card", "on(credit_card, desk)"),
    # written here: a living room, "spot", "not there"
    ("If you spot a phone, put it on the shelf. If it's not there, never mind.", ("living_room",), "cell_phone",
     "on(cell_phone, wall_shelf)"),
])
def test_not_there_after_a_presence_asked_is_its_absence(text: str, rooms: tuple[str, ...], thing: str,
                                                         goal: str) -> None:
    """After a condition asking whether a thing is there at all, "if it isn't there" is that
    presence (`analysis._THERE_OR_NOT`, `_presence_asked`), not the place the instruction in
    between put it."""
    found = factors(text, rooms)
    assert {f"exists({thing})", f"not exists({thing})"} in found.values()
    assert not any(goal in values for values in found.values())


def test_not_there_after_an_instruction_alone_is_away_from_its_goal() -> None:
    # no presence asked before: "not there" is still away from where the instruction puts it
    assert asks("The remote goes on the TV stand. If it is not there, put it there.", ("living_room",),
                "on(remote_control, tv_stand)")


# -- "left behind" says the thing is there ---------------------------------------------------------


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev 10 chalet_cleaning_job_email (a cleaning app's email)
    ("Guests often forget their watches! If a watch has been left behind, put it on the hall table so we can "
     "post it on.", ("chalet",), "exists(watch)"),
    # written here: a living room, "got left behind"
    ("In case a phone got left behind, put it on the shelf.", ("living_room",), "exists(cell_phone)"),
    # written here: a hallway, someone as the subject, "behind" after the thing
    ("If someone has left a scarf behind, hang it on the coat rack.", ("hallway",), "exists(scarf)"),
])
def test_left_behind_asks_whether_there_is_one(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"behind" of a verb of leaving or arriving (`analysis.ARRIVALS`) is a known word, never an
    adjective of the thing ("behindness"): the condition asks whether there is one."""
    assert asks(text, rooms, condition)
    assert not any("behind" in fid for fid in factors(text, rooms))


# -- "to" after a verb of falling is where the thing lies -------------------------------------------


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev 10 bedroom_morning_tidy_d10 (a horoscope column)
    ("Saturn hints that a pillow may have tumbled to the floor, and Mercury suggests a shirt could be lying "
     "there beside it.", ("bedroom",), "on(pillow, floor)"),
    # written here: a plain condition, "fallen to"
    ("If the teddy bear has fallen to the floor, put it on the bed.", ("bedroom",), "on(teddy_bear, floor)"),
    # written here: a kitchen, "toppled to"
    ("A mug may have toppled to the floor; if so, put it in the sink.", ("kitchen",), "on(mug, floor)"),
])
def test_to_after_a_verb_of_falling_is_where_the_thing_lies(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """After a verb of falling (`analysis.FALLS`), "to" says where the thing came to rest: in a
    guess or a condition, the place asked."""
    assert asks(text, rooms, condition)


def test_to_after_a_verb_of_moving_is_still_a_goal() -> None:
    assert not factors("Return the pillow to the bed.", ("bedroom",))
    assert not factors("Take the mug to the sink.", ("kitchen",))


# -- a thing at a place, then a verb of going back, is a rule, not a stated placement -----------------


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev 10 bedroom_morning_tidy_d10
    ("The stars counsel order: a pillow on the floor returns to the bed.", ("bedroom",), "on(pillow, floor)"),
    # written here: a study, a house rule
    ("House rule: a mug on the desk returns to the kitchen.", ("study",), "on(mug, desk)"),
])
def test_a_thing_at_a_place_that_returns_is_asked_not_placed(text: str, rooms: tuple[str, ...],
                                                            condition: str) -> None:
    """"returns" is a verb of motion for the placement reader (`placement.MOTION`), as "goes"
    and "belongs" are: "a pillow on the floor returns to the bed" says what happens to a pillow
    that is on the floor; it states no pillow on the floor."""
    assert condition not in placed(text, rooms)
    assert asks(text, rooms, condition)


def test_a_thing_said_to_be_at_a_place_is_still_placed() -> None:
    assert "on(pillow, floor)" in placed("The pillow is on the floor.", ("bedroom",))


# -- a place put first, then an agent coming upon things ---------------------------------------------


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev 11 snug_wildlife_documentary (a wildlife documentary's voice-over)
    ("On the floor we may find the game controller, dropped where its owner last lay. If it is down there, it "
     "should be lifted gently and returned to the coffee table.", ("snug",), "on(game_controller, floor)"),
    # written here: a kitchen, "might spot", "if so"
    ("In the sink you might spot a mug. If so, wash it.", ("kitchen",), "inside(mug, sink)"),
    # written here: a study, a list after the place
    ("On the desk you may see the mug, and perhaps the lamp. If the mug is there, put it in the sink.",
     ("study",), "on(mug, desk)"),
])
def test_a_place_put_first_then_someone_finding_things_places_them_there(
        text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"On the floor we may find X" reads as "On the floor there may be X"
    (`analysis._FRONTED_FINDING`, `_Reader._fronted_place`)."""
    assert asks(text, rooms, condition)


def test_a_fronted_time_or_a_stated_finding_asks_nothing() -> None:
    # a time put first is no place; a finding said outright is a stated fact, not a question
    assert not factors("On Sunday we may find time to tidy the desk.", ("study",))
    assert not factors("On the desk you will find the lamp.", ("study",))


# -- a verb of posture before a state is the copula ---------------------------------------------------


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev 11 cellar_dungeon_master (a game master's notes)
    ("In the corner squats the safe, the Vault of the Dragon King. If its door is hanging open, you close it.",
     ("cellar",), "state(safe, open)"),
    # written here: a kitchen, a part of the thing
    ("If the fridge door is hanging open, shut it.", ("kitchen",), "state(fridge, open)"),
])
def test_hanging_before_a_state_is_being_in_that_state(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """"hanging" is read as "standing" is (`analysis.DESCRIPTIVE`): "its door is hanging open"
    asks whether the thing is open."""
    assert asks(text, rooms, condition)


def test_hanging_before_a_place_is_still_where_the_thing_is() -> None:
    found = factors("If the towel is hanging on the rail, leave it.", ("bathroom",))
    assert {"on(towel, towel_rack)", "not on(towel, towel_rack)"} in found.values()
    assert not any(values & {"state(towel, open)"} for values in found.values())


# -- a given name in apposition names its thing --------------------------------------------------------


@pytest.mark.parametrize(("text", "rooms", "condition"), [
    # dev 10 tower_room_bedtime_story (a bedtime story): the doll's name after "find"
    ("First, the princess had to find Lady Rosabel, her doll. If Lady Rosabel had fallen on the floor, the "
     "princess lifted her up and laid her in her cot.", ("tower_room",), "on(doll, floor)"),
    # written here: a bedroom, the name opening its sentence after a title
    ("Captain Fluff, my teddy bear, sleeps on the bed. If Captain Fluff has fallen on the floor, put him back.",
     ("bedroom",), "on(teddy_bear, floor)"),
    # written here: the noun before the name ("our kettle, Bessie")
    ("Please check our kettle, Bessie. If Bessie is still on, switch it off.", ("kitchen",),
     "state(kettle, toggled_on)"),
])
def test_a_given_name_in_apposition_is_its_thing(text: str, rooms: tuple[str, ...], condition: str) -> None:
    """A capitalised name beside a noun phrase naming one role ("Lady Rosabel, her doll", "Mr
    Snuggles the teddy bear", "our kettle, Bessie") is that role when said alone later
    (`lexicon._named_things`)."""
    assert asks(text, rooms, condition)


def test_a_capitalised_word_opening_its_sentence_is_no_given_name() -> None:
    phrases = {("pillow",): {"pillow"}, ("doll",): {"doll"}, ("teddy", "bear"): {"teddy_bear"}}
    assert _named_things("Then, the pillow goes on the bed. Finally, the doll.", phrases) == {}
    assert _named_things("The dragon was Mr Snuggles the teddy bear, who was lying on the bed.", phrases) == {
        ("mr", "snuggle"): {"teddy_bear"}}
    # a name beside a noun that names no role, or two, names nothing
    assert _named_things("there lived a princess called Isla, the princess.", phrases) == {}


# -- a rule written as a record of keyed fields is its conditional -----------------------------------

_YAML = """tasks:
  - name: desktop
    when: "desktop computer still on"
    do: switch it off   # power button, don't just pull the plug
  - name: laptop_lid
    when: "laptop is open"
    do: close the lid
    note: leave it wherever it is
  - name: headphones
    when: "you find my headphones in here"   # might have taken them, might not
    do: put them on the bookshelf
    else: nothing
"""

_CONFIG = """# kitchen.rules
rules:
  - id: 1
    if: the kettle is still on
    then: switch it off
  - id: 2
    condition: 'mug in the sink'
    action: wash it
    otherwise: leave it
"""


def test_a_record_of_keyed_fields_is_its_conditional() -> None:
    """A record of keyed lines with a condition field and an action field (`sentences.RECORD_FIELDS`,
    `derecord`) reads as "If <condition>, <action>. Otherwise, <else>."."""
    # dev 11 home_office_chores_yaml (a YAML chores file)
    said = derecord(_YAML)
    assert "If you find my headphones in here, put them on the bookshelf. Otherwise, nothing." in said
    assert "If laptop is open, close the lid. Leave it wherever it is." in said
    assert "name:" not in said and "#" not in said
    found = factors(_YAML, ("home_office",))
    for condition in ("exists(headphones)", "state(laptop, open)", "state(desktop_computer, toggled_on)"):
        assert any(condition in values for values in found.values()), condition
    # written here: a rules file in another dialect ("if:" / "then:", "condition:" / "action:")
    said = derecord(_CONFIG)
    assert "If the kettle is still on, switch it off." in said
    assert "If mug in the sink, wash it. Otherwise, leave it." in said
    assert asks(_CONFIG, ("kitchen",), "state(kettle, toggled_on)")


def test_a_record_with_no_condition_or_a_chat_stays_as_it_is() -> None:
    text = "version: 2\nroom: home_office\ncontext:\n  - the desktop computer is on the desk"
    assert derecord(text) == text
    chat = "Mum: if the lamp is on, switch it off\nDad: and close the wardrobe"
    assert derecord(chat) == chat
    assert unquote(chat) == chat
