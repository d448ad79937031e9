"""`exhaustive`: the paper's exponential minimum-set-cover search (Table on MTSA, "Exhaustive").

The paper compares MTSA with "the Exhaustive algorithm", which "theoretically guarantees a minimum
set-cover" at O(2^N) cost, N being the number of trajectories of the Cartesian product. We
implement exactly that search: subsets of the admissible product are tested by increasing size,
each size in lexicographic order (`itertools.combinations`), and the first subset that takes
every decision path is returned — a minimum cover by construction. Every subset before it is
tested; nothing is pruned.

Only the test is made fast: paths are bits, so a subset covers when the OR of its masks is all
ones. The last `b` indices of a subset are tested together, as one numpy operation over the
precomputed ORs of every `b`-combination (a table of at most `TAIL_ELEMENTS`), so the Python loop
runs over the first `size - b` indices only; subsets are still tested one by one, in the same
order, and the count of tested subsets is the same as a plain loop's.

The budget (`max_subsets`) counts tested subsets, not seconds, so whether it is hit does not
depend on machine load and a run stays reproducible. When it is hit, `exhaustive_cover` reports
`optimal=False` and returns MTSA's cover; `logicenvgen-exhaustive` records that per task and the
leaderboard labels the row (docs/logic.md).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from functools import reduce
from operator import or_

import numpy as np

from logicenveval.errors import TrajectoryError
from logicenveval.logic.constraints import PathConstraints
from logicenveval.logic.mtsa import SELECTOR as MTSA
from logicenveval.logic.selectors import PathsPerSubtask, check_inputs, uncovered
from logicenveval.model.tree import Trajectory

#: default budget in subsets tested: the shipped benchmark's offline plans need at most
#: 5.4e10 (kitchen_breakfast_prep), about 20–60 s on one core (docs/logic.md)
MAX_SUBSETS = 10**11
#: largest table of precomputed b-combination ORs (elements): long enough that numpy's per-call
#: overhead is small against the work, short enough to build in tens of milliseconds
TAIL_ELEMENTS = 1 << 22
_DTYPES = (np.uint8, np.uint16, np.uint32, np.uint64)


@dataclass(frozen=True, slots=True)
class SearchResult:
    trajectories: tuple[Trajectory, ...]
    #: True when the search finished (the cover is minimum); False: budget hit, MTSA's cover
    optimal: bool
    #: subsets tested
    tested: int


def exhaustive_cover(
    paths_per_subtask: PathsPerSubtask,
    constraints: PathConstraints | None = None,
    *,
    max_subsets: int = MAX_SUBSETS,
) -> SearchResult:
    cons = check_inputs(paths_per_subtask, constraints)
    if max_subsets < 1:
        raise TrajectoryError(f"max_subsets={max_subsets} must be at least 1", field="max_subsets",
                              hint=f"the default is {MAX_SUBSETS:,} subsets")
    product = [c for c in itertools.product(*paths_per_subtask) if cons.admits(c)]
    missing = uncovered([Trajectory(c) for c in product], paths_per_subtask)
    if missing:
        raise TrajectoryError(
            f"decision path(s) {missing} occur in no admissible trajectory",
            field="constraints",
            hint="relax the forbidden pairs that exclude these paths with every other choice",
        )
    bit = {p.key: 1 << n for n, p in enumerate(p for ps in paths_per_subtask for p in ps)}
    full = (1 << len(bit)) - 1
    masks = [reduce(or_, (bit[p.key] for p in c)) for c in product]
    search = _search_vectorised if len(bit) <= 64 else _search_plain
    found, tested = search(masks, full, max_subsets)
    if found is None:
        return SearchResult(tuple(MTSA.select(paths_per_subtask, cons)), False, tested)
    return SearchResult(tuple(Trajectory(product[i]) for i in found), True, tested)


def _search_plain(masks: list[int], full: int, max_subsets: int) -> tuple[tuple[int, ...] | None, int]:
    """The search as a plain loop over Python integers (more than 64 decision paths; also the
    baseline `benchmarks/trajectory_cover.py --plans` measures the vectorised search against)."""
    tested = 0
    for size in range(1, len(masks) + 1):
        subsets = zip(itertools.combinations(range(len(masks)), size),
                      itertools.combinations(masks, size), strict=True)
        for subset, chosen in subsets:
            if tested >= max_subsets:
                return None, tested
            tested += 1
            if reduce(or_, chosen) == full:
                return subset, tested
    raise AssertionError("the whole admissible product covers every path")  # checked by the caller


def _search_vectorised(masks: list[int], full: int, max_subsets: int) -> tuple[tuple[int, ...] | None, int]:
    """Subsets by size, then lexicographically; the last `b` indices tested in one numpy step."""
    dtype = next(d for d in _DTYPES if full <= np.iinfo(d).max)
    n = len(masks)
    tables: dict[int, tuple[np.ndarray, list[int]]] = {}
    tested = 0
    for size in range(1, n + 1):
        b = max(w for w in range(1, size + 1) if w == 1 or math.comb(n, w) <= TAIL_ELEMENTS)
        lacks, starts = _table(masks, full, b, dtype, tables)
        buf = np.empty_like(lacks)
        for prefix in itertools.combinations(range(n - b), size - b):
            first = prefix[-1] + 1 if prefix else 0
            seg = lacks[starts[first]: starts[first] + max_subsets - tested]  # within the budget
            need = full & ~reduce(or_, (masks[i] for i in prefix), 0)
            out = buf[: len(seg)]
            np.bitwise_and(seg, dtype(need), out=out)
            if out.min() != 0:
                tested += len(seg)
                if tested >= max_subsets:
                    return None, tested
                continue
            hit = int(np.argmin(out))  # the first covering subset in lexicographic order
            tested += hit + 1
            return prefix + _unrank(starts[first] + hit, n, b), tested
    raise AssertionError("the whole admissible product covers every path")  # checked by the caller


def _table(masks: list[int], full: int, b: int, dtype: type[np.unsignedinteger],
           tables: dict[int, tuple[np.ndarray, list[int]]]) -> tuple[np.ndarray, list[int]]:
    """For every b-combination of the masks, in lexicographic order, the bits its OR lacks; and
    `starts[t]`: where the combinations whose first index is t begin (those of masks[t:] follow)."""
    if b in tables:
        return tables[b]
    n = len(masks)
    m = np.array(masks, dtype=dtype)
    ors = m.copy()
    starts = list(range(n + 1))
    for width in range(2, b + 1):  # combos of `width` = mask i joined with the (width-1)-combos after i
        parts = [m[i] | ors[starts[i + 1]:] for i in range(n - width + 1)]
        starts = [0]
        for part in parts:
            starts.append(starts[-1] + len(part))
        starts += [starts[-1]] * (n + 1 - len(starts))
        ors = np.concatenate(parts)
    tables.clear()  # one table at a time: they only grow with the subset size
    tables[b] = (np.bitwise_xor(ors, dtype(full)), starts)
    return tables[b]


def _unrank(index: int, n: int, b: int) -> tuple[int, ...]:
    """The `index`-th b-combination of range(n) in lexicographic order."""
    out: list[int] = []
    x = 0
    for j in range(b):
        while True:
            count = math.comb(n - x - 1, b - j - 1)
            if index < count:
                break
            index -= count
            x += 1
        out.append(x)
        x += 1
    return tuple(out)


class ExhaustiveSelector:
    name = "exhaustive"

    def __init__(self, max_subsets: int = MAX_SUBSETS) -> None:
        self.max_subsets = max_subsets

    def select(
        self, paths_per_subtask: PathsPerSubtask, constraints: PathConstraints | None = None
    ) -> list[Trajectory]:
        return list(exhaustive_cover(paths_per_subtask, constraints,
                                     max_subsets=self.max_subsets).trajectories)


SELECTOR = ExhaustiveSelector()
