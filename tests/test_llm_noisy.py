"""`noisy:<model>`: deterministic perturbations of replies, and metrics that fall, never rise."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from logicenveval.errors import ConfigError
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.registry import make_model

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))

TASKS = ("clean_living_room", "kitchen_dish_cleanup", "bathroom_counter_sort", "bedroom_morning_tidy")


def _scene_request(seed: int) -> ChatRequest:
    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog

    payload = {"task": load_task("clean_living_room").brief().model_dump(mode="json"),
               "categories": sorted(load_catalog().categories)}
    return ChatRequest(kind="holodeck_scene", payload=payload, messages=[], schema=None, seed=seed)


def test_perturbations_are_deterministic_by_seed_and_request() -> None:
    replies = {}
    for seed in (0, 1):
        a = make_model("noisy:offline", f"rate=1.0,seed={seed}")
        b = make_model("noisy:offline", f"rate=1.0,seed={seed}")
        replies[seed] = [a.complete(_scene_request(s)) for s in range(6)]
        assert replies[seed] == [b.complete(_scene_request(s)) for s in range(6)]
    assert replies[0] != replies[1]
    clean = make_model("offline").complete(_scene_request(0))
    assert make_model("noisy:offline", "rate=0,seed=3").complete(_scene_request(0)) == clean
    assert all(r != clean for r in replies[0][:1])


def test_every_error_kind_occurs() -> None:
    from logicenveval.llm.noisy import NoisyModel

    model = make_model("noisy:offline", "rate=1.0,seed=0")
    assert isinstance(model, NoisyModel)
    for s in range(60):
        model.complete(_scene_request(s))
    assert {"drop_object", "drop_relation", "rename_category", "swap_room", "truncate", "prose"} <= set(model.applied)


@pytest.mark.parametrize("args", ["rate=1.5", "rate=abc", "rate=0.1,seed=-1"])
def test_bad_noise_args(args: str) -> None:
    with pytest.raises(ConfigError, match="--model-args"):
        make_model("noisy:offline", args)


def test_noise_lowers_logicenvgen_and_raises_no_metric_beyond_its_interval() -> None:
    from robustness import METRICS, _get, rises, sweep  # type: ignore[import-not-found]

    by_rate = sweep((0.0, 0.3), ("logicenvgen",), TASKS, seed=0, workers=1)
    clean, noisy = by_rate[0.0]["logicenvgen"], by_rate[0.3]["logicenvgen"]
    lowered = [label for label, path in METRICS if label in ("PhyPR", "SceVR", "LogCov")
               and _get(noisy, path) < _get(clean, path)]
    assert lowered, json.dumps({"clean": clean["logcov"], "noisy": noisy["logcov"]})
    assert rises(by_rate, "logicenvgen") == []
