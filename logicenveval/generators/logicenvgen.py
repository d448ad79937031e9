"""LogicEnvGen (paper §3): behaviour plans → logical trajectories → one environment each.

`logicenvgen` is the paper's method, with MTSA (Algorithm 1) selecting the trajectories;
`logicenvgen-exact` swaps in our polynomial exact minimum cover (beyond the paper). Ablations and
comparisons (paper §5.3) are the same class with one part switched off or swapped:
`logicenvgen-no-dbp` (trajectories straight from the description, no decision trees),
`logicenvgen-no-mtsa` (the whole Cartesian product), `logicenvgen-exhaustive` (the paper's
exponential minimum-set-cover search), `logicenvgen-no-cas` (the LLM places objects itself, no
constraint solver).
"""

from __future__ import annotations

from typing import Any

from logicenveval.errors import LogicEnvEvalError
from logicenveval.generators.base import GenerationContext, GenerationFailure, GenerationResult
from logicenveval.generators.construction import EnvironmentBuilder
from logicenveval.generators.plan import DerivedPlan, PlanLog, derive_plan, plan_vocabulary
from logicenveval.llm.ask import ask
from logicenveval.llm.replies import TrajectoriesWire
from logicenveval.llm.structured import literal_text
from logicenveval.logic.exhaustive import exhaustive_cover
from logicenveval.logic.selectors import get_selector
from logicenveval.model.task import TaskBrief
from logicenveval.model.tree import Trajectory, task_paths


class LogicEnvGen:
    """The full method; keyword options select the ablations."""

    def __init__(self, *, selector: str = "mtsa", use_trees: bool = True, use_solver: bool = True,
                 name: str = "logicenvgen", max_refinements: int = 2) -> None:
        self.name = name
        self.selector = selector
        self.use_trees = use_trees
        self.use_solver = use_solver
        self.max_refinements = max_refinements

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        failures: list[GenerationFailure] = []
        if self.use_trees:
            plan = derive_plan(brief, ctx, max_refinements=self.max_refinements)
            artifacts: dict[str, Any] = {**plan.as_json(), "selector": self.selector}
            trajectories = self._select(plan, artifacts)
            situations = [_facts(plan, t) for t in trajectories]
            claims: list[dict[str, dict[str, str]] | None] = [t.as_claim() for t in trajectories]
            artifacts["trajectories"] = [t.key for t in trajectories]
        else:
            reply = ask(ctx.model, "trajectories_direct", {"task": brief.model_dump(mode="json")},
                        TrajectoriesWire, seed=ctx.seed, vocabulary=plan_vocabulary(brief))
            situations = [[literal_text(f) for f in t.facts] for t in reply.trajectories]
            claims = [None] * len(situations)
            plan = None
            artifacts = {"trajectories": [{"description": t.description, "facts": facts}
                                          for t, facts in zip(reply.trajectories, situations, strict=True)],
                         "log": []}
        builder = EnvironmentBuilder(brief, ctx, generator=self.name, use_solver=self.use_solver,
                                     max_refinements=self.max_refinements)
        envs = []
        log = PlanLog()
        for i, facts in enumerate(situations):
            env_id = f"{self.name}-{i:02d}"
            try:
                env = builder.build(env_id, facts, claims[i], plan.task if plan else None, log)
            except LogicEnvEvalError as exc:
                failures.append(GenerationFailure(stage="construct", message=str(exc), env_id=env_id))
                continue
            envs.append(env)
        artifacts["construction_log"] = log.events
        failures += [GenerationFailure(stage=e["stage"], message=e["message"], env_id=e.get("env_id"))
                     for e in log.events if e.get("failure")]
        return GenerationResult(envs=envs, artifacts=artifacts, failures=failures)


    def _select(self, plan: DerivedPlan, artifacts: dict[str, Any]) -> list[Trajectory]:
        if self.selector != "exhaustive":
            return get_selector(self.selector).select(task_paths(plan.task))
        result = exhaustive_cover(task_paths(plan.task))
        artifacts["exhaustive"] = {"optimal": result.optimal, "subsets_tested": result.tested}
        if not result.optimal:
            artifacts["exhaustive"]["note"] = "search budget exhausted; MTSA's cover used"
        return list(result.trajectories)


def _facts(plan: DerivedPlan, trajectory: Trajectory) -> list[str]:
    return [plan.task.variables[v].values[x] for path in trajectory.paths for v, x in path.steps]


def exact() -> LogicEnvGen:
    return LogicEnvGen(selector="exact", name="logicenvgen-exact")


def no_dbp() -> LogicEnvGen:
    return LogicEnvGen(use_trees=False, name="logicenvgen-no-dbp")


def no_mtsa() -> LogicEnvGen:
    return LogicEnvGen(selector="product", name="logicenvgen-no-mtsa")


def exhaustive() -> LogicEnvGen:
    return LogicEnvGen(selector="exhaustive", name="logicenvgen-exhaustive")


def no_cas() -> LogicEnvGen:
    return LogicEnvGen(use_solver=False, name="logicenvgen-no-cas")
