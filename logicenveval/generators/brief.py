"""What a generator is given: as in the paper, the description only (the default), or the task's
roles (our variant).

`--brief description` (the paper's setting, the default since issue 34): id, description and
rooms; every method then asks its own model, as its first request, to name the objects the
description mentions (`name_objects`, one request kind shared by all methods so that the problem
setup is the same), and works with those names. The harness binds the task's roles to the
environment's objects afterwards (`domain.roles.bind_roles`), never the generator. All requests
then also carry the paper's few-shot example (`llm.fewshot`). `--brief roles` (ours, and the
oracle's): `task.brief()` — id, description, rooms and the named roles the policies use.

From request protocol 6 on, a named object's category is *retrieved by its name* when the two
contradict each other (`retrieve`), as the paper retrieves each object's asset from its textual
description (with CLIP, as Holodeck does); docs/llm.md "Request protocol 6".
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.domain.attributes import ALWAYS, catalog_attribute_keys
from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.domain.categories import Vocabulary, singular, vocabulary
from logicenveval.llm.ask import ask, protocol_of
from logicenveval.llm.base import ChatModel
from logicenveval.llm.vocab import Vocab
from logicenveval.model.task import Role, Task, TaskBrief

BriefMode = Literal["roles", "description"]
BRIEF_MODES: tuple[BriefMode, ...] = ("roles", "description")


class NamedObject(BaseModel):
    model_config = ConfigDict(frozen=True)
    name: str = Field(pattern=r"^[a-z][a-z0-9_]*$", description="snake_case name, unique")
    # bound to the catalog's kinds, as every later request's categories are: free, Qwen2.5-Coder-1.5B
    # named "container", "furniture", "tool" and "item", and every scene built on them failed
    category: Annotated[str, Vocab("categories")] = Field(min_length=1, description="asset catalog category")
    attributes: dict[str, str] = Field(default_factory=dict, description="attributes the text fixes")


class NamedObjectsReply(BaseModel):
    model_config = ConfigDict(frozen=True)
    objects: list[NamedObject] = Field(min_length=1)


@dataclass(frozen=True)
class Retrieved:
    """What retrieval changed in one named object's reply: its category (`said` -> `kept`), or
    attribute keys it dropped (`said` the keys, `kept` empty)."""

    name: str
    field: Literal["category", "attributes"]
    said: str
    kept: str


@dataclass(frozen=True)
class NamedBrief:
    """A generator's brief and what retrieval changed in the `name_objects` reply it rests on."""

    brief: TaskBrief
    retrieved: tuple[Retrieved, ...] = ()


def _head(name: str) -> str:
    """A compound's head is its last word (`water_bowl` is a bowl, `tv_remote` a remote)."""
    return singular(name).rsplit("_", 1)[-1]


def named_kind(obj: NamedObject, catalog: Catalog, words: Vocabulary) -> str | None:
    """The offered kind `obj`'s name names (`domain.categories`: key, synonym, plural), or None."""
    hit = words.resolve(obj.name).category
    return hit if hit is not None and catalog.categories[hit].rooms else None


def contradicts(obj: NamedObject, kind: str | None, words: Vocabulary) -> bool:
    """Whether the name names another kind than the category and its head word is the head of no
    name of the category: a `water_bowl` may be a `pet_bowl` and a `counter` a `kitchen_counter`;
    a `tv_remote` is no `television`, a `book` no `filing_cabinet`."""
    return kind is not None and kind != obj.category and \
        _head(obj.name) not in {_head(n) for n in words.names(obj.category)}


def retrieve(objects: Sequence[NamedObject], catalog: Catalog) -> tuple[dict[str, Role], list[Retrieved]]:
    """The roles named objects stand for, categories retrieved by their names where the reply's
    categories contradict most of its names.

    The paper's models describe an object and a retrieval picks its asset; here the reply picks a
    catalog kind itself, and a small model picks kinds its own names contradict (Qwen2.5-Coder-1.5B
    under protocol 5: `sofa`, `book`, `wet_mop` and four more all `filing_cabinet`; `plate` a
    `dishwasher` and `sponge` a `soap_bar` beside a right `counter`). Such a reply is not choosing
    kinds, and its names are the description retrieval reads. One contradiction among names that
    agree is a choice, and stands: a New Zealander's kitchen "bench" is its counter. Attribute
    keys no catalog domain knows (the schema's own words, `additionalProperties`, or a state
    written as an attribute) are dropped: no task reads them, and an environment stating them is
    ill-formed (`model.envspec.unknown_attribute_keys`)."""
    words = vocabulary(catalog)
    by_name: dict[str, NamedObject] = {}  # the first object of each name, in order
    for obj in objects:
        by_name.setdefault(obj.name, obj)
    first = list(by_name.values())
    kinds = {o.name: named_kind(o, catalog, words) for o in first}
    wrong = {o.name for o in first if contradicts(o, kinds[o.name], words)}
    retrieving = 2 * len(wrong) > sum(k is not None for k in kinds.values())
    known = ALWAYS | catalog_attribute_keys(catalog)
    roles: dict[str, Role] = {}
    changes: list[Retrieved] = []
    for obj in first:
        category = obj.category
        kind = kinds[obj.name]
        if retrieving and obj.name in wrong and kind is not None:
            changes.append(Retrieved(obj.name, "category", category, kind))
            category = kind
        attributes = {k: v for k, v in obj.attributes.items() if k in known}
        if len(attributes) < len(obj.attributes):
            changes.append(Retrieved(obj.name, "attributes",
                                     ", ".join(sorted(set(obj.attributes) - known)), ""))
        roles[obj.name] = Role(category=category, attributes=attributes)
    return roles, changes


def description_brief(task: Task) -> TaskBrief:
    """The paper's input: id, description and rooms; no roles."""
    return TaskBrief(id=task.id, description=task.description, rooms=task.rooms, roles={})


def generator_brief(task: Task, mode: BriefMode, model: ChatModel, *, seed: int | None = None,
                    catalog: Catalog | None = None) -> TaskBrief:
    """The brief a generator receives in `mode` (see `named_brief`)."""
    return named_brief(task, mode, model, seed=seed, catalog=catalog).brief


def named_brief(task: Task, mode: BriefMode, model: ChatModel, *, seed: int | None = None,
                catalog: Catalog | None = None) -> NamedBrief:
    """The brief a generator receives in `mode` (see the module docstring) and what retrieval
    changed in it. Under the description brief an object's category is one of the catalog's kinds
    (all of them: a text may name a kind generators are not offered unasked, a drawer)."""
    if mode == "roles":
        return NamedBrief(task.brief())
    brief = description_brief(task)
    catalog = catalog or load_catalog()
    kinds = sorted(catalog.categories)
    reply = ask(model, "name_objects", {"task": brief.model_dump(mode="json")}, NamedObjectsReply,
                seed=seed, vocabulary={"categories": kinds})
    if protocol_of(model) >= 6:
        roles, retrieved = retrieve(reply.objects, catalog)
        return NamedBrief(brief.model_copy(update={"roles": roles}), tuple(retrieved))
    roles = {}
    for obj in reply.objects:
        if obj.name not in roles:
            roles[obj.name] = Role(category=obj.category, attributes=dict(obj.attributes))
    return NamedBrief(brief.model_copy(update={"roles": roles}))
