"""What `run` starts before its command line is parsed in full: the workers' fork server.

The parser imports every command module (~0.2-0.4 s, pydantic models included) before `run`
could start the fork server, and the fork server's own imports (~1 s) are what the first units
wait for. So `cli.main` hands a `run` command line here first: the options that decide whether
a fork server is needed (`--executor`, `--workers`, `--debug`) are read leniently, and the
server is started. Anything unusual (help, a malformed value) starts nothing here; the full
parser then reports it, and `run` starts the server itself as before (a running one is reused).
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Sequence

#: what the workers' `on_commit` hook needs besides the runner's own preload (`run` passes the
#: same): each unit's report page
PAGE_MODULES = ("logicenveval.reporting.unit_page",)


def start_early(argv: Sequence[str]) -> bool:
    """Start the fork server for a `run ...` command line (`argv` without the program name)
    that asks for the process executor; True when one was started."""
    if list(argv[:1]) != ["run"] or any(a in ("-h", "--help", "--debug") for a in argv):
        return False
    early = argparse.ArgumentParser(add_help=False, allow_abbrev=False)
    early.add_argument("--executor", default="process")
    early.add_argument("--workers", default=None)
    try:
        known, _ = early.parse_known_args(list(argv[1:]))
        workers = int(known.workers) if known.workers is not None else (os.cpu_count() or 1)
    except (SystemExit, ValueError):
        return False
    if known.executor != "process" or workers < 1:
        return False
    from logicenveval.runner.executors import prestart

    prestart(known.executor, workers, preload=PAGE_MODULES)
    return True
