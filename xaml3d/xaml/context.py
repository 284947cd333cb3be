"""Reading context shared by the XAML reader modules: diagnostics, documents, namespaces.

Holds what every step of reading needs: the list of diagnostics (each stamped with the file the
element came from and the line and column of its start tag or of the attribute concerned, found
by source_map.py), the parsed documents (the scene, App.xaml, merged dictionaries) and which
folders paths may point into, and the namespace classification of elements and attributes
(presentation, XAML language, ignorable, unknown/clr-namespace).
"""

from __future__ import annotations

from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path

from lxml import etree

from xaml3d.codes import severity
from xaml3d.errors import ERROR, Diagnostic, XamlError
from xaml3d.xaml.parser import MC_NS, PRESENTATION_NAMESPACES, XAML_NS, ParsedDocument


def severity_of(code: str) -> str:
    """The table severity of a code the reader reports (its own, the value converters', the
    animation and layout stages'): a severity is never chosen where a code is emitted. KeyError
    for an uncatalogued code."""
    return severity(code)


def as_written(text: str) -> str:
    """``text`` in quotes exactly as the file has it, for messages: a path such as
    ``images\\a.png`` keeps its single backslash (``repr`` would double it)."""
    return f"'{text}'"


def a_an(word: str) -> str:
    """``word`` with its indefinite article: "an Application", "a Viewport3D", "a UserControl"
    (a "u" read as "you": uni-, use-), "an Unknown"."""
    w = word.lower()
    vowel = w[:1] in ("a", "e", "i", "o") or (w.startswith("u") and not w.startswith(("uni", "us")))
    return f"{'an' if vowel else 'a'} {word}"


def qname(el_or_attr: str) -> tuple[str | None, str]:
    """(namespace, local name) of a Clark-notation tag or attribute name."""
    if el_or_attr.startswith("{"):
        ns, _, local = el_or_attr[1:].partition("}")
        return ns, local
    return None, el_or_attr


def is_presentation(ns: str | None) -> bool:
    return ns in PRESENTATION_NAMESPACES


def _one_edit_apart(a: str, b: str) -> bool:
    """Whether ``a`` and ``b`` differ by exactly one insertion, deletion or substitution."""
    if a == b or abs(len(a) - len(b)) > 1:
        return False
    if len(a) > len(b):
        a, b = b, a
    i = 0
    while i < len(a) and a[i] == b[i]:
        i += 1
    return a[i + (len(a) == len(b)) :] == b[i + 1 :]


def namespace_typo(ns: str | None) -> str | None:
    """The WPF namespace URI that ``ns`` misspells (one edit away, or differing only in case),
    else None: WPF resolves no type in such a namespace and refuses the document."""
    if ns is None or ns in PRESENTATION_NAMESPACES or ns == XAML_NS:
        return None
    for wpf in (*sorted(PRESENTATION_NAMESPACES), XAML_NS):
        if ns.lower() == wpf.lower() or _one_edit_apart(ns, wpf):
            return wpf
    return None


class ReadContext:
    """Diagnostics and documents of one load."""

    def __init__(self, *, stages=None, allow_outside: bool = False, limits=None) -> None:
        # the layout engine and the 2D layer's bounds (stage_services.StageServices), handed
        # to the reader by the pipeline: the reader imports neither (None: a read that lays
        # nothing out and measures no drawing, a value converter's)
        self.stages = stages
        self.diagnostics: list[Diagnostic] = []
        # errors reported so far, repeats suppressed by ``once`` too: a property whose reading
        # raised it saw an error (Props.rejected)
        self.errors = 0
        self.allow_outside = allow_outside
        self.limits = limits
        self.allowed_roots: list[Path] = []
        self.files_used: list[str] = []
        self.images_used: list[str] = []  # image files read (never to be written over)
        self._docs: dict[int, tuple[etree._Element, ParsedDocument]] = {}
        self._once: set = set()
        self._building: list[int] = []
        self._keep: list[etree._Element] = []  # keeps proxies alive while ids are used as keys
        # the framework step's copies (a template's elements instantiated in the window):
        # id(copy) -> (copy, the element it copies), whose source position it reports
        self._copies: dict[int, tuple[etree._Element, etree._Element]] = {}
        # controls drawn by a user's ControlTemplate (the framework step's instance is their
        # only child): id -> element
        self.templated: dict[int, etree._Element] = {}
        # a ProgressBar's PART_Indicator: its share of the track's width (framework step)
        self.width_shares: dict[int, float] = {}
        # the ControlTemplates so instantiated: id -> element
        self.instantiated: dict[int, etree._Element] = {}
        # parts masked by BorderGapMaskConverter: id -> (part, its header part, the offset)
        self.gap_masks: dict[int, tuple] = {}
        # the elements no WPF type names (XAML017), id -> element: no findings follow from
        # their estimated size or their missing drawing
        self.refused_elements: dict[int, etree._Element] = {}

    def refused(self, el) -> bool:
        """Whether ``el`` is an element no WPF type names (XAML017)."""
        return self.refused_elements.get(id(el)) is el

    # ----------------------------------------------------------------- documents
    def add_document(self, doc: ParsedDocument, *, trusted: bool = False) -> None:
        self._docs[id(doc.root)] = (doc.root, doc)
        if trusted and doc.directory is not None:
            self.allowed_roots.append(doc.directory)

    def copied(self, copy: etree._Element, original: etree._Element) -> None:
        """``copy`` (made by the framework step) reports ``original``'s source position."""
        hit = self._copies.get(id(original))
        if hit is not None and hit[0] is original:
            original = hit[1]
        self._copies[id(copy)] = (copy, original)

    def original(self, el: etree._Element) -> etree._Element:
        """The element of a document's text that ``el`` is, or copies."""
        hit = self._copies.get(id(el))
        return hit[1] if hit is not None and hit[0] is el else el

    def pin_positions(self, root: etree._Element) -> None:
        """Locate every element of ``root``'s document now, before the framework step changes
        its tree (a position is found by the element's place in document order)."""
        doc = self.doc_of(root)
        if doc is not None:
            for el in root.iter():
                if isinstance(el.tag, str):
                    doc.locate(el)

    def is_templated(self, el: etree._Element) -> bool:
        """Whether ``el`` is a control drawn by a user's ControlTemplate (framework step)."""
        hit = self.templated.get(id(el))
        return hit is not None and hit is el

    def doc_of(self, el: etree._Element) -> ParsedDocument | None:
        el = self.original(el)
        entry = self._docs.get(id(el.getroottree().getroot()))
        return entry[1] if entry else None

    def file_of(self, el: etree._Element | None) -> str | None:
        if el is None:
            return None
        doc = self.doc_of(el)
        return doc.file if doc else None

    def file_elsewhere(self, el: etree._Element) -> str | None:
        """The file of ``el``'s document when it is not the scene's (the first document read:
        a ``-r`` dictionary, App.xaml, a merged dictionary), else None: what the scene builds
        from it is reported in that file, not in the scene's."""
        el = self.original(el)
        first = next(iter(self._docs.values()), None)
        if first is None or first[0] is el.getroottree().getroot():
            return None
        return self.file_of(el)

    def path_allowed(self, path: Path) -> bool:
        if self.allow_outside:
            return True
        path = path.resolve()
        for root in self.allowed_roots:
            try:
                path.relative_to(root.resolve())
                return True
            except ValueError:
                continue
        return False

    @contextmanager
    def muted(self):
        """Read without reporting: what is reported inside is forgotten (so that the build,
        which reads the same markup, reports it in its place, once)."""
        mark, once, errors = len(self.diagnostics), set(self._once), self.errors
        try:
            yield
        finally:
            del self.diagnostics[mark:]
            self._once, self.errors = once, errors

    def keep(self, el: etree._Element) -> etree._Element:
        self._keep.append(el)
        return el

    # ----------------------------------------------------------------- diagnostics
    def locate(
        self, el: etree._Element, attr: str | None = None, index: int | None = None
    ) -> tuple[int | None, int | None]:
        """(line, column) of an element's ``<``, or of attribute ``attr``'s name (a key of
        ``el.attrib``), or of character ``index`` of its value, in its own document's text;
        (sourceline, None) when not found."""
        el = self.original(el)
        doc = self.doc_of(el)
        where = doc.locate(el, attr, index) if doc is not None else None
        return where if where is not None else (el.sourceline, None)

    def position(self, el: etree._Element) -> dict:
        """``line=`` and ``column=`` of an element's start tag, for the scene objects it makes
        (so camera, model and light checks point at the same place the reader's do)."""
        line, column = self.locate(el)
        return {"line": line, "column": column}

    def diag(
        self,
        code: str,
        message: str,
        el: etree._Element | None = None,
        *,
        attr: str | None = None,
        line: int | None = None,
        column: int | None = None,
        file: str | None = None,
        once: object = None,
    ) -> None:
        """Record a diagnostic about ``el`` (or its attribute ``attr``, a key of ``el.attrib``);
        ``once`` (a key) suppresses repeats of the same report."""
        severity = severity_of(code)
        self.errors += severity == ERROR
        if once is not None:
            if (code, once) in self._once:
                return
            self._once.add((code, once))
        if el is not None:
            if line is None:
                line, column = self.locate(el, attr)
            file = file or self.file_of(el)
        self.diagnostics.append(Diagnostic(code, severity, message, file, line, column))

    def add(
        self, diagnostic: Diagnostic, el: etree._Element | None = None, attr: str | None = None
    ) -> None:
        """Record a diagnostic made elsewhere (mesh building...) about ``el`` (or its attribute
        ``attr``): an unknown location, or ``el``'s sourceline, becomes the located one."""
        self.errors += diagnostic.severity == ERROR
        about_el = el is not None and diagnostic.line in (None, el.sourceline)
        if about_el and diagnostic.column is None:
            line, column = self.locate(el, attr)
            diagnostic = Diagnostic(
                diagnostic.code,
                diagnostic.severity,
                diagnostic.message,
                diagnostic.file or self.file_of(el),
                line,
                column,
            )
        elif el is not None and (diagnostic.file is None or diagnostic.line is None):
            diagnostic = replace(
                diagnostic,
                file=diagnostic.file or self.file_of(el),
                line=el.sourceline if diagnostic.line is None else diagnostic.line,
            )
        self.diagnostics.append(diagnostic)

    def error(self, exc: XamlError, el: etree._Element | None, attr: str | None = None) -> None:
        """Turn a recoverable XamlError (bad value syntax...) into a located diagnostic, with
        its code's table severity (errors stay errors: the property keeps its default only so
        that the rest of the scene can still be checked, or rendered with --lenient)."""
        if el is not None:
            # a converter that names the offending character of the attribute's value, or of
            # the element's text (a property element's value written over many lines)
            at = getattr(exc, "at", None)
            index = at[1] if at and attr is not None and at[0] == el.get(attr) else None
            line, column = self.locate(el, attr, index) if exc.line is None else (None, None)
            text = el.text or ""
            if exc.line is None and at and attr is None and at[0] == text.strip():
                doc = self.doc_of(el)
                lead = len(text) - len(text.lstrip())
                where = doc.locate_text(el, lead + at[1]) if doc is not None else None
                line, column = where if where is not None else (line, column)
            exc.with_location(self.file_of(el), line, column)
        severity = severity_of(exc.code)
        self.errors += severity == ERROR
        self.diagnostics.append(
            Diagnostic(exc.code, severity, exc.message, exc.file, exc.line, exc.column)
        )

    # ----------------------------------------------------------------- resource build guard
    def enter_building(self, el: etree._Element) -> bool:
        """Guard against a resource whose value refers back to itself: False on a cycle, else
        True and ``leave_building`` must follow."""
        key = id(el)
        if key in self._building:
            return False
        self.keep(el)
        self._building.append(key)
        return True

    def leave_building(self) -> None:
        self._building.pop()

    @contextmanager
    def building(self, el: etree._Element):
        """Guard against a resource whose value refers back to itself (yields False on a cycle)."""
        if not self.enter_building(el):
            yield False
            return
        try:
            yield True
        finally:
            self.leave_building()


def ignorable_namespaces(el: etree._Element) -> set[str]:
    """Namespaces listed by mc:Ignorable on this element or its ancestors."""
    out: set[str] = set()
    node = el
    while node is not None:
        val = node.get(f"{{{MC_NS}}}Ignorable")
        if val:
            for prefix in val.split():
                uri = node.nsmap.get(prefix)
                if uri:
                    out.add(uri)
        node = node.getparent()
    out.add(MC_NS)
    return out


def x_attr(el: etree._Element, name: str) -> str | None:
    """An x: (XAML language) attribute: Key, Name, Class, Shared ..."""
    return el.get(f"{{{XAML_NS}}}{name}")


def element_name(el: etree._Element) -> str | None:
    """x:Name, or the Name property (both name an object for Storyboard.TargetName)."""
    return x_attr(el, "Name") or el.get("Name")


def doc_position(el: etree._Element) -> tuple[int, ...]:
    """The element's position in document order, as a comparable path of child indices."""
    path = []
    node = el
    parent = node.getparent()
    while parent is not None:
        path.append(parent.index(node))
        node, parent = parent, parent.getparent()
    return tuple(reversed(path))


def split_markup(value: str) -> tuple[str, str] | None:
    """``{Name args}`` -> (Name without prefix, args); None when not a markup extension.

    ``{}`` at the start escapes a literal brace.
    """
    v = value.strip()
    if not v.startswith("{") or v.startswith("{}"):
        return None
    if not v.endswith("}"):
        return ("", v)
    body = v[1:-1].strip()
    name, _, args = body.partition(" ")
    if "," in name:  # "{Binding,Path=X}" is unusual but legal
        name, _, rest = name.partition(",")
        args = rest + args
    return name.split(":")[-1], args.strip()


def markup_key(args: str) -> str:
    """The key of ``{StaticResource key}`` / ``{StaticResource ResourceKey=key}``."""
    a = args.strip()
    if a.startswith("ResourceKey"):
        _, _, a = a.partition("=")
    return a.strip().strip("'\"")
