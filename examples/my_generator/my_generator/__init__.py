"""An example environment generator for LogicEnvEval, built on the public scene API.

It reads only the task brief (rooms and roles), places every role object in a room that suits
its category, and draws the roles' attributes and states from the catalog with the run's random
generator, one scene per environment. It asks no LLM, so it is a *random-variation* generator:
a useful floor to compare a real method against. docs/own-generator.md walks through it.
"""

from __future__ import annotations

from logicenveval.errors import LogicEnvEvalError
from logicenveval.generators.base import GenerationContext, GenerationFailure, GenerationResult
from logicenveval.model.rooms import room_type_of
from logicenveval.model.task import TaskBrief
from logicenveval.scene.construct import construct_environment
from logicenveval.scene.spec import ObjectRequest, RoomRequest, SceneSpec

__all__ = ["MyGenerator"]


class MyGenerator:
    """`n_envs` scenes per task that differ in the roles' attributes and states."""

    def __init__(self, *, name: str = "my-generator", n_envs: int = 3) -> None:
        self.name = name
        self.n_envs = n_envs

    def generate(self, brief: TaskBrief, ctx: GenerationContext) -> GenerationResult:
        envs, failures = [], []
        for i in range(self.n_envs):
            env_id = f"{self.name}-{i:02d}"
            try:
                scene = construct_environment(self._scene(brief, ctx, env_id), catalog=ctx.catalog,
                                              rng=ctx.rng, solver=ctx.layout_solver)
            except LogicEnvEvalError as exc:  # e.g. a room too small: recorded, not raised
                failures.append(GenerationFailure(stage="layout", message=str(exc), env_id=env_id))
                continue
            envs.append(scene.env)
        return GenerationResult(envs=envs, failures=failures)

    def _scene(self, brief: TaskBrief, ctx: GenerationContext, env_id: str) -> SceneSpec:
        rooms = [RoomRequest(id=r, type=room_type_of(r), area=16.0,
                             adjacent_to=brief.rooms[:1] if k else [],
                             doors=[] if k else [{"to": "exterior"}])
                 for k, r in enumerate(brief.rooms)]
        objects: list[ObjectRequest] = []
        surfaces: dict[str, str] = {}  # room -> a floor-standing surface object to put things on
        # floor/wall objects first, so that small objects find a surface in their room
        order = sorted(brief.roles.items(), key=lambda kv: self._placement(kv[1].category, ctx) != "floor")
        for role, spec in order:
            cat = ctx.catalog.get(spec.category)
            if cat is None:
                continue
            room = next((r for r in brief.rooms if room_type_of(r) in cat.rooms), brief.rooms[0])
            placement = self._placement(spec.category, ctx)
            if placement == "surface":
                if room not in surfaces:
                    continue  # nowhere to put it: the role stays unbound in this scene
                placement = f"on:{surfaces[room]}"
            attributes = {k: str(ctx.rng.choice(v)) for k, v in cat.attributes.items()}
            attributes.update(spec.attributes)  # what the task fixes is not varied
            states = {k: bool(ctx.rng.random() < 0.5) for k in cat.default_states}
            objects.append(ObjectRequest(id=role, category=spec.category, room=room, role=role,
                                         placement=placement, attributes=attributes, states=states))
            if cat.surface and placement == "floor":
                surfaces.setdefault(room, role)
        return SceneSpec(task_id=brief.id, env_id=env_id, generator=self.name, rooms=rooms,
                         objects=objects)

    @staticmethod
    def _placement(category: str, ctx: GenerationContext) -> str:
        cat = ctx.catalog.get(category)
        kinds = cat.placement if cat is not None else ["floor"]
        return next((k for k in ("floor", "wall", "surface") if k in kinds), "floor")
