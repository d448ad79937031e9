"""Generators of the fourth hostile pass (issue 50), importable by worker processes as
`hostile_generators4:<Class>` (the tests folder is the working folder of the CLI subprocesses)."""

from __future__ import annotations

import os
from typing import Any

from hostile_generators import _Base

from logicenveval.generators.base import GenerationContext
from logicenveval.model.task import TaskBrief

#: a key-shaped secret a plug-in's exception carries (never a real key)
SECRET = "sk-live4f00dfacade1234567890"


class ExitsQuietly(_Base):
    """Ends its process at once with status 0, as `os._exit(0)` in a native library would."""

    name = "exits-quietly"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        os._exit(0)


class LeaksSecret(_Base):
    """Raises an exception whose message holds an API key and a bearer header."""

    name = "leaks-secret"

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> Any:
        raise RuntimeError(f"request failed: api_key={SECRET} headers={{'Authorization': "
                           f"'Bearer {SECRET}'}} key {SECRET}")
