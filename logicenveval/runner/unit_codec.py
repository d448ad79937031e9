"""Unit files without the repetition of their traces and mutant ids (~3/4 of a run's `units/`).

A trace line is the `str` of one simulator entry (`{'tick': 3, 'node': 'Walk', 'path':
'Root/Sequence/Walk[0]', 'status': 'RUNNING', 'ports': 'target=toy'}`); on disk it becomes a pair
`[tick, step number]`, with the unit's tree paths (`trace_paths`, a trie: `PathTable`) and its
distinct steps `[node, path number, status(, ports)]` (`trace_steps`) listed once. A line is stored as a pair
only when the step gives back exactly the same text; any other line stays text. The unit's
`mutants` ({id: fault class}) are stored as {fault class: [ids]}, and a sample's `killed_mutants`
as numbers into the sorted ids. Loading restores the strings,
so `UnitRecord` is the same either way; unit files of earlier versions load unchanged (plain text
lines; rows `[tick, node, path number, status(, ports)]` without `trace_steps`; mutant ids).
"""

from __future__ import annotations

import contextlib
import re
from typing import Any

#: the key of the path table; its presence marks an encoded unit
PATHS = "trace_paths"
#: the key of the step table (units written since steps replaced full rows)
STEPS = "trace_steps"
_LINE = re.compile(r"\{'tick': (\d+), 'node': '([^'\\]*)', 'path': '([^'\\]*)', "
                   r"'status': '([^'\\]*)'(?:, 'ports': '([^'\\]*)')?\}")


class PathTable:
    """Tree paths numbered in order of first use, written as a trie: an entry is a path with no
    listed parent, or `[parent number, last part]` (parents come first). A tree path repeats its
    root's long prefix (`Root/Sequence/SubTree(TidyToy)[0]/...`): the trie holds each part once."""

    def __init__(self) -> None:
        self.numbers: dict[str, int] = {}
        self.entries: list[str | list[int | str]] = []

    def number(self, path: str) -> int:
        at = self.numbers.get(path)
        if at is None:
            head, sep, tail = path.rpartition("/")
            entry: str | list[int | str] = [self.number(head), tail] if sep and head else path
            at = self.numbers[path] = len(self.entries)
            self.entries.append(entry)
        return at


def full_paths(entries: object) -> list[str]:
    """The paths a `PathTable`'s entries (or a plain list of paths) stand for."""
    if not isinstance(entries, list):
        raise ValueError("trace_paths is not a list")
    out: list[str] = []
    for entry in entries:
        if isinstance(entry, str):
            out.append(entry)
        elif (isinstance(entry, list) and len(entry) == 2 and type(entry[0]) is int
              and 0 <= entry[0] < len(out) and isinstance(entry[1], str)):
            out.append(f"{out[entry[0]]}/{entry[1]}")
        else:
            raise ValueError("not a trace path entry")
    return out


def _line(tick: int, node: str, path: str, status: str, ports: list[str]) -> str:
    tail = f", 'ports': '{ports[0]}'" if ports else ""
    return f"{{'tick': {tick}, 'node': '{node}', 'path': '{path}', 'status': '{status}'{tail}}}"


def _step_text(step: object, paths: list[str]) -> tuple[str, str, str, list[str]]:
    """(node, path, status, ports) of a step `[node, path number, status(, ports)]`."""
    if not isinstance(step, list) or len(step) not in (3, 4):
        raise ValueError("not a trace step")
    node, at, status, *ports = step
    if not (isinstance(node, str) and type(at) is int and 0 <= at < len(paths) and isinstance(status, str)
            and all(isinstance(p, str) for p in ports)):
        raise ValueError("not a trace step")
    return node, paths[at], status, ports


def _text(row: list[Any], paths: list[str], steps: list[tuple[str, str, str, list[str]]] | None) -> str:
    if steps is not None:  # [tick, step]
        if len(row) != 2 or type(row[0]) is not int or type(row[1]) is not int or not 0 <= row[1] < len(steps):
            raise ValueError("not a trace pair")
        node, path, status, ports = steps[row[1]]
        return _line(row[0], node, path, status, ports)
    tick, *step = row  # the earlier form: [tick, node, path number, status(, ports)]
    if type(tick) is not int:
        raise ValueError("not a trace row")
    return _line(tick, *_step_text(step, paths))


def encode_unit(payload: dict[str, Any]) -> dict[str, Any]:
    """The unit's JSON payload (`UnitRecord.model_dump(mode="json")`) with its traces as
    pairs and its samples' killed mutants as numbers."""
    paths = PathTable()
    steps: dict[tuple[str, int, str, tuple[str, ...]], int] = {}
    #: each distinct line is matched once (a unit's traces repeat most of their lines: the four
    #: BTs of an environment, environments of one situation); numbering follows first use as before
    seen: dict[str, Any] = {}

    def first(line: str) -> Any:
        pair = seen[line] = _pair(line, paths, steps)
        return pair

    details = []
    for detail in payload.get("details") or []:
        traces = {}
        for kind, verdict in (detail.get("traces") or {}).items():
            lines = [seen.get(line) or first(line) for line in verdict.get("trace") or []]
            traces[kind] = {**verdict, "trace": lines}
        details.append({**detail, "traces": traces})
    out = {**payload, "samples": _killed_as_numbers(payload)} if "samples" in payload else payload
    mutants = payload.get("mutants")
    if isinstance(mutants, dict) and mutants and all(isinstance(c, str) for c in mutants.values()):
        grouped: dict[str, list[str]] = {}
        for mutant in sorted(mutants):
            grouped.setdefault(mutants[mutant], []).append(mutant)
        out = {**out, "mutants": grouped}
    if not steps:
        return out
    return {**out, "details": details, PATHS: paths.entries,
            STEPS: [[node, at, status, *ports] for node, at, status, ports in steps]}


def _pair(line: str, paths: PathTable, steps: dict[tuple[str, int, str, tuple[str, ...]], int]) -> Any:
    """`[tick, step number]` of a trace line, or the line itself when it has no exact pair form."""
    m = _LINE.fullmatch(line)
    ports = () if m is None or m[5] is None else (m[5],)
    if m is None or _line(int(m[1]), m[2], m[3], m[4], list(ports)) != line:
        return line
    step = (m[2], paths.number(m[3]), m[4], ports)
    return [int(m[1]), steps.setdefault(step, len(steps))]


def _killed_as_numbers(payload: dict[str, Any]) -> list[Any]:
    number = {m: i for i, m in enumerate(sorted(payload.get("mutants") or {}))}
    out = []
    for sample in payload.get("samples") or []:
        killed = sample.get("killed_mutants") if isinstance(sample, dict) else None
        if killed and isinstance(killed, list):
            with contextlib.suppress(KeyError, TypeError):  # a number or a list names no mutant
                sample = {**sample, "killed_mutants": [number[m] for m in killed]}
        out.append(sample)
    return out


def _killed_as_ids(payload: dict[str, Any]) -> list[Any]:
    mutants = payload.get("mutants")
    ids = sorted(mutants) if isinstance(mutants, dict) else []
    out = []
    for sample in payload.get("samples") or []:
        killed = sample.get("killed_mutants") if isinstance(sample, dict) else None
        if isinstance(killed, list) and any(type(m) is int for m in killed):
            if not all(type(m) is int and 0 <= m < len(ids) for m in killed):
                raise ValueError("a killed mutant's number names no mutant of the unit")
            sample = {**sample, "killed_mutants": [ids[m] for m in killed]}
        out.append(sample)
    return out


def decode_unit(payload: dict[str, Any]) -> dict[str, Any]:
    """The payload with every trace line as text again and mutant ids for numbers (a damaged
    row, step or number raises ValueError)."""
    mutants = payload.get("mutants")
    if isinstance(mutants, dict) and mutants and all(isinstance(ids, list) for ids in mutants.values()):
        if not all(isinstance(m, str) for ids in mutants.values() for m in ids):
            raise ValueError("a unit's mutant ids are not strings")
        payload = {**payload, "mutants": dict(sorted((m, kind) for kind, ids in mutants.items() for m in ids))}
    payload = {**payload, "samples": _killed_as_ids(payload)} if "samples" in payload else payload
    if PATHS not in payload:
        return payload
    table = full_paths(payload[PATHS])
    raw = payload.get(STEPS)
    if raw is not None and not isinstance(raw, list):
        raise ValueError("trace_steps is not a list of steps")
    steps = None if raw is None else [_step_text(s, table) for s in raw]
    details = []
    for detail in payload.get("details") or []:
        traces = {}
        for kind, verdict in (detail.get("traces") or {}).items():
            lines = [x if isinstance(x, str) else _text(x, table, steps) if isinstance(x, list) else x
                     for x in verdict.get("trace") or []]
            traces[kind] = {**verdict, "trace": lines}
        details.append({**detail, "traces": traces})
    return {k: v for k, v in payload.items() if k not in (PATHS, STEPS)} | {"details": details}
