"""XmlDataProvider's inline data (``<x:XData>``) and the XPath of bindings to it, evaluated at
load over the element interface of the data's elements (no lxml here): the subset real files
use. Steps separated by ``/`` (a leading ``/`` from the document, ``//`` any depth below), each
an element name (no prefix: an element of no namespace, as XPath 1.0 reads it; the data is
written with ``xmlns=""``), ``*``, ``@attr``, ``@*``, ``text()``, ``.``, ``..``, with
predicates ``[n]`` (1-based), ``[last()]``, ``[@a]``, ``[@a='v']`` and ``[name='v']``. Any
other XPath raises ``XPathError`` (the binding then needs what xaml3d does not evaluate).

A node is an element of the data, an attribute's or a text node's string, or ``DOCUMENT``
wrapped around the provider's root element. The value of a node as a binding shows it is its
text: an element's InnerText, an attribute's value, a text node's."""

from __future__ import annotations

import re
from dataclasses import dataclass

from xaml3d.framework import markup

XAML_NS = "http://schemas.microsoft.com/winfx/2006/xaml"
XDATA = f"{{{XAML_NS}}}XData"
MAX_NODES = 100_000  # a selection larger than this is refused (hostile data)


class XPathError(ValueError):
    """An XPath outside the subset evaluated at load."""


@dataclass(frozen=True)
class Document:
    """The XML document of a provider: its only child is the root element."""

    root: object


@dataclass(frozen=True)
class Text:
    """An attribute's or text node's string (a selected node that is not an element)."""

    value: str


def _elements(el) -> list:
    return [k for k in el if isinstance(k.tag, str)]


def document(provider, services=None) -> Document | None:
    """The document of an ``XmlDataProvider``: its inline ``<x:XData>`` data, else its
    ``Source`` file read through ``services`` (the file's root put in an ``x:XData`` holder
    of its own, so that its nodes are data as inline ones are); None without either."""
    source = provider.get("Source")
    if source is not None and services is not None and source.strip():
        root = services.xml_file(source.strip(), provider)
        if root is None:
            return None
        if root.getparent() is None:
            holder = provider.makeelement(XDATA, {})
            holder.append(root)
        return Document(root)
    for child in _elements(provider):
        holder = child
        if child.tag.endswith(".XmlSerializer") or child.tag.endswith("}XmlDataProvider.XData"):
            holder = next(iter(_elements(child)), None)
            if holder is None:
                continue
        if holder.tag == XDATA:
            kids = _elements(holder)
            return Document(kids[0]) if kids else None
    return None


def provider_nodes(provider, services=None) -> list | None:
    """The nodes a provider gives a binding: its document, or what its own ``XPath``
    selects in it; None when it has no data that can be read."""
    doc = document(provider, services)
    if doc is None:
        return None
    own = provider.get("XPath")
    return select([doc], own) if own and own.strip() else [doc]


def is_data(el) -> bool:
    """Whether ``el`` is an element of inline XML data (inside ``x:XData``)."""
    return any(a.tag == XDATA for a in el.iterancestors())


def text_of(node) -> str:
    """A node's text as a binding shows it (an element's InnerText)."""
    if isinstance(node, Text):
        return node.value
    if isinstance(node, Document):
        node = node.root
    return "".join(t for t in node.itertext() if isinstance(t, str))


# --------------------------------------------------------------------------- XPath

_STEP = re.compile(r"^(?P<axis>@?)(?P<name>\*|[A-Za-z_][\w.\-]*|text\(\)|\.\.|\.)"
                   r"(?P<preds>(?:\[[^\]]*\])*)$")  # fmt: skip
_PRED = re.compile(r"\[([^\]]*)\]")
_EQ = re.compile(r"""^\s*(@?)([A-Za-z_][\w.\-]*)\s*=\s*(?:'([^']*)'|"([^"]*)")\s*$""")


def select(nodes: list, xpath: str) -> list:
    """The nodes ``xpath`` selects from the context ``nodes`` (document order, no repeats)."""
    path = xpath.strip()
    if not path:
        return list(nodes)
    if path.startswith("/"):
        docs = []
        for n in nodes:
            d = n if isinstance(n, Document) else _document_of(n)
            if d is not None and d not in docs:
                docs.append(d)
        nodes = docs
        path = path[1:]
        if path.startswith("/"):
            nodes = _descendants(nodes)
            path = path[1:]
        if not path:
            return nodes
    for raw in _split(path):
        if raw == "":  # '//' in the middle: any depth below
            nodes = _descendants(nodes)
            continue
        nodes = _step(nodes, raw)
        if len(nodes) > MAX_NODES:
            raise XPathError(f"XPath {xpath!r} selects more than {MAX_NODES} nodes")
    return nodes


def _split(path: str) -> list[str]:
    """The steps of a relative path ('' for each '//'), brackets and quotes respected."""
    out, cur, depth, quote = [], [], 0, ""
    for ch in path:
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch == "[":
            depth += 1
        elif ch == "]":
            depth -= 1
        elif ch == "/" and depth == 0:
            out.append("".join(cur).strip())
            cur = []
            continue
        cur.append(ch)
    out.append("".join(cur).strip())
    if out[-1] == "" or quote or depth:
        raise XPathError(f"malformed XPath {path!r}")
    return out


def _document_of(node):
    if isinstance(node, Text):
        return None
    top = node
    while top.getparent() is not None and top.getparent().tag != XDATA:
        top = top.getparent()
    return Document(top) if top.getparent() is not None else None


def _children(node) -> list:
    if isinstance(node, Document):
        return [node.root]
    if isinstance(node, Text):
        return []
    return _elements(node)


def _descendants(nodes: list) -> list:
    """Each node and every element below it (the ``//`` axis before a step)."""
    out: list = []
    seen: set[int] = set()
    for n in nodes:
        stack = [n]
        while stack:
            k = stack.pop()
            if id(k) in seen:
                continue
            seen.add(id(k))
            out.append(k)
            stack.extend(reversed(_children(k)))
            if len(out) > MAX_NODES:
                raise XPathError(f"more than {MAX_NODES} nodes below the data's root")
    return out


def _step(nodes: list, raw: str) -> list:
    m = _STEP.match(raw)
    if m is None:
        raise XPathError(f"the step {raw!r} is not evaluated at load")
    axis, name = m.group("axis"), m.group("name")
    preds = _PRED.findall(m.group("preds"))
    out: list = []
    for n in nodes:
        if axis:
            if name in ("text()", ".", ".."):
                raise XPathError(f"the step {raw!r} is not evaluated at load")
            picked = _attributes(n, name)
        elif name == ".":
            picked = [n]
        elif name == "..":
            up = None if isinstance(n, (Document, Text)) else n.getparent()
            picked = [] if up is None else [up if up.tag != XDATA else _document_of(n)]
        elif name == "text()":
            picked = _texts(n)
        else:
            picked = [k for k in _children(n) if name == "*" or k.tag == name]
        for p in preds:
            picked = _predicate(picked, p, raw)
        for k in picked:
            if not any(k is o or k == o for o in out if not isinstance(o, Text)):
                out.append(k)
    return out


def _attributes(n, name: str) -> list:
    if isinstance(n, (Document, Text)):
        return []
    return [Text(v) for k, v in n.attrib.items()
            if not k.startswith("{") and (name == "*" or k == name)]  # fmt: skip


def _texts(n) -> list:
    if isinstance(n, (Document, Text)):
        return []
    parts = [n.text] + [k.tail for k in n]
    return [Text(t) for t in parts if t]


def _predicate(picked: list, pred: str, raw: str) -> list:
    p = pred.strip()
    if p.isdigit():
        i = int(p)
        return [picked[i - 1]] if 1 <= i <= len(picked) else []
    if p == "last()":
        return picked[-1:]
    if re.fullmatch(r"@[A-Za-z_][\w.\-]*", p):
        named = [k for k in picked if not isinstance(k, (Text, Document))]
        return [k for k in named if k.get(p[1:]) is not None]
    m = _EQ.match(p)
    if m is None:
        raise XPathError(f"the predicate [{pred}] of {raw!r} is not evaluated at load")
    attr, name = m.group(1), m.group(2)
    want = m.group(3) if m.group(3) is not None else m.group(4)
    out = []
    for k in picked:
        if isinstance(k, (Text, Document)):
            continue
        if attr:
            if k.get(name) == want:
                out.append(k)
        elif any(c.tag == name and text_of(c) == want for c in _elements(k)):
            out.append(k)
    return out


# --------------------------------------------------------------------------- bindings


def xpath_binding(value: str | None) -> str | None:
    """The XPath of a binding to the data context by XPath alone (``{Binding XPath=@Title}``,
    ``Mode`` allowed), None for anything else."""
    m = markup.split(value)
    if m is None or m[0] != "Binding":
        return None
    positional, named = markup.arguments(m[1])
    if positional or "XPath" not in named or named.keys() - {"XPath", "Mode"}:
        return None
    return named["XPath"].strip()


def item_text(node, xpath: str) -> str | None:
    """The text ``xpath`` selects from an item's data ``node`` (its first node's), None when it
    selects nothing or is outside the subset."""
    try:
        picked = select([node], xpath)
    except XPathError:
        return None
    return text_of(picked[0]) if picked else None
