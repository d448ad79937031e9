"""What the offline reader makes of a text, for the reader's rule tests: the brief the offline
model builds from its own naming (roles named as it names them, the first naming of a name kept),
the factors it asks and the placements it reads as stated. One copy, so that every rule test reads
a sentence the way the model does."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

from logicenveval.domain.catalog import load_catalog
from logicenveval.offline.analysis import analyse, nest
from logicenveval.offline.naming import name_objects
from logicenveval.offline.placement import described_placements

CATALOG = load_catalog()


def brief(text: str, rooms: tuple[str, ...]) -> dict[str, Any]:
    roles: dict[str, Any] = {}
    for o in name_objects(text, CATALOG, rooms=rooms):
        roles.setdefault(o["name"], {"category": o["category"], "attributes": o["attributes"]})
    return {"id": "t", "description": text, "rooms": list(rooms), "roles": roles}


def factors(text: str, rooms: tuple[str, ...]) -> dict[str, set[str]]:
    """factor id -> the conditions of its values."""
    return {f.id: set(f.values.values()) for f in analyse(brief(text, rooms), CATALOG).factors}


def named(text: str, rooms: tuple[str, ...] = ("studio",)) -> dict[str, tuple[str, dict[str, str]]]:
    """The objects the offline model names in `text`: name -> (category, attributes)."""
    return {o["name"]: (o["category"], o["attributes"]) for o in name_objects(text, CATALOG, rooms=rooms)}


def kinds(text: str, rooms: tuple[str, ...] = ("studio",)) -> set[str]:
    """The categories of the objects the offline model names in `text`."""
    return {category for category, _ in named(text, rooms).values()}


def asks(text: str, rooms: tuple[str, ...], condition: str) -> bool:
    """Whether some factor of `text` has `condition` and its negation among its values."""
    return any({condition, f"not {condition}"} <= values for values in factors(text, rooms).values())


def placed(text: str, rooms: tuple[str, ...]) -> set[str]:
    """The placements the text states (`on(x, y)`, `inside(x, y)`, `in_room(x, r)`)."""
    return set(described_placements(brief(text, rooms), CATALOG))


def forms_named(path: Path, rooms: tuple[str, ...] = ()) -> int:
    """How many sentences of a naming-forms file (tests/data/naming_forms/: tab-separated kind,
    form, sentence; "#" comments) name their row's kind, for the files' floors."""
    count = 0
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            kind, _, sentence = line.split("\t")
            count += kind in {o["category"] for o in name_objects(sentence, CATALOG, rooms=rooms)}
    return count


def instruction_under(text: str, rooms: tuple[str, ...], condition: str) -> dict[str, str]:
    """The plan `analysis.nest` builds under each value of the condition's factor, joined ("yes":
    under the condition, "no": under its negation); shared by the comma-less condition tests."""
    asked = [f for f in analyse(brief(text, rooms), CATALOG).factors
             if {condition, f"not {condition}"} <= set(f.values.values())]
    if not asked:
        return {}
    tree = nest([replace(asked[0], context=[])])
    return {("yes" if cond == condition else "no"): " ".join(tree["branches"][v].get("plan") or []).lower()
            for v, cond in asked[0].values.items()}
