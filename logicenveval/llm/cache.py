"""SQLite cache of LLM replies (WAL mode: many reader/writer processes of one pool).

A replay pack is opened read-only (`mode=ro`, and `immutable=1` when it has no write-ahead log:
no lock or side file is created), so replaying never changes its input, even on read-only storage.

The key is a SHA-256 of the canonical JSON of (provider, model, kind, messages, schema,
temperature, seed), so any change to a prompt template or schema is a miss, never a stale hit.
"""

from __future__ import annotations

import hashlib
import json
import os
import sqlite3
import stat
import threading
import time
import urllib.parse
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

from logicenveval.errors import CacheMissError, ConfigError
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats, well_formed

_SCHEMA = """
CREATE TABLE IF NOT EXISTS replies (
  key TEXT PRIMARY KEY,
  provider TEXT NOT NULL,
  model TEXT NOT NULL,
  kind TEXT NOT NULL,
  reply TEXT NOT NULL,
  created REAL NOT NULL
)"""
#: the columns a reply cache must have to serve replies
COLUMNS = frozenset({"key", "provider", "model", "reply"})


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

    def __init__(self, path: str | Path, *, create: bool = True, read_only: bool = False) -> None:
        self.path = Path(path)
        self.read_only = read_only
        if not create or read_only:
            try:
                mode = self.path.stat().st_mode
            except OSError:
                raise ConfigError("cache file not found", file=str(self.path),
                                  hint="replay needs a cache written by an earlier run (--cache FILE)") from None
            if not stat.S_ISREG(mode):
                raise ConfigError("not a reply cache: not a regular file", file=str(self.path),
                                  hint="pass the llm_cache.sqlite file of a run, not its folder")
        self._local = threading.local()

    def _open(self) -> sqlite3.Connection:
        if not self.read_only:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            conn = sqlite3.connect(self.path, timeout=BUSY_SECONDS, isolation_level=None)
            conn.execute(f"PRAGMA busy_timeout={int(BUSY_SECONDS * 1000)}")
            _retrying(lambda: _prepare(conn))
            return conn
        wal = self.path.with_name(self.path.name + "-wal")
        query = "mode=ro" if wal.exists() and wal.stat().st_size else "mode=ro&immutable=1"
        uri = f"file:{urllib.parse.quote(str(self.path.resolve()))}?{query}"
        return sqlite3.connect(uri, uri=True, timeout=BUSY_SECONDS, isolation_level=None)

    def _conn(self) -> sqlite3.Connection:
        conn: sqlite3.Connection | None = getattr(self._local, "conn", None)
        if conn is None or getattr(self._local, "pid", None) != os.getpid():
            conn = self._open()
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

    def models(self) -> list[tuple[str, str]]:
        """The distinct (provider, model) pairs whose replies the cache holds."""
        rows = _retrying(lambda: self._conn().execute(
            "SELECT DISTINCT provider, model FROM replies").fetchall())
        return sorted((str(p), str(m)) for p, m in rows)

    def check(self, *, writable: bool = True) -> None:
        """Fail before the first unit when the file cannot serve as a cache (it would fail all)."""
        try:
            conn = self._conn()
            columns = {str(row[1]) for row in conn.execute("PRAGMA table_info(replies)")}
            missing = sorted(COLUMNS - columns)
            if missing:
                self._local.conn = None
                what = "no table `replies`" if not columns else f"no column {', '.join(missing)}"
                raise ConfigError(f"not a reply cache: {what}", file=str(self.path),
                                  hint="pass a cache written by a run (--cache FILE), or a new path")
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
        #: the model's identity in the cache: `cache_name` when the inner model has one (a local
        #: model file's name and content hash), else its name
        self.cache_name: str = getattr(inner, "cache_name", None) or inner.name

    def complete(self, request: ChatRequest) -> str:
        key = cache_key(self.provider, self.cache_name, request)
        hit = self.cache.get(key)
        if hit is not None:
            self.stats.add(cache_hits=1)
            return hit
        self.stats.add(cache_misses=1)
        reply = well_formed(self.inner.complete(request))
        self.cache.put(key, self.provider, self.cache_name, request.kind, reply)
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
