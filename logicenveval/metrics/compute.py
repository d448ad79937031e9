"""Per-task metrics and their aggregation into the `results.<generator>` shape (DESIGN.md §7, §9).

Decisions where DESIGN.md is silent (docs/logic.md):
- coverage (LogCov, LD, JI) counts only well-formed environments: an ill-formed one realises no
  well-defined trajectory;
- PhyPR and SceVR divide by attempted environments (`n_attempted` = built `n_envs` + failed
  attempts `n_failed`): a failed attempt fails every PhyPR dimension and is no valid scenario,
  so failing never pays; LogCov, LD, JI and FauDR count only what was built;
- ST averages, over the BTs that were simulated, the per-BT sum of simulation ms over the task's
  environments (each episode timed after a warm-up run, `runner.evaluation`); `st_ticks` is the
  same figure in simulator ticks, which machine load cannot move;
- a task without environments has no ST and no Redundancy (null, left out of the means): failing
  to build anything must not look fast or lean;
- PhyPR holds the paper's three dimensions only; the extra checks are `plausibility`;
- JI compares with the minimum cover closest to the realised set (`logic.reference`); `ji_fixed`
  beside it compares with one canonical minimum cover (docs/fidelity.md gives both).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, computed_field

from logicenveval.errors import MetricsError
from logicenveval.metrics.records import EnvSample
from logicenveval.model.repeats import repeated
from logicenveval.model.task import FAULTY_KINDS, POLICY_KINDS, Task
from logicenveval.model.tree import all_path_keys, atomic_conditions

if TYPE_CHECKING:
    import pandas as pd


class TaskMetrics(BaseModel):
    """One generator's figures on one task, plus the counts aggregation needs."""

    model_config = ConfigDict(frozen=True)
    task_id: str
    n_envs: int
    #: attempted environments that were not built (they fail PhyPR and SceVR)
    n_failed: int = 0
    n_floor_plan_ok: int
    n_entity_ok: int
    n_relation_ok: int
    #: environments that are well-formed and in which the correct BT passes
    n_valid: int
    logcov: float
    ld: float
    ji: float
    #: JI against the one canonical minimum cover (`logic.reference.reference_set`) instead of the
    #: closest one: shown beside JI, as the paper does not say which minimum cover it means
    ji_fixed: float | None = None
    #: what JI compared: the trajectories the generator reported (every attempt's target a GT
    #: trajectory, the paper's generated set) or, otherwise, those its environments realise
    ji_set: Literal["reported", "realised"] = "realised"
    #: environments / minimum cover size; None for a task without environments
    redundancy: float | None
    min_cover: int
    #: faulty kind -> its BT fails in at least one valid environment
    faudr: dict[str, bool]
    #: None for a task without environments (nothing was simulated)
    st_ms: float | None
    st_ticks: float | None = 0.0
    #: environments passing every extra plausibility check, and per failure code how many fail it
    n_extended_ok: int = 0
    extended_codes: dict[str, int] = Field(default_factory=dict)
    #: share of the task's killable mutants killed in some valid environment (None: not scored)
    faudr_mut: float | None = None
    #: the same share per fault class (classes without killable mutants are left out)
    faudr_mut_by_class: dict[str, float] = Field(default_factory=dict)
    #: built environments that claim a trajectory of the generator's own plan, and those that
    #: realise it (`Attempt.realised`): what `realised_share` divides
    n_claimed: int = 0
    n_realised: int = 0
    covered_paths: list[str] = Field(default_factory=list)
    realised_trajectories: list[str] = Field(default_factory=list)
    #: the minimum cover JI compares with: the one closest to `realised_trajectories`
    reference_trajectories: list[str] = Field(default_factory=list)

    @computed_field  # type: ignore[prop-decorator]
    @property
    def n_attempted(self) -> int:
        """Environments the generator set out to build: the PhyPR and SceVR denominator."""
        return self.n_envs + self.n_failed


class PhyPR(BaseModel):
    model_config = ConfigDict(frozen=True)
    floor_plan: float
    entity: float
    relation: float
    avg: float


class FauDR(BaseModel):
    model_config = ConfigDict(frozen=True)
    counterfactual: float
    unreachable: float
    lackbranch: float
    avg: float


class Plausibility(BaseModel):
    """The extra checks beyond the paper's PhyPR: pass rate and environments failing each code."""

    model_config = ConfigDict(frozen=True)
    rate: float
    codes: dict[str, int]


class GeneratorMetrics(BaseModel):
    """The keys of `results.<generator>` in DESIGN.md §9, plus `st_ticks` and `plausibility`."""

    model_config = ConfigDict(frozen=True)
    phypr: PhyPR
    logcov: float
    ld: float
    scevr: float
    faudr: FauDR
    #: means over the tasks with environments; None when no task has any
    st_ms: float | None
    st_ticks: float | None
    ji: float
    #: JI against the canonical minimum cover (mean over tasks; None for files written before it)
    ji_fixed: float | None = None
    redundancy: float | None
    n_envs: int
    plausibility: Plausibility
    #: environments set out to build (the PhyPR/SceVR denominator) and those not built
    n_attempted: int = 0
    n_failed: int = 0
    #: mutation score (issue 22): mean over scored tasks; None when no task was scored
    faudr_mut: float | None = None
    faudr_mut_by_class: dict[str, float] = Field(default_factory=dict)
    #: share of the built environments claiming a trajectory of the generator's own plan that
    #: realise it (issue 46); None when none claims one (CoT, IFG, Holodeck-like)
    realised_share: float | None = None


def _is_valid(sample: EnvSample) -> bool:
    """A valid scenario (SceVR): well-formed, every explicit task constraint held, the correct
    BT passes."""
    return (sample.well_formed and not sample.violations
            and sample.verdicts.get("correct") == "passed")


def _check_samples(task: Task, samples: Sequence[EnvSample], n_failed: int) -> set[str]:
    if n_failed < 0:
        raise MetricsError(
            f"n_failed={n_failed} is negative", field="n_failed", hint="count failed generations, >= 0"
        )
    keys = set(all_path_keys(task))
    for s in samples:
        if s.task_id != task.id:
            raise MetricsError(
                f"sample {s.env_id!r} belongs to task {s.task_id!r}, not {task.id!r}",
                field="samples.task_id",
                hint="group samples by task before calling task_metrics",
            )
        unknown = [k for k in s.covered_paths if k not in keys]
        if unknown:
            raise MetricsError(
                f"sample {s.env_id!r} covers unknown decision path(s) {unknown} of task {task.id!r}",
                field="samples.covered_paths",
                hint="re-evaluate the environment against the current task.json (coverage())",
            )
    return keys


def task_metrics(task: Task, samples: Sequence[EnvSample], n_failed: int = 0,
                 mutants: Mapping[str, str] | None = None, reported: Sequence[str] = (),
                 claims_realised: Sequence[bool] = ()) -> TaskMetrics:
    """Figures of one task; `mutants` (killable id -> fault class) enables `faudr_mut`;
    `reported`: the trajectory each attempt set out to realise (`Attempt.target`), JI's set when
    every one is a trajectory of the task's GT trees (the paper's generated set), else the
    realised trajectories are; `claims_realised`: per built environment that claims a trajectory of
    the generator's own plan, whether it realises it (`Attempt.realised`)."""
    from logicenveval.logic.reference import closest_reference, jaccard, reference_set

    keys = _check_samples(task, samples, n_failed)
    good = [s for s in samples if s.well_formed]
    covered = {k for s in good for k in s.covered_paths}
    conditions = set(atomic_conditions(task))
    met = {tuple(c) for s in good for c in s.conditions} & conditions
    realised = {s.trajectory for s in good if s.trajectory is not None}
    generated = set(reported) if reported and all(_is_trajectory(task, k, keys) for k in reported) else None
    compared = realised if generated is None else generated
    closest = closest_reference(task, compared)
    valid = [s for s in samples if _is_valid(s)]
    simulated = [k for k in POLICY_KINDS if any(k in s.sim_ms for s in samples)]
    st = (
        sum(sum(s.sim_ms.get(k, 0.0) for s in samples) for k in simulated) / len(simulated)
        if simulated
        else None
    )
    st_ticks = (
        sum(sum(s.sim_ticks.get(k, 0) for s in samples) for k in simulated) / len(simulated)
        if simulated
        else None
    )
    codes = Counter(code for s in samples
                    for code in sorted({f["code"] for f in s.physics.extended_failures}))
    return TaskMetrics(
        task_id=task.id,
        n_envs=len(samples),
        n_failed=n_failed,
        n_floor_plan_ok=sum(s.physics.floor_plan for s in samples),
        n_entity_ok=sum(s.physics.entity for s in samples),
        n_relation_ok=sum(s.physics.relation for s in samples),
        n_valid=len(valid),
        logcov=len(covered) / len(keys),
        ld=len(met) / len(conditions) if conditions else float(bool(good)),
        ji=closest.ji,
        ji_fixed=jaccard(compared, [t.key for t in reference_set(task)]),
        ji_set="realised" if generated is None else "reported",
        redundancy=len(samples) / len(closest.trajectories) if samples else None,
        min_cover=len(closest.trajectories),
        faudr={
            k: any(k in s.verdicts and s.verdicts[k] != "passed" for s in valid)
            for k in FAULTY_KINDS
        },
        st_ms=st,
        st_ticks=st_ticks,
        n_extended_ok=sum(s.physics.extended for s in samples),
        extended_codes=dict(sorted(codes.items())),
        **_mutation_score(valid, mutants),
        n_claimed=len(claims_realised),
        n_realised=sum(claims_realised),
        covered_paths=sorted(covered),
        realised_trajectories=sorted(realised),
        reference_trajectories=[t.key for t in closest.trajectories],
    )


def _is_trajectory(task: Task, key: str, paths: set[str]) -> bool:
    """Is `key` a trajectory key of the task's GT trees (one path per subtask, in order)?
    `paths`: the keys of the task's decision paths (`all_path_keys`, worked out once a task)."""
    parts = key.split(" | ")
    return len(parts) == len(task.subtasks) and all(
        p in paths and p.split(":", 1)[0] == st.id for p, st in zip(parts, task.subtasks, strict=True))


def _mutation_score(valid: Sequence[EnvSample], mutants: Mapping[str, str] | None) -> dict[str, Any]:
    if not mutants:
        return {}
    killed = {m for s in valid for m in s.killed_mutants} & set(mutants)
    by_class: dict[str, float] = {}
    for cls in sorted(set(mutants.values())):
        ids = {m for m, c in mutants.items() if c == cls}
        by_class[cls] = len(killed & ids) / len(ids)
    return {"faudr_mut": len(killed) / len(mutants), "faudr_mut_by_class": by_class}


def load_aggregation() -> None:
    """Import what `aggregate` needs (pandas, ~0.4 s): a run does it while its units run, so
    neither its start, which the workers wait for, nor its end pays for it."""
    import pandas  # noqa: F401


def aggregate(per_task: Sequence[TaskMetrics]) -> GeneratorMetrics:
    """Shares over all attempted environments (PhyPR, SceVR) and means over tasks (the rest)."""
    if not per_task:
        raise MetricsError(
            "no task metrics to aggregate", field="per_task", hint="evaluate at least one task"
        )
    ids = [t.task_id for t in per_task]
    if len(set(ids)) != len(ids):
        raise MetricsError(
            f"task(s) {repeated(ids)} appear more than once",
            field="per_task",
            hint="pass one TaskMetrics per task",
        )
    import pandas as pd  # here, not at the top: a run's start does not need it (load_aggregation)

    df = pd.DataFrame([t.model_dump() for t in per_task])
    for kind in FAULTY_KINDS:
        df[f"faudr_{kind}"] = [t.faudr[kind] for t in per_task]
    slots = int(df["n_envs"].sum() + df["n_failed"].sum())

    def share(column: str) -> float:
        return float(df[column].sum()) / slots if slots else 0.0

    phy = [share("n_floor_plan_ok"), share("n_entity_ok"), share("n_relation_ok")]
    fau = [float(df[f"faudr_{k}"].mean()) for k in FAULTY_KINDS]
    return GeneratorMetrics(
        phypr=PhyPR(floor_plan=phy[0], entity=phy[1], relation=phy[2], avg=sum(phy) / 3),
        logcov=float(df["logcov"].mean()),
        ld=float(df["ld"].mean()),
        scevr=share("n_valid"),
        faudr=FauDR(counterfactual=fau[0], unreachable=fau[1], lackbranch=fau[2], avg=sum(fau) / 3),
        st_ms=_mean_present(df["st_ms"]),
        st_ticks=_mean_present(df["st_ticks"]),
        ji=float(df["ji"].mean()),
        ji_fixed=_mean_present(df["ji_fixed"]),
        redundancy=_mean_present(df["redundancy"]),
        n_envs=int(df["n_envs"].sum()),
        n_attempted=slots,
        n_failed=int(df["n_failed"].sum()),
        plausibility=Plausibility(
            rate=share("n_extended_ok"),
            codes=dict(sorted(sum((Counter(t.extended_codes) for t in per_task), Counter()).items())),
        ),
        **_mean_mutation_score(per_task),
        realised_share=(float(df["n_realised"].sum()) / claimed
                        if (claimed := int(df["n_claimed"].sum())) else None),
    )


def _mean_present(column: pd.Series) -> float | None:
    """Mean over the tasks that have the figure; None when none has it."""
    import pandas as pd

    values = pd.to_numeric(column, errors="coerce").dropna()
    return float(values.mean()) if len(values) else None


def _mean_mutation_score(per_task: Sequence[TaskMetrics]) -> dict[str, Any]:
    scored = [t for t in per_task if t.faudr_mut is not None]
    if not scored:
        return {}
    classes = sorted({c for t in scored for c in t.faudr_mut_by_class})
    by_class = {c: sum(t.faudr_mut_by_class[c] for t in scored if c in t.faudr_mut_by_class)
                / sum(1 for t in scored if c in t.faudr_mut_by_class) for c in classes}
    return {"faudr_mut": sum(float(t.faudr_mut or 0.0) for t in scored) / len(scored),
            "faudr_mut_by_class": by_class}


def null_metrics() -> dict[str, Any]:
    """`results.<generator>` of a generator that was not measured (every unit failed for
    infrastructure reasons): the shape of `GeneratorMetrics` with every figure null, never 0."""

    def nulls(value: Any) -> Any:
        if isinstance(value, dict):
            return {k: nulls(v) for k, v in value.items()} if value else {}
        return None

    shape = aggregate([TaskMetrics(task_id="-", n_envs=0, n_failed=1, n_floor_plan_ok=0, n_entity_ok=0,
                                   n_relation_ok=0, n_valid=0, logcov=0.0, ld=0.0, ji=0.0,
                                   redundancy=0.0, min_cover=1, faudr=dict.fromkeys(FAULTY_KINDS, False),
                                   st_ms=0.0)])
    out: dict[str, Any] = nulls(shape.model_dump(mode="json"))
    return out
