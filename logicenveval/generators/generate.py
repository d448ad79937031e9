"""Running one generator on one task outside a benchmark run (`python -m logicenveval generate`)."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from logicenveval.atomic import atomic_write_text
from logicenveval.benchmark import load_task
from logicenveval.domain.catalog import load_catalog
from logicenveval.envfiles import save_env
from logicenveval.generators.base import (
    GenerationContext,
    GenerationResult,
    make_generator,
    unit_seed,
)
from logicenveval.generators.plugins import resolve_generator
from logicenveval.paths import name_problem, shown
from logicenveval.scene.layout import DEFAULT_SOLVER, Solver


@dataclass
class GenerateSummary:
    out: Path
    result: GenerationResult
    written: list[Path] = field(default_factory=list)
    skipped: list[str] = field(default_factory=list)

    def lines(self) -> list[str]:
        out = [f"{len(self.result.envs)} environment(s) written to {self.out}"]
        out += [f"  {p.name}" for p in self.written]
        out += [f"[red]failure[/red] {f.stage}: {f.message}" for f in self.result.failures]
        out += [f"[red]skipped[/red] {why}" for why in self.skipped]
        return out


def generate_to_folder(
    *,
    generator: str,
    task_id: str,
    model: str,
    model_args: str,
    tasks_dir: str | None,
    seed: int,
    out: Path,
    cache: str | None = None,
    render: bool = True,
    layout_solver: Solver = DEFAULT_SOLVER,
    generator_args: dict[str, Any] | None = None,
) -> GenerateSummary:
    """Generate with the same seeding as a run's unit, so results match `run` exactly.

    The files go to `out/<task_id>/` (environments, renders, plan.json): the layout `evaluate`
    scores, one folder per task; the generator's scratch space is `out/.work/<task_id>/`."""
    from logicenveval.llm.registry import make_model

    task = load_task(task_id, tasks_dir)
    catalog = load_catalog()
    chat = make_model(model, model_args, cache_path=cache or out / "llm_cache.sqlite", run_dir=out)
    ref = resolve_generator(generator, generator_args)
    gen = make_generator(ref.target, **ref.args)
    ctx = GenerationContext(model=chat, catalog=catalog,
                            rng=np.random.default_rng(unit_seed(seed, ref.name, task_id)),
                            seed=seed, work_dir=out / ".work" / task.id, layout_solver=layout_solver)
    result = gen.generate(task.brief(), ctx)
    out = out / task.id
    summary = GenerateSummary(out=out, result=result)
    out.mkdir(parents=True, exist_ok=True)
    for env in result.envs:
        if name_problem(env.env_id) is not None:  # never a file outside `out` (logicenveval.paths)
            summary.skipped.append(f"env_id {shown(env.env_id)} {name_problem(env.env_id)}: not written")
            continue
        path = out / f"{env.env_id}.json"
        save_env(env, path)
        summary.written.append(path)
        if render:
            from logicenveval.physics import check_env
            from logicenveval.physics.render import render_svg

            atomic_write_text(out / f"{env.env_id}.svg", render_svg(env, check_env(env, catalog)))
    plan = {**result.artifacts, "failures": [f.model_dump(mode="json") for f in result.failures]}
    atomic_write_text(out / "plan.json", json.dumps(plan, indent=2, sort_keys=True, default=str) + "\n")
    return summary
