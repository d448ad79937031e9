"""What a generator is given: as in the paper, the description only (the default), or the task's
roles (our variant).

`--brief description` (the paper's setting, the default since issue 34): id, description and
rooms; every method then asks its own model, as its first request, to name the objects the
description mentions (`name_objects`, one request kind shared by all methods so that the problem
setup is the same), and works with those names. The harness binds the task's roles to the
environment's objects afterwards (`domain.roles.bind_roles`), never the generator. All requests
then also carry the paper's few-shot example (`llm.fewshot`). `--brief roles` (ours, and the
oracle's): `task.brief()` — id, description, rooms and the named roles the policies use.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.llm.ask import ask
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


def description_brief(task: Task) -> TaskBrief:
    """The paper's input: id, description and rooms; no roles."""
    return TaskBrief(id=task.id, description=task.description, rooms=task.rooms, roles={})


def generator_brief(task: Task, mode: BriefMode, model: ChatModel, *, seed: int | None = None,
                    catalog: Catalog | None = None) -> TaskBrief:
    """The brief a generator receives in `mode` (see the module docstring). Under the description
    brief an object's category is one of the catalog's kinds (all of them: a text may name a kind
    generators are not offered unasked, a drawer)."""
    if mode == "roles":
        return task.brief()
    brief = description_brief(task)
    kinds = sorted((catalog or load_catalog()).categories)
    reply = ask(model, "name_objects", {"task": brief.model_dump(mode="json")}, NamedObjectsReply,
                seed=seed, vocabulary={"categories": kinds})
    roles: dict[str, Role] = {}
    for obj in reply.objects:
        if obj.name not in roles:
            roles[obj.name] = Role(category=obj.category, attributes=dict(obj.attributes))
    return brief.model_copy(update={"roles": roles})
