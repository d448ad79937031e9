"""A hostile OpenAI-compatible server on 127.0.0.1 for tests: it fails, hangs, trickles and echoes
secrets by turns. Good replies are the offline model's own answers, recorded beforehand and served
by the hash of the request's messages (a server cannot know the payload, only the messages).
"""

from __future__ import annotations

import hashlib
import itertools
import json
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from types import TracebackType
from typing import Any


def messages_key(messages: list[dict[str, Any]]) -> str:
    return hashlib.sha256(json.dumps(messages, sort_keys=True).encode()).hexdigest()


class Loopback:
    """`modes` is cycled per POST: ok, fail (HTTP 500 echoing the request headers), hang,
    trickle (one byte per `trickle_s`), echo (a good reply followed by the request headers), huge
    (a 3 MB reply), badusage (a good reply whose `usage` is malformed, cycling through shapes),
    deep (a reply whose content is JSON nested 100,000 deep), deepbody (the HTTP body itself nested
    that deep), dripheaders (the status line, then one header line per `trickle_s` for a minute),
    surrogate (a reply whose content is a lone surrogate, `"\\ud800"`). `get_mode` shapes every
    GET: ok, drip (one byte per `trickle_s` for a minute), dripheaders, huge (a 50 MB body)."""

    def __init__(self, *, replies: dict[str, str] | None = None, modes: list[str] | None = None,
                 get_status: int = 200, echo: bool = False, hang_s: float = 6.0,
                 trickle_s: float = 0.5, get_mode: str = "ok") -> None:
        self.replies = replies or {}
        self.modes = itertools.cycle(modes or ["ok"])
        self.get_status = get_status
        self.echo = echo
        self.hang_s = hang_s
        self.trickle_s = trickle_s
        self.get_mode = get_mode
        self.gets = 0
        self._usages = itertools.cycle(['"abc"', '{"prompt_tokens": "x", "completion_tokens": []}',
                                        "[1, 2]", '{"prompt_tokens": 1e400}', "null"])
        self.posts = 0
        self.seen: list[str] = []
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._httpd = ThreadingHTTPServer(("127.0.0.1", 0), self._handler())
        self._httpd.daemon_threads = True
        self.url = f"http://127.0.0.1:{self._httpd.server_address[1]}/v1"

    def set_modes(self, modes: list[str]) -> None:
        with self._lock:
            self.modes = itertools.cycle(modes)

    def _handler(self) -> type[BaseHTTPRequestHandler]:
        server = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args: Any) -> None:
                pass

            def _send(self, status: int, body: bytes) -> None:
                self.send_response(status)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)

            def _drip_headers(self) -> None:
                self.wfile.write(b"HTTP/1.1 200 OK\r\n")
                self.wfile.flush()
                for k in range(int(60 / server.trickle_s)):
                    if server._stop.wait(server.trickle_s):
                        break
                    self.wfile.write(f"X-Drip-{k}: {k}\r\n".encode())
                    self.wfile.flush()

            def do_GET(self) -> None:
                server.gets += 1
                try:
                    if server.get_mode == "dripheaders":
                        self._drip_headers()
                        return
                    if server.get_mode == "drip":
                        self.send_response(200)
                        self.send_header("Content-Length", "100000")
                        self.end_headers()
                        for _ in range(int(60 / server.trickle_s)):
                            if server._stop.wait(server.trickle_s):
                                break
                            self.wfile.write(b" ")
                            self.wfile.flush()
                        return
                    if server.get_mode == "huge":
                        self.send_response(200)
                        self.send_header("Content-Length", str(50 * 2**20))
                        self.end_headers()
                        block = b" " * 2**20
                        for _ in range(50):
                            self.wfile.write(block)
                        return
                except (BrokenPipeError, ConnectionResetError):
                    return
                headers = json.dumps(dict(self.headers)) if server.echo else "{}"
                self._send(server.get_status, f'{{"data": [], "headers": {headers}}}'.encode())

            def do_POST(self) -> None:
                body = json.loads(self.rfile.read(int(self.headers.get("Content-Length", 0))))
                with server._lock:
                    server.posts += 1
                    mode = next(server.modes)
                server.seen.append(mode)
                headers = json.dumps(dict(self.headers))
                reply = server.replies.get(messages_key(body["messages"]))
                try:
                    if mode == "fail":
                        self._send(500, f'{{"error": "boom", "your_headers": {headers}}}'.encode())
                    elif mode == "hang":
                        server._stop.wait(server.hang_s)
                    elif mode == "trickle":
                        self.send_response(200)
                        self.send_header("Content-Type", "application/json")
                        self.send_header("Content-Length", "100000")
                        self.end_headers()
                        for _ in range(int(60 / server.trickle_s)):
                            if server._stop.wait(server.trickle_s):
                                break
                            self.wfile.write(b" ")
                            self.wfile.flush()
                    elif mode == "dripheaders":
                        self._drip_headers()
                    elif mode == "surrogate":
                        self._send(200, b'{"choices": [{"message": {"content": "\\ud800"}}]}')
                    elif mode == "huge":
                        self._send(200, b'{"choices": [{"message": {"content": "' + b"x" * 3_000_000 + b'"}}]}')
                    elif mode == "deep":
                        chat = {"choices": [{"message": {"content": "[" * 100_000 + "]" * 100_000}}]}
                        self._send(200, json.dumps(chat).encode())
                    elif mode == "deepbody":
                        self._send(200, b"[" * 100_000 + b"]" * 100_000)
                    elif reply is None:
                        self._send(404, b'{"error": "no recorded reply for these messages"}')
                    else:
                        content = reply + ("\n\nrequest headers: " + headers if mode == "echo" else "")
                        usage = next(server._usages) if mode == "badusage" else \
                            '{"prompt_tokens": 1, "completion_tokens": 1}'
                        chat = {"choices": [{"message": {"role": "assistant", "content": content}}]}
                        self._send(200, (json.dumps(chat)[:-1] + f', "usage": {usage}}}').encode())
                except (BrokenPipeError, ConnectionResetError):
                    pass  # the client gave up (its deadline): expected for hang/trickle

        return Handler

    def __enter__(self) -> Loopback:
        threading.Thread(target=self._httpd.serve_forever, daemon=True).start()
        return self

    def __exit__(self, et: type[BaseException] | None, ev: BaseException | None,
                 tb: TracebackType | None) -> None:
        self._stop.set()
        self._httpd.shutdown()
        self._httpd.server_close()
        time.sleep(0.05)
