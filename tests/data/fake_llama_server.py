#!/usr/bin/env python3
"""A stand-in for llama.cpp's llama-server in process-management tests (no model, no network).

Accepts llama-server's command line, listens on 127.0.0.1:--port, answers GET /health, GET
/v1/models (its `--alias` as the model id, as llama-server does) and POST /v1/chat/completions with the text in $FAKE_LLAMA_REPLY (default `{}`), and writes its pid to
$FAKE_LLAMA_PIDFILE (and a line per start to $FAKE_LLAMA_STARTS). $FAKE_LLAMA_EXIT=1 makes it exit at once (a server that cannot load), =SIGILL die of SIGILL;
$FAKE_LLAMA_DELAY=S makes each completion take S seconds; $FAKE_LLAMA_POSTS names a file that
gets a line per completion request when it arrives (a test can wait until a unit is asking).
"""

import argparse
import json
import os
import signal
import sys
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

parser = argparse.ArgumentParser()
parser.add_argument("--port", type=int, required=True)
parser.add_argument("--alias", default="")
args, _ = parser.parse_known_args()
if os.environ.get("FAKE_LLAMA_EXIT") == "SIGILL":  # a build for instructions this CPU refuses
    os.kill(os.getpid(), signal.SIGILL)
if os.environ.get("FAKE_LLAMA_EXIT"):
    print("error: failed to load model", file=sys.stderr)
    sys.exit(1)
if os.environ.get("FAKE_LLAMA_STARTS"):
    with open(os.environ["FAKE_LLAMA_STARTS"], "a") as fh:
        fh.write(f"{os.getpid()}\n")
if os.environ.get("FAKE_LLAMA_PIDFILE"):
    with open(os.environ["FAKE_LLAMA_PIDFILE"], "w") as fh:
        fh.write(str(os.getpid()))


class Handler(BaseHTTPRequestHandler):
    def _send(self, body: dict) -> None:
        data = json.dumps(body).encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    def do_GET(self) -> None:  # noqa: N802
        if self.path == "/health":
            self._send({"status": "ok"})
        else:
            self._send({"object": "list", "data": [{"id": args.alias, "object": "model"}]})

    def do_POST(self) -> None:  # noqa: N802
        self.rfile.read(int(self.headers.get("Content-Length", 0)))
        if os.environ.get("FAKE_LLAMA_POSTS"):
            with open(os.environ["FAKE_LLAMA_POSTS"], "a") as fh:
                fh.write("post\n")
        time.sleep(float(os.environ.get("FAKE_LLAMA_DELAY", "0")))
        reply = os.environ.get("FAKE_LLAMA_REPLY", "{}")
        self._send({"choices": [{"message": {"content": reply}, "finish_reason": "stop"}]})

    def log_message(self, *a: object) -> None:
        pass


ThreadingHTTPServer(("127.0.0.1", args.port), Handler).serve_forever()
