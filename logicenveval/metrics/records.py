"""Typed records that flow from evaluation into the metrics (one `EnvSample` per environment).

`samples.jsonl` holds exactly these records, so every metric can be recomputed from a run folder.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from logicenveval.domain.roles import RoleChoice
from logicenveval.generators.base import Attempt, GenerationFailure


class PhysicsSummary(BaseModel):
    model_config = ConfigDict(frozen=True)
    floor_plan: bool
    entity: bool
    relation: bool
    #: typed failures as plain dicts (code, objects, measured, tolerance, message, dimension)
    failures: list[dict[str, Any]] = Field(default_factory=list)
    #: the extra plausibility checks beyond the paper's PhyPR (`physics.EXTENDED_CODES`)
    extended: bool = True
    extended_failures: list[dict[str, Any]] = Field(default_factory=list)


class EnvSample(BaseModel):
    """Everything measured about one generated environment."""

    model_config = ConfigDict(frozen=True)
    generator: str
    task_id: str
    env_id: str
    claimed_trajectory: dict[str, dict[str, str]] | None = None
    #: GT decision-path keys reached on the initial state (`DecisionPath.key`)
    covered_paths: list[str] = Field(default_factory=list)
    #: `Trajectory.key` when every GT tree reached a leaf, else None
    trajectory: str | None = None
    #: atomic conditions (variable, value) met on the reached paths (paper Def. 1)
    conditions: list[tuple[str, str]] = Field(default_factory=list)
    well_formed: bool = False
    problems: list[str] = Field(default_factory=list)
    #: one message per explicit task constraint the environment violates (not a valid scenario)
    violations: list[str] = Field(default_factory=list)
    physics: PhysicsSummary
    #: policy kind -> verdict status (`passed`, `precondition_violation`, ...)
    verdicts: dict[str, str] = Field(default_factory=dict)
    #: policy kind -> simulation wall time in milliseconds (a timing field); key `mutants`:
    #: time to simulate the task's killable mutants (not part of ST)
    sim_ms: dict[str, float] = Field(default_factory=dict)
    #: ids of the task's killable mutants that fail here (valid environments only; `faudr_mut`)
    killed_mutants: list[str] = Field(default_factory=list)
    #: policy kind -> simulator ticks of the run (deterministic companion of `sim_ms`)
    sim_ticks: dict[str, int] = Field(default_factory=dict)
    #: written category -> the catalog key it was judged as, where it was not a key already
    categories: dict[str, str] = Field(default_factory=dict)
    #: written categories that name no catalog category -> object ids (judged as obstacles)
    unknown_categories: dict[str, list[str]] = Field(default_factory=dict)
    #: task role -> the object that played it and why (`domain.roles`: explicit map, id,
    #: attribute, name words, category, absent, ambiguous), so a verdict can be replayed
    binding: dict[str, RoleChoice] = Field(default_factory=dict)
    #: entries of the EnvSpec's own role map the check refused (bound by meaning instead)
    refused_roles: list[str] = Field(default_factory=list)


class VerdictTrace(BaseModel):
    """One BT's run in one environment as the report shows it: verdict, message, tick trace."""

    model_config = ConfigDict(frozen=True)
    status: str
    message: str = ""
    trace: list[str] = Field(default_factory=list)


class EnvDetail(BaseModel):
    """What the reports show about one environment beyond its metrics, recorded when the unit
    evaluated it, so that `report` reads instead of re-running physics and simulation."""

    model_config = ConfigDict(frozen=True)
    env_id: str
    #: the top-down render, relative to the run folder (a derived file, re-drawn when missing)
    render: str | None = None
    #: policy kind -> a traced re-run of the episode whose verdict is in `EnvSample.verdicts`
    traces: dict[str, VerdictTrace] = Field(default_factory=dict)


class UnitRecord(BaseModel):
    """The committed result of one (generator, task) unit of a run."""

    model_config = ConfigDict(frozen=True)
    generator: str
    task_id: str
    samples: list[EnvSample] = Field(default_factory=list)
    failures: list[GenerationFailure] = Field(default_factory=list)
    #: a unit that crashed as a whole (LLM error, solver timeout): its reason
    error: str | None = None
    #: why the unit failed: `infrastructure` (endpoint, cache, disk: recomputed by the next run),
    #: `generation` (the generator or model could not do it) or `internal` (a generator bug)
    error_kind: Literal["infrastructure", "generation", "internal"] | None = None
    gen_seconds: float = 0.0
    #: killable mutant id -> fault class (`faults.score`); empty when mutants were not scored
    mutants: dict[str, str] = Field(default_factory=dict)
    #: LLM counters of the unit (requests, cache hits/misses, retries, re-asks, tokens, latency)
    llm: dict[str, float] = Field(default_factory=dict)
    #: one per sample, same order: what the drill-down of `leaderboard.html` shows
    details: list[EnvDetail] = Field(default_factory=list)
    #: run-relative path -> SHA-256 of each file the unit wrote that only generation can rebuild
    files: dict[str, str] = Field(default_factory=dict)
    #: every environment the generator set out to build (`generators.base.counted_attempts`);
    #: a unit that failed as a whole holds its planned attempts as failed (none: infrastructure)
    attempts: list[Attempt] = Field(default_factory=list)
    #: a search of the generator that stopped at its budget, and what it used instead
    budget_hit: str | None = None
    #: the full traceback (redacted) of an exception that failed the unit as a whole
    traceback: str | None = None
    #: fingerprints of what made the unit: harness, generator code, task files, catalog
    #: (`runner.fingerprint`); a resumed run recomputes the unit when one changed
    inputs: dict[str, str] = Field(default_factory=dict)
    #: the limits (`logicenveval.limits`) that refused something in this unit, with the values in
    #: force: the outcome depends on them, so a run under other values recomputes the unit
    limits: dict[str, int] = Field(default_factory=dict)
    #: seconds per phase of the unit (`logicenveval.phases`: tasks, start-up, generation, layout,
    #: physics, coverage, simulation, traces, mutants, render, writing); a timing field
    phases: dict[str, float] = Field(default_factory=dict)

    @property
    def measured(self) -> bool:
        """False when the unit failed for infrastructure reasons: not a result, never a zero."""
        return self.error_kind != "infrastructure"

    @property
    def n_failed(self) -> int:
        """Attempted environments that were not built (docs/logic.md). Units written before
        attempts were recorded: failures naming an environment that is not among the samples,
        at least one when the unit holds no sample."""
        if self.attempts:
            return sum(not a.built for a in self.attempts)
        built = {s.env_id for s in self.samples}
        failed = {f.env_id for f in self.failures if f.env_id is not None and f.env_id not in built}
        return len(failed) if self.samples or failed else 1

    @property
    def n_attempted(self) -> int:
        return len(self.samples) + self.n_failed
