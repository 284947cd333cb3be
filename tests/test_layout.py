"""Exact layout numbers (xaml3d.layout): WPF's measure/arrange of each panel, the window frame,
rounding, the gotchas, and the panels reader on markup."""

from __future__ import annotations

import math

import pytest

import xaml3d
from xaml3d.layout import layout
from xaml3d.layout.engine import scale_factor
from xaml3d.layout.gotchas import viewport_notes
from xaml3d.layout.grid import distribute, round_sizes
from xaml3d.pipeline import load
from xaml3d.scene import element_tree as L
from xaml3d.scene.element_tree import Definition, Node

NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
LINE = 2724 / 2048 * 12  # one line of text at 12 px: Segoe UI's LineSpacing x FontSize


def vp(**kw) -> Node:
    return Node(L.VIEWPORT, "Viewport3D", viewport=0, **kw)


def D(spec: str, **kw) -> Definition:
    if spec == "Auto":
        return Definition("auto", 1.0, **kw)
    if spec.endswith("*"):
        return Definition("star", float(spec[:-1] or 1), **kw)
    return Definition("pixel", float(spec), **kw)


def window(child, w=800, h=600, **kw) -> Node:
    return Node(L.WINDOW, "Window", width=w, height=h, children=[child], **kw)


def test_window_toolbar_row_and_star_row():
    v = vp(row=1)
    bar = Node(L.CONTROL, "ToolBar", height=40, estimate=(0, 0))
    grid = Node(L.GRID, "Grid", rows=(D("Auto"), D("*")), children=[bar, v])
    r = layout(window(grid))
    assert r.client == (784, 561)
    assert v.rect == (0, 40, 784, 521)
    assert v.slot == "row 1 (*)"


def test_two_star_columns_of_a_user_control():
    a, b = vp(col=0), vp(col=1)
    grid = Node(L.GRID, "Grid", columns=(D("*"), D("*")), children=[a, b])
    layout(Node(L.USER_CONTROL, "UserControl", width=600, height=300, children=[grid]))
    assert a.rect == (0, 0, 300, 300) and b.rect == (300, 0, 300, 300)


def test_grid_pixel_auto_star_mix_and_weights():
    kids = [vp(row=i) for i in range(4)]
    kids[1].height = 30  # sizes the Auto row
    grid = Node(L.GRID, "Grid", rows=(D("50"), D("Auto"), D("*"), D("2*")), children=kids)
    layout(Node(L.GRID, "Grid", width=300, height=380, children=[grid]))
    assert [k.rect[1] for k in kids] == [0, 50, 80, 180]
    assert [k.rect[3] for k in kids] == [50, 30, 100, 200]


def test_star_min_and_max():
    a, b = vp(col=0), vp(col=1)
    grid = Node(L.GRID, "Grid", columns=(D("*", max=100), D("*")), children=[a, b],
                width=500, height=10)  # fmt: skip
    layout(grid)
    assert (a.rect[2], b.rect[2]) == (100, 400)
    a.width = math.nan
    grid.columns = (D("*", min=400), D("*"))
    layout(grid)
    assert (a.rect[2], b.rect[2]) == (400, 100)
    assert distribute([1, 1, 2], [0, 0, 0], [math.inf] * 3, 100) == [25, 25, 50]


def test_grid_spans_and_out_of_range_indices():
    a = vp(row=0, col=0, col_span=2)
    b = vp(row=5, col=-1)  # clamped to the last row, first column
    grid = Node(L.GRID, "Grid", rows=(D("100"), D("*")), columns=(D("*"), D("3*")),
                children=[a, b], width=400, height=300)  # fmt: skip
    layout(grid)
    assert a.rect == (0, 0, 400, 100)
    assert b.rect == (0, 100, 100, 200)


def test_spanning_cell_grows_the_auto_definitions():
    c = Node(L.CONTROL, "Button", estimate=(0, 0), height=90, col_span=2, row=0)
    v = vp(row=0, col=0)
    grid = Node(L.GRID, "Grid", rows=(D("Auto"),), columns=(D("Auto"), D("Auto")),
                children=[c, v], row_span=1)  # fmt: skip
    c.row_span, c.col_span = 1, 1
    layout(Node(L.BORDER, "Border", width=200, height=200, children=[grid]))
    assert v.rect[3] == 90


def _defs(*specs, constraint=500.0):
    from xaml3d.layout.grid import _Defs

    return _Defs(tuple(D(x) for x in specs), constraint)


def test_span_within_preferred_sizes_grows_the_star_not_the_auto():
    # WPF's EnsureMinSizeInDefinitionRange: Auto definitions stay tight while the others'
    # preferred sizes (a resolved star: its share) can hold the spanning cell
    d = _defs("Auto", "*")
    d.min = [16.0, 0.0]
    d.resolve_star_measure(640.0)
    assert d.measure[1] == 624.0
    d.ensure_min(0, 2, 217.0)
    assert d.min == [16.0, 201.0]


def test_span_beyond_preferred_sizes_fills_non_auto_first():
    # a star measured with infinite room acts as Auto for sizing, but is not a markup Auto:
    # it takes the growth, the markup Auto stays tight
    d = _defs("Auto", "*", constraint=math.inf)
    d.min = [16.0, 200.0]
    d.ensure_min(0, 2, 217.0)
    assert d.min == [16.0, 201.0]
    # two markup Autos share it equally
    d = _defs("Auto", "Auto", constraint=math.inf)
    d.min = [10.0, 20.0]
    d.ensure_min(0, 2, 60.0)
    assert d.min == [25.0, 35.0]
    # a pixel column is not Auto: WPF grows its minimum (and so its arranged size)
    d = _defs("100", "Auto")
    d.ensure_min(0, 2, 150.0)
    assert d.min == [150.0, 0.0]


def test_span_beyond_maximums_grows_smaller_definitions_faster():
    from xaml3d.layout.grid import _Defs

    d = _Defs((Definition("auto", 1.0, max=50.0), Definition("auto", 1.0, max=200.0)), math.inf)
    d.ensure_min(0, 2, 300.0)
    assert d.min == [100.0, 200.0]
    d = _Defs((Definition("auto", 1.0, max=50.0), Definition("auto", 1.0, max=100.0)), math.inf)
    d.ensure_min(0, 2, 300.0)
    assert d.min == [150.0, 150.0]


def test_grid_cycle_auto_column_star_row_and_span_over_auto_and_star():
    # Auto | * columns, Auto / * / Auto rows in a DockPanel (finite room: the star is a real
    # star). The header spans both columns (217 px): WPF puts the extra into the star column,
    # so the Grid is 217 wide, not 16 + 217; the 16 px cell in the star row sizes the Auto
    # column (WPF's group 2 / group 3 cycle).
    head = Node(L.CONTROL, "Rectangle", width=217, height=16, col_span=2, estimate=(0, 0))
    big = Node(L.CONTROL, "Rectangle", width=200, height=200, row=1, col=1, estimate=(0, 0))
    side = Node(L.CONTROL, "Rectangle", width=16, height=150, row=1, col=0, estimate=(0, 0))
    foot = Node(L.CONTROL, "Rectangle", width=161, height=16, row=2, col=1, estimate=(0, 0))
    grid = Node(L.GRID, "Grid", rows=(D("Auto"), D("*"), D("Auto")), columns=(D("Auto"), D("*")),
                children=[head, big, side, foot], dock="Left")  # fmt: skip
    v = vp()
    page = Node(L.PAGE, "Page", width=640, height=480,
                children=[Node(L.DOCK, "DockPanel", children=[grid, v])])  # fmt: skip
    r = layout(page)
    assert grid.desired == (217.0, 232.0)  # the sums of the minimums
    assert v.rect == (217.0, 0.0, 423.0, 480.0)
    # column 0 is 16, column 1 201: the 200 px square sits centred in it
    assert side.rect[2] == 16.0 and big.rect[0] == 16.5
    # the side cell is measured twice (infinite height, then its star row's height), as in
    # WPF; the loop's repeat with an unchanged size is skipped
    assert r.measure_calls == r.arrange_calls + 1


def test_border_margin_padding():
    v = vp()
    border = Node(L.BORDER, "Border", margin=(10, 10, 10, 10), border=(2, 2, 2, 2),
                  padding=(5, 5, 5, 5), children=[v])  # fmt: skip
    layout(window(border, 416, 339))  # client 400 x 300
    assert border.rect == (10, 10, 380, 280)
    assert v.rect == (17, 17, 366, 266)


def test_dockpanel_sides_and_fill():
    top = Node(L.CONTROL, "Menu", height=20, estimate=(50, 16), dock="Top")
    left = Node(L.CONTROL, "ListBox", width=120, estimate=(0, 0), dock="Left")
    bottom = Node(L.CONTROL, "StatusBar", height=24, estimate=(0, 0), dock="Bottom")
    v = vp()
    dock = Node(L.DOCK, "DockPanel", children=[top, left, bottom, v])
    layout(window(dock))
    assert top.rect == (0, 0, 784, 20)
    assert left.rect == (0, 20, 120, 541)
    assert bottom.rect == (120, 537, 664, 24)
    assert v.rect == (120, 20, 664, 517)
    assert v.slot == "the remaining space (LastChildFill)"


def test_dockpanel_without_last_child_fill_docks_the_viewport_left():
    v = vp()
    layout(window(Node(L.DOCK, "DockPanel", last_child_fill=False, children=[v])))
    assert v.rect[2] == 0
    (note,) = viewport_notes([v])
    assert note.code == "LAY001" and "docked Left" in note.message


def test_stackpanel_gotcha_and_sized_item():
    v, w = vp(), vp(height=200)
    w.viewport = 1
    stack = Node(L.STACK, "StackPanel", children=[v, w])
    layout(window(stack))
    assert v.rect == (0, 0, 784, 0)
    assert w.rect == (0, 0, 784, 200)
    notes = viewport_notes([v, w])
    assert len(notes) == 1 and "vertical StackPanel" in notes[0].message
    h = vp(width=100)
    layout(window(Node(L.STACK, "StackPanel", orientation="Horizontal", children=[h])))
    assert h.rect == (0, 0, 100, 561)


def test_canvas_positions_and_gotcha():
    a = vp(width=100, height=50, left=10, top=20)
    b = vp(width=30, height=30, right=5, bottom=5)
    c = vp()
    canvas = Node(L.CANVAS, "Canvas", children=[a, b, c], width=200, height=100)
    layout(canvas)
    assert a.rect == (10, 20, 100, 50)
    assert b.rect == (165, 65, 30, 30)
    assert c.rect[2:] == (0, 0)
    assert "Canvas" in viewport_notes([c])[0].message


@pytest.mark.parametrize(
    ("stretch", "direction", "expected"),
    [
        ("Uniform", "Both", (2.0, 2.0)),
        ("UniformToFill", "Both", (4.0, 4.0)),
        ("Fill", "Both", (2.0, 4.0)),
        ("None", "Both", (1.0, 1.0)),
        ("Uniform", "DownOnly", (1.0, 1.0)),
    ],
)
def test_viewbox_scale(stretch, direction, expected):
    assert scale_factor((200, 200), (100, 50), stretch, direction) == expected


def test_viewbox_scales_the_viewport_and_unsized_gotcha():
    v = vp(width=400, height=300)
    box = Node(L.VIEWBOX, "Viewbox", children=[v])
    layout(Node(L.GRID, "Grid", width=200, height=200, children=[box]))
    assert box.rect == (0, 25, 200, 150)
    assert v.rect == (0, 25, 200, 150)
    v.width = v.height = math.nan
    layout(Node(L.GRID, "Grid", width=200, height=200, children=[box]))
    assert v.rect[2:] == (0, 0) and "Viewbox" in viewport_notes([v])[0].message


def test_scrollviewer_fills_the_view_beside_the_vertical_bar():
    v = vp()
    layout(window(Node(L.SCROLL, "ScrollViewer", children=[v])))
    assert v.rect == (0, 0, 784 - 17, 561)


def test_alignment_margin_min_max():
    v = vp(width=100, height=80, h_align="Right", v_align="Top", margin=(0, 10, 20, 0))
    layout(Node(L.GRID, "Grid", width=300, height=200, children=[v]))
    assert v.rect == (180, 10, 100, 80)
    c = vp(max_width=150, min_height=250)  # Stretch but capped: centred in the slot
    layout(Node(L.GRID, "Grid", width=300, height=200, children=[c]))
    assert c.rect == (75, 0, 150, 250)


def test_collapsed_takes_no_room_hidden_keeps_it():
    bar = Node(L.CONTROL, "ToolBar", height=40, estimate=(0, 0), visibility="Collapsed")
    v = vp(row=1)
    grid = Node(L.GRID, "Grid", rows=(D("Auto"), D("*")), children=[bar, v])
    layout(window(grid))
    assert v.rect == (0, 0, 784, 561)
    hid = vp(visibility="Hidden")
    layout(window(Node(L.GRID, "Grid", children=[hid])))
    assert hid.rect[2:] == (784, 561)
    assert viewport_notes([hid])[0].code == "LAY002"
    gone = vp()
    layout(window(Node(L.GRID, "Grid", visibility="Collapsed", children=[gone])))
    (note,) = viewport_notes([gone])
    assert note.code == "LAY002" and "Collapsed" in note.message


def test_size_to_content_and_window_size_override():
    v = vp(width=300, height=200)
    r = layout(window(Node(L.GRID, "Grid", children=[v]), size_to_content="WidthAndHeight"))
    assert r.client == (300, 200)
    v2 = vp()
    r = layout(window(Node(L.GRID, "Grid", children=[v2])), (1000, 500))
    assert r.client == (1000, 500) and v2.rect == (0, 0, 1000, 500)


def test_layout_rounding():
    a, b, c = vp(col=0), vp(col=1), vp(col=2)
    grid = Node(L.GRID, "Grid", columns=(D("*"),) * 3, children=[a, b, c], width=100,
                height=10, rounding=True)  # fmt: skip
    layout(grid)
    widths = [k.rect[2] for k in (a, b, c)]
    assert sum(widths) == 100 and all(w == int(w) for w in widths)
    grid.rounding = None
    layout(grid)
    assert a.rect[2] == pytest.approx(100 / 3)
    assert (
        round_sizes([33.5, 33.5, 33.0]) == [34.0, 33.0, 33.0]
        or sum(round_sizes([33.5, 33.5, 33.0])) == 100
    )


def test_every_element_measured_and_arranged_once():
    # 10 000 panels: a chain of nested Borders 200 deep, each holding 49 sized leaves
    root = Node(L.GRID, "Grid", width=800, height=600)
    node, count = root, 1
    while count < 10_000:
        inner = Node(L.BORDER, "Border", margin=(0.01, 0, 0, 0))
        leaves = [Node(L.CONTROL, "TextBlock", estimate=(5, 5)) for _ in range(48)]
        holder = Node(L.GRID, "Grid", children=[*leaves, inner])
        node.children.append(holder)
        node, count = inner, count + 50
    node.children.append(vp())
    r = layout(root)
    assert r.measure_calls == r.arrange_calls == count + 1


def test_root_defaults_and_design_size():
    v = vp()
    r = layout(Node(L.GRID, "Grid", children=[v]))
    assert r.client == (640, 480) and "default" in r.how
    uc = Node(L.USER_CONTROL, "UserControl", design_size=(300, 200), children=[vp()])
    assert layout(uc).client == (300, 200)


# ------------------------------------------------------------------ reader on markup


def size(xaml: str, i: int = 0, **kw):
    s = load(xaml, text=True, **kw)
    v = s.viewports[i]
    return v.width, v.height


def test_markup_window_toolbar_example():
    x = (
        f"<Window {NS} Width='800' Height='600'><Grid><Grid.RowDefinitions>"
        "<RowDefinition Height='Auto'/><RowDefinition/></Grid.RowDefinitions>"
        "<ToolBar Height='40'/><Viewport3D Grid.Row='1'/></Grid></Window>"
    )
    assert size(x) == (784, 521)
    assert size(x, window_size=(1000, 700)) == (1000, 660)


def test_markup_window_without_caption_or_frame():
    def win(attrs: str) -> str:
        return (f"<Window {NS} Width='816' Height='639' {attrs}><Grid><Grid.RowDefinitions>"
                "<RowDefinition Height='40'/><RowDefinition/></Grid.RowDefinitions>"
                "<Viewport3D Grid.Row='1'/></Grid></Window>")  # fmt: skip

    assert size(win("")) == (800, 560)
    assert size(win("WindowStyle='None'")) == (800, 583)  # the resize border stays
    assert size(win("WindowStyle='None' ResizeMode='NoResize'")) == (816, 599)
    assert size(win("WindowStyle='None' AllowsTransparency='True'")) == (816, 599)


def test_markup_values_units_and_bad_values():
    x = (
        f"<Grid {NS} Width='1in' Height='2cm' UseLayoutRounding='True'>"
        "<Viewport3D Margin='4,2' Grid.Row='{Binding R}'/></Grid>"
    )
    w, h = size(x)
    assert (w, h) == (96 - 8, round(96 / 2.54 * 2) - 4)
    s = load(f"<Grid {NS} Width='100' Height='50'><Viewport3D Margin='1,2,3'/></Grid>", text=True)
    assert (s.viewports[0].width, s.viewports[0].height) == (100, 50)
    assert "VAL003" in {d.code for d in s.diagnostics}


def test_markup_gotcha_is_located_warning():
    s = load(f"<StackPanel {NS} Width='100' Height='100'>\n  <Viewport3D/></StackPanel>", text=True)
    (d,) = [d for d in s.diagnostics if d.code == "LAY001"]
    assert (d.severity, d.line, d.column) == ("warning", 2, 3)
    assert "vertical StackPanel" in d.message


def test_markup_control_measured_and_estimate_is_info():
    # a Button's text is measured with the font (one 15.96 px line of Segoe UI at 12 px) inside
    # Aero2's 1 px border and Padding 1: 19.96 px, as WPF sizes it; nothing is estimated
    x = (
        f"<DockPanel {NS} Width='300' Height='200'>"
        "<Button DockPanel.Dock='Top'>Go</Button><Viewport3D/></DockPanel>"
    )
    s = load(x, text=True)
    assert (s.viewports[0].width, s.viewports[0].height) == (300, 200 - (2724 / 2048 * 12 + 4))
    assert not any(d.code == "LAY003" for d in s.diagnostics)
    # a control whose template xaml3d does not know is estimated (16 px line), and says so
    s = load(x.replace("<Button DockPanel.Dock='Top'>Go</Button>",
                       "<TreeView DockPanel.Dock='Top'/>"), text=True)  # fmt: skip
    assert (s.viewports[0].width, s.viewports[0].height) == (300, 200 - 16)
    # ... and as the viewport shares its DockPanel, the guess places the viewport: a warning
    (d,) = [d for d in s.diagnostics if d.code in ("LAY003", "LAY007")]
    assert (d.code, d.severity) == ("LAY007", "warning")
    assert d.message.startswith(
        "TreeView is not laid out by xaml3d: its content size is "
        "estimated as 0 x 16, and a Viewport3D in the same panel"
    )


def test_a_date_picker_beside_the_viewport_is_measured_as_aero2s():
    from xaml3d.text_metrics import line_height, text_width

    # its 1 px border and Padding 2, the watermark "Select a date" in a 1 px border at Padding
    # 2 (always measured), the 20 px calendar button at Margin 3,0,3,0: 27.96 px tall
    s = load(f"<DockPanel {NS} Width='400' Height='200'><DatePicker DockPanel.Dock='Left'/>"
             "<Viewport3D/></DockPanel>", text=True)  # fmt: skip
    width = 3 + text_width("Select a date", 12.0) + 6 + 26 + 3
    assert s.viewports[0].width == pytest.approx(400 - width)
    assert not [d for d in s.diagnostics if d.code in ("LAY003", "LAY007", "DRW007")]
    # a long date wider than the watermark widens it; the height stays
    s = load(f"<DockPanel {NS} Width='400' Height='200'><DatePicker DockPanel.Dock='Top' "
             "SelectedDate='2024-01-05' SelectedDateFormat='Long'/><Viewport3D/></DockPanel>",
             text=True)  # fmt: skip
    assert s.viewports[0].height == pytest.approx(200 - (line_height(12.0) + 12))


def test_a_menu_above_the_viewport_is_measured_as_aero2s():
    from xaml3d.text_metrics import line_height

    # the bar is one line of menu text in the items' 1 px borders: 17.96 px, as WPF's
    s = load(f"<DockPanel {NS} Width='300' Height='200'><Menu DockPanel.Dock='Top'>"
             "<MenuItem Header='_File'/><MenuItem Header='Edit'/></Menu><Viewport3D/>"
             "</DockPanel>", text=True)  # fmt: skip
    assert (s.viewports[0].width, s.viewports[0].height) == (300, 200 - (line_height(12.0) + 2))
    assert not [d for d in s.diagnostics if d.code in ("LAY003", "LAY007", "DRW007")]
    # the Menu's Style sets SystemFonts.MenuFontSize (12 px): a size set around it stays out,
    # its own applies
    for around, own, size in (("TextElement.FontSize='20'", "", 12.0), ("", "FontSize='20'", 20.0)):
        s = load(f"<DockPanel {NS} Width='300' Height='200' {around}><Menu {own} "
                 "DockPanel.Dock='Top'><MenuItem Header='File'/></Menu><Viewport3D/></DockPanel>",
                 text=True)  # fmt: skip
        assert s.viewports[0].height == 200 - (line_height(size) + 2)


def test_a_calendar_beside_the_viewport_is_measured_as_aero2s_month_view():
    from xaml3d.text_metrics import line_height, text_width
    from xaml3d.xaml.date_templates import month_days

    s = load(f"<DockPanel {NS} Width='400' Height='300'><Calendar DockPanel.Dock='Left' "
             "DisplayDate='2024-01-05'/><Viewport3D/></DockPanel>", text=True)  # fmt: skip
    assert not [d for d in s.diagnostics if d.code in ("LAY003", "LAY007", "DRW007")]
    # the month grid: each column as wide as its day name (bold 9.5 px) or its widest day
    # button (10 px text at Margin 5,1,5,1); 6 weeks from Sunday 31 December 2023
    days = month_days(__import__("datetime").date(2024, 1, 5))
    assert days[0].isoformat() == "2023-12-31" and len(days) == 42
    names = ("Su", "Mo", "Tu", "We", "Th", "Fr", "Sa")
    cols = [max([text_width(names[c], 9.5, 700)]
                + [text_width(str(d.day), 10.0) + 10 for d in days[c::7]])
            for c in range(7)]  # fmt: skip
    header = 28 + text_width("January 2024", 10.5, 700) + 2 + 28
    # the 1 px border and the 2 px white one each side, the grid's Margin 6,-1,6,6
    width = 6 + max(header, sum(cols) + 12)
    assert s.viewports[0].width == pytest.approx(400 - width)
    # and docked at the top: CalendarItem's Margin 0,3,0,3, the header row (20 px buttons or
    # the title at Margin 1,4,1,9), the day names at Margin 0,6,0,6, 6 rows of day buttons
    s = load(f"<DockPanel {NS} Width='400' Height='300'><Calendar DockPanel.Dock='Top' "
             "DisplayDate='2024-01-05'/><Viewport3D/></DockPanel>", text=True)  # fmt: skip
    height = (3 + 3 + max(20, 4 + line_height(10.5) + 9) - 1 + 12 + line_height(9.5)
              + 6 * (line_height(10.0) + 2) + 6 + 3 + 3)  # fmt: skip
    assert s.viewports[0].height == pytest.approx(300 - height)


def test_estimate_beside_viewport_is_a_warning_and_drawn_controls_say_so():
    # a TreeView docked left of the viewport: its guessed width is the viewport's room
    x = (f"<DockPanel {NS} Width='400' Height='200'>"
         "<TreeView DockPanel.Dock='Left'/><Viewport3D/></DockPanel>")  # fmt: skip
    s = load(x, text=True)
    assert [(d.code, d.severity) for d in s.diagnostics if d.code.startswith("LAY")] == [
        ("LAY007", "warning")
    ]
    # a ProgressBar is laid out as its theme template's instance: nothing estimated
    s = load(f"<Canvas {NS} Width='400' Height='200'><ProgressBar/>"
             "<Viewport3D Width='10' Height='10'/></Canvas>", text=True)  # fmt: skip
    assert not [d for d in s.diagnostics if d.code.startswith("LAY")]


XNS = 'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'


def _dock_left(left: str, resources: str = "") -> str:
    return (
        f"<Page {NS} {XNS} Width='640' Height='480'><Page.Resources>{resources}</Page.Resources>"
        f"<DockPanel>{left}<Viewport3D/></DockPanel></Page>"
    )


def test_markup_style_setters_size_elements():
    base = "<Style x:Key='B' TargetType='Border'><Setter Property='MinWidth' Value='100'/></Style>"
    keyed = (
        "<Style x:Key='S' TargetType='{x:Type Border}' BasedOn='{StaticResource B}'>"
        "<Setter Property='Border.Width' Value='300'/><Setter Property='Grid.Column' Value='9'/>"
        "<Style.Triggers><Trigger Property='IsMouseOver' Value='True'>"
        "<Setter Property='Width' Value='50'/></Trigger></Style.Triggers></Style>"
    )
    # a keyed Style (its Trigger's Setter applies only when it fires)
    assert size(_dock_left("<Border DockPanel.Dock='Left' Style='{StaticResource S}'/>",
                           base + keyed)) == (340, 480)  # fmt: skip
    # the element's own value wins over its Style's (and the Style's MinWidth still holds)
    for width, left in (("120", 120), ("20", 100)):
        border = f"<Border DockPanel.Dock='Left' Width='{width}' Style='{{StaticResource S}}'/>"
        assert size(_dock_left(border, base + keyed)) == (640 - left, 480)
    # BasedOn: the base Style's Setters apply too (the derived ones win)
    derived = "<Style x:Key='D' TargetType='Border' BasedOn='{StaticResource B}'/>"
    assert size(_dock_left("<Border DockPanel.Dock='Left' Style='{StaticResource D}'/>",
                           base + derived)) == (540, 480)  # fmt: skip
    # an implicit Style (no key: keyed by its TargetType) applies to every Border in scope
    implicit = "<Style TargetType='Border'><Setter Property='Width' Value='200'/></Style>"
    assert size(_dock_left("<Border DockPanel.Dock='Left'/>", implicit)) == (440, 480)
    assert size(_dock_left("<Border DockPanel.Dock='Left' Style='{x:Null}'/>", implicit)) == (
        640, 480)  # fmt: skip


def test_markup_style_setters_with_attached_properties_and_element_values():
    grid = (
        f"<Page {NS} {XNS} Width='400' Height='300'><Page.Resources>"
        "<Style x:Key='R' TargetType='Viewport3D'><Setter Property='Grid.Row' Value='1'/>"
        "<Setter Property='Grid.ColumnSpan' Value='2'/></Style>"
        "<Style x:Key='M' TargetType='Border'><Setter Property='Margin'><Setter.Value>"
        "<Thickness>50</Thickness></Setter.Value></Setter></Style></Page.Resources>"
        "<Grid><Grid.RowDefinitions><RowDefinition/><RowDefinition/></Grid.RowDefinitions>"
        "<Grid.ColumnDefinitions><ColumnDefinition/><ColumnDefinition/></Grid.ColumnDefinitions>"
        "<Viewport3D Style='{StaticResource R}'/></Grid></Page>"
    )
    assert size(grid) == (400, 150)
    dock = _dock_left(
        "<Border Style='{StaticResource T}' Height='60'/>",
        "<Style x:Key='T' TargetType='Border'>"
        "<Setter Property='DockPanel.Dock' Value='Top'/></Style>",
    )
    assert size(dock) == (640, 420)
    margin = grid.replace("<Viewport3D Style='{StaticResource R}'/></Grid>",
                          "<Border Grid.RowSpan='2' Grid.ColumnSpan='2' Style='{StaticResource M}'>"
                          "<Viewport3D/></Border></Grid>")  # fmt: skip
    assert size(margin) == (300, 200)


def test_markup_out_of_range_cells_and_infinite_sizes_are_errors():
    x = (f"<Grid {NS}><Grid.RowDefinitions><RowDefinition/><RowDefinition/>"
         "</Grid.RowDefinitions><Viewport3D Grid.Row='-1' Grid.RowSpan='0'/></Grid>")  # fmt: skip
    s = load(x, text=True)
    found = [(d.severity, d.column) for d in s.diagnostics if d.code == "LAY005"]
    # at the attributes (columns are 1-based)
    assert found == [("error", x.index("Grid.Row=") + 1), ("error", x.index("Grid.RowSpan") + 1)]
    s = load(f"<Grid {NS}><Viewport3D Height='Infinity'/></Grid>", text=True)
    assert [d.severity for d in s.diagnostics if d.code == "SCN012"] == ["error"]
    s = load(f"<Grid {NS}><Grid.LayoutTransform><ScaleTransform ScaleX='2'/></Grid.LayoutTransform>"
             "<Viewport3D/></Grid>", text=True)  # fmt: skip
    # laid out in its own space: half the width, scaled back up by the transform
    assert not [d for d in s.diagnostics if d.code == "LAY006"]
    assert (s.viewports[0].width, s.viewports[0].height) == (320.0, 480.0)


def test_markup_text_after_a_property_element_and_layout_transform():
    text = "KeyFrame Progress (Output)"  # 158.07 px in Open Sans 12 px
    plain = f"<TextBlock DockPanel.Dock='Left'>{text}</TextBlock>"
    assert size(_dock_left(plain)) == (640 - 158.068359375, 480)
    turned = (
        "<TextBlock DockPanel.Dock='Left'><TextBlock.LayoutTransform>"
        f"<RotateTransform Angle='-90'/></TextBlock.LayoutTransform>\n  {text}\n</TextBlock>"
    )
    assert size(_dock_left(turned)) == (640 - LINE, 480)
    group = (
        "<Button DockPanel.Dock='Left' Width='40' Height='10' Margin='5'>"
        "<Button.LayoutTransform><TransformGroup><ScaleTransform ScaleX='2'/>"
        "<RotateTransform Angle='90'/></TransformGroup></Button.LayoutTransform></Button>"
    )
    w, h = size(_dock_left(group))  # 80 x 10 turned: 10 x 80, plus the margins
    assert (round(w, 9), h) == (640 - 20, 480)


def test_markup_estimates_follow_font_size_padding_and_toolbar_items():
    def top(item: str, resources: str = "", attrs: str = "") -> tuple[float, float]:
        return size(
            f"<Page {NS} {XNS} Width='400' Height='300' {attrs}><Page.Resources>{resources}"
            f"</Page.Resources><DockPanel>{item}<Viewport3D/></DockPanel></Page>"
        )

    # one line of text at FontSize 12 (15.96 px); at 24 twice that (direct, inherited, or
    # from a Style)
    assert top("<TextBlock DockPanel.Dock='Top' Text='Title'/>") == (400, 300 - LINE)
    assert top("<TextBlock DockPanel.Dock='Top' FontSize='24' Text='Title'/>") == (
        400,
        300 - 2 * LINE,
    )
    assert top("<TextBlock DockPanel.Dock='Top' Text='Title'/>", attrs="FontSize='24'") == (
        400,
        300 - 2 * LINE,
    )
    style = "<Style TargetType='TextBlock'><Setter Property='FontSize' Value='18pt'/></Style>"
    assert top("<TextBlock DockPanel.Dock='Top' Text='Title'/>", style) == (400, 300 - 2 * LINE)
    # an own Padding replaces the template's (a Label's default Padding is 5)
    assert top("<Label DockPanel.Dock='Top' Content='x'/>") == (400, 300 - LINE - 10)
    assert top("<Label DockPanel.Dock='Top' Content='x' Padding='4,0'/>") == (400, 300 - LINE)
    assert top("<TextBlock DockPanel.Dock='Top' FontSize='24' Padding='4' Text='T'/>") == (
        400,
        300 - 2 * LINE - 8,
    )
    # a ToolBarTray holding a ToolBar of Buttons, laid out as Aero2's template: the Buttons
    # in ToolBar.ButtonStyleKey (a 1 px border, Padding 2: 21.96 px), the bar's Grid Margin
    # 3,1,1,1 and its items' panel Margin 0,1,2,2 (5 px more)
    tray = ("<ToolBarTray DockPanel.Dock='Top'><ToolBar><Button Content='Open'/><Separator/>"
            "<Button Content='Save'/></ToolBar></ToolBarTray>")  # fmt: skip
    assert top(tray) == (400, 300 - (LINE + 6 + 5))


def test_auto_row_sized_by_a_cell_in_a_star_column():
    # the TextBlock (an Auto row, star column: WPF's last measure group) still sizes the row
    text = Node(L.CONTROL, "TextBlock", estimate=(30, 16), col=1)
    v = vp(row=1, col_span=2)
    grid = Node(L.GRID, "Grid", rows=(D("Auto"), D("*")), columns=(D("*"), D("*")),
                children=[text, v], width=200, height=100)  # fmt: skip
    layout(grid)
    assert text.rect == (100, 0, 100, 16)
    assert v.rect == (0, 16, 200, 84)


def test_star_rows_act_as_auto_with_unlimited_height():
    # a Grid in a vertical StackPanel: its star row gets the content's height, here 0
    v, w = vp(row=0), vp(row=1, height=30)
    grid = Node(L.GRID, "Grid", rows=(D("*"), D("*")), children=[v, w])
    layout(window(Node(L.STACK, "StackPanel", children=[grid])))
    assert v.rect[3] == 0 and w.rect == (0, 0, 784, 30)
    assert "vertical StackPanel" in viewport_notes([v])[0].message


def test_markup_roots_page_user_control_size_to_content():
    page = f"<Page {NS} WindowWidth='416' WindowHeight='339'><Grid><Viewport3D/></Grid></Page>"
    assert size(page) == (400, 300)
    uc = (
        f"<UserControl {NS} xmlns:mc='http://schemas.openxmlformats.org/markup-compatibility/2006'"
        " xmlns:d='http://schemas.microsoft.com/expression/blend/2008' mc:Ignorable='d'"
        " d:DesignWidth='300' d:DesignHeight='200'><Viewport3D/></UserControl>"
    )
    assert size(uc) == (300, 200)
    stc = (
        f"<Window {NS} SizeToContent='WidthAndHeight'><Border Padding='5'>"
        "<Viewport3D Width='100' Height='50'/></Border></Window>"
    )
    s = load(stc, text=True)
    assert s.layout.client == (110, 60) and (s.viewports[0].width, s.viewports[0].height) == (
        100,
        50,
    )


def test_markup_rounding_and_fractions():
    cols = "<Grid.ColumnDefinitions><ColumnDefinition/><ColumnDefinition/><ColumnDefinition/>"
    x = (
        f"<Grid {NS} Width='100' Height='30' UseLayoutRounding='{{r}}'>{cols}"
        "</Grid.ColumnDefinitions><Viewport3D Grid.Column='1'/></Grid>"
    )
    assert size(x.replace("{r}", "False"))[0] == pytest.approx(100 / 3)
    assert size(x.replace("{r}", "True"))[0] in (33, 34)


def test_markup_viewport_in_a_custom_control_and_a_button():
    x = (
        f"<Grid {NS} xmlns:h='clr-namespace:H' Width='200' Height='100'>"
        "<h:View Margin='10'><Button HorizontalContentAlignment='Stretch'"
        " VerticalContentAlignment='Stretch'><Viewport3D/></Button></h:View></Grid>"
    )
    s = load(x, text=True)
    # the theme's Button template: a 1 px Border, the ContentPresenter at Padding 1
    assert (s.viewports[0].width, s.viewports[0].height) == (176, 76)
    assert {"LAY004"} <= {d.code for d in s.diagnostics}
    # Aero2 centres a Button's content: a Viewport3D (no size of its own) gets none
    s = load(x.replace("Stretch", "Center"), text=True)
    assert (s.viewports[0].width, s.viewports[0].height) == (0, 0)
    assert {"LAY001", "LAY004"} <= {d.code for d in s.diagnostics}


def test_rounding_rounds_margin_sums_not_offsets_and_border_not_padding():
    v = vp(margin=(0.3, 0.3, 0.3, 0.3))
    layout(Node(L.GRID, "Grid", width=100, height=100, rounding=True, children=[v]))
    assert v.rect == (0, 0, 99, 99)  # margins 0.6 round to 1; the 0.3 offset rounds to 0
    w = vp()
    b = Node(L.BORDER, "Border", border=(1.4, 1.4, 1.4, 1.4), padding=(0.5, 0, 0, 0),
             children=[w], rounding=True)  # fmt: skip
    layout(Node(L.GRID, "Grid", width=100, height=100, children=[b]))
    # thickness 1.4 -> 1 on each side, padding 0.5 kept: the child's 97.5 rounds to 98 (even)
    assert w.rect[0] == 2 and w.rect[2] == 98


def test_fractional_layout_size_keeps_its_exact_aspect_ratio():
    from xaml3d.api import render_arrays

    # a Viewport3D 100 x 33.4 (a third of 100.2): the image is 100 x 33, the projection keeps
    # 100 / 33.4, so an orthographic camera of Width 100 shows 33.4 units over the 33 rows and
    # a quad 33 units high leaves the top and bottom rows partly covered
    x = (
        f"<Grid {NS} Width='100' Height='100.2'><Grid.RowDefinitions><RowDefinition/>"
        "<RowDefinition/><RowDefinition/></Grid.RowDefinitions><Viewport3D>"
        "<Viewport3D.Camera><OrthographicCamera Position='0,0,5' LookDirection='0,0,-1'"
        " Width='100'/></Viewport3D.Camera><ModelVisual3D><ModelVisual3D.Content>"
        "<Model3DGroup><AmbientLight/><GeometryModel3D><GeometryModel3D.Geometry>"
        "<MeshGeometry3D Positions='-60,-16.5,0 60,-16.5,0 60,16.5,0 -60,16.5,0'"
        " TriangleIndices='0 1 2 0 2 3'/></GeometryModel3D.Geometry><GeometryModel3D.Material>"
        "<DiffuseMaterial Brush='White'/></GeometryModel3D.Material></GeometryModel3D>"
        "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D></Grid>"
    )
    s = load(x, text=True)
    vp0 = s.viewports[0]
    assert vp0.height == pytest.approx(33.4)
    r = render_arrays(s, ssaa=4)
    assert (r.width, r.height) == (100, 33)
    alpha = r.rgba[:, 50, 3]
    assert alpha[16] == 255 and 0 < alpha[0] < 255 and 0 < alpha[32] < 255
    exact = render_arrays(s, 100, 33, ssaa=4)  # both sizes given: the image's own aspect
    assert exact.rgba[0, 50, 3] == 255 and exact.rgba[32, 50, 3] == 255


def test_uniform_grid_cells_and_first_column():
    kids = [vp() for _ in range(3)]
    layout(Node(L.UNIFORM, "UniformGrid", width=200, height=100, children=kids))
    # 3 children: 2 x 2 cells of 100 x 50
    assert [k.rect for k in kids] == [(0, 0, 100, 50), (100, 0, 100, 50), (0, 50, 100, 50)]
    kids = [vp() for _ in range(3)]
    layout(Node(L.UNIFORM, "UniformGrid", uniform=(0, 3, 1), width=300, height=100, children=kids))
    assert [k.rect[:2] for k in kids] == [(100, 0), (200, 0), (0, 50)]
    x = (
        f"<UniformGrid {NS} Columns='2' Width='200' Height='80' xmlns:x="
        "'http://schemas.microsoft.com/winfx/2006/xaml'><Viewport3D/><Viewport3D/></UniformGrid>"
    )
    assert size(x, 1) == (100, 80)


def test_scrollviewer_auto_bar_only_when_the_content_overflows():
    small, tall = vp(height=100), vp(height=1000)
    layout(window(Node(L.SCROLL, "ScrollViewer", scroll_v="Auto", children=[small])))
    assert small.rect[2] == 784
    layout(window(Node(L.SCROLL, "ScrollViewer", scroll_v="Auto", children=[tall])))
    assert tall.rect[2] == 784 - 17


# --------------------------------------------------------------------------- LayoutTransform

R90 = ((0.0, -1.0), (1.0, 0.0))  # RotateTransform 90 in column form: x' = -y, y' = x
R45 = ((math.sqrt(0.5), -math.sqrt(0.5)), (math.sqrt(0.5), math.sqrt(0.5)))


def test_layout_transform_bounds_and_maximal_local_size():
    from xaml3d.layout.transform import bounds, maximal_local_size

    assert bounds(R90, 64, 48) == (-48.0, 0.0, 48.0, 64.0)
    assert bounds(((2.0, 0.0), (0.0, 1.0)), 10, 20) == (0.0, 0.0, 20.0, 20.0)
    # a quarter turn swaps the room; a scale divides it
    assert maximal_local_size(R90, 80, 64) == (64.0, 80.0)
    assert maximal_local_size(((2.0, 0.0), (0.0, 0.5)), 80, 64) == (40.0, 128.0)
    # 45 degrees in a 100 x 100 square: the largest square whose turned bounds fit
    w, h = maximal_local_size(R45, 100, 100)
    assert (round(w, 9), round(h, 9)) == (round(100 * math.sqrt(0.5), 9),) * 2
    # unlimited room one way is taken as a square of the other (WPF's rule)
    assert maximal_local_size(R45, math.inf, 100) == maximal_local_size(R45, 100, 100)
    assert maximal_local_size(R45, math.inf, math.inf) == (math.inf, math.inf)
    assert maximal_local_size(R90, 0, 10) == (0.0, 0.0)
    assert maximal_local_size(((1.0, 1.0), (1.0, 1.0)), 10, 10) == (0.0, 0.0)  # singular
    # a shear: the width line bounds both (WPF's signed formula), half the room each way
    assert maximal_local_size(((1.0, 0.5), (0.0, 1.0)), 100, 100) == (50.0, 100.0)


def _turned(inner: str, angle: float = 90) -> str:
    return (
        f"<Grid {NS} Width='96' Height='64'><Grid.ColumnDefinitions><ColumnDefinition "
        "Width='Auto'/><ColumnDefinition/></Grid.ColumnDefinitions>"
        f"<Border Width='32' Height='16'><Border.LayoutTransform><RotateTransform Angle='{angle}'/>"
        f"</Border.LayoutTransform></Border>{inner}</Grid>"
    )


def test_layout_transform_turns_sizes_and_boxes():
    # the turned Border takes 16 x 32 in the Auto column; the viewport, turned too, is laid
    # out in its own space as 64 x 80 in the 80 x 64 star column
    vp = (
        "<Viewport3D Grid.Column='1'><Viewport3D.LayoutTransform><RotateTransform Angle='90'/>"
        "</Viewport3D.LayoutTransform></Viewport3D>"
    )
    s = load(_turned(vp), text=True)
    assert (s.viewports[0].width, s.viewports[0].height) == (64.0, 80.0)
    border, view = s.layout.boxes[1], s.layout.boxes[2]
    assert border.rect == (0.0, 16.0, 32.0, 16.0)  # its bounds' corner at col 0, row 16
    assert [round(v, 9) for v in view.rect] == [16.0, 0.0, 64.0, 80.0]
    turn = border.layer.layout_transform.round(9) + 0.0  # cos 90 is 6e-17: no -0.0
    assert turn.tolist() == [[0.0, -1.0, 16.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    # a panel scaled by 2 around a viewport: half the room, the picture scaled back up
    s = load(
        f"<Grid {NS} Width='96' Height='64'><Border>"
        "<Border.LayoutTransform><ScaleTransform ScaleX='2' ScaleY='2'/></Border.LayoutTransform>"
        "<Viewport3D/></Border></Grid>",
        text=True,
    )
    assert (s.viewports[0].width, s.viewports[0].height) == (48.0, 32.0)
    # the picture of the viewport alone is drawn at its own size, then scaled as on screen
    [around] = s.viewports[0].picture.around
    assert around.layer.layout_transform.tolist() == [[2, 0, 0], [0, 2, 0], [0, 0, 1]]
    r = xaml3d.render_arrays(s)
    assert r.rgba.shape == (64, 96, 4) and (r.width, r.height) == (96, 64)
    assert r.depth.shape == (64, 96) and r.distance.shape == (64, 96)


def test_rounding_rounds_a_centred_child_offset_halves_to_even():
    # a Button's template under UseLayoutRounding: a Border (1 px) holding a centred 16 px
    # ContentPresenter in 29 px: WPF rounds the visual offset 1 + 5.5 = 6.5 to 6 (Math.Round)
    text = Node(L.CONTROL, "TextBlock", estimate=(15.6, 15.96))
    presenter = Node(L.CONTAINER, "ContentPresenter", h_align="Center", children=[text])
    border = Node(L.BORDER, "Border", border=(1, 1, 1, 1), children=[presenter])
    button = Node(L.CONTAINER, "Button", width=29, height=20, children=[border])
    layout(Node(L.GRID, "Grid", width=29, height=20, rounding=True, children=[button]))
    assert presenter.rect[2] == 16  # 15.6 rounded
    assert presenter.rect[0] == 6 and text.rect[0] == 6
    assert presenter.clip_box is None


def test_layout_clip_cuts_a_child_wider_than_its_slot():
    # a 30 px Button whose 96 px text is given 26 px: the TextBlock (Stretch, wider than its
    # slot: placed at the left) is clipped to the slot; the Button and its parts are not
    text = Node(L.CONTROL, "TextBlock", estimate=(96.0, 16.0))
    presenter = Node(L.CONTAINER, "ContentPresenter", h_align="Center", children=[text])
    border = Node(L.BORDER, "Border", border=(1, 1, 1, 1), padding=(1, 1, 1, 1),
                  children=[presenter])  # fmt: skip
    button = Node(L.CONTAINER, "Button", width=30, children=[border])
    layout(Node(L.STACK, "StackPanel", width=100, height=50, children=[button]))
    assert button.rect == (35, 0, 30, 20)
    assert presenter.rect == (37, 2, 26, 16)
    assert text.rect[0] == 37 and text.rect[2] == 96
    assert text.clip_box == (0, 0, 26, 16)
    assert button.clip_box is None and border.clip_box is None and presenter.clip_box is None
