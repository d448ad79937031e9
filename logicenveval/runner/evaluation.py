"""Judging one generated environment: physics, GT coverage, and the four policies.

This is where the independent parts meet; each is called through its public API so that the
same evaluation serves the runner, `generate`, and tests.
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from logicenveval.domain.catalog import Catalog
from logicenveval.domain.roles import prepare_env
from logicenveval.metrics.evaluate import constraint_problems, coverage
from logicenveval.metrics.records import EnvSample, PhysicsSummary, VerdictTrace
from logicenveval.model.conditions import Cond, to_text
from logicenveval.model.envspec import EnvSpec, unknown_state_flags
from logicenveval.model.task import Task
from logicenveval.phases import phase
from logicenveval.physics import PhysicsReport, check_env
from logicenveval.sim.simulator import compiled, simulate, task_goal
from logicenveval.sim.world import World, symbolic_key

if TYPE_CHECKING:
    from logicenveval.faults.score import MutationScorer


@dataclass(frozen=True)
class Evaluation:
    """The measured sample plus what the reports show (judged env and physics report for the
    render, traces)."""

    sample: EnvSample
    #: the environment as judged (roles bound)
    env: EnvSpec
    physics: PhysicsReport
    traces: dict[str, VerdictTrace]
    #: the initial symbolic world of `env` (never ticked: episodes run on copies)
    world: World
    #: `sim.world.symbolic_key(env)`: all that an episode on `env` depends on
    key: str


def evaluate_env(
    generator: str,
    task: Task,
    env: EnvSpec,
    policies: Mapping[str, Any],
    catalog: Catalog,
    given: Mapping[str, str] | None = None,
) -> Evaluation:
    """Measure one environment; never raises for a bad environment (that is a finding).

    Categories are mapped to catalog keys and the roles the environment does not map are bound
    first (`domain.roles.prepare_env`), so environments made by other tools are judged by the
    same trees, physics and policies; an ambiguous role makes it ill-formed, a violated task
    constraint an invalid scenario (`violations`). The sample records
    the written categories that were mapped and those that name nothing (kept as obstacles).

    Each policy runs twice: traced for the report's drill-down (so that `report` never simulates),
    which is also the warm-up, then untraced and timed (`sim_ms`, the paper's ST): a unit's first
    episode pays for tree building and caches that are no simulation time (they made a generator
    with one environment per task look slower than one with seven), and recording a trace adds
    ~40 % to these sub-millisecond episodes. A traced episode is not run again for a symbolic
    world this process already traced (`_traced`); the timed one always runs.
    """
    with phase("physics"):
        prepared = prepare_env(env, task.roles, catalog, given)
        env, binding = prepared.env, prepared.binding
        report = check_env(env, catalog)
        flags = unknown_state_flags(env)
    failures = [
        f.model_dump(mode="json")
        for dim in (report.floor_plan, report.entity, report.relation)
        for f in dim.failures
    ]
    physics = PhysicsSummary(
        floor_plan=report.floor_plan.passed,
        entity=report.entity.passed,
        relation=report.relation.passed,
        failures=failures,
        extended=report.extended.passed,
        extended_failures=[f.model_dump(mode="json") for f in report.extended.failures],
    )
    with phase("coverage"):
        world = World.from_env(env, catalog)  # the initial state, copied for each traced episode
        holds = world.holds
        cov = coverage(task, holds, env.roles, binding)
        violations = constraint_problems(task, env, holds)
        goal = task_goal(task, world)
        key = symbolic_key(env)
    verdicts: dict[str, str] = {}
    sim_ms: dict[str, float] = {}
    sim_ticks: dict[str, int] = {}
    traces: dict[str, VerdictTrace] = {}
    memo_key = (key, None if goal is None else to_text(goal))
    for kind, policy in policies.items():
        with phase("traces"):
            traces[kind], sim_ticks[kind] = _traced(policy, catalog, memo_key, world, goal)
        with phase("simulation"):
            start = time.perf_counter()
            verdicts[kind] = simulate(policy, env, task, catalog).status
            sim_ms[kind] = (time.perf_counter() - start) * 1000.0
    sample = EnvSample(
        generator=generator,
        task_id=task.id,
        env_id=env.env_id,
        claimed_trajectory=env.claimed_trajectory,
        covered_paths=list(cov.covered_paths),
        trajectory=cov.trajectory,
        conditions=[tuple(c) for c in cov.conditions],
        well_formed=cov.well_formed and binding.well_formed and not flags,
        problems=binding.problems + list(cov.problems) + flags,
        violations=violations,
        physics=physics,
        verdicts=verdicts,
        sim_ms=sim_ms,
        sim_ticks=sim_ticks,
        categories=prepared.categories.mapped,
        unknown_categories=prepared.categories.unknown,
        binding=binding.record(),
        refused_roles=list(binding.refused),
    )
    return Evaluation(sample=sample, env=env, physics=report, traces=traces, world=world, key=key)


#: traced episodes by (policy, catalog, symbolic world, goal), with the policy and catalog they
#: were run with (kept alive, so their ids are not reused) -> trace, root ticks
_TRACED: dict[tuple[int, int, str, str | None], tuple[Any, Catalog, VerdictTrace, int]] = {}


def _traced(policy: Any, catalog: Catalog, key: tuple[str, str | None], world: World,
            goal: Cond | None) -> tuple[VerdictTrace, int]:
    """`simulate(policy, env, task, catalog, trace=True)` as the report shows it (`key` is
    `symbolic_key(env)` and the goal's text, `world` its initial world, `goal` the task's goal
    there), also the warm-up of the timed episode. An episode sees nothing but the symbolic world, so one already
    traced in this process (another generator's environment that realises the same situation
    with the same objects) is not run again: the warm-up it was is still warm."""
    memo = (id(policy), id(catalog), *key)
    hit = _TRACED.get(memo)
    if hit is not None and hit[0] is policy and hit[1] is catalog:
        return hit[2], hit[3]
    verdict = compiled(policy).run(world.copy(), goal, trace=True, final_state=False)
    trace = VerdictTrace(status=verdict.status, message=verdict.message or "",
                         trace=[str(t) for t in verdict.trace])
    if len(_TRACED) >= 4096:
        _TRACED.clear()
    _TRACED[memo] = (policy, catalog, trace, verdict.ticks)
    return trace, verdict.ticks


def with_killed_mutants(done: Evaluation, task: Task, scorer: MutationScorer,
                        catalog: Catalog) -> EnvSample:
    """The sample with the mutants its environment kills (`faudr_mut`), timed as `sim_ms.mutants`.

    Only valid environments (well-formed, correct BT passes) score mutants, and on the env as
    judged (roles bound), like the four policies."""
    sample = done.sample
    if not (sample.well_formed and not sample.violations
            and sample.verdicts.get("correct") == "passed"):
        return sample
    start = time.perf_counter()
    with phase("mutants"):
        killed = scorer.killed(done.env, task, catalog, initial=done.world, key=done.key)
    ms = (time.perf_counter() - start) * 1000.0
    return sample.model_copy(update={"killed_mutants": killed,
                                     "sim_ms": {**sample.sim_ms, "mutants": ms}})
