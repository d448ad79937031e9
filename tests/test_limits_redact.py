"""Unit and property tests of the limits, the SubTree node budget and redaction (issue 20)."""

from __future__ import annotations

import os

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.errors import ConfigError, PolicyFormatError
from logicenveval.limits import DEFAULTS, limit
from logicenveval.redact import MASK, redact, register_secret
from logicenveval.sim.loader import policy_from_xml


def test_limits_default_and_override(monkeypatch: pytest.MonkeyPatch) -> None:
    assert limit("max_subtree_nodes") == DEFAULTS["max_subtree_nodes"][0] == 100_000
    monkeypatch.setenv("LOGICENVEVAL_MAX_SUBTREE_NODES", "7")
    assert limit("max_subtree_nodes") == 7
    for bad in ("abc", "0", "-3"):
        monkeypatch.setenv("LOGICENVEVAL_MAX_SUBTREE_NODES", bad)
        with pytest.raises(ConfigError, match="LOGICENVEVAL_MAX_SUBTREE_NODES"):
            limit("max_subtree_nodes")


# a random DAG of trees: tree i may call trees > i (so no recursion), each call any number of times
_dags = st.integers(1, 6).flatmap(lambda n: st.lists(
    st.lists(st.integers(1, n), max_size=3), min_size=n, max_size=n).map(
        lambda calls: [[c for c in cs if c > i] for i, cs in enumerate(calls)]))


def _xml(calls: list[list[int]]) -> str:
    trees = []
    for i, cs in enumerate(calls):
        body = "".join(f'<SubTree ID="T{c}"/>' for c in cs) or "<AlwaysSuccess/>"
        trees.append(f'<BehaviorTree ID="T{i}"><Sequence>{body}</Sequence></BehaviorTree>')
    n = len(calls)
    trees.append(f'<BehaviorTree ID="T{n}"><AlwaysSuccess/></BehaviorTree>')
    return f'<root BTCPP_format="4" main_tree_to_execute="T0">{"".join(trees)}</root>'


def _expanded(calls: list[list[int]], i: int) -> int:
    """Brute force: nodes of tree i with every SubTree inlined (1 for the SubTree node itself)."""
    if i == len(calls):
        return 1
    return 1 + (sum(1 + _expanded(calls, c) for c in calls[i]) if calls[i] else 1)


@settings(max_examples=60, deadline=None)
@given(calls=_dags, budget=st.integers(1, 200))
def test_subtree_budget_matches_brute_force_expansion(calls: list[list[int]], budget: int) -> None:
    size = _expanded(calls, 0)
    os.environ["LOGICENVEVAL_MAX_SUBTREE_NODES"] = str(budget)
    try:
        if size > budget:
            with pytest.raises(PolicyFormatError, match=f"more than {budget} nodes"):
                policy_from_xml(_xml(calls))
        else:
            policy_from_xml(_xml(calls))
    finally:
        del os.environ["LOGICENVEVAL_MAX_SUBTREE_NODES"]


_secret = st.text(alphabet=st.characters(min_codepoint=33, max_codepoint=126), min_size=8, max_size=40)


@settings(max_examples=100, deadline=None)
@given(secret=_secret, before=st.text(max_size=50), after=st.text(max_size=50))
def test_registered_secret_never_survives_redaction(secret: str, before: str, after: str) -> None:
    register_secret(secret)
    out = redact(f"{before}{secret}{after}{secret}")
    assert secret not in out
    assert MASK in out


@pytest.mark.parametrize("text,leak", [
    ("Authorization: Bearer abcdef123456", "abcdef123456"),
    ('{"authorization": "Basic dXNlcjpwYXNz"}', "dXNlcjpwYXNz"),
    ("key sk-proj-abcdefghijkl in body", "sk-proj-abcdefghijkl"),
    ("http://alice:s3cret@host:8000/v1", "s3cret"),
    ("api_key=plainvalue,timeout=3", "plainvalue"),
    ("x-api-key: zzzzzzzz", "zzzzzzzz"),
])
def test_secret_shapes_are_masked(text: str, leak: str) -> None:
    assert leak not in redact(text)


def test_harmless_text_is_kept() -> None:
    text = "field 'objects.0.position': Input should be a valid tuple; task clean_living_room"
    assert redact(text) == text
