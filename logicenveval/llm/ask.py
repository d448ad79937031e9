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
from logicenveval.errors import ConfigError, ModelReplyError, ModelTruncatedError
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats, split_truncation
from logicenveval.llm.jsonextract import JSONExtractionError, extract_json
from logicenveval.llm.vocab import CONTEXT_KEY, Vocabulary, specialise
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
    schema: dict[str, Any] = _without_titles(reply_model.model_json_schema())
    return schema


def _without_titles(node: Any) -> Any:
    """The schema without pydantic's `title` keys: they repeat the field names, cost prompt
    tokens on every request and constrain nothing (a property *named* `title` is kept)."""
    if isinstance(node, dict):
        return {k: (_without_titles(v) if k != "properties" else
                    {name: _without_titles(sub) for name, sub in v.items()})
                for k, v in node.items() if k != "title" or not isinstance(v, str)}
    if isinstance(node, list):
        return [_without_titles(v) for v in node]
    return node


def render_messages(kind: str, payload: dict[str, Any], schema: dict[str, Any]) -> list[dict[str, str]]:
    """System + user messages of a request kind from `prompts/<kind>.j2`."""
    try:
        template = _jinja().get_template(f"{kind}.j2")
    except TemplateNotFound:
        raise ConfigError(f"no prompt template for request kind {kind!r}",
                          file=f"logicenveval/llm/prompts/{kind}.j2",
                          hint="add the template or use an existing kind") from None
    text = template.render(payload=payload, schema=json.dumps(schema, separators=(",", ":")), json=json)
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


#: reply-length bound (tokens) per request kind: generous for a valid reply, short enough that a
#: model looping inside a grammar stops in seconds, not at the end of its context
MAX_TOKENS: dict[str, int] = {
    "name_objects": 600, "decompose_task": 800, "identify_factors": 1000, "tree_step": 48,
    "tree_leaves": 1000, "trajectories_direct": 2000, "floor_plan": 1000, "select_objects": 2000,
    "spatial_relations": 1000, "refine_relations": 1000, "place_objects": 3000,
    "holodeck_scene": 3000, "cot_environments": 4000, "ifg_intents": 1500, "ifg_environment": 3000,
}
DEFAULT_MAX_TOKENS = 2500
#: each re-ask raises the temperature by this much (and steps the seed): a deterministic model
#: asked the same thing at temperature 0 repeats its invalid reply byte for byte
REASK_TEMPERATURE_STEP = 0.3
#: how much of an invalid (complete) reply a re-ask quotes back; a cut reply is never quoted
QUOTE_CHARS = 600


def _reask_messages(messages: list[dict[str, str]], raw: str, problem: str,
                    truncated: bool, max_tokens: int | None) -> list[dict[str, str]]:
    """The first request plus one exchange about the last invalid reply (the prompt never grows
    with the number of attempts)."""
    if truncated:
        return [*messages, {"role": "user", "content":
                f"Your previous reply was cut off at max_tokens={max_tokens} before its JSON was "
                "complete. Reply again with a shorter JSON value that satisfies the schema: no "
                "repetition, short strings."}]
    quoted = raw if len(raw) <= QUOTE_CHARS else raw[:QUOTE_CHARS] + " ...(cut)"
    return [*messages, {"role": "assistant", "content": quoted},
            {"role": "user", "content": f"Your reply is invalid: {problem}. Reply again with only "
             "one JSON value that satisfies the schema."}]


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
    vocabulary: Vocabulary | None = None,
    max_tokens: int | None = None,
) -> T:
    """Ask `model` a `kind` question and return the validated reply.

    With a `vocabulary`, fields marked `Vocab(name)` in the reply model are sent as enums (or
    patterns) and validated against it (`llm.vocab`). Invalid replies (no JSON, broken JSON,
    schema violations, a reply cut at `max_tokens`) are re-asked at most `max_reasks` times,
    each time with the validator's message and a higher temperature and another seed, so no
    attempt repeats an identical request; then `ModelReplyError` (`ModelTruncatedError` when the
    last reply was cut) names the kind, the model and the problem, and the raw replies are saved
    under `run_dir/llm_errors/`. Counts per kind go to the model's `stats`.
    """
    schema = specialise(reply_schema(reply_model), vocabulary)
    first = render_messages(kind, payload, schema)
    messages = first
    bound = max_tokens or MAX_TOKENS.get(kind, DEFAULT_MAX_TOKENS)
    context = {CONTEXT_KEY: vocabulary or {}}
    replies: list[str] = []
    problem = ""
    truncated = False
    stats: ModelStats | None = getattr(model, "stats", None)
    if stats is not None:
        stats.count(kind, questions=1)
    for attempt in range(max_reasks + 1):
        step_seed = seed if attempt == 0 else (seed or 0) + attempt
        request = ChatRequest(kind=kind, payload=payload, messages=messages, schema=schema,
                              temperature=temperature if attempt == 0 else
                              min(2.0, temperature + REASK_TEMPERATURE_STEP * attempt),
                              seed=step_seed, max_tokens=bound)
        raw, truncated = split_truncation(model.complete(request))
        replies.append(raw)
        if stats is not None:
            stats.count(kind, attempts=1, truncated=int(truncated))
        try:
            if truncated:
                raise JSONExtractionError(f"the reply was cut at max_tokens={bound}")
            reply = reply_model.model_validate(extract_json(raw), context=context)
        except JSONExtractionError as exc:
            problem = str(exc)
        except ValidationError as exc:
            loc, msg = first_error(exc)
            problem = f"field '{loc}': {msg}"
        else:
            if stats is not None:
                stats.count(kind, valid=1, valid_first=int(attempt == 0))
            return reply
        if attempt < max_reasks:
            if stats is not None:
                stats.add(reasks=1)
            messages = _reask_messages(first, raw, problem, truncated, bound)
    saved = _save_raw(run_dir or getattr(model, "run_dir", None), kind, model.name, replies)
    error = ModelTruncatedError if truncated else ModelReplyError
    raise error(
        f"the {kind!r} reply of model {model.name!r} stayed invalid after {max_reasks + 1} "
        f"attempt(s): {problem}",
        file=saved,
        hint=f"the model wrote more than max_tokens={bound}: raise it with --model-args "
        "max_tokens=N, or use a stronger model" if truncated else
        "inspect the saved raw reply; a stronger model usually helps",
    )
