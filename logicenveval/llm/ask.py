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

from jinja2 import Environment, PackageLoader, StrictUndefined, Template, TemplateNotFound
from pydantic import BaseModel, ValidationError

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import ConfigError, ModelReplyError, ModelTruncatedError
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats, split_truncation, well_formed
from logicenveval.llm.bounds import fit_numbers
from logicenveval.llm.jsonextract import JSONExtractionError, extract_json
from logicenveval.llm.meaning import MEANING_KEY, meaningless
from logicenveval.llm.vocab import CONTEXT_KEY, Pattern, Vocabulary, specialise
from logicenveval.redact import redact
from logicenveval.validation import first_error

T = TypeVar("T", bound=BaseModel)

_SPLIT = "=== user ==="

#: the request protocol `ask` speaks by default. 1: the protocol of the packs recorded before
#: issue 39 (no reply-format line, `MAX_TOKENS_V1`, "shorter" re-ask of a cut reply, no meaning
#: checks), kept so that those packs replay byte for byte (their cache keys are the request
#: texts); 2: compact-JSON line in every prompt, bounds sized from measured content
#: (`MAX_TOKENS`), a cut reply re-asked with a larger bound, meaning checks (`llm.meaning`).
#: 3: as 2, and the objects of a scene are asked keyed by role (`replies.SelectionWire`: one
#: required object per role the situation requires, then at most `MAX_OTHER_OBJECTS` others).
#: 4: as 3, and the environments CoT and IFG write are bounded in the grammar
#: (`baselines.replies.written_slots`): at most as many environments as asked for (CoT's "at
#: most N", IFG's one per intent), and per environment at most one object, and one relation, per
#: role plus `MAX_OTHER_OBJECTS` others (Qwen2.5-Coder-1.5B's protocol-3 replies repeated
#: environments and relations until their token bound).
#: A model built with `--model-args protocol=N` (`registry.make_model`) carries `reply_protocol`.
#: Protocol 1 also keeps LogicEnvGen's question flow of those packs (`generators.plan`,
#: `generators.construction`): no rule-(a) re-ask of the decomposition and one floor plan per
#: task, since each extra question is a request the packs never recorded.
#: 5: as 4, and IFG samples each intent in its own request (`ifg_intent`, the intent
#: temperature, a seed of its own) as structured literals bound to the task's vocabulary
#: (`baselines.replies.IntentWire`), as IFG samples i ~ M(p) once per intent; under 4 one
#: `ifg_intents` request asked for all k as free strings, and Qwen2.5-Coder-1.5B gave 1 of 8.
#: 6: as 5, and a `name_objects` reply's category is retrieved by the object's name where the two
#: contradict each other, its attribute keys no catalog domain knows dropped
#: (`generators.brief.retrieve`); the requests are those of 5, the brief built from a reply differs.
#: 7: as 6, and LogicEnvGen's plan is held to the physical axioms `tasks validate` holds the
#: benchmark's trees to (`logic.axioms`): a factor response no environment can meet (an object on
#: itself) is rule (d)'s to ask again, and a tree does not ask a factor its path already decides or
#: contradicts (`generators.plan._open_factors`); Qwen2.5-Coder-1.5B's protocol-6 plan for
#: bathroom_counter_sort asked the bottle "on the vanity?" and "on the floor?" as two factors and
#: planned the bottle in both places. A plan without such factors asks what protocol 6 asks.
PROTOCOL = 7
PROTOCOLS = (1, 2, 3, 4, 5, 6, 7)


def protocol_of(model: Any) -> int:
    """The request protocol `model` speaks (`reply_protocol`, else `PROTOCOL`)."""
    return int(getattr(model, "reply_protocol", PROTOCOL))


@lru_cache(maxsize=1)
def _jinja() -> Environment:
    # the prompts are package files: no `stat` per request to see whether one changed on disk
    return Environment(loader=PackageLoader("logicenveval", "llm/prompts"), undefined=StrictUndefined,
                       keep_trailing_newline=False, autoescape=False, auto_reload=False)


@lru_cache(maxsize=1)
def _reply_format() -> str:
    """The protocol-2 reply-format paragraph: constant, rendered once."""
    return _jinja().get_template("_reply_format.j2").render().strip()


@lru_cache(maxsize=256)
def reply_schema(reply_model: type[BaseModel]) -> dict[str, Any]:
    """The JSON schema of a reply class, built once per class (pydantic rebuilds it per call).

    The dict is shared by every request of that class: read it, never change it.
    """
    schema: dict[str, Any] = _without_titles(reply_model.model_json_schema())
    return schema


VocabularyKey = tuple[tuple[str, "tuple[str, ...] | Pattern"], ...]


def _vocabulary_key(vocabulary: Vocabulary | None) -> VocabularyKey:
    return tuple((name, words if isinstance(words, Pattern) else tuple(words))
                 for name, words in sorted((vocabulary or {}).items()))


@lru_cache(maxsize=512)
def _specialised(reply_model: type[BaseModel], vocabulary: VocabularyKey, bounds: bool) -> tuple[dict[str, Any], str]:
    """The schema of a reply class specialised to a vocabulary, and its compact JSON text, built
    once per (class, vocabulary): a unit asks many questions over the same words (every
    `tree_step` of a task, every scene of a floor plan). Shared: read it, never change it."""
    schema = specialise(reply_schema(reply_model), dict(vocabulary), bounds=bounds)
    return schema, json.dumps(schema, separators=(",", ":"))


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


def render_messages(kind: str, payload: dict[str, Any], schema: dict[str, Any],
                    protocol: int = PROTOCOL) -> list[dict[str, str]]:
    """System + user messages of a request kind from `prompts/<kind>.j2`; from protocol 2 on the
    system message ends with `_reply_format.j2` (compact JSON: layout must not spend the bound)."""
    return _render(kind, payload, json.dumps(schema, separators=(",", ":")), protocol)


@lru_cache(maxsize=64)
def _template(kind: str) -> Template:
    """A request kind's prompt template, looked up once (jinja's own cache costs a lock and a
    key per request)."""
    try:
        return _jinja().get_template(f"{kind}.j2")
    except TemplateNotFound:
        raise ConfigError(f"no prompt template for request kind {kind!r}",
                          file=f"logicenveval/llm/prompts/{kind}.j2",
                          hint="add the template or use an existing kind") from None


def _render(kind: str, payload: dict[str, Any], schema_text: str, protocol: int) -> list[dict[str, str]]:
    text = _template(kind).render(payload=payload, schema=schema_text, json=json, protocol=protocol)
    system, _, user = text.partition(_SPLIT)
    if protocol >= 2:
        system = system.strip() + "\n" + _reply_format()
    return [{"role": "system", "content": system.strip()}, {"role": "user", "content": user.strip()}]


def _save_raw(run_dir: Path | None, kind: str, model: str, replies: list[str]) -> str | None:
    """Save the invalid replies under `run_dir/llm_errors/`; the path returned is relative to
    the run folder, so messages (kept in units and results) name no folder of this machine."""
    if run_dir is None:
        return None
    digest = hashlib.sha256("\n".join(replies).encode()).hexdigest()[:12]
    rel = Path("llm_errors") / f"{kind}-{digest}.txt"
    sep = "\n\n----- next attempt -----\n\n"
    atomic_write_text(Path(run_dir) / rel, redact(f"model: {model}\nkind: {kind}\n\n" + sep.join(replies)),
                      durable=False)
    return rel.as_posix()



#: reply-length bounds (tokens) of protocol 1, as the SmolLM2 pack was recorded with
MAX_TOKENS_V1: dict[str, int] = {
    "name_objects": 600, "decompose_task": 800, "identify_factors": 1000, "tree_step": 48,
    "tree_leaves": 1000, "trajectories_direct": 2000, "floor_plan": 1000, "select_objects": 2000,
    "spatial_relations": 1000, "refine_relations": 1000, "place_objects": 3000,
    "holodeck_scene": 3000, "cot_environments": 4000, "ifg_intents": 1500, "ifg_environment": 3000,
}
DEFAULT_MAX_TOKENS = 2500
#: reply-length bound (tokens) per request kind from protocol 2 on: the largest compact reply of
#: the offline model over all 25 tasks (`benchmarks/reply_bounds.py`, chars / 3.5) times 1.5,
#: rounded up to 100, at least the protocol-1 bound; what a valid reply must hold fits, and a
#: model looping inside a grammar still stops long before the end of its context
#: (measured: cot_environments 38,935 chars on lamp_or_pillow_fetch, trajectories_direct 9,110,
#: ifg_intents 3,889; every other kind fits its protocol-1 bound). A CoT reply of 16,700 tokens
#: needs a context of at least that plus its prompt: `llamacpp:` takes `ctx=20480` (docs/llm.md)
MAX_TOKENS: dict[str, int] = {**MAX_TOKENS_V1, "cot_environments": 16700, "trajectories_direct": 4000,
                              "ifg_intents": 1700, "tree_step": 100, "ifg_intent": 1000}
#: kinds whose top-level list has as many items as the request fixes (`maxItems`): the list's
#: key and the tokens one item may take (largest measured item x 1.5, `benchmarks/reply_bounds.py`)
PER_ITEM_TOKENS: dict[str, tuple[str, int]] = {"tree_leaves": ("leaves", 100)}
#: tokens of a reply besides its items (braces, the key)
ITEMS_OVERHEAD = 50
#: a cut reply is re-asked with twice its bound, up to this many times the kind's bound and at
#: most `MAX_TOKENS_CAP` tokens: never "shorter" (a re-ask for less lost 3 of 4 good factors)
GROWTH_FACTOR = 2
MAX_TOKENS_CAP = 32768
#: each re-ask raises the temperature by this much (and steps the seed): a deterministic model
#: asked the same thing at temperature 0 repeats its invalid reply byte for byte
REASK_TEMPERATURE_STEP = 0.3
#: how much of an invalid (complete) reply a re-ask quotes back; a cut reply is never quoted
QUOTE_CHARS = 600


def bounds_of(kind: str, protocol: int = PROTOCOL, schema: dict[str, Any] | None = None) -> int:
    """The first attempt's reply bound of a request kind under `protocol`; from protocol 2 on, a
    kind whose list length the request fixes (`PER_ITEM_TOKENS`) gets its per-item size times
    that length when more (a `tree_leaves` reply for 40 situations cannot fit in 1,000 tokens)."""
    if protocol < 2:
        return MAX_TOKENS_V1.get(kind, DEFAULT_MAX_TOKENS)
    bound = MAX_TOKENS.get(kind, DEFAULT_MAX_TOKENS)
    per_item = PER_ITEM_TOKENS.get(kind)
    if per_item is not None and schema is not None:
        key, tokens = per_item
        count = ((schema.get("properties") or {}).get(key) or {}).get("maxItems")
        if isinstance(count, int):
            bound = max(bound, count * tokens + ITEMS_OVERHEAD)
    return bound


def grown_bound(bound: int, first: int) -> int:
    """The bound of the re-ask of a reply cut at `bound` (`first`: the kind's first bound)."""
    return min(bound * GROWTH_FACTOR, first * GROWTH_FACTOR ** 2, MAX_TOKENS_CAP)


def _reask_messages(messages: list[dict[str, str]], raw: str, problem: str,
                    truncated: bool, max_tokens: int | None,
                    protocol: int = PROTOCOL, grown: int | None = None, quote: bool = True) -> list[dict[str, str]]:
    """The first request plus one exchange about the last invalid reply (the prompt never grows
    with the number of attempts); `quote=False` names the finding without quoting the reply."""
    if truncated and protocol >= 2:
        return [*messages, {"role": "user", "content":
                f"Your previous reply was cut off at max_tokens={max_tokens} before its JSON was "
                f"complete. You now have max_tokens={grown}: reply again with the complete JSON "
                "value, every item included, written compactly (no indentation, no line breaks)."}]
    if truncated:
        return [*messages, {"role": "user", "content":
                f"Your previous reply was cut off at max_tokens={max_tokens} before its JSON was "
                "complete. Reply again with a shorter JSON value that satisfies the schema: no "
                "repetition, short strings."}]
    if not quote:
        return [*messages, {"role": "user", "content": f"Your previous reply was invalid: {problem}. "
                            "Reply again with only one JSON value that satisfies the schema and "
                            "changes what this names."}]
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
    quote: bool = True,
) -> T:
    """Ask `model` a `kind` question and return the validated reply.

    With a `vocabulary`, fields marked `Vocab(name)` in the reply model are sent as enums (or
    patterns) and validated against it (`llm.vocab`). Invalid replies (no JSON, broken JSON,
    schema violations, a reply cut at `max_tokens`) are re-asked at most `max_reasks` times,
    each time with the validator's message and a higher temperature and another seed, so no
    attempt repeats an identical request; from protocol 2 on (`PROTOCOL`) a cut reply is re-asked
    with a larger bound (`grown_bound`) and meaning checks (`llm.meaning`) run as part of
    validation; a re-ask quotes the invalid reply unless `quote=False`; then `ModelReplyError` (`ModelTruncatedError` when the
    last reply was cut) names the kind, the model and the problem, and the raw replies are saved
    under `run_dir/llm_errors/`. Counts per kind go to the model's `stats`.
    """
    protocol = protocol_of(model)
    schema, schema_text = _specialised(reply_model, _vocabulary_key(vocabulary), protocol >= 2)
    first = _render(kind, payload, schema_text, protocol)
    messages = first
    first_bound = max_tokens or bounds_of(kind, protocol, schema)
    bound = first_bound
    context: dict[str, Any] = {CONTEXT_KEY: vocabulary or {}}
    if protocol >= 2:
        context[MEANING_KEY] = True
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
        raw, truncated = split_truncation(well_formed(model.complete(request)))
        replies.append(raw)
        if stats is not None:
            stats.count(kind, attempts=1, truncated=int(truncated))
        try:
            if truncated:
                raise JSONExtractionError(f"the reply was cut at max_tokens={bound}")
            value, clamped = fit_numbers(extract_json(raw), schema)
            if clamped and stats is not None:
                stats.count(kind, clamped=len(clamped))
            reply = reply_model.model_validate(value, context=context)
        except JSONExtractionError as exc:
            problem = str(exc)
        except ValidationError as exc:
            loc, msg = first_error(exc)
            problem = f"field '{loc}': {msg}"
            if stats is not None and meaningless(exc):
                stats.count(kind, meaningless=1)
        else:
            if stats is not None:
                stats.count(kind, valid=1, valid_first=int(attempt == 0))
                if protocol >= 2:
                    stats.count(kind, answered=1)
            return reply
        if attempt < max_reasks:
            if stats is not None:
                stats.add(reasks=1)
            grown = grown_bound(bound, first_bound) if truncated and protocol >= 2 else bound
            messages = _reask_messages(first, raw, problem, truncated, bound, protocol, grown, quote)
            bound = grown
    if stats is not None and protocol >= 2:
        stats.count(kind, answered=1)  # a question is answered once its attempts are spent
    saved = _save_raw(run_dir or getattr(model, "run_dir", None), kind, model.name, replies)
    error = ModelTruncatedError if truncated else ModelReplyError
    raise error(
        f"the {kind!r} reply of model {model.name!r} stayed invalid after {max_reasks + 1} "
        f"attempt(s): {problem}",
        file=saved,
        hint=f"the model wrote more than max_tokens={bound}: raise it with --model-args "
        "max_tokens=N, or use a stronger model" if truncated else
        "inspect the saved raw reply (in the run folder); a stronger model usually helps",
    )
