"""The offline model's answers, registered per request kind (`handler`). The answer modules of
this package register theirs when imported; `offline.model` imports them all."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from logicenveval.llm.base import ChatRequest

Handler = Callable[[dict[str, Any], ChatRequest], Any]

_HANDLERS: dict[str, Handler] = {}


def handler(kind: str) -> Callable[[Handler], Handler]:
    """Register `fn(payload, request) -> JSON-able reply` as the offline answer to `kind`."""

    def register(fn: Handler) -> Handler:
        _HANDLERS[kind] = fn
        return fn

    return register


def answer_for(kind: str) -> Handler | None:
    """The registered answer to `kind`, or None (the model names the known kinds in its error)."""
    return _HANDLERS.get(kind)


def known_kinds() -> list[str]:
    """Every request kind the offline model answers, sorted."""
    return sorted(_HANDLERS)
