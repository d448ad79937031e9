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
from logicenveval.generators.registry import ALIASES, BUILTIN
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
    #: whether the built environment realises the trajectory the generator set out to realise,
    #: in the generator's own plan, as the generator checked it (`realised_share` in
    #: results.json); None when it claims none or was not built
    realised: bool | None = None

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


def make_generator(name: str, /, **options: Any) -> Generator:
    """Make a registered generator (old names via their alias), or import a `module:attr` target
    (see generators.plugins). `name` is positional-only, so a factory may take a `name` keyword
    argument of its own (`--generator-args MOD:ATTR:name=...`)."""
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


class Overdue(BaseException):
    """Raised inside plug-in code when its time bound passes (`--unit-timeout`).

    A BaseException, so a plug-in's own `except Exception` does not swallow it; the loading
    boundary lets it through too."""


def import_target(target: str) -> Callable[..., Any]:
    """The object `module:attr` (attr may be dotted) names: the one boundary where plug-in code
    is imported (`run`, `generate`, workers and anything that fingerprints a plug-in use it).

    Whatever the module does while being imported or looked up — a syntax error, raising,
    `sys.exit`, a module `__getattr__` that raises — is one `ConfigError` (exit 2) naming the
    module and the file and line where it happened; a relative form (`.mod:G`) is refused before
    anything is imported. A real Ctrl-C still stops the caller."""
    module_name, _, attr = target.partition(":")
    if not module_name or not attr:
        raise ConfigError(f"generator {target!r} is not MODULE:ATTR", field="--generators",
                          hint="write it as package.module:ClassOrFactory")
    if module_name.startswith("."):
        raise ConfigError(f"generator {target!r} names a relative module", field="--generators",
                          hint="write the module's absolute dotted path, as imported from the "
                          "current folder (e.g. my_pkg.module:MyGenerator)")
    if not all(part.isidentifier() for part in module_name.split(".")):
        raise ConfigError(f"{module_name!r} of generator {target!r} is not a dotted module path",
                          field="--generators", hint="write it as package.module:ClassOrFactory")
    obj: Any = _import_module(module_name, target)
    for part in attr.split("."):
        try:
            obj = getattr(obj, part)
        except AttributeError:
            raise ConfigError(f"module {module_name!r} has no attribute {attr!r}",
                              field="--generators",
                              hint=f"name a class or factory defined in {module_name}") from None
        except (KeyboardInterrupt, Overdue):
            raise
        except BaseException as exc:  # a module __getattr__ or a class property that raises
            file, line = plugin_frame(exc)
            raise ConfigError(f"looking up {attr!r} in module {module_name!r} raised {said(exc)}",
                              file=file, line=line, field="--generators",
                              hint="fix the plug-in at that line") from None
    if not callable(obj):
        raise ConfigError(f"generator {target!r} is not callable", field="--generators",
                          hint="point at a generator class or a factory function")
    factory: Callable[..., Any] = obj
    return factory


def _import_module(module_name: str, target: str) -> Any:
    try:
        return importlib.import_module(module_name)
    except (KeyboardInterrupt, Overdue):
        raise
    except SyntaxError as exc:  # also IndentationError, TabError
        raise ConfigError(f"module {module_name!r} of generator {target!r} has a syntax error: "
                          f"{exc.msg}", file=exc.filename, line=exc.lineno, field="--generators",
                          hint="fix the syntax at that line") from None
    except ModuleNotFoundError as exc:
        if exc.name and (module_name + ".").startswith(exc.name + "."):  # it, or its package
            raise ConfigError(f"cannot import module {module_name!r} of generator {target!r}: "
                              f"{said(exc, False)}", field="--generators",
                              hint="check the spelling, install the package, or run from the folder "
                              "that holds the module (it is imported from the current Python path)"
                              ) from None
        file, line = plugin_frame(exc)
        raise ConfigError(f"module {module_name!r} of generator {target!r} imports a missing "
                          f"module: {said(exc, False)}", file=file, line=line, field="--generators",
                          hint=f"install {exc.name!r} or fix the import at that line") from None
    except SystemExit as exc:
        file, line = plugin_frame(exc)
        raise ConfigError(f"module {module_name!r} of generator {target!r} called "
                          f"sys.exit({_short(exc.code)}) while being imported", file=file, line=line,
                          field="--generators",
                          hint="a plug-in module must not exit when imported; guard script code "
                          "with `if __name__ == \"__main__\":`") from None
    except BaseException as exc:
        file, line = plugin_frame(exc)
        raise ConfigError(f"importing module {module_name!r} of generator {target!r} raised "
                          f"{said(exc)}", file=file, line=line, field="--generators",
                          hint="fix the plug-in at that line; importing it must not fail") from None


def plugin_frame(exc: BaseException) -> tuple[str | None, int | None]:
    """File and line of the innermost frame of `exc` in real source (not the import machinery)."""
    found: tuple[str | None, int | None] = (None, None)
    tb = exc.__traceback__
    while tb is not None:
        name = tb.tb_frame.f_code.co_filename
        if not name.startswith("<") and "importlib" not in Path(name).parts:
            found = (name, tb.tb_lineno)
        tb = tb.tb_next
    return found


def said(exc: BaseException, with_type: bool = True) -> str:
    """`Type: message` of a plug-in's exception, short, even when its `__str__` raises."""
    try:
        text = str(exc)
    except Exception:
        text = "<unprintable>"
    text = _short(text, quote=False)
    return f"{type(exc).__name__}: {text}" if with_type else text


def _short(value: object, quote: bool = True, n: int = 200) -> str:
    try:
        text = repr(value) if quote else str(value)
    except Exception:
        text = "<unprintable>"
    text = " ".join(text.split())
    return text if len(text) <= n else text[:n - 3] + "..."


def _load_builtin() -> None:
    """Register the built-in generators' names and old names where missing (a few dict look-ups;
    no generator module is imported before it is made). Not cached: with a once-only load, a
    caller that swapped `_REGISTRY` for a copy before the first load (tests do, to register a
    plug-in) left the restored registry empty for the rest of the process."""
    for name, entry in BUILTIN.items():
        _REGISTRY.setdefault(name, entry)
    for old, new in ALIASES.items():
        _ALIASES.setdefault(old, new)
