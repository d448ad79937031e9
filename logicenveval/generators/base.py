"""The generator interface and registry (Gymnasium-style `make` with lazy import).

A generator receives only a `TaskBrief` (never GT trees or policies) and a context holding the
chat model, the catalog and the run's random generator, and returns EnvSpecs plus a log of what
it did and where it failed, so that a missed decision path can be traced to its stage.
"""

from __future__ import annotations

import importlib
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from logicenveval.domain.catalog import Catalog
from logicenveval.errors import ConfigError
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import TaskBrief
from logicenveval.scene.layout import DEFAULT_SOLVER, Solver


class GenerationFailure(BaseModel):
    """A recorded, explained failure of one stage (e.g. `decompose`, `layout`)."""

    model_config = ConfigDict(frozen=True)
    stage: str
    message: str
    env_id: str | None = None


class GenerationResult(BaseModel):
    model_config = ConfigDict(frozen=True)
    envs: list[EnvSpec] = Field(default_factory=list)
    #: JSON-serialisable artefacts (e.g. plan.json: subtasks, factors, trees, trajectories, log)
    artifacts: dict[str, Any] = Field(default_factory=dict)
    failures: list[GenerationFailure] = Field(default_factory=list)


@dataclass
class GenerationContext:
    """Everything a generator may use besides the brief."""

    model: Any  # logicenveval.llm.base.ChatModel (kept Any to keep this module import-light)
    catalog: Catalog
    rng: np.random.Generator
    seed: int = 0
    #: folder where the generator may write debugging artefacts (raw replies, renders); optional
    work_dir: Path | None = None
    #: layout backend for generators that construct scenes with the solver (docs/scene.md)
    layout_solver: Solver = DEFAULT_SOLVER
    options: dict[str, Any] = field(default_factory=dict)


class Generator(Protocol):
    name: str

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult: ...


#: name -> "module:attribute"; the attribute is a class or factory taking keyword options
_REGISTRY: dict[str, str] = {}


def register(name: str, entry_point: str) -> None:
    """Register a generator by name (`module:attr`), imported only when first made."""
    _REGISTRY[name] = entry_point


#: old name -> current name; using an old name works and warns
_ALIASES: dict[str, str] = {}


def register_alias(old: str, new: str) -> None:
    """Keep an old generator name working (with a FutureWarning) after a rename."""
    _ALIASES[old] = new


def canonical_name(name: str) -> str:
    """The current name of a generator; warns (FutureWarning) when `name` is an old alias."""
    _load_builtin()
    if name in _ALIASES and name not in _REGISTRY:
        new = _ALIASES[name]
        warnings.warn(f"generator {name!r} is an old name of {new!r}; use {new!r}",
                      FutureWarning, stacklevel=2)
        return new
    return name


def registered() -> list[str]:
    _load_builtin()
    return sorted(_REGISTRY)


def make_generator(name: str, **options: Any) -> Generator:
    name = canonical_name(name)
    if name not in _REGISTRY:
        raise ConfigError(f"unknown generator {name!r}", field="--generators",
                          hint="use one of " + ", ".join(sorted(_REGISTRY)))
    module_name, attr = _REGISTRY[name].split(":")
    factory = getattr(importlib.import_module(module_name), attr)
    gen: Generator = factory(**options)
    return gen


def _load_builtin() -> None:
    """Import the modules that register the built-in generators (cheap: no heavy imports)."""
    importlib.import_module("logicenveval.generators.registry")
