"""Semantic validation of benchmark tasks (`tasks validate`, DESIGN.md §4-§5).

Structure is checked by `load_task_file`; this module adds what needs the catalog, a solver or the
simulator: roles and categories, disjoint subtask roles, exclusive and exhaustive variable values
(proved with z3 over predicates as free booleans plus the physical axioms; an optional role may
be absent), the explicit constraints (each role attribute stated, all consistent with every
situation: z3), and the four policies simulated in every situation (several worlds per Cartesian
trajectory of decision paths, each holding the constraints, absence worlds for optional roles).
Problems are returned as typed data, never raised, so that one run reports every task.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import z3

from logicenveval.atomic import atomic_write_text
from logicenveval.benchmark import load_task_file, tasks_dir
from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.errors import LogicEnvEvalError, PolicyFormatError, TaskFormatError
from logicenveval.limits import limit, raise_hint, read_text
from logicenveval.logic.axioms import Axioms
from logicenveval.model.conditions import parse
from logicenveval.model.task import FAULTY_KINDS, POLICY_KINDS, Leaf, Node, Task
from logicenveval.model.tree import Trajectory, task_paths
from logicenveval.sim.worlds import DEFAULT_WORLDS

#: verdicts each faulty kind may fail with (DESIGN.md §5, "Faulty kinds map to verdicts")
FAULT_VERDICTS: dict[str, frozenset[str]] = {
    "counterfactual": frozenset({"precondition_violation"}),
    "unreachable": frozenset({"goal_unmet", "tree_failure"}),
    "lackbranch": frozenset({"tree_failure", "goal_unmet", "precondition_violation"}),
}
_MISSING_OBJECT = ("role is not bound", "no such object")
_Add = Callable[[str, str, str], None]  # add(file, where, message)


@dataclass(frozen=True)
class Problem:
    """One defect: which task and file, where inside it, and what is wrong."""

    task: str
    file: str
    where: str
    message: str

    def __str__(self) -> str:
        return f"{self.task}: {self.file}: {self.where}: {self.message}"


@dataclass
class TaskReport:
    """Outcome of validating one task; `revealing[kind]` lists the situations exposing a fault."""

    task: str
    problems: list[Problem] = field(default_factory=list)
    situations: int = 0
    revealing: dict[str, list[str]] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return not self.problems


def validate_all(directory: str | Path | None = None, catalog: Catalog | None = None,
                 *, simulate: bool = True, worlds: int = DEFAULT_WORLDS,
                 ids: Sequence[str] = (),
                 progress: Callable[[int, int, str], None] | None = None) -> list[TaskReport]:
    """Validate every task folder of `directory` (default: the shipped benchmark), or those of
    `ids`; `progress(done, total, task)` is called before each task (a long check: seconds each)."""
    d = tasks_dir(directory)
    folders: list[Path | str] = list(ids) or sorted(
        p for p in d.iterdir() if p.is_dir() and not p.name.startswith("."))
    reports = []
    for i, f in enumerate(folders):
        if progress is not None:
            progress(i, len(folders), f.name if isinstance(f, Path) else f)
        reports.append(validate_task(f, d, catalog, simulate=simulate, worlds=worlds))
    if progress is not None:
        progress(len(folders), len(folders), "")
    return reports


def write_models(directory: str | Path | None = None, ids: list[str] | None = None) -> list[Path]:
    """Give every policy of the tasks (all, or `ids`) the library's current Groot2
    `<TreeNodesModel>`; returns the files that changed."""
    from logicenveval.sim.groot import with_current_model

    d = tasks_dir(directory)
    changed = []
    for folder in sorted(p for p in d.iterdir() if p.is_dir() and not p.name.startswith(".")):
        if ids and folder.name not in ids:
            continue
        task = load_task_file(folder / "task.json")
        for rel in task.policies.values():
            path = folder / rel
            if not path.resolve().is_relative_to(folder.resolve()):
                continue  # a policy outside its task folder is never written (validate reports it)
            text = read_text(path, what="policy file", error=PolicyFormatError,
                             max_bytes="max_xml_bytes", hint="check the task's policies")
            new = with_current_model(text)
            if new != text:
                atomic_write_text(path, new)
                changed.append(path)
    return changed


def validate_task(task: Task | str | Path, directory: str | Path | None = None,
                  catalog: Catalog | None = None, *, simulate: bool = True,
                  worlds: int = DEFAULT_WORLDS) -> TaskReport:
    """Validate one task given as a `Task`, a task folder or a task id within `directory`.

    Each situation is simulated in up to `worlds` environments (`sim.worlds.situation_worlds`);
    `worlds=1` checks only the minimal world of each situation.
    """
    if worlds < 1:
        raise ValueError(f"worlds must be >= 1, got {worlds}")
    d = tasks_dir(directory)
    cat = catalog if catalog is not None else load_catalog()
    if isinstance(task, Task):
        folder, name = d / task.id, task.id
    else:
        p = Path(task)
        folder = p if isinstance(task, Path) and p.is_dir() else d / str(task)
        if not isinstance(task, Path) and not folder.resolve().is_relative_to(d.resolve()):
            raise TaskFormatError(f"{task!r} is not a task of the tasks folder", file=str(d),
                                  field="--task", hint="give a task id (folder name), not a path")
        name = folder.name
    report = TaskReport(task=name)
    if not isinstance(task, Task):
        try:
            task = load_task_file(folder / "task.json")
        except LogicEnvEvalError as exc:
            report.problems.append(Problem(name, "task.json", exc.field or "-", str(exc)))
            return report
    _impl_validate(task, folder, cat, report, simulate, worlds)
    return report


def _impl_validate(task: Task, folder: Path, cat: Catalog, report: TaskReport,
                   simulate: bool, worlds: int) -> None:
    def add(file: str, where: str, message: str) -> None:
        report.problems.append(Problem(task.id, file, where, message))

    for role, spec in task.roles.items():
        category = cat.get(spec.category)
        if category is None:
            add("task.json", f"roles.{role}.category",
                f"category {spec.category!r} is not in the catalog (fix: use a catalog category "
                "or add it to benchmark_data/catalog_requests.txt)")
            continue
        for key, value in spec.attributes.items():
            domain = category.attributes.get(key)
            if domain is not None and value not in domain:
                add("task.json", f"roles.{role}.attributes.{key}",
                    f"value {value!r} is not in the catalog domain {domain} of {spec.category!r}")
    _check_disjoint(task, add)
    try:
        situation_count(task)
    except TaskFormatError as exc:
        add("task.json", exc.field or "subtasks", f"{exc.message} (fix: {exc.hint})")
        return
    _check_values(task, add)
    _check_constraints(task, cat, add)
    policies = _load_policies(task, folder, add)
    if simulate and not report.problems and len(policies) == len(POLICY_KINDS):
        _check_policies(task, cat, policies, report, add, worlds)
    _check_models(task, folder, policies, add)


def _check_disjoint(task: Task, add: _Add) -> None:
    owner: dict[str, str] = {}
    for st in task.subtasks:
        for role in sorted(task.subtask_roles(st)):
            first = owner.setdefault(role, st.id)
            if first != st.id:
                add("task.json", f"subtasks.{st.id}",
                    f"role {role!r} is tested by variables of subtasks {first!r} and {st.id!r}; "
                    "variables of different subtasks must test disjoint roles")


def _check_constraints(task: Task, cat: Catalog, add: _Add) -> None:
    """Every role attribute is stated as a constraint (the description's words for it), and the
    constraints hold together with every situation (z3: `situation_env` makes them hard)."""
    from logicenveval.errors import TrajectoryError
    from logicenveval.sim.situations import situation_env

    stated = {c.fact.replace(" ", "") for c in task.constraints}
    for role, spec in task.roles.items():
        for key, value in spec.attributes.items():
            if f"attr({role},{key},{value})" not in stated:
                add("task.json", f"roles.{role}.attributes.{key}",
                    f"{key}={value} tells {role} apart but no constraint states it (fix: add "
                    f"{{\"fact\": \"attr({role}, {key}, {value})\", \"says\": <the description's "
                    "words>} to constraints)")
    if not task.constraints:
        return
    for traj in situations(task):
        try:
            situation_env(task, traj, cat)
        except TrajectoryError as exc:
            add("task.json", "constraints", f"situation {traj.key}: {exc.message}")
            return


# ----- exclusive / exhaustive values ----------------------------------------------------------

def _check_values(task: Task, add: _Add) -> None:
    extra = [parse(t) for var in task.variables.values() for t in var.values.values()]
    enc = Axioms(task.roles, extra)
    for st in task.subtasks:
        _check_node(task, enc, st.tree, [], f"subtasks.{st.id}.tree", add)


def _check_node(task: Task, enc: Axioms, node: Node | Leaf, path: list[z3.BoolRef], where: str,
                add: _Add) -> None:
    if isinstance(node, Leaf):
        return
    var = task.variables[node.var]
    conds = {v: enc.cond(var.condition(v)) for v in var.values}
    if enc.witness(*path) is None:
        add("task.json", where, "this node is unreachable: the path conditions leading to it "
            "contradict each other or the physical axioms")
        return
    for (a, ca), (b, cb) in itertools.combinations(conds.items(), 2):
        w = enc.witness(*path, ca, cb)
        if w is not None:
            add("task.json", f"variables.{node.var}",
                f"values {a!r} and {b!r} overlap at {where} (both hold in {w}); values must be "
                "mutually exclusive")
    w = enc.witness(*path, z3.Not(z3.Or(*conds.values())))
    if w is not None:
        add("task.json", f"variables.{node.var}",
            f"values {sorted(conds)} are not exhaustive at {where}: none holds in {w}; add a value "
            "or an explicit `not exists(...)` case")
    for value, child in node.branches.items():
        _check_node(task, enc, child, [*path, conds[value]], f"{where}.branches.{value}", add)


# ----- policies ---------------------------------------------------------------------------------

def _load_policies(task: Task, folder: Path, add: _Add) -> dict[str, object]:
    from logicenveval.sim.loader import load_policy

    loaded: dict[str, object] = {}
    for kind in POLICY_KINDS:
        rel = task.policies.get(kind)
        if rel is None:
            add("task.json", "policies", f"no {kind!r} policy declared")
            continue
        if not (folder / rel).resolve().is_relative_to(folder.resolve()):
            add("task.json", f"policies.{kind}", f"policy {rel!r} is outside the task folder "
                "(fix: policies are files inside the task's own folder)")
            continue
        try:
            loaded[kind] = load_policy(folder / rel, roles=task.roles, rooms=task.rooms)
        except LogicEnvEvalError as exc:
            add(rel, exc.field or (f"line {exc.line}" if exc.line else "-"), str(exc))
    return loaded


def _check_models(task: Task, folder: Path, loaded: dict[str, object], add: _Add) -> None:
    """Each loaded policy carries the library's current Groot2 model (checked after the
    simulation, so that a stale model never hides a behaviour problem)."""
    from logicenveval.sim.groot import model_problem

    for kind in loaded:
        rel = task.policies[kind]
        stale = model_problem(read_text(folder / rel, what="policy file", error=PolicyFormatError,
                                        max_bytes="max_xml_bytes", hint="restore the policy file"))
        if stale is not None:
            add(rel, "TreeNodesModel", f"{stale}; run `python -m logicenveval tasks validate "
                "--write-models` to write the action library's current one")


def situations(task: Task) -> list[Trajectory]:
    """Every logical trajectory: the Cartesian product of the subtasks' decision paths.

    The product grows exponentially with independent subtasks, so its size is checked first.
    """
    situation_count(task)
    return [Trajectory(tuple(combo)) for combo in itertools.product(*task_paths(task))]


def situation_count(task: Task) -> int:
    """The number of situations, refused above the `max_situations` limit before any is built."""
    paths = task_paths(task)
    count = math.prod(len(p) for p in paths)
    cap = limit("max_situations")
    if count > cap:
        raise TaskFormatError(f"the task has {count} situations ({' x '.join(str(len(p)) for p in paths)} "
                              f"decision paths), more than the limit of {cap}", file=f"{task.id}/task.json",
                              field="subtasks", hint="merge or drop independent subtasks, or "
                              + raise_hint("max_situations"))
    return count


def _check_policies(task: Task, cat: Catalog, policies: dict[str, object],
                    report: TaskReport, add: _Add, worlds: int) -> None:
    """Run every policy in every world of every situation.

    The correct policy must pass in all worlds; a faulty one must fail in some world of some
    situation, pass in some situation's every world, and fail only with verdicts of its kind.
    """
    from logicenveval.sim.policy import Policy
    from logicenveval.sim.simulator import simulate
    from logicenveval.sim.worlds import situation_worlds

    passed: dict[str, list[str]] = {k: [] for k in POLICY_KINDS}
    failed: dict[str, list[tuple[str, str, str]]] = {k: [] for k in POLICY_KINDS}
    for traj in situations(task):
        report.situations += 1
        try:
            envs = situation_worlds(task, traj, cat, limit=worlds)
        except LogicEnvEvalError as exc:
            add("task.json", f"situation {traj.key}", f"cannot be realised: {exc.message}")
            continue
        for kind, policy in policies.items():
            assert isinstance(policy, Policy)
            fails: list[tuple[str, str]] = []
            for env in envs:
                v = simulate(policy, env, task, cat)
                if v.status != "passed":
                    fails.append((v.status, _where(env.env_id, v.message or "")))
            if not fails:
                passed[kind].append(traj.key)
            for status, message in fails if kind != "correct" else fails[:1]:
                failed[kind].append((traj.key, status, message))
    files = task.policies
    for key, why, message in failed["correct"]:
        add(files["correct"], f"situation {key}",
            f"the correct policy fails ({why}: {message})")
    for kind in FAULTY_KINDS:
        report.revealing[kind] = list(dict.fromkeys(k for k, _, _ in failed[kind]))
        if not failed[kind]:
            add(files[kind], "all situations",
                f"the {kind} policy passes every situation; a faulty policy must fail in at least one")
        if not passed[kind]:
            add(files[kind], "all situations",
                f"the {kind} policy fails every situation; it must pass in at least one")
        for key, why, message in failed[kind]:
            if not _fits(kind, why, message):
                add(files[kind], f"situation {key}",
                    f"fails with {why} ({message}), which is not a {kind} fault; expected "
                    f"{sorted(FAULT_VERDICTS[kind])}")


def _where(env_id: str, message: str) -> str:
    """`message`, naming the varied world (`#wN`) when the failure is not in the minimal one."""
    _, sep, world = env_id.rpartition("#")
    return f"{message} [in varied world {world}]" if sep else message


def _fits(kind: str, status: str, message: str) -> bool:
    if status not in FAULT_VERDICTS[kind]:
        return False
    if kind == "lackbranch" and status == "precondition_violation":
        return any(m in message for m in _MISSING_OBJECT)
    return True


