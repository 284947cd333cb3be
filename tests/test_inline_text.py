"""A TextBlock's inlines (xaml3d/xaml/inline_text.py): Run (its Text attribute too), Bold,
Italic, Underline, Span and a Run's own Foreground / FontSize / FontWeight, LineBreak; drawn in
visuals and beside the viewports (render --window), measured with the font's metrics."""

from __future__ import annotations

import pytest

from xaml3d.pipeline import load
from xaml3d.scene.drawing import DrawingGroup, GeometryDrawing, TextDrawing
from xaml3d.text_metrics import baseline, line_height, text_width

NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
LINE = line_height(12.0)


def _window(text_block: str):
    """The TextBlock's box and its drawing's parts, laid out beside a viewport."""
    s = load(f"<StackPanel {NS} Width='300' Height='200'>{text_block}"
             "<Viewport3D Height='10'/></StackPanel>", text=True)  # fmt: skip
    [b] = [b for b in s.layout.boxes if b.type == "TextBlock"]
    return b, list(_parts(b.drawing))


def _parts(d):
    if isinstance(d, DrawingGroup):
        for k in d.children:
            yield from _parts(k)
    elif d is not None:
        yield d


def _texts(parts):
    return [p for p in parts if isinstance(p, TextDrawing)]


def test_run_text_attribute_is_drawn_between_the_text():
    b, parts = _window('<TextBlock>Plain text <Run Text="x"/> end</TextBlock>')
    assert "".join(t.text for t in _texts(parts)) == "Plain text x end"
    # the runs follow one another on one line, each at the end of the one before
    t = _texts(parts)
    assert t[1].origin[0] == pytest.approx(text_width("Plain text ", 12.0))
    assert b.rect[3] == pytest.approx(LINE)
    assert b.rect[2] == 300  # stretched; its measured width is the line's
    assert {p.origin[1] for p in t} == {baseline(12.0)}


def test_line_break_starts_a_new_line():
    b, parts = _window("<TextBlock>one <LineBreak/> two</TextBlock>")
    t = _texts(parts)
    assert [(p.text, p.origin) for p in t] == [
        ("one", (0.0, baseline(12.0))),
        ("two", (0.0, LINE + baseline(12.0))),
    ]
    assert b.rect[3] == pytest.approx(2 * LINE)


def test_runs_keep_their_own_format():
    b, parts = _window(
        "<TextBlock>a <Bold>b</Bold> <Italic>c</Italic> <Underline>d</Underline> "
        '<Span FontWeight="SemiBold">e</Span> <Run Foreground="Red" FontSize="24">f</Run>'
        "</TextBlock>"
    )
    t = {p.text.strip(): p for p in _texts(parts)}
    assert (t["b"].weight, t["c"].italic, t["e"].weight) == (700, True, 600)
    assert (t["a"].weight, t["a"].italic, t["a"].font_size) == (400, False, 12.0)
    assert t["f"].font_size == 24.0 and t["f"].brush.color == (1.0, 0.0, 0.0, 1.0)
    # the line is as tall as its 24 px run's line; every run sits on its baseline
    assert b.rect[3] == pytest.approx(line_height(24.0))
    assert {p.origin[1] for p in t.values()} == {baseline(24.0)}
    # the underline: a bar under "d" only, as wide as it, in its brush
    [bar] = [p for p in parts if isinstance(p, GeometryDrawing)]
    x, y, w, h = bar.geometry.rect
    assert (x, w) == (pytest.approx(t["d"].origin[0]), pytest.approx(text_width("d", 12.0)))
    assert baseline(24.0) < y < baseline(24.0) + 3 and 0 < h < 2


def test_inlines_wrap_at_spaces_across_runs():
    b, parts = _window(
        '<TextBlock TextWrapping="Wrap" Width="60">aaa <Bold>bbb ccc</Bold> ddd</TextBlock>'
    )
    t = _texts(parts)
    lines = sorted({p.origin[1] for p in t})
    assert len(lines) >= 2 and b.rect[3] == pytest.approx(len(lines) * LINE)
    for y in lines:
        row = [p for p in t if p.origin[1] == y]
        assert sum(text_width(p.text, 12.0, p.weight) for p in row) <= 60.5


def test_inlines_in_a_visual_brush():
    s = load(
        f"<Viewport3D {NS}><Viewport3D.Camera><OrthographicCamera Width='2'/></Viewport3D.Camera>"
        "<ModelVisual3D><ModelVisual3D.Content><GeometryModel3D><GeometryModel3D.Geometry>"
        "<MeshGeometry3D Positions='0,0,0 1,0,0 1,1,0' TriangleIndices='0 1 2' "
        "TextureCoordinates='0,0 1,0 1,1'/></GeometryModel3D.Geometry>"
        "<GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush><VisualBrush>"
        "<VisualBrush.Visual><TextBlock>a<LineBreak/><Run Text='b' FontWeight='Bold'/>"
        "</TextBlock></VisualBrush.Visual></VisualBrush></DiffuseMaterial.Brush>"
        "</DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>"
        "</ModelVisual3D.Content></ModelVisual3D></Viewport3D>",
        text=True,
    )
    drawing = s.viewports[0].models[0].material[0].brush.drawing
    t = [(p.text, p.weight, p.origin[1]) for p in _texts(_parts(drawing))]
    assert t == [("a", 400, baseline(12.0)), ("b", 700, LINE + baseline(12.0))]
