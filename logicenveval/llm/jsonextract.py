"""Extracting the JSON value from an LLM reply that may wrap it in prose or code fences."""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from typing import Any

#: deepest nesting of a reply's JSON value: far above any schema's, far below the interpreter's
#: recursion limit (a deeper reply raised RecursionError, an *internal* error kept on resume)
MAX_DEPTH = 64
_FENCE = re.compile(r"```(?:json|JSON)?\s*\n?(.*?)```", re.S)


class JSONExtractionError(ValueError):
    """No parseable JSON value in a reply; the message says what was wrong (for re-asking)."""


def _brackets(text: str) -> Iterator[tuple[int, int, bool]]:
    """(index, depth after it, opening?) of every bracket outside JSON strings; a quote opens a
    string only inside brackets, since the prose around a reply may quote words."""
    depth, in_str, esc = 0, False, False
    for i, ch in enumerate(text):
        if in_str:
            if esc:
                esc = False
            elif ch == "\\":
                esc = True
            elif ch == '"':
                in_str = False
            continue
        if ch == '"' and depth > 0:
            in_str = True
        elif ch in "{[":
            depth += 1
            yield i, depth, True
        elif ch in "}]" and depth > 0:
            depth -= 1
            yield i, depth, False


def _balanced_spans(text: str) -> list[str]:
    """Top-level `{...}` / `[...]` spans, tracking strings and escapes."""
    spans: list[str] = []
    start = -1
    for i, depth, opening in _brackets(text):
        if opening and depth == 1:
            start = i
        elif not opening and depth == 0:
            spans.append(text[start : i + 1])
    return spans


def _too_deep(text: str) -> bool:
    """Whether the brackets of `text` (outside strings) nest deeper than MAX_DEPTH."""
    return any(depth > MAX_DEPTH for _, depth, _ in _brackets(text))


def _depth(value: Any) -> int:
    """How deep `value`'s containers nest (a scalar 0): for a parsed JSON text, the depth of its
    brackets outside strings, which `_too_deep` counts."""
    if not isinstance(value, (dict, list)):
        return 0
    deepest, level = 0, [(value, 1)]
    while level:
        node, depth = level.pop()
        deepest = max(deepest, depth)
        items = node.values() if isinstance(node, dict) else node
        level.extend((item, depth + 1) for item in items if isinstance(item, (dict, list)))
    return deepest


def _candidates(text: str) -> Iterator[str]:
    """The whole text, each fenced block, then each balanced span: spans are only scanned for
    when the earlier candidates do not parse (a well-formed reply is parsed at once)."""
    yield text
    for m in _FENCE.finditer(text):
        yield m.group(1).strip()
    yield from _balanced_spans(text)


def extract_json(reply: str) -> Any:
    """The first JSON object/array in `reply`: whole text, fenced block, then balanced span."""
    text = reply.strip()
    too_deep = JSONExtractionError(f"the reply's JSON nests deeper than {MAX_DEPTH} levels; "
                                   "reply with the flat structure the schema asks for")
    first_error: json.JSONDecodeError | None = None
    for cand in _candidates(text):
        if not cand or cand[0] not in "{[":
            continue
        try:
            value = json.loads(cand)
        except json.JSONDecodeError as exc:
            if _too_deep(cand):
                raise too_deep from None
            first_error = first_error or exc
            continue
        except RecursionError:  # nested far deeper than MAX_DEPTH
            raise too_deep from None
        if _depth(value) > MAX_DEPTH:
            raise too_deep
        return value
    if first_error is not None:
        raise JSONExtractionError(
            f"the reply contains JSON that does not parse: {first_error.msg} at line "
            f"{first_error.lineno} column {first_error.colno}"
        )
    raise JSONExtractionError("the reply contains no JSON object or array")
