"""The 2D layer's foundation: reading geometries and drawings, drawing them, skia on demand.

Reference pictures of drawings on surfaces are cases of ``tests/reference/drawing/``; here:
exact values of the path reader, pixels of drawn tiles, the resolution rule, corpus 014 against
its checked picture, and that a scene without 2D content never imports skia.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from conftest import CORPUS, ROOT, needs_corpus
from PIL import Image
from test_reference import compare_images

import xaml3d
from xaml3d.errors import ValueSyntaxError
from xaml3d.scene.drawing import (
    DrawingBrush,
    DrawingGroup,
    GeometryDrawing,
    PathGeometry,
    Pen,
    RectangleGeometry,
    TextDrawing,
)
from xaml3d.scene.types import SolidColorBrush
from xaml3d.xaml.geometry_reader import parse_path_data

LIME = SolidColorBrush(color=(0.0, 1.0, 0.0, 1.0))


def test_path_data_absolute_commands():
    cmds, fill = parse_path_data("F1 M 10,10 h 5 v 5 l -5,0 z m 1,1 L2,2 3,3")
    assert fill == "Nonzero"
    assert cmds == (
        ("M", 10.0, 10.0), ("L", 15.0, 10.0), ("L", 15.0, 15.0), ("L", 10.0, 15.0), ("Z",),
        ("M", 11.0, 11.0), ("L", 2.0, 2.0), ("L", 3.0, 3.0),
    )  # fmt: skip


def test_path_data_curves_and_arcs():
    cmds, fill = parse_path_data("M0,0 C1,1 2,1 3,0 S5,-1 6,0 Q7,1 8,0 T10,0 a2,3 45 1 0 4,0")
    assert fill == "EvenOdd"  # F0, PathGeometry's default
    assert cmds[1] == ("C", 1.0, 1.0, 2.0, 1.0, 3.0, 0.0)
    assert cmds[2] == ("C", 4.0, -1.0, 5.0, -1.0, 6.0, 0.0)  # S mirrors the last control
    assert cmds[3] == ("Q", 7.0, 1.0, 8.0, 0.0)
    assert cmds[4] == ("Q", 9.0, -1.0, 10.0, 0.0)  # T mirrors the quadratic control
    assert cmds[5] == ("A", 2.0, 3.0, 45.0, True, False, 14.0, 0.0)


def test_path_data_commas_as_in_real_files():
    # corpus 014 writes "1,0.9, 0.9,1z": a comma after a pair is a separator
    cmds, _ = parse_path_data("M0,0.1 L0.1,0 1,0.9, 0.9,1z")
    assert cmds[-2] == ("L", 0.9, 1.0) and cmds[-1] == ("Z",)
    with pytest.raises(ValueSyntaxError):
        parse_path_data("L 1,1")


def _tile(brush, size=(8, 8)):
    from xaml3d.render.layer2d.paint import PLAYER
    from xaml3d.render.layer2d.shaders import content_bounds, tile_layout
    from xaml3d.render.layer2d.surface import rasterize_tile

    viewport, m = tile_layout(brush, (np.zeros(2), np.ones(2)), content_bounds(brush, PLAYER))
    return rasterize_tile(brush, viewport, m, size)


def test_tile_of_a_drawing_premultiplied_exact():
    half = SolidColorBrush(color=(0.0, 1.0, 0.0, 0.5))
    d = DrawingGroup(children=(
        GeometryDrawing(RectangleGeometry((0.0, 0.0, 4.0, 4.0)), brush=half),
        GeometryDrawing(RectangleGeometry((0.0, 0.0, 2.0, 4.0)), brush=LIME),
    ))  # fmt: skip
    tile = _tile(DrawingBrush(drawing=d))
    # the 4x4 drawing fills the 8x8 tile: left half opaque lime, right half lime at 50%
    assert np.allclose(tile[:, :4], (0.0, 1.0, 0.0, 1.0))
    assert np.allclose(tile[:, 4:], (0.0, 128 / 255, 0.0, 128 / 255))


def test_drawing_bounds_include_the_pen():
    from xaml3d.render.layer2d.paint import drawing_bounds

    g = GeometryDrawing(
        PathGeometry((("M", 0.0, 0.0), ("L", 10.0, 0.0))), pen=Pen(brush=LIME, thickness=4.0)
    )
    r = drawing_bounds(g)
    assert (r.left(), r.top(), r.right(), r.bottom()) == (0.0, -2.0, 10.0, 2.0)


def test_texture_density_is_screen_pixels_per_uv_unit():
    from xaml3d.render.brushes import uv_density

    screen = np.array([[0.0, 0.0], [100.0, 0.0], [0.0, 50.0], [np.nan, np.nan]])
    uv = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])
    # 100 x 50 pixels for a unit: sqrt(5000); a triangle behind the eye does not count
    d = uv_density(screen, uv, np.array([[0, 1, 2], [1, 3, 2]]))
    assert d == pytest.approx(np.sqrt(5000.0))


def test_a_scene_without_2d_content_does_not_import_skia():
    code = (
        "import sys, xaml3d; xaml3d.render_arrays('samples/cube.xaml', 32, 32); "
        "print('skia' in sys.modules)"
    )
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert p.stdout.decode().strip() == "False"


@needs_corpus
def test_corpus_014_shows_its_drawing_pattern():
    path = CORPUS / "014_docs-apply-drawing-material.xaml"
    scene = xaml3d.load(path)
    brush = scene.viewports[0].models[0].material[0].brush
    assert isinstance(brush, DrawingBrush) and brush.tile_mode == "Tile"
    assert len(brush.drawing.children) == 6
    got = xaml3d.render(scene)
    expected = Image.open(ROOT / "tests" / "reference" / "_corpus" / f"{path.stem}.png")
    result = compare_images(expected, got)
    assert result.ok, result.reason
    # the pattern's colours are there: yellow, red, medium blue and grey tiles
    px = np.asarray(got.convert("RGBA")).reshape(-1, 4)
    opaque = px[px[:, 3] == 255, :3].astype(int)
    assert (opaque[:, 0] > 2 * opaque[:, 2] + 60).any()  # red / yellow
    assert (opaque[:, 2] > opaque[:, 0] + 60).any()  # blue


def test_text_is_measured_with_the_package_font_and_segoe_line_metrics():
    from xaml3d.text_metrics import baseline, line_height, text_width

    assert text_width("Hello World", 12.0) == pytest.approx(65.666, abs=0.01)  # Segoe UI: 63.8
    assert line_height(12.0) == pytest.approx(12 * 2724 / 2048)  # WPF: 15.96 px per line
    assert baseline(12.0) == pytest.approx(12 * 2210 / 2048)


def _visual_scene(visual: str, extra: str = "") -> str:
    return f"""<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml">{extra}
  <Viewport3D Width="64" Height="48">
    <Viewport3D.Camera><OrthographicCamera Position="0,0,10" Width="64"/></Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
      <GeometryModel3D><GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,16,0 -16,16,0"
            TriangleIndices="0 1 2 0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
      </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial>
        <DiffuseMaterial.Brush>{visual}</DiffuseMaterial.Brush>
      </DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D></Grid>"""


def test_visual_brush_bound_by_element_name_draws_that_element(tmp_path):
    panel = '<Border x:Name="panel" Width="20" Height="10" Background="Lime"/>'
    path = tmp_path / "s.xaml"
    path.write_text(_visual_scene('<VisualBrush Visual="{Binding ElementName=panel}"/>', panel))
    scene = xaml3d.load(path)
    brush = scene.viewports[0].models[0].material[0].brush
    assert isinstance(brush, DrawingBrush) and brush.kind == "VisualBrush"
    rgba = xaml3d.render_arrays(scene).rgba
    # the lime 20x10 border fills the whole square (Viewbox relative to its bounds, Fill)
    assert (rgba[8:40, 16:48] == (0, 255, 0, 255)).all()
    assert not {d.code for d in scene.diagnostics if d.code.startswith(("BRU", "DRW"))}


def test_textblock_in_a_visual_brush_sits_where_wpf_lays_it_out(tmp_path):
    path = tmp_path / "s.xaml"
    tb = '<TextBlock Text="x" FontSize="24" Padding="4,2,0,0" Background="Blue"/>'
    path.write_text(_visual_scene(f"<VisualBrush><VisualBrush.Visual>{tb}"
                                  "</VisualBrush.Visual></VisualBrush>"))  # fmt: skip
    scene = xaml3d.load(path)
    group = scene.viewports[0].models[0].material[0].brush.drawing.children[0]
    background, text = group.children
    from xaml3d.text_metrics import text_width

    w = text_width("x", 24.0) + 4
    assert background.geometry.rect == pytest.approx((0.0, 0.0, w, 2 + 24 * 2724 / 2048))
    assert text.origin == pytest.approx((4.0, 2 + 24 * 2210 / 2048))
    assert text.font_size == 24.0 and text.brush.color == (0.0, 0.0, 0.0, 1.0)


PICTURE = ROOT / "tests" / "reference" / "picture"


def test_render_transform_origin_is_folded_into_the_matrix():
    vp = xaml3d.load(PICTURE / "render-transform-flip.xaml").viewports[0]
    # ScaleY=-1 about (0.5, 0.5) of 64 x 48: y' = 48 - y
    assert np.array_equal(vp.picture.render_transform, [[1, 0, 0], [0, -1, 48], [0, 0, 1]])
    assert vp.picture.changes_picture and vp.picture.edge_mode == "Unspecified"


def test_effect_defaults_and_edge_mode_alone():
    shadow = xaml3d.load(PICTURE / "drop-shadow.xaml").viewports[0].picture.effect
    assert (shadow.kind, shadow.direction, shadow.shadow_depth, shadow.radius) == (
        "DropShadow", 270.0, 4.0, 0.0,
    )  # fmt: skip
    assert shadow.color == (0.0, 0.0, 0.0, 1.0) and shadow.opacity == 1.0
    aliased = xaml3d.load(PICTURE / "aliased-edges.xaml").viewports[0].picture
    assert aliased.edge_mode == "Aliased" and not aliased.changes_picture


def test_an_effect_from_another_assembly_is_an_info_and_is_not_applied(tmp_path):
    text = (PICTURE / "opacity.xaml").read_text().replace(' Opacity="0.5"', "")
    text = text.replace(
        "</Viewport3D.Camera>",
        '</Viewport3D.Camera><Viewport3D.Effect><fx:Glow xmlns:fx="clr-namespace:Fx"/>'
        "</Viewport3D.Effect>",
    )
    path = tmp_path / "s.xaml"
    path.write_text(text)
    scene = xaml3d.load(path)
    assert scene.viewports[0].picture is None  # drawn without it
    [found] = [d for d in scene.diagnostics if d.code in ("DRW003", "XAML001")]
    assert (found.code, found.severity) == ("DRW003", "info")
    assert "Glow" in found.message and "drawn without it" in found.message


def test_viewport_opacity_fades_the_picture_not_the_background():
    scene = xaml3d.load(PICTURE / "opacity.xaml")
    rgba = xaml3d.render_arrays(scene, background=(1.0, 1.0, 1.0, 1.0)).rgba
    # lime at 50% over white (the picture's alpha is 8-bit: 128/255)
    assert np.abs(rgba[12, 20].astype(int) - (128, 255, 128, 255)).max() <= 1
    assert tuple(rgba[0, 0]) == (255, 255, 255, 255)  # the background itself is not faded


def test_aliased_edges_unless_anti_aliasing_is_asked_for():
    scene = xaml3d.load(PICTURE / "aliased-edges.xaml")
    plain = xaml3d.render_arrays(scene).rgba.reshape(-1, 4)
    assert len(np.unique(plain, axis=0)) == 3  # lime, blue, transparent: no edge blends
    smooth = xaml3d.render_arrays(scene, msaa=2).rgba.reshape(-1, 4)
    assert len(np.unique(smooth, axis=0)) > 3  # an explicit --msaa still anti-aliases


def test_cli_renders_a_blurred_viewport(tmp_path):
    out = tmp_path / "b.png"
    p = subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", str(PICTURE / "blur.xaml"), "-o", str(out)],
        capture_output=True,
        timeout=120,
    )
    assert p.returncode == 0 and b"Traceback" not in p.stderr
    expected = Image.open(PICTURE / "blur.png")
    assert compare_images(expected, Image.open(out)).ok


def test_progress_bar_in_aero2_look(tmp_path):
    bar = '<ProgressBar Width="102" Height="10" Value="25"/>'
    path = tmp_path / "s.xaml"
    path.write_text(_visual_scene(f"<VisualBrush><VisualBrush.Visual>{bar}"
                                  "</VisualBrush.Visual></VisualBrush>"))  # fmt: skip
    drawing = xaml3d.load(path).viewports[0].models[0].material[0].brush.drawing
    face, band, *rest = _geometries(drawing)  # the theme template's Border first
    assert face.brush.color[:3] == pytest.approx((0xE6 / 255,) * 3)
    assert face.geometry.rect == (1.0, 1.0, 100.0, 8.0)
    assert band.brush.color[:3] == pytest.approx((0xBC / 255,) * 3)
    # PART_Indicator: a quarter of PART_Track's 102 px from the left, over the Border, #06B025
    green = (6 / 255, 0xB0 / 255, 0x25 / 255)
    filled = [g for g in rest if g.brush is not None and g.brush.color[:3] == pytest.approx(green)]
    assert filled and all(g.geometry.rect == (0.0, 0.0, 25.5, 10.0) for g in filled)


def test_outer_glow_is_an_unmoved_shadow_and_bitmap_scaling_mode_is_said(tmp_path):
    text = (
        (PICTURE / "opacity.xaml")
        .read_text()
        .replace(' Opacity="0.5"', ' RenderOptions.BitmapScalingMode="NearestNeighbor"')
    )
    text = text.replace(
        "</Viewport3D.Camera>",
        "</Viewport3D.Camera><Viewport3D.BitmapEffect>"
        '<OuterGlowBitmapEffect GlowColor="Red" GlowSize="6"/></Viewport3D.BitmapEffect>',
    )
    path = tmp_path / "s.xaml"
    path.write_text(text)
    scene = xaml3d.load(path)
    e = scene.viewports[0].picture.effect
    assert (e.kind, e.shadow_depth, e.radius, e.color) == ("DropShadow", 0.0, 6.0, (1, 0, 0, 1))
    [d] = [d for d in scene.diagnostics if d.code == "DRW003"]
    assert "BitmapScalingMode" in d.message and d.severity == "info"
    rgba = xaml3d.render_arrays(scene).rgba
    # the glow shows around the picture, red, fading outwards; the picture itself is intact
    assert rgba[6, 32, 0] == 255 and rgba[6, 32, 3] > rgba[4, 32, 3] > 0
    assert tuple(rgba[12, 20]) == (0, 255, 0, 255)


def test_textblock_wraps_to_its_width(tmp_path):
    from xaml3d.text_metrics import line_height, text_width

    tb = '<TextBlock Width="60" TextWrapping="Wrap" Text="one two three four" Background="Blue"/>'
    path = tmp_path / "s.xaml"
    path.write_text(_visual_scene(f"<VisualBrush><VisualBrush.Visual>{tb}"
                                  "</VisualBrush.Visual></VisualBrush>"))  # fmt: skip
    group = xaml3d.load(path).viewports[0].models[0].material[0].brush.drawing.children[0]
    background, lines = group.children
    words = [t.text for t in lines.children]
    assert all(text_width(t, 12.0) <= 60 for t in words) and " ".join(words) == "one two three four"
    assert len(words) > 1
    # one line box per line, baselines one LineSpacing apart
    assert background.geometry.rect[3] == pytest.approx(len(words) * line_height(12.0))
    ys = [t.origin[1] for t in lines.children]
    assert np.allclose(np.diff(ys), line_height(12.0))


def test_closed_combo_box_shows_its_selected_item(tmp_path):
    from xaml3d.text_metrics import line_height

    scene, drawing = _control_drawing(
        tmp_path,
        '<ComboBox SelectedIndex="1"><ComboBoxItem>Alpha</ComboBoxItem>'
        "<ComboBoxItem>Beta</ComboBoxItem></ComboBox>",
    )
    assert [t for t, _, _ in _texts(drawing)] == ["Beta"]
    # the theme's template: the presenter at Padding 6,3,5,3 beside the button's 1 px border,
    # so the box is the text's line and 3 + 3 tall (22 px at 12 px Segoe UI): its face, inside
    # templateRoot's 1 px #FFACACAC border, 2 px less
    rects = [g for g in _geometries(drawing) if isinstance(g.geometry, RectangleGeometry)]
    assert max(g.geometry.rect[3] for g in rects) == pytest.approx(line_height(12.0) + 4)
    grey = (0xAC / 255,) * 3
    assert any(tuple(getattr(b, "color", (0, 0, 0))[:3]) == pytest.approx(grey)
               for b in _fills(drawing))  # fmt: skip


def test_slider_thumb_at_its_value(tmp_path):
    slider = '<Slider Width="111" Value="5"/>'
    path = tmp_path / "s.xaml"
    path.write_text(_visual_scene(f"<VisualBrush><VisualBrush.Visual>{slider}"
                                  "</VisualBrush.Visual></VisualBrush>"))  # fmt: skip
    group = xaml3d.load(path).viewports[0].models[0].material[0].brush.drawing.children[0]
    track, thumb = group.children
    # halfway (5 of 0..10) along the 100 px the 11 px thumb can travel; 18 px tall slider
    assert thumb.geometry.rect == (50.5, 0.5, 10.0, 17.0)
    assert track.transform[0, 2] == 5.5 and track.transform[1, 2] == 7.0


def test_start_and_end_caps_are_each_ends_own():
    from xaml3d.render.layer2d.paint import rasterize

    pen = Pen(brush=LIME, thickness=4.0, start_cap="Square", end_cap="Round")
    line = GeometryDrawing(PathGeometry((("M", 4.0, 8.0), ("L", 12.0, 8.0))), pen=pen)
    a = rasterize(line, 16, 16)[..., 3]
    assert a[6:10, 2:4].min() == 1.0  # the square start reaches 2 px before the line's start
    assert a[8, 14] == 0.0 and 0.0 < a[7, 13] < 1.0  # the round end is a half disc, AA edge
    assert a[6, 13] < a[8, 13]  # rounder than a square: thinner away from the axis


def test_a_figure_that_is_not_filled_is_only_stroked():
    from xaml3d.render.layer2d.paint import rasterize

    square = (("L", 12.0, 4.0), ("L", 12.0, 12.0), ("L", 4.0, 12.0), ("Z",))
    for start, inside in (("M", 1.0), ("M-", 0.0)):
        g = GeometryDrawing(PathGeometry(((start, 4.0, 4.0), *square)), brush=LIME)
        assert rasterize(g, 16, 16)[8, 8, 3] == inside


def test_drawing_group_opacity_mask_in_the_groups_own_coordinates():
    from xaml3d.render.layer2d.paint import rasterize
    from xaml3d.scene.types import GradientStop, LinearGradientBrush

    fade = LinearGradientBrush(
        stops=(GradientStop((0, 0, 0, 1.0), 0.0), GradientStop((0, 0, 0, 0.0), 1.0)),
        start_point=(0.0, 0.5), end_point=(1.0, 0.5),
    )  # fmt: skip
    moved = np.array([[1.0, 0, 8.0], [0, 1.0, 0], [0, 0, 1.0]])
    g = DrawingGroup(
        children=(GeometryDrawing(RectangleGeometry((0.0, 0.0, 8.0, 8.0)), brush=LIME),),
        transform=moved, opacity_mask=fade,
    )  # fmt: skip
    a = rasterize(g, 16, 8)[4, :, 3]
    assert (a[:8] == 0).all()  # moved right by 8: nothing on the left
    # the mask fades across the square itself: opaque at its left edge, clear at its right
    assert a[8] > 0.85 and a[15] < 0.15 and (np.diff(a[8:]) < 0).all()


def _texts(drawing, origin=(0.0, 0.0)) -> list:
    """(text, x, y of its baseline origin) of every TextDrawing in a drawing tree."""
    if isinstance(drawing, DrawingGroup):
        if drawing.transform is not None:
            m = drawing.transform
            origin = (origin[0] + m[0, 2], origin[1] + m[1, 2])  # translations only here
        return [t for k in drawing.children for t in _texts(k, origin)]
    if isinstance(drawing, TextDrawing):
        return [(drawing.text, origin[0] + drawing.origin[0], origin[1] + drawing.origin[1])]
    return []


def test_a_buttons_element_content_is_laid_out_inside_its_chrome(tmp_path):
    # Aero2's Button: a 1 px border, Padding 1, the content centred; here a 4 px dot and a
    # TextBlock side by side in a 60 x 30 Button
    button = (
        "<Button Width='60' Height='30'><StackPanel Orientation='Horizontal'>"
        "<Ellipse Width='4' Height='4' Fill='Blue'/><TextBlock Text='Go'/></StackPanel></Button>"
    )
    path = tmp_path / "s.xaml"
    path.write_text(_visual_scene(f"<VisualBrush><VisualBrush.Visual>{button}"
                                  "</VisualBrush.Visual></VisualBrush>"))  # fmt: skip
    scene = xaml3d.load(path)
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]
    from xaml3d.text_metrics import baseline, line_height, text_width

    drawing = scene.viewports[0].models[0].material[0].brush.drawing
    [(text, x, y)] = _texts(drawing)
    content_w = 4 + text_width("Go", 12.0)
    left = (60 - content_w) / 2  # centred in the box inside the border and padding
    top = (30 - line_height(12.0)) / 2
    assert text == "Go"
    assert (x, y) == pytest.approx((left + 4, top + baseline(12.0)))


def _control_drawing(tmp_path, control: str):
    path = tmp_path / "s.xaml"
    path.write_text(_visual_scene(f"<VisualBrush><VisualBrush.Visual>{control}"
                                  "</VisualBrush.Visual></VisualBrush>"))  # fmt: skip
    scene = xaml3d.load(path)
    return scene, scene.viewports[0].models[0].material[0].brush.drawing


def _fills(drawing) -> list:
    """The brushes of every filled GeometryDrawing in a drawing tree, in paint order."""
    if isinstance(drawing, DrawingGroup):
        return [b for k in drawing.children for b in _fills(k)]
    if isinstance(drawing, GeometryDrawing) and drawing.brush is not None:
        return [drawing.brush]
    return []


def test_list_box_items_and_the_selected_items_highlight(tmp_path):
    from xaml3d.text_metrics import baseline, line_height

    scene, drawing = _control_drawing(
        tmp_path,
        "<ListBox SelectedIndex='1'><ListBoxItem>Alpha</ListBoxItem><ListBoxItem>Beta"
        "</ListBoxItem><TextBlock Text='Gamma'/></ListBox>",
    )
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]
    texts = _texts(drawing)
    # border 1 + the template's Padding 1, then each item's 1 px border and Padding 4,1
    row = line_height(12.0) + 4
    assert [t for t, _, _ in texts] == ["Alpha", "Beta", "Gamma"]
    for i, (_, x, y) in enumerate(texts):
        assert (x, y) == pytest.approx((7.0, 2 + i * row + 2 + baseline(12.0)))
    colors = [getattr(b, "color", None) for b in _fills(drawing)]
    # white inside the #FFABADB3 border; one item highlighted (#3DDADADA in #FFDADADA)
    assert colors[:2] == [(1.0, 1.0, 1.0, 1.0), (0xAB / 255, 0xAD / 255, 0xB3 / 255, 1.0)]
    assert colors.count((0xDA / 255,) * 3 + (0x3D / 255,)) == 1


def test_tab_control_shows_the_selected_tabs_content_only(tmp_path):
    scene, drawing = _control_drawing(
        tmp_path,
        "<TabControl SelectedIndex='1'><TabItem Header='One'><TextBlock Text='first'/></TabItem>"
        "<TabItem Header='Two'><TextBlock Text='second'/></TabItem></TabControl>",
    )
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]
    texts = {t: (x, y) for t, x, y in _texts(drawing)}
    assert set(texts) == {"One", "Two", "second"}
    from xaml3d.text_metrics import baseline, line_height, text_width

    # the headers from 2 px in, each its text plus Padding 6,2,6,2 and a 1 px border each
    # side; the selected one (Two) drawn last, its text 1 px up with its larger box
    one_w = text_width("One", 12.0) + 12 + 2
    assert texts["One"] == pytest.approx((2 + 1 + 6, 2 + 1 + 2 + baseline(12.0)))
    assert texts["Two"] == pytest.approx((2 + one_w + 1 + 6, 2 + 1 + 2 + baseline(12.0) - 1))
    # the content inside the 1 px border at Padding 2, below the header row
    row = 2 + 1 + 2 + line_height(12.0) + 2
    assert texts["second"] == pytest.approx((1 + 2, row + 1 + 2 + baseline(12.0)))
    assert _texts(drawing)[-2][0] == "Two"  # the selected tab over its neighbours


def test_group_box_and_expander(tmp_path):
    from xaml3d.text_metrics import baseline, line_height

    scene, drawing = _control_drawing(
        tmp_path,
        "<StackPanel><GroupBox Header='Group'><TextBlock Text='in'/></GroupBox>"
        "<Expander Header='More' IsExpanded='True'><TextBlock Text='shown'/></Expander>"
        "<Expander Header='Less'><TextBlock Text='hidden'/></Expander></StackPanel>",
    )
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]
    texts = {t: (x, y) for t, x, y in _texts(drawing)}
    assert set(texts) == {"Group", "in", "More", "shown", "Less"}
    line = line_height(12.0)
    # the header at Padding 3,1,3,0 in the 6 px column; the content 6 px in, below it
    assert texts["Group"] == pytest.approx((6 + 3, 1 + baseline(12.0)))
    assert texts["in"] == pytest.approx((6, 1 + line + baseline(12.0)))
    group_h = 1 + line + line + 6
    # the Expander: 1 px border, the toggle's 1 px margin, the 19 px circle, 4 px, the header
    # centred on the circle's row; the content below when IsExpanded
    assert texts["More"][0] == pytest.approx(1 + 1 + 19 + 4)
    assert texts["More"][1] == pytest.approx(group_h + 2 + (19 - line) / 2 + baseline(12.0))
    assert texts["shown"] == pytest.approx((1, group_h + 1 + 21 + baseline(12.0)))


def test_vertical_slider_and_separator(tmp_path):
    scene, drawing = _control_drawing(
        tmp_path,
        "<StackPanel Width='40'><Separator/><Slider Orientation='Vertical' Height='111' "
        "Value='3'/></StackPanel>",
    )
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]
    geometry = [k for k in _geometries(drawing)]
    separator = geometry[0]
    assert separator.geometry.rect == (0.0, 0.0, 40.0, 1.0)  # 2 px from the top: a group moves it
    # the 18 x 11 thumb 3/10 of the way up from the bottom: (111 - 11) * 0.7 from the top
    thumb = geometry[-1].geometry.rect
    assert thumb == pytest.approx((20 - 8.5, 70 + 0.5, 17.0, 10.0))


def _geometries(drawing) -> list:
    if isinstance(drawing, DrawingGroup):
        return [g for k in drawing.children for g in _geometries(k)]
    return [drawing] if isinstance(drawing, GeometryDrawing) else []


def test_a_window_background_drawing_brush_tiles_at_one_texel_a_pixel(tmp_path):
    # corpus 008's grid brush: a white 10 px tile with 1 px #66CCCCFF lines on its top and left
    lines = (
        '<GeometryDrawing Geometry="M0,0 L1,0 1,0.1, 0,0.1Z" Brush="#66CCCCFF"/>'
        '<GeometryDrawing Geometry="M0,0 L0,1 0.1,1, 0.1,0Z" Brush="#66CCCCFF"/>'
    )
    text = f"""<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
        Width="216" Height="139"><Grid><Grid.Background>
      <DrawingBrush Viewport="0,0,10,10" ViewportUnits="Absolute" TileMode="Tile">
        <DrawingBrush.Drawing><DrawingGroup>
          <GeometryDrawing Brush="White" Geometry="M0,0 L1,0 1,1 0,1Z"/>{lines}
        </DrawingGroup></DrawingBrush.Drawing></DrawingBrush></Grid.Background>
      <Viewport3D Margin="50"/></Grid></Window>"""
    path = tmp_path / "w.xaml"
    path.write_text(text)
    from xaml3d.render.window import compose_window

    rgba, _ = compose_window(xaml3d.load(path))
    assert rgba.shape == (100, 200, 4)
    line = (235, 235, 255, 255)  # 40% of #CCCCFF over white
    assert tuple(rgba[0, 5]) == line and tuple(rgba[5, 10]) == line and tuple(rgba[37, 40]) == line
    assert tuple(rgba[5, 5]) == (255, 255, 255, 255) and tuple(rgba[15, 13]) == (255, 255, 255, 255)


def _wrapped(inner_attrs: str, outer: str = "Grid") -> str:
    """The aliased-edges case's Viewport3D (its own EdgeMode removed) inside ``outer``."""
    text = (PICTURE / "aliased-edges.xaml").read_text()
    text = text.replace(' RenderOptions.EdgeMode="Aliased"', "")
    start = text.index("<Viewport3D")
    head = text[start:].split(">", 1)[0]
    ns = ' xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
    body = text[start:].replace(ns, "", 1)
    return f"<{outer}{ns} {inner_attrs}>{body}</{outer}>" if ns in head else ""


def test_edge_mode_set_around_the_viewport_is_inherited(tmp_path):
    # RenderOptions.EdgeMode is an inherited attached property: a panel's reaches the viewport
    path = tmp_path / "s.xaml"
    path.write_text(_wrapped('RenderOptions.EdgeMode="Aliased"'))
    scene = xaml3d.load(path)
    assert scene.viewports[0].picture.edge_mode == "Aliased"
    reference = xaml3d.render_arrays(xaml3d.load(PICTURE / "aliased-edges.xaml")).rgba
    assert np.array_equal(xaml3d.render_arrays(scene).rgba, reference)
    assert not [d for d in scene.diagnostics if d.code == "DRW006"]


def test_picture_properties_around_the_viewport_are_drawn(tmp_path):
    # a Border's Opacity and a Grid's Effect around the viewport act on its picture in turn
    path = tmp_path / "s.xaml"
    path.write_text(
        _wrapped('Opacity="0.5"', "Border")
        .replace("<Viewport3D", "<Grid><Grid.Effect><BlurEffect/></Grid.Effect><Viewport3D", 1)
        .replace("</Viewport3D>", "</Viewport3D></Grid>")
    )
    scene = xaml3d.load(path)
    assert not [d for d in scene.diagnostics if d.code == "DRW006"]
    around = scene.viewports[0].picture.around
    assert [a.layer.effect.kind if a.layer.effect else a.layer.opacity for a in around] == [
        "Blur",
        0.5,
    ]
    assert around[0].rect == (-288.0, -216.0, 640.0, 480.0)  # a 64 x 48 view centred in 640 x 480
    # an Opacity of 1 changes nothing: no layer
    path.write_text(_wrapped('Opacity="1"', "Border"))
    assert xaml3d.load(path).viewports[0].picture is None


def test_properties_around_a_viewport_the_layout_does_not_reach_are_said(tmp_path):
    # a viewport in a Button's ToolTip is not laid out: the Grid around it has no box
    path = tmp_path / "s.xaml"
    inner = _wrapped('Opacity="0.5"').replace(
        ' xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"', ""
    )
    path.write_text(
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"><Button>'
        f"<Button.ToolTip>{inner}</Button.ToolTip></Button></Grid>"
    )
    scene = xaml3d.load(path)
    [d] = [d for d in scene.diagnostics if d.code == "DRW006"]
    assert d.message.startswith("Grid around the viewport sets Opacity:")
    assert "the layout did not reach it" in d.message


@pytest.mark.parametrize(
    ("case", "own"),
    [("around-opacity", "opacity"), ("around-clip-offset", "clip"), ("around-blur", "blur")],
)
def test_a_layer_around_draws_as_the_viewports_own(case, own):
    around = xaml3d.render_arrays(xaml3d.load(PICTURE / f"{case}.xaml")).rgba
    assert np.array_equal(around, xaml3d.render_arrays(xaml3d.load(PICTURE / f"{own}.xaml")).rgba)


def test_window_draws_a_panels_layer_over_its_whole_content(tmp_path):
    from xaml3d.render.window import compose_window

    scene = xaml3d.load(PICTURE.parent / "layout" / "window-around-layer.xaml")
    [b] = [b for b in scene.layout.boxes if b.layer is not None]
    assert b.type == "Border" and b.layer.opacity == 0.5
    rgba, _ = compose_window(scene)
    # the Border's red, faded over the yellow Grid; turned: 48 wide, 64 tall
    assert np.abs(rgba[40, 26].astype(int) - (255, 128, 0, 255)).max() <= 1
    assert tuple(rgba[4, 26]) == (255, 255, 0, 255) and tuple(rgba[40, 20]) == (255, 255, 0, 255)
    assert np.abs(rgba[40, 56].astype(int) - (128, 255, 0, 255)).max() <= 1


def _glyphs(drawing) -> int:
    """GeometryDrawings in Aero2's option-mark glyph colour (#FF212121) in a drawing tree, not
    counting those under a group at Opacity 0 (the theme template's hidden marks)."""
    if isinstance(drawing, DrawingGroup):
        return 0 if drawing.opacity == 0 else sum(_glyphs(k) for k in drawing.children)
    brush = getattr(drawing, "brush", None)
    return int(isinstance(drawing, GeometryDrawing) and brush is not None
               and brush.color == (0x21 / 255, 0x21 / 255, 0x21 / 255, 1.0))  # fmt: skip


@pytest.mark.parametrize(
    "control, checked, glyphs",
    [("CheckBox", "True", 1), ("CheckBox", "False", 0), ("CheckBox", "{x:Null}", 1),
     ("RadioButton", "True", 1), ("RadioButton", "False", 0)],
)  # fmt: skip
def test_checked_option_controls_draw_their_mark(tmp_path, control, checked, glyphs):
    path = tmp_path / "s.xaml"
    path.write_text(_visual_scene(
        f'<VisualBrush><VisualBrush.Visual><{control} Content="x" IsChecked="{checked}"/>'
        "</VisualBrush.Visual></VisualBrush>"
    ))  # fmt: skip
    brush = xaml3d.load(path).viewports[0].models[0].material[0].brush
    assert _glyphs(brush.drawing) == glyphs


def test_window_controls_not_drawn_are_said(tmp_path):
    path = tmp_path / "w.xaml"
    path.write_text(
        '<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" Width="300"'
        ' Height="200"><DockPanel><DataGrid DockPanel.Dock="Left" Width="80"/>'
        '<ListBox DockPanel.Dock="Top"/><Viewport3D/></DockPanel></Window>'
    )
    found = [d for d in xaml3d.load(path).diagnostics if d.code == "DRW007"]
    assert [(d.severity, d.line, d.column) for d in found] == [("info", 1, 111)]
    assert found[0].message.startswith("DataGrid is not drawn by --window")


def _images(drawing) -> list:
    if isinstance(drawing, DrawingGroup):
        return [i for k in drawing.children for i in _images(k)]
    return [drawing] if type(drawing).__name__ == "ImageDrawing" else []


def test_bitmap_scaling_mode_reaches_the_images_of_a_visual_not_across_a_brush(tmp_path):
    from test_reference import REFERENCE

    case = REFERENCE / "layout" / "window-bitmap-scaling.xaml"
    scene = xaml3d.load(case)
    images = [i for b in scene.layout.boxes if b.drawing is not None for i in _images(b.drawing)]
    assert [i.scaling for i in images] == ["Unspecified", "NearestNeighbor"]
    # a Grid's mode stops at a VisualBrush drawn on a 3D surface; a wrong name is said
    text = (PICTURE / "opacity.xaml").read_text().replace(' Opacity="0.5"', "")
    brush = (
        '<VisualBrush><VisualBrush.Visual><Border RenderOptions.BitmapScalingMode="Fast">'
        f'<Image Source="{REFERENCE}/layout/textures/quad2x2.png" Width="4" Height="4"/>'
        "</Border></VisualBrush.Visual></VisualBrush>"
    )
    text = text.replace(
        '<DiffuseMaterial Brush="Lime" />',
        f"<DiffuseMaterial><DiffuseMaterial.Brush>{brush}</DiffuseMaterial.Brush></DiffuseMaterial>",
    )
    grid = text.index("<Viewport3D")
    text = (
        text[:grid]
        + '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        + 'RenderOptions.BitmapScalingMode="NearestNeighbor">'
        + text[grid:]
        + "</Grid>"
    )
    path = tmp_path / "s.xaml"
    path.write_text(text)
    scene = xaml3d.load(path)
    brushes = [m.brush for mo in scene.viewports[0].models for m in mo.material]
    [visual] = [b for b in brushes if getattr(b, "kind", None) == "VisualBrush"]
    assert [i.scaling for i in _images(visual.drawing)] == ["Unspecified"]
    [d] = [d for d in scene.diagnostics if d.code == "DRW003"]
    assert d.message == "RenderOptions.BitmapScalingMode 'Fast' is not a mode: Unspecified"


def test_an_animated_viewport_render_transform_is_a_track():
    from test_reference import REFERENCE

    from xaml3d.animation.moment import scene_at

    scene = xaml3d.load(REFERENCE / "animation" / "viewport-render-transform.xaml")
    assert not [d for d in scene.diagnostics if d.code == "ANIM014"]
    [track] = scene.tracks.tracks
    assert [str(p) for p in track.moves] == ["viewport 0 / picture . render_transform"]
    loaded = scene.viewports[0].picture.render_transform
    assert np.array_equal(scene_at(scene, 0.0).viewports[0].picture.render_transform, loaded)
    # half a turn about the centre (32, 24), then X: 8 at t = 0.5
    m = scene_at(scene, 0.5).viewports[0].picture.render_transform
    assert np.allclose(m, [[-1, 0, 64 + 8], [0, -1, 48], [0, 0, 1]])


def test_window_draws_a_viewports_render_transform_beyond_its_box(tmp_path):
    from xaml3d.render.window import compose_window

    text = (PICTURE / "opacity.xaml").read_text().replace(' Opacity="0.5"', "")
    text = text.replace(
        'Width="64" Height="48">',
        'Width="64" Height="48" HorizontalAlignment="Left"><Viewport3D.RenderTransform>'
        '<TranslateTransform X="64"/></Viewport3D.RenderTransform>',
    )
    start = text.index("<Viewport3D")
    ns = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
    body = text[start:].replace(f" {ns}", "", 1)
    path = tmp_path / "w.xaml"
    path.write_text(f'<Grid {ns} Width="128" Height="48" Background="White">{body}</Grid>')
    rgba, _ = compose_window(xaml3d.load(path))
    # the quads moved 64 px right, out of the viewport's 64 x 48 box, are drawn there
    assert tuple(rgba[12, 64 + 20]) == (0, 255, 0, 255)
    assert tuple(rgba[30, 64 + 20]) == (0, 0, 255, 255)
    assert tuple(rgba[12, 20]) == (255, 255, 255, 255)


def test_a_layer_inside_a_viewbox_is_in_the_elements_own_units(tmp_path):
    # a Grid of 32 x 24 scaled 2x by a Viewbox, translated by 8 of its own units: 16 px on
    # screen, for the viewport's picture and in the window
    from xaml3d.render.window import compose_window

    text = (PICTURE / "opacity.xaml").read_text().replace(' Opacity="0.5"', "")
    text = text.replace('Width="64" Height="48"', "")
    start = text.index("<Viewport3D")
    ns = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
    body = text[start:].replace(f" {ns}", "", 1)
    path = tmp_path / "v.xaml"
    path.write_text(
        f'<Grid {ns} Width="64" Height="48"><Viewbox><Grid Width="32" Height="24">'
        f'<Grid.RenderTransform><TranslateTransform X="8"/></Grid.RenderTransform>{body}'
        "</Grid></Viewbox></Grid>"
    )
    scene = xaml3d.load(path)
    [around] = scene.viewports[0].picture.around
    assert around.unit == (2.0, 2.0)
    rgba = xaml3d.render_arrays(scene).rgba
    assert rgba.shape == (48, 64, 4)
    assert tuple(rgba[12, 31]) == (0, 0, 0, 0) and tuple(rgba[12, 32]) == (0, 255, 0, 255)
    window, _ = compose_window(scene)
    assert np.array_equal(window, rgba)


def test_textblock_wraps_to_the_width_its_parent_gives(tmp_path):
    from xaml3d.text_metrics import line_height, text_width

    tb = '<TextBlock TextWrapping="Wrap" Text="one two three four" Background="Blue"/>'
    scene, drawing = _control_drawing(tmp_path, f'<StackPanel Width="60">{tb}</StackPanel>')
    words = [t for t, _, _ in _texts(drawing)]
    assert " ".join(words) == "one two three four" and len(words) > 1
    assert all(text_width(t, 12.0) <= 60 for t in words)
    # the TextBlock is as tall as its lines (its Background's box)
    [background] = [g for g in _geometries(drawing) if g.brush.color == (0.0, 0.0, 1.0, 1.0)]
    assert background.geometry.rect == pytest.approx((0, 0, 60, len(words) * line_height(12.0)))


def test_window_text_wraps_to_its_column_and_moves_the_viewport(tmp_path):
    from xaml3d.text_metrics import line_height, text_width

    path = tmp_path / "w.xaml"
    text = "one two three four five six"
    path.write_text(
        '<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" Width="116"'
        ' Height="239"><DockPanel><TextBlock DockPanel.Dock="Top" TextWrapping="Wrap"'
        f' Text="{text}"/><Viewport3D/></DockPanel></Window>'
    )
    scene = xaml3d.load(path)
    lines, line = [], ""
    for word in text.split():  # greedy breaking at spaces within the 100 px client width
        trial = f"{line} {word}".strip()
        if line and text_width(trial, 12.0) > 100:
            lines.append(line)
            line = word
        else:
            line = trial
    lines.append(line)
    assert len(lines) == 2
    vp = scene.viewports[0]
    assert (vp.width, vp.height) == pytest.approx((100, 200 - 2 * line_height(12.0)))


@pytest.mark.parametrize(
    "mode, text, expected",
    [("CharacterEllipsis", "Hello World", "Hello Wo\u2026"),
     ("WordEllipsis", "Hello World again", "Hello\u2026"),
     ("None", "Hello World", "Hello World")],
)  # fmt: skip
def test_text_trimming_cuts_the_line_to_the_laid_out_width(tmp_path, mode, text, expected):
    from xaml3d.text_metrics import text_width

    tb = f'<TextBlock TextTrimming="{mode}" Text="{text}"/>'
    scene, drawing = _control_drawing(tmp_path, f'<StackPanel Width="60">{tb}</StackPanel>')
    [(shown, _, _)] = _texts(drawing)
    assert shown == expected
    # the longest start that fits with the ellipsis: one more character (or word) does not
    longer = {
        "CharacterEllipsis": text[: len(shown)] + "\u2026",
        "WordEllipsis": "Hello World\u2026",
    }
    if mode in longer:
        assert text_width(shown, 12.0) <= 60 < text_width(longer[mode], 12.0)
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]


def test_an_open_combo_box_is_drawn_closed(tmp_path):
    # WPF shows the list in a Popup, a window of its own: never part of a visual's picture
    scene, drawing = _control_drawing(
        tmp_path,
        "<ComboBox IsDropDownOpen='True' SelectedIndex='0'><ComboBoxItem>Alpha</ComboBoxItem>"
        "<ComboBoxItem>Beta</ComboBoxItem></ComboBox>",
    )
    assert [t for t, _, _ in _texts(drawing)] == ["Alpha"]
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]


def test_scroll_bar_thumb_placed_as_wpfs_track(tmp_path):
    # a 100 px vertical bar: 17 px line buttons at the ends, a 66 px track; ViewportSize 50 of
    # a 0..100 range: the thumb is 66 * 50 / 150 = 22 px, a quarter of the rest down (Value 25)
    scene, drawing = _control_drawing(
        tmp_path, "<ScrollBar Height='100' Maximum='100' Value='25' ViewportSize='50'/>"
    )
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]
    rects = [(g.geometry.rect, g.brush.color) for g in _geometries(drawing)
             if isinstance(g.geometry, RectangleGeometry)]  # fmt: skip
    grey = 0xF0 / 255
    assert rects[0] == ((0.0, 0.0, 17.0, 100.0), (grey, grey, grey, 1.0))
    thumb, color = rects[-1]
    assert thumb == pytest.approx((0.0, 17 + (66 - 22) * 0.25, 17.0, 22.0))
    assert color == (0xCD / 255, 0xCD / 255, 0xCD / 255, 1.0)
    # nothing to scroll (Maximum = Minimum): WPF hides the thumb
    _, drawing = _control_drawing(tmp_path, "<ScrollBar Height='100' Maximum='0'/>")
    assert len([g for g in _geometries(drawing) if isinstance(g.geometry, RectangleGeometry)]) == 1


def test_a_check_boxs_element_content_sits_beside_its_mark(tmp_path):
    from xaml3d.text_metrics import baseline, line_height

    scene, drawing = _control_drawing(
        tmp_path,
        "<CheckBox IsChecked='True'><StackPanel><TextBlock Text='a'/><TextBlock Text='b'/>"
        "</StackPanel></CheckBox>",
    )
    assert not [d for d in scene.diagnostics if d.code == "DRW002"]
    assert _glyphs(drawing) == 1  # the check glyph in the theme template's mark
    # the content after the mark's 15.97 px column (the check Path's 9.97 px extent, its
    # Margin 1, the 1 px border, the Border's Margin 1) and 4 px, 1 px up (Padding 4,-1,0,0),
    # two lines below each other
    texts = _texts(drawing)
    line = line_height(12.0)
    x = pytest.approx(1 + 1 + 1 + 9.97498 + 1 + 1 + 1 + 4)
    assert texts == [("a", x, pytest.approx(-1 + baseline(12.0))),
                     ("b", x, pytest.approx(-1 + line + baseline(12.0)))]  # fmt: skip


def test_an_effect_counts_in_a_drawing_groups_bounds_as_wpf_counts_it():
    # WPF's Effect.GetRenderBounds: a blur spreads Radius every way; a drop shadow BlurRadius
    # every way and ShadowDepth along Direction (y up on screen)
    from xaml3d.render.layer2d.paint import drawing_bounds
    from xaml3d.scene.drawing import Effect, GeometryDrawing, RectangleGeometry

    square = GeometryDrawing(RectangleGeometry((10.0, 20.0, 16.0, 8.0)), brush=LIME)

    def bounds(effect):
        r = drawing_bounds(DrawingGroup(children=(square,), effect=effect))
        return tuple(round(v, 9) for v in (r.left(), r.top(), r.right(), r.bottom()))

    assert bounds(None) == (10, 20, 26, 28)
    assert bounds(Effect(kind="Blur", radius=4.0)) == (6, 16, 30, 32)
    shadow = Effect(kind="DropShadow", radius=2.0, direction=135.0, shadow_depth=2**0.5 * 3)
    assert bounds(shadow) == (5, 15, 28, 30)  # 3 left and 3 up, the blur 2 all round
    below = Effect(kind="DropShadow", radius=0.0, direction=270.0, shadow_depth=5.0)
    assert bounds(below) == (10, 20, 26, 33)


def test_an_animated_render_transform_and_opacity_around_a_viewport_are_tracks():
    from test_reference import REFERENCE

    from xaml3d.animation.moment import scene_at

    scene = xaml3d.load(REFERENCE / "animation" / "around-render-transform.xaml")
    assert not [d for d in scene.diagnostics if d.code.startswith("ANIM")]
    slide, fade = scene.tracks.tracks
    assert [str(p) for p in slide.moves] == [
        "viewport 0 / picture / around[0] / layer . render_transform",
        "layout / boxes[0] / layer . render_transform",
    ]
    assert [str(p) for p in fade.paths] == [
        "viewport 0 / picture / around[0] / layer . opacity",
        "layout / boxes[0] / layer . opacity",
    ]
    [around] = scene.viewports[0].picture.around
    assert around.layer.opacity == 1.0
    assert np.array_equal(around.layer.render_transform, np.eye(3))
    frame = scene_at(scene, 0.5)
    [moved] = frame.viewports[0].picture.around
    assert moved.layer.opacity == 0.75
    assert np.array_equal(moved.layer.render_transform, [[1, 0, 8], [0, 1, 0], [0, 0, 1]])
    box = frame.layout.boxes[0].layer
    assert box.opacity == 0.75 and box.render_transform[0, 2] == 8.0
    assert scene.layout.boxes[0].layer.opacity == 1.0  # the loaded scene is untouched


def test_a_panels_width_animation_resolves_and_is_said_to_be_laid_out_once():
    text = (
        '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
        'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" x:Name="g" Width="100">'
        '<Grid.Triggers><EventTrigger RoutedEvent="Grid.Loaded"><BeginStoryboard><Storyboard>'
        '<DoubleAnimation Storyboard.TargetName="g" Storyboard.TargetProperty="Width" To="50"/>'
        "</Storyboard></BeginStoryboard></EventTrigger></Grid.Triggers><Viewport3D/></Grid>"
    )
    codes = [d.code for d in xaml3d.load(text, text=True).diagnostics if d.code.startswith("ANIM")]
    assert codes == ["ANIM014"]


def test_an_animated_viewport_opacity_is_a_track():
    from test_reference import REFERENCE

    from xaml3d.animation.moment import scene_at

    text = (REFERENCE / "animation" / "viewport-render-transform.xaml").read_text()
    text = text.replace(
        'Storyboard.TargetProperty="X" From="0" To="16" Duration="0:0:1"/>',
        'Storyboard.TargetProperty="X" From="0" To="16" Duration="0:0:1"/>'
        '<DoubleAnimation Storyboard.TargetName="view" Storyboard.TargetProperty="Opacity" '
        'From="1" To="0.5" Duration="0:0:1"/>',
    ).replace('Width="64" Height="48"', 'x:Name="view" Width="64" Height="48"', 1)
    scene = xaml3d.load(text, text=True)
    assert not [d for d in scene.diagnostics if d.code.startswith("ANIM")]
    fade = scene.tracks.tracks[1]
    assert [str(p) for p in fade.paths] == ["viewport 0 / picture . opacity"]
    assert scene_at(scene, 0.5).viewports[0].picture.opacity == 0.75
    rgba = xaml3d.render_arrays(scene, time=1.0).rgba
    assert tuple(rgba[16, 40]) == (0, 0, 255, 128)  # blue, moved 16 right, half faded


def test_render_under_a_layout_transform_turns_the_buffers_with_the_picture():
    from test_reference import REFERENCE

    scene = xaml3d.load(REFERENCE / "layout" / "render-layout-transform.xaml")
    assert (scene.viewports[0].width, scene.viewports[0].height) == (64.0, 80.0)
    r = xaml3d.render_arrays(scene, ids=True)
    assert (r.width, r.height) == (80, 64)
    assert r.rgba.shape == (64, 80, 4) and r.ids.shape == r.depth.shape == (64, 80)
    # the lime quad (model 0) turned to the right of the blue one (model 1)
    assert tuple(r.rgba[30, 45]) == (0, 255, 0, 255) and r.ids[30, 45] == 0
    assert tuple(r.rgba[30, 30]) == (0, 0, 255, 255) and r.ids[30, 30] == 1
    assert r.ids[5, 5] == -1 and np.isinf(r.depth[5, 5]) and np.isnan(r.distance[5, 5])
    assert np.isfinite(r.distance[30, 30])


def test_menu_items_side_by_side_on_aero2s_bar(tmp_path):
    from xaml3d.text_metrics import baseline, line_height, text_width

    scene, drawing = _control_drawing(
        tmp_path,
        "<Menu><MenuItem Header='_File'><MenuItem Header='Open'/></MenuItem>"
        "<MenuItem Header='Edit'/><TextBlock Text='Help'/></Menu>",
    )
    assert not [d for d in scene.diagnostics if d.code in ("DRW002", "LAY003")]
    # each header at Padding 6,0 in a 1 px border; the access key's underscore not shown;
    # the sub-item is in the closed Popup; a TextBlock is wrapped in a MenuItem
    file_w = text_width("File", 12.0) + 12 + 2
    edit_w = text_width("Edit", 12.0) + 12 + 2
    texts = _texts(drawing)
    assert [t for t, _, _ in texts] == ["File", "Edit", "Help"]
    assert [x for _, x, _ in texts] == pytest.approx([7.0, file_w + 7, file_w + edit_w + 7])
    assert [y for _, _, y in texts] == pytest.approx([1 + baseline(12.0)] * 3)
    bar = _geometries(drawing)[0]
    help_w = text_width("Help", 12.0) + 12 + 2
    assert bar.geometry.rect == pytest.approx((0, 0, file_w + edit_w + help_w,
                                               line_height(12.0) + 2))  # fmt: skip
    assert bar.brush.color == (0xF0 / 255,) * 3 + (1.0,)  # Menu.Static.Background
    # Menu.Static.Foreground for the headers
    inks = [t.brush.color for t in _text_drawings(drawing)]
    assert inks[:2] == [(0x21 / 255,) * 3 + (1.0,)] * 2


def test_tool_bar_items_grip_and_overflow_as_aero2s(tmp_path):
    from xaml3d.text_metrics import baseline, line_height, text_width

    scene, drawing = _control_drawing(
        tmp_path,
        "<ToolBar><Button Content='Open'/><Separator/><Button Content='Save'/></ToolBar>",
    )
    assert not [d for d in scene.diagnostics if d.code in ("DRW002", "LAY003")]
    open_w, save_w = (text_width(t, 12.0) + 6 for t in ("Open", "Save"))
    # Grid Margin 3,1,1,1; the grip 10 px at Margin -3,-1; the items at Margin 0,1,2,2; the
    # main panel 11 px short of the right edge, over the 15 px overflow button
    width = 3 + 7 + open_w + 5 + save_w + 2 + 11 + 1
    height = 1 + 1 + line_height(12.0) + 6 + 2 + 1
    texts = _texts(drawing)
    assert [t for t, _, _ in texts] == ["Open", "Save"]
    assert [x for _, x, _ in texts] == pytest.approx([13.0, 10 + open_w + 5 + 3])
    assert [y for _, _, y in texts] == pytest.approx([2 + 3 + baseline(12.0)] * 2)
    shapes = _placed_rects(drawing)
    bar = (0xEE / 255, 0xF5 / 255, 0xFD / 255, 1.0)
    overflow, main = [(r, g) for r, g in shapes if getattr(g.brush, "color", None) == bar]
    assert overflow[0] == pytest.approx((width - 16, 1, 15, height - 2))
    assert main[0] == pytest.approx((3, 1, width - 15, height - 2))
    assert main[1].geometry.radius_x == 3.0
    # the separator: 1 px of #FFB6BDC5 across the bar at Margin 2
    (line,) = [r for r, g in shapes if getattr(g.brush, "color", None) == _rgb("B6BDC5")]
    assert line == pytest.approx((10 + open_w + 2, 4, 1, height - 2 - 3 - 4))
    # the grip's dots every 4 px from 5 px down, 6 px in (ToolBarGripper #FF6D6D6D)
    dots = [r for r, g in shapes if getattr(g.brush, "color", None) == _rgb("6D6D6D")]
    assert [r[:2] for r in dots[:2]] == [(6.0, 5.0), (6.0, 9.0)]


def _placed_rects(drawing, origin=(0.0, 0.0)) -> list:
    """(absolute rect, drawing) of every RectangleGeometry fill in a drawing tree (the groups
    here only translate)."""
    if isinstance(drawing, DrawingGroup):
        if drawing.transform is not None:
            m = drawing.transform
            origin = (origin[0] + m[0, 2], origin[1] + m[1, 2])
        return [t for k in drawing.children for t in _placed_rects(k, origin)]
    if isinstance(drawing, GeometryDrawing) and isinstance(drawing.geometry, RectangleGeometry):
        x, y, w, h = drawing.geometry.rect
        return [((origin[0] + x, origin[1] + y, w, h), drawing)]
    return []


def _rgb(hex6: str) -> tuple:
    return tuple(int(hex6[i : i + 2], 16) / 255 for i in (0, 2, 4)) + (1.0,)


def test_date_picker_shows_the_watermark_or_the_date(tmp_path):
    from xaml3d.text_metrics import baseline, text_width

    scene, drawing = _control_drawing(
        tmp_path,
        "<StackPanel><DatePicker/><DatePicker SelectedDate='2024-01-05'/>"
        "<DatePicker SelectedDate='2024-01-05' SelectedDateFormat='Long'/></StackPanel>",
    )
    assert not [d for d in scene.diagnostics if d.code in ("DRW002", "LAY003")]
    row = 6 + 2724 / 2048 * 12 + 6  # 27.96 px each
    texts = _texts(drawing)
    assert [t for t, _, _ in texts] == ["Select a date", "1/5/2024", "Friday, January 5, 2024"]
    # the watermark 1 + 2 px inside the text box (border 1, Padding 2 in): 6 px in, 6 down;
    # a date 2 px inside the text view, at its top
    assert [x for _, x, _ in texts] == pytest.approx([6.0, 5.0, 5.0])
    assert [y for _, _, y in texts] == pytest.approx(
        [6 + baseline(12.0), row + 3 + baseline(12.0), 2 * row + 3 + baseline(12.0)]
    )
    # the Style's Foreground, #FF333333
    assert {t.brush.color for t in _text_drawings(drawing)} == {(0x33 / 255,) * 3 + (1.0,)}
    # the text boxes (white, CornerRadius 1) as wide as the widest content: the long date in
    # the text view, 2 px each side; the calendar button's column after them
    boxes = [r for r, g in _placed_rects(drawing)
             if g.geometry.radius_x == 1.0 and g.brush.color == (1.0, 1.0, 1.0, 1.0)]  # fmt: skip
    widest = text_width("Friday, January 5, 2024", 12.0) + 4
    assert boxes == [pytest.approx((3.0, 3 + i * row, widest, row - 6)) for i in range(3)]


def _text_drawings(drawing) -> list:
    if isinstance(drawing, DrawingGroup):
        return [t for k in drawing.children for t in _text_drawings(k)]
    return [drawing] if isinstance(drawing, TextDrawing) else []


def test_calendar_month_view_texts_and_marks(tmp_path):
    from xaml3d.text_metrics import baseline, line_height

    scene, drawing = _control_drawing(
        tmp_path, "<Calendar DisplayDate='2024-01-05' SelectedDate='2024-01-17'/>"
    )
    assert not [d for d in scene.diagnostics if d.code in ("DRW002", "LAY003")]
    texts = _text_drawings(drawing)
    assert [t.text for t in texts[:8]] == ["January 2024", "Su", "Mo", "Tu", "We", "Th", "Fr", "Sa"]
    days = [t.text for t in texts[8:]]
    assert days[:2] == ["31", "1"] and days[-1] == "10" and len(days) == 42
    grey, ink = (0x77 / 255,) * 3 + (1.0,), (0x33 / 255,) * 3 + (1.0,)
    assert [t.brush.color for t in texts[8:10]] == [grey, ink]  # December's 31st, then the 1st
    # the title 3 + 3 px in (Margin 0,3 and the borders), at Margin 1,4,1,9
    (_, _, title_y) = _texts(drawing)[0]
    assert title_y == pytest.approx(3 + 3 + 4 + baseline(10.5))
    # the selected day's cell: #FFBADDE9 at Opacity .75, rounded 1 px
    blue = (0xBA / 255, 0xDD / 255, 0xE9 / 255, 0.75)
    (cell,) = [g for _, g in _placed_rects(drawing) if getattr(g.brush, "color", None) == blue]
    assert cell.geometry.rect[3] == pytest.approx(line_height(10.0) + 2)


RADIAL_MASK = """<RadialGradientBrush><GradientStop Offset="0" Color="#FF000000"/>
  <GradientStop Offset="1" Color="#00000000"/></RadialGradientBrush>"""


def test_an_opacity_mask_hides_the_antialiased_edge_where_it_is_clear(tmp_path):
    """Corpus 009's faint line: a Rectangle at half-pixel offsets (its edge pixels half
    covered) masked by a RadialGradientBrush, clear at the rectangle's edge. WPF multiplies
    the content by the mask wherever it is: the edge pixels, whose centres lie on the edge
    (offset 1: alpha 0), show the background alone, not a quarter of the fill."""
    text = f"""<Canvas xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
        Width="64" Height="44" Background="Black">
      <Rectangle Canvas.Left="10.5" Canvas.Top="10.5" Width="40" Height="20" Fill="White">
        <Rectangle.OpacityMask>{RADIAL_MASK}</Rectangle.OpacityMask></Rectangle>
      <Viewport3D Canvas.Left="60" Canvas.Top="40" Width="2" Height="2"/></Canvas>"""
    path = tmp_path / "m.xaml"
    path.write_text(text)
    from xaml3d.render.window import compose_window

    rgba, _ = compose_window(xaml3d.load(path))
    assert rgba.shape == (44, 64, 4)
    black = (0, 0, 0, 255)
    for row in (10, 30):  # the top and bottom edges, each pixel half covered
        assert {tuple(p) for p in rgba[row, 8:54]} == {black}
    for col in (10, 50):  # the left and right edges
        assert {tuple(p) for p in rgba[8:34, col]} == {black}
    assert tuple(rgba[20, 30]) == (255, 255, 255, 255)  # the centre: the mask's first stop
    # the mask fades towards the edges: along the middle row, bright in, dark out
    mid = rgba[20, 11:30, 0].astype(int)
    assert (np.diff(mid) >= 0).all() and mid[0] < 40 and mid[-1] > 240


def test_a_viewports_opacity_mask_covers_its_edge_pixels(tmp_path):
    """The same for a Viewport3D's own OpacityMask (``layer2d.picture``): a viewport at a
    half-pixel offset whose picture is a white quad filling it."""
    quad = "-20,-10,0 20,-10,0 20,10,0 -20,10,0"
    text = f"""<Canvas xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
        Width="64" Height="44" Background="Black">
      <Viewport3D Canvas.Left="10.5" Canvas.Top="10.5" Width="40" Height="20">
        <Viewport3D.OpacityMask>{RADIAL_MASK}</Viewport3D.OpacityMask>
        <Viewport3D.Camera><OrthographicCamera Position="0,0,10" LookDirection="0,0,-1"
          Width="40"/></Viewport3D.Camera>
        <ModelVisual3D><ModelVisual3D.Content><GeometryModel3D>
          <GeometryModel3D.Geometry><MeshGeometry3D Positions="{quad}"
            TriangleIndices="0 1 2  0 2 3"/></GeometryModel3D.Geometry>
          <GeometryModel3D.Material><EmissiveMaterial Brush="White"/></GeometryModel3D.Material>
        </GeometryModel3D></ModelVisual3D.Content></ModelVisual3D></Viewport3D></Canvas>"""
    path = tmp_path / "v.xaml"
    path.write_text(text)
    from xaml3d.render.window import compose_window

    rgba, _ = compose_window(xaml3d.load(path))
    black = (0, 0, 0, 255)
    for row in (10, 30):  # half covered by the picture (a quarter shown before: 127 here)
        assert {tuple(p) for p in rgba[row, 8:54]} == {black}
    for col in (10, 50):
        assert {tuple(p) for p in rgba[8:34, col]} == {black}
    assert rgba[20, 30, 0] >= 250 and rgba[11, 30, 0] > 0  # the picture inside, faded out


def test_a_drawing_groups_opacity_mask_covers_the_edge_pixels_of_its_content():
    """``layer2d.paint``: a DrawingGroup's OpacityMask multiplies all of its content, the
    antialiased edge pixels half outside the group's bounds too."""
    from xaml3d.render.layer2d.paint import rasterize
    from xaml3d.scene.types import GradientStop, RadialGradientBrush

    mask = RadialGradientBrush(
        stops=(GradientStop((0, 0, 0, 1.0), 0.0), GradientStop((0, 0, 0, 0.0), 1.0))
    )
    square = GeometryDrawing(RectangleGeometry((2.5, 2.5, 12.0, 12.0)), brush=LIME)
    a = rasterize(DrawingGroup(children=(square,), opacity_mask=mask), 18, 18)[..., 3]
    # pixels 2 and 14 are half covered, their centres on the edge (offset 1: alpha 0)
    assert (a[2, :] == 0).all() and (a[14, :] == 0).all()
    assert (a[:, 2] == 0).all() and (a[:, 14] == 0).all()
    assert a[8, 8] == 1.0 and 0 < a[8, 3] < a[8, 5] < a[8, 8]
