"""Simulated environment construction for one situation (paper §3.3).

Floor plan (LLM, asked per situation) → object selection (LLM; task objects realising the
situation + enrichment) → spatial relations (LLM) → compatibility checker with feedback and
bounded refinement → layout by the constraint solver with relaxation (or, for the no-CAS
ablation, coordinates from the LLM). That is the paper's method.

`reselect=True` (our variant, `logicenvgen-reselect`) adds two loops the paper does not have: a
rule check after object selection that re-asks until every situation fact holds, and a failed
layout re-asking the object selection with the solver's message, each bounded by
`max_refinements` (docs/fidelity.md gives their measured effect).
"""

from __future__ import annotations

from typing import Any

from logicenveval.envfiles import env_from_dict
from logicenveval.errors import EnvSpecError, TrajectoryError
from logicenveval.generators.base import GenerationContext
from logicenveval.generators.plan import PlanLog
from logicenveval.generators.settle import settle
from logicenveval.llm.ask import ask, protocol_of
from logicenveval.llm.meaning import present_roles
from logicenveval.llm.replies import (
    FloorPlanReply,
    FloorPlanWire,
    ObjectDraft,
    ObjectsReply,
    PlacementReply,
    RelationDraft,
    RelationsReply,
    RelationsWire,
    SelectionWire,
)
from logicenveval.llm.scene_words import selection_words
from logicenveval.llm.vocab import Words, scene_vocabulary
from logicenveval.model.conditions import STATE_FLAGS, evaluate, parse
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import Task, TaskBrief
from logicenveval.model.tree import evaluate_task


def placement_fields(placement: str) -> tuple[str | None, str | None]:
    """(support, container) of an object draft's placement string."""
    if placement.startswith("on:"):
        return placement[3:], None
    if placement.startswith("inside:"):
        return None, placement[7:]
    return (placement if placement in ("floor", "wall", "ceiling") else "floor"), None


def symbolic_env(brief: TaskBrief, env_id: str, generator: str, rooms: list[dict[str, Any]],
                 objects: list[ObjectDraft]) -> EnvSpec:
    """An EnvSpec without geometry, to check facts before any layout is computed."""
    ids = {o.id for o in objects}
    out = []
    for o in objects:
        support, container = placement_fields(o.placement)
        if support not in (None, "floor", "wall", "ceiling") and support not in ids:
            support = "floor"
        if container is not None and container not in ids:
            container, support = None, "floor"
        out.append({"id": o.id, "category": o.category, "room": o.room, "support": support,
                    "container": container, "attributes": dict(o.attributes), "states": dict(o.states)})
    return env_from_dict({
        "task_id": brief.id, "generator": generator, "env_id": env_id,
        "rooms": [{"id": r["id"], "type": r["type"]} for r in rooms],
        "objects": out,
        "roles": {o.role: o.id for o in objects if o.role in brief.roles},
        "agent": {"room": brief.rooms[0]},
    }, source=env_id)


def violated_facts(env: EnvSpec, facts: list[str], catalog: Any) -> list[str]:
    from logicenveval.sim.world import holds_initial

    holds = holds_initial(env, catalog)
    return [f for f in facts if not evaluate(parse(f), holds)]


class EnvironmentBuilder:
    def __init__(self, brief: TaskBrief, ctx: GenerationContext, *, generator: str,
                 use_solver: bool = True, max_refinements: int = 2, reselect: bool = False) -> None:
        self.brief = brief
        self.ctx = ctx
        self.generator = generator
        self.use_solver = use_solver
        self.max_refinements = max_refinements
        self.reselect = reselect
        self._first_plan: FloorPlanReply | None = None
        #: built environments that do not realise the trajectory they claim (`_check_claim`)
        self.unrealised: set[str] = set()

    @property
    def _reselecting(self) -> bool:
        """Whether failed selections and layouts re-select (`logicenvgen-reselect`, ours); request
        protocol 1 (packs recorded before issue 34) always did, and its replay asks the same."""
        return self.reselect or protocol_of(self.ctx.model) == 1

    def _payload(self, **extra: Any) -> dict[str, Any]:
        return {"task": self.brief.model_dump(mode="json"), **extra}

    def _vocabulary(self, rooms: list[str], object_ids: list[str] | None = None) -> dict[str, Words]:
        categories = [*self.ctx.catalog.generator_categories(), *(r.category for r in self.brief.roles.values())]
        return scene_vocabulary(rooms, sorted(self.brief.roles), categories, object_ids)

    def _plan_for(self, facts: list[str]) -> FloorPlanReply:
        """The floor plan of one situation, asked per situation as the paper's §3.3 does; under
        request protocol 1 (packs recorded before issue 34) the first situation's plan serves
        every situation of the task, as those packs asked it."""
        if protocol_of(self.ctx.model) > 1:
            return self.floor_plan(facts)
        if self._first_plan is None:
            self._first_plan = self.floor_plan(facts)
        return self._first_plan

    def floor_plan(self, facts: list[str]) -> FloorPlanReply:
        return ask(self.ctx.model, "floor_plan", self._payload(situation=facts), FloorPlanWire,
                   seed=self.ctx.seed, vocabulary=self._vocabulary(list(self.brief.rooms))).draft()

    def select_objects(self, env_id: str, rooms: list[dict[str, Any]], facts: list[str],
                       log: PlanLog, feedback: list[str] | None = None) -> list[ObjectDraft]:
        categories = self.ctx.catalog.generator_categories()
        feedback = list(feedback or [])
        for attempt in range(self.max_refinements + 1 if self._reselecting else 1):
            payload = self._payload(rooms=rooms, facts=facts, categories=categories, feedback=feedback)
            required = present_roles(sorted(self.brief.roles), facts)
            vocabulary = {**self._vocabulary([r["id"] for r in rooms]), "required_roles": required}
            if protocol_of(self.ctx.model) >= 5:  # states keyed by the flags only (`SOME_KEYS`)
                vocabulary["state_flags"] = list(STATE_FLAGS)
            if protocol_of(self.ctx.model) >= 3:
                vocabulary.update(selection_words(self.brief, required, self.ctx.catalog))
                # quoted back, Qwen2.5-Coder-1.5B wrote its invalid selection again (2 of 2)
                reply = ask(self.ctx.model, "select_objects", payload, SelectionWire, seed=self.ctx.seed,
                            vocabulary=vocabulary, quote=False).draft()
            else:
                reply = ask(self.ctx.model, "select_objects", payload, ObjectsReply, seed=self.ctx.seed,
                            vocabulary=vocabulary)
            objects = self._known_categories(reply.objects, log, env_id)
            sym = symbolic_env(self.brief, env_id, self.generator, rooms, objects)
            feedback = [f"the situation requires {f}, which does not hold" for f in
                        violated_facts(sym, facts, self.ctx.catalog)]
            if not feedback:
                return objects
            if not self._reselecting:
                log.add("select_objects", "situation facts not realised", env_id=env_id, problems=feedback)
                return objects
            log.add("select_objects", "refine", env_id=env_id, attempt=attempt, problems=feedback)
        raise TrajectoryError(
            f"{env_id}: the selected objects do not realise the situation: {'; '.join(feedback)}",
            hint="the trajectory may be unsatisfiable, or the model cannot place the task objects")

    def _known_categories(self, objects: list[ObjectDraft], log: PlanLog, env_id: str) -> list[ObjectDraft]:
        from logicenveval.scene.objects import resolve_category

        out = []
        for o in objects:
            category, warning = resolve_category(o.category, self.ctx.catalog)
            if warning:
                log.add("select_objects", warning, env_id=env_id)
            out.append(o if category == o.category else o.model_copy(update={"category": category}))
        return out

    def relations(self, env_id: str, objects: list[ObjectDraft], log: PlanLog) -> list[RelationDraft]:
        from logicenveval.scene.compat import check_relations

        payload_objects = [o.model_dump() for o in objects]
        vocab = self._vocabulary(sorted({o.room for o in objects}), [o.id for o in objects])
        keyed = protocol_of(self.ctx.model) >= 3
        if keyed:  # at most one relation per object: a looping reply ends
            vocab["relation_slots"] = [o.id for o in objects]

        def asked(kind: str, payload: dict[str, Any]) -> tuple[list[RelationDraft], list[tuple[dict[str, Any], str]]]:
            if keyed:
                return ask(self.ctx.model, kind, payload, RelationsWire, seed=self.ctx.seed, vocabulary=vocab).split()
            return list(ask(self.ctx.model, kind, payload, RelationsReply, seed=self.ctx.seed,
                            vocabulary=vocab).relations), []

        relations, malformed = asked("spatial_relations", self._payload(objects=payload_objects, feedback=[]))
        for attempt in range(self.max_refinements):
            problems = check_relations(objects, relations, self.ctx.catalog)
            if not problems and not malformed:
                return relations
            reasons = [p.reason for p in problems] + [why for _, why in malformed]
            log.add("spatial_relations", "refine", env_id=env_id, attempt=attempt, problems=reasons)
            relations, malformed = asked("refine_relations", self._payload(
                objects=payload_objects, feedback=reasons,
                rejected=[r.model_dump() for p in problems for r in p.relations] + [r for r, _ in malformed]))
        remaining = check_relations(objects, relations, self.ctx.catalog)
        if remaining or malformed:
            bad = {id(r) for p in remaining for r in p.relations}
            log.add("spatial_relations", "dropped relations the checker still rejects", env_id=env_id,
                    problems=[p.reason for p in remaining] + [why for _, why in malformed])
            relations = [r for r in relations if id(r) not in bad]
        return relations

    def build(self, env_id: str, facts: list[str], claim: dict[str, dict[str, str]] | None,
              plan_task: Task | None, log: PlanLog) -> EnvSpec:
        rooms = [r.model_dump() for r in self._plan_for(facts).rooms]
        feedback: list[str] = []
        for attempt in range(self.max_refinements + 1 if self._reselecting else 1):
            objects = self.select_objects(env_id, rooms, facts, log, feedback)
            relations = self.relations(env_id, objects, log)
            objects, relations = self._settled(env_id, rooms, facts, objects, relations, log)
            try:
                if self.use_solver:
                    env = self._solve(env_id, rooms, objects, relations, claim, log)
                else:
                    env = self._llm_placement(env_id, rooms, objects, relations, claim)
                break
            except EnvSpecError as exc:  # the layout cannot realise this selection: say why
                feedback = [*feedback, exc.message]
                log.add("layout", "refine the object selection", env_id=env_id, attempt=attempt,
                        problems=[exc.message])
        else:
            raise TrajectoryError(f"{env_id}: no layout for the selected objects: {'; '.join(feedback)}",
                                  hint="the situation needs objects that do not fit where they must be")
        if plan_task is not None and claim is not None:
            self._check_claim(env, plan_task, claim, log)
        return env

    def _settled(self, env_id: str, rooms: list[dict[str, Any]], facts: list[str], objects: list[ObjectDraft],
                 relations: list[RelationDraft], log: PlanLog) -> tuple[list[ObjectDraft], list[RelationDraft]]:
        """The arrangement follows the situation's constraints (§3.3: "object placements align
        with task-specific requirements and trajectory constraints"): what a fact the selection
        left false says of one object is set (`generators.settle`), and a relation placing such
        an object elsewhere gives way to it, as the solver's relaxation gives task constraints
        priority. Done after the relations are asked, so the requests are those the selection
        makes (recorded replies replay)."""
        sym = symbolic_env(self.brief, env_id, self.generator, rooms, objects)
        settled = settle(objects, violated_facts(sym, facts, self.ctx.catalog))
        if not settled.set:
            return objects, relations
        before = {o.id: o.placement for o in objects}
        after = {o.id: o.placement for o in settled.objects}
        moved = {oid for oid, placement in before.items() if after.get(oid) != placement}
        kept = [r for r in relations if all(a in after for a in r.args)
                and not (r.type in ("on", "inside") and r.args[0] in moved)]
        log.add("construct", "situation facts set by construction", env_id=env_id, facts=settled.set,
                **({"dropped_relations": [f"{r.type}({', '.join(r.args)})" for r in relations if r not in kept]}
                   if len(kept) < len(relations) else {}))
        return settled.objects, kept

    def _check_claim(self, env: EnvSpec, plan_task: Task, claim: dict[str, dict[str, str]],
                     log: PlanLog) -> None:
        """The environment must reach, in the generator's own trees, the leaves it claims
        (`unrealised`: the environments that do not, for `Attempt.realised`)."""
        from logicenveval.sim.world import holds_initial

        reached = {o.subtask: (o.path.assignment() if o.path else None)
                   for o in evaluate_task(plan_task, holds_initial(env, self.ctx.catalog))}
        wrong = [s for s, a in claim.items() if reached.get(s) != a]
        if wrong:
            self.unrealised.add(env.env_id)
            log.add("construct", f"{env.env_id} does not realise its trajectory in subtasks {wrong}",
                    env_id=env.env_id, failure=True)

    def _solve(self, env_id: str, rooms: list[dict[str, Any]], objects: list[ObjectDraft],
               relations: list[RelationDraft], claim: dict[str, dict[str, str]] | None,
               log: PlanLog) -> EnvSpec:
        from logicenveval.scene.construct import construct_from_drafts

        result = construct_from_drafts(
            brief=self.brief, env_id=env_id, generator=self.generator, rooms=rooms, objects=objects,
            relations=relations, claimed_trajectory=claim, catalog=self.ctx.catalog, rng=self.ctx.rng,
            solver=self.ctx.layout_solver)
        for entry in result.relaxation_log:
            log.add("layout", str(entry), env_id=env_id)
        return result.env

    def _llm_placement(self, env_id: str, rooms: list[dict[str, Any]], objects: list[ObjectDraft],
                       relations: list[RelationDraft], claim: dict[str, dict[str, str]] | None) -> EnvSpec:
        """No CAS: the model places the objects, and the doors and windows on the wall stretches
        of the floor plan (their positions are the solver's variables otherwise, paper §3.3)."""
        import numpy as np

        from logicenveval.scene.construct import env_from_placed, room_requests
        from logicenveval.scene.floorplan import plan_floor

        plan = plan_floor(room_requests(rooms), np.random.default_rng(int(self.ctx.rng.integers(2**31))))
        reply = ask(self.ctx.model, "place_objects", self._payload(
            rooms=[r.model_dump(mode="json") for r in plan.rooms], openings=plan.opening_requests(),
            objects=[o.model_dump() for o in objects], relations=[r.model_dump() for r in relations]),
            PlacementReply, seed=self.ctx.seed,
            vocabulary=self._vocabulary([r["id"] for r in rooms], [o.id for o in objects]))
        return env_from_placed(brief=self.brief, env_id=env_id, generator=self.generator, plan=plan,
                               placed=reply.objects, relations=reply.relations or relations,
                               openings={o.id: o.segment for o in reply.openings}, claimed_trajectory=claim,
                               catalog=self.ctx.catalog)
