"""The paper's few-shot setting: every request of every method carries the same example.

The paper gives all methods "the same problem setup, few-shot examples, and asset library"
(App. B); its example is the Clean Living Room task and its behaviour plan (App. A). `FewShotModel`
wraps any ChatModel and appends that example to the system message of every request, so no
generator needs to know about it; the reply cache underneath keys on the augmented messages.
"""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache
from pathlib import Path

from jinja2 import Environment, PackageLoader

from logicenveval.llm.ask import PROTOCOL
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats


@lru_cache(maxsize=1)
def few_shot_example() -> str:
    env = Environment(loader=PackageLoader("logicenveval", "llm/prompts"), autoescape=False)
    text: str = env.get_template("_few_shot.j2").module.example()  # type: ignore[attr-defined]
    return str(text).strip()


def with_example(messages: list[dict[str, str]]) -> list[dict[str, str]]:
    """`messages` with the example appended to the system message (added when there is none)."""
    example = few_shot_example()
    if messages and messages[0].get("role") == "system":
        return [{**messages[0], "content": messages[0]["content"] + "\n\n" + example}, *messages[1:]]
    return [{"role": "system", "content": example}, *messages]


class FewShotModel:
    """A ChatModel that forwards every request with the few-shot example added."""

    def __init__(self, inner: ChatModel) -> None:
        self.inner = inner
        self.name = inner.name
        self.stats: ModelStats | None = getattr(inner, "stats", None)
        self.run_dir: Path | None = getattr(inner, "run_dir", None)
        #: the request protocol of the wrapped model (`llm.ask.PROTOCOL`): a replay keeps its own
        self.reply_protocol: int = getattr(inner, "reply_protocol", PROTOCOL)

    def complete(self, request: ChatRequest) -> str:
        return self.inner.complete(replace(request, messages=with_example(request.messages)))
