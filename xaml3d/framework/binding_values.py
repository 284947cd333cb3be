"""What a binding reads and writes: a value as the markup holds it (``Value``), WPF's default
values and CLR types of the properties bindings commonly read, the properties that inherit down
the tree, and the text of a value for the target's attribute."""

from __future__ import annotations

import math
from dataclasses import dataclass

from xaml3d.framework import binding_format as F
from xaml3d.framework.binding_tree import XAML, children, local, qname


@dataclass(frozen=True)
class Value:
    """A source value: ``text`` as markup writes it (typed by ``clr`` when known), or an object
    element ``el`` (a brush, an x:Array, a resource entry found by ``key`` from ``at``), or a
    list of ``items`` (a collection property), or null."""

    text: str | None = None
    clr: str = "Object"
    el: object = None
    key: str | None = None
    at: object = None
    items: tuple | None = None
    null: bool = False
    visual: bool = False  # an element of the visual tree (a binding to it is the element's own)


NULL = Value(null=True)


class Unresolved(Exception):
    """A binding that takes its FallbackValue (or the property's default): ``code`` BND001 (it
    needs code or layout xaml3d does not run) or BND003 (WPF's binding fails too), None when
    the cause was said already (a missing resource: RES001); ``kind`` is what is said once."""

    def __init__(self, code: str | None, kind: str, detail: str = "") -> None:
        super().__init__(detail or kind)
        self.code, self.kind, self.detail = code, kind, detail or kind


def needs_code(kind: str, detail: str = "") -> Unresolved:
    return Unresolved("BND001", kind, detail)


def fails(kind: str, detail: str = "") -> Unresolved:
    return Unresolved("BND003", kind, detail)


# --------------------------------------------------------------------------- property tables
DOUBLE = frozenset(
    "Width Height MinWidth MinHeight MaxWidth MaxHeight Value Minimum Maximum SmallChange "
    "LargeChange TickFrequency Opacity FontSize Angle ScaleX ScaleY CenterX CenterY X Y X1 Y1 X2 "
    "Y2 Radius RadiusX RadiusY StrokeThickness StrokeMiterLimit StrokeDashOffset Canvas.Left "
    "Canvas.Top Canvas.Right Canvas.Bottom FieldOfView Offset LineHeight HorizontalOffset "
    "VerticalOffset Delay Interval ViewportSize".split()
)
BOOLEAN = frozenset(
    "IsChecked IsEnabled IsSelected IsExpanded IsOpen IsReadOnly IsHitTestVisible Focusable "
    "ClipToBounds ShowGridLines IsDefault IsCancel IsThreeState IsIndeterminate "
    "IsSnapToTickEnabled IsDirectionReversed AutoReverse SnapsToDevicePixels IsTabStop "
    "AcceptsReturn IsEditable".split()
)
INT32 = frozenset(
    "SelectedIndex Grid.Row Grid.Column Grid.RowSpan Grid.ColumnSpan Panel.ZIndex MaxLength "
    "AlternationCount Rows Columns FirstColumn MaxLines MinLines Count Length".split()
)
BRUSH = frozenset(
    "Background Foreground BorderBrush Fill Stroke OpacityMask CaretBrush SelectionBrush "
    "Brush".split()
)
STRING = frozenset("Text Title Name ContentStringFormat StringFormat Uid".split())
# enumerations a target accepts by name (a bound value of another text is a failed conversion)
ENUMS = {
    "Visibility": ("Visible", "Hidden", "Collapsed"),
    "HorizontalAlignment": ("Left", "Center", "Right", "Stretch"),
    "VerticalAlignment": ("Top", "Center", "Bottom", "Stretch"),
    "Orientation": ("Horizontal", "Vertical"),
    "Dock": ("Left", "Top", "Right", "Bottom"),
    "DockPanel.Dock": ("Left", "Top", "Right", "Bottom"),
}
# properties whose value children take from their parent when they set none
INHERITED = frozenset(
    "DataContext FontSize FontFamily FontWeight FontStyle FontStretch Foreground FlowDirection "
    "Language TextElement.Foreground TextElement.FontSize TextElement.FontFamily "
    "TextElement.FontWeight TextOptions.TextFormattingMode".split()
)
# results of layout: WPF's bindings to them update after layout, which a load does not see
LAYOUT_RESULTS = frozenset("ActualWidth ActualHeight RenderSize DesiredSize".split())

_DEFAULTS: dict[str, tuple[str | None, str]] = {
    "IsChecked": ("False", "Boolean"), "IsEnabled": ("True", "Boolean"),
    "IsSelected": ("False", "Boolean"), "IsExpanded": ("False", "Boolean"),
    "IsOpen": ("False", "Boolean"), "IsReadOnly": ("False", "Boolean"),
    "IsHitTestVisible": ("True", "Boolean"), "IsThreeState": ("False", "Boolean"),
    "IsIndeterminate": ("False", "Boolean"), "ClipToBounds": ("False", "Boolean"),
    "ShowGridLines": ("False", "Boolean"), "Focusable": ("False", "Boolean"),
    "Visibility": ("Visible", "Visibility"), "Opacity": ("1", "Double"),
    "Text": ("", "String"), "Title": ("", "String"),
    "Width": ("NaN", "Double"), "Height": ("NaN", "Double"),
    "MinWidth": ("0", "Double"), "MinHeight": ("0", "Double"),
    "MaxWidth": ("Infinity", "Double"), "MaxHeight": ("Infinity", "Double"),
    "Value": ("0", "Double"), "Minimum": ("0", "Double"), "Maximum": ("1", "Double"),
    "SmallChange": ("0.1", "Double"), "LargeChange": ("1", "Double"),
    "FontSize": ("12", "Double"), "FontFamily": ("Segoe UI", "FontFamily"),
    "FontWeight": ("Normal", "FontWeight"), "FontStyle": ("Normal", "FontStyle"),
    "FlowDirection": ("LeftToRight", "FlowDirection"),
    "SelectedIndex": ("-1", "Int32"), "Orientation": ("Horizontal", "Orientation"),
    "HorizontalAlignment": ("Stretch", "HorizontalAlignment"),
    "VerticalAlignment": ("Stretch", "VerticalAlignment"),
    "Margin": ("0", "Thickness"), "Padding": ("0", "Thickness"),
    "Grid.Row": ("0", "Int32"), "Grid.Column": ("0", "Int32"),
    "Grid.RowSpan": ("1", "Int32"), "Grid.ColumnSpan": ("1", "Int32"),
    "Panel.ZIndex": ("0", "Int32"), "DockPanel.Dock": ("Left", "Dock"),
    "Canvas.Left": ("NaN", "Double"), "Canvas.Top": ("NaN", "Double"),
    "Angle": ("0", "Double"), "ScaleX": ("1", "Double"), "ScaleY": ("1", "Double"),
    "Content": (None, "Object"), "Tag": (None, "Object"), "Header": (None, "Object"),
    "ToolTip": (None, "Object"), "DataContext": (None, "Object"),
    "Background": (None, "Brush"), "BorderBrush": (None, "Brush"), "Fill": (None, "Brush"),
    "Stroke": (None, "Brush"), "Foreground": ("#FF000000", "Brush"),
    "StrokeThickness": ("1", "Double"), "AlternationCount": ("0", "Int32"),
    "TickFrequency": ("1", "Double"),
}  # fmt: skip
# a class that overrides a default of its base class
_TYPE_DEFAULTS = {
    ("Slider", "Maximum"): ("10", "Double"), ("Slider", "LargeChange"): ("1", "Double"),
    ("ScrollBar", "Maximum"): ("1", "Double"), ("ProgressBar", "Maximum"): ("100", "Double"),
    ("Control", "Focusable"): ("True", "Boolean"), ("Button", "Focusable"): ("True", "Boolean"),
    ("CheckBox", "Focusable"): ("True", "Boolean"), ("TextBox", "Focusable"): ("True", "Boolean"),
    ("StackPanel", "Orientation"): ("Vertical", "Orientation"),
    ("WrapPanel", "Orientation"): ("Horizontal", "Orientation"),
    ("Line", "Stretch"): ("None", "Stretch"),
}  # fmt: skip


def default(type_name: str, prop: str) -> Value | None:
    """WPF's default value of ``prop`` on a ``type_name``, when xaml3d knows it."""
    hit = _TYPE_DEFAULTS.get((type_name, prop)) or _DEFAULTS.get(prop)
    if hit is None:
        return None
    text, clr = hit
    return NULL if text is None else Value(text, clr)


def clr_of(prop: str) -> str:
    """The CLR type of a property of that name, as far as formatting and conversion care."""
    short = prop.rpartition(".")[2] if prop.startswith(("Canvas.", "Grid.", "Panel.")) else prop
    for table, clr in ((DOUBLE, "Double"), (BOOLEAN, "Boolean"), (INT32, "Int32"),
                       (BRUSH, "Brush"), (STRING, "String")):  # fmt: skip
        if prop in table or short in table:
            return clr
    if prop in ENUMS:
        return prop
    return "Object"


# --------------------------------------------------------------------------- primitives
_SYSTEM = {"Double": "Double", "Single": "Double", "Decimal": "Double", "Int32": "Int32",
           "Int16": "Int32", "Int64": "Int32", "Byte": "Int32", "Boolean": "Boolean",
           "String": "String", "Char": "String"}  # fmt: skip


def primitive(el) -> Value | None:
    """A ``<sys:Double>2</sys:Double>`` (``x:Double`` in XAML 2009, ``sys:String``...) as its
    text value; None for any other element."""
    ns, name = qname(el)
    clr = _SYSTEM.get(name)
    if clr is None or children(el):
        return None
    if ns == XAML or (ns or "").replace(" ", "").startswith("clr-namespace:System;"):
        text = el.text or ""
        return Value(text if clr == "String" else text.strip(), clr)
    return None


def as_number(v: Value) -> float | None:
    """The value as a double when it is one (or reads as one), else None."""
    if v.text is None or v.clr not in ("Double", "Int32", "Object", "String"):
        return None
    t = v.text.strip()
    if v.clr in ("Object", "String"):
        return None
    low = t.lower()
    if low in ("nan", "auto"):
        return math.nan
    if low in ("infinity", "+infinity", "∞"):
        return math.inf
    if low in ("-infinity", "-∞"):
        return -math.inf
    try:
        return float(t)
    except ValueError:
        return None


def as_bool(v: Value) -> bool | None:
    if v.text is None:
        return None
    t = v.text.strip().lower()
    return True if t == "true" else False if t == "false" else None


def display_text(v: Value) -> str:
    """The value's ``ToString()`` (what a string target shows)."""
    if v.clr in ("Double", "Int32"):
        x = as_number(v)
        if x is not None:
            return F.double_text(x)
    if v.clr == "Boolean":
        b = as_bool(v)
        if b is not None:
            return F.bool_text(b)
    return v.text or ""


def to_target(v: Value, prop: str) -> str:
    """The attribute text for a target ``prop`` (a value with text); raises Unresolved when
    WPF's default conversion fails (a Boolean into a Visibility)."""
    text = display_text(v)
    allowed = ENUMS.get(prop) or ENUMS.get(prop.rpartition(".")[2])
    if allowed is not None and text.strip() not in allowed:
        raise fails("conversion", f"{text!r} is not a {prop.rpartition('.')[2]} "
                                  f"({', '.join(allowed)})")  # fmt: skip
    kind = clr_of(prop)
    if kind == "Brush" and v.clr not in ("Brush", "String", "Object"):
        # no default conversion makes a Brush of a number or a Color (WPF's binding fails)
        raise fails("conversion", f"a {v.clr} ({text!r}) is not a Brush")
    if kind == "Boolean" and as_bool(Value(text)) is None:
        raise fails("conversion", f"{text!r} is not a Boolean")
    if kind == "Int32":
        try:
            int(text.strip())
        except ValueError:
            raise fails("conversion", f"{text!r} is not an integer") from None
    elif kind == "Double" and v.clr not in ("Double", "Int32"):
        try:
            float(text)
        except ValueError:
            if text.strip().lower() not in ("nan", "auto", "infinity", "-infinity"):
                raise fails("conversion", f"{text!r} is not a number") from None
    return text


def element_type(el) -> str:
    return local(el)
