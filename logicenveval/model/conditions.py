"""The condition language of DESIGN.md §3: parser, printer, evaluator.

A condition is parsed once into an immutable AST and evaluated against any state that can answer
atomic predicates (`holds(name, args) -> bool`), so the same code serves task validation, GT-tree
evaluation, goal checking and BT conditions.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import lru_cache

from logicenveval.errors import ConditionSyntaxError
from logicenveval.limits import limit, raise_hint

#: predicate name -> arity (v1 vocabulary, fixed by DESIGN.md §3)
PREDICATES: dict[str, int] = {
    "exists": 1,
    "on": 2,
    "inside": 2,
    "in_room": 2,
    "attr": 3,
    "state": 2,
    "holding": 1,
    "near": 1,
    "agent_in": 1,
}

#: boolean state flags allowed in `state(r, flag)`
STATE_FLAGS: tuple[str, ...] = (
    "open",
    "toggled_on",
    "dirty",
    "wet",
    "filled",
    "cooked",
    "sliced",
    "broken",
)

#: predicates that speak about the agent; not allowed in task variables (DESIGN.md §4)
AGENT_PREDICATES: frozenset[str] = frozenset({"holding", "near", "agent_in"})

KEYWORDS = frozenset({"and", "or", "not", "true", "false"})

Holds = Callable[[str, tuple[str, ...]], bool]


@dataclass(frozen=True, slots=True)
class Const:
    value: bool


@dataclass(frozen=True, slots=True)
class Pred:
    name: str
    args: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Not:
    operand: Cond


@dataclass(frozen=True, slots=True)
class And:
    operands: tuple[Cond, ...]


@dataclass(frozen=True, slots=True)
class Or:
    operands: tuple[Cond, ...]


Cond = Const | Pred | Not | And | Or

TRUE = Const(True)
FALSE = Const(False)

_TOKEN = re.compile(r"\s*(?:(?P<punct>[(),])|(?P<word>[A-Za-z0-9_][A-Za-z0-9_\-.]*)|(?P<bad>\S))")


@dataclass(frozen=True, slots=True)
class _Tok:
    kind: str  # "punct" | "word" | "end"
    text: str
    col: int  # 1-based column


def _tokenize(text: str, source: str | None) -> list[_Tok]:
    toks: list[_Tok] = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None:  # only trailing whitespace left
            break
        if m.group("bad") is not None:
            col = m.start("bad") + 1
            raise ConditionSyntaxError(
                f"unexpected character {m.group('bad')!r} in condition {text!r}",
                file=source,
                column=col,
                hint="conditions use predicates like on(toy, floor) joined by and/or/not",
            )
        kind = "punct" if m.group("punct") is not None else "word"
        toks.append(_Tok(kind, m.group(kind), m.start(kind) + 1))
        pos = m.end()
    toks.append(_Tok("end", "", len(text) + 1))
    return toks


def _check_nesting(text: str, source: str | None, max_depth: int) -> None:
    depth = 0
    for col, ch in enumerate(text, 1):
        depth += (ch == "(") - (ch == ")")
        if depth > max_depth:
            shown = text if len(text) <= 120 else text[:117] + "..."
            raise ConditionSyntaxError(
                f"nesting deeper than {max_depth} levels in condition {shown!r}", file=source,
                column=col, hint="simplify the condition (" + raise_hint("max_condition_depth") + ")")


class _Parser:
    def __init__(self, text: str, source: str | None) -> None:
        self.text = text
        self.source = source
        self.depth = 0
        self.max_depth = limit("max_condition_depth")
        if text.count("(") > self.max_depth:  # refuse absurd nesting before tokenising it all
            _check_nesting(text, source, self.max_depth)
        self.toks = _tokenize(text, source)
        self.i = 0

    def _peek(self) -> _Tok:
        return self.toks[self.i]

    def _next(self) -> _Tok:
        tok = self.toks[self.i]
        self.i += 1
        return tok

    def _fail(self, tok: _Tok, message: str, hint: str) -> ConditionSyntaxError:
        shown = self.text if len(self.text) <= 120 else self.text[:117] + "..."
        return ConditionSyntaxError(
            f"{message} in condition {shown!r}", file=self.source, column=tok.col, hint=hint
        )

    def _nest(self, tok: _Tok) -> None:
        self.depth += 1
        if self.depth > self.max_depth:
            raise self._fail(tok, f"nesting deeper than {self.max_depth} levels",
                             "simplify the condition (" + raise_hint("max_condition_depth") + ")")

    def parse(self) -> Cond:
        cond = self._expr()
        tok = self._peek()
        if tok.kind != "end":
            raise self._fail(tok, f"unexpected {tok.text!r}", "join conditions with 'and' / 'or'")
        return cond

    def _expr(self) -> Cond:
        items = [self._term()]
        while self._peek().kind == "word" and self._peek().text == "or":
            self._next()
            items.append(self._term())
        return items[0] if len(items) == 1 else Or(tuple(items))

    def _term(self) -> Cond:
        items = [self._factor()]
        while self._peek().kind == "word" and self._peek().text == "and":
            self._next()
            items.append(self._factor())
        return items[0] if len(items) == 1 else And(tuple(items))

    def _factor(self) -> Cond:
        tok = self._next()
        if tok.kind == "punct" and tok.text == "(":
            self._nest(tok)
            inner = self._expr()
            close = self._next()
            if close.text != ")":
                raise self._fail(close, "missing ')'", "balance the parentheses")
            self.depth -= 1
            return inner
        if tok.kind != "word":
            what = "end of condition" if tok.kind == "end" else repr(tok.text)
            raise self._fail(tok, f"expected a predicate, found {what}", "e.g. on(toy, floor)")
        if tok.text == "not":
            self._nest(tok)
            negated = Not(self._factor())
            self.depth -= 1
            return negated
        if tok.text == "true":
            return TRUE
        if tok.text == "false":
            return FALSE
        if tok.text in KEYWORDS:
            raise self._fail(tok, f"misplaced keyword {tok.text!r}", "check the and/or/not order")
        return self._predicate(tok)

    def _predicate(self, name_tok: _Tok) -> Pred:
        name = name_tok.text
        if name not in PREDICATES:
            raise self._fail(
                name_tok,
                f"unknown predicate {name!r}",
                "use one of " + ", ".join(sorted(PREDICATES)),
            )
        open_tok = self._next()
        if open_tok.text != "(":
            raise self._fail(open_tok, f"expected '(' after {name!r}", f"write {name}(...)")
        args: list[str] = []
        while True:
            arg = self._next()
            if arg.kind != "word" or arg.text in KEYWORDS:
                raise self._fail(arg, f"expected an argument of {name!r}", "arguments are names")
            args.append(arg.text)
            sep = self._next()
            if sep.text == ")":
                break
            if sep.text != ",":
                raise self._fail(sep, "expected ',' or ')'", "separate arguments with commas")
        arity = PREDICATES[name]
        if len(args) != arity:
            raise self._fail(
                name_tok,
                f"{name} takes {arity} argument(s), got {len(args)}",
                f"write {name}(" + ", ".join(f"a{i + 1}" for i in range(arity)) + ")",
            )
        if name == "state" and args[1] not in STATE_FLAGS:
            raise self._fail(
                name_tok,
                f"unknown state flag {args[1]!r}",
                "use one of " + ", ".join(STATE_FLAGS),
            )
        return Pred(name, tuple(args))


@lru_cache(maxsize=4096)
def _parse_cached(text: str) -> Cond:
    return _Parser(text, None).parse()


def parse(text: str, *, source: str | None = None) -> Cond:
    """Parse a condition string; raise `ConditionSyntaxError` with the column on bad input."""
    if not isinstance(text, str):
        raise ConditionSyntaxError(
            f"a condition must be a string, got {type(text).__name__}", file=source
        )
    if source is None:
        return _parse_cached(text)
    try:
        return _parse_cached(text)
    except ConditionSyntaxError as exc:
        raise ConditionSyntaxError(
            exc.message, file=source, column=exc.column, hint=exc.hint
        ) from None


def to_text(cond: Cond) -> str:
    """Canonical text; `parse(to_text(c)) == c` for every AST `c`."""
    if isinstance(cond, Const):
        return "true" if cond.value else "false"
    if isinstance(cond, Pred):
        return f"{cond.name}({', '.join(cond.args)})"
    if isinstance(cond, Not):
        inner = cond.operand
        text = to_text(inner)
        return f"not ({text})" if isinstance(inner, And | Or) else f"not {text}"
    if isinstance(cond, And):
        return " and ".join(
            f"({to_text(c)})" if isinstance(c, And | Or) else to_text(c) for c in cond.operands
        )
    return " or ".join(f"({to_text(c)})" if isinstance(c, Or) else to_text(c) for c in cond.operands)


def evaluate(cond: Cond, holds: Holds) -> bool:
    """Evaluate `cond` with `holds(name, args)` answering atomic predicates."""
    if isinstance(cond, Pred):
        return holds(cond.name, cond.args)
    if isinstance(cond, Const):
        return cond.value
    if isinstance(cond, Not):
        return not evaluate(cond.operand, holds)
    if isinstance(cond, And):
        return all(evaluate(c, holds) for c in cond.operands)
    return any(evaluate(c, holds) for c in cond.operands)


def atoms(cond: Cond) -> Iterator[Pred]:
    """Every atomic predicate occurring in `cond`, in textual order."""
    if isinstance(cond, Pred):
        yield cond
    elif isinstance(cond, Not):
        yield from atoms(cond.operand)
    elif isinstance(cond, And | Or):
        for c in cond.operands:
            yield from atoms(c)


def subject_roles(cond: Cond) -> set[str]:
    """Roles that appear as the first argument of a predicate (DESIGN.md §4 disjointness)."""
    return {p.args[0] for p in atoms(cond) if p.name not in ("agent_in",)}


def conjunction(conds: list[Cond]) -> Cond:
    """`and` of several conditions, dropping `true` (the goal of several reached leaves)."""
    items = tuple(c for c in conds if c != TRUE)
    if not items:
        return TRUE
    return items[0] if len(items) == 1 else And(items)
