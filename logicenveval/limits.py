"""Size and depth limits on untrusted input, and the one reader of untrusted text files.

Task folders, BT XML, EnvSpecs and LLM replies may come from anyone (docs/security.md), so every
size that drives time or memory has a bound with a clear error. Each limit has a default that is
far above what the benchmark needs and can be raised with an environment variable
`LOGICENVEVAL_<NAME>` (e.g. `LOGICENVEVAL_MAX_XML_BYTES=10000000`).

A run reads and checks every limit once, in the parent (`current`), and hands the values to its
units, which work under them (`pinned`): a bad value is one error before any work, never a
failure inside units, and every unit of a run sees the same values whatever its worker's
environment. A refusal made under a limit (`raise_hint`) is noted, so a unit can tell that its
outcome depends on a limit value rather than on the generator alone (runner.unit).
"""

from __future__ import annotations

import contextlib
import json
import os
import stat
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any, BinaryIO

from logicenveval.errors import ConfigError, LogicEnvEvalError

#: name -> (default, what it bounds)
DEFAULTS: dict[str, tuple[int, str]] = {
    "max_task_bytes": (2_000_000, "size of a task.json"),
    "max_description_chars": (20_000, "characters of a task description"),
    "max_tree_depth": (60, "depth of a task's decision tree"),
    "max_task_roles": (48, "roles of one task (4x the largest shipped task; each situation's z3 "
                           "encoding grows with the square of the roles)"),
    "max_task_constraints": (64, "constraints of one task (8x the largest shipped task)"),
    "max_condition_depth": (50, "parenthesis nesting of a condition"),
    "max_xml_bytes": (2_000_000, "size of a BT XML file"),
    "max_xml_depth": (100, "element nesting of a BT XML file"),
    "max_xml_attribute_chars": (1_000, "characters of one XML attribute value"),
    "max_subtree_nodes": (100_000, "nodes of a BT after expanding its SubTrees"),
    "max_env_bytes": (20_000_000, "size of an EnvSpec file"),
    "max_run_file_bytes": (1_000_000_000, "size of a run's results.json or samples.jsonl"),
    "max_env_objects": (2_000, "objects of one EnvSpec"),
    "max_unit_envs": (2_000, "environments one generator returns for one task"),
    "max_reply_bytes": (2_000_000, "bytes of one LLM HTTP reply"),
    "max_situations": (100_000, "situations (trajectories) of one task"),
    "max_workers": (256, "worker processes of a run"),
    "max_mutants": (500, "first-order mutants of a correct BT classified and scored (evenly "
                         "spaced sample above; docs/faults.md)"),
}


PREFIX = "LOGICENVEVAL_MAX_"
#: the largest value a limit takes (beyond it a bound no longer bounds anything)
MAX_VALUE = 10**15
#: values a run handed to this process (`pinned`); empty: read the environment
_PINNED: dict[str, int] = {}
#: limits that refused something inside the current `pinned` scope
_HIT: set[str] = set()


def limit(name: str) -> int:
    """The current value of a limit: the run's pinned value, else the environment's, else the
    default."""
    if name in _PINNED:
        return _PINNED[name]
    if name not in DEFAULTS:
        raise KeyError(name)
    return _from_environment(name)


def _from_environment(name: str) -> int:
    default, _ = DEFAULTS[name]
    env = f"LOGICENVEVAL_{name.upper()}"
    raw = os.environ.get(env)
    if raw is None:
        return default
    text = raw.strip()
    value = int(text) if text.isdigit() and len(text) <= 16 else 0
    if not 1 <= value <= MAX_VALUE:
        raise ConfigError(f"{env}={raw[:40]!r} is not an integer between 1 and {MAX_VALUE}", field=env,
                          hint=f"set it to an integer >= 1 (default {default}) or unset it")
    return value


def current() -> dict[str, int]:
    """Every limit, checked: what a run reads once at its start and hands to its units.

    A malformed value, or a `LOGICENVEVAL_MAX_*` variable that names no limit (a typo would
    otherwise be ignored in silence), is a `ConfigError`."""
    known = {f"LOGICENVEVAL_{n.upper()}" for n in DEFAULTS}
    unknown = sorted(k for k in os.environ if k.startswith(PREFIX) and k not in known)
    if unknown:
        raise ConfigError(f"{unknown[0]} names no limit", field=unknown[0],
                          hint="the limits are " + ", ".join(sorted(known)) + " (docs/security.md)")
    return {name: limit(name) for name in DEFAULTS}


@contextlib.contextmanager
def pinned(values: Mapping[str, int]) -> Iterator[set[str]]:
    """Work under the limits `values` (a run's `current()`; limits not named keep theirs), and
    yield the set of the limits that refused something meanwhile (`raise_hint`)."""
    saved, hit = dict(_PINNED), set(_HIT)
    _PINNED.update(values)
    _HIT.clear()
    found: set[str] = set()
    try:
        yield found
    finally:
        found |= _HIT
        _PINNED.clear()
        _PINNED.update(saved)
        _HIT.clear()
        _HIT.update(hit | found)


def raise_hint(name: str) -> str:
    """The fix of a refusal made under the limit `name`; also notes that the limit was hit."""
    _HIT.add(name)
    return f"raise the limit with LOGICENVEVAL_{name.upper()}=<n> if the input is genuine"


def read_bytes(path: str | Path, *, what: str, error: type[LogicEnvEvalError],
               max_bytes: str, hint: str) -> bytes:
    """The bytes of an untrusted file, at most the `max_bytes` limit of them.

    Only regular files are read: a FIFO, a socket or a device has no size and may never end or
    never answer (a FIFO without a writer blocks the open itself), so it is refused before it is
    opened — and the open is non-blocking and checked again on the descriptor, so a FIFO swapped
    in between cannot hang the read. Files are opened read-only. The limit is also checked on the
    bytes actually read (a file growing while read).
    """
    p = Path(path)
    cap = limit(max_bytes)
    try:
        _check_regular(os.stat(p).st_mode, p, what, error, hint)
        fd = os.open(p, os.O_RDONLY | os.O_NONBLOCK | os.O_NOCTTY | os.O_CLOEXEC)
        with open(fd, "rb", buffering=0) as fh:
            st = os.fstat(fd)
            _check_regular(st.st_mode, p, what, error, hint)
            if st.st_size > cap:  # a regular file that says it is too big: refused unread
                raise error(f"{what} is {st.st_size} bytes, more than the limit of {cap}",
                            file=str(p), hint=raise_hint(max_bytes))
            os.set_blocking(fd, True)
            data = _read_at_most(fh, cap + 1)
    except FileNotFoundError:
        raise error(f"{what} not found", file=str(p), hint=hint) from None
    except OSError as exc:
        raise error(f"cannot read {what}: {exc.strerror or exc}", file=str(p),
                    hint="check the path and the file's permissions") from None
    except ValueError:  # a NUL in the path
        raise error(f"{what}: the path holds a NUL character", file=repr(str(p)),
                    hint="pass a real file path") from None
    if len(data) > cap:
        raise error(f"{what} has more than the limit of {cap} bytes", file=str(p),
                    hint=raise_hint(max_bytes))
    return data


def _check_regular(mode: int, p: Path, what: str, error: type[LogicEnvEvalError],
                   hint: str) -> None:
    if stat.S_ISDIR(mode):
        raise error(f"{what} is a directory, not a file", file=str(p), hint=hint)
    if not stat.S_ISREG(mode):
        kind = ("a FIFO (named pipe)" if stat.S_ISFIFO(mode) else "a socket" if stat.S_ISSOCK(mode)
                else "a device")
        raise error(f"{what} is {kind}, not a regular file; it was not read", file=str(p),
                    hint="pass a regular file (copy the data to a file first)")


def _read_at_most(fh: BinaryIO, n: int) -> bytes:
    """Up to `n` bytes, read in chunks (a pipe or device has no size to trust)."""
    chunks: list[bytes] = []
    got = 0
    while got < n:
        chunk = fh.read(min(1 << 20, n - got))
        if not chunk:
            break
        chunks.append(chunk)
        got += len(chunk)
    return b"".join(chunks)


def read_text(path: str | Path, *, what: str, error: type[LogicEnvEvalError],
              max_bytes: str, hint: str) -> str:
    """Read an untrusted UTF-8 text file with one precise error for every way it can be unusable.

    `max_bytes` names the size limit (checked on the bytes read: `read_bytes`); `hint` is the fix
    for a missing file.
    """
    data = read_bytes(path, what=what, error=error, max_bytes=max_bytes, hint=hint)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        bom = data[:2] in (b"\xff\xfe", b"\xfe\xff")
        raise error(f"{what} is not UTF-8 text (byte {exc.start}"
                    + (", looks like UTF-16" if bom else "") + ")", file=str(path),
                    hint="save the file as UTF-8") from None


def parse_json(text: str, *, file: str, error: type[LogicEnvEvalError]) -> Any:
    """`json.loads` with one precise error for broken syntax and for absurd nesting."""
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        raise error(f"invalid JSON: {exc.msg}", file=file, line=exc.lineno, column=exc.colno,
                    hint="fix the JSON syntax") from None
    except RecursionError:
        raise error("JSON nested too deeply to read", file=file,
                    hint="flatten the file; no LogicEnvEval format nests more than a few levels") from None
    except ValueError:  # an integer of more than 4,300 digits (Python's conversion limit)
        raise error("JSON holds a number with thousands of digits", file=file,
                    hint="no LogicEnvEval value is that large: the file was edited or damaged") from None
