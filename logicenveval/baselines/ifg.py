"""IFG baseline (intent-first generation, Ahmed et al. 2025): sample intents, then realise each.

Stage 1 (`ifg_intents`, temperature 1.1) samples k intents — logical trajectories written as
the facts that hold initially; stage 2 (`ifg_environment`, temperature 0.5) designs one
environment per intent, floor plan and coordinates written by the model (no solver). Duplicate intents are kept:
IFG's redundancy is part of what the benchmark measures. Seeds of both stages are drawn from the
run's generator, so a run is reproducible and different runs sample differently.
"""

from __future__ import annotations

import dataclasses

from logicenveval.baselines.drafts import env_from_draft
from logicenveval.baselines.replies import (
    IntentWire,
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
from logicenveval.generators.plan import plan_vocabulary
from logicenveval.llm.ask import ask, protocol_of
from logicenveval.llm.replies import TrajectoriesReply
from logicenveval.model.task import TaskBrief

#: intents per task: the paper does not state k; 8 exceeds the minimum cover of most benchmark
#: tasks, as IFG samples more intents than it needs (its redundancy is measured).
DEFAULT_K = 8


class IFG:
    """Registered as `ifg`."""

    def __init__(self, *, name: str = "ifg", k: int = DEFAULT_K, intent_temperature: float = 1.1,
                 env_temperature: float = 0.5) -> None:
        if k < 1:
            raise ConfigError(f"k must be at least 1, got {k}", field="ifg.k", hint="pass a positive intent count")
        if min(intent_temperature, env_temperature) < 0:
            raise ConfigError("temperatures must be >= 0", field="ifg.intent_temperature/env_temperature",
                              hint="the paper uses 1.1 for intents and 0.5 for environments")
        self.name = name
        self.k = k
        self.intent_temperature = intent_temperature
        self.env_temperature = env_temperature

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        """One attempt per intent asked for (k): an intent the model did not give, or whose
        environment is invalid, is a failed attempt."""
        task = brief.model_dump(mode="json")
        seeds = [int(s) for s in ctx.rng.integers(0, 2**31 - 1, size=self.k + 1)]
        ids = [f"{self.name}-{i:02d}" for i in range(self.k)]
        ctx.plan_attempts(self.k)
        protocol = protocol_of(ctx.model)
        if protocol >= 5:
            # one request per intent, each with a seed of its own (drawn after the k + 1 above,
            # so the environments' seeds are those of earlier protocols)
            intent_seeds = [int(s) for s in ctx.rng.integers(0, 2**31 - 1, size=self.k)]
            intents, lost = self._sampled(brief, ctx, intent_seeds)
            seeds += intent_seeds
        else:
            try:
                intents = dict(enumerate(Intent(description=t.description, facts=list(t.facts)) for t in ask(
                    ctx.model, "ifg_intents", {"task": task, "k": self.k}, TrajectoriesReply,
                    temperature=self.intent_temperature, seed=seeds[0]).trajectories[: self.k]))
            except LogicEnvEvalError as exc:
                return GenerationResult(
                    failures=[GenerationFailure(stage="ifg_intents", message=str(exc))],
                    attempts=[Attempt(id=i, stage="ifg_intents", reason=str(exc)) for i in ids])
            missing = f"the intents reply gave {len(intents)} of the {self.k} intents asked for"
            lost = {i: missing for i in range(len(intents), self.k)}
        categories = ctx.catalog.generator_categories()
        # one environment per intent
        slots = written_vocabulary(brief, 1, categories, protocol)
        envs = []
        failures = []
        attempts = []
        written = []
        for i, intent in intents.items():
            env_id = ids[i]
            target = " & ".join(intent.facts)
            try:
                reply = ask(ctx.model, "ifg_environment", {"task": task, "intent": list(intent.facts),
                                                           "categories": categories},
                            WrittenEnvironmentsReply, temperature=self.env_temperature, seed=seeds[i + 1],
                            vocabulary=slots)
                draft = reply.environments[0]
                written.append((env_id, draft))
                envs.append(env_from_draft(brief, env_id=env_id, generator=self.name, draft=draft,
                                           extra={"intent": list(intent.facts), "situation": intent.description}))
            except LogicEnvEvalError as exc:
                failures.append(GenerationFailure(stage="ifg_environment", message=str(exc), env_id=env_id))
                attempts.append(Attempt(id=env_id, target=target, stage="ifg_environment", reason=str(exc)))
                continue
            attempts.append(Attempt(id=env_id, target=target, env_id=env_id))
        stage = "ifg_intent" if protocol >= 5 else "ifg_intents"
        attempts += [Attempt(id=ids[i], stage=stage, reason=why) for i, why in lost.items()]
        attempts.sort(key=lambda a: ids.index(a.id))
        if stage == "ifg_intent":  # each lost intent failed on its own request: said apiece
            failures += [GenerationFailure(stage=stage, message=why, env_id=ids[i]) for i, why in lost.items()]
        return GenerationResult(envs=envs, failures=failures, attempts=attempts, artifacts={
            "k": self.k, "seeds": seeds, "intents": [dataclasses.asdict(t) for t in intents.values()],
            **dropped_relations(written)})

    def _sampled(self, brief: TaskBrief, ctx: GenerationContext,
                 seeds: list[int]) -> tuple[dict[int, Intent], dict[int, str]]:
        """The k intents, each asked on its own (protocol 5): i ~ M(p) at the intent
        temperature, so a reply that fails loses one intent, never the others."""
        task = brief.model_dump(mode="json")
        intents: dict[int, Intent] = {}
        lost: dict[int, str] = {}
        for i, seed in enumerate(seeds):
            try:
                reply = ask(ctx.model, "ifg_intent", {"task": task}, IntentWire,
                            temperature=self.intent_temperature, seed=seed, vocabulary=plan_vocabulary(brief))
            except LogicEnvEvalError as exc:
                lost[i] = str(exc)
                continue
            intents[i] = Intent(description=reply.description, facts=reply.texts())
        return intents, lost


@dataclasses.dataclass(frozen=True)
class Intent:
    """An intent as the environment request is given it: words and facts (condition language)."""

    description: str
    facts: list[str]
