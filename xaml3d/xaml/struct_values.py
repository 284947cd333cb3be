"""Value types written as elements with their members as attributes (struct-element form).

XAML may write a value type as an object element that sets its members, e.g. in a property
element ``<MatrixCamera.ViewMatrix><Matrix3D M11="2" OffsetX="1" .../></MatrixCamera.ViewMatrix>``
or as a keyed resource ``<Point3D x:Key="p" X="1" Y="2" Z="3"/>``. XAML creates the type's default
value and sets each member given: an unset member keeps the default (``Matrix3D`` and
``Quaternion`` start as the identity, ``Color`` as transparent black #00000000, the others at 0).
Covered: Matrix3D, Quaternion, Point3D, Vector3D, Point4D, Size3D, Rect3D, Point, Vector, Size,
Rect, Color (A R G B bytes, or ScA ScR ScG ScB floats).

``struct_text`` turns such an element into the type's string form ("1,2,3"), which the property's
own converter then reads, so both forms give the same value and the same checks.
"""

from __future__ import annotations

from lxml import etree

from xaml3d.errors import ValueSyntaxError
from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.context import is_presentation, qname
from xaml3d.xaml.parser import XAML_NS
from xaml3d.xaml.values import parse_double, parse_int

_IDENTITY_4X4 = [1.0 if r == c else 0.0 for r in range(4) for c in range(4)]
_MATRIX3D = [f"M{r}{c}" for r in (1, 2, 3) for c in (1, 2, 3, 4)] + [
    "OffsetX",
    "OffsetY",
    "OffsetZ",
    "M44",
]

# type -> (members in string-form order, their default values)
STRUCTS: dict[str, tuple[list[str], list[float]]] = {
    "Matrix3D": (_MATRIX3D, _IDENTITY_4X4),
    "Quaternion": (["X", "Y", "Z", "W"], [0.0, 0.0, 0.0, 1.0]),
    "Point3D": (["X", "Y", "Z"], [0.0] * 3),
    "Vector3D": (["X", "Y", "Z"], [0.0] * 3),
    "Point4D": (["X", "Y", "Z", "W"], [0.0] * 4),
    "Size3D": (["X", "Y", "Z"], [0.0] * 3),
    "Rect3D": (["X", "Y", "Z", "SizeX", "SizeY", "SizeZ"], [0.0] * 6),
    "Point": (["X", "Y"], [0.0] * 2),
    "Vector": (["X", "Y"], [0.0] * 2),
    "Size": (["Width", "Height"], [0.0] * 2),
    "Rect": (["X", "Y", "Width", "Height"], [0.0] * 4),
}
_COLOR_BYTES = ["A", "R", "G", "B"]
_COLOR_SC = ["ScA", "ScR", "ScG", "ScB"]
_SILENT_X = {"Key", "Name", "Uid"}


def is_struct_element(el: etree._Element) -> bool:
    ns, local = qname(el.tag)
    return is_presentation(ns) and (local in STRUCTS or local == "Color")


def _members(ctx, el, local: str, allowed: list[str]) -> dict[str, tuple[str, str]] | None:
    """member -> (text, attribute key); reports unknown members (XAML004). None if any is."""
    out: dict[str, tuple[str, str]] = {}
    ok = True
    for key, text in el.attrib.items():
        ns, name = qname(key)
        if (ns == XAML_NS and name in _SILENT_X) or (ns is not None and not is_presentation(ns)):
            continue
        if name not in allowed:
            hint = voc.did_you_mean(name, allowed)
            ctx.diag("XAML004", f"{local} has no member {name!r}{hint}", el, attr=key)
            ok = False
            continue
        out[name] = (text, key)
    return out if ok else None


def struct_text(ctx, el: etree._Element) -> str | None:
    """The string form of a struct element (see module docstring), or None when a member is
    unknown or unreadable (reported at its attribute: the property then keeps its default)."""
    local = qname(el.tag)[1]
    if local == "Color":
        return _color_text(ctx, el)
    names, defaults = STRUCTS[local]
    given = _members(ctx, el, local, names)
    if given is None:
        return None
    values = list(defaults)
    for i, name in enumerate(names):
        if name in given:
            text, key = given[name]
            try:
                values[i] = parse_double(text)
            except ValueSyntaxError as exc:
                exc.message = f"{local}.{name}: {exc.message}"
                ctx.error(exc, el, attr=key)
                return None
    return ",".join(repr(v) for v in values)


def _color_text(ctx, el) -> str | None:
    given = _members(ctx, el, "Color", _COLOR_BYTES + _COLOR_SC)
    if given is None:
        return None
    sc = any(n in given for n in _COLOR_SC)
    names = _COLOR_SC if sc else _COLOR_BYTES
    values: list[float] = [0.0] * 4
    for i, name in enumerate(names):
        if name not in given:
            continue
        text, key = given[name]
        try:
            if sc:
                values[i] = parse_double(text)
            else:
                v = parse_int(text)
                if not 0 <= v <= 255:
                    raise ValueSyntaxError(f"{v} is not a Byte (0..255)", code="VAL001")
                values[i] = v
        except ValueSyntaxError as exc:
            exc.message = f"Color.{name}: {exc.message}"
            ctx.error(exc, el, attr=key)
            return None
    if sc:
        return "sc#" + ",".join(repr(v) for v in values)
    return "#" + "".join(f"{int(v):02X}" for v in values)


# Value collections written with one element per item: <Point3DCollection><Point3D X=".."/>...
# (or the items straight inside the property element). XAML adds each item to the collection;
# the joined string forms give the same collection the attribute form gives.
COLLECTION_ITEMS = {
    "Point3DCollection": "Point3D",
    "Vector3DCollection": "Vector3D",
    "PointCollection": "Point",
    "Int32Collection": "Int32",
    "DoubleCollection": "Double",
}
_KIND_ITEMS = {
    "point3d[]": "Point3D",
    "vector3d[]": "Vector3D",
    "point[]": "Point",
    "int[]": "Int32",
}
# primitive items come from the XAML language namespace (x:Int32) or from mscorlib (sys:Int32)
_PRIMITIVES = {"Int32", "Double"}


def _is_item_namespace(ns: str | None, local: str) -> bool:
    if local in _PRIMITIVES:
        clr = (ns or "").replace(" ", "")
        return ns == XAML_NS or clr.startswith("clr-namespace:System;") or is_presentation(ns)
    return is_presentation(ns)


def collection_items(kids: list, kind: str | None) -> tuple[list, str] | None:
    """(item elements, item type) when ``kids`` write a value collection one item per element:
    a single collection element holding item elements, or item elements straight inside a
    property element of collection ``kind`` ('point3d[]' ...). None for any other form."""
    if len(kids) == 1:
        ns, local = qname(kids[0].tag)
        if is_presentation(ns) and local in COLLECTION_ITEMS and not (kids[0].text or "").strip():
            # no items at all: an empty collection, as the attribute form ""
            return [k for k in kids[0] if isinstance(k.tag, str)], COLLECTION_ITEMS[local]
    item = _KIND_ITEMS.get(kind or "")
    if item is not None and all(
        qname(k.tag)[1] == item and _is_item_namespace(*qname(k.tag)) for k in kids
    ):
        return list(kids), item
    return None


def collection_text(ctx, items: list, item_type: str) -> str | None:
    """The string form of a collection written one item per element (see COLLECTION_ITEMS),
    or None when an item is of another type or unreadable (reported at the item)."""
    parts: list[str] = []
    for el in items:
        ns, local = qname(el.tag)
        if local != item_type or not _is_item_namespace(ns, local):
            msg = f"a collection of {item_type} cannot hold {local!r}"
            ctx.diag("XAML013", msg, el)
            return None
        text = (el.text or "").strip()
        members = [k for k in el.attrib if qname(k)[0] != XAML_NS]
        if local in _PRIMITIVES or (text and not members):
            # <x:Int32>3</x:Int32>, or a struct initialised from its string form
            if not text:
                ctx.diag("XAML013", f"{local} item without a value", el)
                return None
            parts.append(text)
            continue
        part = struct_text(ctx, el)
        if part is None:
            return None
        parts.append(part)
    return " ".join(parts)
