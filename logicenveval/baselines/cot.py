"""CoT baseline: one chain-of-thought request designs several environments, instantiated as given.

The model reasons about the situations the task may present and writes every environment as
JSON: its floor plan (room polygons, door and window segments) and its objects (coordinates,
attributes, states). There is no solver and no repair beyond schema validation: physical
mistakes, the floor plan's included, are part of what the benchmark measures.
"""

from __future__ import annotations

from logicenveval.baselines.drafts import env_from_draft
from logicenveval.baselines.replies import (
    WrittenEnvironmentsReply,
    dropped_relations,
    written_vocabulary,
)
from logicenveval.errors import ConfigError, LogicEnvEvalError
from logicenveval.generators.base import (
    Attempt,
    GenerationContext,
    GenerationFailure,
    GenerationResult,
)
from logicenveval.llm.ask import ask, protocol_of
from logicenveval.model.task import TaskBrief


class CoT:
    """Registered as `cot`; `max_environments` bounds how many environments the model may write."""

    def __init__(self, *, name: str = "cot", max_environments: int = 12) -> None:
        if max_environments < 1:
            raise ConfigError(f"max_environments must be at least 1, got {max_environments}",
                              field="cot.max_environments", hint="pass a positive number of environments")
        self.name = name
        self.max_environments = max_environments

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        """One attempt per draft the model wrote; a reply that never validates fails all
        `max_environments` drafts it could have written, so failing never beats answering. A
        draft that repeats an earlier one (its situation aside) is a failed attempt named as a
        copy: the method was asked for distinct environments, and copies would count as
        coverage-neutral environments that raise PhyPR and SceVR for free."""
        categories = ctx.catalog.generator_categories()
        payload = {"task": brief.model_dump(mode="json"), "n_environments": self.max_environments,
                   "categories": categories}
        ids = [f"{self.name}-{i:02d}" for i in range(self.max_environments)]
        ctx.plan_attempts(self.max_environments)
        try:
            reply = ask(ctx.model, "cot_environments", payload, WrittenEnvironmentsReply, seed=ctx.seed,
                        vocabulary=written_vocabulary(brief, self.max_environments, categories,
                                                      protocol_of(ctx.model)))
        except LogicEnvEvalError as exc:
            return GenerationResult(
                failures=[GenerationFailure(stage="cot_environments", message=str(exc))],
                attempts=[Attempt(id=i, stage="cot_environments", reason=str(exc)) for i in ids])
        drafts = reply.environments[: self.max_environments]
        ctx.plan_attempts(len(drafts))
        envs = []
        failures = []
        attempts = []
        written: dict[str, str] = {}  # a draft's content (its situation aside) -> the first env id
        for env_id, draft in zip(ids, drafts, strict=False):
            content = draft.model_dump_json(exclude={"situation"})
            if content in written:  # Qwen2.5-Coder-1.5B copied one environment 12 times
                why = f"a copy of {written[content]}: the same rooms, objects and relations written again"
                failures.append(GenerationFailure(stage="distinct", message=why, env_id=env_id))
                attempts.append(Attempt(id=env_id, target=draft.situation, stage="distinct", reason=why))
                continue
            written[content] = env_id
            try:
                envs.append(env_from_draft(brief, env_id=env_id, generator=self.name, draft=draft,
                                           extra={"situation": draft.situation}))
            except LogicEnvEvalError as exc:
                failures.append(GenerationFailure(stage="instantiate", message=str(exc), env_id=env_id))
                attempts.append(Attempt(id=env_id, target=draft.situation, stage="instantiate", reason=str(exc)))
                continue
            attempts.append(Attempt(id=env_id, target=draft.situation, env_id=env_id))
        return GenerationResult(envs=envs, failures=failures, attempts=attempts, artifacts={
            "reasoning": reply.reasoning, "situations": [d.situation for d in reply.environments],
            **dropped_relations(zip(ids, drafts, strict=False))})
