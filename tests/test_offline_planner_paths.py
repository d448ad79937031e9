"""Paths combined (docs/reader.md, "Paths combined and the last structural losses (eleventh
session)"): factors whose instructions decide one thing's fate are asked in one subtask, so the
planner combines their values on one path. Each rule is tried on sentences written for the test in
two registers, with near misses that must stay apart; each test fails without its rule."""

from __future__ import annotations

from reading import CATALOG, brief

from logicenveval.offline.analysis import analyse


def _groups(text: str, rooms: tuple[str, ...]) -> list[list[str]]:
    return analyse(brief(text, rooms), CATALOG).groups


# -- an instruction that replaces one given before is asked in that instruction's subtask ----------


def test_an_instruction_said_instead_joins_the_subtask_it_replaces() -> None:
    # plain: the first instruction does not name the dishwasher, the second names the mug
    assert _groups("Should the mug be dirty, it is to be washed. If the dishwasher is running, the mug goes in "
                   "the sink instead.", ("kitchen",)) == [["mug_dirty", "dishwasher_toggled_on"]]
    # formal, "instead" inside the verb group and a "however" aside
    assert _groups("A wet towel is to be dried in the dryer. Whilst the dryer is running, however, the towel is "
                   "instead to be hung on the towel rack.", ("laundry_room",)) == [["towel_wet", "dryer_toggled_on"]]


def test_instead_split_off_as_an_alternative_also_replaces() -> None:
    # spoken, no comma after the condition: "instead" ends the sentence and is read as an `else`
    # clause; the pronoun names no mug, the first instruction names the dishwasher
    assert _groups("If the mug is dirty, it goes into the dishwasher. If the dishwasher is running you put it in "
                   "the sink instead.", ("kitchen",)) == [["mug_dirty", "dishwasher_toggled_on"]]


def test_a_following_condition_without_a_replacement_stays_its_own_subtask() -> None:
    # near misses: the second instruction acts on the machine itself, or on neither thing
    assert _groups("If the mug is dirty, it goes into the dishwasher. If the dishwasher is running, switch it off.",
                   ("kitchen",)) == [["mug_dirty"], ["dishwasher_toggled_on"]]
    assert _groups("A wet towel is to be dried. If the dryer is running, open the window.",
                   ("laundry_room",)) == [["towel_wet"], ["dryer_toggled_on"]]
    # "instead" alone does not join what neither instruction names
    assert _groups("A wet towel is to be dried. If the dryer is running, open the window instead.",
                   ("laundry_room",)) == [["towel_wet"], ["dryer_toggled_on"]]


def test_an_instruction_said_first_joins_the_subtask_it_prepares() -> None:
    # a house rule and a formal manual: the machine's instruction prepares the thing's move
    assert _groups("If the shirt is dirty, put it in the washing machine. If the washing machine is running, "
                   "switch it off first.", ("laundry_room",)) == [["shirt_dirty", "washing_machine_toggled_on"]]
    assert _groups("Should the mug be dirty, it belongs in the dishwasher. Where the dishwasher is running, let it "
                   "finish beforehand.", ("kitchen",)) == [["mug_dirty", "dishwasher_toggled_on"]]


def test_first_opening_a_clause_orders_steps_and_joins_nothing() -> None:
    assert _groups("If the plant is dry, water it. First, if the lamp is off, switch it on.",
                   ("study",)) == [["potted_plant_wet"], ["floor_lamp_toggled_on"]]
    # neither instruction names the other's thing
    assert _groups("If the shirt is dirty, wash it. If the washing machine is running, switch it off first.",
                   ("laundry_room",)) == [["shirt_dirty"], ["washing_machine_toggled_on"]]


# -- a verbless directive is an instruction to put the thing there ---------------------------------


def _goals(text: str, rooms: tuple[str, ...]) -> set[tuple[str, str]]:
    return {(f.subject, f.key) for c in analyse(brief(text, rooms), CATALOG).clauses for f in c.facts
            if f.goal and f.kind == "location"}


def test_a_place_with_it_is_an_instruction_to_put_it_there() -> None:
    # a note on the fridge, and a parent's shout: the elided verb of putting, its thing "with it"
    assert _goals("Mug on the desk? Into the sink with it.", ("kitchen",)) == {("mug", "sink")}
    assert _goals("Toys on the floor? Back in the toy box with them!", ("bedroom",)) == {("toy", "toy_box")}
    # the container's being open is then asked for that move, in the thing's subtask
    assert _groups("Left the milk on the table again? Into the fridge with it. The fridge might still be open, "
                   "so shut it after.", ("kitchen",)) == [["milk_carton_on_dining_table", "fridge_open"]]


def test_a_place_of_motion_after_a_question_answers_it() -> None:
    assert _goals("Shirt on the chair? Straight into the hamper.", ("bedroom",)) == {("shirt", "hamper")}
    assert _goals("Mug on the desk? Into the sink.", ("kitchen",)) == {("mug", "sink")}


def test_a_place_that_may_say_where_a_thing_is_stays_no_instruction() -> None:
    # "on" after a question may answer where the thing is; a verb of its own keeps its thing
    assert _goals("Where is the towel? On the rack.", ("bathroom",)) == set()
    assert _goals("Mug on the desk? Into the kitchen, then wash it.", ("kitchen",)) == set()


def test_an_alternative_of_its_own_condition_relates_to_nothing_before() -> None:
    # "else" with words of its own answers the sentence's own condition; a bare "instead" closing
    # the instruction replaces one said before
    from logicenveval.offline.analysis import _relates

    def relates(text: str, rooms: tuple[str, ...]) -> bool:
        a = analyse(brief(text, rooms), CATALOG)
        return _relates(max(c.sentence for c in a.clauses), a.clauses)

    assert not relates("Counter dirty? Wipe it with the sponge if the sponge is on the counter, else the dish cloth.",
                       ("kitchen",))
    assert not relates("Should the table be sticky, wipe it with the sponge if it is there, otherwise with the cloth.",
                       ("dining_room",))
    assert relates("If the dishwasher is running you put it in the sink instead.", ("kitchen",))
