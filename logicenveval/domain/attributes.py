"""The attribute keys an environment may state for a task (issue 46).

An object's `attributes` are read by the condition language's `attr(r, key, value)`; a key no
task condition, role and catalog category knows says nothing any task can read. Real replies put
their schema's words there (`"attributes": {"additionalProperties": ""}`: 9 of
Qwen2.5-Coder-1.5B's 11 scenes, with the same words in `states`), so such a key is a problem of
the environment, like an unknown state flag (`model.envspec.unknown_state_flags`).
"""

from __future__ import annotations

from logicenveval.domain.catalog import Catalog, per_catalog
from logicenveval.model.conditions import atoms, parse
from logicenveval.model.task import Task

#: the distinguishing attribute DESIGN.md §4 lets any role carry (`"purpose": "novels"`)
ALWAYS = frozenset({"purpose"})


@per_catalog
def catalog_attribute_keys(catalog: Catalog) -> frozenset[str]:
    """Every category's attribute domain keys, worked out once per catalog (the scorer asks for
    each environment it judges)."""
    return frozenset(key for category in catalog.categories.values() for key in category.attributes or {})


def attribute_keys(task: Task, catalog: Catalog) -> frozenset[str]:
    """The catalog's attribute domains (every category's), the task's roles' attributes and the
    keys its conditions (variables and constraints) read, and `ALWAYS`."""
    keys = set(ALWAYS) | catalog_attribute_keys(catalog)
    for role in task.roles.values():
        keys |= set(role.attributes)
    texts = [text for var in task.variables.values() for text in var.values.values()]
    texts += [c.fact for c in task.constraints]
    for text in texts:
        keys |= {p.args[1] for p in atoms(parse(text)) if p.name == "attr" and len(p.args) == 3}
    return frozenset(keys)
