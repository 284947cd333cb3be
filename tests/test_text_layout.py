"""A TextBlock measured by layout (xaml3d/layout/text.py): the reader records its text as plain
data (scene/text_runs.py), the layout engine measures it with the metrics of the font that
draws it, breaks its lines at the width offered, and the drawing sets the lines layout left."""

from __future__ import annotations

import math

import pytest

from xaml3d.layout import layout
from xaml3d.layout.text import ELLIPSIS, lines, measure
from xaml3d.pipeline import load
from xaml3d.scene import element_tree as L
from xaml3d.scene.drawing import DrawingGroup, TextDrawing
from xaml3d.scene.element_tree import Node
from xaml3d.scene.text_runs import Run, TextContent
from xaml3d.text_metrics import baseline, line_height, text_width

NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
LINE = line_height(12.0)


def _block(content: TextContent, **kw) -> Node:
    return Node(L.CONTROL, "TextBlock", text=content, **kw)


def _stack(*children, width=400.0) -> Node:
    return Node(L.STACK, "StackPanel", width=width, height=300.0, children=list(children))


def test_plain_text_is_measured_in_its_own_font():
    bold = TextContent(Run("Hello world", 20.0, 700, False, "Arial"), padding=(1, 2, 3, 4))
    t = _block(bold, h_align="Left")
    layout(_stack(t))
    w = text_width("Hello world", 20.0, 700, False, "Arial")
    assert t.desired == (pytest.approx(w + 4), pytest.approx(line_height(20.0, "Arial") + 6))
    [line] = t.text_lines
    assert [r.text for r in line.runs] == ["Hello world"]
    assert line.width == w and line.baseline == baseline(20.0, "Arial")


def test_wrapping_breaks_at_the_width_offered_and_arrange_keeps_those_lines():
    text = "alpha beta gamma delta epsilon"
    room = text_width("alpha beta gamma", 12.0) + 1.0  # three words fit, four do not
    t = _block(TextContent(Run(text, 12.0), wrapping=True))
    layout(_stack(t, width=room))
    assert [x.runs[0].text for x in t.text_lines] == ["alpha beta gamma", "delta epsilon"]
    assert t.desired[1] == pytest.approx(2 * LINE)
    assert t.desired[0] == pytest.approx(text_width("alpha beta gamma", 12.0))
    assert not t.text_overflow


def test_trimming_cuts_the_line_at_the_arranged_width():
    t = _block(TextContent(Run("alpha beta gamma", 12.0), trimming="WordEllipsis"))
    room = text_width("alpha beta" + ELLIPSIS, 12.0) + 1.0
    layout(_stack(t, width=room))
    [line] = t.text_lines
    assert line.runs[0].text == "alpha beta" + ELLIPSIS
    assert t.desired[0] == pytest.approx(line.width)


def test_inline_runs_wrap_each_in_its_font_and_the_line_takes_the_tallest():
    small = Run("", 12.0)
    runs = ((Run("tiny words ", 12.0), Run("Big Words", 24.0, family="Times New Roman")),)
    content = TextContent(small, inlines=runs, wrapping=True)
    one = measure(content, math.inf)
    assert one[0] == pytest.approx(
        text_width("tiny words ", 12.0) + text_width("Big Words", 24.0, family="Times New Roman")
    )
    assert one[1] == pytest.approx(line_height(24.0, "Times New Roman"))
    # offered room for the first line only: "Big" and "Words" go on lines of their own
    at = text_width("tiny words", 12.0) + 1.0
    broken = lines(content, at)
    assert [[r.text for r in x.runs] for x in broken] == [["tiny words"], ["Big"], ["Words"]]
    assert [x.height for x in broken] == [
        LINE, line_height(24.0, "Times New Roman"), line_height(24.0, "Times New Roman")
    ]  # fmt: skip


def _texts(d):
    if isinstance(d, DrawingGroup):
        for k in d.children:
            yield from _texts(k)
    elif isinstance(d, TextDrawing):
        yield d


def test_the_window_draws_the_lines_layout_broke():
    text = "one two three four five six seven eight nine ten"
    s = load(f"<StackPanel {NS} Width='120' Height='200'>"
             "<TextBlock TextWrapping='Wrap' FontFamily='Courier New' FontSize='14'"
             f" Text='{text}'/>"
             "<Viewport3D Height='10'/></StackPanel>", text=True)  # fmt: skip
    [b] = [b for b in s.layout.boxes if b.type == "TextBlock"]
    drawn = [t.text for t in _texts(b.drawing)]
    # the lines as layout breaks them at the StackPanel's 120 px, in Courier New 14 px
    expect = [x.runs[0].text for x in lines(TextContent(Run(text, 14.0, family="Courier New"),
                                                        wrapping=True), 120.0)]  # fmt: skip
    assert drawn == expect and len(expect) > 2
    assert all(text_width(x, 14.0, family="Courier New") <= 120.5 for x in drawn)
    assert b.rect[3] == pytest.approx(len(expect) * line_height(14.0, "Courier New"))


def test_the_reader_records_the_runs_and_layout_measures_them():
    s = load(f"<StackPanel {NS} Width='300' Height='200'>"
             "<TextBlock HorizontalAlignment='Left'>a <Bold FontSize='20'>b</Bold><LineBreak/>"
             "c</TextBlock><Viewport3D Height='10'/></StackPanel>", text=True)  # fmt: skip
    [b] = [b for b in s.layout.boxes if b.type == "TextBlock"]
    parts = [(t.text, t.weight, t.font_size) for t in _texts(b.drawing)]
    assert parts == [("a ", 400, 12.0), ("b", 700, 20.0), ("c", 400, 12.0)]
    w = text_width("a ", 12.0) + text_width("b", 20.0, 700)
    assert b.rect[2] == pytest.approx(w)
    assert b.rect[3] == pytest.approx(line_height(20.0) + LINE)


def test_a_box_narrower_than_its_text_is_said_to_overflow():
    wide = _block(TextContent(Run("a line too long for its box", 12.0)), width=40.0)
    fits = _block(TextContent(Run("short", 12.0)), h_align="Left")
    layout(_stack(wide, fits))
    assert wide.ink == (40.0, pytest.approx(LINE)) and wide.text_overflow
    assert not fits.text_overflow
    # the line is kept whole (not wrapping, not trimmed): the layout clip cuts it at the box
    assert wide.text_lines[0].runs[0].text == "a line too long for its box"


def test_the_window_cuts_an_overflowing_text_at_its_box():
    s = load(f"<StackPanel {NS} Width='300' Height='200'>"
             "<TextBlock Width='40' HorizontalAlignment='Left' Text='a line too long'/>"
             "<Viewport3D Height='10'/></StackPanel>", text=True)  # fmt: skip
    [b] = [b for b in s.layout.boxes if b.type == "TextBlock"]
    assert isinstance(b.drawing, DrawingGroup)
    clip = b.drawing.clip
    assert clip is not None and clip.rect == (0.0, 0.0, 40.0, pytest.approx(LINE))
