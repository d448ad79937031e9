"""LogicEnvEval: a benchmark and harness for generators of logically diverse test environments."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from logicenveval.errors import LogicEnvEvalError

__version__ = "0.1.0"
__all__ = ["LogicEnvEvalError", "__version__", "register_generator"]


def register_generator(name: str, factory: Callable[..., Any] | str) -> None:
    """Make your generator (class, factory or `module:attr`) usable by name in `run`/`evaluate`.

    See `logicenveval.generators.plugins.register_generator` and docs/own-generator.md.
    """
    from logicenveval.generators.plugins import register_generator as _register

    _register(name, factory)
