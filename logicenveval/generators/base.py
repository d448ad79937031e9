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
from pydantic import BaseModel, ConfigDict, Field, model_validator

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


class Attempt(BaseModel):
    """One environment a generator set out to build: the one it built, or why it could not.

    Attempts are the denominator of PhyPR and SceVR (docs/logic.md), so a generator cannot
    raise its scores by failing: a failed attempt fails every PhyPR dimension and is no valid
    scenario."""

    model_config = ConfigDict(frozen=True)
    #: the environment id the attempt was for (e.g. `logicenvgen-03`)
    id: str
    #: what it was to realise (a trajectory key, a draft's situation, an intent), for the reader
    target: str = ""
    #: the built environment's `env_id`; None when the attempt failed
    env_id: str | None = None
    #: where and why it failed (both None when built)
    stage: str | None = None
    reason: str | None = None

    @model_validator(mode="after")
    def _built_or_failed(self) -> Attempt:
        if (self.env_id is None) == (self.reason is None):
            raise ValueError(f"attempt {self.id!r} must have either env_id (built) or reason "
                             "(failed), not both or neither")
        return self

    @property
    def built(self) -> bool:
        return self.env_id is not None


class GenerationResult(BaseModel):
    model_config = ConfigDict(frozen=True)
    envs: list[EnvSpec] = Field(default_factory=list)
    #: JSON-serialisable artefacts (e.g. plan.json: subtasks, factors, trees, trajectories, log)
    artifacts: dict[str, Any] = Field(default_factory=dict)
    failures: list[GenerationFailure] = Field(default_factory=list)
    #: every environment the generator set out to build; empty: derived by `counted_attempts`
    attempts: list[Attempt] = Field(default_factory=list)
    #: a search that stopped at its budget and what was used instead (e.g. the exhaustive cover)
    budget_hit: str | None = None

    @model_validator(mode="after")
    def _attempts_match_envs(self) -> GenerationResult:
        if self.attempts:
            built = sorted(a.env_id for a in self.attempts if a.env_id is not None)
            returned = sorted(e.env_id for e in self.envs)
            if built != returned:
                raise ValueError(f"the built attempts name environments {built[:5]} but the result "
                                 f"holds {returned[:5]}: list one built attempt per returned environment")
        return self


def counted_attempts(result: GenerationResult) -> list[Attempt]:
    """The attempts a unit counts (docs/own-generator.md): the declared ones; for a generator that
    declares none, one per returned environment plus one per distinct `env_id` of a failure that
    names no returned environment. At least one: a generator that returns nothing has failed
    the one environment it was asked for."""
    if result.attempts:
        return list(result.attempts)
    out = [Attempt(id=e.env_id, env_id=e.env_id) for e in result.envs]
    built = {e.env_id for e in result.envs}
    for f in result.failures:
        if f.env_id is not None and f.env_id not in built:
            built.add(f.env_id)
            out.append(Attempt(id=f.env_id, stage=f.stage, reason=f.message))
    if not out:
        first = result.failures[0] if result.failures else None
        out.append(Attempt(id="environment", stage=first.stage if first else "generate",
                           reason=first.message if first else "the generator returned no environment"))
    return out


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
    #: how many environments the generator plans to build, once it knows (`plan_attempts`)
    planned_attempts: int = 0

    def plan_attempts(self, n: int) -> None:
        """Announce how many environments this generation sets out to build: if it then fails
        as a whole (an exception), the unit counts that many failed attempts (at least one)."""
        self.planned_attempts = max(0, int(n))


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
