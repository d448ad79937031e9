"""`extract_json` parses a well-formed reply at once and scans for spans only when it must: the
same value or the same error as scanning every candidate first (the earlier implementation)."""

from __future__ import annotations

import json
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.llm.jsonextract import (
    _FENCE,
    MAX_DEPTH,
    JSONExtractionError,
    _balanced_spans,
    _too_deep,
    extract_json,
)


def _scanned_first(reply: str) -> Any:
    """The earlier `extract_json`: every candidate listed, depth checked before parsing."""
    text = reply.strip()
    candidates = [text] + [m.group(1).strip() for m in _FENCE.finditer(text)] + _balanced_spans(text)
    first_error: json.JSONDecodeError | None = None
    for cand in candidates:
        if not cand or cand[0] not in "{[":
            continue
        if _too_deep(cand):
            raise JSONExtractionError("too deep")
        try:
            return json.loads(cand)
        except json.JSONDecodeError as exc:
            first_error = first_error or exc
    if first_error is not None:
        raise JSONExtractionError(f"{first_error.msg} {first_error.lineno} {first_error.colno}")
    raise JSONExtractionError("none")


def _outcome(fn: Any, reply: str) -> tuple[str, Any]:
    try:
        return "value", fn(reply)
    except JSONExtractionError as exc:
        text = str(exc)
        return "error", ("too deep" if "deep" in text else "none" if "no JSON" in text or text == "none"
                         else "parse")


_JSON = st.recursive(st.none() | st.booleans() | st.integers() | st.text(alphabet='ab"{[]}\\', max_size=4),
                     lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=3), inner,
                                                                                 max_size=3),
                     max_leaves=10)


def _nested(depth: int) -> str:
    return "[" * depth + "]" * depth


@settings(deadline=None, max_examples=200)
@given(st.lists(st.one_of(_JSON.map(json.dumps), st.sampled_from(
    ["prose ", "```json\n", "```", "{", "}", "[", "]", '"', "\\", "\n", "{\"a\": ", _nested(MAX_DEPTH),
     _nested(MAX_DEPTH + 1), "not json"])), max_size=6).map("".join))
def test_extract_json_is_the_scan_first_version(reply: str) -> None:
    assert _outcome(extract_json, reply) == _outcome(_scanned_first, reply)


def test_depth_limit_applies_to_parsed_and_unparsed_replies() -> None:
    assert extract_json(_nested(MAX_DEPTH)) is not None
    for reply in (_nested(MAX_DEPTH + 1), "[" * 100_000 + "]" * 100_000, _nested(MAX_DEPTH + 1)[:-1],
                  "see " + _nested(MAX_DEPTH + 1) + " and {}"):
        assert _outcome(extract_json, reply) == ("error", "too deep")
