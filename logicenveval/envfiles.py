"""Reading and writing EnvSpec JSON files with precise errors."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import EnvSpec
from logicenveval.validation import first_error


def env_from_dict(data: Any, *, source: str | None = None) -> EnvSpec:
    try:
        return EnvSpec.model_validate(data)
    except ValidationError as exc:
        loc, msg = first_error(exc)
        raise EnvSpecError(msg, file=source, field=loc,
                           hint="see DESIGN.md §6 for the EnvSpec format") from None


def load_env(path: str | Path) -> EnvSpec:
    p = Path(path)
    try:
        data = json.loads(p.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise EnvSpecError("file not found", file=str(p), hint="check the path") from None
    except json.JSONDecodeError as exc:
        raise EnvSpecError(f"invalid JSON: {exc.msg}", file=str(p), line=exc.lineno,
                           column=exc.colno, hint="fix the JSON syntax") from None
    return env_from_dict(data, source=str(p))


def env_to_json(env: EnvSpec) -> str:
    """Canonical, byte-stable JSON text of an EnvSpec."""
    return json.dumps(env.to_json_dict(), indent=2, sort_keys=False) + "\n"


def save_env(env: EnvSpec, path: str | Path) -> None:
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(env_to_json(env), encoding="utf-8")
