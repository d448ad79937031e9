"""The OpenAI-compatible provider against a real loopback HTTP server with scripted replies."""

from __future__ import annotations

import json
import logging
import threading
import time
from collections.abc import Iterator
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

import pytest

from logicenveval.errors import CacheMissError, ModelConnectionError, ModelReplyError
from logicenveval.llm.ask import ask, bounds_of, reply_schema
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.registry import (
    UNBOUNDED_SECONDS,
    make_model,
    parse_model_args,
    with_unit_budget,
)
from logicenveval.llm.replies import DecomposeReply

SECRET = "sk-test-SECRET-value-123"
BRIEF = {"task": {"id": "t", "description": "Tidy the room.", "rooms": ["living_room"],
                  "roles": {"toy": {"category": "toy", "attributes": {}}}}}
VALID = {"reasoning": "r", "subtasks": [{"id": "tidy", "description": "tidy", "roles": ["toy"]}]}


class Script:
    """Replies served in order: (status, body, headers) or ("hang", seconds)."""

    def __init__(self, steps: list[Any]) -> None:
        self.steps = list(steps)
        self.requests: list[dict[str, Any]] = []
        self.headers: list[dict[str, str]] = []


def _chat(content: str) -> tuple[int, str, dict[str, str]]:
    body = {"choices": [{"message": {"role": "assistant", "content": content}}],
            "usage": {"prompt_tokens": 10, "completion_tokens": 5}}
    return 200, json.dumps(body), {}


@pytest.fixture
def server() -> Iterator[tuple[str, Script]]:
    script = Script([])

    class Handler(BaseHTTPRequestHandler):
        def log_message(self, *args: Any) -> None:
            pass

        def do_GET(self) -> None:
            self.send_response(200)
            self.end_headers()
            self.wfile.write(b'{"data": []}')

        def do_POST(self) -> None:
            length = int(self.headers.get("Content-Length", 0))
            script.requests.append(json.loads(self.rfile.read(length)))
            script.headers.append(dict(self.headers))
            step = script.steps.pop(0) if script.steps else _chat(json.dumps(VALID))
            if step[0] == "hang":
                time.sleep(step[1])
                return
            status, body, headers = step
            self.send_response(status)
            for k, v in headers.items():
                self.send_header(k, v)
            self.send_header("Content-Type", "application/json")
            self.end_headers()
            self.wfile.write(body.encode())

    httpd = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{httpd.server_address[1]}/v1", script
    finally:
        httpd.shutdown()
        httpd.server_close()


def _model(url: str, tmp_path: Path, **extra: Any) -> Any:
    args = {"base_url": url, "api_key_env": "LEE_TEST_KEY", "backoff_base": 0.01, "backoff_max": 0.05,
            "timeout": 2.0, **extra}
    return make_model("openai:test-model", args, no_cache=True, run_dir=tmp_path / "run")


@pytest.fixture(autouse=True)
def _key(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("LEE_TEST_KEY", SECRET)


def test_valid_reply_and_schema_sent(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [_chat(json.dumps(VALID))]
    reply = ask(_model(url, tmp_path), "decompose_task", BRIEF, DecomposeReply)
    assert reply.subtasks[0].id == "tidy"
    sent = script.requests[0]
    assert sent["model"] == "test-model"
    assert sent["response_format"]["json_schema"]["schema"] == reply_schema(DecomposeReply)
    assert script.headers[0]["Authorization"] == f"Bearer {SECRET}"


def test_fenced_json_is_extracted(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [_chat("Sure! Here it is:\n```json\n" + json.dumps(VALID) + "\n```\nDone.")]
    assert ask(_model(url, tmp_path), "decompose_task", BRIEF, DecomposeReply).subtasks[0].roles == ["toy"]


def test_broken_json_then_valid_after_reask(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [_chat('{"subtasks": [ {"id": "x",'), _chat(json.dumps(VALID))]
    model = _model(url, tmp_path)
    assert ask(model, "decompose_task", BRIEF, DecomposeReply).subtasks[0].id == "tidy"
    assert len(script.requests) == 2
    assert "invalid" in script.requests[1]["messages"][-1]["content"]
    assert model.stats.reasks == 1


def test_schema_violation_forever_raises_model_reply_error(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [_chat('{"subtasks": "none"}')] * 3
    with pytest.raises(ModelReplyError) as info:
        ask(_model(url, tmp_path), "decompose_task", BRIEF, DecomposeReply, max_reasks=2)
    text = str(info.value)
    assert "decompose_task" in text and "test-model" in text and "subtasks" in text
    saved = list((tmp_path / "run" / "llm_errors").glob("decompose_task-*.txt"))
    assert saved and "none" in saved[0].read_text()
    assert info.value.file == f"llm_errors/{saved[0].name}"  # relative: no folder of this machine


def test_429_with_retry_after_then_success(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [(429, '{"error": "slow down"}', {"Retry-After": "0.2"}), _chat(json.dumps(VALID))]
    start = time.perf_counter()
    model = _model(url, tmp_path, backoff_max=1.0)
    ask(model, "decompose_task", BRIEF, DecomposeReply)
    assert time.perf_counter() - start >= 0.2  # honoured Retry-After, not the tiny backoff
    assert model.stats.retries == 1 and len(script.requests) == 2


def test_500s_until_retry_budget_ends(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [(500, "boom", {})] * 10
    with pytest.raises(ModelConnectionError, match="3 time"):
        ask(_model(url, tmp_path, max_retries=2), "decompose_task", BRIEF, DecomposeReply)
    assert len(script.requests) == 3


def test_hanging_server_times_out(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [("hang", 1.5)] * 2
    with pytest.raises(ModelConnectionError, match="timed out"):
        ask(_model(url, tmp_path, timeout=0.3, max_retries=1), "decompose_task", BRIEF, DecomposeReply)


def test_api_key_never_leaks(server: tuple[str, Script], tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    url, script = server
    script.steps = [(500, "boom", {})] * 5
    caplog.set_level(logging.DEBUG)
    model = _model(url, tmp_path, max_retries=1)
    with pytest.raises(ModelConnectionError) as info:
        ask(model, "decompose_task", BRIEF, DecomposeReply)
    for text in (str(info.value), repr(model), caplog.text, json.dumps(model.stats.as_dict())):
        assert SECRET not in text
    assert all(SECRET not in json.dumps(r) for r in script.requests)


def test_unreachable_server_preflight() -> None:
    model = make_model("openai:x", "base_url=http://127.0.0.1:9/v1", no_cache=True)
    with pytest.raises(ModelConnectionError, match="cannot reach http://127.0.0.1:9/v1"):
        model.preflight()  # type: ignore[attr-defined]


def test_cache_second_call_makes_no_request(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    cache = tmp_path / "cache.sqlite"
    args = {"base_url": url, "api_key_env": "LEE_TEST_KEY"}
    first = make_model("openai:test-model", args, cache_path=cache)
    ask(first, "decompose_task", BRIEF, DecomposeReply)
    second = make_model("openai:test-model", args, cache_path=cache)
    ask(second, "decompose_task", BRIEF, DecomposeReply)
    assert len(script.requests) == 1
    assert second.stats.cache_hits == 1 and second.stats.requests == 0  # type: ignore[attr-defined]
    replay = make_model(f"replay:{cache}")
    assert ask(replay, "decompose_task", BRIEF, DecomposeReply).subtasks[0].id == "tidy"
    other = {"task": {**BRIEF["task"], "description": "Something else."}}
    with pytest.raises(CacheMissError, match="'decompose_task'"):
        ask(replay, "decompose_task", other, DecomposeReply)


def _writer(path: str, start: int) -> None:
    from logicenveval.llm.cache import ReplyCache

    cache = ReplyCache(path)
    for i in range(start, start + 200):
        cache.put(f"k{i}", "p", "m", "kind", f"reply {i}")


def test_concurrent_writers_lose_nothing(tmp_path: Path) -> None:
    import multiprocessing

    from logicenveval.llm.cache import ReplyCache

    path = str(tmp_path / "c.sqlite")
    ctx = multiprocessing.get_context("spawn")
    procs = [ctx.Process(target=_writer, args=(path, k * 200)) for k in range(2)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(60)
        assert p.exitcode == 0
    cache = ReplyCache(path)
    assert len(cache) == 400
    assert cache.get("k399") == "reply 399"


def test_model_args_parsing() -> None:
    assert parse_model_args("base_url=http://h:8000/v1, timeout=30,json_schema=false,x=1.5") == {
        "base_url": "http://h:8000/v1", "timeout": 30, "json_schema": False, "x": 1.5}
    with pytest.raises(Exception, match="not key=value"):
        parse_model_args("oops")


def test_http_models_take_the_runs_unit_timeout_as_their_budget() -> None:
    """One bound per unit: --unit-timeout reaches the HTTP model's request budget (a run given
    3 h per unit had a slow local model stopped at the model's own default of 30 minutes)."""
    assert with_unit_budget("openai:m", "base_url=http://h/v1", 10800.0)["unit_timeout"] == 10800.0
    assert with_unit_budget("llamacpp:/m.gguf", "threads=1", 60.0) == {"threads": 1, "unit_timeout": 60.0}
    assert with_unit_budget("noisy:openai:m", "rate=0.3", 60.0)["unit_timeout"] == 60.0
    assert with_unit_budget("openai:m", "", None)["unit_timeout"] == UNBOUNDED_SECONDS  # --unit-timeout 0
    assert with_unit_budget("openai:m", "unit_timeout=5", 60.0)["unit_timeout"] == 5  # the user's own
    assert "unit_timeout" not in with_unit_budget("offline", "", 60.0)
    assert "unit_timeout" not in with_unit_budget("noisy:offline", "rate=0.1", 60.0)


def test_a_run_hands_its_unit_timeout_to_the_model(server: tuple[str, Script], tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    from logicenveval.cli import main
    from logicenveval.llm import openai_http

    budgets: list[float] = []
    init = openai_http.OpenAIChatModel.__init__

    def spy(self: Any, *args: Any, **kwargs: Any) -> None:
        budgets.append(kwargs.get("unit_timeout", 1800.0))
        init(self, *args, **kwargs)

    monkeypatch.setattr(openai_http.OpenAIChatModel, "__init__", spy)
    url, _ = server
    main(["run", "--model", "openai:test-model", "--model-args", f"base_url={url},max_retries=0",
          "--tasks", "clean_living_room", "--generators", "holodeck", "--unit-timeout", "7200",
          "--executor", "inprocess", "--output", str(tmp_path), "--quiet", "--no-cache"])
    assert budgets and budgets[-1] == 7200.0  # the unit's model (the first is the run's preflight)


def _cut(content: str) -> tuple[int, str, dict[str, str]]:
    body = {"choices": [{"message": {"role": "assistant", "content": content}, "finish_reason": "length"}]}
    return 200, json.dumps(body), {}


def test_reasks_change_temperature_and_seed_and_never_repeat_a_request(
        server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [_chat('{"subtasks": "none"}')] * 3
    with pytest.raises(ModelReplyError):
        ask(_model(url, tmp_path), "decompose_task", BRIEF, DecomposeReply, seed=7)
    bodies = [json.dumps(r, sort_keys=True) for r in script.requests]
    assert len(set(bodies)) == 3  # no two attempts identical
    assert [r["temperature"] for r in script.requests] == [0.0, 0.3, 0.6]
    assert [r["seed"] for r in script.requests] == [7, 8, 9]
    # each re-ask quotes the validator's message, and the prompt does not grow with the attempts
    assert "subtasks" in script.requests[1]["messages"][-1]["content"]
    assert len(script.requests[1]["messages"]) == len(script.requests[2]["messages"])
    assert all(r["max_tokens"] == bounds_of("decompose_task") for r in script.requests)  # not cut: kept
    assert "compactly on one line" in script.requests[0]["messages"][0]["content"]


def test_a_reply_cut_at_max_tokens_is_a_truncation_error_naming_it(
        server: tuple[str, Script], tmp_path: Path) -> None:
    from logicenveval.errors import ModelTruncatedError

    url, script = server
    script.steps = [_cut('{"subtasks": [{"id": "ZZCUT')] * 3
    model = _model(url, tmp_path)
    first = bounds_of("decompose_task")
    with pytest.raises(ModelTruncatedError, match=f"max_tokens={4 * first}"):
        ask(model, "decompose_task", BRIEF, DecomposeReply)
    # the cut reply is never sent back: the re-ask says it was cut and grants a larger bound
    # (never "shorter": that lost the content a cut reply had)
    assert all("ZZCUT" not in m["content"] for m in script.requests[1]["messages"])
    again = script.requests[1]["messages"][-1]["content"]
    assert f"cut off at max_tokens={first}" in again and f"now have max_tokens={2 * first}" in again
    assert "shorter" not in again
    assert [r["max_tokens"] for r in script.requests] == [first, 2 * first, 4 * first]
    counts = model.stats.by_kind["decompose_task"]
    assert counts == {"questions": 1, "attempts": 3, "truncated": 3, "answered": 1}


def test_protocol_1_keeps_the_recorded_requests(server: tuple[str, Script], tmp_path: Path) -> None:
    """Packs recorded before issue 39 replay only if their requests are rebuilt byte for byte."""
    from logicenveval.errors import ModelTruncatedError
    from logicenveval.llm.ask import MAX_TOKENS_V1

    url, script = server
    script.steps = [_cut('{"subtasks": [')] * 2
    model = _model(url, tmp_path)
    model.reply_protocol = 1
    with pytest.raises(ModelTruncatedError):
        ask(model, "decompose_task", BRIEF, DecomposeReply, max_reasks=1)
    bound = MAX_TOKENS_V1["decompose_task"]
    assert [r["max_tokens"] for r in script.requests] == [bound, bound]
    assert "compactly" not in script.requests[0]["messages"][0]["content"]
    assert "shorter JSON value" in script.requests[1]["messages"][-1]["content"]
    assert "answered" not in model.stats.by_kind["decompose_task"]


def test_validity_counters_per_kind(server: tuple[str, Script], tmp_path: Path) -> None:
    url, script = server
    script.steps = [_chat("no json"), _chat(json.dumps(VALID)), _chat(json.dumps(VALID))]
    model = _model(url, tmp_path)
    ask(model, "decompose_task", BRIEF, DecomposeReply)
    ask(model, "decompose_task", {**BRIEF, "x": 1}, DecomposeReply)
    assert model.stats.by_kind["decompose_task"] == {
        "questions": 2, "attempts": 3, "truncated": 0, "valid": 2, "valid_first": 1, "answered": 2}
    flat = model.stats.as_dict()
    assert flat["kind.decompose_task.valid_first"] == 1 and "by_kind" not in flat


def test_the_request_timeout_scales_with_the_reply_bound(server: tuple[str, Script], tmp_path: Path) -> None:
    """A reply bounded to many tokens may take longer than `timeout`: a reply that takes 0.6 s
    arrives under timeout=0.3 s when its bound (100 tokens x 0.01 s) allows 1 s."""
    url, script = server
    model = _model(url, tmp_path, timeout=0.3, seconds_per_token=0.01, max_retries=0)
    assert model.timeout_for({"max_tokens": 100}) == 1.0
    assert model.timeout_for({"max_tokens": 10}) == 0.3 and model.timeout_for({}) == 0.3
    default = make_model("openai:m", {"base_url": url}, no_cache=True)
    assert default.timeout_for({"max_tokens": 16700}) == 16700 * 0.25 and default.timeout_for({}) == 60.0
    fixed = make_model("openai:m", {"base_url": url, "timeout": 30}, no_cache=True)  # the user's bound
    assert fixed.timeout_for({"max_tokens": 16700}) == 30

    script.steps = [("hang", 1.5)]  # the 1 s the bound allows, not the 0.3 s of `timeout`, ends it
    with pytest.raises(ModelConnectionError, match="within 1s"):
        model.complete(ChatRequest(kind="k", payload={}, messages=[{"role": "user", "content": "x"}],
                                   schema=None, max_tokens=100))


def test_no_retry_once_the_units_budget_is_spent(server: tuple[str, Script], tmp_path: Path) -> None:
    """A request that times out at the end of the unit's budget is not retried (nor announced)."""
    url, script = server
    model = _model(url, tmp_path, timeout=5.0, unit_timeout=0.3, max_retries=3)
    script.steps = [("hang", 0.6)]
    with pytest.raises(ModelConnectionError, match="time budget ran out during a 'k' request") as info:
        model.complete(ChatRequest(kind="k", payload={}, messages=[{"role": "user", "content": "x"}],
                                   schema=None, max_tokens=10))
    assert len(script.requests) == 1 and model.stats.retries == 0
    # one label per cause: the budget's expiry is a generation failure, as when the alarm fires
    from logicenveval.runner.unit import failure_kind

    assert failure_kind(info.value) == "generation"
    assert failure_kind(ModelConnectionError("endpoint down")) == "infrastructure"
