"""Reading the panels around the viewports into a layout tree (xaml3d.scene.element_tree.Node).

Covers, for every element from the document's root down to the Viewport3Ds: Window (and
NavigationWindow), Page, UserControl, Grid (RowDefinitions/ColumnDefinitions: pixel, Auto,
star, Min/Max), DockPanel, StackPanel, Border, Canvas, Viewbox, ScrollViewer, UniformGrid
(Rows, Columns, FirstColumn), Viewport3D, the
content controls and decorators a viewport can sit in, and the 2D controls beside them (sized by
Width/Height, else by an estimate: LAY003). Per element: Width/Height (``Auto``, ``px``, ``in``,
``cm``, ``pt``), Min/Max sizes, Margin, Padding, BorderThickness, alignments, Visibility,
UseLayoutRounding, the attached Grid.Row/Column/RowSpan/ColumnSpan, DockPanel.Dock,
Canvas.Left/Top/Right/Bottom and ScrollViewer.*ScrollBarVisibility, the panels' own properties,
and the Background/BorderBrush that ``render --window`` paints. Values go through the reader's
converters, so a bad value is a located diagnostic and the property keeps WPF's default. A
property the element does not set comes from its Style's Setters (keyed or implicit, BasedOn
chains); every element's LayoutTransform (its 2 x 2 part) is kept for the layout engine.
"""

from __future__ import annotations

import math

import numpy as np

from xaml3d.codes.layout import LAYOUT_CODES
from xaml3d.errors import Diagnostic, ValueSyntaxError
from xaml3d.scene import element_tree as L
from xaml3d.xaml import framework_members as fm
from xaml3d.xaml import values as V
from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.brushes_reader import brush_property, transform2d, transform2d_text
from xaml3d.xaml.context import element_name, is_presentation, markup_key, qname, split_markup
from xaml3d.xaml.resources import type_key, type_name
from xaml3d.xaml.text_content import content_text

BLEND_NS = "http://schemas.microsoft.com/expression/blend/2008"

_KINDS = {
    "Window": L.WINDOW, "NavigationWindow": L.WINDOW, "Page": L.PAGE,
    "UserControl": L.USER_CONTROL, "Grid": L.GRID, "DockPanel": L.DOCK,
    "StackPanel": L.STACK, "Border": L.BORDER, "Canvas": L.CANVAS, "InkCanvas": L.CANVAS,
    "Viewbox": L.VIEWBOX, "ScrollViewer": L.SCROLL, "Viewport3D": L.VIEWPORT,
    "UniformGrid": L.UNIFORM, "WrapPanel": L.WRAP,
}  # fmt: skip
# Elements that simply hold their content (no chrome of their own): laid out as a Border.
_PLAIN = {"ContentControl", "ContentPresenter", "Decorator", "AdornerDecorator", "Frame"}
# 2D elements taking part in layout that xaml3d neither lays out inside nor draws.
_CONTROLS = set("""
Button TextBlock TextBox Label Slider CheckBox RadioButton ComboBox ComboBoxItem ListBox
ListBoxItem ListView ListViewItem Image Rectangle Ellipse Path Line Polygon Polyline Menu MenuItem
Separator Expander GroupBox TabControl TabItem ItemsControl ToggleButton RepeatButton ProgressBar
MediaElement FlowDocumentScrollViewer RichTextBox PasswordBox GridSplitter
StatusBar StatusBarItem ToolBar ToolBarTray DocumentViewer Thumb Track ScrollBar ResizeGrip
HeaderedContentControl Calendar DatePicker DataGrid TreeView TreeViewItem
""".split())  # fmt: skip
_SHAPES = {"Rectangle", "Ellipse", "Path", "Line", "Polygon", "Polyline", "Image"}
# The documented estimate of a control's content size: about 7 px per character of its text
# (Segoe UI 12 px), one 16 px text line, plus the chrome (padding + border) of its default
# template, (width, height) in px.
CHAR_WIDTH, LINE_HEIGHT = 7.0, 16.0
FONT_SIZE = 12.0  # WPF's default FontSize (px); the estimate scales with the FontSize in effect
_CHROME = {
    "TextBlock": (0, 0), "Label": (10, 10), "Button": (4, 4), "ToggleButton": (4, 4),
    "RepeatButton": (4, 4), "CheckBox": (20, 0), "RadioButton": (20, 0), "TextBox": (6, 6),
    "PasswordBox": (6, 6), "ComboBox": (26, 6), "Slider": (0, 6), "ProgressBar": (0, -6),
    "Separator": (0, -12), "Menu": (0, 4), "MenuItem": (14, 6), "ToolBar": (12, 10),
    "StatusBar": (0, 6), "GroupBox": (12, 30), "Expander": (24, 8), "TabControl": (8, 32),
}  # fmt: skip
# The default templates' Padding, replaced by an element's own Padding in the estimate.
_DEFAULT_PADDING = {
    "Label": (5, 5, 5, 5), "Button": (1, 1, 1, 1), "ToggleButton": (1, 1, 1, 1),
    "RepeatButton": (1, 1, 1, 1), "TextBox": (1, 1, 1, 1), "PasswordBox": (1, 1, 1, 1),
}  # fmt: skip
# Bars whose items sit side by side: their estimate is the sum of the items' sizes.
_BARS = {"ToolBar", "ToolBarTray", "StatusBar"}
# Property elements whose children are not laid out as content.
_NOT_CONTENT = ("Resources", "Triggers", "MergedDictionaries", "RowDefinitions",
                "ColumnDefinitions", "Style", "Template", "ToolTip", "ContextMenu",
                "InputBindings", "CommandBindings", "Background", "BorderBrush", "Foreground",
                "Effect", "RenderTransform", "LayoutTransform", "OpacityMask", "Clip",
                "ItemTemplate", "ItemsPanel", "DataContext", "Camera", "Header",
                "BitmapEffect", "BitmapEffectInput", "CacheMode", "Tag",
                # an items control's item properties: values the framework step reads
                "ItemContainerStyle", "ItemContainerStyleSelector", "ItemTemplateSelector",
                "ItemsSource")  # fmt: skip
_PAINTED = (L.WINDOW, L.PAGE, L.USER_CONTROL, L.GRID, L.DOCK, L.STACK, L.BORDER, L.CANVAS,
            L.CONTAINER, L.SCROLL, L.UNIFORM, L.WRAP)  # fmt: skip
_UNITS = {"px": 1.0, "in": 96.0, "cm": 96.0 / 2.54, "pt": 96.0 / 72.0}
_ALIGN_H = ("Left", "Center", "Right", "Stretch")
_ALIGN_V = ("Top", "Center", "Bottom", "Stretch")


def parse_length(s: str) -> float:
    """A FrameworkElement length (LengthConverter): a number with an optional px, in, cm or pt
    unit, or ``Auto`` (NaN: sized by layout)."""
    t = s.strip()
    if t.lower() == "auto":
        return math.nan
    factor = 1.0
    if t[-2:].lower() in _UNITS:
        factor, t = _UNITS[t[-2:].lower()], t[:-2]
    return V.parse_double(t) * factor


def parse_thickness(s: str) -> tuple[float, float, float, float]:
    """A Thickness: one length (all sides), two (left/right, top/bottom) or four (left, top,
    right, bottom)."""
    toks = [parse_length(t) for t, _ in V.split_tokens(s, "Thickness")]
    if any(v != v for v in toks):
        raise ValueSyntaxError(
            f"Thickness: Auto is not a thickness in {s.strip()!r}", code="VAL001"
        )
    if len(toks) == 1:
        return (toks[0],) * 4
    if len(toks) == 2:
        return (toks[0], toks[1], toks[0], toks[1])
    if len(toks) == 4:
        return tuple(toks)
    raise ValueSyntaxError(f"Thickness needs 1, 2 or 4 lengths, got {len(toks)}", code="VAL003")


def parse_corner_radius(s: str) -> tuple[float, float, float, float]:
    """A CornerRadius: one number (every corner) or four (TopLeft, TopRight, BottomRight,
    BottomLeft); a negative radius is taken as 0, as Border draws it."""
    toks = [V.parse_double(t) for t, _ in V.split_tokens(s, "CornerRadius")]
    if len(toks) not in (1, 4):
        raise ValueSyntaxError(f"CornerRadius needs 1 or 4 numbers, got {len(toks)}", code="VAL003")
    return tuple(max(0.0, t) if math.isfinite(t) else 0.0 for t in toks * (4 // len(toks)))


def parse_grid_length(s: str) -> tuple[str, float]:
    """A GridLength: ``Auto``, ``*``, ``2*`` or a length -> (unit, value)."""
    t = s.strip()
    if t.lower() == "auto":
        return "auto", 1.0
    if t.endswith("*"):
        w = V.parse_double(t[:-1]) if t[:-1].strip() else 1.0
        if w < 0:
            raise ValueSyntaxError(f"GridLength: negative star weight in {t!r}", code="VAL007")
        return "star", w
    v = parse_length(t)
    if v != v or v < 0:
        raise ValueSyntaxError(f"GridLength: {t!r} is not a size", code="VAL001")
    return "pixel", v


# WPF's validate callbacks of framework properties: a value they refuse is an error where it is
# written (VAL008), and WPF's default stands in
_VALID = {
    "MinWidth": (lambda v: 0.0 <= v < math.inf, "a size must be finite and >= 0"),
    "MinHeight": (lambda v: 0.0 <= v < math.inf, "a size must be finite and >= 0"),
    "MaxWidth": (lambda v: v >= 0.0, "a size must be >= 0"),
    "MaxHeight": (lambda v: v >= 0.0, "a size must be >= 0"),
    "BorderThickness": (
        lambda t: all(0.0 <= x < math.inf for x in t),
        "a thickness must be finite and >= 0",
    ),
    "Padding": (
        lambda t: all(0.0 <= x < math.inf for x in t),
        "a thickness must be finite and >= 0",
    ),
    "Margin": (lambda t: all(math.isfinite(x) for x in t), "a margin must be finite"),
    "FontSize": (
        lambda v: 0.0 < v <= 35791.39453125,
        "a font size must be above 0 and at most 35791.39",
    ),
}


def _validated(prop: str, conv):
    rule = _VALID.get(prop)
    if rule is None:
        return conv
    ok, what = rule

    def convert(s: str):
        v = conv(s)
        if not ok(v):
            raise ValueSyntaxError(f"{s.strip()!r}: {what} (WPF refuses it)", code="VAL008")
        return v

    return convert


class ElementValues:
    """Property values of one element, through Props (presentation elements) or, for custom
    elements, their plain attributes with bad values ignored."""

    def __init__(self, r, el, style: dict[str, str] | None = None) -> None:
        self.r, self.el = r, el
        self.p = r.props(el) if is_presentation(qname(el.tag)[0]) else None
        self.style = style or {}

    def get(self, prop: str, conv, default):
        conv = _validated(prop, conv)
        if self.p is not None:
            p = self.p
            raw = self.style.get(prop)
            if raw is None or prop in p.attrs or prop in p.elem_text or prop in p.elems:
                return p.value(prop, conv, default)
            # not set on the element: its Style's Setter (an animation still applies on top)
            if split_markup(raw) is None:
                try:
                    default = conv(raw)
                except ValueSyntaxError:
                    pass
            self.r.read(self.el, prop)
            return default
        raw = self.el.get(prop)
        if raw is None or split_markup(raw) is not None:
            return default
        try:
            return conv(raw)
        except ValueSyntaxError:
            return default

    def attr_key(self, prop: str) -> str | None:
        """The attribute key of an attached property set on the element (None: from a Style)."""
        if self.p is None:
            return prop if prop in self.el.attrib else None
        return prop if prop in self.p.attached else None

    def attached(self, prop: str, conv, default):
        if self.p is None:
            raw = self.el.get(prop)
        else:
            raw = self.p.attached.get(prop)
            owner, _, short = prop.partition(".")
            if raw is None and owner == self.p.type:  # Grid.Row on a Grid: read as its own
                raw = self.p.attrs.get(short)
                prop = self.p.attr_keys.get(short, prop)
        from_style = raw is None and prop in self.style
        if from_style:  # Grid.Row (DockPanel.Dock ...) set by the element's Style
            raw = self.style[prop]
        if raw is None or split_markup(raw) is not None:
            return default  # a {Binding} row cannot be evaluated: WPF's default
        try:
            return conv(raw)
        except ValueSyntaxError as exc:
            if self.p is not None and not from_style:
                exc.message = f"{prop}: {exc.message}"
                self.r.ctx.error(exc, self.el, attr=prop)
            return default


_STYLE_DEPTH = 16  # BasedOn chains longer than this are cut (a cycle, or hostile markup)


_ATTACHED_OWNERS = {"Grid", "DockPanel", "Canvas", "ScrollViewer"}


def _style_setter_elements(style):
    """A Style's own Setters (direct children or inside ``<Style.Setters>``); a Trigger's
    Setters apply only when it fires, so they are not among them."""
    for child in style:
        if not isinstance(child.tag, str):
            continue
        local = qname(child.tag)[1]
        if local == "Setter":
            yield child
        elif local == "Style.Setters":
            yield from (k for k in child if isinstance(k.tag, str) and qname(k.tag)[1] == "Setter")


_WINDOW_STYLES = ("None", "SingleBorderWindow", "ThreeDBorderWindow", "ToolWindow")
_RESIZE_MODES = ("NoResize", "CanMinimize", "CanResize", "CanResizeWithGrip")


# The base classes of a Viewport3D: the TargetTypes a Style may name to apply to it.
_VIEWPORT_BASES = {"Viewport3D", "FrameworkElement", "UIElement", "Visual", "DependencyObject",
                   "DispatcherObject", "Object", ""}  # fmt: skip


def _mismatched(target: str, local: str) -> bool:
    """Whether WPF refuses a Style of TargetType ``target`` on a ``local`` element; only the
    cases that are certain: a Viewport3D's Style must target it or a base class, nothing but a
    Viewport3D derives from Viewport3D, and the 2D types of known class trees."""
    if local == "Viewport3D":
        return target not in _VIEWPORT_BASES
    # a 2D type whose class tree framework_members.py knows to its top: WPF's verdict
    return target == "Viewport3D" or fm.derives(local, target) is False


def _setter_value(setter) -> str | None:
    """A Setter's value as text: its Value attribute, or a ``<Setter.Value>`` holding plain text
    or one element whose text is the value (``<Thickness>50</Thickness>``)."""
    value = setter.get("Value")
    if value is not None:
        return value
    for child in setter:
        if isinstance(child.tag, str) and qname(child.tag)[1] == "Setter.Value":
            kids = [k for k in child if isinstance(k.tag, str)]
            if not kids:
                return (child.text or "").strip() or None
            if len(kids) == 1 and len(kids[0]) == 0 and (kids[0].text or "").strip():
                return kids[0].text.strip()
    return None


def _enum(allowed):
    return lambda s: V.parse_enum(s, allowed)


def _style_property(r, el):
    """The Style a ``<X.Style>`` property element of ``el`` holds: a Style written in place, or
    the entry a ``<StaticResource ResourceKey="k"/>`` in it names; None without one."""
    for child in el:
        if isinstance(child.tag, str) and qname(child.tag)[1].endswith(".Style"):
            kids = [k for k in child if isinstance(k.tag, str)]
            if len(kids) != 1:
                return None
            k = kids[0]
            if qname(k.tag)[1] in ("StaticResource", "DynamicResource"):
                key = k.get("ResourceKey")
                return r.resources.find(key, k) if key else None
            return k
    return None


def _style_chain(r, el, local: str, report: bool = True) -> list:
    """The Styles that apply to ``el``, most derived first: ``Style="{StaticResource k}"`` (or
    DynamicResource) or a Style given as the ``<X.Style>`` property element, else the implicit
    Style keyed by the element's type in scope, then the ones it is BasedOn. ``report``: say
    (XAML022) that a Style of another TargetType is not applied (none apply then)."""
    res = r.resources
    ref = el.get("Style")
    given = _style_property(r, el) if ref is None else None
    if ref is not None or given is not None:
        if ref is not None:
            m = split_markup(ref)
            if m is None or m[0] not in ("StaticResource", "DynamicResource"):
                return []
            entry = res.find(markup_key(m[1]), el)
        else:
            entry = given
        if entry is not None and qname(entry.tag)[1] == "Style":
            target = type_name(entry.get("TargetType") or "")
            if is_presentation(qname(el.tag)[0]) and _mismatched(target, local):
                if not report:
                    return []
                r.ctx.diag("XAML022", f"the Style's TargetType {target} does not match "
                                f"this {local}: WPF refuses to apply it", el,
                                attr="Style" if ref is not None else None)  # fmt: skip
                return []
    else:
        # (every dictionary of the document is read by now: the walk before layout reads
        # each element's resources, so a type no implicit Style names needs no search)
        key = type_key(local)
        entry = res.find_implicit(key, el) if key in res.type_keys else None
    chain = []
    while entry is not None and qname(entry.tag)[1] == "Style" and len(chain) < _STYLE_DEPTH:
        chain.append(entry)
        based = entry.get("BasedOn")
        m = split_markup(based) if based else None
        if m is None:
            break
        if m[0] in ("StaticResource", "DynamicResource"):
            entry = res.find(markup_key(m[1]), entry)
        elif m[0] == "Type":
            entry = res.find(type_key(based), entry)
        else:
            break
    return chain


def style_setters(r, el, local: str, report: bool = True) -> dict[str, str]:
    """Property -> value text of the Setters of ``el``'s Style: ``Style="{StaticResource
    k}"`` (or DynamicResource), else the implicit Style keyed by the element's type in
    scope; BasedOn styles first, so the derived Setters win. Setter values that are
    property elements or markup are left out (the property keeps its default). ``report``:
    say (XAML022) that a Style of another TargetType is not applied."""
    chain = _style_chain(r, el, local, report)
    setters: dict[str, str] = {}
    for style in reversed(chain):
        for child in _style_setter_elements(style):
            prop, value = child.get("Property"), _setter_value(child)
            if not prop or value is None or child.get("TargetName"):
                continue
            owner, _, short = prop.rpartition(".")
            owner = owner.split(":")[-1]
            # attached properties keep their owner (Grid.Row); others their own name
            setters[f"{owner}.{short}" if owner in _ATTACHED_OWNERS else short] = value
    return setters


def style_value_element(r, el, prop: str):
    """The element a Setter of ``el``'s Style gives ``prop`` as its value
    (``<Setter Property="RenderTransform"><Setter.Value><ScaleTransform .../>``), the most
    derived Style's; None when no Setter gives one."""
    ns, local = qname(el.tag)
    if not is_presentation(ns):
        return None
    for style in _style_chain(r, el, local, report=False):
        for setter in reversed(list(_style_setter_elements(style))):
            if setter.get("Property") != prop or setter.get("TargetName"):
                continue
            for child in setter:
                if isinstance(child.tag, str) and qname(child.tag)[1] == "Setter.Value":
                    kids = [k for k in child if isinstance(k.tag, str)]
                    return kids[0] if len(kids) == 1 else None
            return None
    return None


def element_style(r, el) -> dict[str, str]:
    """``style_setters`` of ``el`` (a presentation element) for drawing it, silently (the
    layout reported any mismatch) and once per element: the values a Style sets that the
    element does not (Foreground, Background, TextAlignment...) are drawn as WPF draws them."""
    cache = r.__dict__.setdefault("_element_styles", {})
    hit = cache.get(id(el))
    if hit is None or hit[0] is not el:
        ns, local = qname(el.tag)
        setters = style_setters(r, el, local, report=False) if is_presentation(ns) else {}
        hit = cache[id(el)] = (el, setters)
    return hit[1]


class PanelsReader:
    def __init__(self, r, viewport_elements: list) -> None:
        self.r = r
        self.index = {id(el): i for i, el in enumerate(viewport_elements)}
        self.holds_viewport: set[int] = set()
        for el in viewport_elements:
            node = el.getparent()
            while node is not None and id(node) not in self.holds_viewport:
                self.holds_viewport.add(id(node))
                node = node.getparent()
        self.viewports: dict[int, L.Node] = {}
        # id(node) -> (element, FontSize in effect): what draws a control (visuals_reader)
        self.elements: dict[int, tuple] = {}

    def note(self, code: str, message: str, el, attr: str | None = None) -> None:
        if attr is not None:
            self.r.ctx.diag(code, message, el, attr=attr)
        else:
            self.r.ctx.add(Diagnostic(code, LAYOUT_CODES[code][0], message), el)

    # ----------------------------------------------------------------- elements
    def kind_of(self, el) -> str | None:
        """The layout rule of an element, None when it takes no part in layout."""
        ns, local = qname(el.tag)
        if self.r.ctx.is_templated(el):
            return L.CONTAINER  # its template's instance is its child (xaml3d.framework)
        if not is_presentation(ns) or voc.lookup(local) is None:
            return L.CONTAINER if id(el) in self.holds_viewport else L.CONTROL
        if local == "Viewport3D":
            return L.VIEWPORT if id(el) in self.index else None
        if local in _KINDS:
            return _KINDS[local]
        if local in _PLAIN:
            return L.CONTAINER
        if local in _CONTROLS:
            return L.CONTAINER if id(el) in self.holds_viewport else L.CONTROL
        return None

    def content_of(self, el):
        """The child elements that are laid out inside ``el`` (content and Child/Content/
        Children/Items property elements), in document order."""
        for child in el:
            if not isinstance(child.tag, str):
                continue
            ns, local = qname(child.tag)
            if "." in local:
                if local.rpartition(".")[2] in _NOT_CONTENT:
                    continue
                owner = (ns, local.rpartition(".")[0])
                if (not is_presentation(ns) and owner != qname(el.tag)
                        and id(child) not in self.holds_viewport):  # fmt: skip
                    # another assembly's attached property (<i:Interaction.Behaviors>): what
                    # it holds is a value of that property, not laid-out content
                    continue
                for g in child:
                    if isinstance(g.tag, str) and "." not in qname(g.tag)[1]:
                        yield g
            else:
                yield child

    def build(self, el, font: float = FONT_SIZE) -> L.Node | None:
        """The layout node of ``el`` and its content; ``font``: the FontSize it inherits."""
        kind = self.kind_of(el)
        if kind is None:
            return None
        ns, local = qname(el.tag)
        n = L.Node(kind, local, element_name(el), **self.r.ctx.position(el))
        if local == "GridSplitter":  # its HorizontalAlignment's own default (GridSplitter's)
            n.h_align = "Right"
        n.width_share = self.r.ctx.width_shares.get(id(el))
        v = ElementValues(self.r, el, self.style_setters(el, local))
        self._framework(n, v)
        turned = layout_transform_of(self.r, v)
        if turns(turned):  # laid out in its own space, its box turned (xaml3d.layout)
            (a, b), (c, d) = (tuple(float(x) for x in row) for row in turned[:2, :2])
            n.layout_transform = ((a, b), (c, d))
        size = v.get("FontSize", parse_length, None)
        if size is None:
            size = v.attached("TextElement.FontSize", parse_length, None)
        if size is not None and math.isfinite(size) and size > 0:
            font = size  # inherited by the content, as WPF's FontSize is
        self.elements[id(n)] = (el, font)
        if kind == L.VIEWPORT:
            n.viewport = self.index[id(el)]
            self.viewports[n.viewport] = n
            return n
        self._panel(n, v, el)
        if kind == L.CONTROL:
            self._estimate(n, v, el, font)
            return n
        if kind == L.CONTAINER and local not in _PLAIN and not self.r.ctx.is_templated(el):
            what = "custom element" if not is_presentation(ns) else local
            self.note("LAY004", f"{what} {local!r} holding a Viewport3D is laid out as a plain "
                      "container (its own chrome and rules are not known)", el)  # fmt: skip
        for child in self.content_of(el):
            k = self.build(child, font)
            if k is not None:
                n.children.append(k)
        return n

    def style_setters(self, el, local: str) -> dict[str, str]:
        """Property -> value text of the Setters of ``el``'s Style (``style_setters``)."""
        return style_setters(self.r, el, local)

    def _framework(self, n: L.Node, v: ElementValues) -> None:
        for prop in ("Width", "Height"):
            x = v.get(prop, parse_length, math.nan)
            if x == x and (x < 0 or x == math.inf):
                # WPF refuses a negative or infinite size outright; xaml3d draws it empty.
                what = "negative" if x < 0 else "infinite"
                self.r.ctx.diag(
                    "SCN012", f"{n.type}.{prop} = {x:g} is {what} (invalid in WPF): taken as 0",
                    v.el, attr=v.p.attr_keys.get(prop) if v.p else None,
                )  # fmt: skip
                x = 0.0
            setattr(n, prop.lower(), x)
        n.min_width = _finite(v.get("MinWidth", parse_length, 0.0), 0.0)
        n.min_height = _finite(v.get("MinHeight", parse_length, 0.0), 0.0)
        n.max_width = _nonneg(v.get("MaxWidth", parse_length, math.inf), math.inf)
        n.max_height = _nonneg(v.get("MaxHeight", parse_length, math.inf), math.inf)
        n.margin = v.get("Margin", parse_thickness, n.margin)
        n.h_align = v.get("HorizontalAlignment", _enum(_ALIGN_H), n.h_align)
        n.v_align = v.get("VerticalAlignment", _enum(_ALIGN_V), n.v_align)
        n.visibility = v.get("Visibility", _enum(("Visible", "Hidden", "Collapsed")), "Visible")
        n.rounding = v.get("UseLayoutRounding", V.parse_bool, None)
        for attr, name, low in (
            ("Grid.Row", "row", 0),
            ("Grid.Column", "col", 0),
            ("Grid.RowSpan", "row_span", 1),
            ("Grid.ColumnSpan", "col_span", 1),
        ):
            x = v.attached(attr, V.parse_int, low)
            if x < low:  # WPF's value check refuses it at load
                self.note("LAY005", f"{attr} = {x} is out of range (at least {low} in WPF): "
                          f"taken as {low}", v.el, attr=v.attr_key(attr))  # fmt: skip
            setattr(n, name, max(low, x))
        n.dock = v.attached("DockPanel.Dock", _enum(("Left", "Top", "Right", "Bottom")), "Left")
        for side in ("Left", "Top", "Right", "Bottom"):
            setattr(n, side.lower(), v.attached(f"Canvas.{side}", parse_length, math.nan))

    def _panel(self, n: L.Node, v: ElementValues, el) -> None:
        kind = n.kind
        if self.r.ctx.is_templated(el):
            # a control drawn by its template: measured and drawn as the template's root (WPF's
            # Control.MeasureOverride); its Padding, border and Background are the template's
            kind = None
        bars = ("Disabled", "Auto", "Hidden", "Visible")
        if kind == L.WINDOW:
            n.size_to_content = v.get(
                "SizeToContent", _enum(("Manual", "Width", "Height", "WidthAndHeight")), "Manual"
            )
            style = v.get("WindowStyle", _enum(_WINDOW_STYLES), "SingleBorderWindow")
            resize = v.get("ResizeMode", _enum(_RESIZE_MODES), "CanResize")
            if v.get("AllowsTransparency", V.parse_bool, False):
                n.frame = (0.0, 0.0)
            elif style == "None":
                resizable = resize in ("CanResize", "CanResizeWithGrip")
                n.frame = L.WINDOW_FRAME_NO_CAPTION if resizable else (0.0, 0.0)
        if kind == L.SCROLL:
            n.scroll_h = v.get("HorizontalScrollBarVisibility", _enum(bars), "Disabled")
            n.scroll_v = v.get("VerticalScrollBarVisibility", _enum(bars), "Visible")
        if kind in (L.WINDOW, L.PAGE, L.USER_CONTROL, L.BORDER, L.CONTAINER, L.SCROLL):
            n.padding = v.get("Padding", parse_thickness, n.padding)
            n.border = v.get("BorderThickness", parse_thickness, n.border)
        if kind == L.BORDER:
            n.corner_radius = v.get("CornerRadius", parse_corner_radius, n.corner_radius)
        if kind == L.UNIFORM:
            n.uniform = tuple(
                max(0, v.get(p, V.parse_int, 0)) for p in ("Rows", "Columns", "FirstColumn")
            )
        if kind == L.STACK:
            n.orientation = v.get("Orientation", _enum(("Vertical", "Horizontal")), "Vertical")
        if kind == L.WRAP:
            n.orientation = v.get("Orientation", _enum(("Vertical", "Horizontal")), "Horizontal")
            n.item_width = _nonneg(v.get("ItemWidth", parse_length, math.nan), math.nan)
            n.item_height = _nonneg(v.get("ItemHeight", parse_length, math.nan), math.nan)
        if kind == L.DOCK:
            n.last_child_fill = v.get("LastChildFill", V.parse_bool, True)
        if kind == L.VIEWBOX:
            n.stretch = v.get(
                "Stretch", _enum(("None", "Fill", "Uniform", "UniformToFill")), "Uniform"
            )
            n.stretch_direction = v.get(
                "StretchDirection", _enum(("UpOnly", "DownOnly", "Both")), "Both"
            )
        if kind == L.GRID and v.p is not None:
            n.rows = self._definitions(v.p, "RowDefinitions", "Height")
            n.columns = self._definitions(v.p, "ColumnDefinitions", "Width")
        if kind == L.PAGE:
            ww = v.get("WindowWidth", parse_length, math.nan)
            wh = v.get("WindowHeight", parse_length, math.nan)
            if ww == ww or wh == wh:
                fw, fh = L.WINDOW_FRAME
                n.design_size = (ww - fw if ww == ww else None, wh - fh if wh == wh else None)
        if el.getparent() is None and kind != L.WINDOW and n.design_size is None:
            dw, dh = _design(el, "DesignWidth"), _design(el, "DesignHeight")
            if dw is not None or dh is not None:
                n.design_size = (dw, dh)
        if v.p is not None and kind in _PAINTED:
            if v.p.has("Background"):
                n.background = brush_property(self.r, v.p, "Background")
            if kind in (L.BORDER, L.WINDOW, L.USER_CONTROL, L.CONTAINER) and v.p.has("BorderBrush"):
                n.border_brush = brush_property(self.r, v.p, "BorderBrush")

    def _definitions(self, p, prop: str, size: str) -> tuple[L.Definition, ...]:
        out = []
        for d in p.items(prop):
            if not isinstance(d.tag, str) or qname(d.tag)[1] not in (
                "RowDefinition",
                "ColumnDefinition",
            ):
                continue
            dv = ElementValues(self.r, d)
            unit, value = dv.get(size, parse_grid_length, ("star", 1.0))
            lo = _finite(dv.get(f"Min{size}", parse_length, 0.0), 0.0)
            hi = _nonneg(dv.get(f"Max{size}", parse_length, math.inf), math.inf)
            out.append(L.Definition(unit, value, lo, hi))
        return tuple(out)

    def content_size(self, n: L.Node, v: ElementValues, el, font: float):
        """A control's content size as its template measures it, None when it is not known
        (the documented estimate then stands in). The 2D layer's reader measures text and
        shapes (``control_content``); this plain reader knows none."""
        return None

    def _estimated_size(self, n: L.Node, v: ElementValues, el, font: float):
        """The documented estimate: 7 px a character, a 16 px line, the template's chrome."""
        local = n.type
        text = None
        for prop in ("Text", "Content", "Header"):
            s = el.get(prop)
            if s is not None and split_markup(s) is None:
                text = s
                break
        if text is None:
            text = content_text(el)
        cw, ch = _CHROME.get(local, (0, 0))
        pad = v.get("Padding", parse_thickness, None)
        if pad is not None:  # the element's own Padding instead of its template's default
            dl, dt, dr, db = _DEFAULT_PADDING.get(local, (0, 0, 0, 0))
            cw += pad[0] + pad[2] - dl - dr
            ch += pad[1] + pad[3] - dt - db
        scale = font / FONT_SIZE
        w = CHAR_WIDTH * scale * len(text) + cw
        h = LINE_HEIGHT * scale + ch
        if local in _BARS:  # a toolbar of buttons: its items side by side
            items = [k for k in (self.build(c, font) for c in self.content_of(el)) if k is not None]
            if items:
                w = sum(_outer(k)[0] for k in items) + cw
                h = max(LINE_HEIGHT * scale, max(_outer(k)[1] for k in items)) + ch
        return (max(0.0, w), max(0.0, h))

    def _estimate(self, n: L.Node, v: ElementValues, el, font: float = FONT_SIZE) -> None:
        local = n.type
        measured = self.content_size(n, v, el, font)
        if measured is not None:  # measured as WPF's template does: no estimate to report
            n.estimate = measured
        elif local in _SHAPES or not is_presentation(qname(el.tag)[0]):
            n.estimate = (0.0, 0.0)  # shapes and images without a size: nothing to measure
            return
        else:
            n.estimate = self._estimated_size(n, v, el, font)
        w, h = n.estimate
        # a LayoutTransform is applied by the layout engine (layout/transform.py) to the
        # measured or estimated size alike
        unsized = n.width != n.width or n.height != n.height
        if measured is not None or not unsized or self.r.ctx.refused(el):
            return  # an unknown element is an error already: its estimate is no news
        what = f"{local} is not laid out by xaml3d"
        turned = ", then turned by its LayoutTransform" if n.layout_transform is not None else ""
        if self._beside_viewport(el):
            # the viewport's box depends on the guess: said without -v (LAY007)
            self.note("LAY007", f"{what}: its content size is estimated as {w:g} x {h:g}"
                      f"{turned}, and a Viewport3D in the same panel is placed by that "
                      "estimate (give the control a Width and Height)", el)  # fmt: skip
        else:
            self.note("LAY003", f"{what}: its content size is estimated as {w:g} x {h:g}"
                      f"{turned}", el)  # fmt: skip

    def _beside_viewport(self, el) -> bool:
        """Whether an estimated element shares a panel that lays out its children one after
        another (not a Canvas) with a Viewport3D: the viewport's room is then what the estimate
        leaves."""
        parent = el.getparent()
        while parent is not None and "." in qname(parent.tag)[1]:
            parent = parent.getparent()  # a property element: its owner is the panel
        return (parent is not None and id(parent) in self.holds_viewport
                and qname(parent.tag)[1] != "Canvas")  # fmt: skip


def _outer(k: L.Node) -> tuple[float, float]:
    """An estimated item's size with its margin: its Width/Height, else its estimate."""
    est = k.estimate or (0.0, 0.0)
    w = k.width if k.width == k.width else max(k.min_width, min(est[0], k.max_width))
    h = k.height if k.height == k.height else max(k.min_height, min(est[1], k.max_height))
    ml, mt, mr, mb = k.margin
    return w + ml + mr, h + mt + mb


def layout_transform_of(r, v: ElementValues):
    """An element's LayoutTransform as a 3x3 column-form matrix (the brushes' 2D Transform
    reader: Rotate, Scale, Skew, Translate, Matrix transforms and groups, a matrix string or a
    resource), or None when it has none (or it is unreadable: reported where it is read)."""
    if v.p is None or not v.p.has("LayoutTransform"):
        return None
    return v.p.obj(
        "LayoutTransform", lambda e: transform2d(r, e), None, from_string=transform2d_text
    )


def turns(m) -> bool:
    """Whether a LayoutTransform changes a box's size or shape (not the identity, not a move)."""
    return m is not None and not np.allclose(m[:2, :2], np.eye(2))


def _finite(x: float, default: float) -> float:
    return x if (x == x and math.isfinite(x) and x >= 0) else default


def _nonneg(x: float, default: float) -> float:
    return x if (x == x and x >= 0) else default


def _design(el, name: str) -> float | None:
    raw = el.get(f"{{{BLEND_NS}}}{name}")
    if raw is None:
        return None
    try:
        x = parse_length(raw)
    except ValueSyntaxError:
        return None
    return x if x == x and x >= 0 else None


def read_layout(r, root_el, viewport_elements: list, reader_type=PanelsReader):
    """(layout root or None, {viewport index: Node}, {id(node): (element, FontSize)}) for the
    document whose root is ``root_el``; None when the root takes no part in layout.
    ``reader_type``: the panel reader (a subclass measuring the controls' content)."""
    reader = reader_type(r, viewport_elements)
    root = reader.build(root_el)
    return root, reader.viewports, reader.elements
