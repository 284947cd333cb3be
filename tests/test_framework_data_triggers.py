"""DataTrigger, MultiDataTrigger and SourceName conditions applied at load
(xaml3d.framework.data_triggers): each feature rendered beside a hand-written twin (the tree
WPF builds from it, its triggered values written out) must give the same pixels; the
comparison of a bound value with a trigger's Value; what is said when a binding needs code."""

from __future__ import annotations

import pytest
from test_framework_templates import _line, _same, _window_pixels, window

from xaml3d.framework.binding_values import Value
from xaml3d.framework.data_triggers import matches
from xaml3d.pipeline import load

RED = (255, 0, 0)


def _codes(tmp_path, text: str) -> set:
    path = tmp_path / "doc.xaml"
    path.write_text(text, encoding="utf-8")
    return {(d.code, d.line) for d in load(path).diagnostics}


# ------------------------------------------------------------------ the comparison


@pytest.mark.parametrize(
    ("value", "wanted", "expected"),
    [
        (Value("True", "Boolean"), "true", True),
        (Value("False", "Boolean"), "True", False),
        (Value("2", "Double"), "2.0", True),
        (Value("2", "Int32"), "3", False),
        (Value("NaN", "Double"), "NaN", True),  # Double.Equals
        (Value("Collapsed", "Visibility"), "collapsed", True),
        (Value("Abc", "String"), "abc", False),
        (Value("Abc", "String"), "Abc", True),
        (Value("True", "Object"), "true", True),  # a code type's property: a boolean
        (Value("1.50", "Object"), "1.5", True),
        (Value("Book", "Object"), "book", False),
        (Value(null=True), "{x:Null}", True),
        (Value("x", "String"), "{x:Null}", False),
        (Value(null=True), "", False),
        (Value("{a}", "String"), "{}{a}", True),
        (Value("Red", "Brush"), "Red", False),  # brushes compare by identity in WPF
    ],
)
def test_matches_converts_the_value_to_the_source_type(value, wanted, expected):
    assert matches(value, wanted) is expected


# ------------------------------------------------------------------ Style.Triggers

STYLE = """
    <Style x:Key="s" TargetType="Button">
      <Setter Property="Background" Value="Blue" />
      <Style.Triggers>
        <DataTrigger Binding="{Binding IsChecked, ElementName=box}" Value="true">
          <Setter Property="Background" Value="Red" />
          <Setter Property="Height" Value="40" />
        </DataTrigger>
        <DataTrigger Binding="{Binding Tag, RelativeSource={RelativeSource Self}}" Value="big">
          <Setter Property="Width" Value="70" />
        </DataTrigger>
      </Style.Triggers>
    </Style>"""


def test_style_data_trigger_on_element_name_and_self(tmp_path):
    feature = window(
        STYLE,
        """
      <CheckBox x:Name="box" IsChecked="True" Content="c" />
      <Button Style="{StaticResource s}" Tag="big" Content="b" />
      <Button Style="{StaticResource s}" Tag="small" Content="b" />""",
    )
    twin = window(
        '<Style x:Key="s" TargetType="Button"><Setter Property="Background" Value="Blue" />'
        "</Style>",
        """
      <CheckBox x:Name="box" IsChecked="True" Content="c" />
      <Button Style="{StaticResource s}" Tag="big" Content="b" Background="Red" Height="40"
              Width="70" />
      <Button Style="{StaticResource s}" Tag="small" Content="b" Background="Red"
              Height="40" />""",
    )
    _same(tmp_path, feature, twin)


def test_style_data_trigger_that_does_not_fire(tmp_path):
    feature = window(
        STYLE,
        """
      <CheckBox x:Name="box" Content="c" />
      <Button Style="{StaticResource s}" Content="b" />""",
    )
    twin = window(
        STYLE.split("<Style.Triggers>")[0] + "</Style>",
        """
      <CheckBox x:Name="box" Content="c" />
      <Button Style="{StaticResource s}" Content="b" />""",
    )
    _same(tmp_path, feature, twin)


def test_multi_data_trigger_needs_every_condition(tmp_path):
    style = """
    <Style TargetType="Label">
      <Setter Property="Background" Value="Blue" />
      <Style.Triggers>
        <MultiDataTrigger>
          <MultiDataTrigger.Conditions>
            <Condition Binding="{Binding Tag, RelativeSource={RelativeSource Self}}" Value="a" />
            <Condition Binding="{Binding Text, ElementName=t}" Value="on" />
          </MultiDataTrigger.Conditions>
          <Setter Property="Background" Value="Red" />
        </MultiDataTrigger>
      </Style.Triggers>
    </Style>"""
    feature = window(
        style,
        """
      <TextBlock x:Name="t" Text="on" />
      <Label Tag="a" Height="20" />
      <Label Tag="b" Height="20" />""",
    )
    twin = window(
        "",
        """
      <TextBlock x:Name="t" Text="on" />
      <Label Tag="a" Height="20" Background="Red" />
      <Label Tag="b" Height="20" Background="Blue" />""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[26, 40][:3]) == RED


NS = (
    'xmlns:sys="clr-namespace:System;assembly=mscorlib" xmlns:local="clr-namespace:Demo" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)


def _with_ns(text: str) -> str:
    return text.replace('xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"', NS, 1)


def test_data_trigger_on_a_data_context_from_markup(tmp_path):
    style = """
    <local:Alarm x:Key="alarm" Mode="Alert" Armed="true" />
    <Style TargetType="Label">
      <Style.Triggers>
        <DataTrigger Binding="{Binding Mode}" Value="Alert">
          <Setter Property="Background" Value="Red" />
        </DataTrigger>
        <DataTrigger Binding="{Binding Armed}" Value="True">
          <Setter Property="Height" Value="30" />
        </DataTrigger>
      </Style.Triggers>
    </Style>"""
    feature = window(
        style,
        """
      <Border DataContext="{StaticResource alarm}"><Label Content="x" /></Border>
      <Label Content="y" />""",
    )
    twin = window(
        "",
        """
      <Border><Label Content="x" Background="Red" Height="30" /></Border>
      <Label Content="y" />""",
    )
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    assert tuple(px[20, 40][:3]) == RED


# ------------------------------------------------------------------ ControlTemplate.Triggers

TEMPLATE = """
      <Button Content="t" Tag="{}{on}">
        <Button.Template>
          <ControlTemplate TargetType="Button">
            <Border x:Name="bd" Background="Blue" Width="{TemplateBinding Width}">
              <ContentPresenter />
            </Border>
            <ControlTemplate.Triggers>
              <DataTrigger Binding="{Binding Tag, RelativeSource={RelativeSource TemplatedParent}}"
                           Value="{}{on}">
                <Setter TargetName="bd" Property="Background" Value="Red" />
              </DataTrigger>
              <Trigger SourceName="bd" Property="Width" Value="NaN">
                <Setter Property="Height" Value="44" />
              </Trigger>
              <MultiTrigger>
                <MultiTrigger.Conditions>
                  <Condition SourceName="bd" Property="Visibility" Value="Visible" />
                  <Condition Property="IsEnabled" Value="True" />
                </MultiTrigger.Conditions>
                <Setter TargetName="bd" Property="BorderBrush" Value="Lime" />
                <Setter TargetName="bd" Property="BorderThickness" Value="3" />
              </MultiTrigger>
            </ControlTemplate.Triggers>
          </ControlTemplate>
        </Button.Template>
      </Button>"""
TEMPLATE_TWIN = """
      <Button Height="44" Content="t">
        <Button.Template>
          <ControlTemplate TargetType="Button">
            <Border Background="Red" BorderBrush="Lime" BorderThickness="3">
              <ContentPresenter />
            </Border>
          </ControlTemplate>
        </Button.Template>
      </Button>"""


def test_template_data_trigger_and_source_name(tmp_path):
    px = _same(tmp_path, window("", TEMPLATE), window("", TEMPLATE_TWIN))
    assert tuple(px[40, 40][:3]) == RED  # the Button is 44 tall: the SourceName trigger fired


def test_source_name_that_names_no_part_is_said(tmp_path):
    feature = window("", TEMPLATE.replace('SourceName="bd" Property="Width"', 'SourceName="bx" '
                                          'Property="Width"'))  # fmt: skip
    codes = _codes(tmp_path, feature)
    assert ("TPL009", _line(feature, 'SourceName="bx"')) in codes


# ------------------------------------------------------------------ bindings that need code


def test_a_binding_that_needs_code_leaves_the_trigger_unfired_said_once(tmp_path):
    style = """
    <Style TargetType="Label">
      <Setter Property="Background" Value="Blue" />
      <Style.Triggers>
        <DataTrigger Binding="{Binding IsBusy}" Value="True">
          <Setter Property="Background" Value="Red" />
        </DataTrigger>
        <DataTrigger Binding="{Binding Text, ElementName=nosuch}" Value="x">
          <Setter Property="Background" Value="Red" />
        </DataTrigger>
      </Style.Triggers>
    </Style>"""
    feature = window(style, '<Label Height="20" /><Label Height="20" />')
    codes = _codes(tmp_path, feature)
    assert [c for c in codes if c[0] == "BND001"] == [("BND001", _line(feature, "{Binding IsB"))]
    assert ("BND003", _line(feature, "ElementName=nosuch")) in codes
    assert not [c for c in codes if c[0] == "TPL003"]
    px = _window_pixels(tmp_path / "doc.xaml")
    assert tuple(px[10, 40][:3]) == (0, 0, 255)


# ------------------------------------------------------------------ DataTemplate.Triggers

PEOPLE = """
    <x:Array x:Key="people" Type="local:Person">
      <local:Person Name="Ann" Busy="True" />
      <local:Person Name="Bob" Busy="False" />
    </x:Array>"""


def test_data_template_trigger_reads_the_item(tmp_path):
    feature = window(
        PEOPLE,
        """
      <ItemsControl ItemsSource="{StaticResource people}">
        <ItemsControl.ItemTemplate>
          <DataTemplate>
            <Border x:Name="b" Background="Blue" Height="16"><TextBlock Text="{Binding Name}" />
            </Border>
            <DataTemplate.Triggers>
              <DataTrigger Binding="{Binding Busy}" Value="true">
                <Setter TargetName="b" Property="Background" Value="Red" />
                <Setter Property="Margin" Value="4" />
              </DataTrigger>
            </DataTemplate.Triggers>
          </DataTemplate>
        </ItemsControl.ItemTemplate>
      </ItemsControl>""",
    )
    rows = (
        '<ContentPresenter Margin="4"><Border Background="Red" Height="16">'
        '<TextBlock Text="Ann" /></Border></ContentPresenter>'
        '<ContentPresenter><Border Background="Blue" Height="16">'
        '<TextBlock Text="Bob" /></Border></ContentPresenter>'
    )
    twin = window(
        "", f"<ContentControl><Border><StackPanel>{rows}</StackPanel></Border></ContentControl>"
    )
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    assert tuple(px[10, 40][:3]) == RED
    assert tuple(px[30, 40][:3]) == (0, 0, 255)


def test_item_container_style_data_trigger_reads_the_item(tmp_path):
    feature = window(
        PEOPLE,
        """
      <ListBox Height="60" ItemsSource="{StaticResource people}" DisplayMemberPath="Name">
        <ListBox.ItemContainerStyle>
          <Style TargetType="ListBoxItem">
            <Style.Triggers>
              <DataTrigger Binding="{Binding Busy}" Value="True">
                <Setter Property="Background" Value="Red" />
              </DataTrigger>
            </Style.Triggers>
          </Style>
        </ListBox.ItemContainerStyle>
      </ListBox>""",
    )
    twin = window(
        "",
        """
      <ListBox Height="60">
        <ListBox.ItemContainerStyle><Style TargetType="ListBoxItem" /></ListBox.ItemContainerStyle>
        <ListBoxItem Content="Ann" Background="Red" /><ListBoxItem Content="Bob" />
      </ListBox>""",
    )
    px = _same(tmp_path, _with_ns(feature), _with_ns(twin))
    assert ((px[..., 0] == 255) & (px[..., 1] == 0) & (px[..., 2] == 0)).any()


def test_content_template_trigger_on_string_content(tmp_path):
    feature = window(
        "",
        """
      <ContentControl Content="stop">
        <ContentControl.ContentTemplate>
          <DataTemplate>
            <Border x:Name="b" Height="20" Background="Blue" />
            <DataTemplate.Triggers>
              <DataTrigger Binding="{Binding}" Value="stop">
                <Setter TargetName="b" Property="Background" Value="Red" />
              </DataTrigger>
              <Trigger Property="IsMouseOver" Value="True">
                <Setter TargetName="b" Property="Background" Value="Lime" />
              </Trigger>
            </DataTemplate.Triggers>
          </DataTemplate>
        </ContentControl.ContentTemplate>
      </ContentControl>""",
    )
    twin = window(
        "",
        '<ContentControl><ContentPresenter><Border Height="20" Background="Red" />'
        "</ContentPresenter></ContentControl>",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[10, 40][:3]) == RED
    codes = _codes(tmp_path, feature)
    assert ("TPL003", _line(feature, "<Trigger Property")) in codes


def test_style_data_trigger_on_elements_that_are_not_controls(tmp_path):
    style = """
    <Style TargetType="TextBlock">
      <Setter Property="Background" Value="Blue" />
      <Style.Triggers>
        <DataTrigger Binding="{Binding IsChecked, ElementName=box}" Value="True">
          <Setter Property="Background" Value="Red" />
        </DataTrigger>
      </Style.Triggers>
    </Style>
    <Style x:Key="b" TargetType="Border">
      <Style.Triggers>
        <MultiDataTrigger>
          <MultiDataTrigger.Conditions>
            <Condition Binding="{Binding Tag, RelativeSource={RelativeSource Self}}" Value="on" />
            <Condition Binding="{Binding IsChecked, ElementName=box}" Value="True" />
          </MultiDataTrigger.Conditions>
          <Setter Property="Height" Value="12" />
          <Setter Property="Background" Value="Orange" />
        </MultiDataTrigger>
      </Style.Triggers>
    </Style>"""
    feature = window(
        style,
        """
      <CheckBox x:Name="box" IsChecked="True" Content="c" />
      <TextBlock Text="x" />
      <TextBlock Text="y" Background="Lime" />
      <Border Style="{StaticResource b}" Tag="on" />""",
    )
    twin = window(
        "",
        """
      <CheckBox x:Name="box" IsChecked="True" Content="c" />
      <TextBlock Text="x" Background="Red" />
      <TextBlock Text="y" Background="Lime" />
      <Border Height="12" Background="Orange" />""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[20, 40][:3]) == RED


def test_data_trigger_on_find_ancestor(tmp_path):
    style = """
    <Style TargetType="Label">
      <Style.Triggers>
        <DataTrigger Binding="{Binding Tag, RelativeSource={RelativeSource
                               AncestorType=StackPanel}}" Value="alert">
          <Setter Property="Background" Value="Red" />
        </DataTrigger>
      </Style.Triggers>
    </Style>"""
    feature = window(
        style,
        """
      <StackPanel Tag="alert"><Label Content="a" /></StackPanel>
      <StackPanel Tag="calm"><Label Content="b" /></StackPanel>""",
    )
    twin = window(
        "",
        """
      <StackPanel><Label Content="a" Background="Red" /></StackPanel>
      <StackPanel><Label Content="b" /></StackPanel>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[5, 40][:3]) == RED


def test_a_value_of_code_is_not_known(tmp_path):
    style = """
    <Style TargetType="Label">
      <Style.Triggers>
        <DataTrigger Binding="{Binding Tag, RelativeSource={RelativeSource Self}}"
                     Value="{x:Static SystemColors.ControlBrush}">
          <Setter Property="Background" Value="Red" />
        </DataTrigger>
      </Style.Triggers>
    </Style>"""
    feature = window(style, '<Label Content="a" Tag="x" />')
    codes = _codes(tmp_path, feature)
    assert ("TPL003", _line(feature, "<DataTrigger")) in codes
