"""Hostile inputs, round 3 (issue 37), the model side: a foreign service on the managed server's
port, two model files of one name, slow or huge probe replies, `noisy:llamacpp:`, replay packs
that must stay untouched, malformed `usage` and deeply nested replies, unparseable URLs, bad
`server=`, typos found only after a server started, repeated model arguments, and redaction of
ordinary text. Each case asserts the error class or exit code and one message naming the problem;
the stand-in servers are `tests/loopback.py` and `tests/data/fake_llama_server.py`.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import httpx
import pytest
from cli_support import cli
from loopback import Loopback, messages_key

from logicenveval.errors import ConfigError, ModelConnectionError, ServerStartError
from logicenveval.llm import llamacpp, openai_http
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.jsonextract import JSONExtractionError, extract_json
from logicenveval.llm.openai_http import OpenAIChatModel
from logicenveval.llm.registry import make_model, parse_model_args
from logicenveval.redact import redact

HERE = Path(__file__).parent
REPO = HERE.parent
FAKE = HERE / "data" / "fake_llama_server.py"
PACK = REPO / "reports" / "real" / "stability" / "llm_cache.sqlite"
TASK = "clean_living_room"


@pytest.fixture
def gguf(tmp_path: Path) -> Path:
    path = tmp_path / "tiny-model.gguf"
    path.write_bytes(b"GGUF" + bytes(60))
    return path


def _port(url: str) -> int:
    return int(url.split(":")[2].split("/")[0])


def _run(out: Path, model: str, args: str, *extra: str, tasks: str = TASK,
         generators: str = "holodeck") -> list[str]:
    return ["run", "--model", model, "--model-args", args, "--tasks", tasks, "--generators",
            generators, "--executor", "inprocess", "--output", str(out), "--quiet", *extra]


def _request(text: str = "hi") -> ChatRequest:
    return ChatRequest(kind="decompose_task", payload={}, messages=[{"role": "user", "content": text}],
                       schema=None, temperature=0.0, seed=0)


# ----- class 2: a foreign server answers on the managed server's port ---------------------------

def test_a_port_taken_by_another_service_is_refused_before_starting(
        gguf: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    with Loopback() as other:
        code, _, err = cli(capsys, *_run(tmp_path / "o", f"llamacpp:{gguf}",
                                         f"server={FAKE},port={_port(other.url)}"))
        assert other.posts == 0, "units were answered by the foreign service"
    assert code == 2
    assert f"port {_port(other.url)} is already in use" in err


def test_a_server_that_is_not_ours_is_refused_by_its_nonce(gguf: Path,
                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    """The port was free when checked and taken a moment later: the service answering /health
    does not report our nonce as its model, so it is never used."""
    monkeypatch.setattr(llamacpp, "_port_free", lambda port: True)
    with Loopback() as other:
        settings, _ = llamacpp._split_args(str(gguf), {"server": str(FAKE), "port": _port(other.url),
                                                       "startup_timeout": 20})
        server = llamacpp.LlamaServer(settings)
        with pytest.raises(ServerStartError, match="answered by another service"):
            server.start()
    assert not server.alive()


def test_a_server_that_exits_because_another_service_took_its_port_names_that_service(
        gguf: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The same race, seen after ours gave up: a llama-server that cannot bind the port exits at
    once, and the message names the service that answers there, not only the exit code (whichever
    the start loop sees first)."""
    exits = shutil.which("false")
    assert exits is not None
    monkeypatch.setattr(llamacpp, "_port_free", lambda port: True)
    with Loopback() as other:
        settings, _ = llamacpp._split_args(str(gguf), {"server": exits, "port": _port(other.url),
                                                       "startup_timeout": 20})
        server = llamacpp.LlamaServer(settings)
        with pytest.raises(ServerStartError, match="answered by another service"):
            server.start()
    assert not server.alive()


def test_our_server_reports_our_nonce(gguf: Path) -> None:
    settings, _ = llamacpp._split_args(str(gguf), {"server": str(FAKE)})
    server = llamacpp.LlamaServer(settings)
    server.start()
    try:
        assert server.nonce.startswith("logicenveval-")
        status, body = openai_http.bounded_get(httpx.Client(), f"{server.base_url}/models")
        assert status == 200 and json.loads(body)["data"][0]["id"] == server.nonce
    finally:
        server.stop()


# ----- class 3: two model files of one name ----------------------------------------------------

def test_two_model_files_of_one_name_do_not_share_cached_replies(tmp_path: Path) -> None:
    first, second = tmp_path / "a" / "model.gguf", tmp_path / "b" / "model.gguf"
    for path, fill in ((first, b"\x01"), (second, b"\x02")):
        path.parent.mkdir()
        path.write_bytes(b"GGUF" + fill * 60)
    cache = tmp_path / "cache.sqlite"
    request = _request()
    with Loopback(replies={messages_key(request.messages): '{"from": "A"}'}) as server:
        model_a = make_model(f"llamacpp:{first}", {"base_url": server.url}, cache_path=cache)
        assert model_a.complete(request) == '{"from": "A"}'
        server.replies[messages_key(request.messages)] = '{"from": "B"}'
        model_b = make_model(f"llamacpp:{second}", {"base_url": server.url}, cache_path=cache)
        assert model_b.complete(request) == '{"from": "B"}', "model B was served model A's reply"
        assert server.posts == 2
    names = {m for _, m in sqlite3.connect(cache).execute("SELECT provider, model FROM replies")}
    digest = hashlib.sha256(first.read_bytes()).hexdigest()
    assert names == {f"model@sha256:{digest[:16]}",
                     f"model@sha256:{hashlib.sha256(second.read_bytes()).hexdigest()[:16]}"}


def test_the_model_file_is_hashed_once_per_file_version(gguf: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    reads: list[Path] = []
    real_open = Path.open

    def counting_open(self: Path, *args: object, **kwargs: object) -> object:
        if self == gguf and args and args[0] == "rb":
            reads.append(self)
        return real_open(self, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(Path, "open", counting_open)
    llamacpp._DIGESTS.clear()
    first = llamacpp.model_digest(gguf)
    assert llamacpp.model_digest(gguf) == first and len(reads) == 1
    gguf.write_bytes(b"GGUF" + bytes(61))  # a new version of the file: hashed again
    assert llamacpp.model_digest(gguf) != first and len(reads) == 2


# ----- class 6: unbounded probes -----------------------------------------------------------------

@pytest.mark.parametrize("mode", ["drip", "huge"])
def test_preflight_get_has_a_total_deadline_and_a_size_cap(mode: str, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(openai_http, "PROBE_SECONDS", 2.0)
    with Loopback(get_mode=mode, trickle_s=0.2) as server:
        model = OpenAIChatModel("m", base_url=server.url)
        with pytest.raises(ModelConnectionError, match="in time" if mode == "drip" else "larger than"):
            model.preflight()


def test_health_poll_of_a_dripping_service_is_bounded() -> None:
    with Loopback(get_mode="drip", trickle_s=0.2) as server, httpx.Client() as client:
        assert llamacpp._probe(client, server.url.removesuffix("/v1") + "/health",
                               time.monotonic() + 1.0) == (0, b"")


# ----- class 7: noisy:llamacpp: goes through the run's one server --------------------------------

def test_noisy_llamacpp_uses_one_managed_server_with_its_log(gguf: Path, tmp_path: Path) -> None:
    starts = tmp_path / "starts.txt"
    out = tmp_path / "o"
    argv = _run(out, f"noisy:llamacpp:{gguf}", f"server={FAKE},threads=1,rate=0.2", "--workers", "2",
                generators="holodeck,cot")
    argv[argv.index("inprocess")] = "process"
    proc = subprocess.run([sys.executable, "-m", "logicenveval", *argv], capture_output=True, text=True,
                          timeout=600, env={**os.environ, "FAKE_LLAMA_STARTS": str(starts),
                                            "PYTHONPATH": str(REPO)})
    assert "Traceback" not in proc.stderr, proc.stderr
    assert len(starts.read_text().splitlines()) == 1, "one server per run"
    assert len(list(out.glob("*/llama-server.log"))) == 1


# ----- classes 10 and 11: replay opens its pack read-only, refuses what is not a cache -----------

def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_replay_leaves_its_pack_untouched(tmp_path: Path) -> None:
    pack = tmp_path / "pack" / "llm_cache.sqlite"
    pack.parent.mkdir()
    shutil.copy(PACK, pack)
    before = _digest(pack)
    model = make_model(f"replay:{pack}")
    model.preflight()
    assert len(model.cache) > 0  # type: ignore[attr-defined]
    with pytest.raises(sqlite3.OperationalError, match="readonly"):
        model.cache._conn().execute("CREATE TABLE intruder (x)")  # type: ignore[attr-defined]
    assert _digest(pack) == before
    assert sorted(p.name for p in pack.parent.iterdir()) == ["llm_cache.sqlite"]


def test_replay_keeps_a_rollback_journal_cache_as_it_is(tmp_path: Path) -> None:
    path = tmp_path / "journal.sqlite"
    conn = sqlite3.connect(path)
    conn.execute("CREATE TABLE replies (key TEXT PRIMARY KEY, provider TEXT, model TEXT, kind TEXT, "
                 "reply TEXT, created REAL)")
    conn.execute("INSERT INTO replies VALUES ('k', 'openai', 'm', 'decompose_task', '{}', 0)")
    conn.commit()
    conn.close()
    before = _digest(path)
    make_model(f"replay:{path}").preflight()
    assert _digest(path) == before, "replay switched the file to WAL"


def test_replay_of_an_empty_file_creates_nothing(tmp_path: Path) -> None:
    path = tmp_path / "empty.sqlite"
    path.touch()
    with pytest.raises(ConfigError, match="not a reply cache: no table"):
        make_model(f"replay:{path}")
    assert path.stat().st_size == 0


def test_replay_of_a_folder_is_one_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = cli(capsys, *_run(tmp_path / "o", f"replay:{tmp_path}", ""))
    assert code == 2 and "not a regular file" in err


def test_a_cache_without_a_reply_column_fails_at_preflight(tmp_path: Path,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "cut.sqlite"
    conn = sqlite3.connect(path)
    conn.execute("CREATE TABLE replies (key TEXT, provider TEXT, model TEXT, kind TEXT)")
    conn.execute("INSERT INTO replies VALUES ('k', 'openai', 'm', 'decompose_task')")
    conn.commit()
    conn.close()
    code, _, err = cli(capsys, *_run(tmp_path / "o", f"replay:{path}", ""))
    assert code == 2 and "no column reply" in err
    assert not (tmp_path / "o" / "units").exists()


# ----- class 12: malformed usage, deeply nested replies ------------------------------------------

def test_a_malformed_usage_field_counts_no_tokens(tmp_path: Path) -> None:
    request = _request()
    with Loopback(replies={messages_key(request.messages): "{}"}, modes=["badusage"]) as server:
        model = OpenAIChatModel("m", base_url=server.url)
        for _ in range(5):  # every malformed shape the loopback cycles through
            assert model.complete(request) == "{}"
    assert model.stats.as_dict()["prompt_tokens"] == 0


def test_a_deeply_nested_reply_is_a_reply_problem_not_an_internal_error() -> None:
    with pytest.raises(JSONExtractionError, match="nests deeper"):
        extract_json("[" * 100_000 + "]" * 100_000)
    assert extract_json('{"a": "[[[[[[[[[["}') == {"a": "[[[[[[[[[["}  # brackets in strings


def test_a_deeply_nested_http_body_is_a_connection_failure() -> None:
    with Loopback(modes=["deepbody"]) as server:
        model = OpenAIChatModel("m", base_url=server.url)
        with pytest.raises(ModelConnectionError, match="without choices"):
            model.complete(_request())


def test_a_run_against_deeply_nested_replies_keeps_no_internal_error(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "o"
    with Loopback(modes=["deep"]) as server:
        code, _, _ = cli(capsys, *_run(out, "openai:m", f"base_url={server.url},max_retries=0",
                                       "--no-cache"))
    unit = json.loads(next(out.glob("*/units/**/*.json")).read_text())["unit"]
    assert unit["error_kind"] != "internal", unit["error"]
    failures = json.dumps(unit)
    assert "nests deeper" in failures and "RecursionError" not in failures and code == 1


# ----- classes 14, 15, 20, 21: model arguments ----------------------------------------------------

@pytest.mark.parametrize("url", ["http://h:1:2", "http://" + "a" * 100_000 + "/v1", "http://:80/v1",
                                 "http://h:99999/v1"])
def test_an_unparseable_base_url_is_one_short_config_error(url: str, tmp_path: Path,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = cli(capsys, *_run(tmp_path / "o", "openai:m", f"base_url={url}"))
    assert code == 2 and "base_url" in err and len(err) < 600


@pytest.mark.parametrize("value", ["123", "true", ""])
def test_server_must_be_a_path(value: str, gguf: Path) -> None:
    with pytest.raises(ConfigError, match="server=.* is not a path"):
        llamacpp._split_args(str(gguf), parse_model_args(f"server={value}"))


def test_llamacpp_with_base_url_needs_no_binary(gguf: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(llamacpp.ENV_BINARY, raising=False)
    monkeypatch.setenv("PATH", "")
    monkeypatch.setattr(llamacpp, "_packaged_binary", lambda: None)
    request = _request()
    with Loopback(replies={messages_key(request.messages): "{}"}) as server:
        model = make_model(f"llamacpp:{gguf}", {"base_url": server.url}, no_cache=True)
        assert model.complete(request) == "{}"


@pytest.mark.parametrize("extra", [("--tasks", "clean_livng_room"), ("--generators", "holodek"),
                                   ("--model-args", f"server={FAKE},timeout=abc"),
                                   ("--model-args", f"server={FAKE},temprature=0.2")])
def test_a_typo_is_reported_before_any_server_starts(extra: tuple[str, str], gguf: Path, tmp_path: Path,
                                                     monkeypatch: pytest.MonkeyPatch,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    starts = tmp_path / "starts.txt"
    monkeypatch.setenv("FAKE_LLAMA_STARTS", str(starts))
    argv = _run(tmp_path / "o", f"llamacpp:{gguf}", f"server={FAKE}")
    argv[argv.index(extra[0]) + 1] = extra[1]
    code, _, err = cli(capsys, *argv)
    assert code == 2 and err.strip()
    assert not starts.exists(), "a server was started before the typo was reported"


def test_a_repeated_model_argument_is_refused(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(ConfigError, match="'timeout' is given twice"):
        parse_model_args("timeout=5,max_retries=1,timeout=50")
    code, _, err = cli(capsys, *_run(tmp_path / "o", "openai:m",
                                     "base_url=http://127.0.0.1:9/v1,base_url=http://127.0.0.1:8/v1"))
    assert code == 2 and "given twice" in err


@pytest.mark.parametrize("args,message", [("timeout=5", "replay takes no model argument timeout"),
                                          ("replay_model=nocolon", "is not <provider>:<model>"),
                                          ("replay_model=7", "is not <provider>:<model>")])
def test_replay_refuses_arguments_it_cannot_use(args: str, message: str, tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = cli(capsys, *_run(tmp_path / "o", f"replay:{PACK}", args))
    assert code == 2 and message in err


# ----- class 22: redaction masks secrets, not ordinary text -----------------------------------

@pytest.mark.parametrize("text", ["--model-args max_tokens=1000", "write key=value pairs separated by commas",
                                  "api_key_env=OPENAI_API_KEY", "the 1,000-token bound ran out",
                                  "Token limit reached", "basic household objects",
                                  "max_completion_tokens=5,prompt_tokens=3"])
def test_ordinary_text_is_not_masked(text: str) -> None:
    assert redact(text) == text


@pytest.mark.parametrize("text,leak", [("api_key=plainvalue", "plainvalue"), ("x_auth_token=abc123", "abc123"),
                                       ("password=hunter2", "hunter2"), ("Token ghp_a1b2c3d4e5", "ghp_a1b2c3d4e5"),
                                       ("Bearer abcdefgh", "abcdefgh"), ("Basic dXNlcjpwYXNz", "dXNlcjpwYXNz")])
def test_secrets_are_still_masked(text: str, leak: str) -> None:
    assert leak not in redact(text)


def test_recorded_model_args_mask_credentials_only(tmp_path: Path) -> None:
    from logicenveval.runner.config import _redact

    assert _redact("max_tokens=1000,api_key_env=K,api_key=abc,x_token=t") == \
        "max_tokens=1000,api_key_env=K,api_key=***,x_token=***"


def test_a_hint_shows_key_value_unmasked(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = cli(capsys, *_run(tmp_path / "o", "offline", "nonsense"))
    assert code == 2 and "key=value" in err and "key=***" not in err


def test_a_fifo_as_the_server_log_is_refused_without_hanging(gguf: Path, tmp_path: Path) -> None:
    out = tmp_path / "o"
    (out / "fifo-log").mkdir(parents=True)
    os.mkfifo(out / "fifo-log" / "llama-server.log")
    proc = subprocess.run([sys.executable, "-m", "logicenveval",
                           *_run(out, f"llamacpp:{gguf}", f"server={FAKE},threads=1"),
                           "--run-id", "fifo-log"], capture_output=True, text=True, timeout=120,
                          env={**os.environ, "PYTHONPATH": str(REPO)})
    assert proc.returncode == 2, proc.stderr
    assert "FIFO" in proc.stderr and "Traceback" not in proc.stderr
    assert (out / "fifo-log" / "llama-server.log").is_fifo()
