"""Classify mutants by exhaustive simulation, and score environments by the mutants they kill.

A mutant is *equivalent* when it passes every GT situation in every world the validator builds
(`sim.worlds.situation_worlds`); otherwise it is *killable*, and the situations that kill it and
its verdict kinds are recorded. Each of a task's three hand-written faulty BTs is *reproduced*
when some mutant has the same signature (situation -> verdict kinds over all worlds).

Speed: a mutant differs from the correct BT only inside its `region`. Every episode records
the correct BT once (`CompiledPolicy.record`: every leaf tick, constant leaves included, and a
snapshot before every root tick); a mutant none of whose region's leaves were ticked there
behaves exactly like the correct BT (same ticks, same statuses, same world), so it gets its
verdict without being simulated. The others resume from the snapshot before the first root tick
where they can differ (`MutantRunner._status`), on the correct tree with only their edited
subtree spliced in, built once and reset per episode.
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from logicenveval.benchmark import load_task, policy_path
from logicenveval.benchmark_validation import situations
from logicenveval.domain.catalog import Catalog, load_catalog
from logicenveval.faults.operators import FAULT_CLASSES, PARENT_EDITS, Mutant, mutants
from logicenveval.model.conditions import Cond
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import FAULTY_KINDS, Task
from logicenveval.sim.loader import load_policy
from logicenveval.sim.nodes import BTNode, Decorator, build_tree
from logicenveval.sim.policy import Policy, PolicyNode
from logicenveval.sim.simulator import CompiledPolicy, Recording, task_goal
from logicenveval.sim.world import World
from logicenveval.sim.worlds import DEFAULT_WORLDS, situation_worlds

Signature = dict[str, tuple[str, ...]]  # situation key -> sorted verdict kinds of its failures


@dataclass(frozen=True)
class MutantOutcome:
    id: str
    operator: str
    fault_class: str
    description: str
    killed_by: Signature

    @property
    def equivalent(self) -> bool:
        return not self.killed_by


@dataclass(frozen=True)
class HandwrittenMatch:
    """How a hand-written faulty BT relates to the mutants."""

    kind: str
    signature: Signature
    reproduced_by: list[str]
    #: when not reproduced: the closest mutant and the Jaccard index of (situation, kind) pairs
    closest: str | None = None
    closest_jaccard: float = 0.0
    #: number of single-node differences between the faulty and the correct BT
    edits: int = 0
    reason: str = ""


@dataclass
class TaskMutants:
    task: str
    situations: int
    worlds: int
    outcomes: list[MutantOutcome] = field(default_factory=list)
    handwritten: dict[str, HandwrittenMatch] = field(default_factory=dict)

    @property
    def killable(self) -> list[MutantOutcome]:
        return [o for o in self.outcomes if not o.equivalent]

    def by_operator(self) -> dict[str, dict[str, int]]:
        out: dict[str, dict[str, int]] = {}
        for o in self.outcomes:
            row = out.setdefault(o.operator, {"mutants": 0, "killable": 0})
            row["mutants"] += 1
            row["killable"] += not o.equivalent
        return dict(sorted(out.items()))

    def to_json(self) -> dict[str, object]:
        return {
            "task": self.task, "situations": self.situations, "worlds": self.worlds,
            "mutants": len(self.outcomes), "killable": len(self.killable),
            "equivalent": len(self.outcomes) - len(self.killable),
            "by_operator": self.by_operator(),
            "by_class": {c: sum(1 for o in self.killable if o.fault_class == c) for c in FAULT_CLASSES},
            "handwritten": {k: {"reproduced_by": h.reproduced_by, "closest": h.closest,
                                "closest_jaccard": round(h.closest_jaccard, 4), "edits": h.edits,
                                "reason": h.reason}
                            for k, h in self.handwritten.items()},
            "mutant_list": [{"id": o.id, "class": o.fault_class, "description": o.description,
                             "killed_by": o.killed_by} for o in self.outcomes],
        }


#: (parent, child index, original child, spliced-in child, the spliced subtree's new nodes —
#: the rest are the correct tree's own, reused)
_Splice = tuple[BTNode, int, BTNode, BTNode, list[BTNode]]


class MutantRunner:
    """Runs the correct BT and its mutants on environments, reusing compiled trees.

    A mutant is not compiled as a whole: only its anchor (the smallest subtree holding the
    edit) is built, and spliced into the correct BT's compiled tree for the episode, in place
    of the original subtree, then taken out again. Everything outside the anchor is the very
    same py_trees nodes, so building a mutant costs its anchor, not the whole tree.
    """

    def __init__(self, correct: Policy, muts: Sequence[Mutant]) -> None:
        self.correct = CompiledPolicy(correct)
        self.mutants = list(muts)
        self._splices: dict[int, list[_Splice]] = {}
        self._whole: dict[int, CompiledPolicy] = {}
        self._paths = _compiled_paths(correct)
        self._by_path: dict[str, tuple[BTNode, BTNode | None, int]] = {}
        for node in self.correct.root.iterate():
            if isinstance(node, BTNode):
                self._by_path.setdefault(node.path, (node, None, 0))
                for i, child in enumerate(node.children):
                    if isinstance(child, BTNode):
                        self._by_path[child.path] = (child, node, i)
        # sets: a deletion's region holds every later sibling, and a node can have thousands
        regions = [frozenset(p for r in m.region for p in self._paths.get((m.location[0], r), ()))
                   for m in self.mutants]
        #: a condition replaced by a constant behaves as before wherever it already returned
        #: that constant: leaf paths and the status the mutant forces
        self._forced = [(regions[i], _FORCED.get(m.operator)) for i, m in enumerate(self.mutants)]
        #: compiled paths where each mutant's episode can first differ: its anchor, or its
        #: region when the anchor is a parent whose edit keeps its kind and its first k children
        #: (then the edited parent takes the original's state when the region is first entered)
        self._mirrored = [_mirrors(correct, m) for m in self.mutants]
        self._entries = [regions[i] if self._mirrored[i] else
                         frozenset(self._paths.get((m.location[0], m.anchor), ()))
                         for i, m in enumerate(self.mutants)]
        self._index = {id(n): j for j, n in enumerate(self.correct.nodes)}
        self._prefix: dict[str, list[str]] = {}

    def run(self, world: World, goal: Cond | None,
            only: Iterable[int] | None = None) -> dict[int, str]:
        """Verdict status of each mutant (index -> status) that does not pass on `world`."""
        base = self.correct.record(world.copy(), goal)
        first: dict[str, int] = {}  # compiled path -> first root tick that entered it
        leaf_status: dict[str, set[str]] = {}
        for tick, leaf, st in base.ticks:
            path = leaf.path
            leaf_status.setdefault(path, set()).add(st.value)
            for p in self._prefixes(path):
                first.setdefault(p, tick)
        out: dict[int, str] = {}
        for i in (only if only is not None else range(len(self.mutants))):
            region, forced = self._forced[i]
            same = first.keys().isdisjoint(region) or (  # iterates the smaller of the two
                forced is not None and all(leaf_status.get(p, {forced}) == {forced} for p in region))
            if same and base.status != "tick_limit":
                if base.status != "passed":
                    out[i] = base.status
                continue
            entries = self._entries[i]
            entered = (p for p in first if p in entries) if len(first) < len(entries) else (
                p for p in entries if p in first)
            start = min((first[p] for p in entered), default=1)
            status = self._status(i, base, start, goal)
            if status != "passed":
                out[i] = status
        return out

    def _prefixes(self, path: str) -> list[str]:
        got = self._prefix.get(path)
        if got is None:
            parts = path.split("/")
            got = self._prefix[path] = ["/".join(parts[:k]) for k in range(1, len(parts) + 1)]
        return got

    def _status(self, i: int, base: Recording, start: int, goal: Cond | None) -> str:
        """The mutant's status, resumed from the correct BT's state before the first root tick
        that entered its anchor (or region, see `_mirrors`): until then the two trees tick the
        same nodes the same way."""
        whole = self._whole.get(i)
        if whole is not None:
            return whole.status(base.snapshots[0].world.copy(), goal)
        splices = self._splices.get(i)
        if splices is None:
            splices = self._build_splices(i)
            if splices is None:  # a whole tree of its own: run from the start
                whole = self._whole[i] = CompiledPolicy(self.mutants[i].policy)
                return whole.status(base.snapshots[0].world.copy(), goal)
        snapshot = base.snapshots[start - 1]
        for parent, k, _, new, _ in splices:
            _put(parent, k, new)
        mirror = [(new, self._index[id(old)]) for _, _, old, new, _ in splices] if self._mirrored[i] else ()
        try:
            return self.correct.resume(snapshot, goal, (n for *_, nodes in splices for n in nodes),
                                       mirror)
        finally:
            for parent, k, old, _, _ in splices:
                _put(parent, k, old)

    def _build_splices(self, i: int) -> list[_Splice] | None:
        m = self.mutants[i]
        tree = m.location[0]
        places = self._paths.get((tree, m.anchor), [])
        out = []
        for path in places:
            old, parent, k = self._by_path[path]
            if parent is None:
                return None  # the anchor is the main tree's root: compile the mutant whole
            anchor = _node_at(m.policy.trees[tree], m.anchor)
            host = f"{tree}#anchor"
            part = Policy(host, {**m.policy.trees, host: anchor}, m.policy.source)
            new = build_tree(part, self.correct.root.binding,
                             reuse=_reuser(_node_at(self.correct.policy.trees[tree], m.anchor), old))
            _adopt(old)
            out.append((parent, k, old, new, [n for n in new.iterate()
                                              if isinstance(n, BTNode) and id(n) not in self._index]))
        self._splices[i] = out
        return out


#: parents that tick their children in order and whose behaviour before child k does not depend
#: on how many children follow (no yielding between children, unlike SequenceWithMemory)
_IN_ORDER = frozenset({"Sequence", "Fallback", "ReactiveSequence", "ReactiveFallback", "IfThenElse"})


def _mirrors(correct: Policy, m: Mutant) -> bool:
    """Whether the mutant's edited parent can take the original parent's state when the edit's
    region is first entered: the edit deletes or reorders children from k on (the region) of a
    parent that keeps its kind and ticks children in order. Until the region is entered both
    parents have ticked the same first k children (the very same reused nodes) the same way."""
    if m.operator not in PARENT_EDITS:
        return False
    tree = m.location[0]
    old = _node_at(correct.trees[tree], m.anchor)
    return old.kind in _IN_ORDER and _node_at(m.policy.trees[tree], m.anchor).kind == old.kind


def _reuser(policy_anchor: PolicyNode, built: BTNode) -> Callable[[PolicyNode], BTNode | None]:
    """The correct BT's built nodes below its anchor, by policy node: a mutant's anchor keeps
    every unchanged child (the same `PolicyNode` object), so only the edited nodes are built.
    Each built node is handed out once, so no node appears twice in a tree."""
    pairs: dict[int, BTNode] = {}

    def visit(p: PolicyNode, n: BTNode) -> None:
        for pc, nc in zip(p.children, n.children, strict=True):
            if isinstance(nc, BTNode):
                pairs.setdefault(id(pc), nc)
                if pc.kind != "SubTree":  # reused whole, with the tree it expands
                    visit(pc, nc)

    visit(policy_anchor, built)

    def reuse(p: PolicyNode) -> BTNode | None:
        got = pairs.pop(id(p), None)
        if got is not None:
            got.parent = None  # py_trees adopts only orphans; `_adopt` gives it back
        return got

    return reuse


def _adopt(root: BTNode) -> None:
    """Point every node below `root` back to its parent in `root`'s tree (py_trees' `parent`)."""
    for node in root.iterate():
        for child in node.children:
            child.parent = node


def _put(parent: BTNode, k: int, child: BTNode) -> None:
    parent.children[k] = child
    if isinstance(parent, Decorator):
        parent.decorated = child


def _node_at(root: PolicyNode, idx: tuple[int, ...]) -> PolicyNode:
    node = root
    for j in idx:
        node = node.children[j]
    return node


#: operators that replace a condition by a constant, and the leaf status that constant gives
_FORCED = {"condition_true": "SUCCESS", "condition_false": "FAILURE"}


def _compiled_paths(policy: Policy) -> dict[tuple[str, tuple[int, ...]], list[str]]:
    """Fault paths (as `sim.nodes` spells them) of every (tree, child-index) location."""
    out: dict[tuple[str, tuple[int, ...]], list[str]] = {}

    def visit(tree: str, node: PolicyNode, idx: tuple[int, ...], path: str) -> None:
        out.setdefault((tree, idx), []).append(path)
        if node.kind == "SubTree":
            sub = node.param("ID") or ""
            root = policy.trees[sub]
            visit(sub, root, (), f"{path}/{root.label}")
        for i, c in enumerate(node.children):
            visit(tree, c, (*idx, i), f"{path}/{c.label}[{i}]")

    main = policy.trees[policy.main]
    visit(policy.main, main, (), f"{policy.main}/{main.label}")
    return out


def task_worlds(task: Task, catalog: Catalog, worlds: int) -> list[tuple[str, EnvSpec]]:
    """(situation key, world) for every world of every situation of `task`."""
    return [(traj.key, env) for traj in situations(task)
            for env in situation_worlds(task, traj, catalog, limit=worlds)]


def classify_task(task: Task | str, tasks_dir: str | Path | None = None,
                  catalog: Catalog | None = None, *, worlds: int = DEFAULT_WORLDS) -> TaskMutants:
    """Generate every first-order mutant of the task's correct BT and classify it."""
    t = task if isinstance(task, Task) else load_task(task, tasks_dir)
    cat = catalog if catalog is not None else load_catalog()
    correct = load_policy(policy_path(t, "correct", tasks_dir), roles=t.roles, rooms=t.rooms)
    muts = mutants(correct, roles=t.roles, rooms=t.rooms)
    envs = task_worlds(t, cat, worlds)
    prepared: list[tuple[str, World, Cond | None]] = []
    for key, env in envs:
        w = World.from_env(env, cat)
        prepared.append((key, w, task_goal(t, w)))
    runner = MutantRunner(correct, muts)
    kills: list[dict[str, set[str]]] = [{} for _ in muts]
    for key, world, goal in prepared:
        for i, status in runner.run(world, goal).items():
            kills[i].setdefault(key, set()).add(status)
    report = TaskMutants(task=t.id, situations=len(situations(t)), worlds=len(envs))
    for m, k in zip(muts, kills, strict=True):
        report.outcomes.append(MutantOutcome(m.id, m.operator, m.fault_class, m.description,
                                             {s: tuple(sorted(v)) for s, v in sorted(k.items())}))
    for kind in FAULTY_KINDS:
        faulty = load_policy(policy_path(t, kind, tasks_dir), roles=t.roles, rooms=t.rooms)
        sig = _signature(faulty, prepared)
        report.handwritten[kind] = _match(kind, sig, report.outcomes, correct, faulty)
    return report


def _signature(policy: Policy, prepared: list[tuple[str, World, Cond | None]]) -> Signature:
    cp = CompiledPolicy(policy)
    out: dict[str, set[str]] = {}
    for key, world, goal in prepared:
        status = cp.status(world.copy(), goal)
        if status != "passed":
            out.setdefault(key, set()).add(status)
    return {s: tuple(sorted(v)) for s, v in sorted(out.items())}


def _pairs(sig: Signature) -> set[tuple[str, str]]:
    return {(s, k) for s, ks in sig.items() for k in ks}


def _match(kind: str, sig: Signature, outcomes: list[MutantOutcome], correct: Policy,
           faulty: Policy) -> HandwrittenMatch:
    same = [o.id for o in outcomes if o.killed_by == sig]
    edits = _distance(correct, faulty)
    if same:
        return HandwrittenMatch(kind, sig, same, edits=edits)
    want = _pairs(sig)
    best, best_j = None, 0.0
    for o in outcomes:
        got = _pairs(o.killed_by)
        if not got:
            continue
        j = len(want & got) / len(want | got)
        if j > best_j:
            best, best_j = o.id, j
    reason = (f"the hand-written BT differs from the correct one in {edits} places (a higher-order "
              "fault); no single edit has the same failing situations and verdict kinds"
              if edits > 1 else
              "the hand-written edit is outside the operator families (see docs/faults.md)")
    return HandwrittenMatch(kind, sig, [], best, best_j, edits, reason)


def _distance(a: Policy, b: Policy) -> int:
    """Number of differing places between two policies (a rough tree edit count)."""
    total = 0
    for tree in set(a.trees) | set(b.trees):
        x, y = a.trees.get(tree), b.trees.get(tree)
        total += _node_distance(x, y)
    return total


def _node_distance(x: PolicyNode | None, y: PolicyNode | None) -> int:
    if x is None or y is None:
        return 0 if x is y else 1
    if x.kind != y.kind or x.params != y.params:
        return 1
    if len(x.children) != len(y.children):
        # one child inserted or deleted counts once, plus differences among the aligned rest
        sm = difflib.SequenceMatcher(a=[_key(c) for c in x.children], b=[_key(c) for c in y.children])
        d = 0
        for op, i1, i2, j1, j2 in sm.get_opcodes():
            if op == "equal":
                continue
            if op == "replace" and i2 - i1 == j2 - j1:
                d += sum(_node_distance(x.children[i], y.children[j])
                         for i, j in zip(range(i1, i2), range(j1, j2), strict=True))
            else:
                d += max(i2 - i1, j2 - j1)
        return d
    return sum(_node_distance(c, d) for c, d in zip(x.children, y.children, strict=True))


def _key(n: PolicyNode) -> str:
    return f"{n.kind}{n.params}{len(n.children)}"


def classify_tasks(ids: Iterable[str], tasks_dir: str | Path | None = None, *,
                   worlds: int = DEFAULT_WORLDS) -> list[TaskMutants]:
    cat = load_catalog()
    return [classify_task(i, tasks_dir, cat, worlds=worlds) for i in ids]

