"""`lint`: what would make each EnvSpec of a folder ill-formed, found before any scoring.

For every `ENVS_DIR/<task_id>/*.json` (the layout `evaluate` scores) the environment is taken in
exactly as evaluation takes it (`domain.roles.prepare_env`: categories mapped, roles bound) and
checked, without physics or simulation:

* **file**: not a valid EnvSpec, a `task_id` of another task, an `env_id` used twice;
* **binding**: an ambiguous role (several objects qualify), a role left unbound that is not
  optional and that no reached decision path allows to be absent — one message per role, naming
  the nearest objects and what they lack — a variable whose values reach no leaf (the GT trees
  are evaluated on the initial state);
* **constraint**: a fact the task description fixes that the environment violates (not a valid
  scenario);
* **category**: names that fit several catalog categories (the choice made) and names that fit
  none (kept as obstacles) — notes; `readings` lists how each object's category was read;
* **affordance**: an object resting on something that is not a surface, inside something that is
  not a container; a role the EnvSpec maps itself to an object of another category or with other
  attributes (the harness never second-guesses such a map, so it is reported here).

Problems make a file fail (exit 1); notes do not.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from logicenveval.benchmark import load_task, task_ids
from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.domain.roles import matches, parse_role_map, prepare_env, unknown_roles
from logicenveval.envfiles import load_env
from logicenveval.errors import ConfigError, LogicEnvEvalError
from logicenveval.metrics.evaluate import constraint_problems, coverage
from logicenveval.model.envspec import EnvSpec, unknown_state_flags
from logicenveval.model.task import Task
from logicenveval.sim.world import holds_initial


@dataclass
class FileReport:
    path: str
    task_id: str
    env_id: str | None = None
    #: (kind, message): kind is file, binding, category or affordance
    problems: list[tuple[str, str]] = field(default_factory=list)
    notes: list[tuple[str, str]] = field(default_factory=list)
    #: per object: its id, the category as written and the catalog key it was read as (None:
    #: names no category)
    readings: list[tuple[str, str, str | None]] = field(default_factory=list)

    @property
    def clean(self) -> bool:
        return not self.problems


def lint_env(env: EnvSpec, task: Task, catalog: Catalog, report: FileReport,
             given: Mapping[str, str] | None = None) -> None:
    """Add the binding, constraint, category and affordance findings of one loaded environment;
    `given` maps roles first (`--roles`)."""
    prepared = prepare_env(env, task.roles, catalog, given)
    judged, cats = prepared.env, prepared.categories
    for o in judged.objects:
        written = getattr(o, "source_category", None) or o.category
        report.readings.append((o.id, written, None if written in cats.unknown else o.category))
    for name, ids in sorted(cats.unknown.items()):
        report.notes.append(("category", f"category {name!r} names no catalog category: "
                             f"{', '.join(ids[:5])}{' …' if len(ids) > 5 else ''} kept as immovable "
                             "obstacle(s) (use a catalog category or synonym, docs/catalog.md)"))
    for name, options in sorted(cats.ambiguous.items()):
        report.notes.append(("category", f"category {name!r} fits {', '.join(options)}: "
                             f"read as {cats.mapped[name]}"))
    report.problems += [("binding", p) for p in prepared.binding.problems]
    report.problems += [("states", p) for p in unknown_state_flags(judged)]
    holds = holds_initial(judged, catalog)
    cov = coverage(task, holds, judged.roles, prepared.binding)
    report.problems += [("binding", p) for p in cov.problems]
    report.problems += [("constraint", p) for p in constraint_problems(task, judged, holds)]
    by_id = {o.id: o for o in judged.objects}
    for o in judged.objects:
        sup = by_id.get(o.support or "")
        if sup is not None and not _has(catalog, sup.category, "surface"):
            report.problems.append(("affordance", f"{o.id} rests on {sup.id}, a {sup.category}, "
                                    "which is not a surface"))
        box = by_id.get(o.container or "")
        if box is not None and not _has(catalog, box.category, "container"):
            report.problems.append(("affordance", f"{o.id} is inside {box.id}, a {box.category}, "
                                    "which is not a container"))
    for role, oid in sorted(env.roles.items()):
        spec = task.roles.get(role)
        if spec is None or oid is None or oid not in by_id:
            continue
        if not matches(by_id[oid], spec, catalog):
            want = spec.category + (f" with {spec.attributes}" if spec.attributes else "")
            report.problems.append(("affordance", f"role {role} is mapped to {oid}, a "
                                    f"{by_id[oid].category}, but the task's {role} is a {want}"))


def _has(catalog: Catalog, category: str, affordance: str) -> bool:
    cat = catalog.get(category)
    return bool(cat is not None and getattr(cat, affordance))


def lint_folder(envs_dir: str | Path, tasks_dir: str | Path | None = None,
                catalog: Catalog | None = None, roles: str | None = None) -> list[FileReport]:
    """One report per EnvSpec file of `envs_dir/<task_id>/`, in task and natural file order;
    `roles` (`--roles ROLE=ID,...`) maps roles of every file first."""
    from logicenveval.runner.score_envs import env_files

    root = Path(envs_dir)
    if not root.is_dir():
        raise ConfigError("not a folder", file=str(root),
                          hint="pass a folder of <task_id>/*.json EnvSpecs (the layout `evaluate` scores)")
    known = set(task_ids(tasks_dir))
    folders = sorted(p for p in root.iterdir() if p.is_dir() and p.name in known)
    if not folders:
        raise ConfigError("no folder named after a task", file=str(root),
                          hint="lay out ENVS_DIR/<task_id>/*.json; task ids: `python -m logicenveval tasks list`")
    cat = catalog or load_catalog()
    tasks = [load_task(folder.name, tasks_dir) for folder in folders]
    # malformed, repeated or unknown ROLEs are bad input (exit 2), not a problem of each file
    unknown_roles(roles, [t.roles for t in tasks])
    reports = []
    for folder, task in zip(folders, tasks, strict=True):
        given = parse_role_map(roles, task.roles, strict=False)
        seen: dict[str, str] = {}
        for path in env_files(folder):
            report = FileReport(path=str(path), task_id=task.id)
            reports.append(report)
            try:
                env = load_env(path)
            except LogicEnvEvalError as exc:
                report.problems.append(("file", f"not a valid EnvSpec: {exc}"))
                continue
            report.env_id = env.env_id
            if env.task_id != task.id:
                report.problems.append(("file", f"task_id {env.task_id!r} but the file is in the folder "
                                        f"of task {task.id!r}"))
                continue
            if env.env_id in seen:
                report.problems.append(("file", f"env_id {env.env_id!r} is also used by {seen[env.env_id]}"))
            seen.setdefault(env.env_id, path.name)
            try:
                lint_env(env, task, cat, report, given)
            except ConfigError as exc:
                report.problems.append(("binding", str(exc)))
    if not reports:  # "no problems" about nothing would read as a pass
        raise ConfigError(f"no EnvSpec file (*.json) in the task folder(s) "
                          f"{', '.join(f.name for f in folders[:5])}, so nothing was checked",
                          file=str(root), hint="put the EnvSpecs in ENVS_DIR/<task_id>/*.json, "
                          "as regular files the user may read")
    return reports
