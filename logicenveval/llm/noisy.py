"""`noisy:<model>`: a model whose replies are perturbed the ways real models err (beyond the paper).

`rate` is the probability that one element of a reply errs: each object draft (displaced, dropped,
its category renamed to a synonym or an invented word, or moved to another room), each relation
(dropped) and each decision branch (a tree step answering `act`, a factor losing all but one
response) errs on its own, by one error applicable to it — so a reply describing twelve
environments carries as many errors per object as one describing a single environment, and
methods that ask in one big reply are not spared. With probability `rate / 2` a reply's text is
broken instead (the JSON cut short, or wrapped in prose), which a re-ask may mend. Draws come from a numpy Generator seeded with `seed` and a hash of the request,
so a run is deterministic and independent of scheduling, and a re-ask (another temperature and
seed) draws again, as a real model's second attempt would. `benchmarks/robustness.py` sweeps the
rate to show how gracefully each method degrades when its LLM errs.
"""

from __future__ import annotations

import hashlib
import json
from typing import Any

import numpy as np

from logicenveval.errors import ConfigError
from logicenveval.llm.base import ChatModel, ChatRequest, ModelStats


def _holders(data: Any) -> list[dict[str, Any]]:
    """The dicts of a reply that hold object and relation lists (top level, each environment)."""
    if not isinstance(data, dict):
        return []
    out = [data]
    for env in data.get("environments") or []:
        out += _holders(env)
    return out


_INVENTED = ("thingamajig", "gizmo", "widget", "doohickey")


def _rename(o: dict[str, Any], rng: np.random.Generator) -> None:
    from logicenveval.domain.catalog import load_catalog

    cat = load_catalog().get(o["category"])
    synonyms = list(cat.synonyms) if cat is not None else []
    if synonyms and rng.random() < 0.5:
        o["category"] = synonyms[int(rng.integers(len(synonyms)))]
    else:
        o["category"] = f"{o['category']}_{_INVENTED[int(rng.integers(len(_INVENTED)))]}"


def _object_errors(o: dict[str, Any]) -> list[str]:
    """The errors that can befall one object draft."""
    out = ["drop_object"]
    pos = o.get("position")
    if isinstance(pos, list) and len(pos) == 3 and all(isinstance(v, int | float) for v in pos):
        out.append("displace")
    if isinstance(o.get("category"), str):
        out.append("rename_category")
    if isinstance(o.get("room"), str):
        out.append("swap_room")
    return out


def _perturb_elements(data: Any, rate: float, rng: np.random.Generator) -> list[str]:
    """Each object, relation and branch of the reply errs with probability `rate`, by one error
    applicable to it; returns the errors applied. Per element, so a reply that describes twelve
    environments carries as many errors per object as a reply that describes one."""
    applied: list[str] = []
    for holder in _holders(data):
        objects = holder.get("objects")
        if isinstance(objects, list):
            rooms = sorted({o["room"] for o in objects if isinstance(o, dict) and isinstance(o.get("room"), str)}
                           | {r["id"] for r in (holder.get("rooms") or data.get("rooms") or [])
                              if isinstance(r, dict) and isinstance(r.get("id"), str)})
            kept = []
            for o in objects:
                if not isinstance(o, dict) or rng.random() >= rate:
                    kept.append(o)
                    continue
                errors = _object_errors(o)
                error = errors[int(rng.integers(len(errors)))]
                applied.append(error)
                if error == "drop_object":
                    continue
                if error == "displace":
                    x, y, z = o["position"]
                    o["position"] = [x + float(rng.normal(0, 0.6)), y, z + float(rng.normal(0, 0.6))]
                elif error == "rename_category":
                    _rename(o, rng)
                else:
                    others = [r for r in rooms if r != o["room"]]
                    o["room"] = others[int(rng.integers(len(others)))] if others else "attic"
                kept.append(o)
            holder["objects"] = kept
        relations = holder.get("relations")
        if isinstance(relations, list):
            kept_rel = [r for r in relations if rng.random() >= rate]
            applied += ["drop_relation"] * (len(relations) - len(kept_rel))
            holder["relations"] = kept_rel
    if isinstance(data, dict):
        if data.get("next") not in (None, "act") and rng.random() < rate:
            data["next"] = "act"  # a tree step that stops asking: the branch below is empty
            applied.append("empty_branch")
        for f in data.get("factors") or []:
            if isinstance(f, dict) and isinstance(f.get("responses"), list) and len(f["responses"]) > 1 \
                    and rng.random() < rate:
                f["responses"] = f["responses"][:1]
                applied.append("empty_branch")
    return applied


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
        if self.rate <= 0.0:
            return reply
        try:
            data = json.loads(reply)
        except (ValueError, RecursionError):
            return reply
        if rng.random() < self.rate / 2:  # the reply's text itself is broken (a re-ask may mend it)
            name = "truncate" if rng.random() < 0.5 else "prose"
            self.applied[name] = self.applied.get(name, 0) + 1
            if name == "truncate":
                text = json.dumps(data)
                return text[: int(len(text) * float(rng.uniform(0.2, 0.9)))]
            return ("Sure! Here is the JSON you asked for:\n```json\n"
                    f"{json.dumps(data, indent=1)}\n```\nHope it helps.")
        for name in _perturb_elements(data, self.rate, rng):
            self.applied[name] = self.applied.get(name, 0) + 1
        return json.dumps(data)
