"""What a generator is given: the task's roles (default) or, as in the paper, the description only.

`--brief roles` (default, DESIGN.md §4): `task.brief()` — id, description, rooms and the named
roles the policies use. `--brief description` (the paper's setting): id, description and rooms;
every method then asks its own model, as its first request, to name the objects the description
mentions (`name_objects`, one request kind shared by all methods so that the problem setup is the
same), and works with those names. The harness binds the task's roles to the environment's
objects afterwards (`domain.roles.bind_roles`), never the generator. All requests then also carry
the paper's few-shot example (`llm.fewshot`).
"""

from __future__ import annotations

import re
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.llm.ask import ask
from logicenveval.llm.base import ChatModel, ChatRequest
from logicenveval.llm.lexicon import COLOR_WORDS, tokens, words_of
from logicenveval.llm.offline import handler
from logicenveval.model.task import Role, Task, TaskBrief

BriefMode = Literal["roles", "description"]
BRIEF_MODES: tuple[BriefMode, ...] = ("roles", "description")


class NamedObject(BaseModel):
    model_config = ConfigDict(frozen=True)
    name: str = Field(pattern=r"^[a-z][a-z0-9_]*$", description="snake_case name, unique")
    category: str = Field(min_length=1, description="asset catalog category")
    attributes: dict[str, str] = Field(default_factory=dict, description="attributes the text fixes")


class NamedObjectsReply(BaseModel):
    model_config = ConfigDict(frozen=True)
    objects: list[NamedObject] = Field(min_length=1)


def description_brief(task: Task) -> TaskBrief:
    """The paper's input: id, description and rooms; no roles."""
    return TaskBrief(id=task.id, description=task.description, rooms=task.rooms, roles={})


def generator_brief(task: Task, mode: BriefMode, model: ChatModel, *, seed: int | None = None) -> TaskBrief:
    """The brief a generator receives in `mode` (see the module docstring)."""
    if mode == "roles":
        return task.brief()
    brief = description_brief(task)
    reply = ask(model, "name_objects", {"task": brief.model_dump(mode="json")}, NamedObjectsReply,
                seed=seed)
    roles: dict[str, Role] = {}
    for obj in reply.objects:
        if obj.name not in roles:
            roles[obj.name] = Role(category=obj.category, attributes=dict(obj.attributes))
    return brief.model_copy(update={"roles": roles})


@handler("name_objects")
def _offline_name_objects(payload: dict[str, Any], request: ChatRequest) -> dict[str, Any]:
    """Catalog categories and synonyms named in the description (longest match), with a colour
    word right before them as the colour attribute — what a careful reader would list."""
    return {"objects": name_objects(payload["task"]["description"], load_catalog())}


def name_objects(description: str, catalog: Catalog) -> list[dict[str, Any]]:
    phrases: dict[tuple[str, ...], str] = {}
    for name, cat in catalog.categories.items():
        for text in (name, *cat.synonyms):
            phrases.setdefault(words_of(text), name)
    longest = max(len(p) for p in phrases)
    words = [w for w, _, _ in tokens(description)]
    found: dict[str, dict[str, Any]] = {}
    i = 0
    while i < len(words):
        for n in range(min(longest, len(words) - i), 0, -1):
            category = phrases.get(tuple(words[i:i + n]))
            if category is None:
                continue
            color = words[i - 1] if i > 0 and words[i - 1] in COLOR_WORDS else None
            allowed = catalog.categories[category].attributes.get("color", [])
            attrs = {"color": color} if color is not None and color in allowed else {}
            name = re.sub(r"[^a-z0-9_]", "_", (f"{color}_" if attrs else "") + category)
            found.setdefault(name, {"name": name, "category": category, "attributes": attrs})
            i += n
            break
        else:
            i += 1
    return list(found.values())
