"""A stand-in ChatModel for tests of the model boundary (`llm.ask`): it answers each request with
the next recorded reply and keeps the requests, so a test sees what was asked and re-asked."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from logicenveval.llm.base import ChatRequest, ModelStats


@dataclass
class Scripted:
    """A stand-in ChatModel answering with recorded replies, one per request, and keeping them."""

    replies: list[str]
    name: str = "scripted"
    reply_protocol: int = 2
    stats: ModelStats = field(default_factory=ModelStats)
    run_dir: Any = None
    requests: list[ChatRequest] = field(default_factory=list)

    def complete(self, request: ChatRequest) -> str:
        self.requests.append(request)
        return self.replies[len(self.requests) - 1]
