"""One binding's value as WPF computes it at load: its source (ElementName, RelativeSource
Self / FindAncestor, Source={StaticResource}, x:Reference, or the DataContext set in markup
and inherited), its path through properties, attached properties and indexers (each step the
source's effective value: binding_props.py) or its XPath over an XmlDataProvider's data
(xml_data.py), then BooleanToVisibilityConverter,
TargetNullValue and StringFormat; MultiBinding with a StringFormat, PriorityBinding, and the
element form's arguments. What cannot be known without
code (a DataContext set by code-behind, an application's converter class, x:Static, a property
of a code type that the markup does not set) raises ``Unresolved``."""

from __future__ import annotations

from xaml3d.framework import binding_format as F
from xaml3d.framework.binding_path import PathError, parse_path
from xaml3d.framework.binding_props import PropertyValues, content_property
from xaml3d.framework.binding_sites import Site
from xaml3d.framework.binding_tree import (
    children,
    is_property_element,
    is_wpf,
    local,
    object_ancestors,
    object_parent,
    qname,
    type_argument,
    type_matches,
)
from xaml3d.framework.binding_values import (
    Unresolved,
    Value,
    as_bool,
    as_number,
    clr_of,
    display_text,
    fails,
    needs_code,
    primitive,
)
from xaml3d.framework.markup_syntax import (
    Extension,
)

# the longest chain of bindings followed (each one's source a binding): deeper is refused rather
# than recursed into
MAX_CHAIN = 64


# the properties an XPath gives nodes (a collection), not the first node's text
_NODE_TARGETS = ("ItemsSource", "DataContext")


def _xml_source(v: Value) -> bool:
    """Whether ``v`` is an XmlDataProvider (or nodes of its data a DataContext holds)."""
    return v.el is not None and is_wpf(v.el) and local(v.el) == "XmlDataProvider"


def _own_xpath(v: Value) -> bool:
    """Whether ``v`` is an XmlDataProvider itself (not nodes of it) with an XPath of its own."""
    return v.items is None and _xml_source(v) and bool((v.el.get("XPath") or "").strip())


class Cycle(Exception):
    """A binding whose source is, through other bindings, its own target."""

    def __init__(self, site: Site) -> None:
        super().__init__("binding cycle")
        self.site = site
        self.chain: list[Site] = [site]


class Evaluator(PropertyValues):
    """Binding values over one document (``sites``: (id(element), property) -> Site)."""

    def __init__(self, services, names: dict, sites: dict) -> None:
        self.s = services
        self.names = names
        self.sites = sites
        self.depth = 0  # bindings being evaluated, each for the one before

    # ----------------------------------------------------------------- a site's value
    def site_value(self, site: Site) -> Value:
        """The site's value (evaluated once); raises Unresolved or Cycle."""
        if site.state == "busy":
            raise Cycle(site)
        if site.state == "new":
            site.state = "busy"
            try:
                site.value = self.binding_value(site.el, site.prop, site.ext)
            except Cycle as c:
                if c.site is not site:
                    c.chain.append(site)
                site.error = c
            except Unresolved as u:
                site.error = u
            finally:
                site.state = "done"
        if site.error is not None:
            raise site.error
        return site.value

    def binding_value(self, el, prop: str, ext: Extension) -> Value:
        """The value of binding ``ext`` set on ``el``'s property ``prop`` ("" when it is not a
        property's: an argument, a trigger's condition)."""
        self.depth += 1
        try:
            if self.depth > MAX_CHAIN:
                raise needs_code("chain", f"a chain of more than {MAX_CHAIN} bindings, each the "
                                          "source of the next: not followed")  # fmt: skip
            return self._binding_value(el, prop, ext)
        finally:
            self.depth -= 1

    def _binding_value(self, el, prop: str, ext: Extension) -> Value:
        if ext.name == "MultiBinding":
            return self._multi(el, prop, ext)
        if ext.name == "PriorityBinding":
            return self._priority(el, prop, ext)
        mode = ext.arg("Mode", None)
        if isinstance(mode, str) and mode.strip() == "OneWayToSource":
            raise fails("OneWayToSource", "Mode=OneWayToSource never sets the target")
        v = self._source(el, prop, ext)
        xpath = ext.arg("XPath", None)
        path = ext.arg("Path")
        if xpath is None and path is None and prop in _NODE_TARGETS and _own_xpath(v):
            xpath = ""  # the provider's own XPath gives the nodes
        if xpath is not None:
            v = self._xpath(v, xpath, prop)
            if v.items is not None or path is not None:
                if path is not None:
                    raise needs_code("XPath and Path", "a Path after an XPath reads the XML "
                                                       "node's members: not evaluated")  # fmt: skip
                return v
            path = None
        if path is not None and not isinstance(path, str):
            raise needs_code("Path object", "a Path given as an object")
        try:
            steps = parse_path(path or "")
        except PathError as exc:
            raise fails("path", str(exc)) from None
        for step in steps:
            v = self._step(v, step)
        v = self._convert(el, v, ext, prop)
        if v.null:
            tnv = ext.arg("TargetNullValue", None)
            if tnv is not None:
                return self._argument_value(el, tnv, prop)
        fmt = ext.arg("StringFormat", None)
        if isinstance(fmt, str) and fmt and clr_of(prop) == "String" and not v.null:
            return Value(self._format(fmt, [v]), "String")
        return v

    # ----------------------------------------------------------------- sources
    def _source(self, el, prop: str, ext: Extension) -> Value:
        name = ext.arg("ElementName", None)
        rel = ext.arg("RelativeSource", None)
        src = ext.arg("Source", None)
        given = [k for k, v in (("ElementName", name), ("RelativeSource", rel), ("Source", src))
                 if v is not None]  # fmt: skip
        if len(given) > 1:
            raise fails("sources", f"a binding takes one source, not {' and '.join(given)}")
        if name is not None:
            target = self.names.get(name.strip()) if isinstance(name, str) else None
            if target is None:
                raise fails("ElementName", f"no element named {name!r} in this name scope")
            return Value(el=target, visual=True)
        if rel is not None:
            return self._relative(el, rel)
        if src is not None:
            return self._argument_value(el, src, prop)
        return self._data_context(el, prop)

    def _relative(self, el, rel) -> Value:
        if isinstance(rel, Extension) and rel.name in ("RelativeSource", "RelativeSourceExtension"):
            mode = rel.arg("Mode")
            mode = mode.strip() if isinstance(mode, str) else None
            ancestor = type_argument(rel.arg("AncestorType", None))
            if mode is None and ancestor is not None:
                mode = "FindAncestor"
            if mode == "Self":
                return Value(el=el, visual=True)
            if mode == "FindAncestor":
                return self._ancestor(el, ancestor, rel.arg("AncestorLevel", None))
            if mode == "TemplatedParent":
                raise fails("TemplatedParent", "RelativeSource TemplatedParent outside a "
                                               "template has no templated parent")  # fmt: skip
            raise needs_code(f"RelativeSource {mode}", f"RelativeSource {mode} is not evaluated")
        raise fails("RelativeSource", "RelativeSource is not a {RelativeSource ...}")

    def _ancestor(self, el, type_name: str | None, level) -> Value:
        if not type_name:
            raise fails("FindAncestor", "FindAncestor without an AncestorType")
        try:
            n = int(level.strip()) if isinstance(level, str) else 1
        except ValueError:
            raise fails("FindAncestor", f"AncestorLevel {level!r} is not a number") from None
        if n < 1:
            raise fails("FindAncestor", f"AncestorLevel {n} is below 1")
        for up in object_ancestors(el):
            if type_matches(up, type_name):
                n -= 1
                if n == 0:
                    return Value(el=up, visual=True)
        raise fails("FindAncestor", f"no ancestor of type {type_name} above this element")

    def _data_context(self, el, prop: str) -> Value:
        # a binding on DataContext itself reads the parent's DataContext
        node = object_parent(el) if prop == "DataContext" else el
        while node is not None:
            if self._sets(node, "DataContext"):
                v = self.prop_value(node, "DataContext")
                if (
                    v.el is not None
                    and not v.visual
                    and not is_wpf(v.el)
                    and primitive(v.el) is None
                ):
                    return Value(el=v.el)  # an object of a code type: its properties as set
                return v
            node = object_parent(node)
        raise needs_code("DataContext", "no DataContext is set in the markup (code sets it)")

    def _sets(self, el, prop: str) -> bool:
        return (el.get(prop) is not None or self._prop_element(el, prop) is not None
                or (id(el), prop) in self.sites)  # fmt: skip

    def _argument_value(self, el, arg, attr: str | None) -> Value:
        """A binding argument's value (Source, TargetNullValue): a string, an extension (its
        resources looked up as ``el``'s attribute ``attr``), or an element (element form)."""
        if isinstance(arg, str):
            return Value(arg, "String")
        if isinstance(arg, Extension):
            return self._extension_value(el, arg, attr or None)
        return self.element_value(arg)

    # ----------------------------------------------------------------- XML data
    def _xpath(self, v: Value, xpath, prop: str) -> Value:
        """An XPath binding's value: over an XmlDataProvider's inline data or an XML node (an
        item of it): the nodes for an ItemsSource, else the first node's text."""
        from xaml3d.framework import xml_data as X  # for a document that binds XML only

        if not isinstance(xpath, str):
            raise needs_code("XPath object", "an XPath given as an object")
        if v.items is not None and _xml_source(v):
            # nodes a DataContext holds: WPF reads the collection's current item, its first
            nodes = list(v.items[:1])
        elif v.el is not None and is_wpf(v.el) and local(v.el) == "XmlDataProvider":
            try:
                nodes = X.provider_nodes(v.el, self.s)
            except X.XPathError as exc:  # the provider's own XPath
                own = v.el.get("XPath")
                detail = f"the XmlDataProvider's XPath {own!r} is not evaluated ({exc})"
                raise needs_code(f"XPath {own}", detail) from None
            if nodes is None and v.el.get("Source") is not None:
                raise Unresolved(None, "XmlDataProvider")  # said where the file was read
            if nodes is None:
                raise fails("XmlDataProvider", "an XmlDataProvider without data (no x:XData, "
                                               "no Source)")  # fmt: skip
        elif v.el is not None and not is_wpf(v.el) and X.is_data(v.el):
            nodes = [v.el]
        else:
            raise fails("XPath", f"XPath {xpath!r} on a source that is not XML data")
        try:
            picked = X.select(nodes, xpath)
        except X.XPathError as exc:
            detail = f"XPath {xpath!r} is not evaluated ({exc})"
            raise needs_code(f"XPath {xpath}", detail) from None
        if prop in _NODE_TARGETS:
            return Value(items=tuple(picked), el=v.el)
        if not picked:
            raise fails("XPath", f"XPath {xpath!r} selects nothing")
        return Value(X.text_of(picked[0]), "String")

    # ----------------------------------------------------------------- path steps
    def _step(self, v: Value, step) -> Value:
        if v.null:
            raise fails("path", f"the path reaches null before {step.name or step.kind!r}")
        if step.kind == "prop":
            if v.items is not None and step.name in ("Count", "Length"):
                return Value(str(len(v.items)), "Int32")
            if v.el is not None:
                if local(v.el) == "Array" and step.name in ("Length", "Count"):
                    return Value(str(len(children(v.el))), "Int32")
                return self.prop_value(v.el, step.name)
            if v.text is not None:
                if step.name == "Length" and v.clr == "String":
                    return Value(str(len(v.text)), "Int32")
                if v.clr == "Brush" and step.name == "Color":
                    return Value(v.text, "Color")  # a brush from text is a SolidColorBrush
                if v.clr == "Brush" and step.name == "Opacity":
                    return Value("1", "Double")
            raise fails("path", f"a {v.clr} has no property {step.name} xaml3d can read")
        items = self._items(v)
        if step.kind == "current":
            if not items:
                raise fails("path", "'/' on an empty or non-collection value")
            return self.element_value(items[0])
        try:
            i = int(step.name)
        except ValueError:
            raise fails("path", f"indexer [{step.name}] is not a number") from None
        if items is None and v.text is not None and v.clr == "String":
            if 0 <= i < len(v.text):
                return Value(v.text[i], "String")
            raise fails("path", f"index {i} is out of range")
        if items is None:
            raise fails("path", f"[{i}] on a value that is not a collection")
        if not 0 <= i < len(items):
            raise fails("path", f"index {i} is out of range (the collection has {len(items)})")
        return self.element_value(items[i])

    def _items(self, v: Value):
        if v.items is not None:
            return list(v.items)
        if v.el is not None and (local(v.el) == "Array" or local(v.el).endswith("Collection")):
            return children(v.el)
        if v.el is not None and is_wpf(v.el):
            prop = content_property(v.el)
            if prop in ("Children", "Items"):
                return [k for k in children(v.el) if not is_property_element(k)]
        return None

    # ----------------------------------------------------------------- converters, formats
    def _convert(self, el, v: Value, ext: Extension, attr: str) -> Value:
        conv = ext.arg("Converter", None)
        if conv is None:
            return v
        if isinstance(conv, Extension):
            c = self._extension_value(el, conv, attr or None)
            conv_el = c.el
        elif isinstance(conv, str):
            raise fails("Converter", f"Converter={conv!r} is not an object")
        else:
            conv_el = conv
        if conv_el is None:
            raise fails("Converter", "the Converter is not an object")
        if is_wpf(conv_el) and local(conv_el) == "BooleanToVisibilityConverter":
            b = as_bool(v) if v.el is None and not v.null else None
            return Value("Visible" if b else "Collapsed", "Visibility")
        raise needs_code("converter", f"the converter {qname(conv_el)[1]} is a class of the "
                                      "application: its code is not run")  # fmt: skip

    def _format(self, fmt: str, values: list[Value]) -> str:
        args = []
        for v in values:
            x = as_number(v) if v.clr in ("Double", "Int32") else None
            args.append((x, True) if x is not None else (display_text(v), False))
        try:
            return F.composite_args(fmt, args)
        except F.FormatError as exc:
            raise fails("StringFormat", str(exc)) from None

    # ----------------------------------------------------------------- multi and priority
    def _children_bindings(self, ext: Extension) -> list[Extension]:
        return list(ext.named.get("Bindings", ()))

    def _multi(self, el, prop: str, ext: Extension) -> Value:
        if ext.arg("Converter", None) is not None:
            raise needs_code("converter", "a MultiBinding's converter is a class of the "
                                          "application: its code is not run")  # fmt: skip
        fmt = ext.arg("StringFormat", None)
        if not isinstance(fmt, str) or not fmt:
            raise needs_code("MultiBinding", "a MultiBinding without StringFormat needs a "
                                             "converter from code")  # fmt: skip
        values = [self.binding_value(el, "", b) for b in self._children_bindings(ext)]
        if clr_of(prop) != "String":
            raise fails("MultiBinding", "a MultiBinding's StringFormat applies to text only")
        return Value(self._format(fmt, values), "String")

    def _priority(self, el, prop: str, ext: Extension) -> Value:
        first: Unresolved | None = None
        for b in self._children_bindings(ext):
            try:
                return self.binding_value(el, prop, b)
            except Unresolved as u:
                first = first or u
        raise first or fails("PriorityBinding", "a PriorityBinding without bindings")
