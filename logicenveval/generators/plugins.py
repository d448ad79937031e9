"""Generators from outside the package: `PKG.MODULE:ATTR`, installed plug-ins, notebook factories.

A `--generators` item is resolved once, in the parent process, to a `GeneratorRef`: the row
name (the generator's own `name` attribute) and an importable *target* that travels inside every
unit's spec. Workers (spawned processes, Ray tasks) import the target themselves, so a
generator works the same under every executor without any registration in the workers.

Resolution order of an item: a registered name (built-ins, `register_generator`), then an entry
point of the group `logicenveval.generators` published by an installed package, then
`MODULE:ATTR` imported from the current Python path.
"""

from __future__ import annotations

import contextlib
import importlib
import importlib.metadata
import importlib.util
import signal
import sys
import threading
import unicodedata
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from logicenveval.errors import ConfigError, did_you_mean
from logicenveval.generators.base import (
    Overdue,
    canonical_name,
    import_target,
    make_generator,
    plugin_frame,
    register,
    registry_entry,
    said,
)
from logicenveval.paths import check_name, name_problem, shown

ENTRY_POINT_GROUP = "logicenveval.generators"


class NotConstructed(ConfigError):
    """The plug-in's factory raised when called with the arguments given (perhaps it needs others:
    `--generator-args` keyed by its row name; runner.run)."""


@dataclass(frozen=True)
class GeneratorRef:
    spec: str  # as the user wrote it
    name: str  # the generator's `name` attribute: its leaderboard row, units/ and envs/ folder
    target: str  # what a worker passes to `make_generator`: a registered name or MODULE:ATTR
    portable: bool = True  # False: a factory registered in this process that workers cannot import
    #: the folder the target's top-level module was imported from, for workers whose Python path
    #: lacks it (a Ray worker started elsewhere); None for registered names
    search_path: str | None = None
    #: keyword arguments of the factory (`--generator-args`)
    args: dict[str, Any] = field(default_factory=dict)


def entry_points() -> dict[str, str]:
    """Installed plug-ins: entry-point name -> `module:attr`."""
    return {ep.name: ep.value for ep in importlib.metadata.entry_points(group=ENTRY_POINT_GROUP)}


def register_generator(name: str, factory: Callable[..., Any] | str) -> None:
    """Make `factory` (a generator class, a function returning a generator, or `module:attr`)
    available under `name` to `run`, `evaluate` and `make_generator` — e.g. from a notebook.

    Process-pool and Ray workers import the factory by its module and qualified name, so define
    it in a module (or a script run as `__main__`) rather than as a lambda or a nested function;
    an interactive notebook's factories need `--executor inprocess`.
    """
    check_name(name, what="generator name", field="name")
    if not (callable(factory) or isinstance(factory, str)):
        raise ConfigError(f"factory of generator {name!r} is neither callable nor MODULE:ATTR",
                          field="factory", hint="pass the generator class or a factory function")
    register(name, factory)


def _portable(factory: Callable[..., Any]) -> str | None:
    """`module:qualname` when a fresh worker can import `factory` by that path, else None."""
    module = getattr(factory, "__module__", None)
    qualname = getattr(factory, "__qualname__", None)
    if not module or not qualname or "<" in qualname:
        return None
    if module == "__main__" and not getattr(sys.modules.get("__main__"), "__file__", None):
        return None  # an interactive session: nothing a worker could re-import
    return f"{module}:{qualname}"


def resolve_generator(spec: str, args: dict[str, Any] | None = None, *,
                      timeout: float | None = None) -> GeneratorRef:
    """Resolve one `--generators` item, made with `args` as its factory's keyword arguments;
    unknown, unimportable or unmakeable -> `ConfigError` (exit 2).

    The plug-in's import and constructor run here, in the caller, within `timeout` seconds
    (`--unit-timeout`; in the main thread, where the alarm signal can be received)."""
    if len(spec) > 300 or any(unicodedata.category(c) in ("Cc", "Cs") for c in spec):
        raise ConfigError(f"generator {shown(spec)} holds a control character or is too long",
                          field="--generators",
                          hint="name a generator, an installed plug-in or PKG.MODULE:ATTR")
    if ":" not in spec:
        spec = canonical_name(spec)  # an old name of a renamed generator (with a FutureWarning)
    entry = registry_entry(spec)
    portable = True
    if entry is not None:
        target = spec if isinstance(entry, str) else (_portable(entry) or spec)
        portable = isinstance(entry, str) or target != spec
    elif spec in (eps := entry_points()):
        target = eps[spec]
    elif ":" in spec:
        target = spec
    else:
        from logicenveval.generators.base import registered

        raise ConfigError(
            f"unknown generator {spec!r}{did_you_mean(spec, [*registered(), *eps])}",
            field="--generators",
            hint="use a built-in name (" + ", ".join(registered()) + "), an installed plug-in ("
            + (", ".join(sorted(eps)) or f"none installed in group {ENTRY_POINT_GROUP}")
            + "), or PKG.MODULE:ATTR (docs/own-generator.md)")
    with _bounded(timeout, spec):
        gen = _made(spec, target, entry is None, args or {})
        name = _attribute(spec, gen, "name") if entry is None else spec
        generate = _attribute(spec, gen, "generate")
    problem = name_problem(name)
    if problem is not None:
        raise ConfigError(f"generator {shown(spec)} has no usable `name` attribute: {shown(name)} "
                          f"{problem}", field="--generators",
                          hint="give the generator a `name` string (a plain folder name): it names "
                          "its leaderboard row and its units/ and envs/ folders")
    if not callable(generate):
        raise ConfigError(f"generator {spec!r} has no generate(brief, ctx) method",
                          field="--generators", hint="implement the Generator protocol "
                          "(logicenveval.generators.base)")
    assert isinstance(name, str)
    return GeneratorRef(spec=spec, name=name, target=target,
                        portable=portable, search_path=_import_root(target), args=dict(args or {}))


def _made(spec: str, target: str, plugin: bool, args: dict[str, Any]) -> Any:
    """The generator, made once here so that a broken plug-in fails before any unit runs."""
    if plugin:
        import_target(target)  # the module error (file and line), before the constructor's
    try:
        return make_generator(target, **args)
    except (ConfigError, KeyboardInterrupt, Overdue):
        raise
    except BaseException as exc:  # a plug-in's constructor (even sys.exit): bad input, with the cause
        given = ", ".join(f"{k}={v!r}" for k, v in args.items())
        file, line = plugin_frame(exc)
        raise NotConstructed(f"generator {spec!r} could not be constructed"
                          + (f" with {given}" if given else "") + f": {said(exc)}",
                          file=file, line=line, field="--generators",
                          hint="its class or factory must be callable without arguments, or with "
                          "the keyword arguments given by --generator-args") from None


def _attribute(spec: str, gen: Any, attr: str) -> Any:
    """`gen.<attr>`, or a `ConfigError` naming the line when reading it raises (a property)."""
    try:
        return getattr(gen, attr, None)
    except (KeyboardInterrupt, Overdue):
        raise
    except BaseException as exc:
        file, line = plugin_frame(exc)
        raise ConfigError(f"reading `{attr}` of generator {spec!r} raised {said(exc)}", file=file,
                          line=line, field="--generators",
                          hint=f"make `{attr}` a plain attribute that does not raise") from None


@contextlib.contextmanager
def _bounded(seconds: float | None, spec: str) -> Iterator[None]:
    """Raise `ConfigError` when the block (a plug-in's import and constructor) takes more than
    `seconds`; only the main thread can receive the alarm, elsewhere the block is unbounded."""
    if not seconds or not hasattr(signal, "setitimer") or \
            threading.current_thread() is not threading.main_thread():
        yield
        return

    def fire(signum: int, frame: object) -> None:
        raise Overdue()

    old = signal.signal(signal.SIGALRM, fire)
    signal.setitimer(signal.ITIMER_REAL, seconds, 1.0)  # again every second if swallowed
    try:
        yield
    except Overdue:
        signal.setitimer(signal.ITIMER_REAL, 0)
        raise ConfigError(f"generator {spec!r} was not made within {seconds:g} s: its import or "
                          "constructor does not return", field="--generators",
                          hint="make the constructor return (do slow work in generate()), or "
                          "raise --unit-timeout") from None
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def _import_root(target: str) -> str | None:
    """The sys.path entry that provides the top-level module of `module:attr`, if any."""
    if ":" not in target:
        return None
    top = target.partition(":")[0].split(".")[0]
    if top == "__main__":
        return None  # a script's own classes: process workers re-import the script themselves
    found = importlib.util.find_spec(top)
    if found is None:
        return None
    if found.submodule_search_locations:
        return str(Path(next(iter(found.submodule_search_locations))).resolve().parent)
    return str(Path(found.origin).resolve().parent) if found.origin else None


def ensure_importable(target: str, search_path: str | None) -> None:
    """In a worker: make `target`'s module importable from `search_path` when it is not already."""
    if search_path is None or ":" not in target:
        return
    top = target.partition(":")[0].split(".")[0]
    if importlib.util.find_spec(top) is None and search_path not in sys.path:
        sys.path.append(search_path)
