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
    (`$ref`s resolved against the schema's `$defs`); what the schema does not describe is kept,
    and so is (the same object) every part whose schema bounds no list."""
    if not schema:
        return value
    defs = schema.get("$defs") or {}
    return _fit(value, schema, defs, {})


def _resolve(node: dict[str, Any], defs: dict[str, Any]) -> dict[str, Any]:
    ref = node.get("$ref")
    if isinstance(ref, str) and ref.startswith("#/$defs/"):
        found = defs.get(ref.removeprefix("#/$defs/"), {})
        return found if isinstance(found, dict) else {}
    return node


def _bounds(node: dict[str, Any], defs: dict[str, Any], memo: dict[int, bool]) -> bool:
    """Whether `node` or a schema under it (items, properties, through `$ref`s) has a
    `maxItems`: only those parts of a reply are walked (a recursive schema counts as bounding)."""
    node = _resolve(node, defs)
    key = id(node)
    if key not in memo:
        memo[key] = True  # while it is being looked at: a cycle back to it is taken to bound
        inner = node.get("items")
        props = node.get("properties") or {}
        memo[key] = isinstance(node.get("maxItems"), int) \
            or (isinstance(inner, dict) and _bounds(inner, defs, memo)) \
            or any(isinstance(p, dict) and _bounds(p, defs, memo) for p in props.values())
    return memo[key]


def _fit(value: Any, node: dict[str, Any], defs: dict[str, Any], memo: dict[int, bool]) -> Any:
    if not isinstance(value, (list, dict)) or not _bounds(node, defs, memo):
        return value
    node = _resolve(node, defs)
    if isinstance(value, list):
        cap = node.get("maxItems")
        items = value[:cap] if isinstance(cap, int) and cap >= 0 else value
        inner = node.get("items")
        return [_fit(v, inner, defs, memo) for v in items] if isinstance(inner, dict) else list(items)
    props = node.get("properties") or {}
    return {k: _fit(v, props[k], defs, memo) if isinstance(props.get(k), dict) else v
            for k, v in value.items()}
