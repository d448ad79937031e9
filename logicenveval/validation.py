"""Helpers to turn pydantic validation errors into one precise, user-facing sentence."""

from __future__ import annotations

from typing import Any

from pydantic import ValidationError

from logicenveval.errors import LogicEnvEvalError

#: problems listed by field after the first one
MAX_LISTED = 3


def first_error(exc: ValidationError) -> tuple[str, str]:
    """(dotted field path, message) of the most telling error, listing a few more with their fields.

    A tree node is a union of Node and Leaf, so one typo yields an error per union member; the
    errors that carry our own message (a condition syntax error) or a wrong value come before
    "field required" errors of the member the user did not mean.
    """
    errors = sorted(exc.errors(), key=_rank)
    loc, msg = _describe(errors[0])
    others = [f"{lo}: {m}" for lo, m in dict.fromkeys(_describe(e) for e in errors[1:])
              if (lo, m) != (loc, msg)]
    if others:
        msg += "; also " + "; ".join(others[:MAX_LISTED])
        if len(others) > MAX_LISTED:
            rest = len(others) - MAX_LISTED
            msg += f" (and {rest} more problem{'s' if rest > 1 else ''})"
    return loc, msg


def _rank(err: Any) -> int:
    if isinstance((err.get("ctx") or {}).get("error"), LogicEnvEvalError):
        return 0
    return 2 if err.get("type") in ("missing", "extra_forbidden") else 1


def _describe(err: Any) -> tuple[str, str]:
    loc = ".".join(str(p) for p in err.get("loc", ()) if not _is_union_tag(p)) or "<root>"
    inner = (err.get("ctx") or {}).get("error")
    if isinstance(inner, LogicEnvEvalError):
        msg = inner.message + (f" at column {inner.column}" if inner.column else "")
        if inner.hint:
            msg += f"; {inner.hint}"
    else:
        msg = str(err.get("msg", "invalid value"))
        if msg.startswith("Value error, "):
            msg = msg[len("Value error, ") :]
        if err.get("type") == "bool_type":  # a strict boolean given "yes", "true" or 1
            msg += f" (got {err.get('input')!r:.40}; write true or false, without quotes)"
    return loc, msg


def _is_union_tag(part: object) -> bool:
    return isinstance(part, str) and part in {"Node", "Leaf"}
