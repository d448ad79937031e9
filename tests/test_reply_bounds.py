"""No request kind's reply bound is below the content its replies must hold (issue 39),
measured on the offline model's replies (`benchmarks/reply_bounds.py`)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))


def test_bounds_hold_the_largest_replies_of_the_largest_task() -> None:
    from reply_bounds import measure, table, tokens  # type: ignore[import-not-found]

    from logicenveval.llm.replies import MAX_OTHER_OBJECTS

    measured = measure(["lamp_or_pillow_fetch", "kitchen_dish_cleanup"], ["cot", "logicenvgen-no-dbp", "ifg"])
    lines, short = table(measured.largest)
    assert short == [], lines
    assert tokens(measured.largest["cot_environments"][0]) > 4000  # the protocol-1 bound could not hold it
    others, task = measured.others
    assert task == "lamp_or_pillow_fetch" and 0 < others <= MAX_OTHER_OBJECTS


def test_a_bound_grows_with_the_items_a_request_fixes() -> None:
    from logicenveval.generators.plan import leaves_reply
    from logicenveval.llm.ask import (
        ITEMS_OVERHEAD,
        MAX_TOKENS_V1,
        PER_ITEM_TOKENS,
        bounds_of,
        reply_schema,
    )

    schema = reply_schema(leaves_reply(40))
    assert bounds_of("tree_leaves", 2, schema) == 40 * PER_ITEM_TOKENS["tree_leaves"][1] + ITEMS_OVERHEAD
    assert bounds_of("tree_leaves", 2, reply_schema(leaves_reply(2))) == 1000
    assert bounds_of("tree_leaves", 1, schema) == MAX_TOKENS_V1["tree_leaves"]


@pytest.mark.slow
def test_no_bound_is_below_any_tasks_content() -> None:
    from reply_bounds import main

    assert main([]) == 0
