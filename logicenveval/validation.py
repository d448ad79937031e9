"""Helpers to turn pydantic validation errors into one precise, user-facing sentence."""

from __future__ import annotations

from pydantic import ValidationError

from logicenveval.errors import LogicEnvEvalError


def first_error(exc: ValidationError) -> tuple[str, str]:
    """(dotted field path, message) of the first error of a pydantic ValidationError."""
    err = exc.errors()[0]
    loc = ".".join(str(p) for p in err.get("loc", ()) if not _is_union_tag(p))
    inner = (err.get("ctx") or {}).get("error")
    if isinstance(inner, LogicEnvEvalError):
        msg = inner.message + (f" at column {inner.column}" if inner.column else "")
        if inner.hint:
            msg += f"; {inner.hint}"
    else:
        msg = str(err.get("msg", "invalid value"))
        if msg.startswith("Value error, "):
            msg = msg[len("Value error, ") :]
    extra = len(exc.errors()) - 1
    if extra:
        msg += f" (and {extra} more problem{'s' if extra > 1 else ''})"
    return loc or "<root>", msg


def _is_union_tag(part: object) -> bool:
    return isinstance(part, str) and part in {"Node", "Leaf"}
