"""A reply cut to the array bounds of the JSON Schema it was asked for.

A grammar-constrained decoder (llama.cpp's `response_format`, OpenAI's structured outputs) cannot
write more items than a list's `maxItems`: it must close the list. The offline model writes its
replies by rule and then fits them the same way, so it answers a request as a constrained model
would instead of failing on a bound it was shown.
"""

from __future__ import annotations

from typing import Any


def fit_arrays(value: Any, schema: dict[str, Any] | None) -> Any:
    """`value` with every list longer than its schema's `maxItems` cut to that many items
    (`$ref`s resolved against the schema's `$defs`); what the schema does not describe is kept."""
    if not schema:
        return value
    return _fit(value, schema, schema.get("$defs") or {})


def _fit(value: Any, node: dict[str, Any], defs: dict[str, Any]) -> Any:
    ref = node.get("$ref")
    if isinstance(ref, str) and ref.startswith("#/$defs/"):
        node = defs.get(ref.removeprefix("#/$defs/"), {})
    if isinstance(value, list):
        cap = node.get("maxItems")
        items = value[:cap] if isinstance(cap, int) and cap >= 0 else value
        inner = node.get("items")
        return [_fit(v, inner, defs) for v in items] if isinstance(inner, dict) else list(items)
    if isinstance(value, dict):
        props = node.get("properties") or {}
        return {k: _fit(v, props[k], defs) if isinstance(props.get(k), dict) else v
                for k, v in value.items()}
    return value
