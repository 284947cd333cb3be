"""One binding's value as WPF computes it at load: its source (ElementName, RelativeSource
Self / FindAncestor, Source={StaticResource}, x:Reference, or the DataContext set in markup
and inherited), its path through properties, attached properties and indexers, the source's
effective value (local value, Style setter, inherited value, WPF's default), then
BooleanToVisibilityConverter, TargetNullValue and StringFormat. What cannot be known without
code (a DataContext set by code-behind, an application's converter class, x:Static, a property
of a code type that the markup does not set) raises ``Unresolved``."""

from __future__ import annotations

from dataclasses import dataclass, field

from xaml3d.framework import binding_format as F
from xaml3d.framework.binding_path import PathError, parse_path
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
    INHERITED,
    LAYOUT_RESULTS,
    NULL,
    Unresolved,
    Value,
    as_bool,
    as_number,
    clr_of,
    default,
    display_text,
    fails,
    needs_code,
    primitive,
)
from xaml3d.framework.markup_syntax import (
    Extension,
    MarkupSyntaxError,
    is_extension,
    literal,
    parse,
)

BINDINGS = ("Binding", "MultiBinding", "PriorityBinding")
_STYLE_DEPTH = 16


class Cycle(Exception):
    """A binding whose source is, through other bindings, its own target."""

    def __init__(self, site: Site) -> None:
        super().__init__("binding cycle")
        self.site = site
        self.chain: list[Site] = [site]


@dataclass(eq=False)
class Site:
    """A binding set on a property: ``el``'s attribute ``key`` (property ``prop``), or a
    property element ``prop_el`` holding the Binding element ``binding_el``."""

    el: object
    prop: str
    key: str | None = None
    ext: Extension | None = None
    prop_el: object = None
    binding_el: object = None
    state: str = "new"  # new | busy | done
    value: Value | None = None
    error: Exception | None = None
    notes: list = field(default_factory=list)


class Evaluator:
    """Binding values over one document (``sites``: (id(element), property) -> Site)."""

    def __init__(self, services, names: dict, sites: dict) -> None:
        self.s = services
        self.names = names
        self.sites = sites

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
        if ext.name == "MultiBinding":
            return self._multi(el, prop, ext)
        if ext.name == "PriorityBinding":
            return self._priority(el, prop, ext)
        mode = ext.arg("Mode", None)
        if isinstance(mode, str) and mode.strip() == "OneWayToSource":
            raise fails("OneWayToSource", "Mode=OneWayToSource never sets the target")
        if ext.arg("XPath", None) is not None:
            raise needs_code("XPath", "an XPath binding reads XML data xaml3d does not load")
        v = self._source(el, prop, ext)
        path = ext.arg("Path")
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

    def _extension_value(self, el, ext: Extension, key_attr: str | None) -> Value:
        n = ext.name
        if n in ("StaticResource", "DynamicResource", "StaticResourceExtension"):
            key = ext.arg("ResourceKey")
            if not isinstance(key, str):
                raise fails("resource", "a resource key that is not a string")
            entry = self.s.lookup(key.strip(), el, key_attr)
            if entry is None:
                raise Unresolved(None, "resource", f"resource {key!r} not found")  # RES001 said
            return self.element_value(entry, key=key.strip(), at=el)
        if n in ("Null", "NullExtension"):
            return NULL
        if n in ("Reference", "ReferenceExtension"):
            name = ext.arg("Name")
            target = self.names.get(name.strip()) if isinstance(name, str) else None
            if target is None:
                raise fails("x:Reference", f"no element named {name!r}")
            return Value(el=target, visual=True)
        if n in ("Type", "TypeExtension"):
            return Value(type_argument(ext) or "", "Type")
        if n in BINDINGS:
            return self.binding_value(el, "", ext)
        if n in ("Static", "StaticExtension"):
            raise needs_code("x:Static", "{x:Static} reads a CLR member xaml3d does not run")
        raise needs_code(f"{{{n}}}", f"{{{n}}} is not evaluated")

    def element_value(self, el, key: str | None = None, at=None) -> Value:
        """An object element as a value: a primitive's text, else the element."""
        p = primitive(el)
        if p is not None:
            return p
        ns, name = qname(el)
        if is_wpf(el) and name in ("StaticResource", "DynamicResource"):
            k = el.get("ResourceKey")
            if k is None:
                raise fails("resource", f"<{name}> without ResourceKey")
            return self._extension_value(el, Extension(name, positional=[k]), "ResourceKey")
        if name == "Null" and ns == "http://schemas.microsoft.com/winfx/2006/xaml":
            return NULL
        return Value(el=el, key=key, at=at)

    # ----------------------------------------------------------------- a property's value
    def prop_value(self, el, prop: str) -> Value:
        """``el``'s effective value of ``prop`` (attached: ``Grid.Row``): its own binding,
        attribute or property element, its content, its Style's setter, the inherited value,
        WPF's default."""
        site = self.sites.get((id(el), prop))
        if site is not None:
            return self.site_value(site)
        raw = el.get(prop)
        if raw is None and "." in prop and local(el) == prop.partition(".")[0]:
            raw = el.get(prop.partition(".")[2])  # Grid.Row on a Grid written as Row
        if raw is not None:
            return self.text_value(el, prop, raw)
        pe = self._prop_element(el, prop)
        if pe is not None:
            return self._prop_element_value(el, prop, pe)
        v = self._content(el, prop)
        if v is not None:
            return v
        v = self._style_value(el, prop)
        if v is not None:
            return v
        if prop in INHERITED:
            parent = object_parent(el)
            if parent is not None:
                return self.prop_value(parent, prop)
        if prop in LAYOUT_RESULTS:
            raise needs_code(
                "layout result", f"{prop} is a result of layout: a binding to it is updated "
                "after layout, which a load does not run")  # fmt: skip
        if not is_wpf(el):
            raise needs_code(
                "code type", f"{local(el)}.{prop} is not set in the markup: its value is the "
                f"code's ({local(el)} is a type of the application)")  # fmt: skip
        d = default(local(el), prop) or self._base_default(el, prop)
        if d is None:
            raise fails("path", f"{local(el)}.{prop}: not set in the markup and its default is "
                                "not known to xaml3d")  # fmt: skip
        return d

    def _base_default(self, el, prop: str) -> Value | None:
        for base in ("ContentControl", "Control", "RangeBase", "Panel"):
            if type_matches(el, base):
                hit = default(base, prop)
                if hit is not None:
                    return hit
        return None

    def text_value(self, el, prop: str, raw: str) -> Value:
        if not is_extension(raw):
            return Value(literal(raw), clr_of(prop))
        try:
            ext = parse(raw)
        except MarkupSyntaxError as exc:
            raise fails("syntax", str(exc)) from None
        return self._extension_value(el, ext, prop)

    def _prop_element(self, el, prop: str):
        want = prop if "." in prop else None
        for k in children(el):
            name = local(k)
            if not is_property_element(k):
                continue
            owner, _, short = name.rpartition(".")
            if (want is not None and name == want) or (want is None and short == prop and (
                    owner == local(el) or is_wpf(k) and owner in _OWNER_BASES)):  # fmt: skip
                return k
        return None

    def _prop_element_value(self, el, prop: str, pe) -> Value:
        kids = children(pe)
        if not kids:
            return Value((pe.text or "").strip(), clr_of(prop))
        if len(kids) == 1 and not local(kids[0]).endswith("Collection"):
            return self.element_value(kids[0])
        if len(kids) == 1:
            kids = children(kids[0])
        return Value(items=tuple(kids), el=pe)

    def _content(self, el, prop: str) -> Value | None:
        """The content property's value written as the element's content."""
        if not is_wpf(el) or prop != _content_property(el):
            return None
        kids = [k for k in children(el) if not is_property_element(k)]
        if prop in ("Children", "Items", "Inlines"):
            return Value(items=tuple(kids), el=el)
        if kids:
            return (
                self.element_value(kids[0])
                if prop != "Content"
                else Value(el=kids[0], visual=is_wpf(kids[0]) and primitive(kids[0]) is None)
            )
        text = (el.text or "").strip()
        return Value(text, "String") if text else None

    def _style_value(self, el, prop: str) -> Value | None:
        """The value a Setter of ``el``'s Style gives ``prop`` (explicit Style resource, else
        the implicit Style of its type; BasedOn followed)."""
        if not is_wpf(el):
            return None
        ref = el.get("Style")
        style = None
        if ref is not None:
            if not is_extension(ref):
                return None
            try:
                ext = parse(ref)
            except MarkupSyntaxError:
                return None
            key = ext.arg("ResourceKey")
            if ext.name not in ("StaticResource", "DynamicResource") or not isinstance(key, str):
                return None
            style = self.s.find(key.strip(), el)
        else:
            style = self.s.find("{x:Type " + local(el) + "}", el)
        depth = 0
        while style is not None and local(style) == "Style" and depth < _STYLE_DEPTH:
            for setter in _setters(style):
                if setter.get("TargetName") or (setter.get("Property") or "").split(":")[-1] \
                        not in (prop, f"{local(el)}.{prop}"):  # fmt: skip
                    continue
                raw = setter.get("Value")
                if raw is not None:
                    return self.text_value(setter, prop, raw)
                for pe in children(setter):
                    if local(pe) == "Setter.Value":
                        return self._prop_element_value(setter, prop, pe)
            based = style.get("BasedOn")
            style = None
            if based and is_extension(based):
                try:
                    b = parse(based)
                except MarkupSyntaxError:
                    break
                key = b.arg("ResourceKey") if b.name != "Type" else None
                if isinstance(key, str):
                    style = self.s.find(key.strip(), el)
                elif b.name == "Type":
                    style = self.s.find("{x:Type " + (type_argument(b) or "") + "}", el)
            depth += 1
        return None

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
            prop = _content_property(v.el)
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


# the classes whose property elements name a property by its owner (<FrameworkElement.Width>)
_OWNER_BASES = frozenset({"FrameworkElement", "UIElement", "Control", "Panel",
                          "ContentControl", "ItemsControl", "TextElement", "Shape"})  # fmt: skip


def _content_property(el) -> str | None:
    name = local(el)
    if name in ("TextBlock", "Run", "TextBox", "AccessText"):
        return "Text"
    if type_matches(el, "ContentControl"):
        return "Content"
    if type_matches(el, "Panel"):
        return "Children"
    if type_matches(el, "ItemsControl"):
        return "Items"
    if type_matches(el, "Decorator"):
        return "Child"
    return None


def _setters(style):
    for child in children(style):
        name = local(child)
        if name == "Setter":
            yield child
        elif name == "Style.Setters":
            yield from (k for k in children(child) if local(k) == "Setter")


def binding_element_extension(b) -> Extension:
    """A ``<Binding .../>`` (``<MultiBinding>``, ``<PriorityBinding>``) element as the
    Extension its attribute form would be: attributes parsed as attributes are, property
    elements (``<Binding.Source>``...) as their single object, child bindings as
    ``Bindings``."""
    ext = Extension(local(b))
    for key, raw in b.attrib.items():
        if key.startswith("{"):
            continue
        ext.named[key] = parse(raw) if is_extension(raw) else literal(raw)
    nested = []
    for k in children(b):
        name = local(k)
        if is_property_element(k):
            prop = name.rpartition(".")[2]
            kids = children(k)
            if len(kids) == 1:
                ext.named[prop] = _object_argument(kids[0])
            elif not kids:
                ext.named[prop] = (k.text or "").strip()
        elif name in BINDINGS:
            nested.append(binding_element_extension(k))
    if nested:
        ext.named["Bindings"] = nested
    return ext


def _object_argument(el):
    """An object written as an argument's property element: an extension element as its
    Extension (``<RelativeSource Mode="Self"/>``, ``<StaticResource ResourceKey="k"/>``),
    anything else as the element itself."""
    name = local(el)
    if is_wpf(el) and name == "RelativeSource":
        ext = Extension("RelativeSource")
        for key, raw in el.attrib.items():
            ext.named[key] = parse(raw) if is_extension(raw) else literal(raw)
        return ext
    if name in BINDINGS:
        return binding_element_extension(el)
    return el
