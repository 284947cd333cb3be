"""The shapes as WPF's Shape lays them out (xaml3d/xaml/shapes_reader.py): the natural size
from the geometry's render bounds (curve extrema, arcs, joins and caps, the pen; dashes left
out), Stretch in measure and arrange, and their drawing in ``render --window`` not cut to the
box in a Canvas, cut by the layout clip where WPF's is."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from PIL import Image

from xaml3d.pipeline import load
from xaml3d.render.window import compose_window
from xaml3d.xaml.shapes_reader import SHAPES, stretch_metrics

NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'


def _boxes(content: str, panel: str = "StackPanel Orientation='Horizontal'"):
    """The laid-out boxes of the shapes in ``panel``, beside a viewport, by type."""
    s = load(f"<Grid {NS} Width='400' Height='300'><{panel.split()[0]} "
             f"{' '.join(panel.split()[1:])} VerticalAlignment='Top' HorizontalAlignment='Left'>"
             f"{content}</{panel.split()[0]}><Viewport3D Width='4' Height='4'/></Grid>",
             text=True)  # fmt: skip
    return s, [b for b in s.layout.boxes if b.type in SHAPES]


def _size(content: str):
    _, boxes = _boxes(content)
    return boxes[0].rect[2:]


def test_cubic_bezier_is_as_tall_as_its_extremum_not_its_end_points():
    # end points at y = 100; the curve's lowest point (t = 0.5) at 0.75 * 200 + 0.25 * 100
    w, h = _size('<Path Stroke="Black" StrokeThickness="2" '
                 'Data="M 10,100 C35,200 135,200 160,100"/>')  # fmt: skip
    # the flat end is square to the curve's last tangent (25, -100): its corner reaches
    # half the thickness times that tangent's y share past the end point
    assert w == pytest.approx(160 + 100 / math.hypot(25, 100), abs=1e-3)
    assert h == pytest.approx(175 + 1, abs=1e-3)


def test_quadratic_and_arc_extrema_and_no_pen():
    # a quadratic's extremum: 0.25 * 20 + 0.5 * 120 + 0.25 * 20 = 70; no Stroke: no pen
    assert _size('<Path Fill="Red" Data="M 0,20 Q 40,120 80,20"/>') == pytest.approx((80, 70))
    # a half circle of radius 25 from (0,50) to (50,50) bulging down to y = 75
    w, h = _size('<Path Stroke="Red" Data="M 0,50 A 25,25 0 0 0 50,50"/>')
    assert (w, h) == pytest.approx((50.5, 75.5), abs=1e-3)


def test_miter_join_and_square_caps_count():
    # a 90 degree corner at (20,20) drawn 4 wide: the miter's tip is half the thickness times
    # sqrt(2) beyond the corner along its bisector, i.e. 2 further out on each axis
    w, h = _size('<Polyline Stroke="Black" StrokeThickness="4" Points="0,0 20,20 0,40"/>')
    assert w == pytest.approx(20 + 2 * math.sqrt(2), abs=1e-3)
    assert h == pytest.approx(40 + math.sqrt(2), abs=1e-3)  # the flat end's corner
    # square caps reach half the thickness past each end
    assert _size('<Line X1="10" Y1="10" X2="50" Y2="10" Stroke="Black" StrokeThickness="6" '
                 'StrokeStartLineCap="Square" StrokeEndLineCap="Square"/>') == pytest.approx(
        (53, 13), abs=1e-3)  # fmt: skip


def test_dashes_do_not_change_the_layout_size():
    plain = _size('<Line X2="50" Y2="10" Stroke="Black" StrokeThickness="2"/>')
    dashed = _size('<Line X2="50" Y2="10" Stroke="Black" StrokeThickness="2" '
                   'StrokeDashArray="5 20"/>')  # fmt: skip
    assert dashed == pytest.approx(plain)


def test_rectangle_without_a_size_is_its_stroke_thickness_square():
    assert _size('<Rectangle Stroke="Black" StrokeThickness="3"/>') == pytest.approx((3, 3))
    assert _size('<Ellipse Fill="Black"/>') == pytest.approx((0, 0))


def test_stretch_metrics_as_wpf_computes_them():
    # Fill: each axis its own scale, the pen kept inside; Uniform: the smaller scale
    b = (10.0, 20.0, 30.0, 60.0)  # 20 x 40
    xs, ys, dx, dy, size = stretch_metrics("Fill", 2.0, (42.0, 42.0), b)
    assert (xs, ys, dx, dy, *size) == pytest.approx((2.0, 1.0, -9.0, -19.0, 42.0, 42.0))
    xs, ys, _, _, size = stretch_metrics("Uniform", 2.0, (42.0, 42.0), b)
    assert (xs, ys, *size) == pytest.approx((1.0, 1.0, 22.0, 42.0))
    xs, ys, _, _, size = stretch_metrics("UniformToFill", 2.0, (42.0, 42.0), b)
    assert (xs, ys, *size) == pytest.approx((2.0, 2.0, 42.0, 82.0))
    # infinite room (a Canvas, an Auto cell): the natural scale
    assert stretch_metrics("Uniform", 0.0, (math.inf, math.inf), b)[4] == pytest.approx((20, 40))
    # a horizontal line is stretched as Fill whatever the mode
    xs, ys, _, _, size = stretch_metrics("Uniform", 0.0, (50.0, 30.0), (0.0, 5.0, 10.0, 5.0))
    assert (xs, ys, *size) == pytest.approx((5.0, 1.0, 50.0, 0.0))


def test_uniform_path_is_scaled_into_its_box_and_centred():
    s, [b] = _boxes('<Path Stretch="Uniform" Fill="Blue" Width="60" Height="30" '
                    'Data="M 100,100 L 110,100 110,110 100,110 Z"/>', panel="Canvas")  # fmt: skip
    # its RenderSize is the stretched square's, 30 x 30, centred in the 60 wide room as
    # FrameworkElement centres a Stretch-aligned element smaller than its room
    assert b.rect == pytest.approx((15, 0, 30, 30))
    rgba, _ = compose_window(s)
    blue = (rgba[..., 2] == 255) & (rgba[..., 0] == 0)
    rows, cols = np.nonzero(blue)
    # the 10 x 10 square at (100, 100) scaled by 3 (the smaller ratio) to the box's corner
    assert (cols.min(), cols.max(), rows.min(), rows.max()) == (15, 44, 0, 29)


def test_a_path_in_a_canvas_draws_beyond_its_box(tmp_path):
    src = tmp_path / "x.xaml"
    src.write_text(
        f'<Window {NS} Width="400" Height="300"><Canvas Background="White">'
        '<Path Stroke="Black" StrokeThickness="2" '
        'Data="M 10,100 C35,200 135,200 160,100 C185,0 285,0 310,100"/>'
        '<Path Stroke="Red" Data="M 20,20 C 40,80 60,80 80,20"/>'
        '<Viewport3D Canvas.Left="300" Canvas.Top="200" Width="50" Height="50"/>'
        "</Canvas></Window>"
    )
    out = tmp_path / "x.png"
    r = subprocess.run([sys.executable, "-m", "xaml3d", "render", str(src), "--window",
                        "-o", str(out), "-q"], capture_output=True, text=True)  # fmt: skip
    assert r.returncode == 0, r.stderr
    a = np.asarray(Image.open(out).convert("RGB")).astype(int)
    dark = a.sum(axis=2) < 200
    red = (a[..., 0] > 200) & (a[..., 1] < 100)
    # the black curve's lowest point (y 175) and its highest (y 25) are drawn
    assert dark[170:182, 80:90].any() and dark[20:30, 230:240].any()
    # the red curve dips to y 65 between its end points at y 20
    assert red[60:68, 45:56].any() and red[30:40].any()


def test_a_shape_larger_than_its_width_is_cut_at_it():
    s, [b] = _boxes('<Line X2="100" Y1="5" Y2="5" Stroke="Blue" StrokeThickness="10" '
                    'Width="40"/>', panel="Canvas")  # fmt: skip
    rgba, _ = compose_window(s)
    blue = (rgba[..., 2] == 255) & (rgba[..., 0] == 0) & (rgba[..., 3] == 255)
    cols = np.nonzero(blue.any(axis=0))[0]
    assert (cols.min(), cols.max()) == (0, 39)


def test_clip_to_bounds_cuts_a_shape_at_its_box():
    # the line starts 20 px left of the shape's box (negative x is drawn, outside the box)
    line = 'Canvas.Left="30" Data="M -20,10 L 40,10" Stroke="Blue" StrokeThickness="4"'
    free, [b] = _boxes(f"<Path {line}/>", panel="Canvas")
    cut, [_] = _boxes(f'<Path {line} ClipToBounds="True"/>', panel="Canvas")
    assert b.rect == pytest.approx((30, 0, 40, 12))  # its natural size: right 40, bottom 12

    def cols(scene):
        rgba, _ = compose_window(scene)
        blue = (rgba[..., 2] == 255) & (rgba[..., 0] < 100) & (rgba[..., 3] > 0)
        found = np.nonzero(blue.any(axis=0))[0]
        return int(found.min()), int(found.max())

    assert cols(free) == (10, 69)  # all of it, from x 30 - 20
    assert cols(cut) == (30, 69)  # cut at the box's left edge


def test_a_shape_in_a_visual_brush_counts_all_of_its_curve():
    from xaml3d.render.layer2d.paint import drawing_bounds

    s = load(f"<Grid {NS} Width='40' Height='40'><Grid.Background><VisualBrush><VisualBrush."
             "Visual><Canvas><Path Stroke='Black' StrokeThickness='2' "
             "Data='M 0,10 C 10,90 30,90 40,10'/></Canvas></VisualBrush.Visual></VisualBrush>"
             "</Grid.Background><Viewport3D Width='4' Height='4'/></Grid>", text=True)  # fmt: skip
    [grid] = [b for b in s.layout.boxes if b.type == "Grid"]
    brush = grid.background
    box = drawing_bounds(brush.drawing)
    # the visual's ink reaches the curve's lowest point (70) and the pen's half below it
    assert box.bottom() == pytest.approx(71, abs=1e-3)


def test_poly_segments_and_geometry_elements_by_their_extrema():
    # a PolyBezierSegment's second curve dips to 0.75 * 80 + 0.25 * 20 = 65; a
    # PolyQuadraticBezierSegment's second curve rises to 0.5 * -40 + 0.5 * 20 = -10 (outside,
    # above the box: the size counts only the right and bottom)
    poly = ('<Path Fill="Black"><Path.Data><PathGeometry><PathFigure StartPoint="0,20">'
            '<PolyBezierSegment Points="5,20 15,20 20,20 25,80 35,80 40,20"/>'
            '<PolyQuadraticBezierSegment Points="45,20 50,20 55,-40 60,20"/>'
            "</PathFigure></PathGeometry></Path.Data></Path>")  # fmt: skip
    assert _size(poly) == pytest.approx((60, 65), abs=1e-3)
    # an EllipseGeometry and a turned RectangleGeometry: their own bounds, transform included
    assert _size('<Path Fill="Black"><Path.Data><EllipseGeometry Center="30,20" RadiusX="10" '
                 'RadiusY="5"/></Path.Data></Path>') == pytest.approx((40, 25))  # fmt: skip
    turned = ('<Path Fill="Black"><Path.Data><RectangleGeometry Rect="0,0,10,10">'
              '<RectangleGeometry.Transform><RotateTransform Angle="45"/>'
              "</RectangleGeometry.Transform></RectangleGeometry></Path.Data></Path>")  # fmt: skip
    assert _size(turned) == pytest.approx((10 / math.sqrt(2), 20 / math.sqrt(2)), abs=1e-3)


def test_polygon_is_as_large_as_its_right_and_bottom():
    # what lies left of or above the box's corner is not counted (Shape.GetNaturalSize)
    assert _size('<Polygon Fill="Black" Points="-10,-5 30,0 30,20"/>') == pytest.approx((30, 20))
    # a closed figure's corner at (30, 20) with a 2 px pen: a miter within the limit, its tip
    # half the thickness / sin(half the angle) beyond the corner along the bisector
    w, h = _size('<Polygon Stroke="Black" StrokeThickness="2" Points="0,20 30,20 30,0"/>')
    assert (w, h) == pytest.approx((31, 21), abs=1e-3)  # a right angle: 1 px out each way


def test_a_moved_layer_brings_in_what_a_shape_draws_left_of_the_window():
    # the line lies at x -150..-50, left of the window and of its own (empty) box; the Canvas's
    # RenderTransform moves it 100 right: -50..50, of which 0..50 shows
    s = load(f"<Grid {NS} Width='200' Height='60'><Canvas><Canvas.RenderTransform>"
             "<TranslateTransform X='100'/></Canvas.RenderTransform>"
             '<Path Data="M -150,10 L -50,10" Stroke="Blue" StrokeThickness="4"/></Canvas>'
             "<Viewport3D Width='4' Height='4'/></Grid>", text=True)  # fmt: skip
    rgba, _ = compose_window(s)
    blue = (rgba[..., 2] == 255) & (rgba[..., 0] < 100) & (rgba[..., 3] > 0)
    cols = np.nonzero(blue.any(axis=0))[0]
    assert (cols.min(), cols.max()) == (0, 49)


def test_a_panels_clip_to_bounds_cuts_what_it_holds_at_its_box():
    """ClipToBounds on a Canvas (WPF's layout clip of the panel, applied to all it holds): an
    Ellipse reaching out of it is cut at the Canvas's box; the same Canvas without it lets the
    Ellipse draw past its box."""

    def red_box(clip: str):
        s, _ = _boxes(
            f'<Canvas Width="100" Height="80" {clip}><Ellipse Canvas.Left="40" Canvas.Top="30" '
            'Width="120" Height="100" Fill="Red"/></Canvas>',
            panel="Grid",
        )
        rgba, _ = compose_window(s)
        ys, xs = np.nonzero(rgba[..., 3] > 0)  # the ellipse, edges included
        return int(xs.min()), int(xs.max()), int(ys.min()), int(ys.max())

    assert red_box("") == (40, 159, 30, 129)
    x0, x1, y0, y1 = red_box('ClipToBounds="True"')
    assert (x0, y0, x1, y1) == (40, 30, 99, 79)  # cut at the box: right 100, bottom 80


def test_a_panels_clip_to_bounds_inside_a_visual_brush():
    """The same cut inside a VisualBrush's visual, intersected with the panel's own Clip."""
    from xaml3d.render.layer2d.paint import drawing_bounds

    def bounds(attrs: str):
        s = load(f"<Grid {NS} Width='40' Height='40'><Grid.Background><VisualBrush><VisualBrush."
                 f"Visual><Grid><Canvas Width='50' Height='40' {attrs}><Rectangle Canvas.Left="
                 "'30' Width='60' Height='20' Fill='Red'/></Canvas></Grid></VisualBrush.Visual>"
                 "</VisualBrush></Grid.Background><Viewport3D Width='4' Height='4'/></Grid>",
                 text=True)  # fmt: skip
        [grid] = [b for b in s.layout.boxes if b.type == "Grid" and b.background is not None]
        box = drawing_bounds(grid.background.drawing)
        return round(box.right(), 3)

    assert bounds("") == 90.0
    assert bounds("ClipToBounds='True'") == 50.0
    assert bounds("ClipToBounds='True' Clip='M 0,0 L 45,0 45,10 0,10 Z'") == 45.0
