"""SQLite cache of LLM replies (WAL mode: many reader/writer processes of one pool).

A replay pack is opened read-only (`mode=ro`, and `immutable=1` when it has no write-ahead log:
no lock or side file is created), so replaying never changes its input, even on read-only storage.

The key is a SHA-256 of the canonical JSON of (provider, model, kind, messages, schema,
temperature, seed), so any change to a prompt template or schema is a miss, never a stale hit.

Each reply keeps what it cost when it was recorded (prompt and completion tokens, seconds): a
replay serves the reply at no cost, and reports the recorded cost beside it (`recorded_*`
counters, results.json `timing.per_task`), so a user planning a run on a slow model reads what
each method asked of each task from any pack. Caches written before these columns serve as
before (their recorded cost is unknown and counted as such) and gain the columns when opened
for writing.
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
from dataclasses import dataclass
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
  created REAL NOT NULL,
  prompt_tokens INTEGER,
  completion_tokens INTEGER,
  seconds REAL
)"""
#: what a reply cost when it was recorded (nullable: added after the first packs were written)
COST_COLUMNS = (("prompt_tokens", "INTEGER"), ("completion_tokens", "INTEGER"), ("seconds", "REAL"))
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
            # whether rows carry a recorded cost: a read-only pack written before the columns has none
            columns = {str(row[1]) for row in conn.execute("PRAGMA table_info(replies)")}
            self._local.has_cost = all(name in columns for name, _ in COST_COLUMNS)
            self._local.conn, self._local.pid = conn, os.getpid()
        return conn

    def get(self, key: str) -> str | None:
        hit = self.get_recorded(key)
        return None if hit is None else hit[0]

    def get_recorded(self, key: str) -> tuple[str, RecordedCost | None] | None:
        """The reply and what it cost when recorded (None when the cache predates the columns
        or the model reported no usage)."""
        def read() -> tuple[str, RecordedCost | None] | None:
            conn = self._conn()
            if not self._local.has_cost:
                row = conn.execute("SELECT reply FROM replies WHERE key = ?", (key,)).fetchone()
                return None if row is None else (str(row[0]), None)
            row = conn.execute("SELECT reply, prompt_tokens, completion_tokens, seconds FROM replies "
                               "WHERE key = ?", (key,)).fetchone()
            if row is None:
                return None
            cost = None if row[3] is None else RecordedCost(int(row[1] or 0), int(row[2] or 0), float(row[3]))
            return str(row[0]), cost
        return _retrying(read)

    def put(self, key: str, provider: str, model: str, kind: str, reply: str,
            cost: RecordedCost | None = None) -> None:
        c = cost or RecordedCost(None, None, None)
        _retrying(lambda: self._conn().execute(
            "INSERT OR REPLACE INTO replies (key, provider, model, kind, reply, created, "
            "prompt_tokens, completion_tokens, seconds) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
            (key, provider, model, kind, reply, time.time(), c.prompt_tokens, c.completion_tokens,
             None if c.seconds is None else round(c.seconds, 3)),
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
    """WAL mode (set once per file: it persists), then the table, with the cost columns added to
    a cache written before them (its rows keep a null cost)."""
    mode = conn.execute("PRAGMA journal_mode").fetchone()[0]
    if str(mode).lower() != "wal":
        conn.execute("PRAGMA journal_mode=WAL")
    conn.execute("PRAGMA synchronous=NORMAL")
    conn.execute(_SCHEMA)
    columns = {str(row[1]) for row in conn.execute("PRAGMA table_info(replies)")}
    for name, sql_type in COST_COLUMNS:
        if name not in columns:
            conn.execute(f"ALTER TABLE replies ADD COLUMN {name} {sql_type}")


@dataclass(frozen=True)
class RecordedCost:
    """What one reply cost the model that wrote it: tokens as its server counted them, seconds
    of the request (retries included)."""

    prompt_tokens: int | None
    completion_tokens: int | None
    seconds: float | None

    def counters(self) -> dict[str, float]:
        """The `recorded_*` counters of `ModelStats` for one reply served from the cache."""
        return {"recorded_replies": 1, "recorded_prompt_tokens": self.prompt_tokens or 0,
                "recorded_completion_tokens": self.completion_tokens or 0,
                "recorded_seconds": self.seconds or 0.0}


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
        hit = self.cache.get_recorded(key)
        if hit is not None:
            self.stats.add(cache_hits=1, **(hit[1].counters() if hit[1] else {}))
            return hit[0]
        self.stats.add(cache_misses=1)
        before = (self.stats.prompt_tokens, self.stats.completion_tokens)
        start = time.perf_counter()
        reply = well_formed(self.inner.complete(request))
        # the unit's counters around the request: one model per unit asks one request at a time
        cost = RecordedCost(self.stats.prompt_tokens - before[0], self.stats.completion_tokens - before[1],
                            time.perf_counter() - start)
        self.cache.put(key, self.provider, self.cache_name, request.kind, reply, cost)
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
        hit = self.cache.get_recorded(cache_key(self.provider, self.name, request))
        if hit is None:
            self.stats.add(cache_misses=1)
            raise CacheMissError(
                f"no cached reply for a {request.kind!r} request of model {self.provider}:{self.name}",
                file=str(self.cache.path),
                hint="replay with the same model args, seed and prompts as the recorded run "
                "(pass replay_model=<provider:model> if it differs)",
            )
        self.stats.add(cache_hits=1, **(hit[1].counters() if hit[1] else {}))
        return hit[0]

    def preflight(self) -> None:
        self.cache.check(writable=False)
