"""Executable BT nodes with BehaviorTree.CPP v4 semantics (sequence_node.cpp, fallback_node.cpp,
reactive_*.cpp, if_then_else_node.cpp, while_do_else_node.cpp, parallel_node.cpp, decorators).

A policy is compiled once into these nodes; an episode binds a fresh `Episode` (world copy,
fault slot, optional trace) and ticks the root. Actions are asynchronous and take one tick: the
first tick checks the precondition and returns RUNNING, the next applies the effect and returns
SUCCESS, so every action costs one root tick and `tick_limit` bounds plan length and loops.
The first precondition violation stops the episode at once (it decides the verdict whatever
recovers from it later).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from logicenveval.domain.actions import ACTIONS, CONDITIONS, ActionSpec
from logicenveval.sim.policy import Policy, PolicyNode
from logicenveval.sim.world import World

IDLE, SUCCESS, FAILURE, RUNNING = 0, 1, 2, 3
STATUS_NAMES = ("IDLE", "SUCCESS", "FAILURE", "RUNNING")
#: node ticks allowed within one episode, so that a loop that never returns RUNNING
#: (e.g. RetryUntilSuccessful num_attempts=-1 over a failing condition) still ends
STEP_BUDGET = 100_000


class Violation(Exception):  # noqa: N818
    """Internal signal: a precondition failed; it ends the episode (never leaves `sim`)."""

    def __init__(self, node: Leaf, message: str) -> None:
        super().__init__(message)
        self.node = node
        self.message = message


class BudgetExceeded(Exception):  # noqa: N818
    """Internal signal: a loop inside one tick used up `STEP_BUDGET` node ticks."""


@dataclass(slots=True)
class Episode:
    """Per-run state shared by all nodes during one episode."""

    world: World
    tick: int = 0
    steps: int = 0
    trace: list[dict[str, Any]] | None = None
    last_fail: Node | None = field(default=None)


class Node:
    __slots__ = ("label", "path", "name", "status")

    def __init__(self, label: str, path: str, name: str | None) -> None:
        self.label = label
        self.path = path
        self.name = name
        self.status = IDLE

    def tick(self, ep: Episode) -> int:
        st = self._tick(ep)
        self.status = st
        return st

    def _tick(self, ep: Episode) -> int:
        raise NotImplementedError

    def halt(self) -> None:
        """Interrupt a RUNNING node (BT.CPP `haltNode`)."""

    def reset_all(self) -> None:
        """Forget every bit of state, memory included (start of an episode)."""
        self.status = IDLE


def _reset(node: Node) -> None:
    """BT.CPP `resetChild`: halt the node only if it is RUNNING, then mark it IDLE; a
    finished SequenceWithMemory thus keeps its position."""
    if node.status == RUNNING:
        node.halt()
    node.status = IDLE


class Leaf(Node):
    __slots__ = ()


class ActionNode(Leaf):
    __slots__ = ("spec", "args", "running")

    def __init__(self, label: str, path: str, name: str | None, spec: ActionSpec,
                 args: dict[str, str]) -> None:
        super().__init__(label, path, name)
        self.spec = spec
        self.args = args
        self.running = False

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        why = self.spec.check(ep.world, self.args)
        if why is not None:
            self.running = False
            if ep.trace is not None:
                ep.trace.append(_event(ep, self, "violation", why))
            raise Violation(self, why)
        if not self.running:
            self.running = True
            if ep.trace is not None:
                ep.trace.append(_event(ep, self, "RUNNING"))
            return RUNNING
        self.running = False
        self.spec.apply(ep.world, self.args)
        if ep.trace is not None:
            ep.trace.append(_event(ep, self, "SUCCESS"))
        return SUCCESS

    def halt(self) -> None:
        self.running = False

    def reset_all(self) -> None:
        self.status = IDLE
        self.running = False


class ConditionNode(Leaf):
    __slots__ = ("predicate", "args")

    def __init__(self, label: str, path: str, name: str | None, predicate: str,
                 args: tuple[str, ...]) -> None:
        super().__init__(label, path, name)
        self.predicate = predicate
        self.args = args

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        st = SUCCESS if ep.world.holds(self.predicate, self.args) else FAILURE
        if st == FAILURE:
            ep.last_fail = self
        if ep.trace is not None:
            ep.trace.append(_event(ep, self, STATUS_NAMES[st]))
        return st


class ConstNode(Leaf):
    __slots__ = ("value",)

    def __init__(self, label: str, path: str, name: str | None, value: int) -> None:
        super().__init__(label, path, name)
        self.value = value

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        if self.value == FAILURE:
            ep.last_fail = self
        return self.value


def _event(ep: Episode, node: Node, status: str, detail: str | None = None) -> dict[str, Any]:
    ev: dict[str, Any] = {"tick": ep.tick, "node": node.name or node.label, "path": node.path,
                          "status": status}
    if detail is not None:
        ev["detail"] = detail
    return ev


class Control(Node):
    __slots__ = ("children", "idx")

    def __init__(self, label: str, path: str, name: str | None, children: list[Node]) -> None:
        super().__init__(label, path, name)
        self.children = children
        self.idx = 0

    def halt(self) -> None:
        self.idx = 0
        for c in self.children:
            _reset(c)

    def reset_all(self) -> None:
        self.status = IDLE
        self.idx = 0
        for c in self.children:
            c.reset_all()

    def _halt_others(self, keep: int) -> None:
        for i, c in enumerate(self.children):
            if i != keep:
                _reset(c)


class Sequence(Control):
    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        kids = self.children
        while self.idx < len(kids):
            st = kids[self.idx].tick(ep)
            if st == RUNNING:
                return RUNNING
            if st == FAILURE:
                self.halt()
                return FAILURE
            self.idx += 1
        self.halt()
        return SUCCESS


class SequenceWithMemory(Control):
    """Like Sequence, but after a FAILURE the next tick resumes at the failed child."""

    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        kids = self.children
        while self.idx < len(kids):
            st = kids[self.idx].tick(ep)
            if st == RUNNING:
                return RUNNING
            if st == FAILURE:
                for c in kids[self.idx:]:
                    _reset(c)
                return FAILURE
            self.idx += 1
        self.halt()
        return SUCCESS


class Fallback(Control):
    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        kids = self.children
        while self.idx < len(kids):
            st = kids[self.idx].tick(ep)
            if st == RUNNING:
                return RUNNING
            if st == SUCCESS:
                self.halt()
                return SUCCESS
            self.idx += 1
        self.halt()
        return FAILURE


class ReactiveSequence(Control):
    """Re-ticks every child from the first on each tick; a RUNNING child halts the others."""

    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        for i, c in enumerate(self.children):
            st = c.tick(ep)
            if st == RUNNING:
                self._halt_others(i)
                return RUNNING
            if st == FAILURE:
                self.halt()
                return FAILURE
        self.halt()
        return SUCCESS


class ReactiveFallback(Control):
    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        for i, c in enumerate(self.children):
            st = c.tick(ep)
            if st == RUNNING:
                self._halt_others(i)
                return RUNNING
            if st == SUCCESS:
                self.halt()
                return SUCCESS
        self.halt()
        return FAILURE


class IfThenElse(Control):
    """The condition is ticked once; then the chosen branch runs to completion.

    With only two children a false condition returns FAILURE (BT.CPP).
    """

    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        kids = self.children
        if self.idx == 0:
            st = kids[0].tick(ep)
            if st == RUNNING:
                return RUNNING
            if st == SUCCESS:
                self.idx = 1
            elif len(kids) == 3:
                self.idx = 2
            else:
                self.halt()
                return FAILURE
        st = kids[self.idx].tick(ep)
        if st == RUNNING:
            return RUNNING
        self.halt()
        return st


class WhileDoElse(Control):
    """Re-checks the condition every tick and halts the branch that is no longer chosen."""

    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        kids = self.children
        cond = kids[0].tick(ep)
        if cond == RUNNING:
            return RUNNING
        if cond == SUCCESS:
            if len(kids) == 3:
                _reset(kids[2])
            st = kids[1].tick(ep)
        elif len(kids) == 3:
            _reset(kids[1])
            st = kids[2].tick(ep)
        else:
            st = FAILURE
        if st == RUNNING:
            return RUNNING
        self.halt()
        return st


class Parallel(Control):
    """Ticks every unfinished child; SUCCESS at `success_count` successes, FAILURE when
    `failure_count` children failed or success became impossible (negative counts mean
    "all but |n|-1")."""

    __slots__ = ("succ_needed", "fail_needed", "done", "n_succ", "n_fail")

    def __init__(self, label: str, path: str, name: str | None, children: list[Node],
                 success_count: int, failure_count: int) -> None:
        super().__init__(label, path, name, children)
        n = len(children)
        self.succ_needed = n + success_count + 1 if success_count < 0 else success_count
        self.fail_needed = n + failure_count + 1 if failure_count < 0 else failure_count
        self.done: set[int] = set()
        self.n_succ = 0
        self.n_fail = 0

    def halt(self) -> None:
        super().halt()
        self.done = set()
        self.n_succ = self.n_fail = 0

    def reset_all(self) -> None:
        super().reset_all()
        self.done = set()
        self.n_succ = self.n_fail = 0

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        n = len(self.children)
        for i, c in enumerate(self.children):
            if i in self.done:
                continue
            st = c.tick(ep)
            if st == SUCCESS:
                self.done.add(i)
                self.n_succ += 1
            elif st == FAILURE:
                self.done.add(i)
                self.n_fail += 1
            if self.n_succ >= self.succ_needed:
                self.halt()
                return SUCCESS
            if n - self.n_fail < self.succ_needed or self.n_fail == self.fail_needed:
                self.halt()
                return FAILURE
        return RUNNING


class Decorator(Node):
    __slots__ = ("child",)

    def __init__(self, label: str, path: str, name: str | None, child: Node) -> None:
        super().__init__(label, path, name)
        self.child = child

    def halt(self) -> None:
        _reset(self.child)

    def reset_all(self) -> None:
        self.status = IDLE
        self.child.reset_all()


class Inverter(Decorator):
    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        st = self.child.tick(ep)
        return FAILURE if st == SUCCESS else SUCCESS if st == FAILURE else st


class ForceSuccess(Decorator):
    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        st = self.child.tick(ep)
        return RUNNING if st == RUNNING else SUCCESS


class ForceFailure(Decorator):
    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        st = self.child.tick(ep)
        return RUNNING if st == RUNNING else FAILURE


class SubTree(Decorator):
    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        return self.child.tick(ep)


class _CountedLoop(Decorator):
    """Re-ticks its child up to `limit` times (< 0: forever); `stop_on` ends the loop at once.

    RetryUntilSuccessful and Repeat are the same loop with the child's statuses swapped.
    """

    __slots__ = ("limit", "count")
    stop_on: int
    exhausted: int

    def __init__(self, label: str, path: str, name: str | None, child: Node, limit: int) -> None:
        super().__init__(label, path, name, child)
        self.limit = limit
        self.count = 0

    def halt(self) -> None:
        self.count = 0
        _reset(self.child)

    def reset_all(self) -> None:
        self.count = 0
        super().reset_all()

    def _tick(self, ep: Episode) -> int:
        while self.limit < 0 or self.count < self.limit:
            ep.steps += 1
            if ep.steps > STEP_BUDGET:
                raise BudgetExceeded
            st = self.child.tick(ep)
            if st == RUNNING:
                return RUNNING
            if st == self.stop_on:
                self.halt()
                return self.stop_on
            self.count += 1
            _reset(self.child)
        self.halt()
        return self.exhausted


class RetryUntilSuccessful(_CountedLoop):
    __slots__ = ()
    stop_on = SUCCESS
    exhausted = FAILURE


class Repeat(_CountedLoop):
    __slots__ = ()
    stop_on = FAILURE
    exhausted = SUCCESS


class KeepRunningUntilFailure(Decorator):
    __slots__ = ()

    def _tick(self, ep: Episode) -> int:
        ep.steps += 1
        st = self.child.tick(ep)
        if st == SUCCESS:
            _reset(self.child)
            return RUNNING
        if st == FAILURE:
            _reset(self.child)
            return FAILURE
        return RUNNING


_COMPOSITE_CLASSES: dict[str, type[Control]] = {
    "Sequence": Sequence, "SequenceWithMemory": SequenceWithMemory, "Fallback": Fallback,
    "ReactiveSequence": ReactiveSequence, "ReactiveFallback": ReactiveFallback,
    "IfThenElse": IfThenElse, "WhileDoElse": WhileDoElse,
}
_SIMPLE_DECORATORS: dict[str, type[Decorator]] = {
    "Inverter": Inverter, "ForceSuccess": ForceSuccess, "ForceFailure": ForceFailure,
    "KeepRunningUntilFailure": KeepRunningUntilFailure,
}


def compile_policy(policy: Policy) -> Node:
    """Executable node tree of the policy's main tree (SubTrees expanded in place)."""
    root = policy.trees[policy.main]
    return _build(policy, root, f"{policy.main}/{root.label}")


def _build(policy: Policy, p: PolicyNode, path: str) -> Node:
    kind, name = p.kind, p.name
    kids = [_build(policy, c, f"{path}/{c.label}[{i}]") for i, c in enumerate(p.children)]
    if kind in ACTIONS:
        return ActionNode(kind, path, name, ACTIONS[kind], dict(p.params))
    if kind in CONDITIONS:
        spec = CONDITIONS[kind]
        args = dict(p.params)
        return ConditionNode(kind, path, name, spec.predicate, tuple(args[k] for k in spec.ports))
    if kind == "AlwaysSuccess":
        return ConstNode(kind, path, name, SUCCESS)
    if kind == "AlwaysFailure":
        return ConstNode(kind, path, name, FAILURE)
    if kind == "SubTree":
        sub = p.param("ID") or ""
        sub_root = policy.trees[sub]
        return SubTree(p.label, path, name, _build(policy, sub_root, f"{path}/{sub_root.label}"))
    if kind in _COMPOSITE_CLASSES:
        return _COMPOSITE_CLASSES[kind](kind, path, name, kids)
    if kind == "Parallel":
        return Parallel(kind, path, name, kids, int(p.param("success_count") or -1),
                        int(p.param("failure_count") or 1))
    if kind == "RetryUntilSuccessful":
        return RetryUntilSuccessful(kind, path, name, kids[0], int(p.param("num_attempts") or 0))
    if kind == "Repeat":
        return Repeat(kind, path, name, kids[0], int(p.param("num_cycles") or 0))
    return _SIMPLE_DECORATORS[kind](kind, path, name, kids[0])
