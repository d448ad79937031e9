"""`noisy:<model>`: a model whose replies are perturbed the ways real models err (beyond the paper).

Each reply of the wrapped model is perturbed with probability `rate` by one error drawn from
those applicable to it: coordinates displaced, an object or relation dropped, a category renamed
to a synonym or to an invented word, an object moved to another room, a decision branch emptied
(a tree step answering `act`, a factor losing its responses), the JSON cut short, or the JSON
wrapped in prose. Draws come from a numpy Generator seeded with `seed` and a hash of the request,
so a run is deterministic and independent of scheduling, and a re-ask (another temperature and
seed) draws again, as a real model's second attempt would. `benchmarks/robustness.py` sweeps the
rate to show how gracefully each method degrades when its LLM errs.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable
from typing import Any

import numpy as np

from logicenveval.errors import ConfigError
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats

Perturb = Callable[[Any, np.random.Generator], Any]


def _objects(data: Any) -> list[dict[str, Any]]:
    """Every object draft in a reply (top level or inside environments)."""
    if not isinstance(data, dict):
        return []
    out = [o for o in data.get("objects") or [] if isinstance(o, dict)]
    for env in data.get("environments") or []:
        out += _objects(env)
    return out


def _lists(data: Any, key: str) -> list[list[Any]]:
    if not isinstance(data, dict):
        return []
    found = [data[key]] if isinstance(data.get(key), list) and data[key] else []
    for env in data.get("environments") or []:
        found += _lists(env, key)
    return found


def _displace(data: Any, rng: np.random.Generator) -> Any:
    placed = [o for o in _objects(data) if isinstance(o.get("position"), list) and len(o["position"]) == 3]
    for o in placed:
        if rng.random() < 0.5:
            x, y, z = o["position"]
            o["position"] = [x + float(rng.normal(0, 0.6)), y, z + float(rng.normal(0, 0.6))]
    return data


def _drop(key: str) -> Perturb:
    def drop(data: Any, rng: np.random.Generator) -> Any:
        lists = _lists(data, key)
        target = lists[int(rng.integers(len(lists)))]
        del target[int(rng.integers(len(target)))]
        return data

    return drop


_INVENTED = ("thingamajig", "gizmo", "widget", "doohickey")


def _rename(data: Any, rng: np.random.Generator) -> Any:
    from logicenveval.domain.catalog import load_catalog

    objects = [o for o in _objects(data) if isinstance(o.get("category"), str)]
    o = objects[int(rng.integers(len(objects)))]
    cat = load_catalog().get(o["category"])
    synonyms = list(cat.synonyms) if cat is not None else []
    if synonyms and rng.random() < 0.5:
        o["category"] = synonyms[int(rng.integers(len(synonyms)))]
    else:
        o["category"] = f"{o['category']}_{_INVENTED[int(rng.integers(len(_INVENTED)))]}"
    return data


def _swap_room(data: Any, rng: np.random.Generator) -> Any:
    objects = [o for o in _objects(data) if isinstance(o.get("room"), str)]
    rooms = sorted({o["room"] for o in objects} | {r["id"] for r in (data.get("rooms") or [])
                                                    if isinstance(r, dict) and isinstance(r.get("id"), str)})
    o = objects[int(rng.integers(len(objects)))]
    others = [r for r in rooms if r != o["room"]]
    o["room"] = others[int(rng.integers(len(others)))] if others else "attic"
    return data


def _empty_branch(data: Any, rng: np.random.Generator) -> Any:
    if "next" in data:
        data["next"] = "act"
        return data
    factors = [f for f in data["factors"] if isinstance(f, dict) and f.get("responses")]
    f = factors[int(rng.integers(len(factors)))]
    f["responses"] = f["responses"][:1]
    return data


def _applicable(data: Any) -> list[tuple[str, Perturb]]:
    out: list[tuple[str, Perturb]] = []
    if not isinstance(data, dict):
        return out
    objects = _objects(data)
    if any(isinstance(o.get("position"), list) for o in objects):
        out.append(("displace", _displace))
    if _lists(data, "objects"):
        out.append(("drop_object", _drop("objects")))
    if _lists(data, "relations"):
        out.append(("drop_relation", _drop("relations")))
    if any(isinstance(o.get("category"), str) for o in objects):
        out.append(("rename_category", _rename))
    if any(isinstance(o.get("room"), str) for o in objects):
        out.append(("swap_room", _swap_room))
    if data.get("next") not in (None, "act") or any(
            isinstance(f, dict) and f.get("responses") for f in data.get("factors") or []):
        out.append(("empty_branch", _empty_branch))
    return out


class NoisyModel:
    """Wraps a ChatModel; perturbs each reply with probability `rate` (deterministic by seed)."""

    def __init__(self, inner: ChatModel, *, rate: float = 0.0, seed: int = 0,
                 stats: ModelStats | None = None) -> None:
        if not isinstance(rate, int | float) or isinstance(rate, bool) or not 0.0 <= rate <= 1.0:
            raise ConfigError(f"rate={rate!r} is not a number in [0, 1]", field="--model-args rate",
                              hint="e.g. --model-args rate=0.3,seed=0")
        if not isinstance(seed, int) or isinstance(seed, bool) or seed < 0:
            raise ConfigError(f"seed={seed!r} is not an integer >= 0", field="--model-args seed",
                              hint="e.g. --model-args rate=0.3,seed=0")
        self.inner = inner
        self.rate = float(rate)
        self.seed = seed
        self.name = f"noisy({inner.name})"
        self.stats = stats or getattr(inner, "stats", None) or ModelStats()
        #: how often each perturbation was applied (for the robustness benchmark)
        self.applied: dict[str, int] = {}

    def _rng(self, request: ChatRequest) -> np.random.Generator:
        blob = json.dumps([request.kind, request.messages, request.temperature, request.seed],
                          sort_keys=True)
        digest = hashlib.sha256(blob.encode()).digest()
        return np.random.default_rng([self.seed, int.from_bytes(digest[:8], "little")])

    def complete(self, request: ChatRequest) -> str:
        reply = self.inner.complete(request)
        rng = self._rng(request)
        if self.rate <= 0.0 or rng.random() >= self.rate:
            return reply
        try:
            data = json.loads(reply)
        except ValueError:
            return reply
        options: list[tuple[str, Perturb | None]] = [*_applicable(data), ("truncate", None),
                                                     ("prose", None)]
        name, perturb = options[int(rng.integers(len(options)))]
        self.applied[name] = self.applied.get(name, 0) + 1
        if name == "truncate":
            text = json.dumps(data)
            return text[: int(len(text) * float(rng.uniform(0.2, 0.9)))]
        if name == "prose":
            return ("Sure! Here is the JSON you asked for:\n```json\n"
                    f"{json.dumps(data, indent=1)}\n```\nHope it helps.")
        assert perturb is not None
        return json.dumps(perturb(data, rng))
