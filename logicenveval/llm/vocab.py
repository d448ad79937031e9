"""Request vocabularies: reply fields whose values must come from the task's own words.

A reply model marks a string field, `Annotated[str, Vocab("roles")]`. The marker alone changes
nothing. A request that passes a vocabulary
(`ask(..., vocabulary={"roles": ["toy", "box"], ...})`) gets a JSON schema in which every marked
field is an `enum` of those words (or a `pattern`, for open sets such as object ids), and its
reply is validated against the same words, so the server's grammar (llama.cpp enforces `enum` and
`pattern`), the prompt and the validator agree. A value outside the vocabulary is a validation
error that quotes the value and lists the allowed ones, which is what the re-ask sends back.

Any reply model can adopt it by marking fields; request kinds without a vocabulary keep free
strings.
"""

from __future__ import annotations

import json
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from pydantic import GetCoreSchemaHandler, GetJsonSchemaHandler, ValidationInfo
from pydantic.json_schema import JsonSchemaValue
from pydantic_core import CoreSchema, core_schema

#: JSON-schema key of the marker (kept in the schema sent without a vocabulary: servers ignore it)
MARK = "x-vocab"
#: JSON-schema key of a list whose length is at most the size of a vocabulary (`maxItems`);
#: its items must then be distinct, which the reply model checks
COUNT = "x-count"
#: JSON-schema key of a list of the *other* words of a vocabulary (a room's neighbours): at most
#: one item fewer than the vocabulary (`maxItems`), none when it has one word. Removed from the
#: schema sent; the bound applies from request protocol 2 on (`specialise(..., others=True)`)
OTHERS = "x-others"
#: JSON-schema key of a list that must hold at least one item per word of a vocabulary (the
#: objects of a scene: one per role the situation requires; `minItems`). Removed from the schema
#: sent; the bound applies from request protocol 2 on, like `OTHERS`
AT_LEAST = "x-at-least"
#: JSON-schema key of an object (a map) whose keys are exactly the words of a vocabulary (the
#: objects of a scene keyed by the roles the situation requires): sent as one required property
#: per word, so a grammar writes each key once and none other. Removed from the schema sent;
#: a bound like `OTHERS` (`specialise(..., bounds=True)`); without it the map is open
KEYS = "x-keys"
#: JSON-schema key of a list of at most one item per word of a vocabulary that only some requests
#: give (`maxItems`; the relations of a scene: at most one per object, from protocol 3 on, whose
#: requests give `relation_slots`; the environments CoT and IFG write, and their objects and
#: relations, from protocol 4 on: `environment_slots`, `object_slots`). Removed from the schema
#: sent, so a request without the vocabulary sends the schema it always did
AT_MOST = "x-at-most"
#: JSON-schema key of a map whose keys may only be words of a vocabulary that only some
#: requests give (an object's `states`: the condition language's state flags, from protocol 5
#: on, `state_flags`): sent as one optional property per word and no other, so a grammar cannot
#: write its own schema's words as keys (Qwen2.5-Coder-1.5B's `"states": {"additionalProperties":
#: false}`, 9 of 11 scenes). Removed from the schema sent, so a request without the vocabulary
#: sends the schema it always did
SOME_KEYS = "x-some-keys"
#: validation-context key under which `ask` passes the vocabulary
CONTEXT_KEY = "vocabulary"


@dataclass(frozen=True)
class Pattern:
    """An open vocabulary: any string matching `regex` (e.g. snake_case ids)."""

    regex: str


Words = Sequence[str] | Pattern
Vocabulary = Mapping[str, Words]

#: a snake_case id of at most 40 characters (a bound the grammar enforces: small models loop in ids)
SNAKE = Pattern(r"^[a-z][a-z0-9_]{0,39}$")


def admits(words: Words, value: str) -> bool:
    """Whether `value` is one of `words` (matches it, for a pattern; an empty list admits all)."""
    if isinstance(words, Pattern):
        return re.fullmatch(words.regex, value) is not None
    return not words or value in words


def _check(name: str) -> Any:
    def check(value: str, info: ValidationInfo) -> str:
        vocabulary = (info.context or {}).get(CONTEXT_KEY) or {}
        words = vocabulary.get(name)
        if words is None or admits(words, value):
            return value
        if isinstance(words, Pattern):
            raise ValueError(f"{value!r} is not a valid {name} (must match {words.regex})")
        shown = ", ".join(list(words)[:40]) + (", ..." if len(words) > 40 else "")
        raise ValueError(f"{value!r} is not one of the {name}: {shown}")

    return check


@dataclass(frozen=True)
class Vocab:
    """Marker of a string field drawn from the request vocabulary `name`:
    `Annotated[str, Vocab("roles")]`."""

    name: str
    description: str = ""

    def __get_pydantic_core_schema__(self, source: Any, handler: GetCoreSchemaHandler) -> CoreSchema:
        return core_schema.with_info_after_validator_function(_check(self.name), handler(source))

    def __get_pydantic_json_schema__(self, schema: CoreSchema,
                                     handler: GetJsonSchemaHandler) -> JsonSchemaValue:
        out = handler.resolve_ref_schema(handler(schema))
        out[MARK] = self.name
        if self.description:
            out.setdefault("description", self.description)
        return out


def specialise(schema: dict[str, Any], vocabulary: Vocabulary | None, *, bounds: bool = True) -> dict[str, Any]:
    """A copy of `schema` whose marked fields list their vocabulary (enum) or pattern.

    `bounds` (request protocol 2 on; protocol 1 sent neither): `OTHERS` lists hold only the
    other words (a one-room task's room has no neighbour to name: Qwen2.5-Coder-1.5B, offered
    only its own room, listed it three times in a row), `AT_LEAST` lists one item per word at
    least (the same model wrote one object per scene, whatever the re-ask said about the roles
    left without one), `KEYS` maps have one required property per word (the same model, asked
    for at least one object per role, repeated `cloth` eight times and left roles out). Copied
    and specialised in one pass over the JSON data
    (`copy.deepcopy` of the schema took most of this per request: ~0.2 s of LogicEnvGen's
    generation per run)."""
    defs = schema.get("$defs") or {}
    inlined_defs: set[str] = set()

    def walk(node: Any, vocabulary: Vocabulary) -> Any:
        if isinstance(node, list):
            return [walk(value, vocabulary) for value in node]
        if not isinstance(node, dict):
            return node
        out = {key: walk(value, vocabulary) for key, value in node.items()}
        name = out.get(MARK)
        words = vocabulary.get(name) if isinstance(name, str) else None
        if isinstance(words, Pattern):
            out["pattern"] = words.regex
        elif words:
            out["enum"] = list(dict.fromkeys(words))
        counted = out.get(COUNT)
        bound = vocabulary.get(counted) if isinstance(counted, str) else None
        if bound and not isinstance(bound, Pattern):  # a list of at most one item per word
            out["maxItems"] = len(set(bound))
        other = out.pop(OTHERS, None)
        rest = vocabulary.get(other) if isinstance(other, str) and bounds else None
        if rest and not isinstance(rest, Pattern):
            out["maxItems"] = len(set(rest)) - 1
        keyed = out.pop(KEYS, None)
        keys = vocabulary.get(keyed) if isinstance(keyed, str) and bounds else None
        if keys is not None and not isinstance(keys, Pattern):
            value = out.pop("additionalProperties", {})
            out["properties"] = {word: _per_key(node.get("additionalProperties"), word, vocabulary) or value
                                 for word in dict.fromkeys(keys)}
            out["required"] = list(dict.fromkeys(keys))
            out["additionalProperties"] = False
        some = out.pop(SOME_KEYS, None)
        allowed = vocabulary.get(some) if isinstance(some, str) else None
        if allowed and not isinstance(allowed, Pattern):
            value = out.pop("additionalProperties", {})
            out["properties"] = {word: value for word in dict.fromkeys(allowed)}
            out["additionalProperties"] = False
        most = out.pop(AT_MOST, None)
        slots = vocabulary.get(most) if isinstance(most, str) else None
        if slots and not isinstance(slots, Pattern):
            out["maxItems"] = min(int(out.get("maxItems", len(slots))), len(slots))
        least = out.pop(AT_LEAST, None)
        each = vocabulary.get(least) if isinstance(least, str) and bounds else None
        if each and not isinstance(each, Pattern):
            out["minItems"] = max(int(out.get("minItems", 0)), len(set(each)))
        return out

    def _per_key(value: Any, word: str, vocabulary: Vocabulary) -> dict[str, Any] | None:
        """A `KEYS` map's value schema for one key, inlined and specialised with the key's own
        words (`name@key` entries of the vocabulary); None when the key has none."""
        own = {name.rpartition("@")[0]: words for name, words in vocabulary.items() if name.endswith(f"@{word}")}
        ref = value.get("$ref") if isinstance(value, dict) else None
        if not own or not isinstance(ref, str) or not ref.startswith("#/$defs/"):
            return None
        inlined_defs.add(ref.removeprefix("#/$defs/"))
        inlined: dict[str, Any] = _bare(walk(defs[ref.removeprefix("#/$defs/")], {**vocabulary, **own}))
        return inlined

    result: dict[str, Any] = walk(schema, vocabulary or {})
    if inlined_defs and isinstance(result.get("$defs"), dict):  # a def every key inlined is sent no more
        text = json.dumps({k: v for k, v in result.items() if k != "$defs"}) + json.dumps(
            [d for d in result["$defs"].values()])
        result["$defs"] = {k: d for k, d in result["$defs"].items() if f'"#/$defs/{k}"' in text}
        if not result["$defs"]:
            del result["$defs"]
    return result


def _bare(node: Any) -> Any:
    """A schema without descriptions and vocabulary marks: what a key's inlined copy sends (its
    words say it; the shared definition says the rest once)."""
    if isinstance(node, list):
        return [_bare(value) for value in node]
    if not isinstance(node, dict):
        return node
    return {key: {name: _bare(sub) for name, sub in value.items()} if key == "properties" else _bare(value)
            for key, value in node.items() if key not in ("description", MARK)}


#: `floor`, `wall`, `ceiling`, `on:<object id>`, `inside:<object id>`
PLACEMENT = Pattern(r"^(floor|wall|ceiling|(on|inside):[a-z0-9_]{1,40})$")


def scene_vocabulary(rooms: Sequence[str], roles: Sequence[str], categories: Sequence[str],
                     object_ids: Sequence[str] | None = None,
                     required_roles: Sequence[str] | None = None) -> dict[str, Words]:
    """The words of a scene reply (floor plan, objects, relations): the task's rooms, room
    types, categories (the catalog's and the roles'), roles, relation types; object ids listed when the request names
    them (relations over given objects), else any snake_case id. `required_roles`: the roles
    the reply must give an object (checked, not sent: `llm.replies.bind_objects`)."""
    from logicenveval.model.envspec import RELATION_TYPES
    from logicenveval.model.rooms import ROOM_TYPES

    return {"rooms": list(rooms), "door_targets": [*rooms, "exterior"], "room_types": list(ROOM_TYPES),
            "roles": list(roles), "categories": list(dict.fromkeys(categories)), "placements": PLACEMENT,
            "relation_types": list(RELATION_TYPES), "object_ids": list(object_ids or []) or SNAKE,
            **({"required_roles": list(required_roles)} if required_roles is not None else {})}
