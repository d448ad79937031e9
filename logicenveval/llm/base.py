"""`ChatRequest` and the `ChatModel` protocol of DESIGN.md §8, plus per-model statistics."""

from __future__ import annotations

import re
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
    #: reply length bound of this request kind (`ask.MAX_TOKENS`); a model arg overrides it
    max_tokens: int | None = None


#: appended by providers to a reply cut at its token bound (`finish_reason: length`); it travels
#: through the reply cache with the text, so a replayed run sees the same truncation
TRUNCATION_MARK = "\n<<logicenveval:finish_reason=length>>"


#: a UTF-16 surrogate code point: in a Python str it is always unpaired (JSON's "\\ud83d\\ude00"
#: decodes to one character), so it is no character at all and cannot be encoded as UTF-8
_SURROGATE = re.compile("[\ud800-\udfff]")


def well_formed(reply: str) -> str:
    """`reply` with every lone surrogate (a server's `"\\ud800"`) replaced by U+FFFD, as a UTF-8
    decoder replaces a broken byte. Such a reply is still the model's answer, judged like any
    other (an invalid reply is re-asked and counted), and never an encoding error in the cache,
    a saved raw reply or a page that would fail the unit as a harness bug."""
    return _SURROGATE.sub("\ufffd", reply) if _SURROGATE.search(reply) else reply


def split_truncation(reply: str) -> tuple[str, bool]:
    """(reply text, whether the provider cut it at its token bound)."""
    if reply.endswith(TRUNCATION_MARK):
        return reply[: -len(TRUNCATION_MARK)], True
    return reply, False


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
    #: what the replies served from a cache cost when they were recorded (`llm.cache`): replies
    #: with a known cost, their tokens and seconds (a replayed pack reports its recording's cost)
    recorded_replies: int = 0
    recorded_prompt_tokens: int = 0
    recorded_completion_tokens: int = 0
    recorded_seconds: float = 0.0
    #: per request kind: questions asked, attempts sent, valid first replies, valid after
    #: re-asks, attempts cut at max_tokens (`ask` counts them; reported as results.json `llm`)
    by_kind: dict[str, dict[str, int]] = field(default_factory=dict)
    _lock: threading.Lock = field(default_factory=threading.Lock, repr=False, compare=False)

    def add(self, **deltas: float) -> None:
        with self._lock:
            for key, value in deltas.items():
                setattr(self, key, getattr(self, key) + value)

    def count(self, kind: str, **deltas: int) -> None:
        with self._lock:
            counters = self.by_kind.setdefault(kind, {})
            for key, value in deltas.items():
                counters[key] = counters.get(key, 0) + value

    def as_dict(self) -> dict[str, float]:
        """Flat counters; per-kind ones as `kind.<kind>.<counter>` (see `KIND_PREFIX`)."""
        with self._lock:
            out: dict[str, float] = {k: v for k, v in vars(self).items()
                                     if not k.startswith("_") and k != "by_kind"}
            for kind, counters in self.by_kind.items():
                for key, value in counters.items():
                    out[f"{KIND_PREFIX}{kind}.{key}"] = value
            return out


KIND_PREFIX = "kind."
