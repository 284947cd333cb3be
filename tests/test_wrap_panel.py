"""WrapPanel's measure and arrange (xaml3d.layout.wrap), a GridSplitter's Aero2 look and
default alignment, and a TextBox's TextWrapping: exact numbers."""

from __future__ import annotations

import math

import xaml3d
from xaml3d.layout import layout
from xaml3d.scene import element_tree as L
from xaml3d.scene.element_tree import Node


def box(w: float, h: float, **kw) -> Node:
    return Node(L.CONTROL, "Rectangle", width=w, height=h, estimate=(0, 0), **kw)


def wrap(children, orientation="Horizontal", **kw) -> Node:
    return Node(L.WRAP, "WrapPanel", children=children, orientation=orientation, **kw)


def window(child, w=216, h=139) -> Node:
    return Node(L.WINDOW, "Window", width=w, height=h, children=[child])


def test_horizontal_lines_break_where_the_next_child_would_not_fit():
    kids = [box(40, 10), box(40, 20), box(40, 10), box(30, 5)]
    panel = wrap(kids, width=100, h_align="Left", v_align="Top")
    layout(window(panel))
    # 40 + 40 fit in 100; the third starts a line, the fourth joins it (40 + 30)
    # every child of a line is arranged in the line's whole thickness, centred in it
    assert [k.rect[:2] for k in kids] == [(0, 5), (40, 0), (0, 20), (40, 22.5)]
    assert panel.desired == (100, 30)  # Width 100 by two lines of 20 and 10


def test_a_child_wider_than_the_room_has_a_line_of_its_own():
    kids = [box(30, 10), box(120, 10), box(30, 10)]
    panel = wrap(kids, width=100, h_align="Left", v_align="Top")
    layout(window(panel))
    assert [k.rect[:2] for k in kids] == [(0, 0), (0, 10), (0, 20)]


def test_vertical_with_item_size_fills_columns():
    kids = [Node(L.CONTROL, "Rectangle", estimate=(0, 0)) for _ in range(3)]
    panel = wrap(kids, orientation="Vertical", item_width=30, item_height=12, height=24,
                 h_align="Left", v_align="Top")  # fmt: skip
    layout(window(panel))
    assert [k.rect for k in kids] == [(0, 0, 30, 12), (0, 12, 30, 12), (30, 0, 30, 12)]
    assert panel.desired == (60, 24)


def test_unconstrained_the_children_share_one_line():
    kids = [box(40, 10), box(40, 10)]
    panel = wrap(kids)
    from xaml3d.layout.wrap import wrap_measure

    class _E:  # the engine's measure of a child with its own size
        def measure(self, k, w, h):
            k.desired = (k.width, k.height)

    assert wrap_measure(_E(), panel, math.inf, math.inf) == (80, 10)


def test_wrap_panel_gridsplitter_and_wrapping_textbox_from_markup(tmp_path):
    path = tmp_path / "w.xaml"
    path.write_text("""<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
      Width="216" Height="139">
      <Grid><Grid.ColumnDefinitions><ColumnDefinition Width="100"/><ColumnDefinition/>
        </Grid.ColumnDefinitions>
        <StackPanel>
          <WrapPanel><RadioButton Content="One" Margin="2"/><RadioButton Content="Three"
            Margin="2"/><RadioButton Content="Two" Margin="2"/></WrapPanel>
          <TextBox Width="80" TextWrapping="Wrap" Text="aaaa bbbb cccc dddd eeee ffff"/>
        </StackPanel>
        <GridSplitter Width="5"/>
        <Viewport3D Grid.Column="1"><Viewport3D.Camera><OrthographicCamera Width="10"/>
        </Viewport3D.Camera></Viewport3D>
      </Grid></Window>""")
    scene = xaml3d.load(path)
    assert not [d for d in scene.diagnostics if d.code in ("DRW007", "LAY003", "LAY007")]
    boxes = {b.type: b for b in scene.layout.boxes}
    # the GridSplitter's default HorizontalAlignment is Right: at the column's right edge
    assert boxes["GridSplitter"].rect == (95, 0, 5, 100)
    # the WrapPanel's three RadioButtons in three lines of 18.96 px (14.96 + the margins): each
    # is its 15 px mark column, Padding 4 and its text, so no two of them fit in 100 px
    assert boxes["WrapPanel"].rect[3] == 3 * (12 * 2724 / 2048 - 1 + 4)
    # the TextBox wraps in its text view, 74 px (80 less the 1 px border and the 2 px
    # insets, each side: Aero2's TextBox Style sets no Padding): "aaaa bbbb" is 59.2 px,
    # "aaaa bbbb cccc" 85.2 px: three lines, and the border
    assert boxes["TextBox"].rect[3] == 3 * (12 * 2724 / 2048) + 2


def test_wrap_panel_in_a_visual_brush_wraps_and_draws_its_background(tmp_path):
    # a 32 px wide WrapPanel of three 16x16 squares: two on the first line, one on the second,
    # on its red Background; the brush's visual is 32x32 on the 32x32 quad, 1 px per DIP
    visual = """<WrapPanel Width="32" Background="Red">
        <Rectangle Width="16" Height="16" Fill="Lime"/><Rectangle Width="16" Height="16"
        Fill="Blue"/><Rectangle Width="16" Height="16" Fill="Lime"/></WrapPanel>"""
    path = tmp_path / "v.xaml"
    path.write_text(f"""<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
      Width="64" Height="48">
      <Viewport3D.Camera><OrthographicCamera Position="0,0,10" Width="64"/></Viewport3D.Camera>
      <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
        <GeometryModel3D><GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,16,0 -16,16,0"
              TriangleIndices="0 1 2 0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
        </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial>
          <DiffuseMaterial.Brush><VisualBrush><VisualBrush.Visual>{visual}
          </VisualBrush.Visual></VisualBrush></DiffuseMaterial.Brush>
        </DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
      </Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D>""")
    rgba = xaml3d.render_arrays(xaml3d.load(path)).rgba
    # the quad: cols 16..47, rows 8..39
    assert tuple(rgba[12, 20]) == (0, 255, 0, 255)  # first line, first square
    assert tuple(rgba[12, 40]) == (0, 0, 255, 255)  # first line, second square
    assert tuple(rgba[30, 20]) == (0, 255, 0, 255)  # the third square on the second line
    assert tuple(rgba[30, 40]) == (255, 0, 0, 255)  # beside it, the panel's Background
