"""The Aero2 templates of the controls that hold other elements, as layout parts (measure pass).

WPF lays a templated control out as the tree its ControlTemplate builds: borders, panels and
content presenters around the control's content. xaml3d builds the same tree of layout nodes
for the controls whose template places content, so their content is laid out and drawn inside
their chrome, beside the viewports (``render --window``) and inside visuals alike:

- TabControl: the row of TabItem headers (Padding 6,2,6,2; a #FFF0F0F0-#FFE5E5E5 face in a
  #FFACACAC border open at the bottom; the selected tab white, 2 px larger each side and above,
  drawn over its neighbours), then the selected tab's content in a white Border (#FFACACAC, 1 px)
  at Padding 2. SelectedIndex or IsSelected choose the tab; the first one otherwise.
- Menu: a #FFF0F0F0 Border (Menu.Static.Background) at Padding, its text #FF212121 at 12 px
  (the Style's Foreground and MenuFontSize), its items side by side (the
  ItemsPanel, a WrapPanel, on one row); each top-level MenuItem a transparent 1 px Border
  around its Header at Padding 6,0 (TopLevelHeaderTemplate; the Icon and check glyph columns
  are collapsed), its sub-items in the closed Popup (not shown). Any other item is wrapped in a
  MenuItem, as WPF's ItemContainerGenerator does; a Separator stays one.
- ToolBar (horizontal): the template's Grid at Margin 3,1,1,1; under the main panel the 15 px
  overflow button (#FFEEF5FD, its arrow in the disabled ToolBarGripper colour: nothing
  overflows), the main panel a #FFEEF5FD Border (CornerRadius 3) 11 px short of the right edge
  holding the 10 px grip (Thumb, Margin -3,-1,0,0, its dots at Padding 6,5,1,6), the Header at
  Margin 4,0,4,0 and the items side by side at Margin 0,1,2,2. Its Buttons (ToggleButton,
  RepeatButton, CheckBox, RadioButton alike) take ToolBar.ButtonStyleKey: transparent, a 1 px
  transparent border, Padding 2, centred; a checked one #400080FF in #80DADADA. A Separator
  takes ToolBar.SeparatorStyleKey: a 1 px #FFB6BDC5 line across the bar with Margin 2.
- ToolBarTray: #FFEEF5FD, its ToolBars side by side on one band.
- DatePicker (closed) and Calendar (month view): ``date_templates``.

A text Header of a GroupBox, Expander, TabItem or MenuItem is AccessText, as their templates'
ContentPresenter (RecognizesAccessKey) shows it: ``_Name`` shows Name (``text_content``); a
ToolBar's Header is not.

Part nodes (type ``#text``, ``#part``, ``#tabs``, ``#grip``) have no element of their own: a
``#text`` part carries its text's drawing, a ``#part`` its Background, BorderBrush,
BorderThickness and CornerRadius (painted as a Border's), ``#tabs`` is the header row whose
selected tab is drawn last (Panel.ZIndex 1), ``#grip`` a ToolBar's grip (its dots drawn once
its height is known: ``after_layout``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from xaml3d.access_text import access_text
from xaml3d.scene import element_tree as L
from xaml3d.scene.drawing import (
    DrawingGroup,
    GeometryDrawing,
    Pen,
    RectangleGeometry,
    TextDrawing,
)
from xaml3d.scene.text_runs import Run, TextContent
from xaml3d.scene.types import GradientStop, LinearGradientBrush
from xaml3d.xaml import values as V
from xaml3d.xaml.context import is_presentation, qname, split_markup
from xaml3d.xaml.geometry_reader import path_from_string
from xaml3d.xaml.panels_reader import ElementValues, parse_thickness
from xaml3d.xaml.text_content import holder_text, property_element
from xaml3d.xaml.visual_style import element_brush as _brush
from xaml3d.xaml.visual_style import font_style as _font_style
from xaml3d.xaml.visual_style import foreground_brush as _foreground
from xaml3d.xaml.visual_style import rgb as _rgb
from xaml3d.xaml.visual_text import warn_uncovered

TEXT_PART, PART, TABS_PART, GRIP_PART = "#text", "#part", "#tabs", "#grip"
_INLINES = {"Run", "Bold", "Italic", "Underline", "Span", "LineBreak", "Hyperlink"}
_OPTIONS = {"CheckBox", "RadioButton"}  # a ToolBar's: drawn as its parts
_HEADERED = {"TabControl", "TabItem"}
_MENUS = {"Menu", "MenuItem"}
_BARS = {"ToolBar", "ToolBarTray"}
_DATES = {"DatePicker", "Calendar"}  # expanded by date_templates (control_sizes calls it)
TEMPLATED = _OPTIONS | _HEADERED | _MENUS | _BARS | _DATES
TEMPLATED |= {"Button", "ToggleButton", "RepeatButton"}  # a ToolBar's: drawn as its parts
_ALIGN_H = ("Left", "Center", "Right", "Stretch")
_ALIGN_V = ("Top", "Center", "Bottom", "Stretch")

# Aero2's brushes for these templates ([[Aero2.NormalColor]])
_TAB_BORDER = _rgb("ACACAC")
_TAB_FACE = LinearGradientBrush(
    stops=(GradientStop((0xF0 / 255,) * 3 + (1.0,), 0.0),
           GradientStop((0xE5 / 255,) * 3 + (1.0,), 1.0)),
    start_point=(0.0, 0.0), end_point=(0.0, 1.0),
)  # fmt: skip
_WHITE = _rgb("FFFFFF")
_MENU_BAR = _rgb("F0F0F0")  # Menu.Static.Background
_MENU_TEXT = _rgb("212121")  # Menu.Static.Foreground
# Aero2's ToolBar brushes: ToolBarHorizontalBackground (and the tray's, the overflow button's),
# ToolBarGripper (also the disabled overflow arrow), ToolBarSeparatorFill, ToolBarButtonChecked
# and ToolBarButtonHoverBorder (a checked toggle's look)
_TOOL_BAR = _rgb("EEF5FD")
_GRIPPER = _rgb("6D6D6D")
_TOOL_SEPARATOR = _rgb("B6BDC5")
_TOOL_CHECKED = _rgb("0080FF", 0x40 / 255)
_TOOL_CHECKED_BORDER = _rgb("DADADA", 0x80 / 255)
_TOOL_BUTTONS = {"Button", "ToggleButton", "RepeatButton", "CheckBox", "RadioButton"}


def _elements(items) -> list:
    return [k for k in items if isinstance(k.tag, str)]


def rich_content(reader, el) -> list:
    """The element content of a content control (not inline text): what its presenter lays out."""
    kids = _elements(reader.content_of(el))
    if any(qname(k.tag)[1] not in _INLINES for k in kids):
        return kids
    return []


def expands(reader, el, local: str) -> bool:
    """Whether ``el`` is laid out through its template's parts (not as one measured box)."""
    if not is_presentation(qname(el.tag)[0]):
        return False
    return local in _HEADERED or local in _MENUS or local in _BARS or local in _DATES


def expand(reader, n: L.Node, el, v: ElementValues, font: float) -> None:
    """Turn the control node ``n`` into its template's tree (its kind and children change)."""
    local = n.type
    n.estimate = None
    if local in _TEMPLATES:
        _TEMPLATES[local](reader, n, el, v, font)
    else:  # a TabItem outside a TabControl: its header alone
        _tab_item(reader, n, el, v, font, False)


# --------------------------------------------------------------------------- parts


def part(reader, kind: str, font: float, children=(), type: str = PART, **fields) -> L.Node:
    n = L.Node(kind, type, **fields)
    n.children = [k for k in children if k is not None]
    reader.elements[id(n)] = (None, font)
    return n


def text_part(reader, owner, text: str, font: float) -> L.Node:
    """One line of ``text`` in the owner's font and Foreground, measured by layout in that
    font (``Node.text``)."""
    weight, italic, family = _font_style(owner, reader.r)
    n = part(reader, L.CONTROL, font, type=TEXT_PART)
    n.text = TextContent(Run(text, font, weight, italic, family))
    if text:
        warn_uncovered(reader.r, owner, text, weight, italic, family)
        n.drawing = TextDrawing(
            # set on its line's baseline as layout measured it (``after_layout``)
            text=text, origin=(0.0, 0.0), font_size=font, weight=weight,
            italic=italic, family=family, brush=_foreground(reader.r, owner),
            **reader.r.ctx.position(owner),
        )  # fmt: skip
    return n


def _presenter(reader, font, children, margin=(0.0,) * 4, h="Stretch", v="Stretch", **fields):
    return part(reader, L.CONTAINER, font, children, margin=margin, h_align=h, v_align=v,
                **fields)  # fmt: skip


def _build_all(reader, items, font) -> list:
    return [k for k in (reader.build(c, font) for c in items) if k is not None]


def _content(reader, el, font) -> list:
    """The laid-out content of a content control: its elements, else its text as one line."""
    from xaml3d.xaml.visual_text import text_of as _text_of

    kids = rich_content(reader, el)
    if kids:
        return _build_all(reader, kids, font)
    text = _text_of(el)
    return [text_part(reader, el, text, font)] if text else []


def _header(reader, el, font, access: bool = True) -> list:
    """A headered control's Header: its text (attribute or property element) or elements.
    ``access``: its template's ContentPresenter recognizes access keys (GroupBox, Expander,
    TabItem, MenuItem): a text header is AccessText (``xaml3d.access_text``)."""
    shown = access_text if access else str
    raw = el.get("Header")
    if raw is not None:
        if split_markup(raw) is not None:
            return []
        return [text_part(reader, el, shown(" ".join(raw.split())), font)]
    holder = property_element(el, "Header")
    if holder is not None:
        kids = _elements(holder)
        if kids:
            return _build_all(reader, kids, font)
        text = shown(holder_text(holder) or "")
        return [text_part(reader, el, text, font)] if text else []
    return []


def _align(v: ElementValues, h_default: str, v_default: str) -> tuple[str, str]:
    h = v.get("HorizontalContentAlignment", lambda s: V.parse_enum(s, _ALIGN_H), h_default)
    vv = v.get("VerticalContentAlignment", lambda s: V.parse_enum(s, _ALIGN_V), v_default)
    return h, vv


def _chrome(reader, n, v, background, border, thickness=(1.0,) * 4) -> None:
    """The control's own Border: its Background and BorderBrush (the Aero2 ones by default)."""
    r = reader.r
    n.kind = L.BORDER
    n.background = _brush(r, v, "Background", background)
    n.border_brush = _brush(r, v, "BorderBrush", border)
    default = thickness if n.border_brush is not None else (0.0,) * 4
    n.border = v.get("BorderThickness", parse_thickness, default)


# --------------------------------------------------------------------------- the templates


def _selected_index(v, items, el) -> int:
    index = v.get("SelectedIndex", V.parse_int, -1)
    if 0 <= index < len(items):
        return index
    for i, k in enumerate(items):
        if k.get("IsSelected") == "True":
            return i
    return -1


def _chosen_tab(r, tab_control, tabs) -> int:
    """The index of the tab a TabControl shows: SelectedIndex or IsSelected, else the first."""
    from xaml3d.xaml.panels_reader import style_setters

    v = ElementValues(r, tab_control, style_setters(r, tab_control, "TabControl"))
    chosen = _selected_index(v, tabs, tab_control)
    return 0 if chosen < 0 and tabs else chosen


def not_shown(r, el) -> str | None:
    """Why WPF does not show ``el`` (a Viewport3D): the nearest TabItem around it that its
    TabControl does not select, or Expander around it that is not IsExpanded (a Header is
    shown either way); None when neither holds it."""
    from xaml3d.xaml.panels_reader import style_setters

    node = el.getparent()
    while node is not None:
        ns, local = qname(node.tag)
        if local.endswith(".Header"):  # what a header holds is shown: skip its owner
            owner = node.getparent()
            node = None if owner is None else owner.getparent()
            continue
        if is_presentation(ns) and local == "TabItem":
            owner = node.getparent()
            if owner is not None and qname(owner.tag)[1].endswith(".Items"):
                owner = owner.getparent()
            if owner is not None and qname(owner.tag)[1] == "TabControl":
                tabs = [k for k in _elements(_items(owner)) if qname(k.tag)[1] == "TabItem"]
                chosen = _chosen_tab(r, owner, tabs)
                if node in tabs and tabs.index(node) != chosen:
                    header = node.get("Header")
                    named = f" {header!r}" if header is not None else ""
                    return f"in the TabItem{named} that its TabControl does not select"
        if is_presentation(ns) and local == "Expander":
            v = ElementValues(r, node, style_setters(r, node, "Expander"))
            if not v.get("IsExpanded", V.parse_bool, False):
                return "in an Expander whose IsExpanded is False"
        node = node.getparent()
    return None


def _items(owner) -> list:
    """A TabControl's items: its element children, and those of its Items property element."""
    out = []
    for k in _elements(owner):
        if qname(k.tag)[1].endswith(".Items"):
            out.extend(_elements(k))
        elif "." not in qname(k.tag)[1]:
            out.append(k)
    return out


def _tab_item(reader, n, el, v, font, selected: bool, h="Center", vv="Center") -> None:
    _chrome(reader, n, v, _WHITE if selected else _TAB_FACE, _TAB_BORDER, (1.0, 1.0, 1.0, 0.0))
    if selected:  # Aero2: the selected tab's white inner border covers the face
        n.background = _WHITE
        n.z_index = 1  # and it is 2 px larger each side and above (raise_selected_tabs)
    pad = v.get("Padding", parse_thickness, (6.0, 2.0, 6.0, 2.0))
    n.padding = (0.0,) * 4
    n.children = [_presenter(reader, font, _header(reader, el, font), pad, h, vv)]


def _tab_control(reader, n, el, v, font) -> None:
    from xaml3d.xaml.panels_reader import PanelsReader

    n.kind = L.GRID
    n.rows = (L.Definition("auto"), L.Definition("star"))
    n.columns = ()
    h, vv = _align(v, "Center", "Center")
    tabs = [k for k in _elements(reader.content_of(el)) if qname(k.tag)[1] == "TabItem"]
    chosen = _selected_index(v, tabs, el)
    chosen = 0 if chosen < 0 and tabs else chosen
    headers = []
    for i, tab in enumerate(tabs):
        k = PanelsReader.build(reader, tab, font)  # its header only: the content goes below
        if k is None:
            continue
        tv = ElementValues(reader.r, tab, reader.style_setters(tab, "TabItem"))
        k.estimate = None
        _tab_item(reader, k, tab, tv, font, i == chosen, h, vv)
        headers.append(k)
    strip = part(reader, L.STACK, font, headers, type=TABS_PART, orientation="Horizontal",
                 margin=(2.0, 2.0, 2.0, 0.0))  # fmt: skip
    content = []
    if 0 <= chosen < len(tabs):
        tab_font = reader.elements.get(id(headers[chosen]), (None, font))[1] if headers else font
        content = _content(reader, tabs[chosen], tab_font)
    pad = v.get("Padding", parse_thickness, (2.0,) * 4)
    panel = part(reader, L.BORDER, font, [_presenter(reader, font, content, pad)], row=1,
                 background=_brush(reader.r, v, "Background", _WHITE),
                 border_brush=_brush(reader.r, v, "BorderBrush", _TAB_BORDER),
                 border=v.get("BorderThickness", parse_thickness, (1.0,) * 4))  # fmt: skip
    n.children = [strip, panel]


def _menu(reader, n, el, v, font) -> None:
    from xaml3d.xaml.panels_reader import FONT_SIZE, parse_length

    # the Menu's Style sets FontSize to SystemFonts.MenuFontSize (12 px at 96 dpi): a size set
    # around the Menu does not reach its items, its own does
    font = v.get("FontSize", parse_length, FONT_SIZE)
    _chrome(reader, n, v, _MENU_BAR, None)
    n.padding = v.get("Padding", parse_thickness, (0.0,) * 4)
    rows = []
    for item in _elements(reader.content_of(el)):
        local = qname(item.tag)[1] if is_presentation(qname(item.tag)[0]) else ""
        if local in ("MenuItem", "Separator"):
            k = reader.build(item, font)
        else:  # WPF wraps any other item in a MenuItem, the item as its Header
            if not local and len(item) == 0:
                inner = [text_part(reader, el, access_text(" ".join((item.text or "").split())),
                                   font)]  # fmt: skip
            else:
                inner = _build_all(reader, [item], font)
            header = _presenter(reader, font, inner, (6.0, 0.0) * 2, v="Center")
            k = part(reader, L.BORDER, font, [header], border=(1.0,) * 4)
        if k is not None:
            rows.append(k)
    n.children = [part(reader, L.STACK, font, rows, orientation="Horizontal")]


def _menu_ink(reader, el):
    """A menu item's Foreground: its own or its Menu's (up to the Menu), else the Menu Style's
    #FF212121, which a Foreground set around the Menu does not override."""
    node = el
    while node is not None and isinstance(node.tag, str):
        p = reader.r.props(node)
        if any(k in p.attrs or k in p.elems for k in ("Foreground", "TextElement.Foreground")):
            return _foreground(reader.r, node)
        if qname(node.tag)[1] == "Menu":
            break
        node = node.getparent()
    return _MENU_TEXT


def _menu_item(reader, n, el, v, font) -> None:
    _chrome(reader, n, v, None, None)
    n.border = v.get("BorderThickness", parse_thickness, (1.0,) * 4)
    n.padding = (0.0,) * 4
    pad = v.get("Padding", parse_thickness, (6.0, 0.0, 6.0, 0.0))
    header = _header(reader, el, font)  # AccessText: its access-key marker is not shown
    ink = _menu_ink(reader, el)
    for k in header:
        if k.type == TEXT_PART and k.drawing is not None:
            k.drawing = replace(k.drawing, brush=ink)
    n.children = [_presenter(reader, font, header, pad, "Left", "Center")]


def _tool_bar(reader, n, el, v, font) -> None:
    from xaml3d.xaml.panels_reader import PanelsReader

    _chrome(reader, n, v, None, None)
    n.border = (0.0,) * 4
    n.padding = (3.0, 1.0, 1.0, 1.0)  # the template's Grid Margin
    arrow = part(reader, L.CONTROL, font, estimate=(6.0, 7.0), margin=(7.0, 2.0, 2.0, 2.0),
                 h_align="Right", v_align="Bottom")  # fmt: skip
    arrow.drawing = _overflow_arrow()
    overflow = part(reader, L.BORDER, font, [arrow], background=_TOOL_BAR, h_align="Right",
                    corner_radius=(3.0,) * 4)  # fmt: skip
    locked = _locked(el)
    grip = part(
        reader,
        L.CONTROL,
        font,
        type=GRIP_PART,
        estimate=(0.0, 11.0),
        width=10.0,
        margin=(-3.0, -1.0, 0.0, 0.0),
        visibility="Collapsed" if locked else "Visible",
    )
    kids = [grip]
    header = _header(reader, el, font, access=False)
    if header:
        kids.append(_presenter(reader, font, header, (4.0, 0.0, 4.0, 0.0), "Center", "Center"))
    items = []
    for item in _elements(reader.content_of(el)):
        local = qname(item.tag)[1] if is_presentation(qname(item.tag)[0]) else ""
        if local in _TOOL_BUTTONS:
            k = PanelsReader.build(reader, item, font)  # restyled: ToolBar.ButtonStyleKey
            if k is not None:
                _tool_button(reader, k, item, font)
        elif local == "Separator":
            k = PanelsReader.build(reader, item, font)
            if k is not None:
                k.estimate = None
                _tool_separator(reader, k, item)
        else:
            k = reader.build(item, font)
        if k is not None:
            items.append(k)
    kids.append(part(reader, L.STACK, font, items, orientation="Horizontal",
                     margin=(0.0, 1.0, 2.0, 2.0)))  # fmt: skip
    main = part(reader, L.BORDER, font, [part(reader, L.DOCK, font, kids)],
                background=_brush(reader.r, v, "Background", _TOOL_BAR),
                border_brush=_brush(reader.r, v, "BorderBrush", None),
                border=v.get("BorderThickness", parse_thickness, (0.0,) * 4),
                padding=v.get("Padding", parse_thickness, (0.0,) * 4),
                corner_radius=(3.0,) * 4, margin=(0.0, 0.0, 11.0, 0.0))  # fmt: skip
    n.children = [part(reader, L.GRID, font, [overflow, main])]


def _locked(el) -> bool:
    """ToolBarTray.IsLocked, on the ToolBar or (inherited) on its tray: the grip is hidden."""
    for e in (el, el.getparent()):
        if e is not None and (e.get("ToolBarTray.IsLocked") or e.get("IsLocked")) == "True":
            return True
    return False


def _tool_button(reader, k, el, font) -> None:
    """A button on a ToolBar (ToolBar.ButtonStyleKey / ToggleButtonStyleKey): a transparent
    1 px border at Padding 2 around its content, centred in the bar; checked: #400080FF."""
    kv = ElementValues(reader.r, el, reader.style_setters(el, k.type))
    checked = kv.get("IsChecked", V.parse_bool, False) if k.type != "Button" else False
    k.estimate = None
    k.kind = L.BORDER
    k.background = _brush(reader.r, kv, "Background", _TOOL_CHECKED if checked else None)
    k.border_brush = _brush(reader.r, kv, "BorderBrush",
                            _TOOL_CHECKED_BORDER if checked else None)  # fmt: skip
    k.border = kv.get("BorderThickness", parse_thickness, (1.0,) * 4)
    k.padding = kv.get("Padding", parse_thickness, (2.0,) * 4)
    if el.get("HorizontalAlignment") is None:
        k.h_align = "Center"
    if el.get("VerticalAlignment") is None:
        k.v_align = "Center"
    h, vv = _align(kv, "Center", "Center")
    k.children = [_presenter(reader, font, _content(reader, el, font), h=h, v=vv)]


def _tool_separator(reader, k, el) -> None:
    """ToolBar.SeparatorStyleKey: a 1 px #FFB6BDC5 Border with Margin 2, across the bar."""
    sv = ElementValues(reader.r, el, reader.style_setters(el, "Separator"))
    k.kind = L.BORDER
    k.type = PART  # drawn as its Border (not as a menu or panel Separator)
    k.background = _brush(reader.r, sv, "Background", _TOOL_SEPARATOR)
    k.margin = sv.get("Margin", parse_thickness, (2.0,) * 4)
    k.min_width = max(k.min_width, 1.0)
    k.min_height = max(k.min_height, 1.0)
    reader.elements[id(k)] = (None, reader.elements.get(id(k), (None, 12.0))[1])


def _tool_bar_tray(reader, n, el, v, font) -> None:
    _chrome(reader, n, v, _TOOL_BAR, None)
    n.border = (0.0,) * 4
    bars = _build_all(reader, _elements(reader.content_of(el)), font)
    n.children = [part(reader, L.STACK, font, bars, orientation="Horizontal")]


def _overflow_arrow() -> DrawingGroup:
    """The overflow button's 6 x 7 arrow (a bar over a triangle, each with a white copy 1 px
    down and right), in ToolBarGripper's colour as the button is disabled at rest."""
    white_bar = path_from_string("M 1 1.5 L 6 1.5")
    bar = path_from_string("M 0 0.5 L 5 0.5")
    return DrawingGroup(children=(
        GeometryDrawing(white_bar, pen=Pen(brush=_WHITE, thickness=1.0)),
        GeometryDrawing(bar, pen=Pen(brush=_GRIPPER, thickness=1.0)),
        GeometryDrawing(path_from_string("M 0.5 4 L 6.5 4 L 3.5 7 Z"), brush=_WHITE),
        GeometryDrawing(path_from_string("M -0.5 3 L 5.5 3 L 2.5 6 Z"), brush=_GRIPPER),
    ))  # fmt: skip


def _grip_dots(w: float, h: float) -> DrawingGroup:
    """The ToolBar Thumb's Rectangle (at Padding 6,5,1,6) filled with its 4 x 4 tile: a
    ToolBarGripper dot at 0,0 over a white one at 1,1, 2 px each, cut at the rectangle."""
    x0, y0 = 6.0, 5.0
    rw, rh = max(0.0, w - 7.0), max(0.0, h - 11.0)
    out = []
    for top in np.arange(0.0, rh, 4.0):  # one dot a tile: a few per bar, not per pixel
        for dx, dy, brush in ((1.0, 1.0, _WHITE), (0.0, 0.0, _GRIPPER)):
            x, y = dx, top + dy
            cw, ch = min(2.0, rw - x), min(2.0, rh - y)
            if cw > 0 and ch > 0:
                out.append(GeometryDrawing(RectangleGeometry((x0 + x, y0 + y, cw, ch)),
                                           brush=brush))  # fmt: skip
    return DrawingGroup(children=tuple(out))


def after_layout(root: L.Node) -> None:
    """The template parts drawn from their laid-out size: the selected tabs raised, the grips'
    dots, a text part's line on the baseline layout measured (``Node.text_lines``)."""
    raise_selected_tabs(root)
    for n in root.walk():
        if n.type == GRIP_PART and n.arranged:
            n.drawing = _grip_dots(*n.ink)
        elif n.type == TEXT_PART and isinstance(n.drawing, TextDrawing) and n.text_lines:
            n.drawing = replace(n.drawing, origin=(0.0, n.text_lines[0].baseline))


def raise_selected_tabs(root: L.Node) -> None:
    """After layout, the selected TabItem as Aero2 shows it: its Margin -2,-2,-2,0 makes it
    2 px larger each side and above the cell the TabPanel gives it (the TabPanel places the tabs
    by their size without margins, so its neighbours keep their places), and Panel.ZIndex 1
    draws it over them. Its centred header moves with its box's centre (1 px up)."""
    for n in root.walk():
        if n.type != TABS_PART:
            continue
        for k in n.children:
            if k.z_index > 0 and k.arranged:
                x, y, w, h = k.rect
                k.rect = (x - 2.0, y - 2.0, w + 4.0, h + 2.0)
                k.ink = (k.ink[0] + 4.0, k.ink[1] + 2.0)
                for d in list(k.walk())[1:]:
                    dx, dy, dw, dh = d.rect
                    d.rect = (dx, dy - 1.0, dw, dh)
        n.children.sort(key=lambda k: k.z_index)  # stable: document order otherwise


# the controls whose template tree ``expand`` builds by name (a MenuItem here is a top-level
# item: its sub-items are in a closed Popup)
_TEMPLATES = {
    "TabControl": _tab_control,
    "Menu": _menu,
    "ToolBar": _tool_bar,
    "ToolBarTray": _tool_bar_tray,
    "MenuItem": _menu_item,
}
