"""Groot2 node models: the `<TreeNodesModel>` of the action library (DESIGN.md §5).

Groot2 tells actions from conditions and shows their ports only through a `<TreeNodesModel>`;
every policy we ship or write carries the same one, generated here from the one action library
(`domain/actions.py`), in the form BT.CPP's `writeTreeNodesModelXML` prints (`<Action ID>` with
`<input_port name type>description</input_port>`). `model_problem` tells whether a file's model
is the current one; `with_current_model` rewrites it in place of the old one, keeping the rest of
the text (comments included) as it is.
"""

from __future__ import annotations

import re
from xml.etree.ElementTree import Element
from xml.sax.saxutils import escape, quoteattr

from defusedxml.ElementTree import fromstring

from logicenveval.domain.actions import ACTIONS, CONDITIONS

#: what a port's value names, by port (and leaf, where it differs)
_PORT_DOCS = {
    "obj": "role name of the object",
    "target": "role name of the destination object, or floor",
    "tool": "role name of a held tool (optional)",
    "source": "role name of the source object (e.g. a sink)",
    "room": "room id or room type",
    "key": "attribute key (e.g. color)",
    "value": "attribute value (e.g. red)",
    "flag": "state flag: open, toggled_on, dirty, wet, filled, cooked, sliced, broken",
}
_LEAF_PORT_DOCS = {
    ("Walk", "target"): "role name of an object, a room id or a room type",
    ("InRoom", "room"): "room id or room type",
}
PORT_TYPE = "std::string"
_MODEL = re.compile(r"[ \t]*<TreeNodesModel\b.*?</TreeNodesModel>[ \t]*\n?|[ \t]*<TreeNodesModel\s*/>[ \t]*\n?",
                    re.S)


def port_doc(kind: str, port: str) -> str:
    return _LEAF_PORT_DOCS.get((kind, port), _PORT_DOCS.get(port, port))


#: one model entry: (tag, ID, description, ((port, port description), ...))
Entry = tuple[str, str, str, tuple[tuple[str, str], ...]]


def library_entries() -> list[Entry]:
    """The entries of every library leaf, actions first, in library order."""
    out = [("Action", a.name, a.doc, tuple((p, port_doc(a.name, p)) for p in (*a.ports, *a.optional)))
           for a in ACTIONS.values()]
    out += [("Condition", c.name, c.doc, tuple((p, port_doc(c.name, p)) for p in c.ports))
            for c in CONDITIONS.values()]
    return out


def tree_nodes_model(indent: str = "  ", entries: list[Entry] | None = None) -> str:
    """The library's `<TreeNodesModel>` element (or one of `entries`) as text, each line
    prefixed by `indent`."""
    lines = [f"{indent}<TreeNodesModel>"]
    for tag, kind, doc, ports in library_entries() if entries is None else entries:
        lines.append(f"{indent}  <{tag} ID={quoteattr(kind)}>")
        for port, text in ports:
            lines.append(f"{indent}    <input_port name={quoteattr(port)} type={quoteattr(PORT_TYPE)}>"
                         f"{escape(text)}</input_port>")
        lines.append(f"{indent}    <MetadataFields><Metadata description={quoteattr(doc)}/>"
                     "</MetadataFields>")
        lines.append(f"{indent}  </{tag}>")
    lines.append(f"{indent}</TreeNodesModel>")
    return "\n".join(lines) + "\n"


Canonical = tuple[tuple[str, str, str, tuple[tuple[str, str, str], ...]], ...]


def _canonical(model: Element) -> Canonical:
    """The model's entries and each entry's ports, sorted: order carries no meaning (BT.CPP's
    `writeTreeNodesModelXML` sorts entries by ID and lists ports in hash-map order; we write
    the library's order)."""
    out = []
    for decl in model:
        ports = tuple(sorted((p.get("name", ""), p.get("type", ""), (p.text or "").strip())
                             for p in decl if p.tag.endswith("_port")))
        meta = next((m.get("description", "") for m in decl.iter("Metadata")), "")
        out.append((decl.tag, decl.get("ID", ""), meta, ports))
    return tuple(sorted(out))


CURRENT: Canonical = _canonical(fromstring(tree_nodes_model()))


def model_problem(text: str) -> str | None:
    """Why the `<TreeNodesModel>` of a policy's XML text is not the library's current one."""
    models = fromstring(text).findall("TreeNodesModel")
    if not models:
        return "no <TreeNodesModel> (Groot2 cannot tell actions from conditions)"
    if _canonical(models[0]) != CURRENT:
        return "its <TreeNodesModel> differs from the action library's"
    return None


def with_current_model(text: str) -> str:
    """`text` with its TreeNodesModel replaced by (or, if none, added as) the current one."""
    body = _MODEL.sub("", text)
    end = body.rindex("</root>")
    return body[:end] + tree_nodes_model() + body[end:]
