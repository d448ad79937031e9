"""BehaviorTree.CPP v4 XML <-> py_trees trees.

XML is parsed (defusedxml) and checked into an immutable `Policy` first, so every format error
names its line; the policy is then built into py_trees behaviours (`sim.nodes`), which is what
the simulator ticks. Export reads a built tree back into a policy and prints v4 XML, so
XML -> py_trees -> XML is the identity on the policy.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

import py_trees

from logicenveval.sim.loader import load_policy, policy_from_xml, policy_to_xml
from logicenveval.sim.nodes import BTNode, build_tree, tree_to_policy


def load_tree(path: str | Path, roles: Iterable[str] | None = None,
              rooms: Iterable[str] | None = None) -> BTNode:
    """The main tree of a policy file as a py_trees tree (SubTrees expanded in place)."""
    return build_tree(load_policy(path, roles, rooms))


def tree_from_xml(text: str, source: str = "<string>", *, roles: Iterable[str] | None = None,
                  rooms: Iterable[str] | None = None) -> BTNode:
    return build_tree(policy_from_xml(text, source, roles=roles, rooms=rooms))


def tree_to_xml(root: BTNode) -> str:
    """BehaviorTree.CPP v4 XML of a tree built by `build_tree` (one BehaviorTree per SubTree ID)."""
    return policy_to_xml(tree_to_policy(root))


def unicode_tree(root: BTNode) -> str:
    """py_trees' unicode rendering (node names carry the BT.CPP IDs, ports and names)."""
    return str(py_trees.display.unicode_tree(root))
