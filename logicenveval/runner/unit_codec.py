"""Unit files without the repetition of their traces, which were ~3/4 of a run's `units/`.

A trace line is the `str` of one simulator entry (`{'tick': 3, 'node': 'Walk', 'path':
'Root/Sequence/Walk[0]', 'status': 'RUNNING', 'ports': 'target=toy'}`); on disk it becomes a row
`[tick, node, path number, status(, ports)]` with the unit's tree paths listed once
(`trace_paths`). A line is stored as a row only when the row gives back exactly the same text;
any other line stays text. Loading restores the strings, so `UnitRecord` is the same either way,
and unit files written before this (plain text lines, no `trace_paths`) load unchanged.
"""

from __future__ import annotations

import re
from typing import Any

#: the key of the path table; its presence marks an encoded unit
PATHS = "trace_paths"
_LINE = re.compile(r"\{'tick': (\d+), 'node': '([^'\\]*)', 'path': '([^'\\]*)', "
                   r"'status': '([^'\\]*)'(?:, 'ports': '([^'\\]*)')?\}")


def _line(tick: int, node: str, path: str, status: str, ports: list[str]) -> str:
    tail = f", 'ports': '{ports[0]}'" if ports else ""
    return f"{{'tick': {tick}, 'node': '{node}', 'path': '{path}', 'status': '{status}'{tail}}}"


def _text(row: list[Any], paths: list[str]) -> str:
    tick, node, at, status, *ports = row
    if not (type(tick) is int and isinstance(node, str) and type(at) is int and 0 <= at < len(paths)
            and isinstance(status, str) and len(ports) <= 1 and all(isinstance(p, str) for p in ports)):
        raise ValueError("not a trace row")
    return _line(tick, node, paths[at], status, ports)


def encode_unit(payload: dict[str, Any]) -> dict[str, Any]:
    """The unit's JSON payload (`UnitRecord.model_dump(mode="json")`) with its traces as rows."""
    paths: dict[str, int] = {}
    table: list[str] = []
    details = []
    for detail in payload.get("details") or []:
        traces = {}
        for kind, verdict in (detail.get("traces") or {}).items():
            lines: list[Any] = []
            for line in verdict.get("trace") or []:
                m = _LINE.fullmatch(line)
                ports = [] if m is None or m[5] is None else [m[5]]
                if m is None or _line(int(m[1]), m[2], m[3], m[4], ports) != line:
                    lines.append(line)
                    continue
                at = paths.setdefault(m[3], len(paths))
                if at == len(table):
                    table.append(m[3])
                lines.append([int(m[1]), m[2], at, m[4], *ports])
            traces[kind] = {**verdict, "trace": lines}
        details.append({**detail, "traces": traces})
    if not table:
        return payload
    return {**payload, "details": details, PATHS: table}


def decode_unit(payload: dict[str, Any]) -> dict[str, Any]:
    """The payload with every trace line as text again (a damaged row raises ValueError)."""
    if PATHS not in payload:
        return payload
    table = payload[PATHS]
    if not isinstance(table, list) or not all(isinstance(p, str) for p in table):
        raise ValueError("trace_paths is not a list of paths")
    details = []
    for detail in payload.get("details") or []:
        traces = {}
        for kind, verdict in (detail.get("traces") or {}).items():
            lines = [x if isinstance(x, str) else _text(x, table) if isinstance(x, list) else x
                     for x in verdict.get("trace") or []]
            traces[kind] = {**verdict, "trace": lines}
        details.append({**detail, "traces": traces})
    return {k: v for k, v in payload.items() if k != PATHS} | {"details": details}
