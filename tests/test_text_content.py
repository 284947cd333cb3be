"""The text of TextBlock, TextBox and the content controls as WPF's XAML reader hands it over
(xaml3d/xaml/text_content.py, visual_text.py, inline_text.py, templates.py): the property
element forms (``<TextBlock.Text>``, ``<TextBlock.Inlines>``, ``<Button.Content>``,
``<ContentControl.Content>``, ``<Label.Content>``, ``<TextBox.Text>``) draw and measure as their
attribute forms do; white space is XAML's (collapsed, or kept by xml:space="preserve"); the
controls whose Aero2 template recognizes access keys show ``_Name`` as ``Name`` and measure the
shown text, a TextBlock shows the underscore. Checked in the boxes ``render --window`` draws, and
in a whole-window picture (a subprocess run of the CLI)."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from conftest import ROOT
from PIL import Image

from xaml3d.access_text import access_text
from xaml3d.pipeline import load
from xaml3d.scene.drawing import DrawingGroup, TextDrawing
from xaml3d.text_metrics import baseline, line_height, text_width
from xaml3d.xaml.text_content import xaml_text

NS = ('xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
      'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"')  # fmt: skip
LINE = line_height(12.0)


def _texts(d):
    if isinstance(d, DrawingGroup):
        for k in d.children:
            yield from _texts(k)
    elif isinstance(d, TextDrawing):
        yield d


def _window(content: str):
    """Every laid-out box of ``content`` (left-aligned in a StackPanel beside a viewport) and
    the texts drawn, in paint order."""
    s = load(f"<StackPanel {NS} Width='300' Height='300'>{content}"
             "<Viewport3D Height='10'/></StackPanel>", text=True)  # fmt: skip
    boxes = [b for b in s.layout.boxes[1:] if b.kind != "viewport"]
    return boxes, [t.text for b in boxes for t in _texts(b.drawing)]


# the property element form and the attribute form of one control: the same text, the same box
PAIRS = [
    ("<TextBlock><TextBlock.Text>Hello</TextBlock.Text></TextBlock>", '<TextBlock Text="Hello"/>'),
    ("<Button><Button.Content>OK</Button.Content></Button>", '<Button Content="OK"/>'),
    ("<Button><ContentControl.Content>text</ContentControl.Content></Button>",
     '<Button Content="text"/>'),
    ("<Label><Label.Content>\n   some   text\n</Label.Content></Label>",
     '<Label Content="some text"/>'),
    ("<TextBox><TextBox.Text>abc</TextBox.Text></TextBox>", '<TextBox Text="abc"/>'),
    ("<CheckBox><CheckBox.Content>Check</CheckBox.Content></CheckBox>",
     '<CheckBox Content="Check"/>'),
]  # fmt: skip


@pytest.mark.parametrize("element,attribute", PAIRS)
def test_a_property_element_draws_as_the_attribute_does(element, attribute):
    left = ' HorizontalAlignment="Left"'
    boxes, texts = _window(element.replace(">", left + ">", 1))
    expected_boxes, expected = _window(attribute.replace("/>", left + "/>"))
    assert texts == expected and texts and texts[0]
    assert [b.rect for b in boxes] == [b.rect for b in expected_boxes]


def test_text_block_inlines_property_element_is_drawn():
    boxes, texts = _window('<TextBlock HorizontalAlignment="Left"><TextBlock.Inlines>'
                           '<Run Text="a"/> <Bold>b</Bold><Run><Run.Text>c</Run.Text></Run>'
                           "</TextBlock.Inlines></TextBlock>")  # fmt: skip
    assert "".join(texts) == "a bc"
    [b] = boxes
    width = text_width("a ", 12.0) + text_width("b", 12.0, 700) + text_width("c", 12.0)
    assert b.rect[2] == pytest.approx(width, abs=0.5)


def test_white_space_is_xamls():
    assert xaml_text("\n  Hello \t  world\n") == "Hello world"
    assert xaml_text("a\u00a0  b") == "a\u00a0 b"  # a no-break space is text, not white space
    assert xaml_text("  a  b ", preserve=True) == "  a  b "
    _, texts = _window("<TextBlock><TextBlock.Text>\n  Hello \t world\n</TextBlock.Text>"
                       "</TextBlock><TextBlock>x&#160;&#160;y</TextBlock>")  # fmt: skip
    assert texts == ["Hello world", "x\u00a0\u00a0y"]


def test_xml_space_preserve_keeps_spaces_and_line_feeds():
    boxes, texts = _window('<TextBlock xml:space="preserve" HorizontalAlignment="Left">'
                           "a  b\nsecond</TextBlock>")  # fmt: skip
    assert texts == ["a  b", "second"]
    [b] = boxes
    assert b.rect[3] == pytest.approx(2 * LINE, abs=0.5)
    width = max(text_width("a  b", 12.0), text_width("second", 12.0))
    assert b.rect[2] == pytest.approx(width, abs=0.5)
    # inherited from an ancestor, and in inlines alike
    _, texts = _window('<StackPanel xml:space="preserve"><TextBlock>x  <Bold>y</Bold>'
                       "</TextBlock></StackPanel>")  # fmt: skip
    assert texts == ["x  ", "y"]


def test_access_text_rule():
    assert access_text("_Name") == "Name"
    assert access_text("Save _As") == "Save As"
    assert access_text("a__b") == "a_b"  # an escaped underscore
    assert access_text("__a_b_c") == "_ab_c"  # only the first lone marker goes
    assert access_text("end_") == "end_"  # a marker with no letter after it stays


@pytest.mark.parametrize("control", ["Label", "Button", "ToggleButton", "RepeatButton",
                                     "CheckBox", "RadioButton"])  # fmt: skip
def test_access_key_controls_show_and_measure_the_text_without_the_marker(control):
    boxes, texts = _window(f'<{control} Content="_Name" HorizontalAlignment="Left"/>')
    plain, expected = _window(f'<{control} Content="Name" HorizontalAlignment="Left"/>')
    assert texts == expected == ["Name"]
    assert boxes[0].rect == plain[0].rect
    _, texts = _window(f"<{control}><{control}.Content>Save__as</{control}.Content></{control}>")
    assert texts == ["Save_as"]


def test_text_block_text_box_and_a_text_block_in_a_button_show_the_underscore():
    boxes, texts = _window('<TextBlock Text="_Name" HorizontalAlignment="Left"/>'
                           '<TextBox Text="_Name"/>'
                           '<Button><TextBlock Text="_Inside"/></Button>'
                           '<ListBox><ListBoxItem Content="_Item"/></ListBox>')  # fmt: skip
    assert texts == ["_Name", "_Name", "_Inside", "_Item"]
    assert boxes[0].rect[2] == pytest.approx(text_width("_Name", 12.0), abs=0.5)


def test_headers_are_access_text_but_a_tool_bars_is_not():
    _, texts = _window('<GroupBox Header="_Group">in_side</GroupBox>'
                       '<Expander><Expander.Header>_More</Expander.Header></Expander>'
                       '<TabControl><TabItem Header="_One">page</TabItem></TabControl>'
                       '<Menu><MenuItem Header="_File"/><MenuItem Header="Save__All"/></Menu>'
                       '<ToolBar Header="_Tools"/>')  # fmt: skip
    assert texts == ["Group", "in_side", "More", "One", "page", "File", "Save_All", "_Tools"]


def test_combo_box_item_content_property_element():
    _, texts = _window('<ComboBox SelectedIndex="0"><ComboBoxItem><ComboBoxItem.Content>'
                       "_Alpha</ComboBoxItem.Content></ComboBoxItem></ComboBox>")  # fmt: skip
    assert texts == ["_Alpha"]  # a ComboBoxItem's presenter does not recognize access keys


WINDOW = f"""<Window {NS} Width="216" Height="139" Background="White" UseLayoutRounding="True">
  <StackPanel>
    <TextBlock><TextBlock.Text>Hello</TextBlock.Text></TextBlock>
    <Button HorizontalAlignment="Left" Width="60"><Button.Content>_OK</Button.Content></Button>
    <Label><Label.Content>_Name</Label.Content></Label>
    <Viewport3D Height="1"/>
  </StackPanel>
</Window>"""


def test_render_window_draws_property_element_text(tmp_path):
    """The CLI run: the texts given as property elements are drawn inside their boxes (dark
    glyph pixels where they were missing), and the access key is not underlined."""
    src = tmp_path / "w.xaml"
    src.write_text(WINDOW, encoding="utf-8")
    out = tmp_path / "w.png"
    r = subprocess.run([sys.executable, "-m", "xaml3d", "render", str(src), "-o", str(out),
                        "--window"], capture_output=True, text=True, cwd=ROOT,
                       timeout=300)  # fmt: skip
    assert r.returncode == 0, r.stderr
    rgb = np.asarray(Image.open(out).convert("RGB")).astype(int)
    assert rgb.shape == (100, 200, 3)
    dark = rgb.max(axis=2) < 110

    def ink(rows, cols):
        return dark[rows[0] : rows[1], cols[0] : cols[1]]

    hello = ink((0, 16), (0, 40))
    assert hello.sum() > 20  # "Hello" in the TextBlock's 16 px line
    # "OK" centred in the 60 x 20 Button from row 16: glyphs inside the face, none at its left
    button = ink((17, 35), (1, 59))
    rows, cols = np.nonzero(button)
    assert button.sum() > 15 and cols.min() + 1 > 18 and cols.max() + 1 < 42
    # "Name" (not "_Name") 5 px in from the Label's corner (row 36): its line from row 41
    label = ink((36, 62), (0, 60))
    lrows, lcols = np.nonzero(label)
    assert label.sum() > 15 and lcols.min() >= 5 and lrows.min() + 36 >= 41
    assert lcols.max() < 5 + text_width("Name", 12.0) + 1  # no marker drawn before the text
    # the access key is not underlined: nothing below the baselines ("OK" and "Name" have no
    # descenders; the line box of "OK" starts at row 18, that of "Name" at row 41)
    assert rows.max() + 17 <= 18 + round(baseline(12.0))
    assert lrows.max() + 36 <= 41 + round(baseline(12.0))
