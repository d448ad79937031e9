"""BehaviorTree.CPP v4 XML <-> `Policy` (DESIGN.md §5).

Parsing goes through defusedxml (no DTDs, no entity expansion) with a tree builder that records
the line of every element, so each error names the node and its line, and lists the valid names.
"""

from __future__ import annotations

import logging
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any
from xml.etree.ElementTree import Element, ParseError, TreeBuilder
from xml.sax.saxutils import quoteattr

from defusedxml import DefusedXmlException
from defusedxml.ElementTree import DefusedXMLParser

from logicenveval.domain.actions import ACTIONS, CONDITIONS
from logicenveval.errors import PolicyFormatError
from logicenveval.limits import limit, raise_hint, read_text
from logicenveval.model.rooms import is_room_type
from logicenveval.sim.groot import tree_nodes_model
from logicenveval.sim.policy import (
    BOOL_PARAMS,
    BRANCHING,
    COMPOSITES,
    CONSTANT_LEAVES,
    DECORATORS,
    MIN_CHILDREN,
    NODE_PARAMS,
    Policy,
    PolicyNode,
    parallel_threshold,
)

_LINE = "__line__"
_log = logging.getLogger(__name__)


class UnknownNodeError(PolicyFormatError):
    """A node ID that is neither a supported BT.CPP node nor in the action library."""


class BadPortError(PolicyFormatError):
    """A leaf with a missing, extra or invalid port (including an unknown role)."""

#: BT.CPP nodes that need wall time, blackboard scripting or ports we do not model (v1)
REJECTED = frozenset({
    "Timeout", "Delay", "Sleep", "Script", "ScriptCondition", "Precondition", "SetBlackboard",
    "UnsetBlackboard", "RunOnce", "Switch2", "Switch3", "Switch4", "Switch5", "Switch6",
    "ManualSelector", "LoopInt", "LoopDouble", "LoopString", "LoopBool", "PopFromQueue",
    "QueueSize", "WasEntryUpdated", "SkipUnlessUpdated", "WaitValueUpdate", "ParallelAll",
    "SequenceStar", "ReactiveSequenceWithMemory", "EntryUpdatedAction", "EntryUpdatedDecorator",
})
_SCRIPT_ATTRS = ("_skipIf", "_successIf", "_failureIf", "_while", "_onSuccess", "_onFailure",
                 "_onHalted", "_post", "_autoremap")
#: BT.CPP's prefix of ID-less `<BehaviorTree>` names (`BehaviorTree_0`, ...; xml_parsing.cpp)
UNNAMED_TREE = "BehaviorTree_"
_BLACKBOARD = re.compile(r"\{[^}]*\}")
_WRAPPERS = ("Action", "Condition", "Control", "Decorator")
#: ports whose value may name a room instead of a role
_ROOM_PORTS = {("Walk", "target"), ("InRoom", "room"), ("AgentIn", "room")}
#: ports whose value is free text (attribute keys/values, state flags)
_FREE_PORTS = {("Attr", "key"), ("Attr", "value"), ("State", "flag")}
_FLOOR_PORTS = {("Place", "target"), ("On", "target"), ("Walk", "target")}
#: integer parameters as BehaviorTree.CPP's `convertFromString<int>` (std::from_chars, int32)
#: reads them in full: ASCII digits, an optional '-', nothing else (`int()` would also take
#: "1_0", " 3", "+3" and non-ASCII digits such as "٣")
_INTEGER = re.compile(r"-?[0-9]+")
_INT32 = (-(2**31), 2**31 - 1)
#: the spellings BehaviorTree.CPP's `convertFromString<bool>` accepts
_BOOLS = {"1": "true", "true": "true", "True": "true", "TRUE": "true",
          "0": "false", "false": "false", "False": "false", "FALSE": "false"}
_ARTICLE = {"Action": "an", "Condition": "a", "Control": "a", "Decorator": "a"}


def _wrapper_of(kind: str) -> str | None:
    """The element a node of this ID is wrapped in (BehaviorTree.CPP's registered type;
    None for an unknown ID, which is reported as such)."""
    if kind in ACTIONS or kind in CONSTANT_LEAVES:
        return "Action"
    if kind in CONDITIONS:
        return "Condition"
    if kind in COMPOSITES or kind in BRANCHING:
        return "Control"
    if kind in DECORATORS:
        return "Decorator"
    return "SubTree" if kind == "SubTree" else None


def _metadata(key: str) -> bool:
    """An attribute BT.CPP keeps out of the ports and ignores (`_description`, `_uid`,
    `_fullpath`, ...; also our `__line__` marker): not a valid port name, and not one of its
    scripting attributes."""
    return key.startswith("_") and key not in _SCRIPT_ATTRS


def known_nodes() -> list[str]:
    return sorted({*COMPOSITES, *BRANCHING, *DECORATORS, *CONSTANT_LEAVES, "SubTree",
                   *ACTIONS, *CONDITIONS})


def ports_of(kind: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(required ports, optional ports) of a leaf."""
    if kind in ACTIONS:
        return ACTIONS[kind].ports, ACTIONS[kind].optional
    if kind in CONDITIONS:
        return CONDITIONS[kind].ports, ()
    return (), ()


#: what is wrong with a node: (message, fix, error class)
Problem = tuple[str, str, type[PolicyFormatError]]


def _children_problem(kind: str, n: int) -> Problem | None:
    """Children counts BT.CPP enforces (VerifyXML, IfThenElse/WhileDoElse ticks)."""
    if kind in DECORATORS and n != 1:
        return (f"decorator <{kind}> needs exactly one child, has {n}",
                "wrap several children in a Sequence", PolicyFormatError)
    if kind in BRANCHING and n not in (2, 3):
        return (f"<{kind}> needs 2 or 3 children (condition, then, else), has {n}",
                "give it a condition, a then-branch and optionally an else-branch", PolicyFormatError)
    if kind in COMPOSITES and n < MIN_CHILDREN.get(kind, 1):
        return (f"<{kind}> needs at least {MIN_CHILDREN.get(kind, 1)} child(ren), has {n}",
                "add children", PolicyFormatError)
    if (kind in ACTIONS or kind in CONDITIONS or kind in CONSTANT_LEAVES or kind == "SubTree") and n:
        return (f"node <{kind}> is a leaf and cannot have children", "move the children out of it",
                PolicyFormatError)
    return None


def _parallel_problem(node: PolicyNode) -> Problem | None:
    """BT.CPP throws when a threshold exceeds the children ("can never succeed/fail")."""
    if node.kind != "Parallel":
        return None
    n = len(node.children)
    for key, default in (("success_count", -1), ("failure_count", 1)):
        count = int(node.param(key) or default)
        if parallel_threshold(count, n) > n:
            return (f"<Parallel> {key}={count} is more than its {n} children (BehaviorTree.CPP "
                    "raises 'Number of children is less than threshold')",
                    f"use a value between 1 and {n}, or -1 for all", PolicyFormatError)
    return None


def _port_problem(kind: str, attrs: dict[str, str], roles: set[str] | None,
                  rooms: set[str] | None) -> Problem | None:
    """A leaf's ports: exactly the library's, each naming a role of the task (or a room or
    the floor where the port allows it, or free text where the port is free)."""
    required, optional = ports_of(kind)
    valid = [*required, *optional]
    for key in attrs:
        if key not in valid:
            return f"node <{kind}> has no port {key!r}", f"valid ports: {valid or 'none'}", BadPortError
    for key in required:
        if key not in attrs:
            return f"node <{kind}> is missing port {key!r}", f"valid ports: {valid}", BadPortError
    if roles is None:
        return None
    for port, value in attrs.items():
        if ((kind, port) in _FREE_PORTS or value in roles
                or ((kind, port) in _FLOOR_PORTS and value == "floor")
                or ((kind, port) in _ROOM_PORTS
                    and (is_room_type(value) or (rooms is not None and value in rooms)))):
            continue
        return (f"node <{kind}>: {port}={value!r} is not a role of the task",
                f"use one of: {', '.join(sorted(roles))}", BadPortError)
    return None


def node_problem(node: PolicyNode, trees: Iterable[str], roles: Iterable[str] | None = None,
                 rooms: Iterable[str] | None = None) -> str | None:
    """Why one node of a built policy (its own kind, parameters, ports and number of children;
    not its children) would not load, or None; `trees` are the policy's BehaviorTree IDs.

    The loader's rules for what a `PolicyNode` can hold, for callers that edit loaded policies
    (mutation operators) and check only the nodes they made.
    """
    kind = node.kind
    problem: Problem | None
    if kind == "SubTree":
        sub = node.param("ID")
        if sub not in set(trees) or len(node.params) != 1:
            return f"<SubTree> needs ID naming one of {sorted(trees)} and nothing else"
        problem = _children_problem(kind, len(node.children))
    elif kind in ACTIONS or kind in CONDITIONS or kind in CONSTANT_LEAVES:
        problem = _children_problem(kind, len(node.children)) or _port_problem(
            kind, dict(node.params), set(roles) if roles is not None else None,
            set(rooms) if rooms is not None else None)
    elif kind in COMPOSITES or kind in BRANCHING or kind in DECORATORS:
        allowed = NODE_PARAMS.get(kind, {})
        keys = [k for k, _ in node.params]
        if len(set(keys)) != len(keys) or not set(keys) <= set(allowed) or any(
                req and k not in keys for k, (req, _) in allowed.items()):
            return f"node <{kind}> has parameters {keys}, valid: {sorted(allowed)}"
        problem = _children_problem(kind, len(node.children)) or _parallel_problem(node)
    else:
        return f"unknown node <{kind}>"
    return None if problem is None else problem[0]


class _LineBuilder(TreeBuilder):
    """Records each element's line and refuses absurd nesting and attribute sizes as it reads."""

    parser: Any = None
    source = "<string>"

    def __init__(self) -> None:
        super().__init__()
        self.depth = 0
        self.max_depth = limit("max_xml_depth")
        self.max_attr = limit("max_xml_attribute_chars")

    def start(self, tag: str, attrs: dict[str, str]) -> Element:
        line = self.parser.parser.CurrentLineNumber
        self.depth += 1
        if self.depth > self.max_depth:
            raise PolicyFormatError(f"elements nest deeper than {self.max_depth} levels",
                                    file=self.source, line=line, hint=raise_hint("max_xml_depth"))
        for key, value in attrs.items():
            if len(value) > self.max_attr:
                raise PolicyFormatError(
                    f"attribute {key[:40]!r} of <{tag[:40]}> has {len(value)} characters, more "
                    f"than the limit of {self.max_attr}", file=self.source, line=line,
                    hint=raise_hint("max_xml_attribute_chars"))
        elem = super().start(tag, attrs)
        elem.set(_LINE, str(line))
        return elem

    def end(self, tag: str) -> Element:
        self.depth -= 1
        return super().end(tag)


def _parse_xml(text: str, source: str) -> Element:
    builder = _LineBuilder()
    parser = DefusedXMLParser(target=builder, forbid_dtd=True)
    builder.parser = parser
    builder.source = source
    try:
        parser.feed(text)
        root: Element = parser.close()
    except ParseError as exc:
        line = exc.position[0] if getattr(exc, "position", None) else None
        raise PolicyFormatError(f"not well-formed XML: {exc}", file=source, line=line,
                                hint="fix the XML syntax") from None
    except DefusedXmlException as exc:
        raise PolicyFormatError(f"forbidden XML construct: {exc}", file=source,
                                hint="remove DTDs and entity declarations") from None
    return root


class _Reader:
    def __init__(self, source: str, roles: Iterable[str] | None, rooms: Iterable[str] | None):
        self.source = source
        self.roles = set(roles) if roles is not None else None
        self.rooms = set(rooms) if rooms is not None else None
        #: the main policy file's folder: includes may not leave it
        self.top: Path | None = None

    def fail(self, elem: Element, message: str, hint: str,
             cls: type[PolicyFormatError] = PolicyFormatError) -> PolicyFormatError:
        return cls(message, file=self.source, line=int(elem.get(_LINE, "0")) or None,
                                 hint=hint)

    # ----- one element -------------------------------------------------------------------
    def node(self, elem: Element) -> PolicyNode:
        tag = elem.tag
        attrs = {k: v for k, v in elem.attrib.items() if not _metadata(k)}
        kind = tag
        if tag in _WRAPPERS:
            if "ID" not in attrs:
                raise self.fail(elem, f"<{tag}> needs an ID attribute", f'write <{tag} ID="..."/>')
            kind = attrs.pop("ID")
            self._check_wrapper(elem, tag, kind)
        where = f"node <{kind}>"
        if kind in REJECTED:
            raise self.fail(elem, f"{where} is not supported: it needs wall time or blackboard "
                            "scripting, which the symbolic simulator (v1) does not model",
                            f"rewrite without {kind}; supported: {', '.join(known_nodes())}")
        for key in _SCRIPT_ATTRS:
            if key in attrs:
                raise self.fail(elem, f"{where}: attribute {key!r} (scripting/remapping) is not "
                                "supported in v1", f"remove {key}")
        # `name` is the instance name (metadata, never a port): `{x}` there is plain text
        name = attrs.pop("name", None)
        for key, value in attrs.items():
            if _BLACKBOARD.search(value):
                raise self.fail(elem, f"{where}: port {key}={value!r} uses a blackboard value; "
                                "not supported in v1", "write the role name literally")
        children = [c for c in elem]
        if kind == "SubTree":
            return self._subtree(elem, attrs, children, name)
        if kind in ACTIONS or kind in CONDITIONS or kind in CONSTANT_LEAVES:
            problem = _children_problem(kind, len(children))
            if problem is not None:
                raise self.fail(elem, *problem)
            return PolicyNode(kind, self._ports(elem, kind, attrs), (), name,
                              int(elem.get(_LINE, "0")))
        if kind in COMPOSITES or kind in BRANCHING or kind in DECORATORS:
            return self._control(elem, kind, attrs, children, name)
        raise self.fail(elem, f"unknown node <{kind}>",
                        f"use one of: {', '.join(known_nodes())}", UnknownNodeError)

    def _check_wrapper(self, elem: Element, tag: str, kind: str) -> None:
        """`<Action|Condition|Control|Decorator ID=...>` must name a node of that type.

        BehaviorTree.CPP looks the node up by ID and ignores the tag (it loads `<Action
        ID="Sequence">` with children and `<Control ID="Walk"/>`), but Groot2 draws and edits the
        node as the tag says; a mismatch is an authoring error, refused here.
        """
        want = _wrapper_of(kind)
        if want is None or want == tag:
            return
        if want == "SubTree":
            raise self.fail(elem, f"<{tag} ID=\"SubTree\"> is not how a SubTree is written",
                            '<SubTree ID="TreeName"/>')
        form = f'<{want} ID="{kind}" .../>' if want in ("Action", "Condition") else (
            f'<{want} ID="{kind}">...</{want}> or <{kind}>...</{kind}>')
        raise self.fail(elem, f"<{tag} ID=\"{kind}\">: {kind} is {_ARTICLE[want]} "
                        f"{want.lower()} node, not {_ARTICLE[tag]} {tag.lower()} node",
                        f"write {form}")

    def _subtree(self, elem: Element, attrs: dict[str, str], children: list[Element],
                 name: str | None) -> PolicyNode:
        sub_id = attrs.pop("ID", None)
        if sub_id is None:
            raise self.fail(elem, "<SubTree> needs an ID attribute", '<SubTree ID="TreeName"/>')
        if attrs:
            raise self.fail(elem, f"<SubTree ID={sub_id!r}>: port remapping "
                            f"{sorted(attrs)} is not supported in v1",
                            "remove the remapping attributes; subtrees see the same roles")
        if children:
            raise self.fail(elem, "<SubTree> cannot have children", "define them in its BehaviorTree")
        return PolicyNode("SubTree", (("ID", sub_id),), (), name, int(elem.get(_LINE, "0")))

    def _control(self, elem: Element, kind: str, attrs: dict[str, str], children: list[Element],
                 name: str | None) -> PolicyNode:
        allowed = NODE_PARAMS.get(kind, {})
        extra = sorted(set(attrs) - set(allowed))
        if extra:
            raise self.fail(elem, f"node <{kind}> has unknown parameter(s) {extra}",
                            f"valid: {sorted(allowed) or 'none'}")
        params: list[tuple[str, str]] = []
        for key, (required, _default) in allowed.items():
            if key not in attrs:
                if required:
                    raise self.fail(elem, f"node <{kind}> needs parameter {key!r}",
                                    f'add {key}="N" (-1 means unbounded)')
                continue
            params.append((key, self._param(elem, kind, key, attrs[key])))
        problem = _children_problem(kind, len(children))
        if problem is not None:
            raise self.fail(elem, *problem)
        kids = tuple(self.node(c) for c in children)
        node = PolicyNode(kind, tuple(params), kids, name, int(elem.get(_LINE, "0")))
        problem = _parallel_problem(node)
        if problem is not None:
            raise self.fail(elem, *problem)
        return node

    def _param(self, elem: Element, kind: str, key: str, text: str) -> str:
        if (kind, key) in BOOL_PARAMS:
            word = _BOOLS.get(text)
            if word is None:
                raise self.fail(elem, f"node <{kind}>: {key}={text[:40]!r} is not a boolean "
                                "as BehaviorTree.CPP reads one (0, 1, true, True, TRUE, false, "
                                "False, FALSE)", f'write {key}="true" or "false"')
            return word
        if not _INTEGER.fullmatch(text):
            lead = _INTEGER.match(text)
            why = f"; BehaviorTree.CPP would read only its leading {lead.group()!r}" if lead else ""
            raise self.fail(elem, f"node <{kind}>: {key}={text[:40]!r} is not an integer "
                            f"(ASCII digits with an optional leading '-'){why}",
                            f'write {key}="3"')
        value = int(text)
        if not _INT32[0] <= value <= _INT32[1]:
            raise self.fail(elem, f"node <{kind}>: {key}={text[:40]} is out of the range of a "
                            "32-bit int (BehaviorTree.CPP refuses it)", f'write {key}="3"')
        return str(value)

    def _ports(self, elem: Element, kind: str, attrs: dict[str, str]) -> tuple[tuple[str, str], ...]:
        problem = _port_problem(kind, attrs, self.roles, self.rooms)
        if problem is not None:
            raise self.fail(elem, *problem)
        valid = [*ports_of(kind)[0], *ports_of(kind)[1]]
        return tuple((k, attrs[k]) for k in valid if k in attrs)

    # ----- documents ---------------------------------------------------------------------
    def document(self, root: Element, path: Path | None, seen: set[str], acc: _Trees) -> _Doc:
        """Read one file into `acc`: includes first, then its trees (BT.CPP's order, which
        numbers ID-less trees)."""
        if root.tag != "root":
            raise self.fail(root, f"root element is <{root.tag}>, expected <root>",
                            '<root BTCPP_format="4" main_tree_to_execute="Main">')
        fmt = root.get("BTCPP_format")
        if fmt is None:
            acc.warnings.append(f"{self.source}: <root> has no BTCPP_format; read as 4 "
                                '(BehaviorTree.CPP does the same); add BTCPP_format="4"')
        elif fmt != "4":
            raise self.fail(root, f"BTCPP_format={fmt!r}; only BehaviorTree.CPP v4 is supported",
                            'set BTCPP_format="4"')
        children = list(root)
        for child in children:
            if child.tag not in ("BehaviorTree", "include", "TreeNodesModel"):
                raise self.fail(child, f"unexpected element <{child.tag}> under <root>",
                                "use <BehaviorTree>, <include> or <TreeNodesModel>")
        for child in children:
            if child.tag == "include":
                self._include(child, path, seen, acc)
            elif child.tag == "TreeNodesModel":
                self._model(child)
        own = [self._tree(c, acc, alone=len(children) == 1)
               for c in children if c.tag == "BehaviorTree"]
        return _Doc(root.get("main_tree_to_execute"), own)

    def _tree(self, elem: Element, acc: _Trees, *, alone: bool) -> str:
        tree_id = elem.get("ID")
        if not tree_id:
            if not alone:
                raise self.fail(elem, "<BehaviorTree> needs an ID when <root> has other elements",
                                '<BehaviorTree ID="Main">')
            tree_id = f"{UNNAMED_TREE}{acc.unnamed}"
            acc.unnamed += 1
        if tree_id in acc.trees:
            raise self.fail(elem, f"BehaviorTree {tree_id!r} is defined twice", "rename one of them")
        kids = list(elem)
        if len(kids) != 1:
            raise self.fail(elem, f"BehaviorTree {tree_id!r} must have exactly one root node, "
                            f"has {len(kids)}", "wrap the nodes in a Sequence")
        acc.trees[tree_id] = (self.node(kids[0]), int(elem.get(_LINE, "0")))
        return tree_id if elem.get("ID") else ""

    def _include(self, elem: Element, path: Path | None, seen: set[str], acc: _Trees) -> None:
        rel = elem.get("path")
        if not rel:
            raise self.fail(elem, "<include> needs a path", '<include path="other.xml"/>')
        base = path.parent if path is not None else Path.cwd()
        target = (base / rel).resolve()
        if str(target) in seen:
            raise self.fail(elem, f"include cycle through {target}", "remove the circular include")
        top = self.top or base.resolve()
        if not target.is_relative_to(top):  # untrusted policies must not read files elsewhere
            raise self.fail(elem, f"include {rel!r} is outside the policy's folder {top}",
                            "keep included files next to (or below) the main policy file")
        if not target.is_file():
            raise self.fail(elem, f"included file {rel!r} not found (looked at {target})",
                            "paths are relative to the including file")
        sub = _Reader(str(target), self.roles, self.rooms)
        sub.top = top
        text = read_text(target, what="included BT XML file", error=PolicyFormatError,
                         max_bytes="max_xml_bytes", hint="paths are relative to the including file")
        sub.document(_parse_xml(text, str(target)), target,
                     seen | {str(target)}, acc)

    def _model(self, elem: Element) -> None:
        """Entries for nodes outside the action library are ignored (Groot2 palettes list
        more than a tree uses; using one is still an unknown node); library entries must
        match the library's kind and ports."""
        for decl in elem:
            kind = decl.get("ID", "")
            if decl.tag not in (*_WRAPPERS, "SubTree"):
                raise self.fail(decl, f"unexpected <{decl.tag}> in TreeNodesModel",
                                "declare <Action ID=...> or <Condition ID=...>")
            if kind not in ACTIONS and kind not in CONDITIONS:
                continue
            wanted = "Action" if kind in ACTIONS else "Condition"
            if decl.tag != wanted:
                raise self.fail(decl, f"TreeNodesModel declares {kind} as <{decl.tag}>; the "
                                f"action library has it as <{wanted}>", f'write <{wanted} ID="{kind}">')
            required, optional = ports_of(kind)
            declared = {p.get("name", "") for p in decl if p.tag.endswith("port")}
            if not declared <= {*required, *optional} or not set(required) <= declared:
                raise self.fail(decl, f"TreeNodesModel ports of {kind} are {sorted(declared)}, "
                                f"the library's are {[*required, *optional]}",
                                "declare exactly the library's ports")


@dataclass
class _Trees:
    """What the files of one policy add up to: trees in BT.CPP's load order."""

    trees: dict[str, tuple[PolicyNode, int]] = field(default_factory=dict)
    unnamed: int = 0
    warnings: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class _Doc:
    main: str | None  # its main_tree_to_execute
    own: list[str]  # IDs of its own BehaviorTrees ("" for an ID-less one)


def policy_from_xml(text: str, source: str = "<string>", *, roles: Iterable[str] | None = None,
                    rooms: Iterable[str] | None = None, path: Path | None = None) -> Policy:
    """Parse BT.CPP v4 XML; `roles`/`rooms` (when given) restrict the names ports may use."""
    reader = _Reader(source, roles, rooms)
    reader.top = path.resolve().parent if path is not None else None
    root = _parse_xml(text, source)
    acc = _Trees()
    doc = reader.document(root, path, {str(path.resolve())} if path else set(), acc)
    trees = acc.trees
    if not trees:
        raise PolicyFormatError("no <BehaviorTree> in the file", file=source,
                                hint='add <BehaviorTree ID="Main">...</BehaviorTree>')
    main = _main_tree(doc, trees)
    if main is None:
        raise reader.fail(root, "several BehaviorTrees but no main_tree_to_execute",
                          f"set main_tree_to_execute to one of {sorted(trees)}")
    if main not in trees:
        raise reader.fail(root, f"main_tree_to_execute={main!r} is not a BehaviorTree",
                          f"use one of {sorted(trees)}")
    for w in acc.warnings:
        _log.warning(w)
    policy = Policy(main, {k: v[0] for k, v in trees.items()}, source, tuple(acc.warnings))
    _check_subtrees(policy, reader)
    return policy


def _main_tree(doc: _Doc, trees: dict[str, tuple[PolicyNode, int]]) -> str | None:
    """BT.CPP's choice (bt_factory.cpp `detectMainTreeId`, `XMLParser::instantiateTree`): the
    file's main_tree_to_execute, else its only BehaviorTree if that has an ID, else the only
    tree loaded (includes counted)."""
    if doc.main is not None:
        return doc.main
    if len(doc.own) == 1 and doc.own[0]:
        return doc.own[0]
    return next(iter(trees)) if len(trees) == 1 else None


def _check_subtrees(policy: Policy, reader: _Reader) -> None:
    """Every SubTree names a defined tree, no tree includes itself, and the expanded tree fits.

    Expansion inlines every SubTree, so trees that each call the next level twice grow
    exponentially from a few KB of XML; the expanded size is counted per tree (memoised, linear
    in the file) and refused above the `max_subtree_nodes` budget.
    """
    budget = limit("max_subtree_nodes")
    sizes: dict[str, int] = {}

    def size(node: PolicyNode, stack: tuple[str, ...]) -> int:
        total = 1
        if node.kind == "SubTree":
            sub = node.param("ID") or ""
            if sub not in policy.trees:
                raise PolicyFormatError(f"<SubTree ID={sub!r}> names no BehaviorTree",
                                        file=reader.source, line=node.line or None,
                                        hint=f"use one of {sorted(policy.trees)}")
            if sub in stack:
                raise PolicyFormatError(f"SubTree {sub!r} is recursive ({' -> '.join(stack)})",
                                        file=reader.source, line=node.line or None,
                                        hint="a tree cannot contain itself")
            if sub not in sizes:
                sizes[sub] = size(policy.trees[sub], (*stack, sub))
            total += sizes[sub]
        for c in node.children:
            total += size(c, stack)
        return min(total, budget + 1)

    expanded = size(policy.trees[policy.main], (policy.main,))
    if expanded > budget:
        raise PolicyFormatError(f"the tree expands to more than {budget} nodes through its "
                                "SubTrees", file=reader.source,
                                hint="reuse fewer SubTrees per level, or "
                                + raise_hint("max_subtree_nodes"))


def load_policy(path: str | Path, roles: Iterable[str] | None = None,
                rooms: Iterable[str] | None = None) -> Policy:
    p = Path(path)
    text = read_text(p, what="policy file", error=PolicyFormatError, max_bytes="max_xml_bytes",
                     hint="give an existing BT.CPP v4 XML file")
    return policy_from_xml(text, str(p), roles=roles, rooms=rooms, path=p)


def _emit(node: PolicyNode, depth: int, out: list[str]) -> None:
    pad = "  " * depth
    attrs = "".join(f" {k}={quoteattr(v)}" for k, v in node.params)
    if node.name is not None:
        attrs = f" name={quoteattr(node.name)}" + attrs
    if not node.children:
        out.append(f"{pad}<{node.kind}{attrs}/>")
        return
    out.append(f"{pad}<{node.kind}{attrs}>")
    for c in node.children:
        _emit(c, depth + 1, out)
    out.append(f"{pad}</{node.kind}>")


def policy_to_xml(policy: Policy) -> str:
    """BT.CPP v4 XML of a policy (includes inlined) with the library's Groot2 TreeNodesModel,
    loadable by BT.CPP, Groot2 and us."""
    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           f'<root BTCPP_format="4" main_tree_to_execute={quoteattr(policy.main)}>']
    for tree_id, node in policy.trees.items():
        out.append(f"  <BehaviorTree ID={quoteattr(tree_id)}>")
        _emit(node, 2, out)
        out.append("  </BehaviorTree>")
    out.append(tree_nodes_model().rstrip("\n"))
    out.append("</root>")
    return "\n".join(out) + "\n"
