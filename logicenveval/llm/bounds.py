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


def fit_numbers(value: Any, schema: dict[str, Any] | None) -> tuple[Any, list[str]]:
    """`value` with every number outside its schema's `minimum`/`maximum` set to the nearer
    bound, and the paths of the numbers so set.

    Why: the compact grammar (`llm.grammar`) cannot bound a decimal, as llama.cpp's own converter
    cannot, so a constrained model may write a door 3 m wide where the schema says at most 2;
    refusing the whole reply for it (and re-asking, three times on Qwen2.5-Coder-1.5B) lets one
    number sink a scene. What the grammar allows, the reply reader accepts: the value is set to
    the bound and counted (`ask` reports `clamped` per request kind), as `fit_arrays` cuts a list
    the grammar bounds. Exclusive bounds are left to validation."""
    if not schema:
        return value, []
    paths: list[str] = []
    out = _fit_numbers(value, schema, schema.get("$defs") or {}, "", paths)
    return out, paths


def _branch(value: Any, node: dict[str, Any], defs: dict[str, Any]) -> dict[str, Any]:
    """The schema `value` is read by: `node`, or the first `anyOf`/`oneOf` branch of the value's
    JSON type."""
    node = _resolve(node, defs)
    for key in ("anyOf", "oneOf"):
        for option in node.get(key) or ():
            option = _resolve(option, defs) if isinstance(option, dict) else {}
            kind = option.get("type")
            if (kind in ("number", "integer") and _is_number(value)) \
                    or (kind == "array" and isinstance(value, list)) \
                    or (kind == "object" and isinstance(value, dict)):
                return option
    return node


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _fit_numbers(value: Any, node: dict[str, Any], defs: dict[str, Any], path: str,
                 paths: list[str]) -> Any:
    node = _branch(value, node, defs)
    if _is_number(value):
        low, high = node.get("minimum"), node.get("maximum")
        if _is_number(low) and value < low:
            paths.append(path)
            return low
        if _is_number(high) and value > high:
            paths.append(path)
            return high
        return value
    if isinstance(value, list):
        inner = node.get("items")
        if not isinstance(inner, dict):
            return value
        return [_fit_numbers(v, inner, defs, f"{path}.{i}".lstrip("."), paths) for i, v in enumerate(value)]
    if isinstance(value, dict):
        props = node.get("properties") or {}
        extra = node.get("additionalProperties")
        out = {}
        for k, v in value.items():
            sub = props.get(k, extra)
            out[k] = _fit_numbers(v, sub, defs, f"{path}.{k}".lstrip("."), paths) if isinstance(sub, dict) else v
        return out
    return value
