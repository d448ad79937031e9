"""OpenAI-compatible `/v1/chat/completions` over httpx (OpenAI, DeepSeek, vLLM, Ollama, llama.cpp).

Retries are bounded with exponential backoff and jitter on 429/5xx, timeouts and connection
errors, honouring `Retry-After`; a semaphore bounds concurrent requests per process. The API key
is read from the environment variable named by `api_key_env` and only ever placed in the
`Authorization` header: never in messages, logs, reprs or reports.
"""

from __future__ import annotations

import email.utils
import json
import logging
import os
import threading
import time
from typing import Any

import httpx
import numpy as np

from logicenveval.errors import ConfigError, ModelConnectionError, UnitBudgetError
from logicenveval.limits import limit, raise_hint
from logicenveval.llm.base import TRUNCATION_MARK, ChatRequest, ModelStats, well_formed
from logicenveval.llm.deadline import client as deadline_client
from logicenveval.llm.deadline import deadline as overall_deadline
from logicenveval.redact import redact, register_secret, strip_url_credentials

log = logging.getLogger(__name__)

_RETRY_STATUS = frozenset({408, 409, 425, 429, 500, 502, 503, 504})


def _retry_after(response: httpx.Response) -> float | None:
    value = response.headers.get("retry-after")
    if not value:
        return None
    try:
        return max(0.0, float(value))
    except ValueError:
        pass
    try:  # an HTTP date; anything else (`soon`) is ignored and the backoff applies
        parsed = email.utils.parsedate_to_datetime(value)
    except (TypeError, ValueError, IndexError):
        return None
    if parsed.tzinfo is None:
        return None
    return max(0.0, parsed.timestamp() - time.time())


def _number(name: str, value: object, *, low: float, integer: bool = False) -> float:
    """A numeric model argument, checked once at construction (preflight) with a clear error."""
    ok = isinstance(value, int | float) and not isinstance(value, bool)
    if ok and integer and not isinstance(value, int):
        ok = False
    if not ok or not (float(value) >= low) or float(value) == float("inf"):  # type: ignore[arg-type]
        kind = "an integer" if integer else "a number"
        raise ConfigError(f"{name}={value!r} is not {kind} >= {low:g}", field=f"--model-args {name}",
                          hint=f"write {name}=<{kind.split()[-1]}> (see docs/llm.md)")
    return float(value)  # type: ignore[arg-type]


#: longest base_url accepted (a URL is echoed in errors: a 100 kB one would flood them)
MAX_URL_CHARS = 2048
#: bytes of a preflight `GET /models` (or a server's health and identity) reply that are read
PROBE_BYTES = 1_000_000
#: total seconds of one such probe, however slowly the server drips its reply
PROBE_SECONDS = 15.0


def check_base_url(base_url: object) -> str:
    """`base_url` without its trailing slash, refused with a ConfigError unless httpx can use it
    (scheme http(s), a host, a port in range): `http://h:1:2` raised httpx.InvalidURL at the
    first request."""
    text = base_url if isinstance(base_url, str) else repr(base_url)
    shown = redact(text if len(text) <= 80 else text[:77] + "...")
    problem = ""
    if not isinstance(base_url, str) or not base_url.startswith(("http://", "https://")):
        problem = "is not an http(s) URL"
    elif len(base_url) > MAX_URL_CHARS:
        problem = f"is longer than {MAX_URL_CHARS} characters"
    else:
        try:
            url = httpx.URL(base_url)
            if not url.host:
                problem = "has no host"
            elif url.port is not None and not 0 < url.port < 65536:
                problem = f"has port {url.port}, not a TCP port"
        except (httpx.InvalidURL, ValueError, TypeError) as exc:
            problem = f"does not parse ({redact(str(exc))[:120]})"
    if problem:
        raise ConfigError(f"base_url={shown!r} {problem}", field="--model-args base_url",
                          hint="e.g. base_url=http://localhost:8000/v1")
    return str(base_url).rstrip("/")


def bounded_get(client: httpx.Client, url: str, *, headers: dict[str, str] | None = None,
                seconds: float | None = None, cap: int = PROBE_BYTES) -> tuple[int, bytes]:
    """GET `url`: its status and at most `cap` bytes of its body, all within `seconds` in total
    (a server dripping one byte a second, or sending 400 MB, cannot hold or flood the caller).
    Connecting and the headers count too on a client made by `llm.deadline.client` (a server
    dripping one header line a second). Raises httpx.TimeoutException when the time runs out,
    ValueError when the body is larger."""
    seconds = PROBE_SECONDS if seconds is None else seconds
    deadline = time.monotonic() + seconds

    def left() -> float:
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            raise httpx.ReadTimeout(f"no complete reply within {seconds:g}s")
        return remaining

    timeout = httpx.Timeout(min(10.0, left()), connect=min(5.0, left()))
    with overall_deadline(deadline), client.stream("GET", url, headers=headers,
                                                   timeout=timeout) as response:
        chunks: list[bytes] = []
        size = 0
        for chunk in response.iter_bytes():
            size += len(chunk)
            if size > cap:
                raise ValueError(f"a reply larger than {cap} bytes")
            chunks.append(chunk)
            left()
        return response.status_code, b"".join(chunks)


def _count(usage: object, key: str) -> int:
    """A token count of a reply's `usage`, 0 when the server sent none or nonsense (a malformed
    `usage` is not the model's answer and must not fail the unit)."""
    value = usage.get(key) if isinstance(usage, dict) else None
    if isinstance(value, bool) or not isinstance(value, int | float) or not 0 <= value < 2**53:
        return 0
    return int(value)


class _Deadline(Exception):
    """The total time of one request (or of the unit) ran out while a reply was arriving."""


class _Reply:
    def __init__(self, status: int, headers: httpx.Headers, body: bytes) -> None:
        self.status_code = status
        self.headers = headers
        self.text = body.decode("utf-8", errors="replace")


#: seconds of a request when no `timeout` is given (raised by the bound: `seconds_per_token`)
DEFAULT_TIMEOUT = 60.0
#: seconds per reply token a request may take when no `timeout` is given (4 tokens/s: a 1.5B
#: model on a loaded 2-core machine)
DEFAULT_SECONDS_PER_TOKEN = 0.25


class OpenAIChatModel:
    """One model on one OpenAI-compatible server."""

    def __init__(
        self,
        model: str,
        *,
        base_url: str = "https://api.openai.com/v1",
        api_key_env: str | None = None,
        timeout: float | None = None,
        connect_timeout: float = 10.0,
        max_retries: int = 4,
        backoff_base: float = 1.0,
        backoff_max: float = 30.0,
        concurrency: int = 4,
        json_schema: str | bool = "auto",
        max_tokens: int | None = None,
        seed: int = 0,
        unit_timeout: float = 1800.0,
        seconds_per_token: float | None = None,
        grammar: str = "schema",
        stats: ModelStats | None = None,
    ) -> None:
        if not model:
            raise ConfigError("missing model name", field="--model", hint="write openai:<model>")
        self.name = model
        #: the model's identity in reply caches when it differs from `name` (llamacpp: the
        #: file's stem and content hash)
        self.cache_name: str | None = None
        self.base_url = check_base_url(base_url)
        self._shown_url = strip_url_credentials(self.base_url)
        self._api_key_env = api_key_env
        self._key: str | None = None
        if api_key_env:
            key = os.environ.get(str(api_key_env))
            if not key:
                raise ConfigError(f"environment variable {api_key_env} is not set",
                                  field="--model-args api_key_env",
                                  hint=f"export {api_key_env}=... or drop api_key_env for a local server")
            self._key = key
            register_secret(key)
        given = timeout is not None
        timeout = _number("timeout", DEFAULT_TIMEOUT if timeout is None else timeout, low=0.001)
        connect_timeout = _number("connect_timeout", connect_timeout, low=0.001)
        #: total seconds of one request (connect + sending + the whole reply), not per read
        self.request_timeout = timeout
        #: a request bounded to N reply tokens may take N x this many seconds when that is more
        #: than `timeout` (a 2-core machine writes 4-17 tokens/s): the bound, not a fixed 60 s,
        #: decides how long a long reply may take. A `timeout` the user gives stays a fixed bound
        #: unless `seconds_per_token` is given too.
        self.seconds_per_token = _number("seconds_per_token", seconds_per_token, low=0) \
            if seconds_per_token is not None else (0.0 if given else DEFAULT_SECONDS_PER_TOKEN)
        self.timeout = httpx.Timeout(timeout, connect=connect_timeout)
        self.max_retries = int(_number("max_retries", max_retries, low=0, integer=True))
        self.backoff_base = _number("backoff_base", backoff_base, low=0)
        self.backoff_max = _number("backoff_max", backoff_max, low=0)
        concurrency = int(_number("concurrency", concurrency, low=1, integer=True))
        self._semaphore = threading.BoundedSemaphore(concurrency)
        self._schema_mode: str = str(json_schema).lower()
        if self._schema_mode not in ("auto", "true", "false"):
            raise ConfigError(f"json_schema={json_schema!r}", field="--model-args json_schema",
                              hint="use auto, true or false")
        if grammar not in ("schema", "compact"):
            raise ConfigError(f"grammar={grammar!r}", field="--model-args grammar",
                              hint="use schema (response_format) or compact (llama.cpp GBNF, no whitespace)")
        #: `compact`: send llama.cpp a GBNF grammar without whitespace (`llm.grammar`) instead of
        #: the JSON schema, whose grammar lets layout spend the reply's bound
        self.grammar = grammar
        self._grammars: dict[str, str | None] = {}
        self.max_tokens = None if max_tokens is None else int(
            _number("max_tokens", max_tokens, low=1, integer=True))
        self._rng = np.random.default_rng(int(_number("seed", seed, low=0, integer=True)))
        #: every request of this model instance (one per unit) ends by this monotonic time
        self._unit_deadline = time.monotonic() + _number("unit_timeout", unit_timeout, low=0.001)
        self.stats = stats or ModelStats()
        #: every socket operation of a request ends by the request's deadline (`_post`): a
        #: server dripping its headers cannot hold a request past it
        self._client = deadline_client(timeout=self.timeout)

    def __repr__(self) -> str:  # never shows the key
        return f"OpenAIChatModel(model={self.name!r}, base_url={self._shown_url!r})"

    def _headers(self) -> dict[str, str]:
        headers = {"Content-Type": "application/json"}
        if self._key:
            headers["Authorization"] = f"Bearer {self._key}"
        return headers

    def _body(self, request: ChatRequest) -> dict[str, Any]:
        body: dict[str, Any] = {
            "model": self.name,
            "messages": request.messages,
            "temperature": request.temperature,
        }
        if request.seed is not None:
            body["seed"] = request.seed
        bound = self.max_tokens or request.max_tokens
        if bound:
            body["max_tokens"] = bound
        compact = self._compact(request.schema) if request.schema is not None else None
        if compact is not None and self._schema_mode != "false":
            body["grammar"] = compact
        elif request.schema is not None and self._schema_mode != "false":
            body["response_format"] = {
                "type": "json_schema",
                "json_schema": {"name": request.kind, "schema": request.schema, "strict": False},
            }
        return body

    def _compact(self, schema: dict[str, Any]) -> str | None:
        """The compact GBNF of `schema` when `grammar=compact` (None: send the schema; also for
        a schema the converter cannot write, e.g. an unsupported pattern)."""
        if self.grammar != "compact":
            return None
        key = json.dumps(schema, sort_keys=True)
        if key not in self._grammars:
            from logicenveval.llm.grammar import to_gbnf

            try:
                self._grammars[key] = to_gbnf(schema)
            except ConfigError as exc:
                log.warning("sending the JSON schema instead of a compact grammar: %s", exc.message)
                self._grammars[key] = None
        return self._grammars[key]

    def _sleep(self, attempt: int, response: _Reply | None) -> None:
        wait = _retry_after(response) if response is not None else None  # type: ignore[arg-type]
        if wait is None:
            wait = min(self.backoff_max, self.backoff_base * (2**attempt))
            wait *= 0.5 + float(self._rng.random())  # jitter: spread synchronized clients
        wait = min(wait, self.backoff_max, max(0.0, self._unit_deadline - time.monotonic()))
        time.sleep(wait)

    def timeout_for(self, body: dict[str, Any]) -> float:
        """Total seconds one request may take: `timeout`, or its reply bound times
        `seconds_per_token` when that is more."""
        bound = body.get("max_tokens")
        return max(self.request_timeout, (bound or 0) * self.seconds_per_token)

    def _post(self, url: str, body: dict[str, Any]) -> _Reply:
        """One POST whose total time — connecting, sending, headers and body — is bounded (a
        server trickling its body or dripping its headers cannot hold it) and whose reply size
        is bounded."""
        allowed = self.timeout_for(body)
        deadline = min(time.monotonic() + allowed, self._unit_deadline)
        cap = limit("max_reply_bytes")

        def remaining() -> float:
            left = deadline - time.monotonic()
            if left <= 0:
                raise _Deadline
            return left

        timeout = httpx.Timeout(min(max(self.timeout.read or 60.0, allowed), remaining()),
                                connect=min(self.timeout.connect or 10.0, remaining()))
        with overall_deadline(deadline), self._client.stream(
                "POST", url, json=body, headers=self._headers(), timeout=timeout) as response:
            chunks: list[bytes] = []
            size = 0
            for chunk in response.iter_bytes():  # decoded: a compressed bomb counts in full
                size += len(chunk)
                if size > cap:
                    raise ModelConnectionError(
                        f"{self._shown_url} sent a reply larger than {cap} bytes",
                        hint="lower max_tokens, or " + raise_hint("max_reply_bytes"))
                chunks.append(chunk)
                remaining()
            return _Reply(response.status_code, response.headers, b"".join(chunks))

    def complete(self, request: ChatRequest) -> str:
        url = f"{self.base_url}/chat/completions"
        shown = f"{self._shown_url}/chat/completions"
        last = "no attempt made"
        with self._semaphore:
            attempt = 0
            while True:
                if time.monotonic() >= self._unit_deadline:
                    raise UnitBudgetError(
                        f"the unit's time budget ran out before a {request.kind!r} request to "
                        f"{shown}; last: {last}",
                        hint="raise --model-args unit_timeout=<seconds>, or check the server")
                start = time.perf_counter()
                response: _Reply | None = None
                try:
                    response = self._post(url, self._body(request))
                except (httpx.TimeoutException, _Deadline):
                    last = f"timed out: no complete reply within {self.timeout_for(self._body(request)):g}s"
                except httpx.TransportError as exc:
                    last = f"connection failed ({type(exc).__name__})"
                else:
                    if response.status_code == 400 and self.grammar == "compact" and "grammar" in response.text:
                        self.grammar = "schema"  # server without GBNF grammars: the JSON schema
                        continue
                    if response.status_code == 400 and self._schema_mode == "auto" and "response_format" in response.text:
                        self._schema_mode = "false"  # server lacks JSON-schema output: plain JSON
                        continue
                    if response.status_code < 300:
                        return self._content(response, time.perf_counter() - start, request.kind)
                    last = redact(f"HTTP {response.status_code}: {response.text[:200]!r}")
                    if response.status_code not in _RETRY_STATUS:
                        raise ModelConnectionError(
                            f"{shown} rejected a {request.kind!r} request: {last}",
                            hint="check the model name, the API key and --model-args of the server",
                        )
                if attempt >= self.max_retries:
                    raise ModelConnectionError(
                        f"{shown} failed a {request.kind!r} request {attempt + 1} time(s); last: {last}",
                        hint="check that the server is up and base_url is right, or raise max_retries/timeout",
                    )
                if time.monotonic() >= self._unit_deadline:  # no retry the budget cannot hold
                    raise UnitBudgetError(
                        f"the unit's time budget ran out during a {request.kind!r} request to "
                        f"{shown}; last: {last}",
                        hint="raise --model-args unit_timeout=<seconds>, or check the server")
                self.stats.add(retries=1)
                log.warning("retrying %s request to %s after %s", request.kind, self._shown_url, last)
                self._sleep(attempt, response)
                attempt += 1

    def _content(self, response: _Reply, latency: float, kind: str) -> str:
        try:
            data = json.loads(response.text)
            choice = data["choices"][0]
            content = choice["message"]["content"]
            finish = choice.get("finish_reason")
        except (ValueError, KeyError, IndexError, TypeError, AttributeError, RecursionError):
            raise ModelConnectionError(
                f"{self._shown_url} answered a {kind!r} request without choices[0].message.content",
                hint="is base_url an OpenAI-compatible /v1 endpoint?",
            ) from None
        usage = data.get("usage")
        self.stats.add(
            requests=1,
            latency_s=latency,
            prompt_tokens=_count(usage, "prompt_tokens"),
            completion_tokens=_count(usage, "completion_tokens"),
        )
        text = redact(well_formed(str(content or "")))  # a server echoing our headers must not leak the key
        return text + TRUNCATION_MARK if finish == "length" else text

    def preflight(self) -> None:
        """Fail fast on what would fail every unit: an unreachable endpoint or a refused key."""
        try:
            status, _ = bounded_get(self._client, f"{self.base_url}/models", headers=self._headers())
        except httpx.TimeoutException:
            raise ModelConnectionError(
                f"{self._shown_url}/models sent no complete reply in time (a slow or foreign server)",
                hint="check that base_url names an OpenAI-compatible server that is up") from None
        except httpx.TransportError as exc:
            raise ModelConnectionError(
                f"cannot reach {self._shown_url} ({type(exc).__name__})",
                hint="start the server or fix --model-args base_url=...",
            ) from None
        except ValueError as exc:
            raise ModelConnectionError(
                f"{self._shown_url}/models sent {exc}",
                hint="check that base_url names an OpenAI-compatible server") from None
        if status in (401, 403):
            raise ModelConnectionError(
                f"{self._shown_url} refused the credentials (HTTP {status})",
                hint="check the key in the variable named by api_key_env"
                if self._key else "the server needs a key: --model-args api_key_env=<VARIABLE>",
            )
