"""Load-time bindings (xaml3d/framework/bindings.py): the markup extension parser, .NET's
number formatting, and each binding replaced by the value WPF computes at load, as the exact
attribute text the reader then reads; bindings that need code or fail keep FallbackValue or
the default, said once per kind."""

from __future__ import annotations

import math

import pytest
from lxml import etree

from xaml3d.framework import binding_format as F
from xaml3d.framework.binding_path import Step, parse_path
from xaml3d.framework.bindings import evaluate
from xaml3d.framework.markup_syntax import Extension, MarkupSyntaxError, parse, to_text

NS = ('xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
      'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" '
      'xmlns:sys="clr-namespace:System;assembly=mscorlib" '
      'xmlns:local="clr-namespace:App"')  # fmt: skip
X = "{http://schemas.microsoft.com/winfx/2006/xaml}"


# --------------------------------------------------------------------------- the parser
def test_parse_nested_named_and_positional():
    e = parse("{Binding IsChecked, ElementName=box, Converter={StaticResource BoolToVis}}")
    conv = Extension("StaticResource", positional=["BoolToVis"])
    assert e == Extension(
        "Binding", positional=["IsChecked"], named={"ElementName": "box", "Converter": conv}
    )


@pytest.mark.parametrize(
    ("text", "fmt"),
    [
        ("{Binding V, StringFormat={}{0:F2}}", "{0:F2}"),
        ("{Binding V, StringFormat='{}{0:F2}'}", "{0:F2}"),
        ("{Binding V, StringFormat={}{0:N0} kg}", "{0:N0} kg"),
        ("{Binding V, StringFormat=F2}", "F2"),
        ("{Binding V, StringFormat='a, b'}", "a, b"),
        (r"{Binding V, StringFormat=a\, b}", "a, b"),
        ("{Binding V, StringFormat=' padded '}", " padded "),
        ("{Binding V, StringFormat=  trimmed  }", "trimmed"),
    ],
)
def test_parse_string_values_quoting_and_escapes(text, fmt):
    assert parse(text).named["StringFormat"] == fmt


def test_parse_relative_source_and_bracketed_path():
    e = parse(
        "{Binding Path=(Grid.Row), RelativeSource={RelativeSource FindAncestor, "
        "AncestorType={x:Type Grid}, AncestorLevel=2}}"
    )
    assert e.named["Path"] == "(Grid.Row)"
    rel = e.named["RelativeSource"]
    assert rel.positional == ["FindAncestor"] and rel.named["AncestorLevel"] == "2"
    assert rel.named["AncestorType"] == Extension("Type", prefix="x", positional=["Grid"])
    assert parse("{Binding Items[0,1].Name}").positional == ["Items[0,1].Name"]
    assert parse("{Binding,Path=X}").named == {"Path": "X"}
    assert parse("{Binding Source='{StaticResource k}'}").named["Source"].name == "StaticResource"


@pytest.mark.parametrize(
    "text",
    [
        "{Binding X",
        "{Binding X, Y='a}",
        "{Binding X}}",
        "{Binding A=1, B}",
        "{Binding a'b}",
        "{}",
        "{Binding X, Path=(a}",
    ],  # fmt: skip
)
def test_parse_refuses_malformed(text):
    with pytest.raises(MarkupSyntaxError):
        parse(text)


def test_to_text_round_trips():
    for text in ["{StaticResource k}", "{Binding V, StringFormat='{0:F2}', ElementName=s}"]:
        assert parse(to_text(parse(text))) == parse(text)


def test_property_path_steps():
    assert parse_path("Children[1].(Canvas.Left)") == [
        Step("prop", "Children"), Step("index", "1"), Step("prop", "Canvas.Left")]  # fmt: skip
    assert parse_path("(local:Gauge.Level)") == [Step("prop", "Gauge.Level")]
    assert parse_path("/Name") == [Step("current"), Step("prop", "Name")]
    assert parse_path("") == [] and parse_path(".") == []


# --------------------------------------------------------------------------- formatting
@pytest.mark.parametrize(
    ("x", "text"),
    [
        (42.5, "42.5"),
        (3.0, "3"),
        (0.1, "0.1"),
        (1 / 3, "0.3333333333333333"),
        (1e15, "1E+15"),
        (123456789012345.0, "123456789012345"),
        (1e-5, "1E-05"),
        (0.0001, "0.0001"),
        (-2.5e-7, "-2.5E-07"),
        (math.nan, "NaN"),
    ],  # fmt: skip
)
def test_double_to_string(x, text):
    assert F.double_text(x) == text


@pytest.mark.parametrize(
    ("fmt", "x", "text"),
    [
        ("{0:F2}", 42.5, "42.50"),
        ("{0:F2}", 0.125, "0.13"),
        ("F2", 2.0, "2.00"),
        ("{0:N0}", 1234567.5, "1,234,568"),
        ("{0:N}", 1234.5, "1,234.50"),
        ("{0:P}", 0.125, "12.50%"),
        ("{0:P0}", 0.5, "50%"),
        ("{0}", 3.0, "3"),
        ("{0:E2}", 1234.5, "1.23E+003"),
        ("{0,8:F1} kg", 3.14159, "     3.1 kg"),
        ("{0,-5}|", 2.0, "2    |"),
        ("{0:0.0#}", 2.5, "2.5"),
        ("{0:0.0#}", 2.125, "2.13"),
        ("{0:#,##0.00}", 1234.5, "1,234.50"),
        ("{0:0%}", 0.25, "25%"),
        ("{0:D3}", 7.0, "007"),
        ("{{{0}}}", 1.0, "{1}"),
        ("Value: {0:F0}", 9.5, "Value: 10"),
    ],  # fmt: skip
)
def test_string_format_numbers(fmt, x, text):
    assert F.composite(fmt, x, True) == text


def test_string_format_ignores_a_number_format_on_text_and_refuses_bad_items():
    assert F.composite("{0:F2}!", "abc", False) == "abc!"
    for bad in ("{1}", "{0", "}", "{x}"):
        with pytest.raises(F.FormatError):
            F.composite(bad, 1.0, True)


# --------------------------------------------------------------------------- evaluation
class FakeServices:
    """The reader's services over a bare lxml tree: resources by x:Key up the tree."""

    def __init__(self) -> None:
        self.said: list[tuple[str, str, int, str | None]] = []
        self._once: set = set()

    def find(self, key, from_el):
        node = from_el
        while node is not None:
            for pe in node:
                if isinstance(pe.tag, str) and pe.tag.endswith(".Resources"):
                    for entry in pe:
                        if not isinstance(entry.tag, str):
                            continue
                        implicit = entry.get("TargetType")
                        own = entry.get(X + "Key") or f"{{x:Type {implicit}}}"
                        if own == key:
                            return entry
            node = node.getparent()
        return None

    def lookup(self, key, from_el, attr=None):
        hit = self.find(key, from_el)
        if hit is None:
            self.diag("RES001", f"StaticResource {key!r} not found", from_el, attr)
        return hit

    def diag(self, code, message, el=None, attr=None, once=None):
        if once is not None:
            if once in self._once:
                return
            self._once.add(once)
        self.said.append((code, message, el.sourceline if el is not None else 0, attr))

    def pin(self, root):
        pass


def run(body: str, root: str = "Grid"):
    doc = etree.fromstring(f"<{root} {NS}>\n{body}\n</{root}>")
    s = FakeServices()
    evaluate(doc, s)
    return doc, s


def attr(doc, name: str, prop: str):
    el = doc.xpath(f"//*[@x:Name='{name}' or @Name='{name}']", namespaces={"x": X[1:-1]})[0]
    return el.get(prop)


def test_a_converted_ischecked_collapses_and_shows():
    body = """<Grid.Resources><BooleanToVisibilityConverter x:Key="BoolToVis"/></Grid.Resources>
    <CheckBox x:Name="box"/>
    <TextBlock x:Name="t" Visibility="{Binding IsChecked, ElementName=box,
        Converter={StaticResource BoolToVis}}"/>
    <CheckBox x:Name="on" IsChecked="True"/>
    <TextBlock x:Name="u" Visibility="{Binding IsChecked, ElementName=on,
        Converter={StaticResource BoolToVis}}"/>"""
    doc, s = run(body)
    assert attr(doc, "t", "Visibility") == "Collapsed"
    assert attr(doc, "u", "Visibility") == "Visible"
    assert s.said == []


def test_sources_paths_and_formats():
    body = """<Grid.Resources>
      <SolidColorBrush x:Key="brush" Color="#FF336699"/>
      <sys:Double x:Key="size">12.50</sys:Double>
      <sys:String x:Key="word">hello</sys:String>
      <x:Array x:Key="names" Type="sys:String"><sys:String>Ann</sys:String>
        <sys:String>Bob</sys:String></x:Array>
    </Grid.Resources>
    <Slider x:Name="s" Value="42.50" Maximum="100"/>
    <TextBlock x:Name="f" Text="{Binding Value, ElementName=s, StringFormat={}{0:F1} units}"/>
    <TextBlock x:Name="plain" Text="{Binding Value, ElementName=s}"/>
    <TextBlock x:Name="max" Text="{Binding Maximum, ElementName=s, StringFormat=N0}"/>
    <Rectangle x:Name="r" Fill="{Binding Source={StaticResource brush}}"/>
    <Rectangle x:Name="c" Tag="{Binding Color, Source={StaticResource brush}}"/>
    <TextBlock x:Name="d" Width="{Binding Source={StaticResource size}}"/>
    <TextBlock x:Name="len" Text="{Binding Length, Source={StaticResource word}}"/>
    <TextBlock x:Name="idx" Text="{Binding [1], Source={StaticResource names}}"/>
    <TextBlock x:Name="cur" Text="{Binding /, Source={StaticResource names}}"/>
    <TextBlock x:Name="self" Tag="x" Text="{Binding Tag, RelativeSource={RelativeSource Self}}"/>
    <Border Grid.Row="3"><StackPanel>
      <TextBlock x:Name="row" Text="{Binding (Grid.Row), RelativeSource={RelativeSource
          FindAncestor, AncestorType={x:Type Border}}}"/>
      <TextBlock x:Name="anc" Text="{Binding Children.Count, RelativeSource={RelativeSource
          AncestorType=Panel}}"/>
    </StackPanel></Border>"""
    doc, s = run(body)
    assert attr(doc, "f", "Text") == "42.5 units"
    assert attr(doc, "plain", "Text") == "42.5"
    assert attr(doc, "max", "Text") == "100"
    assert attr(doc, "r", "Fill") == "{StaticResource brush}"
    assert attr(doc, "c", "Tag") == "#FF336699"
    assert attr(doc, "d", "Width") == "12.5"
    assert attr(doc, "len", "Text") == "5"
    assert attr(doc, "idx", "Text") == "Bob"
    assert attr(doc, "cur", "Text") == "Ann"
    assert attr(doc, "self", "Text") == "x"
    assert attr(doc, "row", "Text") == "3"
    assert attr(doc, "anc", "Text") == "2"
    assert s.said == []


def test_defaults_styles_inheritance_and_data_context():
    body = """<Grid.Resources>
      <Style x:Key="big" TargetType="TextBlock"><Setter Property="FontSize" Value="20"/></Style>
      <Style TargetType="Slider"><Setter Property="Value" Value="7"/></Style>
      <sys:String x:Key="who">Ann</sys:String>
    </Grid.Resources>
    <CheckBox x:Name="box"/>
    <TextBlock x:Name="unset" Text="{Binding IsChecked, ElementName=box}"/>
    <Slider x:Name="s"/>
    <TextBlock x:Name="max" Text="{Binding Maximum, ElementName=s}"/>
    <TextBlock x:Name="styled" Text="{Binding Value, ElementName=s}"/>
    <TextBlock x:Name="big" Style="{StaticResource big}"/>
    <TextBlock x:Name="size" Text="{Binding FontSize, ElementName=big}"/>
    <StackPanel TextElement.FontSize="9" FontSize="15" DataContext="{StaticResource who}">
      <TextBlock x:Name="inh" Text="{Binding FontSize, RelativeSource={RelativeSource Self}}"/>
      <TextBlock x:Name="dc" Text="{Binding}"/>
      <TextBlock x:Name="dcpath" Text="{Binding Length}"/>
    </StackPanel>
    <TextBlock x:Name="w" Text="{Binding Width, RelativeSource={RelativeSource Self}}"/>"""
    doc, s = run(body)
    assert attr(doc, "unset", "Text") == "False"
    assert attr(doc, "max", "Text") == "10"  # Slider's own Maximum default
    assert attr(doc, "styled", "Text") == "7"  # the implicit Style's Setter
    assert attr(doc, "size", "Text") == "20"
    assert attr(doc, "inh", "Text") == "15"
    assert attr(doc, "dc", "Text") == "Ann"
    assert attr(doc, "dcpath", "Text") == "3"
    assert attr(doc, "w", "Text") == "NaN"
    assert s.said == []


def test_chains_element_form_fallback_and_target_null():
    body = """<Slider x:Name="a" Value="3"/>
    <Slider x:Name="b" Value="{Binding Value, ElementName=a}"/>
    <TextBlock x:Name="t" Text="{Binding Value, ElementName=b, StringFormat={}{0:F2}}"/>
    <TextBlock x:Name="e"><TextBlock.Text><Binding ElementName="a" Path="Value"
        StringFormat="{}[{0}]"/></TextBlock.Text></TextBlock>
    <TextBlock x:Name="n" Text="{Binding Tag, ElementName=a, TargetNullValue=none}"/>
    <TextBlock x:Name="m" Text="{Binding Text, ElementName=nosuch, FallbackValue='a, b'}"/>
    <TextBlock x:Name="multi"><TextBlock.Text><MultiBinding StringFormat="{}{0} of {1}">
      <Binding ElementName="a" Path="Value"/><Binding ElementName="a" Path="Maximum"/>
    </MultiBinding></TextBlock.Text></TextBlock>"""
    doc, s = run(body)
    assert attr(doc, "b", "Value") == "3"
    assert attr(doc, "t", "Text") == "3.00"
    assert attr(doc, "e", "Text") == "[3]"
    assert len(doc.xpath("//*[local-name()='TextBlock.Text']")) == 0  # element forms replaced
    assert attr(doc, "n", "Text") == "none"
    assert attr(doc, "m", "Text") == "a, b"
    assert attr(doc, "multi", "Text") == "3 of 10"
    assert [c for c, *_ in s.said] == ["BND003"]  # no element named nosuch


def test_bindings_that_need_code_keep_fallback_or_default_said_once_per_kind():
    body = """<Grid.Resources><local:Conv x:Key="conv"/></Grid.Resources>
    <TextBlock x:Name="a" Text="{Binding Name}"/>
    <TextBlock x:Name="b" Text="{Binding Title, FallbackValue=untitled}"/>
    <TextBlock x:Name="c" Text="{Binding Tag, RelativeSource={RelativeSource Self},
        Converter={StaticResource conv}}"/>
    <TextBlock x:Name="d" Text="{Binding Source={x:Static local:Config.Name}}"/>
    <local:Gauge x:Name="g"/>
    <TextBlock x:Name="e" Text="{Binding Level, ElementName=g}"/>
    <ScrollViewer x:Name="sv"/>
    <Border x:Name="f" Width="{Binding ActualWidth, ElementName=sv}"/>"""
    doc, s = run(body)
    assert attr(doc, "a", "Text") is None  # the default
    assert attr(doc, "b", "Text") == "untitled"
    for name in "cde":
        assert attr(doc, name, "Text") is None
    assert attr(doc, "f", "Width") is None
    said = [(c, line) for c, _, line, _ in s.said]
    # one per kind: DataContext (lines 3, 4: said at 3), converter, x:Static, code type, layout
    # (lxml's line of a start tag is the line it ends on: 6 for c)
    assert said == [("BND001", 3), ("BND001", 6), ("BND001", 7), ("BND001", 9), ("BND001", 11)]


def test_element_values_stay_for_the_reader_and_cycles_are_cut():
    body = """<Border x:Name="frame" Width="{Binding Height, RelativeSource={RelativeSource Self}}"
        Height="{Binding Width, RelativeSource={RelativeSource Self}}">
      <Border.Background><VisualBrush x:Name="vb" Visual="{Binding ElementName=frame}"/>
      </Border.Background>
    </Border>
    <Rectangle x:Name="other"><Rectangle.Fill>
      <VisualBrush x:Name="ok" Visual="{Binding ElementName=frame}"/></Rectangle.Fill></Rectangle>
    <Storyboard x:Name="sb" Storyboard.Target="{Binding ElementName=frame}"/>"""
    doc, s = run(body)
    assert attr(doc, "frame", "Width") is None and attr(doc, "frame", "Height") is None
    assert attr(doc, "vb", "Visual") == "{x:Null}"  # draws its own holder: cut
    assert attr(doc, "ok", "Visual") == "{Binding ElementName=frame}"  # for the reader
    assert attr(doc, "sb", "Storyboard.Target") == "{Binding ElementName=frame}"
    assert [c for c, *_ in s.said] == ["BND002", "BND002"]


def test_a_boolean_into_a_visibility_fails_as_in_wpf_and_templates_are_left():
    body = """<CheckBox x:Name="box" IsChecked="True"/>
    <TextBlock x:Name="v" Visibility="{Binding IsChecked, ElementName=box}"/>
    <Rectangle x:Name="f" Fill="{Binding Opacity, ElementName=box}"/>
    <Slider x:Name="half" Value="1.5"/><Slider x:Name="two" Value="2"/>
    <Border x:Name="r1" Grid.Row="{Binding Value, ElementName=half}"/>
    <Border x:Name="r2" Grid.Row="{Binding Value, ElementName=two}"/>
    <Grid.Resources><Style x:Key="s" TargetType="Button"><Setter Property="Tag"
      Value="{Binding IsChecked, ElementName=box}"/></Style></Grid.Resources>"""
    doc, s = run(body)
    assert attr(doc, "v", "Visibility") is None and attr(doc, "f", "Fill") is None
    assert attr(doc, "r1", "Grid.Row") is None and attr(doc, "r2", "Grid.Row") == "2"
    setter = doc.xpath("//*[local-name()='Setter']")[0]
    assert setter.get("Value") == "{Binding IsChecked, ElementName=box}"
    assert [c for c, *_ in s.said] == ["BND003", "BND003", "BND003"]


def test_an_object_without_a_key_in_scope_is_copied_as_the_property_element():
    body = """<Rectangle x:Name="src"><Rectangle.Fill><SolidColorBrush x:Name="paint"
        Color="Lime"/></Rectangle.Fill></Rectangle>
    <Rectangle x:Name="dst" Fill="{Binding Fill, ElementName=src}"/>"""
    doc, s = run(body)
    dst = doc.xpath("//*[@x:Name='dst']", namespaces={"x": X[1:-1]})[0]
    assert dst.get("Fill") is None
    (pe,) = list(dst)
    assert pe.tag.endswith("}Rectangle.Fill")
    (brush,) = list(pe)
    assert brush.get("Color") == "Lime" and brush.get(X + "Name") is None
    assert s.said == []


def test_through_the_reader_a_missing_source_key_is_one_res001_at_its_attribute():
    from xaml3d.pipeline import load

    text = f"""<Grid {NS}>
  <TextBlock Text="{{Binding Source={{StaticResource nope}}}}" />
  <TextBlock Text="{{Binding Name}}" />
  <TextBlock Text="{{Binding Name}}" />
  <Viewport3D Width="8" Height="8" />
</Grid>"""
    scene = load(text, text=True)
    found = [(d.code, d.line, d.column) for d in scene.diagnostics if d.code[:3] in ("RES", "BND")]
    assert found == [("RES001", 2, 14), ("BND001", 3, 14)]


def test_a_long_chain_is_followed_to_its_limit_without_recursing_forever():
    sliders = ['<Slider x:Name="s0" Value="5"/>'] + [
        f'<Slider x:Name="s{i}" Value="{{Binding Value, ElementName=s{i - 1}}}"/>'
        for i in range(1, 400)
    ]
    doc, s = run("\n".join(sliders))
    assert attr(doc, "s60", "Value") == "5"
    assert attr(doc, "s399", "Value") == "5"  # its chain was followed from s335, already done
    assert [c for c, *_ in s.said] == []
    sliders.reverse()  # the last first: its chain is 399 long
    doc, s = run("\n".join(sliders))
    assert attr(doc, "s1", "Value") == "5" and attr(doc, "s399", "Value") is None
    assert [c for c, *_ in s.said] == ["BND001"]


def test_data_context_of_an_application_type_and_what_the_markup_sets_on_it():
    body = """<Grid.DataContext><local:Person Name="Ann"/></Grid.DataContext>
    <TextBlock x:Name="n" Text="{Binding Name}"/>
    <TextBlock x:Name="a" Text="{Binding Age, FallbackValue=0}"/>
    <StackPanel IsEnabled="False"><Border><CheckBox x:Name="c" IsEnabled="True"/></Border>
    </StackPanel>
    <TextBlock x:Name="e" Text="{Binding IsEnabled, ElementName=c}"/>
    <TextBlock x:Name="runs"><Run Text="Hello"/> <Run>there</Run></TextBlock>
    <TextBlock x:Name="r" Tag="{Binding Text, ElementName=runs}"/>"""
    doc, s = run(body)
    assert attr(doc, "n", "Text") == "Ann"
    assert attr(doc, "a", "Text") == "0"
    assert attr(doc, "e", "Text") == "False"  # coerced under a disabled ancestor
    assert attr(doc, "r", "Tag") == "Hello there"
    assert [c for c, *_ in s.said] == ["BND001"]  # Person.Age: the application's


def test_a_second_pass_changes_nothing_and_says_nothing_more():
    body = """<Grid.Resources><BooleanToVisibilityConverter x:Key="b2v"/></Grid.Resources>
    <CheckBox x:Name="box"/>
    <TextBlock x:Name="t" Visibility="{Binding IsChecked, ElementName=box,
        Converter={StaticResource b2v}}" Text="{Binding Name}"/>
    <Rectangle><Rectangle.Fill><VisualBrush Visual="{Binding ElementName=box}"/></Rectangle.Fill>
    </Rectangle>"""
    doc, s = run(body)
    before, said = etree.tostring(doc), list(s.said)
    evaluate(doc, s)
    assert etree.tostring(doc) == before and s.said == said


def test_value_text_for_a_trigger_condition():
    from xaml3d.framework.bindings import value_text

    doc, s = run("""<CheckBox x:Name="box" IsChecked="True"/><Slider x:Name="s" Value="3"/>
    <Border x:Name="b"/>""")
    b = doc.xpath("//*[@x:Name='b']", namespaces={"x": X[1:-1]})[0]
    assert value_text(doc, s, b, "{Binding IsChecked, ElementName=box}") == "True"
    assert value_text(doc, s, b, "{Binding Value, ElementName=s, StringFormat=F1}", "Text") == "3.0"
    assert value_text(doc, s, b, "{Binding Name}") is None  # needs a DataContext from code
    assert value_text(doc, s, b, "{Binding ElementName=box}") is None  # an element
    assert value_text(doc, s, b, "{Binding Tag, ElementName=box}") == "{x:Null}"
    assert s.said == []


def test_an_element_form_visual_binding_becomes_the_attribute_the_reader_follows():
    body = """<Border x:Name="panel" Width="40" Height="20"/>
    <Rectangle><Rectangle.Fill><VisualBrush x:Name="vb"><VisualBrush.Visual>
      <Binding ElementName="panel"/></VisualBrush.Visual></VisualBrush></Rectangle.Fill></Rectangle>
    <Border x:Name="frame"><Border.Background><VisualBrush x:Name="own"><VisualBrush.Visual>
      <Binding ElementName="frame"/></VisualBrush.Visual></VisualBrush></Border.Background>
    </Border>"""
    doc, s = run(body)
    assert attr(doc, "vb", "Visual") == "{Binding ElementName=panel}"
    assert attr(doc, "own", "Visual") == "{x:Null}"
    assert doc.xpath("//*[local-name()='VisualBrush.Visual']") == []
    assert [c for c, *_ in s.said] == ["BND002"]


def test_diagnostics_after_a_replaced_property_element_keep_their_positions():
    from xaml3d.pipeline import load

    text = f"""<StackPanel {NS}>
  <Slider x:Name="s" Value="2"/>
  <TextBlock><TextBlock.Text><Binding ElementName="s" Path="Value"/></TextBlock.Text></TextBlock>
  <Viewport3D Width="8" Height="8">
    <ModelVisual3D><ModelVisual3D.Content>
      <GeometryModel3D><GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 5"/>
      </GeometryModel3D.Geometry></GeometryModel3D>
    </ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</StackPanel>"""
    scene = load(text, text=True)
    found = [(d.code, d.line, d.column) for d in scene.diagnostics if d.code.startswith("MSH")]
    assert found and all(line == 7 and col is not None and col > 9 for _, line, col in found)


@pytest.mark.parametrize(
    "raw", ["{", "{ ", "{}", "{,}", "{Binding", "{Binding X=}", "{ Binding ,}", "{Binding Pth=A}"]
)
def test_odd_brace_values_never_raise(raw):
    doc = etree.Element("{http://schemas.microsoft.com/winfx/2006/xaml/presentation}Grid")
    doc.set("Tag", raw)
    s = FakeServices()
    evaluate(doc, s)
    assert [c for c, *_ in s.said] in ([], ["XAML016"], ["XAML024"])
    assert doc.get("Tag") in (raw, None)


def test_a_binding_member_wpf_does_not_have_is_refused_with_a_suggestion():
    doc, s = run("""<TextBlock x:Name="t" Text="{Binding Value, ElemntName=s}"/>
    <TextBlock x:Name="u"><TextBlock.Text><Binding Pth="Value"/></TextBlock.Text></TextBlock>""")
    assert attr(doc, "t", "Text") is None and attr(doc, "u", "Text") is None
    assert [(c, m) for c, m, *_ in s.said] == [
        (
            "XAML024",
            "Binding has no property 'ElemntName' (did you mean ElementName?): WPF "
            "refuses the file",
        ),
        ("XAML024", "Binding has no property 'Pth' (did you mean Path?): WPF refuses the file"),
    ]


def test_a_path_the_source_type_does_not_have_fails_as_in_wpf():
    from xaml3d.xaml import framework_members

    class Services(FakeServices):
        def members(self, type_name):
            return framework_members.members(type_name)

    doc = etree.fromstring(f"""<Grid {NS}>
    <CheckBox x:Name="cb" IsChecked="True"/>
    <TextBlock x:Name="t" Text="{{Binding IsChekced, ElementName=cb}}"/>
    <TextBlock x:Name="f" Text="{{Binding Zzz, ElementName=cb, FallbackValue=none}}"/>
    <TextBlock x:Name="ok" Text="{{Binding IsChecked, ElementName=cb}}"/>
    </Grid>""")
    s = Services()
    evaluate(doc, s)
    assert attr(doc, "t", "Text") is None  # the property's default, as WPF shows it
    assert attr(doc, "f", "Text") == "none"
    assert attr(doc, "ok", "Text") == "True"
    assert [(c, line) for c, _, line, _ in s.said] == [("BND003", 3), ("BND003", 4)]
    assert "CheckBox has no property 'IsChekced'; did you mean IsChecked?" in s.said[0][1]
    assert "did you mean" not in s.said[1][1]


def test_the_readers_vocabulary_checks_a_bound_path(tmp_path):
    from test_framework_templates import window

    from xaml3d.pipeline import load

    feature = window(
        "",
        '<CheckBox x:Name="cb" /><TextBlock Text="{Binding IsChekced, ElementName=cb}" />',
    )
    (tmp_path / "f.xaml").write_text(feature, encoding="utf-8")
    said = [d for d in load(tmp_path / "f.xaml").diagnostics if d.code.startswith("BND")]
    assert [d.code for d in said] == ["BND003"]
    assert "did you mean IsChecked?" in said[0].message
