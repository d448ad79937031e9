"""`results.json` as a model: what `run`, `evaluate` and `run --seeds` write (docs/runner.md).

The runner builds the file as plain JSON (`runner.results.build_results`, `runner.seeds.
combine_seeds`); this model states its shape so that `python -m logicenveval schema results`
can publish a JSON Schema, and tests check every written file against it. The per-generator
and per-task blocks are the metric models themselves (`GeneratorMetrics`, `TaskMetrics`).
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.metrics.compute import GeneratorMetrics, TaskMetrics

_Open = ConfigDict(frozen=True, extra="allow", populate_by_name=True)


class GeneratorResults(GeneratorMetrics):
    """`results.<generator>`: the metrics over all tasks (and seeds), plus their intervals."""

    model_config = _Open
    ci95: dict[str, Any] = Field(
        default_factory=dict,
        description="95 % bootstrap interval [lo, hi] per rate, keyed and nested like the "
                    "metrics (logcov, ld, scevr, ji, phypr.*, faudr.*); over tasks (and seeds)")


class FailureEntry(BaseModel):
    """One failed unit or environment: `stage` `unit` for a unit that produced nothing."""

    model_config = _Open
    task: str
    stage: str
    message: str | None = None
    env_id: str | None = None
    kind: str | None = Field(default=None, description="infrastructure, generation or internal (units)")
    seed: int | None = Field(default=None, description="the seed run it came from (run --seeds)")
    attempts: int | None = Field(default=None, description="the failed attempts this entry's reason "
                                 "counts: of a unit that failed as a whole (stage `unit`), or of "
                                 "attempts that failed with no generation failure stating why")


class Timing(BaseModel):
    """Wall times: the only fields that differ between two runs of the same command."""

    model_config = _Open
    wall_seconds: float | None = None
    generation_seconds: dict[str, float] = Field(default_factory=dict)
    llm: dict[str, dict[str, float]] = Field(default_factory=dict)
    phases: dict[str, dict[str, float]] = Field(
        default_factory=dict, description="per generator: seconds its units spent per phase "
        "(tasks, start-up, generation, layout, physics, coverage, simulation, traces, mutants, "
        "render, writing)")
    run_phases: dict[str, float] = Field(
        default_factory=dict, description="seconds of the run's own phases in its main process "
        "(tasks, start-up, resume scan, units: running or awaiting them, saving: committing them, results)")
    per_task: dict[str, dict[str, dict[str, float]]] = Field(
        default_factory=dict, description="per generator and task: generation seconds, model "
        "requests (sent, answered from the cache), re-asks, prompt and completion tokens and model "
        "latency, to plan a run on a slow model")
    per_seed: dict[str, Any] | None = Field(default=None, description="run --seeds: each seed's timing")


class Benchmark(BaseModel):
    model_config = _Open
    task_sha256: dict[str, str] = Field(
        default_factory=dict, description="task id -> digest of its task.json (what `compare` checks)")


class ResultsFile(BaseModel):
    """The whole `results.json` of a run folder. Rates are fractions in [0, 1]."""

    model_config = _Open
    schema_: Literal["logicenveval.results/1"] = Field("logicenveval.results/1", alias="schema")
    run_id: str
    config: dict[str, Any] = Field(description="the run's identity (what names its folder)")
    model: str = Field(description="chat model spec (`external` for evaluate)")
    seed: int | None = Field(description="the run seed; null for a combined run --seeds")
    seeds: list[int] | None = None
    runs: dict[str, str] | None = Field(default=None, description="run --seeds: seed -> sub-folder")
    brief: str = "roles"
    protocol: int | None = Field(default=None, description="the request protocol the model was asked in "
                                 "(docs/llm.md); absent in runs made before it was recorded")
    tasks: list[str]
    benchmark: Benchmark = Field(default_factory=Benchmark)
    versions: dict[str, str] = Field(default_factory=dict)
    git_commit: str | None = None
    generators: list[str] | None = Field(
        default=None, description="the row names of `results` in the run's order (the file's keys "
        "are sorted; reports list the rows in this order)")
    results: dict[str, GeneratorResults] = Field(description="generator (row name) -> metrics")
    per_task: dict[str, dict[str, TaskMetrics]] | None = Field(
        default=None, description="generator -> task id -> that task's metrics (single-seed runs)")
    per_task_seed: dict[str, dict[str, dict[str, TaskMetrics]]] | None = Field(
        default=None, description="run --seeds: generator -> task id -> seed -> metrics")
    failures: dict[str, list[FailureEntry]] = Field(default_factory=dict)
    timing: Timing = Field(default_factory=Timing)
