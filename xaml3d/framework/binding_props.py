"""A binding source's property values as WPF has them at load: an element's local value
(attribute, property element, content), its Style's Setter (explicit or implicit, BasedOn
followed), the value inherited from its ancestors, WPF's default; resource references and
primitives (``sys:Double``...) among them; a binding set on the property evaluated first
(``Evaluator.site_value``, binding_eval.py)."""

from __future__ import annotations

from xaml3d.framework.binding_sites import binding_element_extension
from xaml3d.framework.binding_tree import (
    BINDINGS,
    children,
    is_property_element,
    is_wpf,
    local,
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
    clr_of,
    default,
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

_STYLE_DEPTH = 16


class PropertyValues:
    """The property values bindings read (the base of ``binding_eval.Evaluator``, which gives
    ``s`` (the services), ``names`` (the name scope), ``sites`` (the bindings by element and
    property), ``site_value`` and ``binding_value``)."""

    s: object
    names: dict
    sites: dict

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

    def prop_value(self, el, prop: str) -> Value:
        """``el``'s effective value of ``prop`` (attached: ``Grid.Row``): its own binding,
        attribute or property element, its content, its Style's setter, the inherited value,
        WPF's default. IsEnabled is False under a disabled ancestor, as WPF coerces it."""
        v = self._own_value(el, prop)
        if prop == "IsEnabled" and as_bool(v) is not False and is_wpf(el):
            parent = object_parent(el)
            if parent is not None and is_wpf(parent) and as_bool(
                    self.prop_value(parent, prop)) is False:  # fmt: skip
                return Value("False", "Boolean")
        return v

    def _own_value(self, el, prop: str) -> Value:
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
        v = self._inline_text(el, prop)
        if v is None:
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
            self._check_member(el, prop)
            # xaml3d's limit, not WPF's failure: said once, as what needs code is
            raise needs_code("default", f"{local(el)}.{prop} is not set in the markup and xaml3d "
                                        "does not know its default")  # fmt: skip
        return d

    def _check_member(self, el, prop: str) -> None:
        """A path naming no property of a WPF type the reader's vocabulary knows fails, as
        WPF's binding does at run time (its default shown); the near name suggested."""
        members = getattr(self.s, "members", None)
        known = members(local(el)) if members is not None and "." not in prop else None
        if known is None or prop in known:
            return
        import difflib  # only for a name that is wrong

        near = difflib.get_close_matches(prop, sorted(known), 1, 0.7)
        hint = f"; did you mean {near[0]}?" if near else ""
        raise fails("path", f"{local(el)} has no property {prop!r}{hint}")

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
        if ext.name in BINDINGS and prop:
            return self.binding_value(el, prop, ext)  # for the property it sets (DataContext)
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
        if len(kids) == 1 and is_wpf(kids[0]) and local(kids[0]) in BINDINGS:
            try:  # <X.DataContext><Binding .../></X.DataContext>
                ext = binding_element_extension(kids[0])
            except MarkupSyntaxError as exc:
                raise fails("syntax", str(exc)) from None
            return self.binding_value(el, prop, ext)
        if len(kids) == 1 and not local(kids[0]).endswith("Collection"):
            return self.element_value(kids[0])
        if len(kids) == 1:
            kids = children(kids[0])
        return Value(items=tuple(kids), el=pe)

    def _content(self, el, prop: str) -> Value | None:
        """The content property's value written as the element's content."""
        if not is_wpf(el) or prop != content_property(el):
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

    def _inline_text(self, el, prop: str) -> Value | None:
        """A TextBlock's Text written as Runs (``<Run Text="a"/><Run>b</Run>``): their text
        joined, as TextBlock.Text reads its inlines; None for other content."""
        if prop != "Text" or local(el) != "TextBlock" or not is_wpf(el):
            return None
        kids = [k for k in children(el) if not is_property_element(k)]
        if not kids or any(local(k) != "Run" or children(k) for k in kids):
            return None
        parts = [el.text or ""]
        for k in kids:
            parts.append(k.get("Text") if k.get("Text") is not None else k.text or "")
            parts.append(k.tail or "")
        text = " ".join("".join(parts).split())
        return Value(text, "String")

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


# the classes whose property elements name a property by its owner (<FrameworkElement.Width>)
_OWNER_BASES = frozenset({"FrameworkElement", "UIElement", "Control", "Panel",
                          "ContentControl", "ItemsControl", "TextElement", "Shape"})  # fmt: skip


def content_property(el) -> str | None:
    """The property WPF's content syntax sets on ``el``'s type (Text, Content, Children...)."""
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
