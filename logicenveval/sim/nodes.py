"""py_trees behaviours with BehaviorTree.CPP v4 semantics (sequence_node.cpp, fallback_node.cpp,
reactive_*.cpp, if_then_else_node.cpp, while_do_else_node.cpp, parallel_node.cpp, decorators).

A policy is built once into a py_trees tree (`build_tree`); an episode binds a fresh `Episode`
(world copy, fault slot, optional trace) to the tree's shared `Binding` and ticks the root with
py_trees' generator protocol (`root.tick_once()`). Leaves are ordinary py_trees behaviours
(`initialise`/`update`); the control nodes override `tick()` like py_trees' own composites do,
because BT.CPP's index memory, `resetChild` (halt a child only if it is RUNNING, so a finished
`SequenceWithMemory` keeps its position), `IfThenElse`, `WhileDoElse` and `Parallel` thresholds
are not what py_trees' `Sequence`/`Selector`/`Parallel` do.

Actions are asynchronous and take one tick: the first tick checks the precondition and returns
RUNNING, the next re-checks it, applies the effect and returns SUCCESS, so every action costs one
root tick and `tick_limit` bounds plan length and loops. The first precondition violation stops
the episode at once (it decides the verdict whatever recovers from it later).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

import py_trees
from py_trees.common import Status

from logicenveval.domain.actions import ACTIONS, CONDITIONS, ActionSpec
from logicenveval.sim.policy import Policy, PolicyNode, parallel_threshold
from logicenveval.sim.world import World

IDLE, SUCCESS, FAILURE, RUNNING = Status.INVALID, Status.SUCCESS, Status.FAILURE, Status.RUNNING


class Violation(Exception):  # noqa: N818
    """Internal signal: a precondition failed; it ends the episode (never leaves `sim`)."""

    def __init__(self, node: BTNode, message: str) -> None:
        super().__init__(message)
        self.node = node
        self.message = message


@dataclass(slots=True)
class Episode:
    """Per-run state shared by all nodes during one episode."""

    world: World
    tick: int = 0
    trace: list[dict[str, Any]] | None = None
    last_fail: BTNode | None = field(default=None)
    #: paths whose port values the trace already holds (a node's ports are recorded on its first
    #: event only; readers carry them forward by path, so a long trace does not repeat them)
    traced_ports: set[str] = field(default_factory=set)
    #: when a list: every leaf tick as (root tick, leaf, status), action/condition/constant alike
    #: (mutation scoring reads which nodes an episode entered, and when)
    ticks: list[tuple[int, BTNode, Status]] | None = None


class Binding:
    """The slot through which every node of one tree reaches the current episode."""

    __slots__ = ("ep",)

    def __init__(self) -> None:
        self.ep: Episode | None = None

    @property
    def episode(self) -> Episode:
        if self.ep is None:
            raise RuntimeError("tick the tree through CompiledPolicy.run, which binds an episode")
        return self.ep


class BTNode(py_trees.behaviour.Behaviour):
    """What every node adds to py_trees' Behaviour: its BT.CPP identity, for faults and export.

    `kind` is the BT.CPP node ID, `params` its ports/parameters, `bt_name` its `name` attribute,
    `path` the fault path (`Tree/Node[i]/...`) and `tree_id` the BehaviorTree ID of a tree root.
    """

    kind: str
    params: tuple[tuple[str, str], ...]
    bt_name: str | None
    path: str
    binding: Binding
    tree_id: str | None
    ports: str

    def setup_bt(self, p: PolicyNode, path: str, binding: Binding) -> None:
        self.kind, self.params, self.bt_name = p.kind, p.params, p.name
        self.path, self.binding, self.tree_id = path, binding, None
        #: the ports a trace shows beside the node (`target=kitchen`): what the node acted on
        self.ports = " ".join(f"{k}={v}" for k, v in p.params) if p.kind != "SubTree" else ""

    @property
    def label(self) -> str:
        """The node's ID as fault paths spell it (`SubTree(ID)` for a SubTree)."""
        return f"SubTree({self.param('ID')})" if self.kind == "SubTree" else self.kind

    def param(self, key: str) -> str | None:
        return next((v for k, v in self.params if k == key), None)

    def reset_all(self) -> None:
        """Forget every bit of state, memory included (start of an episode)."""
        self.status = IDLE

    def state(self) -> Any:
        """Everything ticks change in this node (with `restore`: resume an episode mid-way)."""
        return self.status

    def restore(self, state: Any) -> None:
        self.status = state


def display_name(p: PolicyNode) -> str:
    """py_trees name of a node: BT.CPP ID with its ports, prefixed by its `name` attribute."""
    ports = ", ".join(f"{k}={v}" for k, v in p.params)
    text = f"{p.label}({ports})" if ports and p.kind != "SubTree" else p.label
    return f"{p.name}: {text}" if p.name else text


def _reset(node: py_trees.behaviour.Behaviour) -> None:
    """BT.CPP `resetChild`: halt the node only if it is RUNNING, then mark it IDLE; a finished
    SequenceWithMemory thus keeps its position."""
    if node.status is RUNNING:
        node.stop(IDLE)
    node.status = IDLE


def _event(ep: Episode, node: BTNode, status: str, detail: str | None = None) -> dict[str, Any]:
    ev: dict[str, Any] = {"tick": ep.tick, "node": node.bt_name or node.kind, "path": node.path,
                          "status": status}
    if node.ports and node.path not in ep.traced_ports:
        ep.traced_ports.add(node.path)
        ev["ports"] = node.ports
    if detail is not None:
        ev["detail"] = detail
    return ev


class Leaf(BTNode):
    """py_trees' leaf lifecycle (`initialise` unless RUNNING, `update`, `terminate` when done)
    without its per-tick debug-string formatting and generator re-creation, which cost more
    than the action itself; nodes still tick through py_trees' generator protocol."""

    #: BT.CPP `StatefulActionNode::tick`: a finished action that nobody reset returns its
    #: status again without running (an action in the condition slot of `WhileDoElse`, or of
    #: an `IfThenElse` that failed on it, stays finished until a parent resets it); conditions
    #: and `AlwaysSuccess`/`AlwaysFailure` are evaluated on every tick
    keeps_result: bool = False
    #: whether the class overrides py_trees' `initialise` or `terminate` (no-ops otherwise,
    #: not called: a leaf tick is a few attribute reads, two calls were a fifth of it)
    hooks: bool = False

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        base = py_trees.behaviour.Behaviour
        cls.hooks = cls.initialise is not base.initialise or cls.terminate is not base.terminate

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        st = self.status
        if not (self.keeps_result and (st is SUCCESS or st is FAILURE)):
            if self.hooks:
                if st is not RUNNING:
                    self.initialise()
                st = self.update()
                if st is not RUNNING:
                    self.terminate(st)
            else:
                st = self.update()
            self.status = st
        ep = self.binding.ep
        if ep is not None and ep.ticks is not None:
            ep.ticks.append((ep.tick, self, st))
        yield self

    def stop(self, new_status: Status = IDLE) -> None:
        self.terminate(new_status)
        self.status = new_status


class ActionNode(Leaf):
    """An action of the library: `initialise` is BT.CPP's onStart, a RUNNING `update` onRunning."""

    keeps_result = True

    def __init__(self, name: str, spec: ActionSpec, args: dict[str, str]) -> None:
        super().__init__(name)
        self.spec = spec
        self.args = args

    def update(self) -> Status:
        ep = self.binding.episode
        why = self.spec.check(ep.world, self.args)
        if why is not None:
            if ep.trace is not None:
                ep.trace.append(_event(ep, self, "violation", why))
            raise Violation(self, why)
        if self.status is not RUNNING:
            if ep.trace is not None:
                ep.trace.append(_event(ep, self, "RUNNING"))
            return RUNNING
        self.spec.apply(ep.world, self.args)
        if ep.trace is not None:
            ep.trace.append(_event(ep, self, "SUCCESS"))
        return SUCCESS


class ConditionNode(Leaf):
    def __init__(self, name: str, predicate: str, args: tuple[str, ...]) -> None:
        super().__init__(name)
        self.predicate = predicate
        self.args = args

    def update(self) -> Status:
        ep = self.binding.episode
        st = SUCCESS if ep.world.holds(self.predicate, self.args) else FAILURE
        if st is FAILURE:
            ep.last_fail = self
        if ep.trace is not None:
            ep.trace.append(_event(ep, self, st.value))
        return st


class ConstNode(Leaf):
    """AlwaysSuccess / AlwaysFailure."""

    def __init__(self, name: str, value: Status) -> None:
        super().__init__(name)
        self.value = value

    def update(self) -> Status:
        ep = self.binding.episode
        if self.value is FAILURE:
            ep.last_fail = self
        return self.value


class Control(BTNode, py_trees.composites.Composite):
    """A BT.CPP control node; `idx` is its position memory, `stop` is BT.CPP's `halt`.

    Sequences, fallbacks and Parallel also derive from py_trees' Sequence/Selector/Parallel so
    py_trees' renderers and visitors classify them, but none of their methods run: `tick` and
    `stop` here (and `__init__`) take precedence.
    """

    def __init__(self, name: str, children: list[py_trees.behaviour.Behaviour]) -> None:
        py_trees.composites.Composite.__init__(self, name, children)
        self.idx = 0

    def stop(self, new_status: Status = IDLE) -> None:
        self.idx = 0
        for c in self.children:
            _reset(c)
        self.status = new_status

    def reset_all(self) -> None:
        self.status = IDLE
        self.idx = 0

    def state(self) -> Any:
        return self.status, self.idx

    def restore(self, state: Any) -> None:
        self.status, self.idx = state

    def _halt_others(self, keep: int) -> None:
        for i, c in enumerate(self.children):
            if i != keep:
                _reset(c)


class _Ordered(Control):
    """Ticks children in order from the remembered index; `decisive` ends the node at once.

    Sequence and Fallback are the same loop with the child's statuses swapped.
    """

    decisive: Status
    exhausted: Status

    #: BT.CPP's interruptible loop: after a child that finished synchronously (it was IDLE
    #: before this tick) with the non-decisive status, return RUNNING before the next child
    #: (AsyncSequence, AsyncFallback, SequenceWithMemory; `requiresWakeUp()` is always true
    #: in a built BT.CPP tree)
    yields: bool = False

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        kids = self.children
        while self.idx < len(kids):
            child = kids[self.idx]
            before = child.status
            yield from child.tick()
            st = child.status
            if st is RUNNING:
                self.status = RUNNING
                yield self
                return
            if st is self.decisive:
                self.conclude(st)
                yield self
                return
            self.idx += 1
            if self.yields and before is IDLE and self.idx < len(kids):
                self.status = RUNNING
                yield self
                return
        self.idx = 0
        self.stop(self.exhausted)
        yield self

    def conclude(self, st: Status) -> None:
        """A decisive child status: halt (position back to the first child)."""
        self.stop(st)


class Sequence(_Ordered, py_trees.composites.Sequence):
    memory = True  # resumes at a RUNNING child (py_trees' meaning); restarts after FAILURE
    decisive, exhausted = FAILURE, SUCCESS


class AsyncSequence(Sequence):
    """Sequence that returns RUNNING between children finishing synchronously (BT.CPP 4)."""

    yields = True


class SequenceWithMemory(Sequence):
    """Like AsyncSequence, but after a FAILURE the next tick resumes at the failed child, and
    a halt keeps the position (BT.CPP's `SequenceWithMemory::halt` does not reset it)."""

    yields = True

    def conclude(self, st: Status) -> None:
        for c in self.children[self.idx:]:
            _reset(c)
        self.status = st

    def stop(self, new_status: Status = IDLE) -> None:
        for c in self.children:
            _reset(c)
        self.status = new_status


class Fallback(_Ordered, py_trees.composites.Selector):
    memory = True
    decisive, exhausted = SUCCESS, FAILURE


class AsyncFallback(Fallback):
    """Fallback that returns RUNNING between children failing synchronously (BT.CPP 4)."""

    yields = True


class TryCatch(Control):
    """BT.CPP 4.x `TryCatch`: all children but the last run as a Sequence (the try block);
    when one fails, the last child (catch) runs to completion and the node returns FAILURE.
    With `catch_on_halt`, a halt during the try block ticks the catch child once first."""

    def __init__(self, name: str, children: list[py_trees.behaviour.Behaviour],
                 catch_on_halt: bool) -> None:
        super().__init__(name, children)
        self.catch_on_halt = catch_on_halt
        self.in_catch = False

    def reset_all(self) -> None:
        super().reset_all()
        self.in_catch = False

    def state(self) -> Any:
        return self.status, self.idx, self.in_catch

    def restore(self, state: Any) -> None:
        self.status, self.idx, self.in_catch = state

    def stop(self, new_status: Status = IDLE) -> None:
        kids = self.children
        if self.catch_on_halt and not self.in_catch and self.status is RUNNING:
            for c in kids[:-1]:
                _reset(c)
            for _ in kids[-1].tick():
                pass
            if kids[-1].status is RUNNING:
                _reset(kids[-1])
        self.in_catch = False
        super().stop(new_status)

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        kids = self.children
        if self.status is not RUNNING:
            self.in_catch = False
        while not self.in_catch and self.idx < len(kids) - 1:
            child = kids[self.idx]
            yield from child.tick()
            st = child.status
            if st is RUNNING:
                self.status = RUNNING
                yield self
                return
            if st is FAILURE:
                for c in kids:
                    _reset(c)
                self.idx = 0
                self.in_catch = True
            else:
                self.idx += 1
        if not self.in_catch:
            self._finish(SUCCESS)
            yield self
            return
        catch = kids[-1]
        yield from catch.tick()
        if catch.status is RUNNING:
            self.status = RUNNING
        else:
            self._finish(FAILURE)
        yield self

    def _finish(self, st: Status) -> None:
        """Done (not halted): reset the children without running the catch-on-halt."""
        self.in_catch = False
        Control.stop(self, st)


class _Reactive(Control):
    """Re-ticks every child from the first on each tick; a RUNNING child halts the others.

    `decisive` is the child status that ends the node at once (FAILURE for ReactiveSequence).
    """

    decisive: Status
    exhausted: Status

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        for i, child in enumerate(self.children):
            yield from child.tick()
            st = child.status
            if st is RUNNING:
                self._halt_others(i)
                self.status = RUNNING
                yield self
                return
            if st is self.decisive:
                self.stop(st)
                yield self
                return
        self.stop(self.exhausted)
        yield self


class ReactiveSequence(_Reactive, py_trees.composites.Sequence):
    memory = False
    decisive, exhausted = FAILURE, SUCCESS


class ReactiveFallback(_Reactive, py_trees.composites.Selector):
    memory = False
    decisive, exhausted = SUCCESS, FAILURE


class IfThenElse(Control):
    """The condition is ticked once; then the chosen branch runs to completion.

    With only two children a false condition returns FAILURE (BT.CPP), leaving the condition
    finished: an action there is not run again until a halt or a finished branch resets it.
    """

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        kids = self.children
        if self.idx == 0:
            yield from kids[0].tick()
            st = kids[0].status
            if st is RUNNING:
                self.status = RUNNING
                yield self
                return
            if st is SUCCESS:
                self.idx = 1
            elif len(kids) == 3:
                self.idx = 2
            else:
                # BT.CPP returns FAILURE without `resetChildren`: the condition keeps its status
                self.status = FAILURE
                yield self
                return
        branch = kids[self.idx]
        yield from branch.tick()
        st = branch.status
        if st is RUNNING:
            self.status = RUNNING
        else:
            self.stop(st)
        yield self


class WhileDoElse(Control):
    """Re-checks the condition every tick and halts the branch that is no longer chosen.

    The condition is reset only when the node finishes or is halted, so an action there runs
    once and returns the same status while the branch is RUNNING (BT.CPP).
    """

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        kids = self.children
        yield from kids[0].tick()
        cond = kids[0].status
        if cond is RUNNING:
            self.status = RUNNING
            yield self
            return
        st = FAILURE
        if cond is SUCCESS:
            if len(kids) == 3:
                _reset(kids[2])
            yield from kids[1].tick()
            st = kids[1].status
        elif len(kids) == 3:
            _reset(kids[1])
            yield from kids[2].tick()
            st = kids[2].status
        if st is RUNNING:
            self.status = RUNNING
        else:
            self.stop(st)
        yield self


class Parallel(Control, py_trees.composites.Parallel):
    """Ticks every unfinished child; SUCCESS at `success_count` successes, FAILURE when
    `failure_count` children failed or success became impossible (negative counts mean
    "all but |n|-1")."""

    def __init__(self, name: str, children: list[py_trees.behaviour.Behaviour], success_count: int,
                 failure_count: int) -> None:
        super().__init__(name, children)
        n = len(children)
        self.succ_needed = parallel_threshold(success_count, n)
        self.fail_needed = parallel_threshold(failure_count, n)
        self.done: set[int] = set()
        self.n_succ = 0
        self.n_fail = 0

    def stop(self, new_status: Status = IDLE) -> None:
        super().stop(new_status)
        self.done = set()
        self.n_succ = self.n_fail = 0

    def reset_all(self) -> None:
        super().reset_all()
        self.done = set()
        self.n_succ = self.n_fail = 0

    def state(self) -> Any:
        return self.status, self.idx, frozenset(self.done), self.n_succ, self.n_fail

    def restore(self, state: Any) -> None:
        self.status, self.idx, done, self.n_succ, self.n_fail = state
        self.done = set(done)

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        n = len(self.children)
        for i, child in enumerate(self.children):
            if i in self.done:
                continue
            yield from child.tick()
            st = child.status
            if st is SUCCESS:
                self.done.add(i)
                self.n_succ += 1
            elif st is FAILURE:
                self.done.add(i)
                self.n_fail += 1
            if self.n_succ >= self.succ_needed:
                self.stop(SUCCESS)
                yield self
                return
            if n - self.n_fail < self.succ_needed or self.n_fail == self.fail_needed:
                self.stop(FAILURE)
                yield self
                return
        self.status = RUNNING
        yield self


class Decorator(BTNode, py_trees.decorators.Decorator):
    """A BT.CPP decorator; `stop` halts the child (BT.CPP `DecoratorNode::halt`)."""

    def __init__(self, name: str, child: py_trees.behaviour.Behaviour) -> None:
        py_trees.decorators.Decorator.__init__(self, name, child)

    def stop(self, new_status: Status = IDLE) -> None:
        _reset(self.decorated)
        self.status = new_status

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        yield from self.decorated.tick()
        st = self.map(self.decorated.status)
        if st is RUNNING:
            self.status = RUNNING
        else:
            self.stop(st)
        yield self

    def map(self, st: Status) -> Status:
        """The decorator's status for its child's."""
        return st

    def update(self) -> Status:
        """Not called: `tick` decides (py_trees declares `update` abstract for decorators)."""
        return self.status


class Inverter(Decorator):
    def map(self, st: Status) -> Status:
        return FAILURE if st is SUCCESS else SUCCESS if st is FAILURE else st


class ForceSuccess(Decorator):
    def map(self, st: Status) -> Status:
        return RUNNING if st is RUNNING else SUCCESS


class ForceFailure(Decorator):
    def map(self, st: Status) -> Status:
        return RUNNING if st is RUNNING else FAILURE


class SubTree(Decorator):
    """The root of another BehaviorTree of the file, expanded in place (BT.CPP `SubTree`)."""

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        """`Decorator.tick` with the identity `map` left out (a SubTree ticks on every path)."""
        yield from self.decorated.tick()
        st = self.decorated.status
        if st is RUNNING:
            self.status = RUNNING
        else:
            self.stop(st)
        yield self


class KeepRunningUntilFailure(Decorator):
    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        yield from self.decorated.tick()
        st = self.decorated.status
        if st is RUNNING:
            self.status = RUNNING
        else:
            _reset(self.decorated)
            self.status = RUNNING if st is SUCCESS else FAILURE
        yield self


class _CountedLoop(Decorator):
    """Re-ticks its child up to `limit` times (-1: forever, other negatives: never, as in
    BT.CPP); `stop_on` ends the loop at once.

    RetryUntilSuccessful and Repeat are the same loop with the child's statuses swapped.
    """

    stop_on: Status
    exhausted: Status

    def __init__(self, name: str, child: py_trees.behaviour.Behaviour, limit: int) -> None:
        super().__init__(name, child)
        self.limit = limit
        self.count = 0

    def stop(self, new_status: Status = IDLE) -> None:
        self.count = 0
        super().stop(new_status)

    def reset_all(self) -> None:
        self.count = 0
        self.status = IDLE

    def state(self) -> Any:
        return self.status, self.count

    def restore(self, state: Any) -> None:
        self.status, self.count = state

    def tick(self) -> Iterator[py_trees.behaviour.Behaviour]:
        child = self.decorated
        while self.limit == -1 or self.count < self.limit:
            before = child.status
            yield from child.tick()
            st = child.status
            if st is RUNNING:
                self.status = RUNNING
                yield self
                return
            if st is self.stop_on:
                self.stop(st)
                yield self
                return
            self.count += 1
            _reset(child)
            if before is IDLE and (self.limit == -1 or self.count < self.limit):
                # BT.CPP 4.x: a child that finished synchronously returns the flow to the
                # parent before the next iteration (an interruptible loop)
                self.status = RUNNING
                yield self
                return
        self.stop(self.exhausted)
        yield self


class RetryUntilSuccessful(_CountedLoop):
    stop_on, exhausted = SUCCESS, FAILURE


class Repeat(_CountedLoop):
    stop_on, exhausted = FAILURE, SUCCESS


_COMPOSITE_CLASSES: dict[str, type[Control]] = {
    "Sequence": Sequence, "SequenceWithMemory": SequenceWithMemory, "Fallback": Fallback,
    "AsyncSequence": AsyncSequence, "AsyncFallback": AsyncFallback,
    "ReactiveSequence": ReactiveSequence, "ReactiveFallback": ReactiveFallback,
    "IfThenElse": IfThenElse, "WhileDoElse": WhileDoElse,
}
_SIMPLE_DECORATORS: dict[str, type[Decorator]] = {
    "Inverter": Inverter, "ForceSuccess": ForceSuccess, "ForceFailure": ForceFailure,
    "KeepRunningUntilFailure": KeepRunningUntilFailure,
}


#: builds the node of an action/condition leaf from its policy node and py_trees name
LeafFactory = Callable[[PolicyNode, str], "BTNode"]


#: an already built node to use for a policy node (None: build it)
Reuse = Callable[[PolicyNode], "BTNode | None"]


def build_tree(policy: Policy, binding: Binding | None = None,
               leaves: LeafFactory | None = None, reuse: Reuse | None = None) -> BTNode:
    """The policy's main tree as py_trees behaviours (SubTrees expanded in place), all sharing
    `binding` (a new one if not given; reach it as `root.binding`). `leaves` replaces the action
    library's leaves (the BT.CPP conformance corpus runs scripted stubs through it); `reuse`
    supplies built subtrees (a mutant's edited subtree shares its unchanged children with the
    correct BT's tree)."""
    root = policy.trees[policy.main]
    node = _build(policy, root, f"{policy.main}/{root.label}", binding or Binding(), leaves, reuse)
    node.tree_id = policy.main
    return node


def _build(policy: Policy, p: PolicyNode, path: str, binding: Binding,
           leaves: LeafFactory | None, reuse: Reuse | None = None) -> BTNode:
    if reuse is not None:
        got = reuse(p)
        if got is not None:
            return got
    kind, name = p.kind, display_name(p)
    kids = [_build(policy, c, f"{path}/{c.label}[{i}]", binding, leaves, reuse)
            for i, c in enumerate(p.children)]
    node: BTNode
    if leaves is not None and (kind in ACTIONS or kind in CONDITIONS):
        node = leaves(p, name)
    elif kind in ACTIONS:
        node = ActionNode(name, ACTIONS[kind], dict(p.params))
    elif kind in CONDITIONS:
        spec = CONDITIONS[kind]
        args = dict(p.params)
        node = ConditionNode(name, spec.predicate, tuple(args[k] for k in spec.ports))
    elif kind in ("AlwaysSuccess", "AlwaysFailure"):
        node = ConstNode(name, SUCCESS if kind == "AlwaysSuccess" else FAILURE)
    elif kind == "SubTree":
        sub = p.param("ID") or ""
        sub_root = policy.trees[sub]
        child = _build(policy, sub_root, f"{path}/{sub_root.label}", binding, leaves, reuse)
        child.tree_id = sub
        node = SubTree(name, child)
    elif kind in _COMPOSITE_CLASSES:
        node = _COMPOSITE_CLASSES[kind](name, list(kids))
    elif kind == "TryCatch":
        node = TryCatch(name, list(kids), p.param("catch_on_halt") == "true")
    elif kind == "Parallel":
        node = Parallel(name, list(kids), int(p.param("success_count") or -1),
                        int(p.param("failure_count") or 1))
    elif kind == "RetryUntilSuccessful":
        node = RetryUntilSuccessful(name, kids[0], int(p.param("num_attempts") or 0))
    elif kind == "Repeat":
        node = Repeat(name, kids[0], int(p.param("num_cycles") or 0))
    else:
        node = _SIMPLE_DECORATORS[kind](name, kids[0])
    node.setup_bt(p, path, binding)
    return node


def tree_to_policy(root: BTNode, source: str = "<py_trees>") -> Policy:
    """The policy a tree was built from, read back from its nodes (SubTrees become trees again)."""
    trees: dict[str, PolicyNode] = {}
    main = root.tree_id or "MainTree"
    trees[main] = _unbuild(root, trees)
    return Policy(main=main, trees=trees, source=source)


def _unbuild(node: py_trees.behaviour.Behaviour, trees: dict[str, PolicyNode]) -> PolicyNode:
    if not isinstance(node, BTNode):
        raise TypeError(f"{node.name!r} is a {type(node).__name__}, not a node built by build_tree")
    if isinstance(node, SubTree):
        sub = node.param("ID") or ""
        if sub not in trees:
            trees[sub] = _unbuild(node.decorated, trees)
        children: tuple[PolicyNode, ...] = ()
    else:
        children = tuple(_unbuild(c, trees) for c in node.children)
    return PolicyNode(kind=node.kind, params=node.params, children=children, name=node.bt_name)
