"""SQLite cache of LLM replies (WAL mode: many reader/writer processes of one pool).

The key is a SHA-256 of the canonical JSON of (provider, model, kind, messages, schema,
temperature, seed), so any change to a prompt template or schema is a miss, never a stale hit.
"""

from __future__ import annotations

import hashlib
import json
import os
import sqlite3
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from logicenveval.errors import CacheMissError, ConfigError
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats

_SCHEMA = """
CREATE TABLE IF NOT EXISTS replies (
  key TEXT PRIMARY KEY,
  provider TEXT NOT NULL,
  model TEXT NOT NULL,
  kind TEXT NOT NULL,
  reply TEXT NOT NULL,
  created REAL NOT NULL
)"""


def cache_key(provider: str, model: str, request: ChatRequest) -> str:
    blob = json.dumps(
        {
            "provider": provider,
            "model": model,
            "kind": request.kind,
            "messages": request.messages,
            "schema": request.schema,
            "temperature": request.temperature,
            "seed": request.seed,
            # only when bounded, so that keys of unbounded requests stay as they were
            **({"max_tokens": request.max_tokens} if request.max_tokens is not None else {}),
        },
        sort_keys=True,
        separators=(",", ":"),
    )
    return hashlib.sha256(blob.encode()).hexdigest()


#: how long an operation waits for other processes' locks before it fails (seconds)
BUSY_SECONDS = 60.0
T = TypeVar("T")


def _busy(exc: sqlite3.OperationalError) -> bool:
    text = str(exc).lower()
    return "locked" in text or "busy" in text


def _retrying(action: Callable[[], T]) -> T:
    """`action`, retried while another connection holds a lock SQLite will not wait for.

    SQLite's busy timeout covers ordinary lock waits, but not all: switching a new file to WAL
    (which needs the file to itself) and a few WAL recovery states return "database is locked"
    at once. With several workers opening one new cache together, one of them got that error
    and lost its unit; here it waits (backing off) up to `BUSY_SECONDS` like any other lock."""
    deadline = time.monotonic() + BUSY_SECONDS
    pause = 0.005
    while True:
        try:
            return action()
        except sqlite3.OperationalError as exc:
            if not _busy(exc) or time.monotonic() + pause > deadline:
                raise
        time.sleep(pause)
        pause = min(pause * 2, 0.25)


class ReplyCache:
    """One connection per process and thread, opened lazily (connections never cross a fork).

    Many processes share one cache file: the file is in WAL mode (readers never block the
    writer), every connection waits for locks (`busy_timeout`), and what SQLite will not wait
    for is retried (`_retrying`), so concurrent workers never lose a reply or fail a unit."""

    def __init__(self, path: str | Path, *, create: bool = True) -> None:
        self.path = Path(path)
        if not create and not self.path.exists():
            raise ConfigError("cache file not found", file=str(self.path),
                              hint="replay needs a cache written by an earlier run (--cache FILE)")
        self._local = threading.local()

    def _conn(self) -> sqlite3.Connection:
        conn: sqlite3.Connection | None = getattr(self._local, "conn", None)
        if conn is None or getattr(self._local, "pid", None) != os.getpid():
            self.path.parent.mkdir(parents=True, exist_ok=True)
            conn = sqlite3.connect(self.path, timeout=BUSY_SECONDS, isolation_level=None)
            conn.execute(f"PRAGMA busy_timeout={int(BUSY_SECONDS * 1000)}")
            _retrying(lambda: _prepare(conn))
            self._local.conn, self._local.pid = conn, os.getpid()
        return conn

    def get(self, key: str) -> str | None:
        row = _retrying(lambda: self._conn().execute(
            "SELECT reply FROM replies WHERE key = ?", (key,)).fetchone())
        return None if row is None else str(row[0])

    def put(self, key: str, provider: str, model: str, kind: str, reply: str) -> None:
        _retrying(lambda: self._conn().execute(
            "INSERT OR REPLACE INTO replies (key, provider, model, kind, reply, created) "
            "VALUES (?, ?, ?, ?, ?, ?)",
            (key, provider, model, kind, reply, time.time()),
        ))

    def __len__(self) -> int:
        return int(_retrying(lambda: self._conn().execute("SELECT COUNT(*) FROM replies").fetchone()[0]))

    def check(self, *, writable: bool = True) -> None:
        """Fail before the first unit when the file cannot serve as a cache (it would fail all)."""
        try:
            conn = self._conn()
            conn.execute("SELECT COUNT(*) FROM replies").fetchone()
            if writable:
                conn.execute("BEGIN IMMEDIATE")
                conn.execute("ROLLBACK")
        except (sqlite3.Error, OSError) as exc:
            self._local.conn = None
            raise ConfigError(f"the reply cache is unusable: {exc}", file=str(self.path),
                              hint="point --cache at a writable SQLite file (or a new path), "
                              "or pass --no-cache") from None


def _prepare(conn: sqlite3.Connection) -> None:
    """WAL mode (set once per file: it persists), then the table."""
    mode = conn.execute("PRAGMA journal_mode").fetchone()[0]
    if str(mode).lower() != "wal":
        conn.execute("PRAGMA journal_mode=WAL")
    conn.execute("PRAGMA synchronous=NORMAL")
    conn.execute(_SCHEMA)


class CachedModel:
    """Serves replies from the cache, asking the wrapped model only on a miss."""

    def __init__(self, inner: ChatModel, cache: ReplyCache, provider: str, stats: ModelStats) -> None:
        self.inner = inner
        self.cache = cache
        self.provider = provider
        self.stats = stats
        self.name = inner.name

    def complete(self, request: ChatRequest) -> str:
        key = cache_key(self.provider, self.name, request)
        hit = self.cache.get(key)
        if hit is not None:
            self.stats.add(cache_hits=1)
            return hit
        self.stats.add(cache_misses=1)
        reply = self.inner.complete(request)
        self.cache.put(key, self.provider, self.name, request.kind, reply)
        return reply

    def preflight(self) -> None:
        self.cache.check()
        check = getattr(self.inner, "preflight", None)
        if callable(check):
            check()


class ReplayModel:
    """`replay:FILE`: answers only from a cache; a miss is an error naming the request kind."""

    def __init__(self, cache: ReplyCache, provider: str, model: str, stats: ModelStats) -> None:
        self.cache = cache
        self.provider = provider
        self.name = model
        self.stats = stats

    def complete(self, request: ChatRequest) -> str:
        hit = self.cache.get(cache_key(self.provider, self.name, request))
        if hit is None:
            self.stats.add(cache_misses=1)
            raise CacheMissError(
                f"no cached reply for a {request.kind!r} request of model {self.provider}:{self.name}",
                file=str(self.cache.path),
                hint="replay with the same model args, seed and prompts as the recorded run "
                "(pass replay_model=<provider:model> if it differs)",
            )
        self.stats.add(cache_hits=1)
        return hit

    def preflight(self) -> None:
        self.cache.check(writable=False)
