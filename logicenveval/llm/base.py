"""`ChatRequest` and the `ChatModel` protocol of DESIGN.md §8, plus per-model statistics."""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable


@dataclass(frozen=True)
class ChatRequest:
    kind: str  # e.g. "decompose_task", "identify_factors", "build_tree", "floor_plan", ...
    payload: dict[str, Any]  # the structured inputs the prompt was rendered from
    messages: list[dict[str, str]]  # OpenAI-style chat messages rendered from a prompt template
    schema: dict[str, Any] | None  # JSON schema the reply must satisfy
    temperature: float = 0.0
    #: sampling seed forwarded to servers that support it (part of the cache key)
    seed: int | None = None


@runtime_checkable
class ChatModel(Protocol):
    name: str

    def complete(self, request: ChatRequest) -> str: ...


@dataclass
class ModelStats:
    """Counters a run reports (requests, cache hits/misses, tokens, latency); thread-safe."""

    requests: int = 0
    cache_hits: int = 0
    cache_misses: int = 0
    retries: int = 0
    reasks: int = 0
    prompt_tokens: int = 0
    completion_tokens: int = 0
    latency_s: float = 0.0
    _lock: threading.Lock = field(default_factory=threading.Lock, repr=False, compare=False)

    def add(self, **deltas: float) -> None:
        with self._lock:
            for key, value in deltas.items():
                setattr(self, key, getattr(self, key) + value)

    def as_dict(self) -> dict[str, float]:
        with self._lock:
            return {k: v for k, v in vars(self).items() if not k.startswith("_")}
