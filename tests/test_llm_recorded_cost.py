"""A reply cache keeps what each reply cost when recorded, and a replay reports it (issue 46:
a user plans a CPU run from a pack's per-method, per-task cost)."""

from __future__ import annotations

import sqlite3
from pathlib import Path

from logicenveval.llm.base import ChatRequest, ModelStats
from logicenveval.llm.cache import CachedModel, ReplayModel, ReplyCache, cache_key


class _Metered:
    """A model that reports usage as an HTTP model does (into the shared stats)."""

    name = "metered"

    def __init__(self, stats: ModelStats) -> None:
        self.stats = stats

    def complete(self, request: ChatRequest) -> str:
        self.stats.add(requests=1, prompt_tokens=120, completion_tokens=7, latency_s=0.01)
        return '{"ok": true}'


def _request(n: int) -> ChatRequest:
    return ChatRequest(kind="decompose_task", payload={}, messages=[{"role": "user", "content": f"q{n}"}],
                       schema=None)


def test_a_recorded_reply_keeps_its_cost_and_a_replay_reports_it(tmp_path: Path) -> None:
    path = tmp_path / "cache.sqlite"
    stats = ModelStats()
    recording = CachedModel(_Metered(stats), ReplyCache(path), "openai", stats)
    assert recording.complete(_request(1)) == '{"ok": true}'
    assert stats.recorded_replies == 0 and stats.prompt_tokens == 120  # a miss costs, live
    again = ModelStats()
    cached = CachedModel(_Metered(again), ReplyCache(path), "openai", again)
    cached.complete(_request(1))
    assert (again.requests, again.cache_hits, again.recorded_replies) == (0, 1, 1)
    assert (again.recorded_prompt_tokens, again.recorded_completion_tokens) == (120, 7)
    assert again.recorded_seconds >= 0.0
    replayed = ModelStats()
    ReplayModel(ReplyCache(path, read_only=True), "openai", "metered", replayed).complete(_request(1))
    assert (replayed.recorded_replies, replayed.recorded_prompt_tokens) == (1, 120)


def test_a_cache_written_before_the_cost_columns_serves_and_gains_them(tmp_path: Path) -> None:
    path = tmp_path / "old.sqlite"
    key = cache_key("openai", "metered", _request(1))
    with sqlite3.connect(path) as conn:
        conn.execute("CREATE TABLE replies (key TEXT PRIMARY KEY, provider TEXT NOT NULL, model TEXT "
                     "NOT NULL, kind TEXT NOT NULL, reply TEXT NOT NULL, created REAL NOT NULL)")
        conn.execute("INSERT INTO replies VALUES (?, 'openai', 'metered', 'decompose_task', '{}', 0)", (key,))
    replayed = ModelStats()
    model = ReplayModel(ReplyCache(path, read_only=True), "openai", "metered", replayed)
    assert model.complete(_request(1)) == "{}"
    assert (replayed.cache_hits, replayed.recorded_replies) == (1, 0)  # cost unknown, counted so
    stats = ModelStats()
    CachedModel(_Metered(stats), ReplyCache(path), "openai", stats).complete(_request(2))
    with sqlite3.connect(path) as conn:
        rows = dict(conn.execute("SELECT key, prompt_tokens FROM replies").fetchall())
    assert rows[key] is None and sorted(v for v in rows.values() if v is not None) == [120]
