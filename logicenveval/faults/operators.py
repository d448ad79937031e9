"""First-order mutation operators for BT.CPP policies, one family per fault class of the paper.

The paper's taxonomy (appendix): a *counterfactual* BT violates causal logic (places what it never
picked), an *unreachable* BT follows real-world logic but misses the goal in some situation, a
*lack-branch* BT omits some situation's branch. Each operator edits exactly one place of one
`BehaviorTree` of a `Policy`:

| class | operator | edit |
|---|---|---|
| counterfactual | `delete_precondition` | delete a Walk / Open / Pick / ToggleOff... that establishes a later action's precondition |
| counterfactual | `reorder_precondition` | move such an action after its next sibling |
| counterfactual | `swap_object` | give an action the object of another action of the same kind |
| unreachable | `change_destination` | give a Place / PutIn another destination used by the policy |
| unreachable | `swap_branches` | swap the then / else branches of an IfThenElse |
| unreachable | `drop_goal_action` | delete a Place / PutIn / Close / Toggle / Clean / Fill |
| lackbranch | `delete_alternative` | delete a Fallback alternative or an IfThenElse branch (then: the node becomes `Sequence(Inverter(C), else)`) |
| lackbranch | `delete_skip_branch` | `Fallback(Inverter(C), body)` ("if C do body") becomes `Sequence(C, body)`: no branch for not C |
| lackbranch | `condition_true` / `condition_false` | replace a condition by AlwaysSuccess / AlwaysFailure |
| lackbranch | `invert_condition` | wrap a condition in an Inverter |

A mutant is kept only when it still loads as valid BT.CPP v4 XML with the task's roles and rooms
(no empty control node, IfThenElse keeps 2-3 children), and mutants equal to the original or
to an earlier mutant are dropped, so the list is the set of distinct first-order mutants.
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from typing import Any, TypeVar

from logicenveval.domain.actions import ACTIONS, CONDITIONS
from logicenveval.limits import limit
from logicenveval.sim.loader import node_problem, policy_to_xml
from logicenveval.sim.policy import Policy, PolicyNode

FAULT_CLASSES = ("counterfactual", "unreachable", "lackbranch")

#: actions whose effect is another action's precondition (near, holding, open, hand empty)
PRECONDITION_ACTIONS = frozenset({"Walk", "Open", "Pick"})
#: actions whose effect is what a goal asks for
GOAL_ACTIONS = frozenset({"Place", "PutIn", "Close", "ToggleOn", "ToggleOff", "Clean", "Fill"})
_SEQUENCES = frozenset({"Sequence", "SequenceWithMemory", "ReactiveSequence"})
_FALLBACKS = frozenset({"Fallback", "ReactiveFallback"})

Location = tuple[str, tuple[int, ...]]  # (BehaviorTree ID, child indices from its root)


@dataclass(frozen=True, slots=True)
class Mutant:
    """One first-order mutant: `id` is stable (`operator@Tree:0.2.1[:detail]`)."""

    id: str
    operator: str
    fault_class: str
    location: Location
    #: child-index paths (within `location[0]`) whose execution the edit can change
    region: tuple[tuple[int, ...], ...]
    description: str
    #: the mutant (shares every unchanged node with the correct policy)
    policy: Policy
    #: the smallest subtree (child indices within `location[0]`) that contains the whole edit
    anchor: tuple[int, ...] = ()

    @property
    def xml(self) -> str:
        """The mutant as BT.CPP v4 XML (printed on demand: it is as large as the policy)."""
        return policy_to_xml(self.policy)


@dataclass(frozen=True, slots=True)
class _Edit:
    """One candidate edit, not yet applied: `change` turns the node at `anchor` into its
    replacement (built only when needed, so that listing the edits of a node with many
    children costs nothing per edit)."""

    operator: str
    location: Location
    #: child-index paths whose execution the edit can change; None: the edited node and its
    #: later siblings (listed when the mutant is built)
    region: tuple[tuple[int, ...], ...] | None
    description: str
    anchor: tuple[int, ...]
    change: Callable[[PolicyNode], PolicyNode]
    detail: str = ""


OPERATORS: dict[str, str] = {
    "delete_precondition": "counterfactual",
    "reorder_precondition": "counterfactual",
    "swap_object": "counterfactual",
    "change_destination": "unreachable",
    "swap_branches": "unreachable",
    "drop_goal_action": "unreachable",
    "delete_alternative": "lackbranch",
    "delete_skip_branch": "lackbranch",
    "condition_true": "lackbranch",
    "condition_false": "lackbranch",
    "invert_condition": "lackbranch",
}


def mutants(policy: Policy, *, roles: Iterable[str] | None = None,
            rooms: Iterable[str] | None = None) -> list[Mutant]:
    """All distinct, valid first-order mutants of `policy`, in a deterministic order (an evenly
    spaced sample of `max_mutants` of them when there are more; `sample`).

    Linear in the policy's size: an edit is checked on the nodes it makes, never on its whole
    tree. Validity is the loader's rules on the new nodes (`sim.loader.node_problem`; the
    rest is the correct policy's own, already loaded) plus the SubTree expansion budget, and
    duplicates are found by the exact shape of the smallest changed subtree (built on the
    shared nodes' interned ids). This gives the same list as printing and
    re-loading every mutant's XML, without doing so; only the mutants kept are built.
    """
    role_list = list(roles) if roles is not None else None
    room_list = list(rooms) if rooms is not None else None
    shapes = _Shapes(policy)
    budget = _Budget(policy)
    seen: dict[tuple[str, tuple[int, ...], int], list[_Edit]] = {}
    kept: list[_Edit] = []
    for edit in _edits(policy):
        tree = edit.location[0]
        changed = _changed(policy, edit, shapes)
        if changed is None:  # the correct policy itself
            continue
        at, new, old = changed
        shape = shapes.of(new)
        key = (tree, at, hash(shape))
        # kept edits hold no subtree (for a node with many children that would cost memory
        # per edit): an earlier one with the same hash is rebuilt to compare
        if any(_changed_shape(policy, other, shapes) == shape for other in seen.get(key, ())):
            continue
        if not budget.fits(tree, new, old) or any(
                node_problem(n, policy.trees, role_list, room_list) for n in shapes.new_nodes(new)):
            continue
        seen.setdefault(key, []).append(edit)
        kept.append(edit)
    return [_mutant(policy, edit) for edit in sample(kept, limit("max_mutants"))]


_T = TypeVar("_T")


def sample(items: list[_T], cap: int) -> list[_T]:
    """At most `cap` items, evenly spaced over the list (so over the trees and operators in
    proportion). Classifying a mutant runs it in every world and each run can cost the whole
    tree, so the mutants of ever larger BTs would cost quadratically; above the cap they cost
    linearly. Every shipped task has fewer mutants (at most 354; docs/faults.md)."""
    n = len(items)
    return items if n <= cap else [items[k * n // cap] for k in range(cap)]


def _mutant(policy: Policy, edit: _Edit) -> Mutant:
    tree, idx = edit.location
    old_root = policy.trees[tree]
    root = _replace(old_root, edit.anchor, edit.change)
    region = edit.region
    if region is None:
        parent_idx, k = idx[:-1], idx[-1]
        region = tuple((*parent_idx, j) for j in range(k, len(_get(old_root, parent_idx).children)))
    mid = f"{edit.operator}@{tree}:{'.'.join(map(str, idx)) or 'root'}"
    if edit.detail:
        mid += f":{edit.detail}"
    return Mutant(mid, edit.operator, OPERATORS[edit.operator], edit.location, region,
                  edit.description, Policy(policy.main, {**policy.trees, tree: root}, policy.source),
                  edit.anchor)


def _changed_shape(policy: Policy, edit: _Edit, shapes: _Shapes) -> Shape | None:
    changed = _changed(policy, edit, shapes)
    return None if changed is None else shapes.of(changed[1])


def _changed(policy: Policy, edit: _Edit,
             shapes: _Shapes) -> tuple[tuple[int, ...], PolicyNode, PolicyNode] | None:
    """(path, new subtree, old subtree) of the smallest subtree of the edited tree that holds
    every difference the edit makes, or None when the edit changes nothing."""
    at = edit.anchor
    old = _get(policy.trees[edit.location[0]], at)
    new = edit.change(old)
    while True:
        if (new.kind, new.params, new.name, len(new.children)) != (
                old.kind, old.params, old.name, len(old.children)):
            return at, new, old
        same = list(map(operator.is_, new.children, old.children))
        differ: list[int] = []
        i = -1
        for _ in range(same.count(False)):
            i = same.index(False, i + 1)
            if shapes.of(new.children[i]) != shapes.of(old.children[i]):
                differ.append(i)
        if not differ:
            return None
        if len(differ) > 1:
            return at, new, old
        i = differ[0]
        at, new, old = (*at, i), new.children[i], old.children[i]


#: a node's structure: the interned id of an equal node of the policy, else its own key
Shape = int | tuple[Any, ...]


class _Shapes:
    """Exact structural identity of policy nodes without comparing whole subtrees: the
    policy's own nodes are interned (equal subtrees get one id), a new node's shape is the
    tuple of its kind, parameters, name and children's shapes, found in the memo for every
    child it shares with the policy, so a shape costs the edit, not the tree."""

    def __init__(self, policy: Policy) -> None:
        self._table: dict[tuple[Any, ...], int] = {}
        self._ids: dict[int, int] = {}
        for root in policy.trees.values():
            self._intern(root)

    def _intern(self, node: PolicyNode) -> int:
        key = (node.kind, node.params, node.name, tuple(self._intern(c) for c in node.children))
        got = self._ids[id(node)] = self._table.setdefault(key, len(self._table))
        return got

    def of(self, node: PolicyNode) -> Shape:
        got = self._ids.get(id(node))
        if got is not None:
            return got
        kids = node.children
        shapes: list[Any] = list(map(self._ids.get, map(id, kids)))
        for i in _nones(shapes):
            shapes[i] = self.of(kids[i])
        key = (node.kind, node.params, node.name, tuple(shapes))
        return self._table.get(key, key)  # equal to a node of the policy: the same id

    def new_nodes(self, node: PolicyNode) -> list[PolicyNode]:
        """The nodes of `node`'s subtree that are not the policy's own."""
        if id(node) in self._ids:
            return []
        out = [node]
        kids = node.children
        for i in _nones(list(map(self._ids.get, map(id, kids)))):
            out += self.new_nodes(kids[i])
        return out


def _nones(values: list[Any]) -> list[int]:
    """Positions of None in `values` (searched in C: lists of children can be long)."""
    out: list[int] = []
    i = -1
    for _ in range(values.count(None)):
        i = values.index(None, i + 1)
        out.append(i)
    return out


class _Budget:
    """The loader's SubTree expansion budget (`max_subtree_nodes`) for a policy with one
    BehaviorTree replaced: that tree's expanded size changes, the trees it calls do not (no
    recursion), and the main tree grows by the change times the times it expands the tree."""

    def __init__(self, policy: Policy) -> None:
        self.policy = policy
        self.limit = limit("max_subtree_nodes")
        self._size: dict[int, int] = {}
        self.expanded = {t: self._expand(r) for t, r in policy.trees.items()}
        self.uses = self._uses()

    def _expand(self, node: PolicyNode) -> int:
        got = self._size.get(id(node))
        if got is None:
            got = 1 + sum(self._expand(c) for c in node.children)
            if node.kind == "SubTree":
                got += self._expand(self.policy.trees[node.param("ID") or ""])
            self._size[id(node)] = got
        return got

    def _uses(self) -> dict[str, int]:
        """How many times the main tree's expansion contains each tree (the main tree: once)."""
        calls: dict[str, dict[str, int]] = {}
        for t, root in self.policy.trees.items():
            row = calls[t] = {}
            for _, n in _walk(root):
                if n.kind == "SubTree":
                    sub = n.param("ID") or ""
                    row[sub] = row.get(sub, 0) + 1
        order: list[str] = []  # callees before callers (the loader refused recursion)
        done: set[str] = set()

        def visit(t: str) -> None:
            if t not in done:
                done.add(t)
                for sub in calls[t]:
                    visit(sub)
                order.append(t)

        visit(self.policy.main)
        uses = {t: 0 for t in order}
        uses[self.policy.main] = 1
        for t in reversed(order):
            for sub, k in calls[t].items():
                uses[sub] += uses[t] * k
        return uses

    def fits(self, tree: str, new: PolicyNode, old: PolicyNode) -> bool:
        """Whether the policy with `old` (a subtree of `tree`) replaced by `new` fits."""
        grown = self._expand_new(new) - self._expand(old)
        return self.expanded[self.policy.main] + grown * self.uses.get(tree, 0) <= self.limit

    def _expand_new(self, node: PolicyNode) -> int:
        got = self._size.get(id(node))
        if got is not None:
            return got
        kids = node.children
        sizes = list(map(self._size.get, map(id, kids)))
        total = 1 + sum(self._expand_new(kids[i]) for i in _nones(sizes)) + sum(filter(None, sizes))
        if node.kind == "SubTree":
            total += self.expanded[node.param("ID") or ""]
        return total


#: operators that change the children of the edited node's parent (the rest edit the node itself)
PARENT_EDITS = frozenset({"delete_precondition", "reorder_precondition", "drop_goal_action",
                           "delete_alternative"})


# ----- tree surgery ------------------------------------------------------------------------------

def _walk(node: PolicyNode, idx: tuple[int, ...] = ()) -> Iterator[tuple[tuple[int, ...], PolicyNode]]:
    yield idx, node
    for i, c in enumerate(node.children):
        yield from _walk(c, (*idx, i))


def _replace(node: PolicyNode, idx: tuple[int, ...], fn: Callable[[PolicyNode], PolicyNode]) -> PolicyNode:
    if not idx:
        return fn(node)
    kids = list(node.children)
    kids[idx[0]] = _replace(kids[idx[0]], idx[1:], fn)
    return PolicyNode(node.kind, node.params, tuple(kids), node.name, node.line)


def _with_children(node: PolicyNode, kids: list[PolicyNode]) -> PolicyNode:
    return PolicyNode(node.kind, node.params, tuple(kids), node.name, node.line)


def _with_param(node: PolicyNode, key: str, value: str) -> PolicyNode:
    params = tuple((k, value if k == key else v) for k, v in node.params)
    return PolicyNode(node.kind, params, node.children, node.name, node.line)


_Fn = Callable[[PolicyNode], PolicyNode]


def _children_to(kids: list[PolicyNode]) -> _Fn:
    return lambda n: _with_children(n, kids)


def _param_to(key: str, value: str) -> _Fn:
    return lambda n: _with_param(n, key, value)


def _becomes(kind: str, children: tuple[PolicyNode, ...]) -> _Fn:
    """The node replaced by a `kind` node (no ports) with `children`, keeping its name."""
    return lambda n: PolicyNode(kind, (), children, n.name, n.line)


def _inverted(n: PolicyNode) -> PolicyNode:
    return PolicyNode("Inverter", (), (n,), None, n.line)


def _without(k: int) -> _Fn:
    """The node without its child k."""
    return lambda p: _with_children(p, [*p.children[:k], *p.children[k + 1:]])


def _swapped(k: int) -> _Fn:
    """The node with its children k and k + 1 swapped."""
    return lambda p: _with_children(p, [*p.children[:k], p.children[k + 1], p.children[k],
                                        *p.children[k + 2:]])


def _edits(policy: Policy) -> Iterator[_Edit]:
    by_kind: dict[tuple[str, str], list[str]] = {}
    for root in policy.trees.values():
        for _, n in _walk(root):
            for port in ("obj", "target"):
                v = n.param(port)
                if v is not None and n.kind in ACTIONS:
                    names = by_kind.setdefault((n.kind, port), [])
                    if v not in names:
                        names.append(v)
    for tree_id, root in policy.trees.items():
        for idx, node in _walk(root):
            yield from _node_edits(tree_id, root, idx, node, by_kind)


def _node_edits(tree_id: str, root: PolicyNode, idx: tuple[int, ...], node: PolicyNode,
                by_kind: dict[tuple[str, str], list[str]]) -> Iterator[_Edit]:
    loc: Location = (tree_id, idx)
    kind = node.kind
    # parent-relative edits: the node as a child of a sequence / fallback / IfThenElse; they
    # change the parent (the anchor), and can change the node and its later siblings
    if idx:
        parent_idx, k = idx[:-1], idx[-1]
        parent = _get(root, parent_idx)
        siblings = parent.children
        if parent.kind in _SEQUENCES and len(siblings) > 1:
            if kind in PRECONDITION_ACTIONS:
                yield _Edit("delete_precondition", loc, None, f"delete {_show(node)}", parent_idx,
                            _without(k))
                if k + 1 < len(siblings):
                    yield _Edit("reorder_precondition", loc, None,
                                f"move {_show(node)} after {_show(siblings[k + 1])}", parent_idx,
                                _swapped(k))
            if kind in GOAL_ACTIONS:
                yield _Edit("drop_goal_action", loc, None, f"delete {_show(node)}", parent_idx,
                            _without(k))
        if parent.kind in _FALLBACKS and len(siblings) > 1:
            yield _Edit("delete_alternative", loc, None,
                        f"delete alternative {k} ({_show(node)}) of {parent.kind}", parent_idx,
                        _without(k))
        if parent.kind == "IfThenElse" and k == 2:
            yield _Edit("delete_alternative", loc, None, "delete the else branch of IfThenElse",
                        parent_idx, _without(k))
        if parent.kind == "IfThenElse" and k == 1 and len(siblings) == 3:
            cond, _, els = siblings
            yield _Edit("delete_alternative", loc, None, "delete the then branch of IfThenElse",
                        parent_idx, _becomes("Sequence", (PolicyNode("Inverter", (), (cond,)), els)))
    if (kind in _FALLBACKS and len(node.children) == 2 and node.children[0].kind == "Inverter"
            and node.children[0].children[0].kind in CONDITIONS):
        cond, body = node.children[0].children[0], node.children[1]
        yield _Edit("delete_skip_branch", loc, (idx,), f"{kind}(not C, body) -> Sequence(C, body)",
                    idx, _becomes("Sequence", (cond, body)))
    if kind == "IfThenElse" and len(node.children) == 3:
        a, b, c = node.children
        yield _Edit("swap_branches", loc, ((*idx, 1), (*idx, 2)), "swap then / else branches", idx,
                    _children_to([a, c, b]))
    if kind in ACTIONS:
        port = "obj" if node.param("obj") is not None else None
        if port is not None:
            cur = node.param(port)
            for other in by_kind.get((kind, port), []):
                if other != cur:
                    yield _Edit("swap_object", loc, (idx,), f"{_show(node)} with obj={other}", idx,
                                _param_to("obj", other), detail=other)
        if kind in ("Place", "PutIn"):
            cur = node.param("target")
            for other in by_kind.get((kind, "target"), []):
                if other != cur:
                    yield _Edit("change_destination", loc, (idx,), f"{_show(node)} to {other}", idx,
                                _param_to("target", other), detail=other)
    if kind in CONDITIONS:
        for op, const in (("condition_true", "AlwaysSuccess"), ("condition_false", "AlwaysFailure")):
            yield _Edit(op, loc, (idx,), f"replace {_show(node)} by {const}", idx,
                        _becomes(const, ()))
        yield _Edit("invert_condition", loc, (idx,), f"invert {_show(node)}", idx, _inverted)


def _get(root: PolicyNode, idx: tuple[int, ...]) -> PolicyNode:
    node = root
    for i in idx:
        node = node.children[i]
    return node


def _show(node: PolicyNode) -> str:
    ports = " ".join(f"{k}={v}" for k, v in node.params)
    return f"{node.kind}({ports})" if ports else node.kind

