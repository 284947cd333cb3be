"""TextDecorations: TextDecorationCollectionConverter's syntax (xaml/values.py), where WPF draws
each decoration (xaml/visual_text.decoration_bars, the face's metrics from text_metrics), and
which runs carry them (the TextBlock's own, an inline's, every enclosing inline's)."""

from __future__ import annotations

import numpy as np
import pytest

import xaml3d
from xaml3d.errors import ValueSyntaxError
from xaml3d.scene.drawing import GeometryDrawing
from xaml3d.scene.text_runs import Run
from xaml3d.text_metrics import decoration_metrics
from xaml3d.xaml.values import parse_text_decorations
from xaml3d.xaml.visual_text import decoration_bars

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)


@pytest.mark.parametrize(
    ("text", "names"),
    [
        ("", set()),
        ("None", set()),
        (" none ", set()),
        ("Underline", {"Underline"}),
        ("strikethrough", {"Strikethrough"}),
        (" OverLine , Baseline ", {"OverLine", "Baseline"}),
        (
            "Underline,Strikethrough,Overline,Baseline",
            {"Underline", "Strikethrough", "OverLine", "Baseline"},
        ),
    ],
)
def test_the_converter_reads_names_separated_by_commas(text, names):
    assert parse_text_decorations(text) == frozenset(names)


@pytest.mark.parametrize(
    "text",
    [
        "Underline|Strikethrough",
        "Underline Strikethrough",
        "Underline,Underline",
        "None,Underline",
        "Wavy",
        "Underline,",
    ],
)
def test_what_the_converter_refuses(text):
    # WPF: ArgumentException (a XamlParseException at load): not a list of the four names
    with pytest.raises(ValueSyntaxError) as err:
        parse_text_decorations(text)
    assert err.value.code == "VAL005"


def test_each_decoration_at_the_faces_metrics():
    m = decoration_metrics(16.0)
    assert m.underline > 0 > m.strikeout and m.ascent > 0
    run = Run(
        "x", 16.0, decorations=frozenset({"Underline", "Strikethrough", "OverLine", "Baseline"})
    )
    assert decoration_bars(run) == [
        (-m.ascent, m.underline_thickness),
        (m.strikeout, m.strikeout_thickness),
        (0.0, m.underline_thickness),
        (m.underline, m.underline_thickness),
    ]
    assert decoration_bars(Run("x", 16.0)) == []


def _bars(tmp_path, body: str) -> list:
    path = tmp_path / "t.xaml"
    path.write_text(
        f'<Grid {NS} Width="200" Height="60"><Grid.ColumnDefinitions><ColumnDefinition '
        f'Width="160"/><ColumnDefinition/></Grid.ColumnDefinitions>{body}'
        '<Viewport3D Grid.Column="1"/></Grid>',
        encoding="utf-8",
    )
    scene = xaml3d.load(path)
    drawings = []

    def walk(d):
        if isinstance(d, GeometryDrawing):
            drawings.append(d)
        for k in getattr(d, "children", ()):
            walk(k)

    for b in scene.layout.boxes:
        if b.drawing is not None:
            walk(b.drawing)
    return [d for d in drawings if d.geometry.__class__.__name__ == "RectangleGeometry"], scene


def test_a_text_blocks_own_decorations_and_its_inlines(tmp_path):
    m = decoration_metrics(16.0)
    bars, scene = _bars(
        tmp_path, '<TextBlock Text="ab" FontSize="16" TextDecorations="Strikethrough, Underline"/>'
    )
    heights = sorted(round(b.geometry.rect[3], 6) for b in bars)
    assert heights == sorted([round(m.strikeout_thickness, 6), round(m.underline_thickness, 6)])
    tops = sorted(b.geometry.rect[1] for b in bars)
    assert np.isclose(tops[1] - tops[0], m.underline - m.strikeout)
    # an inline inside an Underline with its own Strikethrough: both bars under that run
    bars, _ = _bars(
        tmp_path,
        '<TextBlock FontSize="16"><Underline>u <Run '
        'TextDecorations="Strikethrough">s</Run></Underline></TextBlock>',
    )
    assert len(bars) == 3


def test_a_wrong_value_is_said_with_its_position(tmp_path):
    # WPF refuses the file: an error at the attribute (`validate` exits 1, `render` draws nothing)
    path = tmp_path / "t.xaml"
    path.write_text(
        f'<Grid {NS}><TextBlock Text="a" TextDecorations="Underline|Strikethrough"/>'
        "<Viewport3D/></Grid>",
        encoding="utf-8",
    )
    scene = xaml3d.load(path)
    found = [d for d in scene.diagnostics if d.code == "VAL005"]
    assert [(d.severity, d.line) for d in found] == [("error", 1)]
    assert "TextBlock.TextDecorations" in found[0].message
