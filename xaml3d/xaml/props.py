"""Property access on one XAML element: attribute and property-element forms, content properties.

``Props(reader, el)`` gathers every property an element sets, however it is written:
``Prop="..."`` attributes, ``<Type.Prop>`` property elements (with or without an explicit
collection element such as ``<Model3DCollection>``), and content children that go to the type's
content property (wpf3d.md section 4). Attached properties (``Grid.Column``,
``Storyboard.TargetName``) are kept apart. While gathering, it reports what the vocabulary does
not know (with a did-you-mean suggestion), event handler attributes, ``x:Class``, and attributes
from unknown namespaces. Converting a property to a value (``value``), an object built from
elements (``obj``) or a list of child elements (``items``) goes through markup extensions
(``{StaticResource}``, ``{x:Null}``, ``{Binding}`` ...) and value-syntax errors, which become
located diagnostics while the property keeps its default.
"""

from __future__ import annotations

from collections.abc import Callable

from lxml import etree

from xaml3d.errors import ValueSyntaxError
from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.context import (
    ignorable_namespaces,
    is_presentation,
    markup_key,
    namespace_typo,
    qname,
    split_markup,
)
from xaml3d.xaml.directives import X_DIRECTIVES, unknown_directive
from xaml3d.xaml.parser import XAML_NS
from xaml3d.xaml.struct_values import (
    collection_items,
    collection_text,
    is_struct_element,
    struct_text,
)

NULL = object()  # an explicit {x:Null}

_COLLECTION_KINDS = ("collection",)
# value kinds whose WPF type is a value type (a struct: null is refused), by the type's name
_VALUE_TYPES = {
    "double": "Double", "bool": "Boolean", "color": "Color", "point3d": "Point3D",
    "vector3d": "Vector3D", "point": "Point", "quaternion": "Quaternion", "size": "Size",
    "rect": "Rect", "matrix3d": "Matrix3D", "matrix": "Matrix", "keytime": "KeyTime",
    "duration": "Duration", "repeat": "RepeatBehavior",
}  # fmt: skip
# the element kinds whose value properties are checked for null (an animation's From/To/By are
# nullable: Double? and so on; a Timeline's BeginTime is a TimeSpan?)
_NULL_CHECKED_KINDS = {"camera", "light", "visual3d", "model3d", "geometry", "material",
                       "transform3d", "rotation3d", "brush", "transform2d", "gradientstop",
                       "keyframe", "viewport"}  # fmt: skip
# the collection type of the 2D collection properties (framework types here, whose items the
# content check does not see): an explicit collection element of another type is refused
_PROPERTY_COLLECTIONS = {
    ("DrawingGroup", "Children"): "DrawingCollection",
    ("GeometryGroup", "Children"): "GeometryCollection",
    ("PathGeometry", "Figures"): "PathFigureCollection",
    ("PathFigure", "Segments"): "PathSegmentCollection",
    ("TransformGroup", "Children"): "TransformCollection",
    ("LinearGradientBrush", "GradientStops"): "GradientStopCollection",
    ("RadialGradientBrush", "GradientStops"): "GradientStopCollection",
}
_SILENT_X = {"Key", "Name", "Shared", "Uid", "FieldModifier", "ClassModifier", "Subclass"}


class Props:
    """The properties one element sets (see module docstring)."""

    def __init__(self, reader, el: etree._Element) -> None:
        self.r = reader
        self.el = el
        self.ns, self.type = qname(el.tag)
        self.etype = voc.lookup(self.type)
        self.attrs: dict[str, str] = {}
        self.attr_keys: dict[str, str] = {}  # property -> its attribute's key in el.attrib
        self.attached: dict[str, str] = {}
        self.attached_keys: dict[str, str] = {}  # "Storyboard.TargetName" -> its attribute key
        self.elems: dict[str, list[etree._Element]] = {}
        self.elem_text: dict[str, str] = {}
        self.prop_el: dict[str, etree._Element] = {}
        self.content: list[etree._Element] = []
        # property -> the markup extension element that gave its attrs entry (<Binding/>)
        self.ext_el: dict[str, etree._Element] = {}
        self.text = (el.text or "").strip()
        # properties whose value WPF's loader refuses: an error was reported while reading it
        # and the default stands in. The scene objects carry them, so that the checks do not
        # add a warning that only follows from that error (CHK004 "no Brush" after a bad colour)
        self.rejected: set[str] = set()
        self._read_attributes()
        self._read_children()

    # ----------------------------------------------------------------- gathering
    def _known(self, prop: str) -> bool:
        return self.etype is None or self.etype.open or prop in self.etype.properties

    def _check_property(
        self, prop: str, node: etree._Element, value: str | None, attr: str | None = None
    ) -> bool:
        """Report unknown/unsupported/event properties (located at attribute ``attr`` when the
        property is an attribute); True when the property is usable."""
        ctx = self.r.ctx
        kind = self.etype.property_kind(prop) if self.etype else None
        if kind == "event" or (
            (self.etype is None or self.etype.open or kind is None)
            and voc.is_event_name(prop)
            and value is not None
            and value.strip().isidentifier()
        ):
            msg = f"event handler {prop}={value!r} ignored (code-behind)"
            ctx.diag("XAML008", msg, node, attr=attr)
            return False
        if not self._known(prop):
            meant = voc.suggest(prop, self.etype.properties)
            hint = f" (did you mean {meant}?)" if meant else ""
            ctx.diag("XAML004", f"{self.type} has no property {prop!r}{hint}", node, attr=attr)
            if meant is not None:
                # the property meant is unset because of this error: no follow-on warning
                # ("no Material" after <GeometryModel3D.Materail>)
                self.rejected.add(meant)
            return False
        return True

    def _read_attributes(self) -> None:
        ctx = self.r.ctx
        ignorable = None
        for name, value in self.el.attrib.items():
            ns, local = qname(name)
            if ns == XAML_NS:
                if local == "Class":
                    msg = f"x:Class={value!r}: code-behind is not run"
                    ctx.diag("XAML007", msg, self.el, attr=name)
                elif local not in X_DIRECTIVES:
                    # the scene's own document is checked whole (directives.py); an element of
                    # another one (App.xaml, a merged or -r dictionary) is checked as it is read
                    if ctx.file_elsewhere(self.el) is not None:
                        ctx.diag("XAML004", unknown_directive(local), self.el, attr=name)
                elif local not in _SILENT_X:
                    ctx.diag("XAML006", f"x:{local} is not used by xaml3d", self.el, attr=name)
                continue
            if ns is not None and not is_presentation(ns):
                if ignorable is None:
                    ignorable = ignorable_namespaces(self.el)
                if ns in ignorable or ns == "http://www.w3.org/XML/1998/namespace":
                    continue
                wpf = namespace_typo(ns)
                if wpf is not None:
                    msg = (
                        f"namespace {ns!r} is not WPF's (did you mean {wpf!r}?): {local!r} ignored"
                    )
                    ctx.diag("XAML018", msg, self.el, attr=name)
                else:
                    msg = f"attribute {local!r} from namespace {ns!r} ignored"
                    ctx.diag("XAML002", msg, self.el, attr=name)
                continue
            if "." in local:
                owner, _, prop = local.rpartition(".")
                own = self.etype is not None and prop in self.etype.properties
                # an attached property of the element's own type stays attached when the type
                # does not list it (<Storyboard Storyboard.TargetName="...">)
                attached = owner in voc.ATTACHED_OWNERS
                if (owner == self.type and (own or not attached or self.etype is None)) or (
                        own and not attached):  # fmt: skip
                    local = prop
                else:
                    if voc.is_event_name(prop) and value.strip().isidentifier():
                        msg = f"event handler {local}={value!r} ignored"
                        ctx.diag("XAML008", msg, self.el, attr=name)
                    else:
                        self.attached[local] = value
                        self.attached_keys[local] = name
                    continue
            elif (
                self.etype is not None
                and local not in self.etype.properties
                and local in voc.OWN_ATTACHED.get(self.type, ())
            ):
                # XAML resolves an unqualified attribute that is no member of the type to the
                # type's attachable member: <Storyboard TargetName="..."> is
                # Storyboard.TargetName
                self.attached[f"{self.type}.{local}"] = value
                self.attached_keys[f"{self.type}.{local}"] = name
                continue
            if self._check_property(local, self.el, value, name):
                self.attrs[local] = value
                self.attr_keys[local] = name

    def _read_children(self) -> None:
        for child in self.el:
            if not isinstance(child.tag, str):
                continue
            ns, local = qname(child.tag)
            if is_presentation(ns) and "." in local:
                owner, _, prop = local.rpartition(".")
                if not self._known(prop):
                    self._check_property(prop, child, None)
                    continue
                if (
                    owner != self.type
                    and owner in voc.ATTACHED_OWNERS
                    and not (self.etype and prop in self.etype.properties)
                ):
                    continue  # attached property element on a framework element
                if prop in self.attrs:
                    self.r.ctx.diag(
                        "XAML012",
                        f"{self.type}.{prop} is set both as attribute and as element: "
                        "the element is used",
                        child,
                    )
                    del self.attrs[prop]
                kids = [k for k in child if isinstance(k.tag, str)]
                ext = _extension_text(kids[0]) if len(kids) == 1 else None
                if ext is not None:
                    # a markup extension written as an element (<Binding Path="P"/>,
                    # <x:Null/>) is the attribute form's value: XAML calls its ProvideValue
                    self.attrs[prop] = ext
                    self.ext_el[prop] = kids[0]
                    self.prop_el[prop] = child
                    continue
                self.elems.setdefault(prop, []).extend(kids)
                self.prop_el[prop] = child
                if not kids and (child.text or "").strip():
                    self.elem_text[prop] = child.text.strip()
            elif (ns is not None and not is_presentation(ns) and "." in local
                  and (ns, local.rpartition(".")[0]) != (self.ns, self.type)):  # fmt: skip
                # another assembly's attached property (<i:Interaction.Behaviors>): a value of
                # that property, not content of this element
                msg = f"element {local!r} from namespace {ns!r} skipped"
                self.r.ctx.diag("XAML001", msg, child, once=(ns, local))
            else:
                self.content.append(child)
        if self.content and self.etype is not None and self.etype.content:
            prop = self.etype.content
            if prop in self.attrs:
                self.r.ctx.diag("XAML012", f"{self.type}.{prop} set twice", self.content[0])
                del self.attrs[prop]
            self.elems.setdefault(prop, []).extend(self.content)
            self.prop_el.setdefault(prop, self.el)

    # ----------------------------------------------------------------- access
    def has(self, prop: str) -> bool:
        return prop in self.attrs or prop in self.elems or prop in self.elem_text

    def line_of(self, prop: str) -> etree._Element:
        return self.prop_el.get(prop, self.el)

    def markup(self, prop: str, value: str):
        """Evaluate a markup extension; returns (kind, payload): 'plain' | 'null' | 'element' |
        'default' (reported)."""
        m = split_markup(value)
        if m is None:
            v = value.strip()
            return ("plain", v[2:] if v.startswith("{}") else value)
        name, args = m
        ctx = self.r.ctx
        attr = self.attr_keys.get(prop)
        at = self.ext_el.get(prop, self.el)
        if name == "Null":
            return ("null", None)
        if name in ("StaticResource", "DynamicResource"):
            key = markup_key(args)
            dynamic = name == "DynamicResource"
            entry = self.r.resources.lookup(key, at, dynamic=dynamic, attr=attr)
            return ("element", entry) if entry is not None else ("default", None)
        if name in ("Binding", "MultiBinding", "PriorityBinding"):
            code = "XAML009"
        elif name == "Static":
            code = "XAML010"
        elif name == "":
            msg = f"{prop}={value!r}: malformed markup extension"
            ctx.diag("XAML016", msg, self.el, attr=attr)
            return ("default", None)
        else:
            code = "XAML011"
        msg = f"{self.type}.{prop}={value!r} cannot be evaluated: default kept"
        ctx.diag(code, msg, at, attr=attr)
        return ("default", None)

    def value(self, prop: str, conv: Callable[[str], object], default=None):
        """A value-type property (numbers, vectors, colours, collections...), as written (its
        animations are the Scene's tracks)."""
        errors = self.r.ctx.errors
        value = self._value(prop, conv, default)
        self._rejected(prop, value, default, errors)
        self.r.read(self.el, prop)
        return value

    def _rejected(self, prop: str, value, default, errors: int) -> None:
        if value is default and self.r.ctx.errors > errors:
            self.rejected.add(prop)

    def _value(self, prop: str, conv: Callable[[str], object], default=None):
        if prop in self.attrs:
            kind, payload = self.markup(prop, self.attrs[prop])
            attr = self.attr_keys.get(prop)
            if kind == "plain":
                return self._convert(conv, payload, self.el, prop, default, attr)
            if kind == "null":
                self._null_value(prop, attr)
                return default
            if kind == "element":
                text = (payload.text or "").strip()
                if text and len(payload) == 0:
                    return self._convert(conv, text, payload, prop, default)
                if is_struct_element(payload):
                    return self._struct(conv, payload, prop, default)
                msg = f"resource for {self.type}.{prop} is not a value"
                self.r.ctx.diag("RES008", msg, self.el, attr=attr)
            return default
        if prop in self.elem_text:
            return self._convert(conv, self.elem_text[prop], self.line_of(prop), prop, default)
        kids = self.elems.get(prop, ())
        listed = collection_items(kids, self.etype.property_kind(prop) if self.etype else None)
        if listed is not None:
            items, item_type = listed
            text = collection_text(self.r.ctx, items, item_type)
            if text is None:
                return default
            return self._convert(conv, text, self.line_of(prop), prop, default)
        kids = self.items(prop)
        if kids:
            node = kids[-1]
            text = (node.text or "").strip()
            if text:
                return self._convert(conv, text, node, prop, default)
            if is_struct_element(node):
                return self._struct(conv, node, prop, default)
            key = _resource_key(node)
            if key is not None:  # <StaticResource ResourceKey="fov"/>: the entry's value
                dynamic = qname(node.tag)[1] == "DynamicResource"
                entry = self.r.resources.lookup(key, node, dynamic=dynamic, attr="ResourceKey")
                if entry is None:
                    return default
                text = (entry.text or "").strip()
                if text and len(entry) == 0:
                    return self._convert(conv, text, entry, prop, default)
                if is_struct_element(entry):
                    return self._struct(conv, entry, prop, default)
                msg = f"resource for {self.type}.{prop} is not a value"
                self.r.ctx.diag("RES008", msg, node, attr="ResourceKey")
                return default
            self.r.ctx.diag("XAML013", f"{self.type}.{prop}: expected a value", node)
        return default

    def _null_value(self, prop: str, attr: str | None) -> None:
        """``{x:Null}`` (or ``<x:Null/>``) given to a property: WPF refuses it when the
        property's type is a value type (Double, Point3D, Color ...): its DependencyProperty
        does not take null ("'' is not a valid value for property 'FieldOfView'"). Reference
        types (collections, KeySpline) and the animations' nullable From/To/By take it."""
        et = self.etype
        vtype = _VALUE_TYPES.get(et.property_kind(prop) or "") if et is not None else None
        if vtype is None or et.kind not in _NULL_CHECKED_KINDS:
            return
        msg = (f"{self.type}.{prop} cannot be {{x:Null}}: its type, {vtype}, is a value type "
               f"(WPF: \"'' is not a valid value for property '{prop}'\")")  # fmt: skip
        self.r.ctx.diag("XAML013", msg, self.ext_el.get(prop, self.el), attr=attr)

    def _struct(self, conv, node, prop, default):
        """A value written as ``<Point3D X=".." .../>`` (struct_values.py), converted by the
        property's own converter (a Point3D where a Matrix3D is expected fails there)."""
        text = struct_text(self.r.ctx, node)
        return default if text is None else self._convert(conv, text, node, prop, default)

    def _convert(self, conv, s, node, prop, default, attr=None):
        try:
            return conv(s)
        except ValueSyntaxError as exc:
            # a converter names what it reads ("Color: '#GG1122' is not..."): said once
            own = exc.message.removeprefix(f"{prop}: ")
            exc.message = f"{self.type}.{prop}: {own}"
            self.r.ctx.error(exc, node, attr=attr)
            return default

    def obj(self, prop: str, build: Callable, default=None, *, from_string=None):
        """An object property built from an element (or resource); ``from_string`` converts a
        plain attribute string (e.g. a colour where a Brush is expected). {x:Null} -> None."""
        errors = self.r.ctx.errors
        built = self._obj(prop, build, default, from_string=from_string)
        self._rejected(prop, built, default, errors)
        s = self.r.slots
        if s is not None:
            self.r.read(self.el, prop)
            # a brush made from a colour string: its Color / Opacity animate (the target is
            # that field of the object built here)
            s.tag(built, [(f, k) for f, k in s.of(self.el, prop) if f is not None])
        return built

    def _obj(self, prop: str, build: Callable, default=None, *, from_string=None):
        if prop in self.attrs:
            kind, payload = self.markup(prop, self.attrs[prop])
            if kind == "null":
                return None
            attr = self.attr_keys.get(prop)
            if kind == "element":
                return self.r.build_resource(payload, build, default, self.el, attr)
            if kind == "plain":
                if from_string is not None:
                    return self._convert(from_string, payload, self.el, prop, default, attr)
                msg = f"{self.type}.{prop} needs an element, not {payload!r}"
                self.r.ctx.diag("XAML013", msg, self.el, attr=attr)
            return default
        kids = self.items(prop)
        if not kids:
            if prop in self.elem_text and from_string is not None:
                text = self.elem_text[prop]
                return self._convert(from_string, text, self.line_of(prop), prop, default)
            return default
        if len(kids) > 1:
            self.r.ctx.diag(
                "XAML014", f"{self.type}.{prop} has {len(kids)} values: the last is used", kids[1]
            )
        return self.r.build_node(kids[-1], build, default)

    def items(self, prop: str) -> list[etree._Element]:
        """Child elements of a property, explicit collection elements unwrapped."""
        return self._unwrapped(prop, self.elems.get(prop, ()))

    def children(self, prop: str) -> list[etree._Element]:
        """The items of a collection property the vocabulary gives no content property (the 2D
        types: DrawingGroup.Children, PathGeometry.Figures...): the property element's, else
        the element's content, an explicit collection element unwrapped in either."""
        return self.items(prop) or self._unwrapped(prop, self.content)

    def _unwrapped(self, prop: str, kids) -> list[etree._Element]:
        """``kids`` with every explicit collection element (``<DrawingCollection>``,
        ``<Model3DCollection>``...) replaced by its items, once: WPF sets the collection it
        writes as the property's value. A collection of another type than the property's is
        refused, as WPF's loader refuses it."""
        out: list[etree._Element] = []
        expected = _PROPERTY_COLLECTIONS.get((self.type, prop))
        for k in kids:
            if not isinstance(k.tag, str):
                continue
            ns, local = qname(k.tag)
            et = voc.lookup(local) if is_presentation(ns) else None
            if et is None or et.kind not in _COLLECTION_KINDS:
                out.append(k)
            elif expected is not None and local != expected:
                msg = f"{self.type}.{prop} is a {expected}: WPF cannot set a {local} to it"
                self.r.ctx.diag("XAML013", msg, k)
            else:
                out.extend(c for c in k if isinstance(c.tag, str))
        return out

    def string(self, prop: str, default: str | None = None) -> str | None:
        if prop in self.attrs:
            kind, payload = self.markup(prop, self.attrs[prop])
            return payload if kind == "plain" else default
        return self.elem_text.get(prop, default)


# markup extensions that may be written as elements, by namespace: what their attribute form's
# argument is (the element's attribute of that name)
_EXTENSION_ELEMENTS = {
    "Binding": "Path", "MultiBinding": None, "PriorityBinding": None,
    "TemplateBindingExtension": "Property", "RelativeSource": "Mode",
}  # fmt: skip
_X_EXTENSION_ELEMENTS = {"Null": None, "Static": "Member", "Reference": "Name", "Type": "TypeName"}


def _extension_text(el: etree._Element) -> str | None:
    """The attribute form of a markup extension written as an element (``<Binding Path="P"/>``
    -> ``{Binding P}``, ``<x:Null/>`` -> ``{x:Null}``); None for any other element."""
    ns, local = qname(el.tag)
    if ns == XAML_NS and local in _X_EXTENSION_ELEMENTS:
        arg, name = _X_EXTENSION_ELEMENTS[local], f"x:{local}"
    elif is_presentation(ns) and local in _EXTENSION_ELEMENTS:
        arg, name = _EXTENSION_ELEMENTS[local], local
    else:
        return None
    value = el.get(arg) if arg is not None else None
    return f"{{{name} {value}}}" if value else f"{{{name}}}"


def _resource_key(el: etree._Element) -> str | None:
    """The key of a ``<StaticResource ResourceKey="k"/>`` or ``<DynamicResource .../>``."""
    ns, local = qname(el.tag)
    if is_presentation(ns) and local in ("StaticResource", "DynamicResource"):
        return el.get("ResourceKey")
    return None
