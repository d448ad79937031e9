"""A parsed Behavior Tree policy: plain immutable data, independent of XML and of execution.

The loader produces it, the exporter prints it back to BT.CPP v4 XML and the simulator compiles
it into executable nodes. Line numbers are kept for messages but not compared, so a policy that
was exported and re-loaded equals the original.
"""

from __future__ import annotations

from dataclasses import dataclass, field

#: control nodes with any number (>= 1) of children
COMPOSITES = frozenset({"Sequence", "SequenceWithMemory", "Fallback", "ReactiveSequence",
                        "ReactiveFallback", "Parallel", "AsyncSequence", "AsyncFallback",
                        "TryCatch"})
#: control nodes with a condition child and one or two branches
BRANCHING = frozenset({"IfThenElse", "WhileDoElse"})
#: nodes with exactly one child
DECORATORS = frozenset({"Inverter", "ForceSuccess", "ForceFailure", "RetryUntilSuccessful",
                        "Repeat", "KeepRunningUntilFailure"})
#: leaves without ports
CONSTANT_LEAVES = frozenset({"AlwaysSuccess", "AlwaysFailure"})
#: node parameters (not ports): node -> name -> (required, default); integers unless in
#: BOOL_PARAMS (stored as "true"/"false")
NODE_PARAMS: dict[str, dict[str, tuple[bool, int]]] = {
    "Parallel": {"success_count": (False, -1), "failure_count": (False, 1)},
    "RetryUntilSuccessful": {"num_attempts": (True, 0)},
    "Repeat": {"num_cycles": (True, 0)},
    "TryCatch": {"catch_on_halt": (False, 0)},
}
BOOL_PARAMS = frozenset({("TryCatch", "catch_on_halt")})
#: minimum number of children of a composite (BT.CPP's VerifyXML)
MIN_CHILDREN = {"TryCatch": 2}


def parallel_threshold(count: int, n_children: int) -> int:
    """BT.CPP's `successThreshold`/`failureThreshold` of a Parallel: a negative count means
    "all but |count|-1", clamped at 0."""
    return max(n_children + count + 1, 0) if count < 0 else count


@dataclass(frozen=True, slots=True)
class PolicyNode:
    """One XML element of a tree: `kind` is the node ID (`Sequence`, `Pick`, `SubTree`, ...)."""

    kind: str
    params: tuple[tuple[str, str], ...] = ()
    children: tuple[PolicyNode, ...] = ()
    name: str | None = None
    line: int = field(default=0, compare=False)

    def param(self, key: str) -> str | None:
        for k, v in self.params:
            if k == key:
                return v
        return None

    @property
    def label(self) -> str:
        if self.kind == "SubTree":
            return f"SubTree({self.param('ID')})"
        return self.kind


@dataclass(frozen=True, slots=True)
class Policy:
    """All BehaviorTrees of a policy file (includes merged) and the tree to execute."""

    main: str
    trees: dict[str, PolicyNode]
    source: str = field(default="<string>", compare=False)
    #: what the loader accepted but wants the author to know (e.g. a missing BTCPP_format)
    warnings: tuple[str, ...] = field(default=(), compare=False)

    def __hash__(self) -> int:
        return hash((self.main, tuple(sorted(self.trees))))
