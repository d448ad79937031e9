"""The words of a protocol-3 scene request (`replies.SelectionWire`): what each role's object may
be and where it may rest, from the task's roles and the catalog. LogicEnvGen's `select_objects`
and Holodeck-like's scene ask the same way (the paper gives every method the same setup)."""

from __future__ import annotations

import re
from collections.abc import Sequence

from logicenveval.domain.catalog import Catalog, Category
from logicenveval.llm.vocab import Pattern, Words
from logicenveval.model.task import TaskBrief

#: the id of an object that plays no role in a protocol-3 selection: a name and a number
#: (`sofa_1`), so that a placement can name it and never the role object placed
OTHER_ID = r"[a-z][a-z0-9_]{0,36}_[0-9]{1,2}"


def selection_words(brief: TaskBrief, required: Sequence[str], catalog: Catalog) -> dict[str, Words]:
    """The words of a protocol-3 selection (`replies.SelectionWire`): each role's object is of the
    role's category (`categories@<role>`) and rests (`placements@<role>`) on the floor, on a wall
    or the ceiling where the catalog lets its category hang, and, unless it is furniture
    (`furniture`), on another role that is a surface, inside another role that is a container,
    or on or inside an object that plays no role, whose ids are a name and a number: never on
    itself, nor on a category's name. Qwen2.5-Coder-1.5B put every object of a kitchen, the
    counter and the dishwasher included, `on:kitchen_counter`."""
    words: dict[str, Words] = {"object_ids": Pattern(f"^{OTHER_ID}$")}
    targets = sorted(required)
    words["placements"] = Pattern(
        f"^(floor|wall|ceiling|(on|inside):({'|'.join(map(re.escape, targets)) + '|' if targets else ''}{OTHER_ID}))$")
    for role in required:
        category = brief.roles[role].category
        c = catalog.get(category)
        # a role of a category the catalog lacks (the model's own analysis named it, under the
        # description brief) gets no category to bind, but still never rests on itself: left to
        # the generic pattern, Qwen2.5-Coder-1.5B put its `counter` role `inside:counter` in every
        # attempt, which the grammar allowed and the validator refused
        options = ["floor", *(k for k in ("wall", "ceiling") if c is None or k in c.placement)]
        if c is not None:
            words[f"categories@{role}"] = [category]
            if furniture(c):  # it holds things and stands where its category stands
                words[f"placements@{role}"] = Pattern(f"^({'|'.join(options)})$")
                continue
        options += [f"on:{r}" for r in targets if r != role and _holds(catalog, brief, r, "surface")]
        options += [f"inside:{r}" for r in targets if r != role and _holds(catalog, brief, r, "container")]
        words[f"placements@{role}"] = Pattern(f"^({'|'.join(map(re.escape, options))}|(on|inside):{OTHER_ID})$")
    return words


def furniture(c: Category) -> bool:
    """A category that holds things and is not carried, placed only on the floor, a wall or the
    ceiling (a counter, a sink, a dishwasher): its object rests on nothing. Given a way to name
    any other object, Qwen2.5-Coder-1.5B put its counter `on:counterery_household_..._1`."""
    return not c.pickable and (c.surface or c.container) and set(c.placement) <= {"floor", "wall", "ceiling"}


def _holds(catalog: Catalog, brief: TaskBrief, role: str, how: str) -> bool:
    c = catalog.get(brief.roles[role].category)
    return c is not None and bool(getattr(c, how))
