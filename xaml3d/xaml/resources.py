"""Resource dictionaries and resource references (XAML ``.Resources``, StaticResource...).

Covers: ``x:Key`` entries of any ``<X.Resources>`` (Window, Page, Grid, Viewport3D, Application,
ResourceDictionary ...) and of a root ``ResourceDictionary``; ``MergedDictionaries`` with
``Source`` (resolved relative to the referring file, refused outside the allowed folder trees);
application resources from files the user names or from an ``App.xaml`` found beside the scene
or in its parent folders; ``{StaticResource}`` / ``{DynamicResource}`` / ``<StaticResource/>``
lookup by scope (nearest enclosing element first, up the tree, then the application) and, for
StaticResource, document order (the entry must come first).

Entries are kept as lxml elements and built at each use by the builder (the Scene is immutable,
so a resource used twice is simply built twice), in the context of the document that defines
them: a reference inside an App.xaml entry resolves from App.xaml's tree.
"""

from __future__ import annotations

import os
import re
from dataclasses import replace
from pathlib import Path

from lxml import etree

from xaml3d.errors import Diagnostic, ResourceError, XamlError
from xaml3d.xaml.context import (
    ReadContext,
    as_written,
    ignorable_namespaces,
    is_presentation,
    markup_key,
    qname,
    x_attr,
)
from xaml3d.xaml.parser import XAML_NS, ParsedDocument, parse_document

APP_FILE_NAMES = ("app.xaml",)
APP_DISCOVERY_LEVELS = 8


def reduce_uri(source: str) -> str | None:
    """A local relative path from a XAML URI (pack URIs reduced); None for network URIs."""
    s = source.strip()
    low = s.lower()
    if low.startswith(("http://", "https://", "ftp://", "//", "\\\\")):
        return None
    for marker in (";component/", ",,,/"):
        i = low.rfind(marker)
        if i >= 0:
            s = s[i + len(marker) :]
            break
    if s.lower().startswith("file:///"):
        s = s[8:] if os.name == "nt" else s[7:]
    s = s.replace("\\", "/")
    if s.startswith("/") and not Path(s).exists():
        s = s.lstrip("/")  # "/Folder/x.xaml" is relative to the application root
    return s


_ASSEMBLY = re.compile(r"(?:^|/)([^/;]+);component/", re.IGNORECASE)


def uri_assembly(source: str) -> str | None:
    """The assembly a XAML URI names (``/Name;component/...``, also in a pack URI), else None:
    such a dictionary is compiled into that library."""
    m = _ASSEMBLY.search(source.strip().replace("\\", "/"))
    return m.group(1) if m else None


class Dictionary:
    """One resource dictionary: own entries plus merged dictionaries. ``assembly`` names the
    library of a merged dictionary xaml3d cannot read (its entries are unknown)."""

    def __init__(self, owner: etree._Element, assembly: str | None = None) -> None:
        self.owner = owner
        self.entries: dict[str, etree._Element] = {}
        self.merged: list[Dictionary] = []
        self.assembly = assembly

    def keys(self) -> list[str]:
        """Every key this dictionary defines, its merged dictionaries' too."""
        out = list(self.entries)
        for d in self.merged:
            out.extend(d.keys())
        return out

    def unavailable(self) -> list[str]:
        """The assemblies of the merged dictionaries (at any depth) that could not be read."""
        out = [self.assembly] if self.assembly else []
        for d in self.merged:
            out.extend(d.unavailable())
        return out

    def find(self, key: str) -> tuple[etree._Element, bool] | None:
        """(entry, is_local): local entries first, then merged ones, the last merged first."""
        if key in self.entries:
            return self.entries[key], True
        for d in reversed(self.merged):
            hit = d.find(key)
            if hit:
                return hit[0], False
        return None


_SIBLINGS_MAX = 200  # files of a folder looked into for a missing key's hint
_SIBLING_BYTES = 4 << 20
_DICTIONARY_ROOT = re.compile(rb"<\s*(?:[\w.-]+:)?(ResourceDictionary|Application)[\s>/]")
_sibling_cache: dict[tuple[str, float], list[tuple[str, bytes]]] = {}


def _dictionaries_in(folder: Path) -> list[tuple[str, bytes]]:
    """(name, text) of the resource dictionaries and Application files of ``folder``: the
    first element past the prolog and comments is a ResourceDictionary or Application."""
    try:
        stamp = (str(folder), folder.stat().st_mtime)
    except OSError:
        return []
    hit = _sibling_cache.get(stamp)
    if hit is not None:
        return hit
    out = []
    try:
        names = sorted(p for p in folder.iterdir() if p.suffix.lower() == ".xaml")
    except OSError:
        names = []
    for path in names[:_SIBLINGS_MAX]:
        try:
            if path.stat().st_size > _SIBLING_BYTES:
                continue
            data = path.read_bytes()
        except OSError:
            continue
        head = data[:65536].removeprefix(b"\xef\xbb\xbf")  # a UTF-8 byte order mark
        first = re.sub(rb"<\?.*?\?>|<!--.*?-->", b"", head, flags=re.S).lstrip()
        if _DICTIONARY_ROOT.match(first):
            out.append((path.name, data))
    _sibling_cache.clear()  # one folder at a time: a scene's own
    _sibling_cache[stamp] = out
    return out


def siblings_defining(folder: Path, key: str) -> list[str]:
    """The names of the resource dictionaries (and Application files) in ``folder`` that
    define ``key`` as an x:Key, in name order."""
    pattern = re.compile(rb"\b(?:[\w]+:)?Key\s*=\s*[\"']" + re.escape(key.encode()) + rb"[\"']")
    return [name for name, data in _dictionaries_in(folder) if pattern.search(data)]


def best_siblings(wanted: list[tuple[object, list[str]]]) -> dict[int, tuple[str, int]]:
    """For missing keys ``wanted`` as (anything, the sibling files defining the key), in source
    order: {index: (file, how many of the keys it resolves)}, a file chosen for each key that
    one defines. The file defining the most of the keys still unresolved is taken first (the
    first by name on a tie), then the next for the keys it leaves, and so on: one ``-r`` that
    resolves them all is suggested as that, not as the file that happens to define the first."""
    chosen: dict[int, tuple[str, int]] = {}
    left = [i for i, (_, names) in enumerate(wanted) if names]
    while left:
        counts: dict[str, int] = {}
        for i in left:
            for name in wanted[i][1]:
                counts[name] = counts.get(name, 0) + 1
        best = min(counts, key=lambda n: (-counts[n], n))
        for i in left:
            if best in wanted[i][1]:
                chosen[i] = (best, counts[best])
        left = [i for i in left if i not in chosen]
    return chosen


def _resources_of(owner: etree._Element, child: etree._Element) -> bool:
    """Whether ``child`` is ``owner``'s ``<X.Resources>`` property element."""
    ns, local = qname(child.tag)
    prefix, dot, prop = local.rpartition(".")
    if not dot or prop != "Resources":
        return False
    return is_presentation(ns) or (ns, prefix) == qname(owner.tag)


class Resources:
    """Resource lookup for one load."""

    def __init__(self, ctx: ReadContext) -> None:
        self.ctx = ctx
        self._dicts: dict[int, tuple[etree._Element, Dictionary | None]] = {}
        self._files: dict[Path, Dictionary | None] = {}
        self._loading: set[Path] = set()
        self.app: list[tuple[ParsedDocument, Dictionary]] = []
        self.type_keys: set[str] = set()  # keys of the implicit Styles read so far
        # the references looked up so far: id(element) -> (element, its attributes)
        self._looked: dict[int, tuple[etree._Element, set[str | None]]] = {}
        self._orders: dict[int, tuple] = {}  # id(root) -> (root, its elements, id -> index)
        self.scene_folder: Path | None = None  # the scene file's folder (the sibling hints')
        # RES001 reports whose hint names a dictionary beside the scene: (report, sibling files
        # that define the key, their folder), completed once every key is looked up
        # (``finish_hints``)
        self._sibling_hints: list[tuple[Diagnostic, list[str], Path]] = []

    # ----------------------------------------------------------------- dictionaries
    def dictionary_of(self, owner: etree._Element) -> Dictionary | None:
        """The resources an element carries (its ``.Resources``, or itself if a dictionary)."""
        hit = self._dicts.get(id(owner))
        if hit is not None:
            return hit[1]
        self._dicts[id(owner)] = (owner, None)  # guards re-entry while merging
        d = self._collect(owner)
        self._dicts[id(owner)] = (owner, d)
        return d

    def _collect(self, owner: etree._Element) -> Dictionary | None:
        containers: list[etree._Element] = []
        if qname(owner.tag)[1] == "ResourceDictionary":
            containers.append(owner)
        for child in owner:
            # <X.Resources> of WPF's X or of the element's own type (<local:Panel.Resources>
            # on a custom control is FrameworkElement.Resources); not another assembly's
            # attached property of that name
            if isinstance(child.tag, str) and _resources_of(owner, child):
                kids = [k for k in child if isinstance(k.tag, str)]
                explicit = (
                    len(kids) == 1
                    and qname(kids[0].tag)[1] == "ResourceDictionary"
                    and x_attr(kids[0], "Key") is None
                )
                # <X.Resources><ResourceDictionary>...: the explicit dictionary is the content
                containers.append(kids[0] if explicit else child)
        if not containers:
            return None
        result = Dictionary(owner)
        for c in containers:
            self._fill(result, c)
        return result

    def _fill(self, d: Dictionary, container: etree._Element) -> None:
        if qname(container.tag)[1] == "ResourceDictionary" and container.get("Source"):
            merged = self._merged(container)  # <ResourceDictionary Source="..."/> as the whole
            if merged is not None:
                d.merged.append(merged)
        for child in container:
            if not isinstance(child.tag, str):
                continue
            local = qname(child.tag)[1]
            if local == "ResourceDictionary.MergedDictionaries":
                for md in child:
                    if isinstance(md.tag, str):
                        merged = self._merged(md)
                        if merged is not None:
                            d.merged.append(merged)
                continue
            if "." in local:
                continue  # other property elements of the dictionary
            key = x_attr(child, "Key")
            if key is not None and is_type_key(key):
                key = type_key(key)  # x:Key="{x:Type Border}": the implicit style's own key
            if key is None and local == "Style" and child.get("TargetType"):
                key = type_key(child.get("TargetType"))  # an implicit style: keyed by its type
            if key is None and local == "DataTemplate" and child.get("DataType"):
                # an implicit DataTemplate: keyed by its DataType (WPF's DataTemplateKey)
                key = data_template_key(child.get("DataType"))
            if key is None:
                if local not in ("Style", "DataTemplate", "ControlTemplate"):
                    self.ctx.diag("RES007", f"{local} in a resource dictionary has no x:Key", child)
                continue
            self.ctx.keep(child)
            first = d.entries.get(key)
            if first is not None:  # WPF: "Item has already been added" (the later one is kept)
                written = x_attr(child, "Key")
                shown = written if written is not None else key
                msg = (f"the key {shown!r} is already used in this resource dictionary "
                       f"(line {self.ctx.locate(first)[0]}): WPF refuses the file")  # fmt: skip
                attr = f"{{{XAML_NS}}}Key" if written is not None else None
                self.ctx.diag("RES014", msg, child, attr=attr)
            d.entries[key] = child
            if key.startswith("{x:Type "):
                self.type_keys.add(key)

    def _merged(self, md: etree._Element) -> Dictionary | None:
        source = md.get("Source")
        if source is None:
            inline = Dictionary(md)
            self._fill(inline, md)
            return inline
        doc = self.ctx.doc_of(md)
        rel = reduce_uri(source)
        if rel is None:
            msg = f"merged dictionary {as_written(source)}: network URIs are refused"
            self.ctx.diag("RES004", msg, md, attr="Source")
            return None
        base = doc.directory if doc and doc.directory else Path.cwd()
        path = (base / rel).resolve()
        assembly = uri_assembly(source)
        if assembly is not None and not path.is_file():
            # compiled into another library (a theme, a control toolkit): WPF loads it from
            # there, xaml3d cannot read it
            msg = (f"merged dictionary from assembly {assembly} is not available: the resources "
                   f"it defines are unknown ({as_written(source)})")  # fmt: skip
            self.ctx.diag("RES012", msg, md, attr="Source")
            return Dictionary(md, assembly)
        if not self.ctx.path_allowed(path):
            self.ctx.diag(
                "RES004",
                f"merged dictionary {as_written(source)} leaves the scene's folder tree: refused "
                "(allow_outside=True permits it)",
                md,
                attr="Source",
            )
            return None
        return self.load_dictionary_file(path, source, md)

    def load_dictionary_file(
        self, path: Path, label: str, ref: etree._Element | None
    ) -> Dictionary | None:
        if path in self._loading:
            msg = f"merged dictionary {as_written(label)} includes itself (cycle)"
            self.ctx.diag("RES003", msg, ref, attr="Source")
            return None
        if path in self._files:
            return self._files[path]
        if not path.is_file():
            msg = f"merged dictionary {as_written(label)} not found ({path})"
            self.ctx.diag("RES005", msg, ref, attr="Source")
            return None
        self._loading.add(path)
        try:
            doc = parse_document(path, limits=self.ctx.limits, file=str(path))
        except XamlError as exc:
            msg = f"merged dictionary {as_written(label)} unreadable: {exc.message}"
            self.ctx.diag("RES005", msg, ref, attr="Source")
            self._loading.discard(path)
            self._files[path] = None
            return None
        self.ctx.add_document(doc)
        self.ctx.files_used.append(doc.file)
        d = self.dictionary_of(doc.root)
        self._loading.discard(path)
        self._files[path] = d
        return d

    # ----------------------------------------------------------------- application resources
    def add_app_file(self, path: str | os.PathLike, *, discovered: Path | None = None) -> None:
        """Read application resources from a file (App.xaml or any resource file); ``discovered``
        is the scene whose folder (or a parent of it) the file was found in, None when given."""
        label = os.fspath(path)
        try:
            doc = parse_document(path, limits=self.ctx.limits, file=label)
        except XamlError as exc:
            if discovered:
                msg = f"{label}: cannot be used: {exc.message}"
                self.ctx.diag("RES005", msg, line=exc.line, column=exc.column, file=label)
                return
            raise ResourceError(
                f"resource file {as_written(label)} cannot be read: {exc.message}",
                code="RES009",
                file=label,
                line=exc.line,
                column=exc.column,
            ) from None
        self.ctx.add_document(doc, trusted=True)
        self.ctx.files_used.append(label)
        d = self.dictionary_of(doc.root) or Dictionary(doc.root)
        self.app.append((doc, d))
        how = "given with -r" if discovered is None else _found_where(Path(path), discovered)
        self.ctx.diag(
            "RES006",
            f"application resources read from {label} ({how}: {len(d.entries)} entries)",
            doc.root,
            file=label,
        )

    def discover_app(self, scene_path: Path) -> Path | None:
        """The nearest App.xaml in the scene's folder or its parents (bounded), if any."""
        folder = scene_path.parent
        for _ in range(APP_DISCOVERY_LEVELS):
            try:
                names = os.listdir(folder)
            except OSError:
                names = []
            for n in sorted(names):
                if n.lower() in APP_FILE_NAMES:
                    cand = (folder / n).resolve()
                    if cand != scene_path.resolve() and cand.is_file():
                        return cand
            if folder.parent == folder:
                break
            folder = folder.parent
        return None

    # ----------------------------------------------------------------- lookup
    def find(self, key: str, from_el: etree._Element) -> etree._Element | None:
        """The entry for ``key`` in scope at ``from_el`` (enclosing elements, then the
        application), silently: for lookups WPF makes itself (implicit styles), where a miss
        is not an error."""
        node = from_el = self.ctx.original(from_el)  # a template's copy: the template's scope
        while node is not None:
            d = self.dictionary_of(node)
            hit = d.find(key) if d is not None else None
            if hit is not None:
                return hit[0]
            node = node.getparent()
        for _, d in reversed(self.app):
            hit = d.find(key)
            if hit is not None:
                return hit[0]
        return None

    def find_implicit(self, key: str, el: etree._Element) -> etree._Element | None:
        """The implicit Style ``key`` (a type's) that applies to ``el``: ``find``, except for the
        TextBlock a template's ContentPresenter makes for string content, whose look-up WPF
        stops at its templated parent (FrameworkElement.FindImplicitStyleResource: an element
        that is not a Control, inside a template): only the application's Styles reach it."""
        source = self.ctx.original(el)
        parent = el.getparent()
        made = source is not el and etree.QName(source).localname != etree.QName(el).localname
        if made and parent is not None and etree.QName(parent).localname == "ContentPresenter":
            for _, d in reversed(self.app):
                hit = d.find(key)
                if hit is not None:
                    return hit[0]
            return None
        return self.find(key, el)

    def _order(self, el: etree._Element) -> int:
        """The element's place in its document's order: one walk of each document, kept (a
        lookup is then O(1), not a walk up the tree counting siblings: thousands of
        references to one resource stay linear)."""
        root = el.getroottree().getroot()
        table = self._orders.get(id(root))
        hit = table[2].get(id(el)) if table is not None and table[0] is root else None
        if hit is None:  # a document not walked yet (or an element added since)
            elements = list(root.iter())  # held: the ids below stay those of these elements
            table = (root, elements, {id(e): i for i, e in enumerate(elements)})
            self._orders[id(root)] = table
            hit = table[2][id(el)]
        return hit

    def lookup(
        self, key: str, from_el: etree._Element, *, dynamic: bool = False, attr: str | None = None
    ) -> etree._Element | None:
        """The entry for ``key`` seen from ``from_el``; reports RES001/RES002 when missing (at
        ``from_el``'s attribute ``attr`` when the reference is an attribute)."""
        # a copy the framework step made of a template's element resolves in the template's
        # scope (its Resources, its Style's, the dictionary holding it), as WPF loads it
        from_el = self.ctx.original(from_el)
        seen = self._looked.get(id(from_el))
        if seen is None or seen[0] is not from_el:
            seen = self._looked[id(from_el)] = (from_el, set())
        seen[1].add(attr)
        system = key.lstrip().startswith("{")  # {x:Static SystemColors...Key}, {x:Type T}...
        if system and is_type_key(key):
            key = type_key(key)  # an implicit Style's key, as the dictionaries store it
        here = self._order(from_el)
        later = None
        unavailable: list[str] = []  # assemblies of merged dictionaries in scope not read
        node = from_el
        while node is not None:
            d = self.dictionary_of(node)
            if d is not None:
                unavailable.extend(d.unavailable())
                hit = d.find(key)
                if hit is not None:
                    entry, local = hit
                    if dynamic or not local or self._order(entry) < here:
                        return entry
                    later = later or entry
            node = node.getparent()
        own_root = from_el.getroottree().getroot()
        for doc, d in reversed(self.app):
            if doc.root is own_root:
                continue  # already searched (with the order rule) on the way up
            unavailable.extend(d.unavailable())
            hit = d.find(key)
            if hit is not None:
                return hit[0]
        if system and later is None:
            # a key that is an object (x:Static, ComponentResourceKey, a type) names a system or
            # theme resource WPF finds outside the markup: no load error, but not available here
            msg = (f"resource {key!r} is a system or theme resource: not available to xaml3d, "
                   "the property keeps its default")  # fmt: skip
            self.ctx.diag("RES011", msg, from_el, attr=attr)
        elif later is not None:
            self.ctx.diag(
                "RES002",
                f"StaticResource {key!r} is used before its definition "
                f"(line {self.ctx.locate(later)[0]}); "
                "WPF requires the entry to come first (DynamicResource would allow it)",
                from_el,
                attr=attr,
            )
        elif unavailable:
            names = ", ".join(dict.fromkeys(unavailable))
            kind = "DynamicResource" if dynamic else "StaticResource"
            msg = (f"{kind} {key!r} not found: it may be defined in the merged dictionary from "
                   f"assembly {names}, which xaml3d cannot read; "
                   "the property keeps its default")  # fmt: skip
            self.ctx.diag("RES013", msg, from_el, attr=attr)
        elif dynamic:  # WPF keeps the default and waits for the key to appear: no load error
            msg = f"DynamicResource {key!r} not found: the property keeps its default"
            self.ctx.diag("RES010", msg, from_el, attr=attr)
        else:
            import difflib  # only for a key not found: a scene without one never needs it

            near = difflib.get_close_matches(key, sorted(self._keys_in_scope(from_el)), 1, 0.8)
            hint = f" (did you mean {near[0]}?)" if near else ""
            # a near key in scope is the likelier cause than an application resource
            siblings, folder = ([], None) if hint else self._siblings(key, from_el)
            if siblings:  # the hint is chosen among all the missing keys: finish_hints
                self.ctx.diag("RES001", f"StaticResource {key!r} not found", from_el, attr=attr)
                self._sibling_hints.append((self.ctx.diagnostics[-1], siblings, folder))
                return None
            msg = f"StaticResource {key!r} not found{hint or self._app_hint()}"
            self.ctx.diag("RES001", msg, from_el, attr=attr)
        return None

    def _keys_in_scope(self, from_el: etree._Element) -> set[str]:
        """The keys of the dictionaries seen from ``from_el`` (enclosing elements, then the
        application), implicit Styles' type keys left out: the did-you-mean candidates."""
        keys: set[str] = set()
        node = from_el
        while node is not None:
            d = self.dictionary_of(node)
            if d is not None:
                keys.update(d.keys())
            node = node.getparent()
        for _, d in self.app:
            keys.update(d.keys())
        return {k for k in keys if not k.startswith("{")}

    def _siblings(self, key: str, from_el: etree._Element) -> tuple[list[str], Path | None]:
        """The resource dictionaries beside the scene (or the document holding ``from_el``)
        that define ``key``, and that folder."""
        doc = self.ctx.doc_of(from_el)
        folder = doc.path.parent if doc is not None and doc.path is not None else None
        folder = folder or self.scene_folder
        return (siblings_defining(folder, key) if folder is not None else []), folder

    def _app_hint(self) -> str:
        """For a key no dictionary defines, none beside the scene either: the application's
        resources may (an App.xaml is read only when found beside the scene or above it, or
        given with -r)."""
        if self.app:
            return ""
        return " (if the application's App.xaml defines it, give it with -r App.xaml)"

    def finish_hints(self) -> None:
        """Complete the RES001 reports of keys that dictionaries beside the scene define: the
        dictionary resolving the most of them is suggested once, at the first key it defines,
        with how many it resolves; its other keys point there (``best_siblings``)."""
        pending, self._sibling_hints = self._sibling_hints, []
        at = {id(d): i for i, d in enumerate(self.ctx.diagnostics)}
        pending = [p for p in pending if id(p[0]) in at]  # (a muted read's are gone)
        pending.sort(key=lambda p: (p[0].file or "", p[0].line or 0, p[0].column or 0))
        first: dict[str, Diagnostic] = {}
        for i, (name, count) in sorted(
            best_siblings([(d, names) for d, names, _ in pending]).items()
        ):
            d = pending[i][0]
            total = len(pending)
            if name not in first:
                first[name] = d
                if count == 1:
                    what = "defines it"
                elif count == total:
                    what = f"defines all {total} missing keys, this one included"
                else:
                    what = f"defines it and {count - 1} more of the {total} missing keys"
                typed = typable_path(pending[i][2] / name)
                hint = f"{name} beside the scene {what}: give it with -r {typed}"
            else:
                hint = f"defined in the -r file suggested at line {first[name].line}"
            self.ctx.diagnostics[at[id(d)]] = replace(d, message=f"{d.message} ({hint})")

    # ----------------------------------------------------------------- every reference
    def report_unresolved(self, root: etree._Element) -> None:
        """Look up every ``{StaticResource}`` of the document under ``root`` (attributes, the
        extensions nested in others, ``<StaticResource ResourceKey=.../>`` elements), wherever
        it is: 2D elements, styles, triggers, templates in use... WPF's loader resolves each one
        and fails on a key it cannot find, even where xaml3d reads nothing. A missing key is
        reported (RES001, RES002) once, at its attribute: references the reader already looked
        up are not looked up again. The content of resource dictionaries is skipped: an entry
        is built (and its references resolved) where it is used, as WPF defers it."""

        def looked_up(el, attr) -> bool:
            seen = self._looked.get(id(el))
            return seen is not None and seen[0] is el and attr in seen[1]

        stack = [root]
        while stack:
            el = stack.pop()
            ns, local = qname(el.tag)
            if local.endswith(".Resources") or local == "ResourceDictionary":
                continue  # resource entries: resolved when used
            if ns is not None and not is_presentation(ns) and ns in ignorable_namespaces(el):
                continue  # an element of an mc:Ignorable namespace: WPF skips it
            stack.extend(k for k in reversed(el) if isinstance(k.tag, str))
            if local in ("StaticResource", "StaticResourceExtension"):
                key = el.get("ResourceKey")
                if key is not None and not looked_up(el, "ResourceKey"):
                    self.lookup(key, el, attr="ResourceKey")
                continue
            ignorable = None
            for attr, value in el.attrib.items():
                if not _MARKUP_START.match(value) or "StaticResource" not in value:
                    continue
                if ignorable is None:
                    ignorable = ignorable_namespaces(el)
                if qname(attr)[0] in ignorable:
                    continue  # d:Style="{StaticResource ...}" (mc:Ignorable): WPF skips it
                for key in static_resource_keys(value):
                    if not looked_up(el, attr):
                        self.lookup(key, el, attr=attr)


_MARKUP_START = re.compile(r"\s*\{(?!\})")  # a markup extension ("{}" escapes a brace)
# a StaticResource extension (prefixed or not) with no other extension inside it
_STATIC = re.compile(r"\{\s*(?:[\w.]+:)?StaticResource(?:Extension)?(?=[\s}])([^{}]*)\}")


def static_resource_keys(value: str) -> list[str]:
    """The keys of the ``{StaticResource key}`` extensions in an attribute's value, also those
    nested in another extension (``{Binding Source={StaticResource key}}``)."""
    return [markup_key(m.group(1)) for m in _STATIC.finditer(value)]


def type_name(target: str) -> str:
    """The type a TargetType or type key names: ``Border``, ``{x:Type Border}``,
    ``{x:Type TypeName=local:Border}`` all give ``Border`` (the namespace prefix dropped)."""
    t = target.strip()
    if t.startswith("{") and t.endswith("}"):
        body = t[1:-1].split(None, 1)
        t = body[1] if len(body) == 2 else ""
        if t.startswith("TypeName="):
            t = t[len("TypeName=") :]
    return t.strip().split(":")[-1]


def type_key(target: str) -> str:
    """The key of an implicit Style: ``TargetType="Border"``, ``"{x:Type Border}"`` and
    ``x:Key="{x:Type Border}"`` all give ``{x:Type Border}``."""
    return "{x:Type " + type_name(target) + "}"


def data_template_key(data_type: str) -> str:
    """The key of an implicit DataTemplate (``DataType="{x:Type local:Person}"`` or
    ``"local:Person"``): ``{DataTemplateKey Person}``, apart from the type's implicit Style."""
    return "{DataTemplateKey " + type_name(data_type) + "}"


def is_type_key(key: str) -> bool:
    """Whether a resource key is written as a type (``{x:Type Border}``)."""
    return key.replace(" ", "").startswith(("{x:Type", "{Type"))


def typable_path(path: Path) -> str:
    """``path`` as a user types it in a shell from the current directory: relative to it when
    that is not longer than the absolute path, else absolute (quoted when the shell needs it).
    A hint's file name alone would not be found from another folder (RES009)."""
    absolute = os.path.abspath(path)
    try:
        relative = os.path.relpath(absolute)
    except ValueError:  # another drive (Windows): no relative path
        relative = absolute
    import shlex  # only for this message

    return shlex.quote(relative if len(relative) <= len(absolute) else absolute)


def _found_where(app: Path, scene: Path) -> str:
    """Where an App.xaml was found, said from the scene: its own folder or N folders up."""
    try:
        up = len(scene.resolve().parent.relative_to(app.resolve().parent).parts)
    except ValueError:
        up = -1
    if up == 0:
        return "found in the scene's folder"
    if up > 0:
        return f"found {up} folder{'s' if up > 1 else ''} above the scene's"
    return "found by searching up from the scene's folder"
