"""The reader's services to the framework step (``xaml3d.framework.services.Services``):
resource look-up with the document's scoping, copies that keep their source positions and
located diagnostics."""

from __future__ import annotations

import copy
from pathlib import Path

from xaml3d.errors import XamlError
from xaml3d.xaml import framework_members
from xaml3d.xaml.context import as_written, is_presentation, qname
from xaml3d.xaml.framework_members import derives
from xaml3d.xaml.parser import parse_document
from xaml3d.xaml.resources import data_template_key, reduce_uri, type_key
from xaml3d.xaml.theme import theme_styles

_TEMPLATES = {"ControlTemplate", "DataTemplate", "ItemsPanelTemplate", "HierarchicalDataTemplate"}


class ReaderServices:
    """``Services`` over a ReadContext and the document's Resources."""

    def __init__(self, ctx, resources) -> None:
        self.ctx = ctx
        self.resources = resources
        self._xml: dict[Path, object] = {}  # XML data files read, by path (None: unreadable)

    def lookup(self, key: str, from_el, attr: str | None = None):
        return self.resources.lookup(key, from_el, attr=attr)

    def find(self, key: str, from_el):
        return self.resources.find(key, from_el)

    def implicit_style(self, type_name: str, from_el):
        key = type_key(type_name)
        # every dictionary in scope is read by the look-up itself (dictionary_of)
        entry = self.resources.find_implicit(key, from_el)
        return entry if entry is not None and qname(entry.tag)[1] == "Style" else None

    def implicit_data_template(self, type_name: str, from_el):
        entry = self.resources.find(data_template_key(type_name), from_el)
        return entry if entry is not None and qname(entry.tag)[1] == "DataTemplate" else None

    def theme_styles(self, type_name: str) -> list:
        return theme_styles(type_name)

    def members(self, type_name: str):
        return framework_members.members(type_name)

    def wpf_type(self, el) -> str | None:
        if not isinstance(el.tag, str):
            return None
        ns, local = qname(el.tag)
        return local if is_presentation(ns) else None

    def derives(self, type_name: str, target: str) -> bool | None:
        t = target.strip()
        if t.startswith("{") and t.endswith("}"):
            body = t[1:-1].split(None, 1)
            t = body[1].strip() if len(body) == 2 and body[0] in ("x:Type", "Type") else ""
            t = t.removeprefix("TypeName=").strip()
        if not t or ":" in t:
            return None  # a prefixed type: an application's or another namespace's
        return derives(type_name, t)

    def copy(self, el):
        parent = el.getparent()
        if parent is not None and qname(parent.tag)[1] in _TEMPLATES:
            # a template's content instantiated: its Viewport3Ds are found in the instance
            self.ctx.keep(parent)
            self.ctx.instantiated[id(parent)] = parent
        out = copy.deepcopy(el)
        for a, b in zip(el.iter(), out.iter(), strict=True):
            self.ctx.keep(b)
            self.ctx.copied(b, a)
        return out

    def made(self, el, where) -> None:
        self.ctx.keep(el)
        self.ctx.copied(el, where)

    def templated(self, el, template) -> None:
        self.ctx.keep(el)
        self.ctx.templated[id(el)] = el
        if template is not None:
            self.ctx.keep(template)
            self.ctx.instantiated[id(template)] = template

    def gap_masked(self, el, header, offset) -> None:
        self.ctx.keep(el)
        self.ctx.keep(header)
        self.ctx.gap_masks[id(el)] = (el, header, float(offset))

    def indicator(self, el, share: float) -> None:
        self.ctx.keep(el)
        self.ctx.width_shares[id(el)] = share

    def pin(self, root) -> None:
        self.ctx.pin_positions(root)

    def xml_file(self, source: str, where):
        """The root element of the XML data file ``source`` (an XmlDataProvider's Source,
        relative to the document of ``where``), read with the scene's parser and limits (no
        DOCTYPE or entities, the size limit); None, said (BND004), when it cannot be."""
        rel = reduce_uri(source)
        if rel is None:
            why = "network URIs are refused"
            path = None
        else:
            doc = self.ctx.doc_of(where)
            base = doc.directory if doc and doc.directory else Path.cwd()
            path = (base / rel).resolve()
            why = None if self.ctx.path_allowed(path) else "it leaves the scene's folder tree"
        if path is not None and why is None:
            if path in self._xml:
                return self._xml[path]
            try:
                data = parse_document(path, limits=self.ctx.limits, file=str(path))
            except XamlError as exc:
                why = exc.message
            else:
                self.ctx.files_used.append(data.file)
                self._xml[path] = data.root
                return data.root
            self._xml[path] = None
        msg = (f"XmlDataProvider Source {as_written(source)} cannot be read ({why}): the "
               "bindings to it take their FallbackValue")  # fmt: skip
        self.ctx.diag("BND004", msg, where, attr="Source", once=("BND004", id(where)))
        return None

    def diag(self, code: str, message: str, el=None, attr: str | None = None, once=None) -> None:
        self.ctx.diag(code, message, el, attr=attr, once=once)
