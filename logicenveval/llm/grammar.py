"""A JSON Schema as a GBNF grammar without free whitespace: compact JSON for llama.cpp.

llama.cpp compiles a `response_format` JSON schema with its own converter
(`common/json-schema-to-grammar.cpp`), which puts `space ::= | " " | "\\n"{1,2} [ \\t]{0,20}`
between every two tokens and has no option to drop it: a model may spend its `max_tokens` on
indentation (Qwen2.5-Coder-1.5B did, and lost 3 of 4 factors). The server also takes a GBNF
`grammar` instead of a schema; this module writes one for the schemas of `llm.replies`, with no
whitespace at all, so every token of a reply is content.

Covered: objects (properties in the schema's order, optional ones each omissible),
`additionalProperties` maps, arrays (`items`, `prefixItems`, `minItems`/`maxItems`), `enum`,
`const`, strings (`maxLength`, and `pattern` in the regex subset the vocabularies use), numbers,
integers, booleans, null, `anyOf`/`oneOf`, local `$ref`s. Numeric bounds are not written
(llama.cpp's own converter bounds integers only): the reply reader sets a number outside them to
the bound (`llm.bounds.fit_numbers`), so what the grammar allows is taken. The same tree is also written as a Python regex
(`to_regex`), for tests: the schemas are not recursive.
"""

from __future__ import annotations

import json
import re

try:  # Python 3.11+ keeps the regex parser here
    import re._parser as sre_parse  # type: ignore[import-not-found]
    from re import _constants as sre_constants  # type: ignore[attr-defined]
except ImportError:  # Python 3.10
    import sre_constants
    import sre_parse
from dataclasses import dataclass
from typing import Any

from logicenveval.errors import ConfigError


@dataclass(frozen=True)
class Lit:
    text: str


@dataclass(frozen=True)
class Chars:
    """A character class: `ranges` of code points, negated when `negate`."""

    ranges: tuple[tuple[int, int], ...]
    negate: bool = False


@dataclass(frozen=True)
class Seq:
    items: tuple[Node, ...]


@dataclass(frozen=True)
class Alt:
    options: tuple[Node, ...]


@dataclass(frozen=True)
class Rep:
    node: Node
    low: int
    high: int | None  # None: unbounded


@dataclass(frozen=True)
class Ref:
    name: str


Node = Lit | Chars | Seq | Alt | Rep | Ref

_CHAR = Alt((Chars(((0, 0x1F), (ord('"'), ord('"')), (ord("\\"), ord("\\"))), negate=True),
             Seq((Lit("\\"), Chars(tuple((ord(c), ord(c)) for c in '"\\/bfnrt')))),
             Seq((Lit("\\u"), Rep(Chars(((48, 57), (97, 102), (65, 70))), 4, 4)))))
_DIGITS = Rep(Chars(((48, 57),)), 1, None)
_NUMBER = Seq((Rep(Lit("-"), 0, 1), _DIGITS, Rep(Seq((Lit("."), _DIGITS)), 0, 1),
               Rep(Seq((Chars(((ord("e"), ord("e")), (ord("E"), ord("E")))),
                        Rep(Chars(((ord("+"), ord("+")), (ord("-"), ord("-")))), 0, 1), _DIGITS)), 0, 1)))
_INTEGER = Seq((Rep(Lit("-"), 0, 1), _DIGITS))


def _string(inner: Node) -> Node:
    return Seq((Lit('"'), inner, Lit('"')))


class _Builder:
    def __init__(self, schema: dict[str, Any]) -> None:
        self.defs: dict[str, Any] = schema.get("$defs") or {}
        self.rules: dict[str, Node] = {}

    def ref(self, ref: str) -> Node:
        if not ref.startswith("#/$defs/"):
            raise ConfigError(f"$ref {ref!r} is not local", hint="use #/$defs/ references")
        name = "d-" + re.sub(r"[^A-Za-z0-9-]", "-", ref.removeprefix("#/$defs/"))
        if name not in self.rules:
            self.rules[name] = Lit("")  # placeholder: a recursive schema refers to itself
            self.rules[name] = self.node(self.defs[ref.removeprefix("#/$defs/")])
        return Ref(name)

    def node(self, s: dict[str, Any]) -> Node:
        if "$ref" in s:
            return self.ref(s["$ref"])
        if "const" in s:
            return Lit(json.dumps(s["const"], separators=(",", ":")))
        if "enum" in s:
            return Alt(tuple(Lit(json.dumps(v, separators=(",", ":"))) for v in s["enum"]))
        for key in ("anyOf", "oneOf"):
            if key in s:
                return Alt(tuple(self.node(o) for o in s[key]))
        kind = s.get("type")
        if isinstance(kind, list):
            return Alt(tuple(self.node({**s, "type": k}) for k in kind))
        if kind == "string":
            if "pattern" in s:
                return _string(pattern_node(s["pattern"]))
            return _string(Rep(_CHAR, s.get("minLength", 0), s.get("maxLength")))
        if kind == "number":
            return _NUMBER
        if kind == "integer":
            return _INTEGER
        if kind == "boolean":
            return Alt((Lit("true"), Lit("false")))
        if kind == "null":
            return Lit("null")
        if kind == "array":
            return self.array(s)
        if kind == "object" or "properties" in s:
            return self.object(s)
        return Ref("value")  # any JSON value

    def array(self, s: dict[str, Any]) -> Node:
        prefix = s.get("prefixItems")
        if prefix:
            parts: list[Node] = [Lit("[")]
            for i, item in enumerate(prefix):
                parts += [Lit(",")] * (i > 0) + [self.node(item)]
            return Seq((*parts, Lit("]")))
        item = self.node(s["items"]) if isinstance(s.get("items"), dict) else Ref("value")
        low, high = int(s.get("minItems", 0)), s.get("maxItems")
        if high == 0:
            return Lit("[]")
        rest = Rep(Seq((Lit(","), item)), max(0, low - 1), None if high is None else int(high) - 1)
        body: Node = Seq((item, rest))
        return Seq((Lit("["), body if low > 0 else Rep(body, 0, 1), Lit("]")))

    def object(self, s: dict[str, Any]) -> Node:
        props: dict[str, Any] = s.get("properties") or {}
        if not props:
            extra = s.get("additionalProperties")
            value = self.node(extra) if isinstance(extra, dict) else Ref("value")
            pair = Seq((_string(Rep(_CHAR, 0, None)), Lit(":"), value))
            return Seq((Lit("{"), Rep(Seq((pair, Rep(Seq((Lit(","), pair)), 0, None))), 0, 1), Lit("}")))
        required = [k for k in props if k in set(s.get("required") or ())]
        optional = [k for k in props if k not in required]

        def kv(key: str) -> Node:
            return Seq((Lit(json.dumps(key) + ":"), self.node(props[key])))

        if required:
            # in the schema's order, so a reply is written in the order its model declares (CoT's
            # reasoning before its environments, an object's role and states before its
            # coordinates): optional keys before the first required one each carry their comma
            # after them, the others before them
            parts: list[Node] = [Lit("{")]
            seen_required = False
            for key in props:
                if key in required:
                    parts += [Lit(",")] * seen_required + [kv(key)]
                    seen_required = True
                elif seen_required:
                    parts.append(Rep(Seq((Lit(","), kv(key))), 0, 1))
                else:
                    parts.append(Rep(Seq((kv(key), Lit(","))), 0, 1))
            return Seq((*parts, Lit("}")))
        # all optional: the first one present has no comma before it
        tail: Node = Lit("")
        start: Node = Lit("")
        for key in reversed(optional):
            start = Alt((Seq((kv(key), tail)), start))
            tail = Seq((Rep(Seq((Lit(","), kv(key))), 0, 1), tail))
        return Seq((Lit("{"), start, Lit("}")))


_VALUE_RULES: dict[str, str] = {
    "value": 'object | array | string | number | "true" | "false" | "null"',
    "object": '"{" ( string ":" value ( "," string ":" value )* )? "}"',
    "array": '"[" ( value ( "," value )* )? "]"',
}


def pattern_node(regex: str) -> Node:
    """A regex of the subset the vocabularies use (literals, classes, groups, alternation,
    bounded repeats, anchors) as a grammar node of the string's content."""
    try:
        return _from_sre(sre_parse.parse(regex))
    except (re.error, ConfigError) as exc:
        raise ConfigError(f"pattern {regex!r} cannot be written as a grammar: {exc}",
                          hint="use literals, [classes], (a|b) groups and {m,n} repeats") from None


def _from_sre(parsed: Any) -> Node:
    items: list[Node] = []
    for op, arg in parsed:
        name = str(op)
        if name == "LITERAL":
            items.append(Lit(chr(arg)))
        elif name == "NOT_LITERAL":
            items.append(Chars(((arg, arg),), negate=True))
        elif name == "IN":
            items.append(_in(arg))
        elif name == "ANY":
            items.append(Chars((), negate=True))
        elif name in ("MAX_REPEAT", "MIN_REPEAT"):
            low, high, sub = arg
            items.append(Rep(_from_sre(sub), int(low), None if high == sre_constants.MAXREPEAT else int(high)))
        elif name == "SUBPATTERN":
            items.append(_from_sre(arg[-1]))
        elif name == "BRANCH":
            items.append(Alt(tuple(_from_sre(b) for b in arg[1])))
        elif name == "AT":
            continue  # ^ and $: the grammar matches the whole string anyway
        else:
            raise ConfigError(f"regex element {name} is not supported")
    return items[0] if len(items) == 1 else Seq(tuple(items))


def _in(arg: Any) -> Chars:
    ranges: list[tuple[int, int]] = []
    negate = False
    for op, value in arg:
        name = str(op)
        if name == "NEGATE":
            negate = True
        elif name == "LITERAL":
            ranges.append((value, value))
        elif name == "RANGE":
            ranges.append((value[0], value[1]))
        else:
            raise ConfigError(f"character class element {name} is not supported")
    return Chars(tuple(ranges), negate)


# ----- writers ----------------------------------------------------------------------------------

def _gbnf_lit(text: str) -> str:
    out = []
    for ch in text:
        if ch in '"\\':
            out.append("\\" + ch)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\x{ord(ch):02X}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def _gbnf_char(code: int) -> str:
    """One character of a GBNF class: llama.cpp's parser knows the escapes of a backslash, a
    quote, brackets and hex codes only, so `-` and `^` are written as hex codes."""
    ch = chr(code)
    if ch in "]\\[":
        return "\\" + ch
    if code < 0x20 or code == 0x7F or ch in "-^":
        return f"\\x{code:02X}"
    return ch


def _gbnf(node: Node) -> str:
    if isinstance(node, Lit):
        return _gbnf_lit(node.text) if node.text else '""'
    if isinstance(node, Chars):
        body = "".join(_gbnf_char(a) if a == b else f"{_gbnf_char(a)}-{_gbnf_char(b)}" for a, b in node.ranges)
        if node.negate and not node.ranges:
            return "[^\\x00]"  # any character
        return f"[{'^' if node.negate else ''}{body}]"
    if isinstance(node, Seq):
        return "(" + " ".join(_gbnf(i) for i in node.items) + ")" if node.items else '""'
    if isinstance(node, Alt):
        return "(" + " | ".join(_gbnf(o) for o in node.options) + ")"
    if isinstance(node, Rep):
        inner = _gbnf(node.node)
        if (node.low, node.high) == (0, 1):
            return f"{inner}?"
        if node.high is None:
            return f"{inner}*" if node.low == 0 else f"{inner}+" if node.low == 1 else f"{inner}{{{node.low},}}"
        return f"{inner}{{{node.low},{node.high}}}"
    return node.name


def to_gbnf(schema: dict[str, Any]) -> str:
    """The GBNF grammar (root rule `root`) of compact JSON values that satisfy `schema`'s shape."""
    builder = _Builder(schema)
    root = builder.node(schema)
    lines = [f"root ::= {_gbnf(root)}"]
    lines += [f"{name} ::= {_gbnf(node)}" for name, node in sorted(builder.rules.items())]
    text = "\n".join(lines)
    if re.search(r"\b(value|object|array|string|number)\b(?! ::=)", text):
        lines += [f"{name} ::= {rule}" for name, rule in _VALUE_RULES.items()]
        lines += [f"string ::= {_gbnf(_string(Rep(_CHAR, 0, None)))}", f"number ::= {_gbnf(_NUMBER)}"]
    return "\n".join(lines) + "\n"


def _re_char(code: int) -> str:
    return re.escape(chr(code)) if chr(code) not in "-]\\^" else "\\" + chr(code)


def _regex(node: Node, rules: dict[str, Node]) -> str:
    if isinstance(node, Lit):
        return re.escape(node.text)
    if isinstance(node, Chars):
        if node.negate and not node.ranges:
            return "[\\s\\S]"
        body = "".join(_re_char(a) if a == b else f"{_re_char(a)}-{_re_char(b)}" for a, b in node.ranges)
        return f"[{'^' if node.negate else ''}{body}]"
    if isinstance(node, Seq):
        return "(?:" + "".join(_regex(i, rules) for i in node.items) + ")"
    if isinstance(node, Alt):
        return "(?:" + "|".join(_regex(o, rules) for o in node.options) + ")"
    if isinstance(node, Rep):
        high = "" if node.high is None else str(node.high)
        return f"(?:{_regex(node.node, rules)}){{{node.low},{high}}}"
    if node.name not in rules:
        raise ConfigError(f"the schema needs rule {node.name!r}, which has no regex form")
    return _regex(rules[node.name], rules)


def to_regex(schema: dict[str, Any]) -> str:
    """The same language as `to_gbnf` as a Python regex (schemas without recursion or free
    JSON values; for tests)."""
    builder = _Builder(schema)
    root = builder.node(schema)
    return _regex(root, builder.rules)
