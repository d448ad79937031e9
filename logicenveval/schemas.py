"""JSON Schemas of the files users write and read, generated from the pydantic models.

`python -m logicenveval schema envspec|task|results` prints them; the same text is committed
under `docs/schemas/<name>.schema.json` and a test keeps the two equal. The models stay the
single source: a schema is never edited by hand.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from pydantic import BaseModel

from logicenveval.errors import ConfigError

#: name -> (model path, what the file is, where it is documented)
SCHEMAS: dict[str, tuple[str, str, str]] = {
    "envspec": ("logicenveval.model.envspec:EnvSpec", "One environment (EnvSpec JSON)",
                "docs/envspec.md"),
    "task": ("logicenveval.model.task:Task", "One benchmark task (task.json)", "docs/task-format.md"),
    "results": ("logicenveval.metrics.results_file:ResultsFile", "A run's results.json",
                "docs/runner.md"),
}
DOCS_DIR = Path(__file__).resolve().parents[1] / "docs" / "schemas"


def _model(name: str) -> type[BaseModel]:
    import importlib

    if name not in SCHEMAS:
        raise ConfigError(f"unknown schema {name!r}", field="NAME", hint=f"use one of {', '.join(SCHEMAS)}")
    module, _, attr = SCHEMAS[name][0].partition(":")
    model: type[BaseModel] = getattr(importlib.import_module(module), attr)
    return model


def json_schema(name: str) -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of one file kind, with its title and documentation."""
    model = _model(name)  # refuses unknown names
    _, what, doc = SCHEMAS[name]
    schema = model.model_json_schema(by_alias=True, mode="validation")
    return {"$schema": "https://json-schema.org/draft/2020-12/schema",
            "$id": f"https://logicenveval/schemas/{name}.schema.json",
            "description": f"{what}; documented in {doc} of the LogicEnvEval repository. "
                           "Generated from the package's models: `python -m logicenveval schema "
                           f"{name}`.", **schema}


def schema_text(name: str) -> str:
    """`json_schema` as the stable text that is committed under docs/schemas/."""
    return json.dumps(json_schema(name), indent=2, sort_keys=True) + "\n"
