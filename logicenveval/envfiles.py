"""Reading and writing EnvSpec JSON files with precise errors."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from logicenveval.atomic import atomic_write_text
from logicenveval.errors import EnvSpecError
from logicenveval.limits import limit, parse_json, raise_hint, read_text
from logicenveval.model.envspec import EnvSpec
from logicenveval.validation import first_error


def env_from_dict(data: Any, *, source: str | None = None) -> EnvSpec:
    objects = data.get("objects") if isinstance(data, dict) else None
    cap = limit("max_env_objects")
    if isinstance(objects, list) and len(objects) > cap:
        raise EnvSpecError(f"{len(objects)} objects, more than the limit of {cap}", file=source,
                           field="objects", hint=raise_hint("max_env_objects"))
    try:
        return EnvSpec.model_validate(data)
    except ValidationError as exc:
        loc, msg = first_error(exc)
        raise EnvSpecError(msg, file=source, field=loc,
                           hint="see docs/envspec.md for the EnvSpec format") from None


def load_env(path: str | Path) -> EnvSpec:
    p = Path(path)
    text = read_text(p, what="EnvSpec file", error=EnvSpecError, max_bytes="max_env_bytes",
                     hint="check the path")
    return env_from_dict(parse_json(text, file=str(p), error=EnvSpecError), source=str(p))


#: an object's fields that a file leaves out when they hold nothing (their defaults: null, {})
_EMPTY_OBJECT_FIELDS: dict[str, object] = {"container": None, "attributes": {}, "states": {}, "mesh": None}


def env_to_json(env: EnvSpec) -> str:
    """Canonical, byte-stable JSON text of an EnvSpec: one line per top-level field and per
    room, door, window, object and relation, an object's empty `container`, `attributes`,
    `states` and `mesh` left out (docs/envspec.md). Readable line by line, at half the bytes of
    an indent on every level and every default written out: a run writes ~700 of them."""
    fields = []
    for key, value in env.to_json_dict().items():
        if key == "objects" and isinstance(value, list):
            value = [{k: v for k, v in o.items() if k not in _EMPTY_OBJECT_FIELDS or v != _EMPTY_OBJECT_FIELDS[k]}
                     if isinstance(o, dict) else o for o in value]
        if isinstance(value, list) and value:
            items = ",\n".join(f"    {json.dumps(item)}" for item in value)
            fields.append(f"  {json.dumps(key)}: [\n{items}\n  ]")
        else:
            fields.append(f"  {json.dumps(key)}: {json.dumps(value)}")
    return "{\n" + ",\n".join(fields) + "\n}\n"


def save_env(env: EnvSpec, path: str | Path) -> None:
    """Write an EnvSpec file atomically (temp file + rename: never a partial file)."""
    atomic_write_text(Path(path), env_to_json(env))
