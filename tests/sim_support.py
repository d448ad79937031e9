"""Shared fixtures of the simulator tests: a small catalog and the clean_living_room task."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import Catalog
from logicenveval.model.task import Task

TASKS = Path(__file__).resolve().parents[1] / "benchmark_data" / "tasks"
POLICIES = TASKS / "clean_living_room" / "policies"


def _cat(**kw: Any) -> dict[str, Any]:
    base: dict[str, Any] = {"size_min": [0.1, 0.1, 0.1], "size_max": [0.5, 0.5, 0.5],
                            "placement": ["surface", "floor"]}
    base.update(kw)
    return base


def small_catalog() -> Catalog:
    return Catalog.model_validate({"categories": {
        "toy": _cat(pickable=True, attributes={"kind": ["doll", "car", "ball"],
                                                "color": ["red", "blue"]}),
        "toy_box": _cat(container=True, placement=["floor"]),
        "book": _cat(pickable=True),
        "sofa": _cat(surface=True, placement=["floor"], rooms=["LivingRoom"]),
        "coffee_table": _cat(surface=True, placement=["floor"]),
        "wet_wipe": _cat(pickable=True),
        "mop": _cat(pickable=True, placement=["floor"]),
        "floor_stain": _cat(placement=["floor"], default_states={"dirty": True}),
        "fridge": _cat(container=True, openable=True, placement=["floor"]),
        "lamp": _cat(toggleable=True, pickable=True),
        "cup": _cat(pickable=True, fillable=True),
        "sink": _cat(container=True, placement=["floor"]),
        "trash_can": _cat(container=True, openable=True, placement=["floor"]),
    }})


def living_room_task() -> Task:
    return load_task("clean_living_room", TASKS)
