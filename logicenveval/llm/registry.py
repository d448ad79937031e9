"""Choosing a ChatModel by name (`--model`) with `key=value,...` arguments (`--model-args`).

Providers are imported lazily, so `offline` runs never import httpx and a missing optional
dependency only matters for the provider that needs it.
"""

from __future__ import annotations

import difflib
import importlib
from pathlib import Path
from typing import Any

from logicenveval.errors import ConfigError
from logicenveval.llm.base import ChatModel, ModelStats
from logicenveval.llm.cache import ReplyCache

PROVIDERS: dict[str, str] = {
    "offline": "logicenveval.offline.model:OfflineModel",
    "oracle": "logicenveval.llm.oracle:OracleModel",
    "openai": "logicenveval.llm.openai_http:OpenAIChatModel",
    "llamacpp": "logicenveval.llm.llamacpp:make_llamacpp",
}
#: providers whose replies are cached (HTTP models; the rule-based ones are faster than a lookup)
CACHED = frozenset({"openai", "llamacpp"})


def provider_factory(provider: str) -> Any:
    """The factory of a provider of `PROVIDERS`, imported only now: a target string is no import
    statement, so `llm` never imports the packages above it (the embedded model, `offline`)."""
    module, attr = PROVIDERS[provider].split(":")
    return getattr(importlib.import_module(module), attr)


def _typed(value: str) -> Any:
    low = value.lower()
    if low in ("true", "false"):
        return low == "true"
    if low in ("none", "null"):
        return None
    for cast in (int, float):
        try:
            return cast(value)
        except ValueError:
            pass
    return value


def parse_model_args(text: str | dict[str, Any] | None) -> dict[str, Any]:
    """`base_url=http://h:8000/v1,timeout=30` -> {"base_url": "...", "timeout": 30}."""
    if text is None:
        return {}
    if isinstance(text, dict):
        return dict(text)
    out: dict[str, Any] = {}
    for item in filter(None, (p.strip() for p in text.split(","))):
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise ConfigError(f"model argument {item!r} is not key=value", field="--model-args",
                              hint="write key=value pairs separated by commas")
        key = key.strip()
        if key in out:
            raise ConfigError(f"model argument {key!r} is given twice", field=f"--model-args {key}",
                              hint=f"give {key}= once (the last value would silently win)")
        out[key] = _typed(value.strip())
    return out


#: the HTTP models' unit budget when the run sets no wall-time bound (`--unit-timeout 0`)
UNBOUNDED_SECONDS = 1e9


def with_unit_budget(spec: str, args: str | dict[str, Any] | None,
                     seconds: float | None) -> dict[str, Any]:
    """Model arguments in which an HTTP model's own per-unit request budget (`unit_timeout`)
    follows the run's `--unit-timeout`, unless the user set it in --model-args: one bound, not
    two (a run given 3 h per unit had its slow local model stopped at the model's 30 minutes)."""
    kwargs = parse_model_args(args)
    provider, _, name = spec.partition(":")
    while provider == "noisy":
        provider, _, name = name.partition(":")
    if provider in CACHED and "unit_timeout" not in kwargs:
        kwargs["unit_timeout"] = UNBOUNDED_SECONDS if seconds is None else seconds
    return kwargs


#: the only model argument of `replay:` (the recorded run's arguments are in its replies)
REPLAY_ARGS = frozenset({"replay_model"})


def _replay_target(cache: ReplyCache, wanted: Any) -> tuple[str, str]:
    if wanted is not None:
        provider, sep, model = str(wanted).partition(":")
        if not (isinstance(wanted, str) and sep and provider and model):
            raise ConfigError(f"replay_model={wanted!r} is not <provider>:<model>",
                              field="--model-args replay_model",
                              hint="e.g. replay_model=llamacpp:SmolLM2-135M-Instruct.Q4_1")
        return provider, model
    pairs = cache.models()
    if len(pairs) != 1:
        raise ConfigError(f"the cache holds {len(pairs)} models", file=str(cache.path),
                          field="--model-args replay_model",
                          hint="choose one with replay_model=<provider>:<model>")
    return pairs[0]


def request_protocol(model_args: str | dict[str, Any] | None) -> int:
    """The request protocol a run with these model arguments asks in (`protocol=N`, else the
    default `llm.ask.PROTOCOL`): what its replies answer, so what a replay of them must ask."""
    return _protocol(parse_model_args(model_args).get("protocol"))


def _protocol(value: Any) -> int:
    """The request protocol of `--model-args protocol=N` (`llm.ask.PROTOCOL` by default)."""
    from logicenveval.llm.ask import PROTOCOL, PROTOCOLS

    if value is None:
        return PROTOCOL
    if value not in PROTOCOLS:
        raise ConfigError(f"protocol={value!r} is not a request protocol", field="--model-args protocol",
                          hint=f"use one of {', '.join(map(str, PROTOCOLS))}; 1 replays packs recorded "
                          "before issue 39 (docs/llm.md)")
    return int(value)


def _model_guess(spec: str, provider: str, name: str) -> str:
    """` (did you mean ...?)` for a misspelt model: a provider close to the one written
    (`ofline`, `openia:gpt-4o`), else, for a bare name like `gpt4`, the same name served by an
    OpenAI-compatible endpoint (`openai:gpt4`)."""
    names = ["offline", "oracle", "openai", "llamacpp", "replay", "noisy"]
    close = difflib.get_close_matches(provider, names, n=1)
    if close:
        return f" (did you mean {close[0] + (':' + name if name else '')!r}?)"
    return "" if name or not spec else f" (did you mean 'openai:{spec}'?)"


def make_model(
    spec: str,
    args: str | dict[str, Any] | None = None,
    *,
    cache_path: str | Path | None = None,
    no_cache: bool = False,
    run_dir: str | Path | None = None,
) -> ChatModel:
    """Build the model named by `spec` (`offline`, `oracle`, `openai:<model>`, `llamacpp:<gguf>`,
    `replay:<file>`, `noisy:<spec>`)."""
    from logicenveval.llm.cache import CachedModel, ReplayModel

    kwargs = parse_model_args(args)
    protocol = _protocol(kwargs.pop("protocol", None))
    stats = ModelStats()
    provider, _, name = spec.partition(":")
    model: Any
    if provider == "noisy":
        from logicenveval.llm.noisy import NoisyModel

        rate, seed = kwargs.pop("rate", 0.0), kwargs.pop("seed", 0)
        inner = make_model(name or "offline", kwargs, cache_path=cache_path, no_cache=no_cache,
                           run_dir=run_dir)
        stats = getattr(inner, "stats", None) or stats  # one set of counters for both layers
        model = NoisyModel(inner, rate=rate, seed=seed, stats=stats)
    elif provider == "replay":
        if not name:
            raise ConfigError("replay needs a cache file", field="--model", hint="write replay:<cache.sqlite>")
        unknown = sorted(set(kwargs) - REPLAY_ARGS)
        if unknown:
            raise ConfigError(f"replay takes no model argument {', '.join(unknown)}",
                              field="--model-args",
                              hint="replay answers from the recorded replies: pass only "
                              "replay_model=<provider>:<model> (or nothing)")
        cache = ReplyCache(name, read_only=True)
        cache.check(writable=False)
        target_provider, target_model = _replay_target(cache, kwargs.pop("replay_model", None))
        model = ReplayModel(cache, target_provider, target_model, stats)
    elif provider in PROVIDERS:
        factory = provider_factory(provider)
        try:
            model = factory(name, stats=stats, **kwargs) if provider in CACHED else factory(stats=stats, **kwargs)
        except TypeError as exc:
            raise ConfigError(f"bad model argument for {provider}: {exc}", field="--model-args",
                              hint=f"see docs/llm.md for the arguments of {provider}") from None
        if provider in CACHED and not no_cache:
            default = Path(run_dir).parent / "llm_cache.sqlite" if run_dir else Path("llm_cache.sqlite")
            model = CachedModel(model, ReplyCache(cache_path or default), provider, stats)
    else:
        raise ConfigError(f"unknown model {spec!r}{_model_guess(spec, provider, name)}",
                          field="--model",
                          hint="use offline, oracle, openai:<model>, llamacpp:<model.gguf>, "
                          "replay:<cache.sqlite> or noisy:<model>")
    model.run_dir = Path(run_dir) if run_dir else None
    model.stats = stats
    model.reply_protocol = protocol
    chat_model: ChatModel = model
    return chat_model
