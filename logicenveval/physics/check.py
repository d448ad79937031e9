"""`check_env`: the PhyPR checker, independent of any generator or layout solver."""

from __future__ import annotations

from pathlib import Path

from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.errors import EnvSpecError
from logicenveval.model.envspec import EnvSpec
from logicenveval.physics.entity import check_entities
from logicenveval.physics.floorplan import check_floor_plan
from logicenveval.physics.geometry import build_bodies
from logicenveval.physics.relations import check_relations
from logicenveval.physics.report import (
    DEFAULT_TOLERANCES,
    EXTENDED_CODES,
    DimensionReport,
    PhysicsFailure,
    PhysicsReport,
    Tolerances,
)


def check_env(env: EnvSpec, catalog: Catalog | None = None, *, tolerances: Tolerances = DEFAULT_TOLERANCES,
              mesh_dir: str | Path | None = None, broad_phase: bool = True) -> PhysicsReport:
    """Judge an environment on the floor-plan, entity and relation dimensions (paper Table 2).

    Failures of the extra plausibility checks (`EXTENDED_CODES`) go to `report.extended`.

    `catalog` defaults to the benchmark catalog; `mesh_dir` resolves relative `mesh` paths;
    `broad_phase=False` checks every object pair with fcl (the baseline of the benchmark).
    """
    if not isinstance(env, EnvSpec):
        raise EnvSpecError(f"check_env needs an EnvSpec, got {type(env).__name__}", field="env",
                           hint="load the file with logicenveval.envfiles.load_env or env_from_dict")
    cat = catalog if catalog is not None else load_catalog()
    plan, polys = check_floor_plan(env, tolerances)
    base = Path(mesh_dir) if mesh_dir is not None else None
    bodies = build_bodies(env, base)
    entity = check_entities(env, bodies, polys, cat, tolerances, broad_phase=broad_phase, mesh_dir=base)
    relation = check_relations(env, bodies, polys, tolerances)
    extended = [f for f in (*plan, *entity, *relation) if f.code in EXTENDED_CODES]
    return PhysicsReport(floor_plan=DimensionReport.of(_paper(plan)),
                         entity=DimensionReport.of(_paper(entity)),
                         relation=DimensionReport.of(_paper(relation)),
                         extended=DimensionReport.of(extended))


def _paper(failures: list[PhysicsFailure]) -> list[PhysicsFailure]:
    return [f for f in failures if f.code not in EXTENDED_CODES]
