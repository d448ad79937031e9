"""Reader rules from dev 19 and dev 20's losses other than naming (twelfth session, issue 47).

Each rule reads a structure of English, not a phrase of the sets: every test uses sentences
written for this file, in at least two registers, and near misses the rule must not misread.
"""

from __future__ import annotations

from typing import Any

import pytest

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.analysis import analyse
from logicenveval.offline.placement import described_placements

CATALOG = load_catalog()


def brief(description: str, roles: dict[str, str], rooms: tuple[str, ...] = ("living_room",)) -> dict[str, Any]:
    return {"id": "t", "description": description, "rooms": list(rooms),
            "roles": {name: {"category": cat, "attributes": {}} for name, cat in roles.items()}}


def asked(description: str, roles: dict[str, str], rooms: tuple[str, ...] = ("living_room",)) -> set[str]:
    """Every condition a factor of the reading may take."""
    return {v for f in analyse(brief(description, roles, rooms), CATALOG).factors for v in f.values.values()}


def groups(description: str, roles: dict[str, str], rooms: tuple[str, ...] = ("living_room",)) -> list[set[str]]:
    """The reading's subtasks, as the sets of their factors' subjects."""
    a = analyse(brief(description, roles, rooms), CATALOG)
    by_id = {f.id: f.subject for f in a.factors}
    return [{by_id[i] for i in g} for g in a.groups]


def placed(description: str, roles: dict[str, str], rooms: tuple[str, ...] = ("living_room",)) -> list[str]:
    return described_placements(brief(description, roles, rooms), CATALOG)


LOUNGE = {"remote": "remote_control", "tv_stand": "tv_stand", "keys": "key", "drawer": "drawer",
          "mug": "mug", "desk": "desk", "jacket": "jacket", "sofa": "sofa", "hamper": "hamper",
          "scarf": "scarf", "coat_rack": "coat_rack", "floor_lamp": "floor_lamp"}


# ----- an aside between a subject and its predicate ---------------------------------------------

@pytest.mark.parametrize(("text", "fact"), [
    # a family letter
    ("The remote, as ever, belongs on the TV stand, so if it is lying anywhere else, take it back there.",
     "on(remote, tv_stand)"),
    # a colleague's handover note
    ("The keys, as far as I know, live in the drawer. If they are anywhere else, put them back in it.",
     "inside(keys, drawer)"),
    # a terse memo
    ("Mug, as usual, belongs on the desk; if it's somewhere else, return it.", "on(mug, desk)"),
])
def test_an_aside_after_the_subject_leaves_its_place_read(text: str, fact: str) -> None:
    got = asked(text, LOUNGE)
    assert {fact, f"not {fact}"} <= got, got


@pytest.mark.parametrize("text", [
    # near misses: an aside that names a place or lists things is read as it stands
    "The mug, on the desk, is dirty. If it is dirty, wash it.",
    "The mug, the remote and the keys are on the desk. If the mug is dirty, wash it.",
])
def test_an_aside_naming_a_place_or_a_thing_is_no_aside(text: str) -> None:
    got = asked(text, LOUNGE)
    assert "state(mug, dirty)" in got, got
    assert not any(c.startswith(("on(remote", "on(keys", "inside(keys")) for c in got), got


# ----- a question in quotation marks ------------------------------------------------------------

@pytest.mark.parametrize("text", [
    # a call-centre script
    'Ask: "Is the kettle on the counter?" If not, skip the tea. Either way, say goodbye.',
    # a story's dialogue
    'Gran looked up. "Is the kettle on the counter?" Tom nodded, so she said: "Then fill it at the sink."',
    # the same question unquoted reads the same
    "Ask: Is the kettle on the counter? If not, skip the tea. Either way, say goodbye.",
])
def test_a_quoted_question_asks_about_the_scene(text: str) -> None:
    got = asked(text, {"kettle": "kettle", "counter": "kitchen_counter", "sink": "sink"}, ("kitchen",))
    assert {"on(kettle, counter)", "not on(kettle, counter)"} <= got, got


def test_a_quoted_statement_ends_no_sentence_of_its_own() -> None:
    # near miss: a quoted statement's full stop before narration ('"The pot." She pointed at it')
    # keeps the narration with it, so "it" in the next sentence is still the pot
    text = ('"The pot." She pointed her pen at the iron pot, which sat on the stool. "Look inside it. Dirty? '
            'Into the sink with it."')
    got = asked(text, {"pot": "pot", "stool": "stool", "sink": "sink", "pen": "pen"}, ("kitchen",))
    assert "state(pot, dirty)" in got and "state(pen, dirty)" not in got, got


def test_a_quoted_question_groups_with_what_its_answer_asks() -> None:
    # a call script: the kettle's place and its water are asked in one subtask
    text = ('Ask: "Is the kettle on the counter?" NO: skip the tea. YES: ask: "Is there any water in it?" '
            "If it's empty, fill it at the sink first. Then switch it on.")
    got = groups(text, {"kettle": "kettle", "counter": "kitchen_counter", "sink": "sink"}, ("kitchen",))
    assert {"kettle"} in got and len(got) == 1, got


# ----- an object "it" of a placing verb after a topic ---------------------------------------------

@pytest.mark.parametrize("text", [
    # a best man's speech reading out a message
    "My jacket. I left it on the sofa. If it's dirty, put it in the hamper.",
    # a note with a heading and a colon
    "Jacket: I left it on the sofa. If it's dirty, put it in the hamper.",
    # an email with a dash
    "About the jacket - we dropped it on the sofa. If it's dirty, put it in the hamper.",
])
def test_it_after_a_topic_is_the_topic_a_placing_verb_placed(text: str) -> None:
    assert "on(jacket, sofa)" in placed(text, LOUNGE)


@pytest.mark.parametrize("text", [
    # near misses: a condition, a doubt, and a machine left running place nothing
    "My jacket. If I left it on the sofa, put it in the hamper.",
    "My jacket. Maybe I left it on the sofa. If it's dirty, put it in the hamper.",
    "The floor lamp. I left it on. Switch it off.",
])
def test_it_left_under_a_condition_or_a_doubt_is_no_placement(text: str) -> None:
    assert not any(f.startswith("on(jacket") or f.startswith("on(floor_lamp") for f in placed(text, LOUNGE))


# ----- a modal of doubt with its subject dropped after a topic -----------------------------------

BATH = {"toothbrush": "toothbrush", "vanity": "bathroom_vanity", "trash_can": "trash_can", "kettle": "kettle",
        "sink": "sink", "counter": "kitchen_counter"}


@pytest.mark.parametrize(("text", "fact", "rooms"), [
    # a data sheet's item
    ("Toothbrush (spare). May have fallen on the floor. If so, put it back on the vanity.",
     "on(toothbrush, floor)", ("bathroom",)),
    # a hurried text with a colon
    ("kettle: might be empty. if so fill it at the sink", "state(kettle, filled)", ("kitchen",)),
    # a to-do list line
    ("Toothbrush - could have been knocked onto the floor. If so, bin it.", "on(toothbrush, floor)",
     ("bathroom",)),
])
def test_a_doubt_with_no_subject_after_a_topic_is_asked_of_the_topic(text: str, fact: str,
                                                                      rooms: tuple[str, ...]) -> None:
    assert {fact, f"not {fact}"} <= asked(text, BATH, rooms)


def test_a_request_opening_with_could_keeps_its_subject() -> None:
    # near miss: "Could you ..." asks the reader to act; it is no doubt about the topic
    got = asked("Kettle. Could you fill it at the sink? Then put it on the counter.", BATH, ("kitchen",))
    assert "state(kettle, filled)" not in got and "not state(kettle, filled)" not in got, got


# ----- "put it away": where the thing belongs ----------------------------------------------------

CLOSET = {"medicine": "medicine_bottle", "vanity": "bathroom_vanity", "medicine_cabinet": "medicine_cabinet",
          "mug": "mug", "cupboard": "cabinet", "desk": "desk"}


@pytest.mark.parametrize(("text", "goal", "rooms"), [
    # a house rule sheet
    ("The medicine bottle belongs in the medicine cabinet. If it is standing on the vanity, put it away.",
     "inside(medicine, medicine_cabinet)", ("bathroom",)),
    # an office note: a home, then "tidy ... away"
    ("The mug lives in the cupboard. If it's on the desk, tidy the mug away.", "inside(mug, cupboard)",
     ("office",)),
])
def test_put_away_sends_a_thing_where_it_belongs(text: str, goal: str, rooms: tuple[str, ...]) -> None:
    a = analyse(brief(text, CLOSET, rooms), CATALOG)
    goals = {f.condition for c in a.clauses if c.role == "consequence" for f in c.facts if f.goal}
    assert goal in goals, goals


def test_put_away_groups_the_container_asked_after_it() -> None:
    # the cabinet's door is asked for the bottle's move into it: one subtask
    text = ("The medicine bottle belongs in the medicine cabinet. If it is standing on the vanity, put it away. "
            "The medicine cabinet may be open or shut; either way, make sure it ends up closed.")
    got = groups(text, CLOSET, ("bathroom",))
    assert {"medicine", "medicine_cabinet"} in got, got


def test_throw_away_sends_nothing_where_it_belongs() -> None:
    # near miss: "throw it away" is no "put it away"
    text = "The mug belongs in the cupboard. If it is chipped, throw it away."
    a = analyse(brief(text, CLOSET, ("kitchen",)), CATALOG)
    goals = {f.condition for c in a.clauses[1:] for f in c.facts if f.goal}
    assert "inside(mug, cupboard)" not in goals, goals


# ----- a shortened name before a synonym of another kind -----------------------------------------

@pytest.mark.parametrize("text", [
    # a methods section in the passive
    "The towel on the drying rack was checked. A dry towel was taken to the utility shelf; a wet towel was "
    "left on the rack.",
    # a chatty note
    "Have a look at the towel on the drying rack. Dry? Pop it on the utility shelf. Still wet? Leave it on the "
    "rack.",
])
def test_a_word_of_a_things_own_name_means_that_thing(text: str) -> None:
    # "rack" shortens "drying rack", not the utility shelf (whose kind is also called "storage rack")
    got = asked(text, {"towel": "towel", "drying_rack": "drying_rack", "shelf": "utility_shelf"}, ("laundry_room",))
    assert "on(towel, drying_rack)" in got and "on(towel, shelf)" not in got, got


def test_a_synonym_alone_still_names_its_kind() -> None:
    # near miss: the synonym said in full ("storage rack"), or "rack" with no thing named so, is the shelf
    roles = {"towel": "towel", "drying_rack": "drying_rack", "shelf": "utility_shelf"}
    text = "If the towel is on the drying rack and it is dry, put it on the storage rack."
    a = analyse(brief(text, roles, ("laundry_room",)), CATALOG)
    assert "on(towel, shelf)" in {f.condition for c in a.clauses for f in c.facts if f.goal}
    got = asked("If the towel is dry, put it on the utility shelf. Wet? It stays on the rack.",
                {"towel": "towel", "shelf": "utility_shelf"}, ("laundry_room",))
    assert "state(towel, wet)" in got, got


# ----- labelled answers to a question ------------------------------------------------------------

DESK = {"lamp": "floor_lamp", "mug": "mug", "sink": "sink", "desk": "desk", "bread": "bread",
        "counter": "kitchen_counter", "toaster": "toaster", "plate": "plate"}


def contexts(description: str, roles: dict[str, str], rooms: tuple[str, ...]) -> dict[str, list[tuple[str, frozenset[str]]]]:
    return {f.id: list(f.context) for f in analyse(brief(description, roles, rooms), CATALOG).factors}


@pytest.mark.parametrize(("text", "rooms", "question", "asked_under", "answer"), [
    # a flowchart written out with arrows
    ("Q: Is the mug on the desk?\nYes -> take it to the sink, and if the lamp is on, switch it off.\n"
     "No -> nothing to do.", ("office",), "mug_on_desk", "lamp_toggled_on", "yes"),
    # a call script with quoted speech
    ('Ask: "Is there bread on the counter?"\n> YES: "Great. Put it on the plate. Is the toaster on? If not, '
     'switch it on."\n> NO: "No toast today, then."', ("kitchen",), "bread_on_counter", "toaster_toggled_on", "yes"),
    # an FAQ: the answer under "No"
    ("Is the mug on the desk?\nNo: then check the lamp; if it is on, switch it off.\nYes: take it to the sink.",
     ("office",), "mug_on_desk", "lamp_toggled_on", "no"),
])
def test_a_factor_in_a_labelled_answer_is_asked_under_it(text: str, rooms: tuple[str, ...], question: str,
                                                         asked_under: str, answer: str) -> None:
    got = contexts(text, DESK, rooms)
    assert (question, frozenset({answer})) in got.get(asked_under, []), got


@pytest.mark.parametrize("text", [
    # near misses: a step on a line of its own after the answers, and a "No:" that answers nothing
    "Is the mug on the desk?\nYES: take it to the sink.\nNO: leave it.\nIf the lamp is on, switch it off.",
    "No: I never said that. If the lamp is on, switch it off. Is the mug on the desk? Then take it to the sink.",
])
def test_a_step_outside_the_answer_is_asked_on_its_own(text: str) -> None:
    got = contexts(text, DESK, ("office",))
    assert got.get("lamp_toggled_on") == [], got


def test_an_answers_gloss_says_the_thing_may_be_missing() -> None:
    # a call script: "NO (it is elsewhere, or there is none)" asks whether there is any at all
    text = ('Ask: "Is there a loaf of bread on the counter?"\n> YES: put it on the plate.\n'
            "> NO (the bread is somewhere else, or we are out of bread): skip the toast.")
    assert {"exists(bread)", "not exists(bread)", "on(bread, counter)"} <= asked(text, DESK, ("kitchen",))


# ----- a relative "where" after a room -----------------------------------------------------------

STUDY = {"laptop": "laptop", "desk": "desk", "office_chair": "office_chair", "mug": "mug"}
FLAT = ("living_room", "bedroom", "study")


@pytest.mark.parametrize("text", [
    # a square-dance caller's call
    "Sashay to the study, where in the study the laptop belongs on the desk: if it's on the office chair, "
    "put it on the desk!",
    # an estate agent's description
    "The hall leads on to the study, where a desk stands under the window. Put the laptop on the desk.",
    # a plain instruction
    "Take the mug to the study, where it belongs on the desk.",
])
def test_a_relative_where_after_a_room_frames_what_it_names(text: str) -> None:
    assert "in_room(desk, study)" in placed(text, STUDY, FLAT)


def test_a_room_after_the_relative_ends_the_frame() -> None:
    # near miss: a second, other room named in the relative frames what follows it instead
    text = "Go to the study, where the laptop is; then in the bedroom put the mug on the desk."
    assert "in_room(desk, study)" not in placed(text, STUDY, FLAT)


# ----- a Markdown sub-heading names its section's situation --------------------------------------

OFFICE = {"notebook": "notebook", "desk": "desk", "mug": "mug", "sink": "sink"}


@pytest.mark.parametrize("text", [
    # an on-call runbook
    "## Checks\n### 3. Notebook on the floor\nMy notebook goes on the desk. Found it on the floor? Put it on the "
    "desk. Anywhere else: leave it.",
    # a wiki page for a shared office
    "## Notebook on the floor\nIt belongs on the desk, so pick it up and put it there.",
])
def test_a_markdown_heading_is_no_statement_of_where_a_thing_is(text: str) -> None:
    assert {"on(notebook, floor)", "not on(notebook, floor)"} <= asked(text, OFFICE, ("office",))


def test_a_comment_in_code_is_no_heading() -> None:
    # near miss: one "#" opens a comment in code or YAML; the line is read as it was
    text = "# the mug is in the sink\nif mug.dirty: wash(mug)"
    before = asked(text.replace("# ", ""), OFFICE, ("office",))
    assert asked(text, OFFICE, ("office",)) == before
