"""A py_trees mirror of a policy, for display with py_trees' renderers (unicode, dot).

Execution uses `sim.nodes` (BT.CPP v4 semantics, which py_trees' composites do not share); this
mirror only carries the structure, with py_trees composites of the closest semantics and node
labels that keep the BT.CPP IDs and ports.
"""

from __future__ import annotations

import py_trees

from logicenveval.sim.policy import Policy, PolicyNode


def _label(node: PolicyNode) -> str:
    ports = ", ".join(f"{k}={v}" for k, v in node.params)
    text = f"{node.label}({ports})" if ports and node.kind != "SubTree" else node.label
    return f"{node.name}: {text}" if node.name else text


def _mirror(policy: Policy, node: PolicyNode) -> py_trees.behaviour.Behaviour:
    name, kind = _label(node), node.kind
    if kind == "SubTree":
        sub = node.param("ID") or ""
        return py_trees.decorators.PassThrough(name, _mirror(policy, policy.trees[sub]))
    kids = [_mirror(policy, c) for c in node.children]
    if kind in ("Sequence", "SequenceWithMemory", "ReactiveSequence", "IfThenElse",
                "WhileDoElse"):
        return py_trees.composites.Sequence(name, kind != "ReactiveSequence", kids)
    if kind in ("Fallback", "ReactiveFallback"):
        return py_trees.composites.Selector(name, kind == "Fallback", kids)
    if kind == "Parallel":
        return py_trees.composites.Parallel(name, py_trees.common.ParallelPolicy.SuccessOnAll(),
                                            kids)
    if kind == "Inverter":
        return py_trees.decorators.Inverter(name, kids[0])
    if kids:
        return py_trees.decorators.PassThrough(name, kids[0])
    return py_trees.behaviours.Dummy(name)


def to_py_trees(policy: Policy) -> py_trees.behaviour.Behaviour:
    """py_trees tree with the structure and labels of the policy's main tree."""
    return _mirror(policy, policy.trees[policy.main])


def unicode_tree(policy: Policy) -> str:
    return str(py_trees.display.unicode_tree(to_py_trees(policy)))
