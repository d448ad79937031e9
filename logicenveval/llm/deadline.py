"""An overall deadline on HTTP requests, down to each socket operation.

httpx bounds each read, not a request: a server that sends its status line and then one
header line a second never lets a read time out, so neither a read timeout nor a deadline
checked between body chunks ends the request (issue 50: the preflight `GET /models` never
ended). Here every connect, TLS handshake, write and read of a client's connections is given
at most the time left until the deadline of the request in progress on this thread
(`deadline`), so connecting, sending, the headers and the body all end by it: past it the
next socket operation raises the timeout httpx reports for a slow server (`httpx.ReadTimeout`
and its siblings).
"""

from __future__ import annotations

import contextlib
import ssl
import threading
import time
from collections.abc import Iterable, Iterator
from typing import Any

import httpcore
import httpx

_local = threading.local()


@contextlib.contextmanager
def deadline(at: float) -> Iterator[None]:
    """Requests of this thread made in the block end by monotonic time `at` (or by an outer
    deadline, if sooner) on clients made by `client`."""
    outer: float | None = getattr(_local, "at", None)
    _local.at = at if outer is None else min(outer, at)
    try:
        yield
    finally:
        _local.at = outer


def _bounded(timeout: float | None, error: type[httpcore.TimeoutException]) -> float | None:
    at: float | None = getattr(_local, "at", None)
    if at is None:
        return timeout
    left = at - time.monotonic()
    if left <= 0:
        raise error("the request's total time ran out")
    return left if timeout is None else min(timeout, left)


class _Stream(httpcore.NetworkStream):
    def __init__(self, inner: httpcore.NetworkStream) -> None:
        self._inner = inner

    def read(self, max_bytes: int, timeout: float | None = None) -> bytes:
        return self._inner.read(max_bytes, _bounded(timeout, httpcore.ReadTimeout))

    def write(self, buffer: bytes, timeout: float | None = None) -> None:
        self._inner.write(buffer, _bounded(timeout, httpcore.WriteTimeout))

    def close(self) -> None:
        self._inner.close()

    def start_tls(self, ssl_context: ssl.SSLContext, server_hostname: str | None = None,
                  timeout: float | None = None) -> httpcore.NetworkStream:
        return _Stream(self._inner.start_tls(ssl_context, server_hostname,
                                             _bounded(timeout, httpcore.ConnectTimeout)))

    def get_extra_info(self, info: str) -> Any:
        return self._inner.get_extra_info(info)


class _Backend(httpcore.NetworkBackend):
    def __init__(self, inner: httpcore.NetworkBackend) -> None:
        self._inner = inner

    def connect_tcp(self, host: str, port: int, timeout: float | None = None,
                    local_address: str | None = None,
                    socket_options: Iterable[Any] | None = None) -> httpcore.NetworkStream:
        return _Stream(self._inner.connect_tcp(host, port, _bounded(timeout, httpcore.ConnectTimeout),
                                               local_address, socket_options))

    def connect_unix_socket(self, path: str, timeout: float | None = None,
                            socket_options: Iterable[Any] | None = None) -> httpcore.NetworkStream:
        return _Stream(self._inner.connect_unix_socket(
            path, _bounded(timeout, httpcore.ConnectTimeout), socket_options))

    def sleep(self, seconds: float) -> None:
        self._inner.sleep(seconds)


def client(**kwargs: Any) -> httpx.Client:
    """An `httpx.Client` (proxies from the environment included) whose requests honour
    `deadline`. httpx offers no hook for a network backend, so the backend of each of the
    client's connection pools is wrapped; `tests/test_hostile_inputs4.py` checks that it still
    is on the installed httpx."""
    made = httpx.Client(**kwargs)
    transports: list[object] = [made._transport, *made._mounts.values()]
    for transport in transports:
        pool = getattr(transport, "_pool", None)
        backend = getattr(pool, "_network_backend", None)
        if isinstance(backend, httpcore.NetworkBackend) and not isinstance(backend, _Backend):
            pool._network_backend = _Backend(backend)  # type: ignore[union-attr]
    return made
