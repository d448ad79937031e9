"""The generator interface and registry (Gymnasium-style `make` with lazy import).

A generator receives only a `TaskBrief` (never GT trees or policies) and a context holding the
chat model, the catalog and the run's random generator, and returns EnvSpecs plus a log of what
it did and where it failed, so that a missed decision path can be traced to its stage.
"""

from __future__ import annotations

import hashlib
import importlib
import warnings
from collections.abc import Callable
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


def unit_seed(seed: int, generator: str, task_id: str) -> list[int]:
    """The seed sequence of a unit's `GenerationContext.rng`, independent of scheduling: the run
    seed and stable hashes of the unit's names (`run`, `generate` and tests use the same)."""
    digest = hashlib.sha256(f"{generator}\0{task_id}".encode()).digest()
    return [seed, int.from_bytes(digest[:8], "little")]


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


#: name -> "module:attribute" (imported when first made) or the factory itself
_REGISTRY: dict[str, str | Callable[..., Any]] = {}


def register(name: str, entry_point: str | Callable[..., Any]) -> None:
    """Register a generator by name: `module:attr` (imported only when first made) or a factory."""
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


def registry_entry(name: str) -> str | Callable[..., Any] | None:
    """What `name` was registered with, or None."""
    _load_builtin()
    return _REGISTRY.get(name)


def make_generator(name: str, **options: Any) -> Generator:
    """Make a registered generator (old names via their alias), or import a `module:attr` target
    (see generators.plugins)."""
    name = canonical_name(name)
    entry = _REGISTRY.get(name)
    if entry is None and ":" in name:
        entry = name
    if entry is None:
        raise ConfigError(f"unknown generator {name!r}", field="--generators",
                          hint="use one of " + ", ".join(sorted(_REGISTRY))
                          + ", a PKG.MODULE:ATTR, or an installed plug-in (docs/own-generator.md)")
    factory = import_target(entry) if isinstance(entry, str) else entry
    gen: Generator = factory(**options)
    return gen


def import_target(target: str) -> Callable[..., Any]:
    """The object `module:attr` (attr may be dotted) names; a clear error when it cannot be imported."""
    module_name, _, attr = target.partition(":")
    if not module_name or not attr:
        raise ConfigError(f"generator {target!r} is not MODULE:ATTR", field="--generators",
                          hint="write it as package.module:ClassOrFactory")
    try:
        obj: Any = importlib.import_module(module_name)
    except ImportError as exc:
        raise ConfigError(f"cannot import module {module_name!r} of generator {target!r}: {exc}",
                          field="--generators",
                          hint="check the spelling, install the package, or run from the folder "
                          "that holds the module (it is imported from the current Python path)"
                          ) from None
    for part in attr.split("."):
        if not hasattr(obj, part):
            raise ConfigError(f"module {module_name!r} has no attribute {attr!r}",
                              field="--generators",
                              hint=f"name a class or factory defined in {module_name}")
        obj = getattr(obj, part)
    if not callable(obj):
        raise ConfigError(f"generator {target!r} is not callable", field="--generators",
                          hint="point at a generator class or a factory function")
    factory: Callable[..., Any] = obj
    return factory


def _load_builtin() -> None:
    """Import the modules that register the built-in generators (cheap: no heavy imports)."""
    importlib.import_module("logicenveval.generators.registry")
