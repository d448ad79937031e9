"""Condition language: parser, printer, evaluator (DESIGN.md §3)."""

from __future__ import annotations

import itertools

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from logicenveval.errors import ConditionSyntaxError, LogicEnvEvalError
from logicenveval.model.conditions import (
    FALSE,
    PREDICATES,
    STATE_FLAGS,
    TRUE,
    And,
    Const,
    Not,
    Or,
    Pred,
    atoms,
    conjunction,
    evaluate,
    parse,
    subject_roles,
    to_text,
)

NAMES = st.sampled_from(["toy", "red_box", "book", "sofa", "floor", "living_room", "kind", "doll", "c2"])


@st.composite
def preds(draw: st.DrawFn) -> Pred:
    name = draw(st.sampled_from(sorted(PREDICATES)))
    args = [draw(NAMES) for _ in range(PREDICATES[name])]
    if name == "state":
        args[1] = draw(st.sampled_from(STATE_FLAGS))
    return Pred(name, tuple(args))


conds = st.recursive(
    st.one_of(preds(), st.sampled_from([TRUE, FALSE])),
    lambda inner: st.one_of(
        inner.map(Not),
        st.lists(inner, min_size=2, max_size=3).map(lambda xs: And(tuple(xs))),
        st.lists(inner, min_size=2, max_size=3).map(lambda xs: Or(tuple(xs))),
    ),
    max_leaves=8,
)


@given(conds)
@settings(max_examples=300)
def test_print_then_parse_is_identity(cond: object) -> None:
    assert parse(to_text(cond)) == cond  # type: ignore[arg-type]


def _reference(cond: object, world: dict[Pred, bool]) -> bool:
    """Truth-table reference semantics, written independently of `evaluate`."""
    if isinstance(cond, Const):
        return cond.value
    if isinstance(cond, Pred):
        return world[cond]
    if isinstance(cond, Not):
        return not _reference(cond.operand, world)
    if isinstance(cond, And):
        result = True
        for c in cond.operands:
            result = result and _reference(c, world)
        return result
    assert isinstance(cond, Or)
    result = False
    for c in cond.operands:
        result = result or _reference(c, world)
    return result


@given(conds)
@settings(max_examples=200)
def test_evaluation_matches_truth_table(cond: object) -> None:
    ps = sorted(set(atoms(cond)), key=repr)  # type: ignore[arg-type]
    for values in itertools.product([False, True], repeat=len(ps)):
        world = dict(zip(ps, values, strict=True))
        got = evaluate(cond, lambda n, a, w=world: w[Pred(n, a)])  # type: ignore[arg-type,misc]
        assert got == _reference(cond, world)


def test_precedence_not_binds_tighter_than_and_than_or() -> None:
    c = parse("not on(a, floor) and exists(b) or exists(c)")
    assert c == Or((And((Not(Pred("on", ("a", "floor"))), Pred("exists", ("b",)))), Pred("exists", ("c",))))
    assert parse("exists(a) and (exists(b) or exists(c))") == And(
        (Pred("exists", ("a",)), Or((Pred("exists", ("b",)), Pred("exists", ("c",)))))
    )


@pytest.mark.parametrize(
    ("text", "column", "fragment"),
    [
        ("on(toy floor)", 8, "expected ',' or ')'"),
        ("on(toy, floor) and", 19, "expected a predicate"),
        ("upon(toy, floor)", 1, "unknown predicate 'upon'"),
        ("on(toy)", 1, "takes 2 argument(s), got 1"),
        ("state(fridge, shiny)", 1, "unknown state flag 'shiny'"),
        ("(exists(toy)", 13, "missing ')'"),
        ("exists(toy) exists(book)", 13, "unexpected 'exists'"),
        ("exists(toy) & exists(book)", 13, "unexpected character '&'"),
    ],
)
def test_syntax_errors_name_the_column(text: str, column: int, fragment: str) -> None:
    with pytest.raises(ConditionSyntaxError) as info:
        parse(text, source="task.json")
    err = info.value
    assert isinstance(err, LogicEnvEvalError)
    assert err.column == column
    assert fragment in str(err)
    assert "task.json" in str(err) and "fix:" in str(err)


def test_helpers() -> None:
    c = parse("on(toy, table) and not attr(book, kind, novel) and agent_in(kitchen)")
    assert subject_roles(c) == {"toy", "book"}
    assert conjunction([TRUE, TRUE]) == TRUE
    assert conjunction([TRUE, c]) == c
    assert conjunction([Pred("exists", ("a",)), Pred("exists", ("b",))]) == parse("exists(a) and exists(b)")
