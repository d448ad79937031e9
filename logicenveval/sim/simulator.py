"""Run a compiled policy in a world and judge it (verdict order of DESIGN.md §5).

`simulate` is the public entry point; `CompiledPolicy` lets callers that run one policy in many
environments (validation, the throughput benchmark) build the py_trees tree once and reset it per
episode, and mutation scoring record an episode and resume it from any root tick.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from itertools import repeat
from operator import attrgetter
from pathlib import Path
from typing import Any

from py_trees.common import Status

from logicenveval.domain.catalog import Catalog
from logicenveval.errors import PolicyFormatError
from logicenveval.model.conditions import Cond, evaluate, to_text
from logicenveval.model.envspec import EnvSpec
from logicenveval.model.task import Task
from logicenveval.model.tree import evaluate_task, goal_of
from logicenveval.sim.loader import BadPortError, UnknownNodeError, load_policy
from logicenveval.sim.nodes import (
    FAILURE,
    IDLE,
    RUNNING,
    BTNode,
    Control,
    Episode,
    Violation,
    build_tree,
)
from logicenveval.sim.policy import Policy
from logicenveval.sim.verdict import Verdict
from logicenveval.sim.world import World


@dataclass(frozen=True, slots=True)
class Snapshot:
    """An episode between two root ticks: ticks done, every node's status, the child index of
    the controls that keep only that, the `state()` of the few nodes that keep more (loop
    counters, Parallel's finished children, TryCatch's mode), the world."""

    tick: int
    statuses: list[Status]
    indices: list[int]
    states: list[object]
    world: World


@dataclass(frozen=True, slots=True)
class Recording:
    """A recorded episode: its verdict status, every leaf tick (root tick, leaf, status; a
    precondition violation counts as FAILURE) and a snapshot before every root tick."""

    status: str
    ticks: list[tuple[int, BTNode, Status]]
    snapshots: list[Snapshot]


_STATUS = attrgetter("status")
_IDX = attrgetter("idx")


class CompiledPolicy:
    """The policy as a py_trees tree, reusable across episodes (not thread-safe)."""

    def __init__(self, policy: Policy) -> None:
        self.policy = policy
        self.root: BTNode = build_tree(policy)
        self._nodes: list[BTNode] = [n for n in self.root.iterate() if isinstance(n, BTNode)]
        # snapshots read and restore plain attributes in C loops (`map`), a method call only
        # for the few nodes whose state is more than a status and a child index
        kinds = [type(n).state for n in self._nodes]
        self._indexed = [n for n, k in zip(self._nodes, kinds, strict=True) if k is Control.state]
        self._stateful = [n for n, k in zip(self._nodes, kinds, strict=True)
                          if k is not BTNode.state and k is not Control.state]
        self._indexed_at = {j: i for i, j in enumerate(
            j for j, k in enumerate(kinds) if k is Control.state)}
        self._stateful_at = {j: i for i, j in enumerate(
            j for j, k in enumerate(kinds) if k is not BTNode.state and k is not Control.state)}
        # an episode starts with every node reset: plain attributes set in C loops, `reset_all`
        # called only where it does more
        resets = [type(n).reset_all for n in self._nodes]
        self._zeroed = [n for n, r in zip(self._nodes, resets, strict=True) if r is Control.reset_all]
        self._resetting = [n for n, r in zip(self._nodes, resets, strict=True)
                           if r is not BTNode.reset_all and r is not Control.reset_all]

    @property
    def nodes(self) -> list[BTNode]:
        """Every node of the tree, in the order of a `Snapshot`'s statuses."""
        return self._nodes

    def state_at(self, snapshot: Snapshot, j: int) -> object:
        """The `state()` node `j` had in `snapshot`."""
        k = self._stateful_at.get(j)
        if k is not None:
            return snapshot.states[k]
        i = self._indexed_at.get(j)
        return snapshot.statuses[j] if i is None else (snapshot.statuses[j], snapshot.indices[i])

    def _reset(self) -> None:
        """`reset_all` every node (the start of an episode)."""
        deque(map(setattr, self._nodes, repeat("status"), repeat(IDLE)), maxlen=0)
        deque(map(setattr, self._zeroed, repeat("idx"), repeat(0)), maxlen=0)
        for node in self._resetting:
            node.reset_all()

    def status(self, world: World, goal: Cond | None, *, tick_limit: int = 50) -> str:
        """The verdict status of one episode on `world` (mutated in place: pass a copy).

        Same judgement as `run` without building a `Verdict` (no trace, no final-state digest),
        for callers that run many policies and only need the outcome (mutation scoring).
        """
        self._reset()
        ep = self.root.binding.ep = Episode(world)
        return self._judge(ep, goal, tick_limit)

    def record(self, world: World, goal: Cond | None, *, tick_limit: int = 50) -> Recording:
        """`status` of one episode, plus every leaf tick and the state at the start of every
        root tick (so that an episode of a tree that differs only where this one had not yet
        gone can start there: `resume`)."""
        self._reset()
        ticks: list[tuple[int, BTNode, Status]] = []
        ep = self.root.binding.ep = Episode(world, ticks=ticks)
        snapshots: list[Snapshot] = []
        nodes, indexed, stateful = self._nodes, self._indexed, self._stateful

        def snapshot() -> None:
            snapshots.append(Snapshot(ep.tick, list(map(_STATUS, nodes)), list(map(_IDX, indexed)),
                                      [n.state() for n in stateful], world.copy()))

        try:
            status = self._tick_until_done(ep, tick_limit, snapshot)
        except Violation as v:
            ticks.append((ep.tick, v.node, FAILURE))
            return Recording("precondition_violation", ticks, snapshots)
        return Recording(self._outcome(status, goal, world), ticks, snapshots)

    def resume(self, snapshot: Snapshot, goal: Cond | None, fresh: Iterable[BTNode] = (),
               mirror: Iterable[tuple[BTNode, int]] = (), *, tick_limit: int = 50) -> str:
        """`status` of an episode that starts from `snapshot` (taken by `record` on this tree)
        instead of from the initial state; `fresh` are nodes spliced in since, which start
        reset, except those in `mirror`, which take the state of the tree's node at that
        index."""
        deque(map(setattr, self._nodes, repeat("status"), snapshot.statuses), maxlen=0)
        deque(map(setattr, self._indexed, repeat("idx"), snapshot.indices), maxlen=0)
        for node, state in zip(self._stateful, snapshot.states, strict=True):
            node.restore(state)
        for node in fresh:
            node.reset_all()
        for node, j in mirror:
            node.restore(self.state_at(snapshot, j))
        ep = self.root.binding.ep = Episode(snapshot.world.copy(), tick=snapshot.tick)
        return self._judge(ep, goal, tick_limit)

    def _tick_until_done(self, ep: Episode, tick_limit: int,
                         before_tick: Callable[[], None] | None = None) -> Status:
        """Tick the root until it stops RUNNING or `ep` has `tick_limit` root ticks; the root's
        last status (IDLE when no tick was left). A `Violation` propagates to the caller."""
        root = self.root
        status = IDLE
        while ep.tick < tick_limit:
            if before_tick is not None:
                before_tick()
            ep.tick += 1
            root.tick_once()
            status = root.status
            if status is not RUNNING:
                break
        return status

    def _judge(self, ep: Episode, goal: Cond | None, tick_limit: int) -> str:
        try:
            status = self._tick_until_done(ep, tick_limit)
        except Violation:
            return "precondition_violation"
        return self._outcome(status, goal, ep.world)

    @staticmethod
    def _outcome(status: Status, goal: Cond | None, world: World) -> str:
        if status is RUNNING:
            return "tick_limit"
        if status is FAILURE:
            return "tree_failure"
        if goal is None:
            return "ill_formed"
        return "passed" if evaluate(goal, world.holds) else "goal_unmet"

    def run(self, world: World, goal: Cond | None, *, tick_limit: int = 50,
            trace: bool = False, final_state: bool = True) -> Verdict:
        """Run one episode on `world` (mutated in place: pass a copy); `final_state=False`
        leaves the final-state digest empty (a caller that keeps only the trace)."""
        self._reset()
        ep = self.root.binding.ep = Episode(world, trace=[] if trace else None)
        try:
            status = self._tick_until_done(ep, tick_limit)
        except Violation as v:
            return _verdict(ep, final_state, status="precondition_violation",
                            fault_node=v.node.bt_name or v.node.label, fault_path=v.node.path,
                            message=v.message)
        if status is RUNNING:
            return _verdict(ep, final_state, status="tick_limit",
                            message=f"root still RUNNING after {tick_limit} ticks")
        if status is FAILURE:
            last = _last_failed_leaf(ep)
            return _verdict(ep, final_state, status="tree_failure", fault_node=last[0],
                            fault_path=last[1], message="the root returned FAILURE" + (
                                f" (last failing leaf: {last[1]})" if last[1] else ""))
        if goal is None:
            return _verdict(ep, final_state, status="ill_formed",
                            message="some GT tree reaches no leaf on the initial state, so the "
                                    "environment has no goal")
        ok = evaluate(goal, world.holds)
        text = to_text(goal)
        return _verdict(ep, final_state, status="passed" if ok else "goal_unmet", goal_holds=ok,
                        goal=text, message="" if ok else f"goal {text} is false at the end")


def _verdict(ep: Episode, final_state: bool, **fields: Any) -> Verdict:
    """The verdict of a finished episode, built without validation: every field is made here,
    of its declared type (validating a long trace's events cost a fifth of a traced run)."""
    return Verdict.model_construct(ticks=ep.tick, trace=ep.trace or [],
                                   final_state=ep.world.summary() if final_state else {}, **fields)


def _last_failed_leaf(ep: Episode) -> tuple[str | None, str | None]:
    node = ep.last_fail
    return (node.bt_name or node.label, node.path) if node is not None else (None, None)


def task_goal(task: Task, world: World) -> Cond | None:
    """Conjunction of the goals of the GT leaves reached on `world` (None if ill-formed)."""
    return goal_of(evaluate_task(task, world.holds))


_CACHE: dict[int, CompiledPolicy] = {}


def compiled(policy: Policy) -> CompiledPolicy:
    """The compiled form of `policy`, built once per policy object."""
    got = _CACHE.get(id(policy))
    if got is None or got.policy is not policy:
        if len(_CACHE) > 256:
            _CACHE.clear()
        got = _CACHE[id(policy)] = CompiledPolicy(policy)
    return got


def simulate(policy: Policy, env: EnvSpec, task: Task, catalog: Catalog | None = None, *,
             tick_limit: int = 50, trace: bool = False) -> Verdict:
    """Run `policy` once in `env`'s initial state and judge it against the task's GT goal."""
    if tick_limit < 1:
        raise ValueError(f"tick_limit must be >= 1, got {tick_limit}")
    world = World.from_env(env, catalog)
    goal = task_goal(task, world)
    return compiled(policy).run(world, goal, tick_limit=tick_limit, trace=trace)


def simulate_file(path: str | Path, env: EnvSpec, task: Task, catalog: Catalog | None = None,
                  *, tick_limit: int = 50, trace: bool = False) -> Verdict:
    """Like `simulate` for a policy file; unknown nodes and bad ports become verdicts."""
    try:
        policy = load_policy(path, roles=task.roles, rooms=task.rooms)
    except UnknownNodeError as exc:
        return Verdict(status="unknown_node", message=str(exc))
    except BadPortError as exc:
        return Verdict(status="bad_port", message=str(exc))
    except PolicyFormatError:
        raise
    return simulate(policy, env, task, catalog, tick_limit=tick_limit, trace=trace)


