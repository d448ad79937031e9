"""LogicEnvGen (paper §3): behaviour plans → logical trajectories → one environment each.

`logicenvgen` is the paper's method, with MTSA (Algorithm 1) selecting the trajectories;
`logicenvgen-exact` swaps in our polynomial exact minimum cover (beyond the paper). Ablations and
comparisons (paper §5.3) are the same class with one part switched off or swapped:
`logicenvgen-no-dbp` (trajectories straight from the description, no decision trees),
`logicenvgen-no-mtsa` (the whole Cartesian product), `logicenvgen-exhaustive` (the paper's
exponential minimum-set-cover search), `logicenvgen-no-cas` (the LLM places objects itself, no
constraint solver). `logicenvgen-reselect` is ours: the full method plus two re-selection loops
the paper does not have (`generators/construction.py`).
"""

from __future__ import annotations

from typing import Any

from logicenveval.errors import LogicEnvEvalError
from logicenveval.generators.base import (
    Attempt,
    GenerationContext,
    GenerationFailure,
    GenerationResult,
)
from logicenveval.generators.construction import EnvironmentBuilder
from logicenveval.generators.plan import DerivedPlan, PlanLog, derive_plan, plan_vocabulary
from logicenveval.llm.ask import ask
from logicenveval.llm.replies import TrajectoriesWire
from logicenveval.llm.structured import literal_text
from logicenveval.logic.exhaustive import MAX_SUBSETS, exhaustive_cover
from logicenveval.logic.selectors import get_selector
from logicenveval.model.task import TaskBrief
from logicenveval.model.tree import Trajectory, task_paths


class LogicEnvGen:
    """The full method; keyword options select the ablations."""

    def __init__(self, *, selector: str = "mtsa", use_trees: bool = True, use_solver: bool = True,
                 name: str = "logicenvgen", max_refinements: int = 2,
                 max_subsets: int = MAX_SUBSETS, reselect: bool = False) -> None:
        self.name = name
        self.reselect = reselect
        self.selector = selector
        self.use_trees = use_trees
        self.use_solver = use_solver
        self.max_refinements = max_refinements
        #: budget of the exhaustive search in subsets tested (deterministic, unlike seconds)
        self.max_subsets = max_subsets

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        """One attempt per selected trajectory (no-DBP: per trajectory the model wrote)."""
        failures: list[GenerationFailure] = []
        budget_hit: str | None = None
        if self.use_trees:
            plan = derive_plan(brief, ctx, max_refinements=self.max_refinements)
            artifacts: dict[str, Any] = {**plan.as_json(), "selector": self.selector}
            trajectories, budget_hit = self._select(plan, artifacts)
            situations = [_facts(plan, t) for t in trajectories]
            claims: list[dict[str, dict[str, str]] | None] = [t.as_claim() for t in trajectories]
            targets = [t.key for t in trajectories]
            artifacts["trajectories"] = targets
        else:
            reply = ask(ctx.model, "trajectories_direct", {"task": brief.model_dump(mode="json")},
                        TrajectoriesWire, seed=ctx.seed, vocabulary=plan_vocabulary(brief))
            situations = [[literal_text(f) for f in t.facts] for t in reply.trajectories]
            claims = [None] * len(situations)
            targets = [" & ".join(facts) for facts in situations]
            plan = None
            artifacts = {"trajectories": [{"description": t.description, "facts": facts}
                                          for t, facts in zip(reply.trajectories, situations, strict=True)],
                         "log": []}
        ctx.plan_attempts(len(situations))
        builder = EnvironmentBuilder(brief, ctx, generator=self.name, use_solver=self.use_solver,
                                     max_refinements=self.max_refinements, reselect=self.reselect)
        envs = []
        attempts = []
        log = PlanLog()
        for i, facts in enumerate(situations):
            env_id = f"{self.name}-{i:02d}"
            try:
                env = builder.build(env_id, facts, claims[i], plan.task if plan else None, log)
            except LogicEnvEvalError as exc:
                failures.append(GenerationFailure(stage="construct", message=str(exc), env_id=env_id))
                attempts.append(Attempt(id=env_id, target=targets[i], stage="construct", reason=str(exc)))
                continue
            envs.append(env)
            attempts.append(Attempt(id=env_id, target=targets[i], env_id=env.env_id,
                                    realised=None if claims[i] is None else env.env_id not in builder.unrealised))
        artifacts["construction_log"] = log.events
        failures += [GenerationFailure(stage=e["stage"], message=e["message"], env_id=e.get("env_id"))
                     for e in log.events if e.get("failure")]
        return GenerationResult(envs=envs, artifacts=artifacts, failures=failures, attempts=attempts,
                                budget_hit=budget_hit)

    def _select(self, plan: DerivedPlan, artifacts: dict[str, Any]) -> tuple[list[Trajectory], str | None]:
        """The trajectories, and a note when the exhaustive search stopped at its budget."""
        if self.selector != "exhaustive":
            return get_selector(self.selector).select(task_paths(plan.task)), None
        result = exhaustive_cover(task_paths(plan.task), max_subsets=self.max_subsets)
        artifacts["exhaustive"] = {"optimal": result.optimal, "subsets_tested": result.tested,
                                   "max_subsets": self.max_subsets}
        if result.optimal:
            return list(result.trajectories), None
        note = (f"the exhaustive search stopped at its budget of {self.max_subsets:,} subsets "
                f"({result.tested:,} tested, no cover of fewer trajectories found); MTSA's cover used")
        artifacts["exhaustive"]["note"] = note
        return list(result.trajectories), note


def _facts(plan: DerivedPlan, trajectory: Trajectory) -> list[str]:
    return [plan.task.variables[v].values[x] for path in trajectory.paths for v, x in path.steps]


def exact(**options: Any) -> LogicEnvGen:
    return LogicEnvGen(**{"selector": "exact", "name": "logicenvgen-exact", **options})


def no_dbp(**options: Any) -> LogicEnvGen:
    return LogicEnvGen(**{"use_trees": False, "name": "logicenvgen-no-dbp", **options})


def no_mtsa(**options: Any) -> LogicEnvGen:
    return LogicEnvGen(**{"selector": "product", "name": "logicenvgen-no-mtsa", **options})


def exhaustive(max_subsets: int = MAX_SUBSETS) -> LogicEnvGen:
    return LogicEnvGen(selector="exhaustive", name="logicenvgen-exhaustive", max_subsets=max_subsets)


def reselect(**options: Any) -> LogicEnvGen:
    return LogicEnvGen(**{"reselect": True, "name": "logicenvgen-reselect", **options})


def no_cas(**options: Any) -> LogicEnvGen:
    return LogicEnvGen(**{"use_solver": False, "name": "logicenvgen-no-cas", **options})
