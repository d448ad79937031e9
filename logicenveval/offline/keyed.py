"""The keyed reply shape of protocol 3 (role objects keyed by role), as the offline model writes
it: it answers either shape of a scene request with the same objects."""

from __future__ import annotations

from typing import Any


def keyed_selection(objects: list[dict[str, Any]]) -> dict[str, Any]:
    """A scene's objects (dicts with a `role`) in the keyed shape of protocol 3: a role object's
    id is its role's name (the offline model answers either shape with the same objects)."""
    fields = ("category", "room", "placement", "attributes", "states")
    return {"role_objects": {o["role"]: {k: o[k] for k in fields} for o in objects if o["role"]},
            "other_objects": [{"id": o["id"], **{k: o[k] for k in fields}} for o in objects if not o["role"]]}


def keyed(request: Any) -> bool:
    """Whether a request (`llm.base.ChatRequest`) asks for the role objects keyed by role."""
    return "role_objects" in ((getattr(request, "schema", None) or {}).get("properties") or {})
