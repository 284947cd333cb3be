"""Members of WPF's 2D framework types (XAML024): what WPF's loader refuses is refused, with a
did-you-mean, and what it loads (events, attached properties, x: and xml: attributes, custom
namespaces, template bodies) is not."""

from __future__ import annotations

import pytest
from conftest import CORPUS, needs_corpus
from test_cli_subprocess import xaml3d

from xaml3d.pipeline import load
from xaml3d.xaml import framework_members as fm

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
REFUSED = "; WPF refuses this file"


def _found(body: str, root: str = "Grid", extra: str = "") -> list[tuple[int, int, str]]:
    """(line, column, message) of every XAML024 of a document whose root holds ``body``."""
    scene = load(f"<{root} {NS} {extra}>\n{body}\n<Viewport3D/></{root}>", text=True)
    return [(d.line, d.column, d.message) for d in scene.diagnostics if d.code == "XAML024"]


def _errors(body: str, root: str = "Grid", extra: str = "") -> list[str]:
    scene = load(f"<{root} {NS} {extra}>\n{body}\n<Viewport3D/></{root}>", text=True)
    return [d.code for d in scene.diagnostics if d.severity == "error"]


def test_an_unknown_attribute_is_refused_with_the_closest_name():
    assert _found('  <TextBlock Text="a" Foregrund="Red"/>') == [
        (2, 23, "property 'Foregrund' is not a property of TextBlock "
                f"(did you mean 'Foreground'?){REFUSED}"),
    ]  # fmt: skip


def test_a_name_of_the_wrong_case_is_refused():
    found = _found('<Button fontSize="12"/>')
    assert [m for _, _, m in found] == [
        f"property 'fontSize' is not a property of Button (did you mean 'FontSize'?){REFUSED}"
    ]


def test_an_unknown_property_element_is_refused():
    body = "<TextBlock>\n  <TextBlock.Foregrund>Red</TextBlock.Foregrund>\n</TextBlock>"
    assert _found(body) == [
        (3, 3, "property element <TextBlock.Foregrund>: 'Foregrund' is not a property of "
               f"TextBlock (did you mean 'Foreground'?){REFUSED}"),
    ]  # fmt: skip


def test_members_of_base_classes_are_accepted_in_every_form():
    body = """<Button Control.Background="Red" FrameworkElement.Margin="2" UIElement.Opacity="0.5"
        Content="b" Padding="1" IsDefault="True" Command="{x:Null}" ClickMode="Press">
  <Button.Template><ControlTemplate TargetType="Button"/></Button.Template>
  <Control.Foreground>Red</Control.Foreground>
  <FrameworkElement.Resources/>
</Button>
<Slider Minimum="0" Maximum="9" Value="3" TickPlacement="BottomRight" Orientation="Vertical"/>
<TextBox Text="t" AcceptsReturn="True" TextWrapping="Wrap" CaretBrush="Red"/>
<ListBox SelectionMode="Extended" ItemsSource="{x:Null}" SelectedIndex="0" AlternationCount="2"/>
<Border CornerRadius="3" BorderThickness="1"><Rectangle RadiusX="2" Fill="Red"/></Border>
<Path Data="M0,0 L1,1" Stroke="Red" StrokeThickness="2" StrokeDashArray="1 2"/>"""
    assert _found(body) == []
    assert _errors(body) == []


def test_a_base_class_owner_is_resolved_on_the_element():
    found = _found('<Button Control.Bakground="Red"/>')
    assert [m for _, _, m in found] == [
        f"property 'Bakground' is not a property of Button (did you mean 'Background'?){REFUSED}"
    ]


def test_event_handlers_are_accepted():
    body = """<Button Click="OnClick" MouseDown="OnDown" PreviewKeyDown="OnKey" Loaded="OnLoaded"
        IsEnabledChanged="OnEnabled" MouseDoubleClick="OnDouble" SizeChanged="OnSize"/>
<StackPanel Button.Click="OnAnyClick" Mouse.MouseEnter="OnEnter"/>
<Slider ValueChanged="OnValue"/>"""
    scene = load(f"<Window {NS} Closing='OnClosing' ContentRendered='OnShown'><Grid>{body}"
                 "<Viewport3D/></Grid></Window>", text=True)  # fmt: skip
    assert [d.code for d in scene.diagnostics if d.severity == "error"] == []
    handlers = [d for d in scene.diagnostics if d.code == "XAML008"]
    assert len(handlers) >= 9 and all(d.severity == "info" for d in handlers)


def test_an_unlisted_name_that_reads_like_an_event_with_a_handler_is_accepted():
    # WPF's events are many; a handler name is legal markup and xaml3d does not run it
    assert _found('<Button SomethingChanged="OnSomething"/>') == []
    # but a value that is no handler name is a property value: refused
    assert len(_found('<Button SomethingChanged="12"/>')) == 1


def test_attached_properties_are_accepted_on_any_element():
    body = """<TextBlock Grid.Row="1" Grid.Column="0" Grid.ColumnSpan="2" Canvas.Left="3"
    DockPanel.Dock="Top" Panel.ZIndex="2" ToolTipService.ShowDuration="9"
    ToolTipService.ToolTip="tip" KeyboardNavigation.TabNavigation="Cycle"
    ScrollViewer.HorizontalScrollBarVisibility="Auto" TextOptions.TextFormattingMode="Display"
    RenderOptions.BitmapScalingMode="HighQuality" VirtualizingPanel.IsVirtualizing="True"
    VirtualizingStackPanel.VirtualizationMode="Recycling" TextElement.FontSize="12"
    AutomationProperties.Name="n" Validation.ErrorTemplate="{x:Null}" Grid.IsSharedSizeScope="True">
  <ToolTipService.ToolTip>tip</ToolTipService.ToolTip>
  <Grid.Row>1</Grid.Row>
</TextBlock>
<ListBox ScrollViewer.CanContentScroll="False" Selector.IsSelected="True"/>
<Grid Row="1" Column="1"/>"""
    assert _found(body) == []
    assert _errors(body) == []


def test_an_attached_property_its_owner_does_not_have_is_refused():
    found = _found('<TextBlock Grid.Rwo="1" DockPanel.Dok="Top"/>')
    assert [m for _, _, m in found] == [
        f"property 'Rwo' is not a property of Grid (did you mean 'Row'?){REFUSED}",
        f"property 'Dok' is not a property of DockPanel (did you mean 'Dock'?){REFUSED}",
    ]


def test_language_and_other_namespaces_attributes_are_not_members():
    extra = (
        'xmlns:mc="http://schemas.openxmlformats.org/markup-compatibility/2006" '
        'xmlns:d="http://schemas.microsoft.com/expression/blend/2008" mc:Ignorable="d" '
        'd:DesignWidth="300" x:Name="root" xml:lang="en-GB"'
    )
    body = """<Grid.Resources><SolidColorBrush x:Key="b" Color="Red"/></Grid.Resources>
<TextBlock x:Name="t" x:Uid="u1" xml:space="preserve" d:LayoutOverrides="Width" Text="a"/>"""
    assert _found(body, extra=extra) == []
    assert _errors(body, extra=extra) == []


def test_custom_namespace_elements_are_untouched_but_wpf_elements_inside_are_checked():
    extra = 'xmlns:local="clr-namespace:App.Controls"'
    body = """<local:Gauge Foregrund="1" Spin="2"><local:Gauge.Needle/>
  <TextBlock Foregrund="Red"/>
</local:Gauge>
<TextBlock local:Gauge.Value="3"/>"""
    found = _found(body, extra=extra)
    assert [(ln, m.split(";")[0]) for ln, _, m in found] == [
        (3, "property 'Foregrund' is not a property of TextBlock (did you mean 'Foreground'?)")
    ]


def test_an_owner_of_another_type_on_a_3d_element_is_resolved_once():
    scene = load(
        f"""<Grid {NS}><Viewport3D FrameworkElement.Widht="9" Grid.Row="0">
  <FrameworkElement.Heigth>9</FrameworkElement.Heigth>
</Viewport3D></Grid>""",
        text=True,
    )
    found = [(d.code, d.line, d.message.split(" (")[0]) for d in scene.diagnostics
             if d.severity == "error"]  # fmt: skip
    assert found == [
        ("XAML024", 1, "property 'Widht' is not a property of FrameworkElement"),
        ("XAML004", 2, "Viewport3D has no property 'Heigth'"),
    ]


def test_types_without_a_table_keep_the_open_vocabulary():
    # DataGrid, Calendar ... have no table: their members are not checked
    assert _found('<DataGrid Foo="1"/><Calendar Bar="2"/>') == []


def test_template_bodies_are_not_checked_but_the_template_is():
    body = """<Grid.Resources>
  <ControlTemplate x:Key="t" TargetType="Button" Foo="1">
    <Border Bakground="Red"/>
    <ControlTemplate.Trigers/>
  </ControlTemplate>
  <DataTemplate x:Key="d"><TextBlock Txt="a"/></DataTemplate>
</Grid.Resources>"""
    found = _found(body)
    assert [(ln, m.split(";")[0]) for ln, _, m in found] == [
        (3, "property 'Foo' is not a property of ControlTemplate"),
        (5, "property element <ControlTemplate.Trigers>: 'Trigers' is not a property of "
            "ControlTemplate (did you mean 'Triggers'?)"),
    ]  # fmt: skip


def test_what_wpf_does_not_read_is_not_checked():
    extra = (
        'xmlns:mc="http://schemas.openxmlformats.org/markup-compatibility/2006" '
        'xmlns:d="http://schemas.microsoft.com/expression/blend/2008" mc:Ignorable="d"'
    )
    body = """<d:Designer><TextBlock Foregrund="Red"/></d:Designer>
<mc:AlternateContent><mc:Choice Requires="d"><TextBlock Foregrund="Red"/></mc:Choice>
</mc:AlternateContent>
<Grid.Resources><XmlDataProvider x:Key="x"><x:XData><Item Foregrund="1"/></x:XData>
</XmlDataProvider></Grid.Resources>"""
    assert _found(body, extra=extra) == []


def _style(setters: str, target: str | None = "Button") -> str:
    tt = f' TargetType="{target}"' if target else ""
    return f'<Grid.Resources><Style x:Key="s"{tt}>\n{setters}\n</Style></Grid.Resources>'


def test_a_setter_property_is_resolved_on_the_styles_target_type():
    found = _found(_style('<Setter Property="FontWieght" Value="Bold"/>'))
    assert found == [
        (3, 9, "Setter Property 'FontWieght': 'FontWieght' is not a property of Button, the "
               f"Style's TargetType (did you mean 'FontWeight'?){REFUSED}"),
    ]  # fmt: skip


def test_a_setter_property_with_an_owner_is_resolved_on_that_owner():
    found = _found(_style('<Setter Property="Button.Bakground" Value="Red"/>', target=None))
    assert [m for _, _, m in found] == [
        "Setter Property 'Button.Bakground': 'Bakground' is not a property of Button "
        f"(did you mean 'Background'?){REFUSED}"
    ]
    # {x:Type} target, an owner that is a base type, an attached property: all resolved
    ok = _style(
        '<Setter Property="Control.Background" Value="Red"/>'
        '<Setter Property="Grid.Row" Value="1"/><Setter Property="Margin" Value="1"/>'
        '<Setter Property="ToolTipService.ShowDuration" Value="1"/>',
        target="{x:Type Button}",
    )
    assert _found(ok) == []


def test_a_bare_setter_property_without_target_type_cannot_be_resolved():
    found = _found(_style('<Setter Property="Background" Value="Red"/>', target=None))
    assert [m for _, _, m in found] == [
        "Setter Property 'Background' names no owner type and the Style has no TargetType: WPF "
        "cannot resolve it (write Owner.Property, e.g. 'Control.Background', or give the Style "
        f"a TargetType){REFUSED}"
    ]


def test_trigger_and_condition_properties_are_resolved_like_setters():
    setters = """<Style.Triggers>
  <Trigger Property="IsMouseOver" Value="True"><Setter Property="Foreground" Value="Red"/></Trigger>
  <Trigger Property="IsPresed" Value="True"><Setter Property="Forground" Value="Red"/></Trigger>
  <MultiTrigger><MultiTrigger.Conditions>
    <Condition Property="IsFocused" Value="True"/><Condition Property="IsDefalt" Value="True"/>
  </MultiTrigger.Conditions></MultiTrigger>
  <DataTrigger Binding="{Binding X}" Value="1"><Setter Property="Opacity" Value="1"/></DataTrigger>
</Style.Triggers>"""
    found = _found(_style(setters))
    assert [(ln, m.split(":")[0]) for ln, _, m in found] == [
        (5, "Trigger Property 'IsPresed'"),
        (5, "Setter Property 'Forground'"),
        (7, "Condition Property 'IsDefalt'"),
    ]


def test_a_control_templates_triggers_are_resolved_on_its_target_type():
    body = """<Grid.Resources><ControlTemplate x:Key="t" TargetType="{x:Type CheckBox}">
  <Border x:Name="b"/>
  <ControlTemplate.Triggers>
    <Trigger Property="IsChecked" Value="True"><Setter Property="Foregound" Value="Red"/>
      <Setter TargetName="b" Property="Background" Value="Red"/></Trigger>
    <MultiTrigger><MultiTrigger.Conditions><Condition Property="IsMouseOvr" Value="True"/>
    </MultiTrigger.Conditions></MultiTrigger>
  </ControlTemplate.Triggers>
</ControlTemplate>
<ControlTemplate x:Key="u"><ControlTemplate.Triggers>
  <Trigger Property="Anything" Value="1"/></ControlTemplate.Triggers></ControlTemplate>
</Grid.Resources>"""
    found = _found(body)
    assert [(ln, m.split(";")[0]) for ln, _, m in found] == [
        (5, "Setter Property 'Foregound': 'Foregound' is not a property of CheckBox, the "
            "ControlTemplate's TargetType (did you mean 'Foreground'?)"),
        (7, "Condition Property 'IsMouseOvr': 'IsMouseOvr' is not a property of CheckBox, the "
            "ControlTemplate's TargetType (did you mean 'IsMouseOver'?)"),
    ]  # fmt: skip


def test_setters_of_a_custom_target_type_or_a_named_target_are_not_checked():
    extra = 'xmlns:local="clr-namespace:App.Controls"'
    body = _style('<Setter Property="Needle" Value="1"/>', target="local:Button")
    body += _style('<Setter Property="Needle" Value="1"/>', target="{x:Type local:Gauge}")
    assert _found(body, extra=extra) == []


def test_every_base_class_has_a_table():
    for name, (base, _) in fm.CLASSES.items():
        assert base is None or base in fm.CLASSES, name


@pytest.mark.parametrize(
    "name",
    "Window Page UserControl Grid Canvas StackPanel DockPanel WrapPanel Border TextBlock Label "
    "Button CheckBox Slider TextBox ListBox ComboBox Image Rectangle Ellipse Path Line Polygon "
    "Viewbox ScrollViewer Expander GroupBox TabControl Menu ItemsControl ContentControl Style "
    "Setter Trigger DropShadowEffect BlurEffect".split(),
)
def test_the_common_framework_types_have_a_table(name):
    assert fm.members(name) is not None
    assert {"Name", "Width", "Loaded"} <= fm.members("Button")  # inherited along the hierarchy


@needs_corpus
def test_no_file_of_the_corpus_is_refused_for_its_framework_members():
    files = sorted(CORPUS.glob("*.xaml"))
    for path in files:
        scene = load(path)
        assert [d.message for d in scene.diagnostics if d.code == "XAML024"] == [], path.name


def test_the_command_line_refuses_and_says_why(tmp_path):
    (tmp_path / "s.xaml").write_text(
        f'<Grid {NS}>\n  <TextBlock Foregrund="Red"/>\n  <Viewport3D/>\n</Grid>\n'
    )
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert p.returncode == 1
    assert p.stdout.decode().splitlines()[0] == (
        "s.xaml:2:14: error XAML024 property 'Foregrund' is not a property of TextBlock "
        f"(did you mean 'Foreground'?){REFUSED}"
    )
    r = xaml3d("render", "s.xaml", "-o", "out.png", cwd=tmp_path)
    assert r.returncode == 1 and not (tmp_path / "out.png").exists()
    assert b"error XAML024" in r.stderr
