"""One typed question to a ChatModel: render the prompt, send the schema, validate, re-ask.

The JSON schema sent to the server is generated from the reply's pydantic model, so the prompt,
the server-side constraint and the validation can never disagree.
"""

from __future__ import annotations

import hashlib
import json
from functools import lru_cache
from pathlib import Path
from typing import Any, TypeVar

from jinja2 import Environment, PackageLoader, StrictUndefined, TemplateNotFound
from pydantic import BaseModel, ValidationError

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import ConfigError, ModelReplyError
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats
from logicenveval.llm.jsonextract import JSONExtractionError, extract_json
from logicenveval.redact import redact
from logicenveval.validation import first_error

T = TypeVar("T", bound=BaseModel)

_SPLIT = "=== user ==="


@lru_cache(maxsize=1)
def _jinja() -> Environment:
    return Environment(loader=PackageLoader("logicenveval", "llm/prompts"), undefined=StrictUndefined,
                       keep_trailing_newline=False, autoescape=False)


@lru_cache(maxsize=256)
def reply_schema(reply_model: type[BaseModel]) -> dict[str, Any]:
    """The JSON schema of a reply class, built once per class (pydantic rebuilds it per call).

    The dict is shared by every request of that class: read it, never change it.
    """
    return reply_model.model_json_schema()


def render_messages(kind: str, payload: dict[str, Any], schema: dict[str, Any]) -> list[dict[str, str]]:
    """System + user messages of a request kind from `prompts/<kind>.j2`."""
    try:
        template = _jinja().get_template(f"{kind}.j2")
    except TemplateNotFound:
        raise ConfigError(f"no prompt template for request kind {kind!r}",
                          file=f"logicenveval/llm/prompts/{kind}.j2",
                          hint="add the template or use an existing kind") from None
    text = template.render(payload=payload, schema=json.dumps(schema, indent=1), json=json)
    system, _, user = text.partition(_SPLIT)
    return [{"role": "system", "content": system.strip()}, {"role": "user", "content": user.strip()}]


def _save_raw(run_dir: Path | None, kind: str, model: str, replies: list[str]) -> str | None:
    if run_dir is None:
        return None
    digest = hashlib.sha256("\n".join(replies).encode()).hexdigest()[:12]
    path = Path(run_dir) / "llm_errors" / f"{kind}-{digest}.txt"
    sep = "\n\n----- next attempt -----\n\n"
    atomic_write_text(path, redact(f"model: {model}\nkind: {kind}\n\n" + sep.join(replies)),
                      durable=False)
    return str(path)


def ask(
    model: ChatModel,
    kind: str,
    payload: dict[str, Any],
    reply_model: type[T],
    *,
    temperature: float = 0.0,
    seed: int | None = None,
    max_reasks: int = 2,
    run_dir: Path | None = None,
) -> T:
    """Ask `model` a `kind` question and return the validated reply.

    Invalid replies (no JSON, broken JSON, schema violations) are re-asked at most `max_reasks`
    times with the validation error appended; then `ModelReplyError` names the kind, the model
    and the first invalid field, and the raw replies are saved under `run_dir/llm_errors/`.
    """
    schema = reply_schema(reply_model)
    messages = render_messages(kind, payload, schema)
    replies: list[str] = []
    problem = ""
    stats: ModelStats | None = getattr(model, "stats", None)
    for attempt in range(max_reasks + 1):
        request = ChatRequest(kind=kind, payload=payload, messages=messages, schema=schema,
                              temperature=temperature, seed=seed)
        raw = model.complete(request)
        replies.append(raw)
        try:
            return reply_model.model_validate(extract_json(raw))
        except JSONExtractionError as exc:
            problem = str(exc)
        except ValidationError as exc:
            loc, msg = first_error(exc)
            problem = f"field '{loc}': {msg}"
        forget = getattr(model, "forget", None)
        if callable(forget):
            forget(request)  # an invalid reply is never served from the cache again
        if attempt < max_reasks:
            if stats is not None:
                stats.add(reasks=1)
            messages = [
                *messages,
                {"role": "assistant", "content": raw},
                {"role": "user", "content": f"Your reply is invalid: {problem}. Reply again with "
                 "only one JSON value that satisfies the schema."},
            ]
    saved = _save_raw(run_dir or getattr(model, "run_dir", None), kind, model.name, replies)
    raise ModelReplyError(
        f"the {kind!r} reply of model {model.name!r} stayed invalid after {max_reasks + 1} "
        f"attempt(s): {problem}",
        file=saved,
        hint="inspect the saved raw reply; a stronger model or a lower temperature usually helps",
    )
