"""Masking secrets in any text that may be written to a file, a report or the terminal.

Secrets reach text in three ways: a value we know (the API key read from the environment), a
well-known shape (`Bearer …`, `sk-…`, `user:password@` in a URL, `api_key=…` arguments), or a
server echoing our request headers back in an error body or a reply. Known values are
registered by whoever reads them (`register_secret`), so they are masked wherever they appear.
"""

from __future__ import annotations

import re

MASK = "***"

_known: set[str] = set()

#: argument names whose value is a credential: the name must END in one of these words, so that
#: `max_tokens=1000`, `api_key_env=OPENAI_API_KEY` (a variable's name) and a hint's `key=value`
#: stay readable
_SECRET_NAMES = (r"api[_-]?key|access[_-]?key|secret[_-]?key|private[_-]?key|token|secret|"
                 r"password|passwd|credentials?")
#: the value after an authorization scheme: holding a digit or punctuation, mixed case inside
#: the word (base64) or long, so that ordinary prose ("the token budget", "basic household objects") is not taken for a credential
_CREDENTIAL = r"(?=[A-Za-z0-9._~+/=-]{6,})(?=[A-Za-z._~+/=-]*[0-9._~+/=-]|[A-Za-z]*[a-z][A-Z]|[A-Za-z]{20,})[A-Za-z0-9._~+/=-]+"

_PATTERNS: tuple[tuple[re.Pattern[str], str], ...] = (
    (re.compile(r"(?i)\b(bearer)(\s+)[A-Za-z0-9._~+/=-]{6,}"), rf"\1\2{MASK}"),
    (re.compile(rf"\b((?i:basic|token))(\s+){_CREDENTIAL}"), rf"\1\2{MASK}"),
    (re.compile(r"\bsk-[A-Za-z0-9_-]{6,}"), MASK),
    (re.compile(r"(?i)\b(authorization|x-api-key|api-key)(['\"]?\s*[:=]\s*['\"]?)[^'\",;\s}]+"),
     rf"\1\2{MASK}"),
    (re.compile(rf"(?i)\b([A-Za-z0-9_-]*?(?:{_SECRET_NAMES}))=(?!\*)([^,&\s'\"]+)"),
     rf"\1={MASK}"),
    (re.compile(r"(?i)\b([a-z][a-z0-9+.-]*://)[^/\s@:]+(?::[^/\s@]*)?@"), rf"\1{MASK}@"),
)


def is_secret_name(name: str) -> bool:
    """Whether an argument named `name` holds a credential (`api_key`, `x_auth_token`, not
    `max_tokens` or `api_key_env`, which names a variable)."""
    return re.fullmatch(rf"[A-Za-z0-9_-]*?(?:{_SECRET_NAMES})", name, re.I) is not None


def register_secret(value: str | None) -> None:
    """Mask `value` in every text passed through `redact` in this process from now on."""
    if value and len(value) >= 4:
        _known.add(value)


def redact(text: str) -> str:
    """`text` with known secret values and secret-shaped substrings masked."""
    for value in sorted(_known, key=len, reverse=True):
        text = text.replace(value, MASK)
    for pattern, repl in _PATTERNS:
        text = pattern.sub(repl, text)
    return text


def strip_url_credentials(url: str) -> str:
    """A URL without `user:password@` (for identities and reports)."""
    return _PATTERNS[-1][0].sub(rf"\1{MASK}@", url)
