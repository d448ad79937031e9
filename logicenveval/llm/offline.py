"""The embedded `offline` model: deterministic, rule-based, answering from `kind` + `payload`.

It never reads ground truth (task files, GT trees, policies): every handler receives only what a
real LLM would receive (the request payload, its temperature and seed). Handlers are registered
per request kind by the packages that define those kinds; their modules are imported lazily.
"""

from __future__ import annotations

import importlib
import json
from collections.abc import Callable
from typing import Any

from logicenveval.errors import ConfigError
from logicenveval.llm.base import ChatRequest, ModelStats
from logicenveval.llm.bounds import fit_arrays

Handler = Callable[[dict[str, Any], ChatRequest], Any]

_HANDLERS: dict[str, Handler] = {}

#: modules that register offline handlers (imported on first use of the offline model)
HANDLER_MODULES: tuple[str, ...] = (
    "logicenveval.llm.offline_plan",
    "logicenveval.generators.offline_handlers",
    "logicenveval.baselines.offline_handlers",
    "logicenveval.generators.brief",
)


def handler(kind: str) -> Callable[[Handler], Handler]:
    """Register `fn(payload, request) -> JSON-able reply` as the offline answer to `kind`."""

    def register(fn: Handler) -> Handler:
        _HANDLERS[kind] = fn
        return fn

    return register


def _load_handlers() -> None:
    for module in HANDLER_MODULES:
        importlib.import_module(module)


def handled_kinds() -> list[str]:
    _load_handlers()
    return sorted(_HANDLERS)


class OfflineModel:
    """A ChatModel whose replies are computed by rule-based handlers (no network)."""

    name = "offline"

    def __init__(self, *, stats: ModelStats | None = None) -> None:
        self.stats = stats or ModelStats()
        _load_handlers()

    def complete(self, request: ChatRequest) -> str:
        fn = _HANDLERS.get(request.kind)
        if fn is None:
            raise ConfigError(f"the offline model cannot answer {request.kind!r} requests",
                              field="--model",
                              hint="known kinds: " + ", ".join(sorted(_HANDLERS)))
        self.stats.add(requests=1)
        # within the schema's list bounds, as a grammar-constrained model must write (llm.bounds)
        return json.dumps(fit_arrays(fn(request.payload, request), request.schema))
