"""The offline model reads the placements a description states (offline.placement) and the realiser
puts those objects there unless a situation fact places them (issue 34, the 12 placement facts)."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.model.conditions import Pred, parse
from logicenveval.offline.analysis import analyse
from logicenveval.offline.placement import described_placements
from logicenveval.offline.realise import realise, task_objects
from logicenveval.offline.scene_answers import misfits

CATALOG = load_catalog()


def _brief(description: str, rooms: list[str], **roles: str) -> dict[str, Any]:
    return {"id": "t", "description": description, "rooms": rooms,
            "roles": {name: {"category": cat} for name, cat in roles.items()}}


def _task_brief(task_id: str) -> dict[str, Any]:
    return load_task(task_id).brief().model_dump(mode="json")


@pytest.mark.parametrize(("description", "roles", "fact"), [
    # kept / lives: the object spoken of last is kept in the holder named after the verb
    ("Wipe it with the old towel - it's kept in the vanity, unless someone stuffed it into the cabinet.",
     {"old_towel": "towel", "vanity": "bathroom_vanity", "cabinet": "medicine_cabinet"},
     "inside(old_towel, vanity)"),
    ("Take the spare roll (we keep spares in the vanity cabinet) and put it on the toilet tank.",
     {"spare_roll": "toilet_paper", "vanity": "bathroom_vanity", "toilet": "toilet"},
     "inside(spare_roll, vanity)"),
    ("Use the cloth if we still have one (it lives in the vanity).",
     {"cloth": "cloth", "vanity": "bathroom_vanity"}, "inside(cloth, vanity)"),
    # "a <holder> with a <thing> [on it]"
    ("The bedroom has a bed and a nightstand with a lamp.",
     {"bed": "bed", "nightstand": "nightstand", "lamp": "table_lamp"}, "on(lamp, nightstand)"),
    ("You sit next to a coffee table with a mug on it.",
     {"coffee_table": "coffee_table", "mug": "mug"}, "on(mug, coffee_table)"),
    # a room and the list of what it holds
    ("The home has a kitchen with a stove, a counter and a sink.",
     {"stove": "stove", "counter": "kitchen_counter", "sink": "sink"}, "in_room(counter, kitchen)"),
    ("The dining room opens onto the kitchen, where the fridge and a cabinet are.",
     {"fridge": "fridge", "cabinet": "cabinet"}, "in_room(cabinet, kitchen)"),
    ("In the bedroom, turn off the table lamp if it's on.", {"table_lamp": "table_lamp"},
     "in_room(table_lamp, bedroom)"),
    ("In the study the laptop belongs on the desk: put it there.", {"laptop": "laptop", "desk": "desk"},
     "in_room(desk, study)"),
    # an object named right before "in/on <room>"
    ("Hang the shirt on the drying rack out on the balcony.",
     {"shirt": "shirt", "drying_rack": "drying_rack"}, "in_room(drying_rack, balcony)"),
    # an object named right before "on/in <holder>" (a default, not a settled location)
    ("While you are out there, check the towel on the drying rack.",
     {"towel": "towel", "drying_rack": "drying_rack"}, "on(towel, drying_rack)"),
])
def test_each_kind_of_placement_phrase(description: str, roles: dict[str, str], fact: str) -> None:
    rooms = ["kitchen", "dining_room", "bedroom", "study", "laundry_room", "balcony", "bathroom", "living_room"]
    assert fact in described_placements(_brief(description, rooms, **roles), CATALOG)


@pytest.mark.parametrize(("description", "roles"), [
    # where the mop stands, not that it is on the table
    ("There are a sofa and a table with a wet mop leaning against it.", {"table": "coffee_table", "mop": "mop"}),
    # a condition or a possibility, not a statement
    ("Bring the lamp if there is a pan in the kitchen.", {"pan": "pan", "lamp": "desk_lamp"}),
    # an instruction: where it goes, not where it is
    ("Put the mug in the kitchen.", {"mug": "mug"}),
    ("Hang the shirt on the drying rack.", {"shirt": "shirt", "drying_rack": "drying_rack"}),
    ("Any other book goes into the storage box.", {"book": "book", "storage_box": "storage_box"}),
    # a verb, not an object ("bin the wipe")
    ("Over in the living room, clean the pet bed and bin the wipe.", {"trash_can": "trash_can"}),
])
def test_what_is_no_stated_placement(description: str, roles: dict[str, str]) -> None:
    facts = described_placements(_brief(description, ["kitchen", "living_room", "laundry_room"], **roles), CATALOG)
    assert not [f for f in facts if not f.startswith(("in_room(sofa", "in_room(table", "in_room(pet_bed"))]


def test_a_presumed_place_is_left_out_when_asked_for_settled_ones() -> None:
    brief = _brief("Check the towel on the drying rack.", ["laundry_room"], towel="towel",
                   drying_rack="drying_rack")
    assert described_placements(brief, CATALOG, kinds=frozenset({"settled", "kept"})) == []


@pytest.mark.parametrize(("task_id", "facts"), [
    ("bathroom_counter_sort", {"inside(old_towel, vanity)"}),
    ("bathroom_towel_refresh", {"inside(spare_roll, vanity)", "inside(cloth, vanity)"}),
    ("bedroom_morning_tidy", {"on(lamp, nightstand)"}),
    ("dining_table_clear", {"in_room(cabinet, kitchen)"}),
    ("lamp_or_pillow_fetch", {"on(mug, coffee_table)", "in_room(stove, kitchen)", "in_room(counter, kitchen)",
                              "in_room(sink, kitchen)"}),
    ("laundry_drying_rack", {"in_room(drying_rack, balcony)"}),
    ("multi_room_lights_off", {"in_room(table_lamp, bedroom)", "in_room(desk, study)"}),
])
def test_the_benchmark_placements_are_read_from_the_description(task_id: str, facts: set[str]) -> None:
    """The 12 placement facts the tasks state as constraints, read from the brief alone (the first
    option of a disjunction: the vanity)."""
    assert facts <= set(described_placements(_task_brief(task_id), CATALOG))


def test_the_realiser_follows_the_description_unless_the_situation_places_the_object() -> None:
    brief = _task_brief("laundry_drying_rack")
    assert realise(brief, [], CATALOG)["drying_rack"].room == "balcony"
    assert realise(brief, ["in_room(drying_rack, laundry_room)"], CATALOG)["drying_rack"].room == "laundry_room"
    lamp = realise(_task_brief("bedroom_morning_tidy"), ["state(lamp, toggled_on)"], CATALOG)["lamp"]
    assert lamp.placement == "on:nightstand"
    towel = realise(_task_brief("bathroom_counter_sort"), ["inside(old_towel, medicine_cabinet)"], CATALOG)
    assert towel["old_towel"].placement == "inside:medicine_cabinet"


def test_the_realiser_keeps_a_stated_floor_placement() -> None:
    """"My handbag is on the floor by the door", "The cardboard box is on the floor next to the
    stool": the floor is no role, yet the text says where the thing is; without a situation fact
    on it, the realiser puts it there (not on the first surface of the room)."""
    bag = _brief("Two coat hooks hang by the door. My handbag is on the floor by the door.",
                 ["entryway"], hook="coat_hook", handbag="handbag")
    assert realise(bag, [], CATALOG)["handbag"].placement == "floor"
    box = _brief("The cardboard box is on the floor next to the stool.", ["garage"],
                 stool="stool", box="cardboard_box")
    assert realise(box, [], CATALOG)["box"].placement == "floor"
    assert realise(box, ["not on(box, floor)"], CATALOG)["box"].placement != "floor"


def test_an_item_ruled_off_a_crowded_side_table_gets_another() -> None:
    """Items that must be off the floor in a room with no surface among the roles go on an added
    side table; one the layout found too crowded for it (`not on(x, side_table_<room>_1)`) goes on
    a second, so that the feedback loop can converge (the jacket and hat of an entryway, two
    books of a hallway)."""
    brief = _brief("Hang the jacket and the hat.", ["entryway"], jacket="jacket", hat="hat")
    facts = ["not on(jacket, floor)", "not on(hat, floor)"]
    first = {o["id"]: o["placement"] for o in task_objects(brief, facts, CATALOG)}
    assert first["jacket"] == first["hat"] == "on:side_table_entryway_1"
    again = {o["id"]: o["placement"] for o in
             task_objects(brief, [*facts, "not on(hat, side_table_entryway_1)"], CATALOG)}
    assert again["hat"] == "on:side_table_entryway_2" and "side_table_entryway_2" in again
    books = _brief("Tidy the hallway.", ["hallway"], book="book", magazine="magazine")
    placed = {o["id"]: o["placement"] for o in task_objects(
        books, ["not on(book, floor)", "not on(magazine, floor)", "not on(magazine, side_table_hallway_1)"],
        CATALOG)}
    assert placed["magazine"] == "on:side_table_hallway_2"


def test_a_thing_that_rests_only_on_the_floor_stays_there_when_a_fact_rules_it_out() -> None:
    """Furniture (a fridge, a wardrobe: the reply schema lets it rest on nothing) is never set on a
    table or an added side table, whatever the facts say: the selection stays valid and the
    unrealisable fact simply fails; a pickable thing ruled off the floor still goes on a surface,
    one the catalog keeps on the floor (a mop) too."""
    for room, big, small in (("kitchen", "fridge", "mug"), ("bedroom", "wardrobe", "book")):
        brief = _brief("Tidy up.", [room], big=big, table="side_table", small=small)
        placed = {o["id"]: o["placement"] for o in task_objects(
            brief, ["not on(big, floor)", "not on(small, floor)"], CATALOG)}
        assert placed["big"] == "floor" and placed["small"] == "on:table"
        assert CATALOG.get(big).placement == ["floor"]
    mop = _brief("Tidy up.", ["bathroom"], mop="mop", table="side_table")
    assert {o["id"]: o["placement"] for o in task_objects(mop, ["not on(mop, floor)"], CATALOG)}["mop"] == "on:table"


def test_a_drawer_goes_inside_furniture_it_fits_in_or_a_cabinet_added_for_it() -> None:
    """A drawer is part of a piece of furniture (the catalog places it only inside one): the
    realiser puts it in an openable piece of the room it fits in, a dresser or a nightstand, or
    adds a cabinet for it as it adds a side table for a thing with no surface, never on the floor."""
    with_dresser = _brief("Close the drawer.", ["bedroom"], drawer="drawer", dresser="dresser")
    placed = {o["id"]: o["placement"] for o in task_objects(with_dresser, [], CATALOG)}
    assert placed == {"drawer": "inside:dresser", "dresser": "floor"}
    alone = _brief("Put the scissors in the drawer.", ["kitchen"], drawer="drawer", scissors="scissors")
    objects = {o["id"]: o for o in task_objects(alone, [], CATALOG)}
    assert objects["drawer"]["placement"] == "inside:cabinet_kitchen_1"
    assert objects["cabinet_kitchen_1"]["category"] == "cabinet" and objects["cabinet_kitchen_1"]["role"] is None


@pytest.mark.parametrize(("description", "roles", "thing"), [
    ("If the lamp is on, fetch a book from the dresser (that's where the books are kept) and read it.",
     {"book": "book", "dresser": "dresser", "lamp": "table_lamp"}, "book"),
    ("Should the sink be full, grab a sponge from the cabinet - it's where the sponges are kept - and wipe "
     "the counter.", {"sponge": "sponge", "cabinet": "cabinet", "sink": "sink", "counter": "kitchen_counter"},
     "sponge"),
    # development set (nursery_bedtime)
    ("Normally a fresh diaper is lying on the changing table; if there isn't one, fetch a spare from the "
     "dresser (that's where the spares are kept), lay it on the changing table.",
     {"diaper": "diaper", "spare_diaper": "diaper", "changing_table": "changing_table", "dresser": "dresser"},
     "spare_diaper"),
])
def test_a_thing_taken_from_where_it_is_kept_is_not_asked_on_or_in_it(description: str, roles: dict[str, str],
                                                                       thing: str) -> None:
    """"a book from the dresser (that's where the books are kept)": the text places the thing in
    the holder, so "from the dresser" asks nothing, whether the reader took it as on or in (a
    dresser and a cabinet are both a surface and a container)."""
    factors = analyse(_brief(description, ["kitchen"], **roles), CATALOG).factors
    assert not [f for f in factors if f.subject == thing and f.kind == "location"], factors


def test_a_stated_placement_is_no_uncertain_factor() -> None:
    """"a kitchen with a stove", "a coffee table with a mug on it": nothing to ask; "(a pan may be
    in the kitchen)" still is; "kept in the vanity, unless ... the medicine cabinet" has no
    "elsewhere"."""
    ids = {f.id for f in analyse(_task_brief("lamp_or_pillow_fetch")).factors}
    assert not ids & {"stove_in_room_kitchen", "counter_in_room_kitchen", "sink_in_room_kitchen",
                      "mug_on_coffee_table"}
    assert "pan_in_room_kitchen" in ids
    towel = [f for f in analyse(_task_brief("bathroom_counter_sort")).factors if f.subject == "old_towel"]
    assert all("elsewhere" not in f.values for f in towel)


def test_an_aside_in_a_condition_asks_nothing_and_we_have_one_asks_existence() -> None:
    """"use the microfibre cloth if we still have one (it lives in the vanity ...)": the cloth
    may be absent; the vanity is not in question."""
    ids = {f.id for f in analyse(_task_brief("bathroom_towel_refresh")).factors}
    assert "cloth_present" in ids and "vanity_present" not in ids


def test_a_holders_top_and_inside_are_packed_apart() -> None:
    """A towel on the vanity's top leaves its inside free (the layout packs the two apart)."""
    objects = [
        {"id": "vanity", "category": "bathroom_vanity", "placement": "floor"},
        {"id": "bottle", "category": "medicine_bottle", "placement": "on:vanity"},
        {"id": "towel", "category": "towel", "placement": "inside:vanity"},
    ]
    assert misfits(objects, CATALOG) == []
    objects[1]["placement"] = "inside:vanity"
    assert misfits(objects, CATALOG) == ["not inside(towel, vanity)"]


_WORDS = ["the", "a", "with", "on", "in", "into", "it", "is", "kept", "keep", "lives", "out", "kitchen",
          "balcony", "nightstand", "lamp", "drying", "rack", "mug", "coffee", "table", "vanity", "towel",
          "if", "may", "put", "there", "where", "are", "has", ",", ".", "(", ")", "and", "we", "spares",
          "floor", ":", "which", "that", "lies", "left", "been", "someone", "-", "?", "contains"]


@settings(max_examples=200, deadline=None)
@given(st.lists(st.sampled_from(_WORDS), max_size=40))
def test_any_wording_gives_one_parseable_fact_per_known_object(words: list[str]) -> None:
    """Whatever the text, the reader names only the brief's roles, rooms and the floor, says at
    most one on/inside and one room per object (a room only beside the floor), and every fact
    parses in the condition language."""
    brief = _brief(" ".join(words), ["kitchen", "balcony"], lamp="table_lamp", nightstand="nightstand",
                   drying_rack="drying_rack", mug="mug", coffee_table="coffee_table",
                   vanity="bathroom_vanity", towel="towel")
    preds = [parse(f) for f in described_placements(brief, CATALOG)]
    assert all(isinstance(p, Pred) for p in preds)
    held = [p.args[0] for p in preds if isinstance(p, Pred) and p.name != "in_room"]
    rooms = [p.args[0] for p in preds if isinstance(p, Pred) and p.name == "in_room"]
    assert len(held) == len(set(held)) and len(rooms) == len(set(rooms))
    on_floor = {p.args[0] for p in preds if isinstance(p, Pred) and p.args[1] == "floor"}
    assert set(held) & set(rooms) <= on_floor
    for pred in preds:
        assert isinstance(pred, Pred) and pred.name in ("on", "inside", "in_room")
        assert pred.args[0] in brief["roles"] and pred.args[0] != pred.args[1]
        assert pred.args[1] in (brief["rooms"] if pred.name == "in_room" else [*brief["roles"], "floor"])


def test_a_possible_object_in_a_room_list_is_not_placed() -> None:
    brief = _brief("The flat has a kitchen with a stove and a sink, where a pan may be.", ["kitchen"],
                   stove="stove", sink="sink", pan="pan")
    facts = described_placements(brief, CATALOG)
    assert "in_room(stove, kitchen)" in facts and not [f for f in facts if "pan" in f]


def test_where_a_thing_is_kept_stays_askable_when_the_text_speaks_of_elsewhere() -> None:
    """"The remote is kept on the TV stand - wherever else it may be lying, bring it back there":
    where it belongs, not where it is."""
    brief = _brief("The TV remote is kept on the TV stand - wherever else it may be lying, bring it back there.",
                   ["living_room"], remote="remote_control", tv_stand="tv_stand")
    assert described_placements(brief, CATALOG) == ["on(remote, tv_stand)"]
    assert [f.id for f in analyse(brief).factors if f.subject == "remote"]


def test_described_placements_are_remembered_per_brief_and_kinds(monkeypatch: pytest.MonkeyPatch) -> None:
    """A brief is read once per (catalog, brief, kinds): the same facts as a fresh reading, a
    copy the caller may change, another brief or other kinds read anew."""
    from logicenveval.offline import placement

    brief = _brief("The bedroom has a bed and a nightstand with a lamp.", ["bedroom"],
                   bed="bed", nightstand="nightstand", lamp="table_lamp")
    fresh = placement._read(brief, CATALOG, placement.KINDS)
    readings: list[int] = []
    real = placement._read
    monkeypatch.setattr(placement, "_read", lambda *a: readings.append(1) or real(*a))
    monkeypatch.setattr(placement, "_READ", type(placement._READ)())
    first = described_placements(brief, CATALOG)
    first.append("changed by the caller")
    assert described_placements(dict(brief), CATALOG) == fresh
    assert "on(lamp, nightstand)" in fresh
    assert len(readings) == 1
    assert described_placements(brief, CATALOG, kinds=frozenset({"kept"})) == []
    other = _brief("The bedroom has a desk with a lamp.", ["bedroom"], desk="desk", lamp="table_lamp")
    assert "on(lamp, desk)" in described_placements(other, CATALOG)
    assert len(readings) == 3
    copy = CATALOG.model_copy(deep=True)  # another catalog object: read again
    assert described_placements(brief, copy) == fresh and len(readings) == 4


@pytest.mark.parametrize(("description", "roles", "factor"), [
    ("Document on the desk? A bill goes into the filing cabinet; any other document goes on the bookshelf.",
     {"desk": "desk", "document": "document", "filing_cabinet": "filing_cabinet", "bookshelf": "bookshelf"},
     {"bill": "attr(document, kind, bill)", "other": "not attr(document, kind, bill)"}),
    ("If there is a book on the desk: a cookbook goes on the wall shelf, every other book on the bookshelf.",
     {"desk": "desk", "book": "book", "shelf": "wall_shelf", "bookshelf": "bookshelf"},
     {"cookbook": "attr(book, kind, cookbook)", "other": "not attr(book, kind, cookbook)"}),
])
def test_an_indefinite_set_against_any_other_thing_is_a_kind_of_it(description: str, roles: dict[str, str],
                                                                   factor: dict[str, str]) -> None:
    """"A bill goes into the filing cabinet; any other document goes on the bookshelf": the bill is
    a kind of document (`analysis.CONTRAST`), asked like "if it is a bill"."""
    factors = analyse(_brief(description, ["study"], **roles), CATALOG).factors
    assert factor in [f.values for f in factors], [f.values for f in factors]
    plain = analyse(_brief("The document on the desk goes on the bookshelf.", ["study"], **roles), CATALOG)
    assert not [f for f in plain.factors if f.kind == "attr"]


@pytest.mark.parametrize(("description", "rooms", "roles", "standing"), [
    # dev2 (a kitchenette checklist): the coffee machine is no item of the dish rack
    ("Coffee machine: still on? -> switch OFF. Knife - if not in the dish rack, put it in.",
     ["kitchenette"], {"coffee_maker": "coffee_maker", "dish_rack": "dish_rack", "knife": "knife"},
     "dish_rack"),
    # written here: a toaster is no item of the dish rack either, nor a bowl
    ("Unplug the toaster if it is on. Rinse the bowl and leave it to dry in the drainer.",
     ["kitchen"], {"toaster": "toaster", "dish_rack": "dish_rack", "bowl": "bowl"}, "dish_rack"),
])
def test_an_appliance_that_stands_on_a_counter_holds_nothing_by_default(
        description: str, rooms: list[str], roles: dict[str, str], standing: str) -> None:
    """A thing that itself rests on a surface (its catalog placement is `surface`: a dish rack, a
    microwave) is no default surface for the other objects: stacking a coffee machine and a
    cutting board on a dish rack left no layout. A stated placement still puts a thing on it."""
    choice = realise(_brief(description, rooms, **roles), [], CATALOG)
    assert all(c.placement not in (f"on:{standing}", f"inside:{standing}") for c in choice.values())
    item, how = list(roles)[-1], "on" if CATALOG.categories[standing].surface else "inside"
    placed = realise(_brief(description, rooms, **roles), [f"{how}({item}, {standing})"], CATALOG)
    assert placed[item].placement == f"{how}:{standing}"


@pytest.mark.parametrize(("text", "roles", "fact"), [
    # dev4 porch_closing_recipe and one written here: a norm adverb with a verb of resting says
    # where a thing belongs, not where it is
    ("What's out there: a wooden bench and a bunch of flowers that normally sit on the bench.",
     {"flower": "flower", "bench": "bench"}, "on(flower, bench)"),
    ("The towel usually hangs on the towel rack.", {"towel": "towel", "towel_rack": "towel_rack"},
     "on(towel, towel_rack)"),
])
def test_a_norm_adverb_with_a_resting_verb_is_a_home(text: str, roles: dict[str, str], fact: str) -> None:
    brief = {"id": "t", "description": text, "rooms": ["living_room"],
             "roles": {r: {"category": c, "attributes": {}} for r, c in roles.items()}}
    catalog = load_catalog()
    assert fact in described_placements(brief, catalog, kinds=frozenset({"kept"}))
    assert fact not in described_placements(brief, catalog, kinds=frozenset({"settled"}))
    # without the adverb it is where the thing is now
    plain = dict(brief, description=text.replace("normally ", "").replace("usually ", ""))
    assert fact in described_placements(plain, catalog, kinds=frozenset({"settled"}))


@pytest.mark.parametrize(("text", "roles", "fact"), [
    # dev4 music_corner_note and two written here: a bracket telling which one by where it stands
    ("The desktop computer (the old one on the desk, the one we only use for recording) ought to be off.",
     {"desktop_computer": "desktop_computer", "desk": "desk"}, "on(desktop_computer, desk)"),
    ("The lamp (the one on the nightstand) should be off; if it is on, switch it off.",
     {"table_lamp": "table_lamp", "nightstand": "nightstand"}, "on(table_lamp, nightstand)"),
    ("The mug (the blue one in the sink, not the red one) needs washing.", {"mug": "mug", "sink": "sink"},
     "inside(mug, sink)"),
])
def test_an_identifying_aside_states_the_place(text: str, roles: dict[str, str], fact: str) -> None:
    brief = {"id": "t", "description": text, "rooms": ["living_room"],
             "roles": {r: {"category": c, "attributes": {}} for r, c in roles.items()}}
    assert fact in described_placements(brief, load_catalog(), kinds=frozenset({"settled"}))


def test_an_aside_without_a_place_places_nothing() -> None:
    brief = {"id": "t", "description": "The lamp (the one we bought on Sunday) is broken.", "rooms": ["bedroom"],
             "roles": {"table_lamp": {"category": "table_lamp", "attributes": {}}}}
    assert described_placements(brief, load_catalog()) == []
