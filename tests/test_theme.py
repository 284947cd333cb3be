"""The package's theme dictionary (xaml3d/data/themes/aero2.xaml, read by xaml3d.xaml.theme):
its Button family's Style and ControlTemplate are Aero2's (the only source of their look), it
is read once per process and only when a control needs it, and the framework
step reads a template-bound value from it below the document's Styles."""

from __future__ import annotations

import subprocess
import sys

import pytest
from lxml import etree

from xaml3d.framework.styles import Control, property_name, setter_value, setters
from xaml3d.xaml.context import qname, x_attr
from xaml3d.xaml.theme import theme_entries, theme_styles

BUTTONS = ("Button", "ToggleButton", "RepeatButton")


def _setters(chain) -> dict:
    out = {}
    for style in chain:
        for s in setters(style):
            out[property_name(s.get("Property"))] = setter_value(s)
    return out


def _kids(el) -> list:
    return [k for k in el if isinstance(k.tag, str)]


@pytest.mark.parametrize("control", BUTTONS)
def test_button_family_shares_aero2s_base_style(control):
    chain = theme_styles(control)
    assert [s.get("TargetType") for s in chain] == [
        "{x:Type ButtonBase}",
        "{x:Type " + control + "}",
    ]
    assert x_attr(chain[0], "Key") == "BaseButtonStyle"
    values = {p: v[1] for p, v in _setters(chain).items() if v[0] == "text"}
    assert values == {
        "Background": "#FFDDDDDD",
        "BorderBrush": "#FF707070",
        "Foreground": "#FF000000",
        "BorderThickness": "1",
        "HorizontalContentAlignment": "Center",
        "VerticalContentAlignment": "Center",
        "Padding": "1",
    }


def test_button_template_is_a_bound_border_around_a_content_presenter():
    kind, template = _setters(theme_styles("Button"))["Template"]
    assert kind == "element" and qname(template.tag)[1] == "ControlTemplate"
    visual = [k for k in _kids(template) if "." not in qname(k.tag)[1]]
    assert len(visual) == 1
    border = visual[0]
    assert qname(border.tag)[1] == "Border"
    assert x_attr(border, "Name") == "border"
    for prop in ("BorderThickness", "Background", "BorderBrush"):
        assert border.get(prop) == "{TemplateBinding " + prop + "}"
    (presenter,) = _kids(border)
    assert qname(presenter.tag)[1] == "ContentPresenter"
    assert presenter.get("Margin") == "{TemplateBinding Padding}"
    assert presenter.get("HorizontalAlignment") == "{TemplateBinding HorizontalContentAlignment}"
    assert presenter.get("VerticalAlignment") == "{TemplateBinding VerticalContentAlignment}"
    assert presenter.get("RecognizesAccessKey") == "True"
    (holder,) = [k for k in _kids(template) if qname(k.tag)[1] == "ControlTemplate.Triggers"]
    found = {}
    for trigger in _kids(holder):
        found[(trigger.get("Property"), trigger.get("Value"))] = {
            (s.get("TargetName"), s.get("Property")): s.get("Value") for s in setters(trigger)
        }
    assert found[("Button.IsDefaulted", "True")] == {("border", "BorderBrush"): "#FF0078D7"}
    assert found[("IsEnabled", "False")] == {
        ("border", "Background"): "#FFF4F4F4",
        ("border", "BorderBrush"): "#FFADB2B5",
        (None, "TextElement.Foreground"): "#FF838383",
    }
    assert found[("ToggleButton.IsChecked", "True")] == {
        ("border", "Background"): "#FFBCDDEE",
        ("border", "BorderBrush"): "#FF245A83",
    }
    # the input states WPF's theme lists: never true in a picture at rest
    assert ("IsMouseOver", "True") in found and ("IsPressed", "True") in found


def test_the_theme_keeps_its_brushes_by_aero2s_keys():
    entries = theme_entries()
    assert entries["Button.Static.Background"].get("Color") == "#FFDDDDDD"
    assert entries["Button.Disabled.Foreground"].get("Color") == "#FF838383"
    assert theme_styles("DataGrid") == []  # not written in the theme: no Style


def _template(chain):
    kind, template = _setters(chain)["Template"]
    assert kind == "element" and qname(template.tag)[1] == "ControlTemplate"
    (visual,) = [k for k in _kids(template) if "." not in qname(k.tag)[1]]
    (holder,) = [k for k in _kids(template) if qname(k.tag)[1] == "ControlTemplate.Triggers"]
    found = {}
    for trigger in _kids(holder):
        found[(trigger.get("Property"), trigger.get("Value"))] = {
            (s.get("TargetName"), s.get("Property")): s.get("Value") for s in setters(trigger)
        }
    return visual, found


def test_label_is_aero2s_bordered_content_presenter():
    chain = theme_styles("Label")
    values = {p: v[1] for p, v in _setters(chain).items() if v[0] == "text"}
    assert values == {
        "Foreground": "#FF000000",
        "Background": "Transparent",
        "Padding": "5",
        "HorizontalContentAlignment": "Left",
        "VerticalContentAlignment": "Top",
    }
    border, found = _template(chain)
    assert qname(border.tag)[1] == "Border" and border.get("Padding") == "{TemplateBinding Padding}"
    (presenter,) = _kids(border)
    assert qname(presenter.tag)[1] == "ContentPresenter"
    assert presenter.get("RecognizesAccessKey") == "True"
    assert found[("IsEnabled", "False")] == {(None, "Foreground"): "#FF6D6D6D"}


@pytest.mark.parametrize("control", ["TextBox", "PasswordBox"])
def test_text_boxes_are_aero2s_border_around_the_content_host(control):
    chain = theme_styles(control)
    values = {p: v[1] for p, v in _setters(chain).items() if v[0] == "text"}
    assert values["Background"] == "#FFFFFFFF" and values["BorderBrush"] == "#FFABADB3"
    assert values["BorderThickness"] == "1" and "Padding" not in values  # Aero2 sets none
    if control == "PasswordBox":
        assert values["PasswordChar"] == "\u25cf"
    else:
        assert x_attr(chain[0], "Key") == "TextBoxBaseStyle"
    border, found = _template(chain)
    assert qname(border.tag)[1] == "Border" and x_attr(border, "Name") == "border"
    (host,) = _kids(border)
    assert qname(host.tag)[1] == "ScrollViewer" and x_attr(host, "Name") == "PART_ContentHost"
    assert found[("IsEnabled", "False")] == {("border", "Opacity"): "0.56"}


READ_ONCE = """
import sys
from xaml3d.pipeline import load
from xaml3d.xaml.theme import theme_entries
load(sys.argv[1] + "/plain.xaml")
print(theme_entries.cache_info().currsize)
load(sys.argv[1] + "/button.xaml")
load(sys.argv[1] + "/button.xaml")
info = theme_entries.cache_info()
print(info.currsize, info.misses)
"""
HEAD = (
    '<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="80" Height="40">'
)
# a Button whose own template binds Background: the theme supplies the value
BOUND = """
  <Button Content="x">
    <Button.Template>
      <ControlTemplate TargetType="Button"><Border Background="{TemplateBinding Background}" />
      </ControlTemplate>
    </Button.Template>
  </Button>"""


def test_the_theme_is_read_once_and_only_when_a_control_needs_it(tmp_path):
    (tmp_path / "plain.xaml").write_text(HEAD + '<Rectangle Fill="Red" /></Grid>', "utf-8")
    (tmp_path / "button.xaml").write_text(HEAD + BOUND + "</Grid>", "utf-8")
    run = subprocess.run(
        [sys.executable, "-c", READ_ONCE, str(tmp_path)],
        capture_output=True,
        text=True,
        check=True,
    )
    assert run.stdout.split() == ["0", "1", "1"]


def test_a_template_binding_reads_the_theme_below_the_documents_style():
    class Services:  # the reader's services a Control asks for
        def __init__(self, style=None):
            self.style = style

        def implicit_style(self, type_name, from_el):
            return self.style

        def find(self, key, from_el):
            return None

        def theme_styles(self, type_name):
            return theme_styles(type_name)

    ns = "http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    style = etree.fromstring(
        f'<Style xmlns="{ns}" TargetType="Button"><Setter Property="Padding" Value="4" /></Style>'
    )
    button = etree.fromstring(f'<Button xmlns="{ns}" BorderThickness="2" />')
    c = Control(button, "Button", Services(style))
    assert c.value("BorderThickness") == ("text", "2")  # local
    assert c.value("Padding") == ("text", "4")  # the document's Style
    assert c.value("Background") == ("text", "#FFDDDDDD")  # the theme's Style
    assert c.value("IsEnabled") == ("text", "True")  # the property's default
    plain = etree.fromstring(f'<Button xmlns="{ns}" OverridesDefaultStyle="True" />')
    assert Control(plain, "Button", Services()).value("Background") is None
