"""The content each request kind's reply must hold, measured on the offline model's replies.

Runs the generators with the rule-based offline model over the benchmark's tasks and records, per
request kind, the largest reply written compactly (`json.dumps` without spaces), before the
schema's `maxItems` cut it (`llm.bounds`: that is the content the method wanted to write). Tokens
are approximated as characters / `CHARS_PER_TOKEN` (3.5: JSON of English words and snake_case ids
in a BPE vocabulary such as Qwen2.5's or SmolLM2's). Prints per kind the largest reply, its task,
the bound of protocol 1 and 2 (`llm.ask`), and whether the protocol-2 bound holds it.

    python benchmarks/reply_bounds.py [--tasks a,b] [--generators cot,holodeck]

Exit 1 when a protocol-2 bound is below a measured reply.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Sequence

from logicenveval.llm.ask import PER_ITEM_TOKENS
from logicenveval.llm.base import ChatRequest
from logicenveval.llm.replies import MAX_OTHER_OBJECTS
from logicenveval.offline.handlers import answer_for
from logicenveval.offline.model import OfflineModel

CHARS_PER_TOKEN = 3.5
#: head-room of a bound over the largest measured reply (models write longer ids and sentences
#: than the rule-based model)
MARGIN = 1.5
GENERATORS = ("logicenvgen", "logicenvgen-no-dbp", "logicenvgen-no-cas", "holodeck", "cot", "ifg")


class Measuring(OfflineModel):
    """The offline model, keeping the largest compact reply per request kind."""

    def __init__(self) -> None:
        super().__init__()
        self.largest: dict[str, tuple[int, str]] = {}
        #: the most objects besides the roles' in one `select_objects` reply (protocol 3 bounds
        #: their list: `replies.MAX_OTHER_OBJECTS`)
        self.others: tuple[int, str] = (0, "")
        self.task = ""

    def _keep(self, kind: str, size: int) -> None:
        if size > self.largest.get(kind, (0, ""))[0]:
            self.largest[kind] = (size, self.task)

    def complete(self, request: ChatRequest) -> str:
        handler = answer_for(request.kind)
        if handler is not None:
            reply = handler(request.payload, request)
            self._keep(request.kind, len(json.dumps(reply, separators=(",", ":"))))
            if request.kind == "select_objects" and isinstance(reply, dict):
                others = len(reply.get("other_objects", [o for o in reply.get("objects", []) if not o.get("role")]))
                self.others = max(self.others, (others, self.task))
            for kind, (key, _) in PER_ITEM_TOKENS.items():
                items = reply.get(key) if request.kind == kind and isinstance(reply, dict) else None
                for item in items or []:
                    self._keep(f"{kind} (per item)", len(json.dumps(item, separators=(",", ":"))))
        return super().complete(request)


def tokens(chars: int) -> int:
    return math.ceil(chars / CHARS_PER_TOKEN)


def proposed_bound(chars: int, floor: int) -> int:
    """The bound a kind needs: measured tokens times `MARGIN`, rounded up to 100, never below
    `floor` (the protocol-1 bound)."""
    return max(floor, math.ceil(tokens(chars) * MARGIN / 100) * 100)


def measure(tasks: Sequence[str], generators: Sequence[str]) -> Measuring:
    import numpy as np

    from logicenveval.benchmark import load_task
    from logicenveval.domain.catalog import load_catalog
    from logicenveval.generators.base import GenerationContext, make_generator, unit_seed

    model = Measuring()
    catalog = load_catalog()
    for task_id in tasks:
        task = load_task(task_id)
        model.task = task_id
        for name in generators:
            ctx = GenerationContext(model=model, catalog=catalog, seed=0,
                                    rng=np.random.default_rng(unit_seed(0, name, task_id)))
            make_generator(name).generate(task.brief(), ctx)
    return model


def table(largest: dict[str, tuple[int, str]]) -> tuple[list[str], list[str]]:
    from logicenveval.llm.ask import MAX_TOKENS, MAX_TOKENS_V1, PER_ITEM_TOKENS, bounds_of

    lines = ["| request kind | largest reply (chars) | ≈ tokens | task | bound v1 | bound v2 | proposed |",
             "|---|---:|---:|---|---:|---:|---:|"]
    short = []
    for kind, (chars, task) in sorted(largest.items()):
        base, _, item = kind.partition(" (per ")
        if item:  # per item of a list whose length the request fixes (bound = n x item)
            per = PER_ITEM_TOKENS[base][1]
            need = math.ceil(tokens(chars) * MARGIN)
            lines.append(f"| {kind} | {chars} | {tokens(chars)} | {task} | - | {per} per item | {need} |")
            if per < tokens(chars):
                short.append(kind)
            continue
        v1, v2 = MAX_TOKENS_V1.get(kind), MAX_TOKENS.get(kind)
        need = proposed_bound(chars, v1 or 0)
        lines.append(f"| {kind} | {chars} | {tokens(chars)} | {task} | {v1} | {v2} | {need} |")
        if bounds_of(kind) < tokens(chars):
            short.append(kind)
    return lines, short


def main(argv: list[str] | None = None) -> int:
    from logicenveval.benchmark import task_ids

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tasks", default="", help="comma-separated task ids (default: all)")
    parser.add_argument("--generators", default=",".join(GENERATORS))
    parser.add_argument("--smoke", action="store_true", help="seconds, not minutes: a small case of the same code path (tests/test_benchmarks_smoke.py); the figures are not the documented ones")
    args = parser.parse_args(argv)
    if args.smoke:
        args.tasks = args.tasks or "lamp_or_pillow_fetch"
    tasks = [t for t in args.tasks.split(",") if t] or list(task_ids())
    measured = measure(tasks, [g for g in args.generators.split(",") if g])
    lines, short = table(measured.largest)
    print("\n".join(lines))
    others, task = measured.others
    print(f"select_objects other_objects: at most {others} ({task}), bound {MAX_OTHER_OBJECTS}")
    if others > MAX_OTHER_OBJECTS:
        short.append("select_objects other_objects")
    print(f"reply_bounds tasks={len(tasks)} chars_per_token={CHARS_PER_TOKEN} margin={MARGIN} "
          f"below_content={','.join(short) or 'none'}")
    return 1 if short else 0


if __name__ == "__main__":
    sys.exit(main())
