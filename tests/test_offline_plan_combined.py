"""Values set, paths not combined (nineteenth session): the reader asked every factor value a task's
trees need, but read a condition flat that is asked only on another's branch, so the planner's
cover (each subtask's paths once) never put the two together (dev 29 `bedroom_nightstand_reset_d29`,
dev 33 `lamp_or_pillow_fetch_d33`). The structure: a condition, alone in its sentence, on the thing
the instruction just before brings, sends or puts something into under a branch of its own
("If there's a pan, bring me the lamp. If it's on, switch it off first"), with at most a
listener's aside between (`analysis._taken_up_under`).

Each text is composed here, in several registers, rooms and kinds, with the tree paths a task's
author would write (each path: the conditions met on it, in asking order). The planner covers
every leaf of each subtask's tree, so an author's path set is sure to be covered when one tree's
leaves hold all of it. Measured on main before the rule (10 texts of the structure: 6 nested, 3
lists of cases, 1 checklist): the author's paths were sure to be covered in 6 (the inner condition
already in the outer's subtask, but as the full cross product of both factors, asking it where it
means nothing), in the other 4 it was a subtask of its own, so which outer value it met was the
cover's chance; none had exactly the author's paths. After it all 10 have them, and the 7 near
misses are unchanged. (The rule first took every condition of the sentence before; a first
`--compare` showed two falls, a list's cases in one sentence and a checklist's case by place and
state, so it takes the case that names the thing, tested here by the last two tables.)"""

from __future__ import annotations

from typing import Any

import pytest
from reading import CATALOG, brief

from logicenveval.offline.analysis import analyse, nest


def _leaves(node: dict[str, Any], values: dict[str, dict[str, str]], path: tuple[str, ...] = ()) -> set[tuple[str, ...]]:
    """A tree's root-to-leaf paths, each the conditions of the values taken on it."""
    if "var" not in node:
        return {path}
    return {leaf for value, child in node["branches"].items()
            for leaf in _leaves(child, values, (*path, values[node["var"]][value]))}


def _paths(task: dict[str, Any], condition: str) -> set[tuple[str, ...]]:
    """The root-to-leaf paths (each value's condition, in asking order) of the subtask that asks
    `condition`."""
    a = analyse(task, CATALOG)
    by_id = {f.id: f for f in a.factors}
    for group in a.groups:
        if any(condition in by_id[i].values.values() for i in group):
            return _leaves(nest([by_id[i] for i in group]), {i: by_id[i].values for i in group})
    return set()


def _on(outer: str, inner: str, *, outer_holds: bool = True) -> set[tuple[str, ...]]:
    """The paths of `inner` asked only where `outer` holds (or, `outer_holds=False`, does not)."""
    on, off = (outer, f"not {outer}") if outer_holds else (f"not {outer}", outer)
    return {(on, inner), (on, f"not {inner}"), (off,)}


#: (text, rooms, the outer condition, the inner one, whether the inner is asked where the outer
#: holds): the inner condition is asked only on the outer's branch
NESTED = [
    # an astronomer's observing plan: a labelled target under a condition in brackets
    ("PLAN A (a mug on the desk): the kettle from the kitchen. If it's full, empty it first.\n"
     "PLAN B (no mug on the desk): the teapot, from the kitchen.", ("kitchen", "office"),
     "on(mug, desk)", "state(kettle, filled)", True),
    # a plain note, the fetched thing taken up by "it"
    ("If there's a pan in the kitchen, bring me the desk lamp from the study. If it's on, switch it off first.",
     ("kitchen", "study"), "in_room(pan, kitchen)", "state(desk_lamp, toggled_on)", True),
    # a lower-case text message without commas
    ("if the kettle's on the stove grab the mug from the cupboard. if it's dirty wash it first", ("kitchen",),
     "on(kettle, stove)", "state(mug, dirty)", True),
    # a radio play: a listener's aside between the instruction and the condition on its thing
    ("MAYA: If the bath is full, put the towel on the rail.\nLEO: The rail wobbles.\n"
     "MAYA: If the towel is wet, hang it on the radiator instead.", ("bathroom",),
     "state(bathtub, filled)", "state(towel, wet)", True),
    # a formal request, the branch's condition put after its instruction
    ("Bring me the desk lamp from the study if there's a pan in the kitchen. If it's on, switch it off first.",
     ("kitchen", "study"), "in_room(pan, kitchen)", "state(desk_lamp, toggled_on)", True),
    # a pet-sitter's note: the instruction's branch is the condition's "no" (an empty bowl)
    ("If the dog bowl is empty, grab the bag of dog food from the pantry. If it's open, close it after.",
     ("kitchen",), "state(pet_bowl, filled)", "state(pet_food, open)", False),
]


@pytest.mark.parametrize(("text", "rooms", "outer", "inner", "holds"), NESTED)
def test_a_condition_on_the_thing_an_instruction_brings_is_asked_on_its_branch(
        text: str, rooms: tuple[str, ...], outer: str, inner: str, holds: bool) -> None:
    assert _paths(brief(text, rooms), inner) == _on(outer, inner, outer_holds=holds)


def _task(text: str, roles: dict[str, str], rooms: tuple[str, ...]) -> dict[str, Any]:
    """A brief with its roles given (a list of cases is read over the task's own objects)."""
    return {"id": "t", "description": text, "rooms": list(rooms),
            "roles": {name: {"category": kind} for name, kind in roles.items()}}


#: a list of cases by a thing's kind, then a condition on the container the last case puts it
#: into: (text, roles, rooms, the kind factor's condition of that case, the container's condition)
CASES = [
    # a radio play, the listener's remark between
    ("Novels go on the bookshelf. Textbooks go on the desk. Any other book goes into the nightstand drawer.\n"
     "JO: That drawer sticks.\nANN: Then open it, unless it's already open, and close it afterwards.",
     {"book": "book", "bookshelf": "bookshelf", "desk": "desk", "nightstand": "nightstand"}, ("bedroom",),
     "attr(book, kind, novel)", "state(nightstand, open)"),
    # a laundry rota, terse, the condition in the next sentence
    ("White shirts go in the wardrobe. Any other shirt goes into the washing machine. "
     "If it's closed, open it first.",
     {"shirt": "shirt", "wardrobe": "wardrobe", "washing_machine": "washing_machine"}, ("bedroom",),
     "attr(shirt, color, white)", "state(washing_machine, open)"),
    # an incident report's action item, the cases in one sentence after arrows
    ("Sort it by type: a novel -> the bookshelf; a textbook -> the desk; any other book -> the nightstand "
     "drawer. Open the drawer unless it's already open.",
     {"book": "book", "bookshelf": "bookshelf", "desk": "desk", "nightstand": "nightstand"}, ("bedroom",),
     "attr(book, kind, textbook)", "state(nightstand, open)"),
]


#: a checklist's cases by a thing's place and state, then a condition on where the last case puts
#: it: the place says which thing, the state is the case (text, roles, rooms, the case's state, the
#: container's condition)
PLACED_CASES = [
    ("Shirt on the floor and dirty: it goes into the hamper.\nShirt on the floor and clean: hang it in "
     "the wardrobe.\nIs the wardrobe shut? Then open it first.",
     {"shirt": "shirt", "hamper": "laundry_hamper", "wardrobe": "wardrobe"}, ("bedroom",),
     "state(shirt, dirty)", "state(wardrobe, open)"),
]


@pytest.mark.parametrize(("text", "roles", "rooms", "case", "inner"), PLACED_CASES)
def test_a_condition_after_a_placed_case_is_asked_in_its_state(
        text: str, roles: dict[str, str], rooms: tuple[str, ...], case: str, inner: str) -> None:
    assert _paths(_task(text, roles, rooms), inner) == _on(case, inner, outer_holds=False)


@pytest.mark.parametrize(("text", "roles", "rooms", "named", "inner"), CASES)
def test_a_condition_on_the_last_cases_container_is_asked_in_that_case(
        text: str, roles: dict[str, str], rooms: tuple[str, ...], named: str, inner: str) -> None:
    paths = _paths(_task(text, roles, rooms), inner)
    asking = [p for p in paths if inner in p or f"not {inner}" in p]
    # the container's state is asked on the "any other" case's paths only, both ways
    assert len(asking) == 2 and all(named not in p for p in asking), paths
    assert any(named in p and inner not in p and f"not {inner}" not in p for p in paths), paths


#: near misses: the condition's thing is not what the instruction before deals with, or that
#: instruction has no branch, or the condition restates the same thing's: asked in every situation
#: (text, rooms, the condition, its paths)
NEAR_MISSES = [
    ("If the bed is unmade, make it. If the lamp is on, switch it off.", ("bedroom",),
     "state(table_lamp, toggled_on)"),
    ("Bring me the lamp from the study. If it's on, switch it off first.", ("study",),
     "state(floor_lamp, toggled_on)"),
    ("If the mug is dirty, wash it. If it's chipped, throw it away.", ("kitchen",), "state(mug, dirty)"),
    ("Should the kettle be on the stove, bring me a mug. If the towel is wet, hang it up.", ("kitchen",),
     "state(towel, wet)"),
    ("If the pan is on the stove, bring me the lamp. The plant may be wet: if it is, dry it.",
     ("kitchen",), "state(potted_plant, wet)"),
    # where the thing is sent, with a case of its own (not its opening for the thing)
    ("If the shirt is dirty, it goes in the hamper. If the hamper is full, empty it.", ("bedroom",),
     "state(hamper, filled)"),
    ("plate dirty? into the dishwasher with it. dishwasher running? switch it off", ("kitchen",),
     "state(dishwasher, toggled_on)"),
]


@pytest.mark.parametrize(("text", "rooms", "condition"), NEAR_MISSES)
def test_a_condition_on_another_thing_stays_asked_everywhere(text: str, rooms: tuple[str, ...],
                                                             condition: str) -> None:
    assert _paths(brief(text, rooms), condition) == {(condition,), (f"not {condition}",)}


#: a sentence saying the branch's fact both ways (a case and its opposite, or a misread negation)
#: names no one branch: the condition after it stays as read, across both cases (a cross product,
#: which covers the author's paths): (text, rooms, the outer condition, the inner one)
BOTH_WAYS = [
    ("If the mug is dirty, wash it in the sink; if it is clean, leave it. If the sink is full, empty it first.",
     ("kitchen",), "state(mug, dirty)", "state(sink, filled)"),
]


@pytest.mark.parametrize(("text", "rooms", "outer", "inner"), BOTH_WAYS)
def test_a_sentence_of_both_cases_sets_no_branch(text: str, rooms: tuple[str, ...], outer: str, inner: str) -> None:
    assert _paths(brief(text, rooms), inner) == {(o, i) for o in (outer, f"not {outer}")
                                                 for i in (inner, f"not {inner}")}
