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
(no empty control node, IfThenElse keeps 2-3 children), and mutants whose XML equals the original
or an earlier mutant are dropped, so the list is the set of distinct first-order mutants.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from logicenveval.domain.actions import ACTIONS, CONDITIONS
from logicenveval.errors import PolicyFormatError
from logicenveval.sim.loader import policy_from_xml, policy_to_xml
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
    xml: str
    #: the smallest subtree (child indices within `location[0]`) that contains the whole edit
    anchor: tuple[int, ...] = ()


@dataclass(frozen=True, slots=True)
class _Edit:
    operator: str
    location: Location
    region: tuple[tuple[int, ...], ...]
    description: str
    new_root: PolicyNode
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
    """All distinct, valid first-order mutants of `policy`, in a deterministic order."""
    role_list = list(roles) if roles is not None else None
    room_list = list(rooms) if rooms is not None else None
    seen = {policy_to_xml(policy)}
    out: list[Mutant] = []
    for edit in _edits(policy):
        trees = dict(policy.trees)
        trees[edit.location[0]] = edit.new_root
        candidate = Policy(policy.main, trees, policy.source)
        xml = policy_to_xml(candidate)
        if xml in seen:
            continue
        try:
            policy_from_xml(xml, f"{policy.source}#{edit.operator}", roles=role_list, rooms=room_list)
        except PolicyFormatError:
            continue
        seen.add(xml)
        tree, idx = edit.location
        mid = f"{edit.operator}@{tree}:{'.'.join(map(str, idx)) or 'root'}"
        if edit.detail:
            mid += f":{edit.detail}"
        out.append(Mutant(mid, edit.operator, OPERATORS[edit.operator], edit.location, edit.region,
                          edit.description, candidate, xml, _anchor(edit)))
    return out


#: operators that change the children of the edited node's parent (the rest edit the node itself)
PARENT_EDITS = frozenset({"delete_precondition", "reorder_precondition", "drop_goal_action",
                           "delete_alternative"})


def _anchor(edit: _Edit) -> tuple[int, ...]:
    idx = edit.location[1]
    return idx[:-1] if edit.operator in PARENT_EDITS else idx


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


def _delete_child(root: PolicyNode, parent: tuple[int, ...], k: int) -> PolicyNode:
    return _replace(root, parent, lambda p: _with_children(
        p, [c for i, c in enumerate(p.children) if i != k]))


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
    # parent-relative edits: the node as a child of a sequence / fallback / IfThenElse
    if idx:
        parent_idx, k = idx[:-1], idx[-1]
        parent = _get(root, parent_idx)
        siblings = parent.children
        tail = tuple((*parent_idx, j) for j in range(k, len(siblings)))
        if parent.kind in _SEQUENCES and len(siblings) > 1:
            if kind in PRECONDITION_ACTIONS:
                yield _Edit("delete_precondition", loc, tail, f"delete {_show(node)}",
                            _delete_child(root, parent_idx, k))
                if k + 1 < len(siblings):
                    kids = list(siblings)
                    kids[k], kids[k + 1] = kids[k + 1], kids[k]
                    yield _Edit("reorder_precondition", loc, tail,
                                f"move {_show(node)} after {_show(siblings[k + 1])}",
                                _replace(root, parent_idx, _children_to(kids)))
            if kind in GOAL_ACTIONS:
                yield _Edit("drop_goal_action", loc, tail, f"delete {_show(node)}",
                            _delete_child(root, parent_idx, k))
        if parent.kind in _FALLBACKS and len(siblings) > 1:
            yield _Edit("delete_alternative", loc, tail,
                        f"delete alternative {k} ({_show(node)}) of {parent.kind}",
                        _delete_child(root, parent_idx, k))
        if parent.kind == "IfThenElse" and k == 2:
            yield _Edit("delete_alternative", loc, tail, "delete the else branch of IfThenElse",
                        _delete_child(root, parent_idx, k))
        if parent.kind == "IfThenElse" and k == 1 and len(siblings) == 3:
            cond, _, els = siblings
            yield _Edit("delete_alternative", loc, tail, "delete the then branch of IfThenElse",
                        _replace(root, parent_idx, _becomes("Sequence", (PolicyNode("Inverter", (), (cond,)), els))))
    if (kind in _FALLBACKS and len(node.children) == 2 and node.children[0].kind == "Inverter"
            and node.children[0].children[0].kind in CONDITIONS):
        cond, body = node.children[0].children[0], node.children[1]
        yield _Edit("delete_skip_branch", loc, (idx,), f"{kind}(not C, body) -> Sequence(C, body)",
                    _replace(root, idx, _becomes("Sequence", (cond, body))))
    if kind == "IfThenElse" and len(node.children) == 3:
        a, b, c = node.children
        yield _Edit("swap_branches", loc, ((*idx, 1), (*idx, 2)), "swap then / else branches",
                    _replace(root, idx, _children_to([a, c, b])))
    if kind in ACTIONS:
        port = "obj" if node.param("obj") is not None else None
        if port is not None:
            cur = node.param(port)
            for other in by_kind.get((kind, port), []):
                if other != cur:
                    yield _Edit("swap_object", loc, (idx,), f"{_show(node)} with obj={other}",
                                _replace(root, idx, _param_to("obj", other)), detail=other)
        if kind in ("Place", "PutIn"):
            cur = node.param("target")
            for other in by_kind.get((kind, "target"), []):
                if other != cur:
                    yield _Edit("change_destination", loc, (idx,), f"{_show(node)} to {other}",
                                _replace(root, idx, _param_to("target", other)), detail=other)
    if kind in CONDITIONS:
        for op, const in (("condition_true", "AlwaysSuccess"), ("condition_false", "AlwaysFailure")):
            yield _Edit(op, loc, (idx,), f"replace {_show(node)} by {const}",
                        _replace(root, idx, _becomes(const, ())))
        yield _Edit("invert_condition", loc, (idx,), f"invert {_show(node)}",
                    _replace(root, idx, _inverted))


def _get(root: PolicyNode, idx: tuple[int, ...]) -> PolicyNode:
    node = root
    for i in idx:
        node = node.children[i]
    return node


def _show(node: PolicyNode) -> str:
    ports = " ".join(f"{k}={v}" for k, v in node.params)
    return f"{node.kind}({ports})" if ports else node.kind

