"""OpenAI-compatible `/v1/chat/completions` over httpx (OpenAI, DeepSeek, vLLM, Ollama, llama.cpp).

Retries are bounded with exponential backoff and jitter on 429/5xx, timeouts and connection
errors, honouring `Retry-After`; a semaphore bounds concurrent requests per process. The API key
is read from the environment variable named by `api_key_env` and only ever placed in the
`Authorization` header: never in messages, logs, reprs or reports.
"""

from __future__ import annotations

import email.utils
import logging
import os
import threading
import time
from typing import Any

import httpx
import numpy as np

from logicenveval.errors import ConfigError, ModelConnectionError
from logicenveval.llm.base import ChatRequest, ModelStats

log = logging.getLogger(__name__)

_RETRY_STATUS = frozenset({408, 409, 425, 429, 500, 502, 503, 504})


def _retry_after(response: httpx.Response) -> float | None:
    value = response.headers.get("retry-after")
    if not value:
        return None
    try:
        return max(0.0, float(value))
    except ValueError:
        parsed = email.utils.parsedate_to_datetime(value)
        return max(0.0, parsed.timestamp() - time.time()) if parsed else None


class OpenAIChatModel:
    """One model on one OpenAI-compatible server."""

    def __init__(
        self,
        model: str,
        *,
        base_url: str = "https://api.openai.com/v1",
        api_key_env: str | None = None,
        timeout: float = 60.0,
        connect_timeout: float = 10.0,
        max_retries: int = 4,
        backoff_base: float = 1.0,
        backoff_max: float = 30.0,
        concurrency: int = 4,
        json_schema: str | bool = "auto",
        max_tokens: int | None = None,
        seed: int = 0,
        stats: ModelStats | None = None,
    ) -> None:
        if not model:
            raise ConfigError("missing model name", field="--model", hint="write openai:<model>")
        self.name = model
        self.base_url = base_url.rstrip("/")
        self._api_key_env = api_key_env
        self._key: str | None = None
        if api_key_env:
            key = os.environ.get(api_key_env)
            if not key:
                raise ConfigError(f"environment variable {api_key_env} is not set",
                                  field="--model-args api_key_env",
                                  hint=f"export {api_key_env}=... or drop api_key_env for a local server")
            self._key = key
        self.timeout = httpx.Timeout(timeout, connect=connect_timeout)
        self.max_retries = max_retries
        self.backoff_base = backoff_base
        self.backoff_max = backoff_max
        self._semaphore = threading.BoundedSemaphore(max(1, concurrency))
        self._schema_mode: str = str(json_schema).lower()
        if self._schema_mode not in ("auto", "true", "false"):
            raise ConfigError(f"json_schema={json_schema!r}", field="--model-args json_schema",
                              hint="use auto, true or false")
        self.max_tokens = max_tokens
        self._rng = np.random.default_rng(seed)
        self.stats = stats or ModelStats()
        self._client = httpx.Client(timeout=self.timeout)

    def __repr__(self) -> str:  # never shows the key
        return f"OpenAIChatModel(model={self.name!r}, base_url={self.base_url!r})"

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
        if self.max_tokens:
            body["max_tokens"] = self.max_tokens
        if request.schema is not None and self._schema_mode != "false":
            body["response_format"] = {
                "type": "json_schema",
                "json_schema": {"name": request.kind, "schema": request.schema, "strict": False},
            }
        return body

    def _sleep(self, attempt: int, response: httpx.Response | None) -> None:
        wait = _retry_after(response) if response is not None else None
        if wait is None:
            wait = min(self.backoff_max, self.backoff_base * (2**attempt))
            wait *= 0.5 + float(self._rng.random())  # jitter: spread synchronized clients
        time.sleep(min(wait, self.backoff_max))

    def complete(self, request: ChatRequest) -> str:
        url = f"{self.base_url}/chat/completions"
        last = "no attempt made"
        with self._semaphore:
            attempt = 0
            while True:
                start = time.perf_counter()
                response: httpx.Response | None = None
                try:
                    response = self._client.post(url, json=self._body(request), headers=self._headers())
                except httpx.TimeoutException:
                    last = f"timed out after {self.timeout.read}s"
                except httpx.TransportError as exc:
                    last = f"connection failed ({type(exc).__name__})"
                else:
                    if response.status_code == 400 and self._schema_mode == "auto" and "response_format" in response.text:
                        self._schema_mode = "false"  # server lacks JSON-schema output: plain JSON
                        continue
                    if response.status_code < 300:
                        return self._content(response, time.perf_counter() - start, request.kind)
                    last = f"HTTP {response.status_code}: {response.text[:200]!r}"
                    if response.status_code not in _RETRY_STATUS:
                        raise ModelConnectionError(
                            f"{url} rejected a {request.kind!r} request: {last}",
                            hint="check the model name and --model-args of the server",
                        )
                if attempt >= self.max_retries:
                    raise ModelConnectionError(
                        f"{url} failed a {request.kind!r} request {attempt + 1} time(s); last: {last}",
                        hint="check that the server is up and base_url is right, or raise max_retries/timeout",
                    )
                self.stats.add(retries=1)
                log.warning("retrying %s request to %s after %s", request.kind, self.base_url, last)
                self._sleep(attempt, response)
                attempt += 1

    def _content(self, response: httpx.Response, latency: float, kind: str) -> str:
        try:
            data = response.json()
            content = data["choices"][0]["message"]["content"]
        except (ValueError, KeyError, IndexError, TypeError):
            raise ModelConnectionError(
                f"{self.base_url} answered a {kind!r} request without choices[0].message.content",
                hint="is base_url an OpenAI-compatible /v1 endpoint?",
            ) from None
        usage = data.get("usage") or {}
        self.stats.add(
            requests=1,
            latency_s=latency,
            prompt_tokens=int(usage.get("prompt_tokens") or 0),
            completion_tokens=int(usage.get("completion_tokens") or 0),
        )
        return str(content or "")

    def preflight(self) -> None:
        """Fail fast when the endpoint is unreachable (any HTTP answer counts as reachable)."""
        try:
            self._client.get(f"{self.base_url}/models", headers=self._headers(),
                             timeout=httpx.Timeout(10.0, connect=5.0))
        except httpx.TransportError as exc:
            raise ModelConnectionError(
                f"cannot reach {self.base_url} ({type(exc).__name__})",
                hint="start the server or fix --model-args base_url=...",
            ) from None
