"""Thin command line: parse arguments, call library functions, print results.

Each command lives in `logicenveval/commands/<name>.py` with `add_arguments(parser)` and
`run(args) -> int`; command modules keep heavy imports inside `run` so that `--help` is fast.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import os
import sys
import traceback
from collections.abc import Sequence
from types import TracebackType
from typing import NoReturn

from logicenveval.atomic import RESOURCE_ERRNOS
from logicenveval.errors import ECHO_LIMITS, LogicEnvEvalError, clip
from logicenveval.limits import current as current_limits
from logicenveval.redact import redact

#: command -> (module, one-line help)
COMMANDS: dict[str, tuple[str, str]] = {
    "run": ("logicenveval.commands.run", "evaluate generators on the benchmark, write a leaderboard"),
    "tasks": ("logicenveval.commands.tasks", "list, show, validate or summarise benchmark tasks"),
    "evaluate": ("logicenveval.commands.evaluate", "score a folder of EnvSpecs made by any tool"),
    "generate": ("logicenveval.commands.generate", "run one generator on one task"),
    "generators": ("logicenveval.commands.generators", "list the generators (built-in and plug-ins)"),
    "simulate": ("logicenveval.commands.simulate", "run a policy (BT) in an environment or situation"),
    "import-house": ("logicenveval.commands.import_house",
                     "convert a ProcTHOR/AI2-THOR house (schema 1.0.0) into an EnvSpec"),
    "check-env": ("logicenveval.commands.check_env", "check an EnvSpec's physical plausibility"),
    "export": ("logicenveval.commands.export", "write an environment as ProcTHOR house JSON or GLB"),
    "check-house": ("logicenveval.commands.check_house",
                    "check a ProcTHOR house JSON against ProcTHOR's databases"),
    "lint": ("logicenveval.commands.lint",
             "list the binding, category and affordance problems of a folder of EnvSpecs"),
    "schema": ("logicenveval.commands.schema", "print the JSON Schema of EnvSpecs, tasks or results"),
    "report": ("logicenveval.commands.report", "rebuild leaderboard.md/.html of a run folder"),
    "compare": ("logicenveval.commands.compare", "compare two runs; exit 1 on a regression"),
}


class _Parser(argparse.ArgumentParser):
    """argparse, whose usage errors echo a bounded part of a value (`invalid choice: '<100 kB>'`)."""

    def error(self, message: str) -> NoReturn:
        super().error(clip(message, ECHO_LIMITS["message"]))


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="python -m logicenveval",
        description="LogicEnvEval: evaluate generators of logically diverse test environments.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, (module, help_text) in COMMANDS.items():
        mod = importlib.import_module(module)
        p = sub.add_parser(name, help=help_text, description=help_text)
        mod.add_arguments(p)
        p.set_defaults(_run=mod.run)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    try:
        current_limits()  # a malformed LOGICENVEVAL_MAX_* is one line before anything else
    except LogicEnvEvalError as exc:
        print(f"error: {redact(str(exc))}", file=sys.stderr)
        return exc.exit_code
    given = list(argv) if argv is not None else sys.argv[1:]
    from logicenveval.commands.run_start import start_early

    start_early(given)  # `run`'s workers start importing while the parser below is built
    parser = build_parser()
    args = parser.parse_args(given)
    args.argv = given  # for messages that quote the exact command to type next
    if getattr(args, "debug", False):  # every exception with its traceback, for a debugger
        sys.excepthook = _redacted_traceback
        try:
            debug_code: int = args._run(args)
        except BrokenPipeError:
            return _broken_pipe()
        return debug_code
    try:
        code: int = args._run(args)
    except BrokenPipeError:
        return _broken_pipe()
    except LogicEnvEvalError as exc:
        print(f"error: {redact(str(exc))}", file=sys.stderr)
        return exc.exit_code
    except RecursionError:
        print("error: the input nests too deeply to process (fix: flatten it; no LogicEnvEval "
              "format nests more than a few levels)", file=sys.stderr)
        return 2
    except OSError as exc:
        return _os_error(exc, args.command)
    except KeyboardInterrupt:
        kept = " finished units are kept and a re-run resumes" if args.command in RESUMABLE else ""
        print(f"interrupted;{kept or ' nothing was written partially'}", file=sys.stderr)
        return 130
    return code


def _redacted_traceback(kind: type[BaseException], exc: BaseException,
                        tb: TracebackType | None) -> None:
    """Print an uncaught exception's traceback as Python does, with secrets masked (`--debug`
    re-raises a generator's exception, whose message may hold a key: docs/security.md). A
    debugger (`python -m pdb`) still gets the exception itself: it catches it before this hook."""
    sys.stderr.write(redact("".join(traceback.format_exception(kind, exc, tb))))


#: exit status after the reader of our output went away (`... | head`): the output is
#: incomplete, said without a message (as Python's documented recipe and rich's consoles do)
EXIT_BROKEN_PIPE = 1


def _broken_pipe() -> int:
    """The reader closed the pipe: stop quietly, like a Unix tool. Standard output is pointed at
    the null device so that the interpreter's final flush does not fail a second time."""
    with contextlib.suppress(OSError, ValueError):
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    return EXIT_BROKEN_PIPE


#: commands whose finished units survive a failure (a re-run of the same command resumes)
RESUMABLE = frozenset({"run", "evaluate"})


def _os_error(exc: OSError, command: str) -> int:
    """One line for an operating-system error: exit 1 when the machine failed the work (a full
    disk, an I/O error), 2 when the path given cannot be used (missing, a folder, read-only)."""
    where = f"{clip(str(exc.filename), ECHO_LIMITS['file'])}: " if exc.filename else ""
    kept = "; finished units are kept and a re-run resumes" if command in RESUMABLE else ""
    if exc.errno in RESOURCE_ERRNOS:
        print(f"error: {where}{exc.strerror or exc} (fix: free disk space or fix the device, then "
              f"re-run{kept})", file=sys.stderr)
        return 1
    print(f"error: {where}{exc.strerror or exc} (fix: check that the path exists, is a file or "
          f"folder as expected and is writable{kept})", file=sys.stderr)
    return 2
