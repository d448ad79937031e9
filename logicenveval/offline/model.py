"""The embedded `offline` model: deterministic, rule-based, answering from `kind` + `payload`.

It never reads ground truth (task files, GT trees, policies): every handler receives only what a
real LLM would receive (the request payload, its temperature and seed). Importing this module
imports every answer module of the package, which registers its request kinds (`handlers`).
"""

from __future__ import annotations

import json

from logicenveval.errors import ConfigError
from logicenveval.llm.base import ChatRequest, ModelStats
from logicenveval.llm.bounds import fit_arrays
from logicenveval.offline import baseline_answers, naming, plan, scene_answers  # noqa: F401  (they register their answers)
from logicenveval.offline.handlers import answer_for, known_kinds


class OfflineModel:
    """A ChatModel whose replies are computed by rule-based handlers (no network)."""

    name = "offline"

    def __init__(self, *, stats: ModelStats | None = None) -> None:
        self.stats = stats or ModelStats()

    def complete(self, request: ChatRequest) -> str:
        fn = answer_for(request.kind)
        if fn is None:
            raise ConfigError(f"the offline model cannot answer {request.kind!r} requests",
                              field="--model",
                              hint="known kinds: " + ", ".join(known_kinds()))
        self.stats.add(requests=1)
        # within the schema's list bounds, as a grammar-constrained model must write (llm.bounds)
        return json.dumps(fit_arrays(fn(request.payload, request), request.schema))
