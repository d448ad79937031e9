"""`repeated`: the items listed more than once, as every "listed twice" error reports them."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from logicenveval.model.repeats import repeated


@given(st.lists(st.sampled_from(["a", "b", "c", "kitchen", "sofa_1"]), max_size=12))
def test_repeated_is_each_item_seen_twice_once_and_sorted(items: list[str]) -> None:
    assert repeated(items) == sorted({i for i in items if items.count(i) > 1})


def test_repeated_examples() -> None:
    assert repeated([]) == [] and repeated(["a", "b"]) == []
    assert repeated(["b", "a", "b", "a", "b", "c"]) == ["a", "b"]
