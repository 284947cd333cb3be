"""The framework step's control templates and triggers (xaml3d.framework.templates): each
feature rendered beside a hand-written twin (the element tree WPF builds from it, written
out) must give the same pixels, through ``render --window`` and inside a VisualBrush; and the
step's diagnostics, names and source positions."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import xaml3d
from xaml3d.pipeline import load
from xaml3d.render.window import compose_window

HEAD = (
    '<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="176" Height="139">'
)
VIEWPORT = """
    <Viewport3D Grid.Column="1">
      <Viewport3D.Camera>
        <OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" UpDirection="0,1,0"
                            Width="80" />
      </Viewport3D.Camera>
      <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
        <AmbientLight Color="White" />
        <GeometryModel3D>
          <GeometryModel3D.Geometry>
            <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,16,0 -16,16,0"
                            TriangleIndices="0 1 2  0 2 3" />
          </GeometryModel3D.Geometry>
          <GeometryModel3D.Material><DiffuseMaterial Brush="Lime" /></GeometryModel3D.Material>
        </GeometryModel3D>
      </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
    </Viewport3D>"""


def window(resources: str, left: str) -> str:
    """A 160 x 100 window: ``left`` in an 80 px column beside a viewport."""
    return f"""{HEAD}
  <Window.Resources>{resources}</Window.Resources>
  <Grid Background="White">
    <Grid.ColumnDefinitions>
      <ColumnDefinition Width="80" /><ColumnDefinition />
    </Grid.ColumnDefinitions>
    <StackPanel>{left}</StackPanel>{VIEWPORT}
  </Grid>
</Window>"""


def in_brush(resources: str, visual: str) -> str:
    """A 64 x 64 viewport filled by a square whose material is a VisualBrush of ``visual``."""
    return f"""{HEAD.replace('Width="176" Height="139"', "")}
  <Window.Resources>{resources}</Window.Resources>
  <Viewport3D Width="64" Height="64">
    <Viewport3D.Camera>
      <OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" UpDirection="0,1,0"
                          Width="64" />
    </Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
      <AmbientLight Color="White" />
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="-32,-32,0 32,-32,0 32,32,0 -32,32,0"
                          TextureCoordinates="0,1 1,1 1,0 0,0" TriangleIndices="0 1 2  0 2 3" />
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material>
          <DiffuseMaterial><DiffuseMaterial.Brush>
            <VisualBrush><VisualBrush.Visual>{visual}</VisualBrush.Visual></VisualBrush>
          </DiffuseMaterial.Brush></DiffuseMaterial>
        </GeometryModel3D.Material>
      </GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</Window>"""


def _window_pixels(path: Path) -> np.ndarray:
    rgba, _ = compose_window(load(path))
    return np.asarray(rgba)


def _viewport_pixels(path: Path) -> np.ndarray:
    return np.asarray(xaml3d.render(str(path)).convert("RGBA"))


def _line(text: str, part: str) -> int:
    """The 1-based line of ``text`` where ``part`` first appears."""
    return text[: text.index(part)].count("\n") + 1


def _same(tmp_path: Path, feature: str, twin: str, pixels=_window_pixels) -> np.ndarray:
    a, b = tmp_path / "feature.xaml", tmp_path / "twin.xaml"
    a.write_text(feature, encoding="utf-8")
    b.write_text(twin, encoding="utf-8")
    pa, pb = pixels(a), pixels(b)
    assert pa.shape == pb.shape
    assert np.array_equal(pa, pb), f"{int((pa != pb).any(axis=-1).sum())} pixels differ"
    return pa


FLAT_STYLE = """
    <Style x:Key="flat" TargetType="Button">
      <Setter Property="Foreground" Value="White" />
      <Setter Property="Template">
        <Setter.Value>
          <ControlTemplate TargetType="Button">
            <Border Background="Blue" BorderBrush="Orange" BorderThickness="4">
              <ContentPresenter HorizontalAlignment="Center" VerticalAlignment="Center" />
            </Border>
          </ControlTemplate>
        </Setter.Value>
      </Setter>
    </Style>"""
# what WPF builds from a Button drawn by that template: the Button (its own size and
# Foreground) holding the Border, the presenter and the TextBlock for its string content
FLAT_TWIN = """
      <ContentControl Height="40" Foreground="White">
        <Border Background="Blue" BorderBrush="Orange" BorderThickness="4">
          <ContentPresenter HorizontalAlignment="Center" VerticalAlignment="Center">
            <TextBlock Text="Go" />
          </ContentPresenter>
        </Border>
      </ContentControl>"""


def test_style_template_is_the_tree_wpf_builds(tmp_path):
    feature = window(FLAT_STYLE, '<Button Height="40" Style="{StaticResource flat}">Go</Button>')
    px = _same(tmp_path, feature, window("", FLAT_TWIN))
    assert tuple(px[20, 2]) == (255, 165, 0, 255)  # the orange border
    assert tuple(px[6, 10]) == (0, 0, 255, 255)  # the blue face


def test_style_template_inside_a_visual_brush(tmp_path):
    button = '<Button Height="40" Style="{StaticResource flat}">Go</Button>'
    visual = f'<StackPanel Width="64">{button}</StackPanel>'
    twin = f'<StackPanel Width="64">{FLAT_TWIN}</StackPanel>'
    px = _same(tmp_path, in_brush(FLAT_STYLE, visual), in_brush("", twin), _viewport_pixels)
    assert tuple(px[20, 20][:3]) == (0, 0, 255)


def test_template_property_element_and_element_content(tmp_path):
    feature = window(
        "",
        """
      <Button Height="30">
        <Button.Template>
          <ControlTemplate TargetType="Button">
            <Border Background="Blue" BorderBrush="Orange" BorderThickness="2">
              <ContentPresenter Margin="3" />
            </Border>
          </ControlTemplate>
        </Button.Template>
        <StackPanel Orientation="Horizontal">
          <Rectangle Width="8" Height="8" Fill="Lime" /><TextBlock Text="Hi" />
        </StackPanel>
      </Button>""",
    )
    twin = window(
        "",
        """
      <ContentControl Height="30">
        <Border Background="Blue" BorderBrush="Orange" BorderThickness="2">
          <ContentPresenter Margin="3">
            <StackPanel Orientation="Horizontal">
              <Rectangle Width="8" Height="8" Fill="Lime" /><TextBlock Text="Hi" />
            </StackPanel>
          </ContentPresenter>
        </Border>
      </ContentControl>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[14, 8][:3]) == (0, 255, 0)  # the rectangle at 2 + 3 px, centred


BOUND_STYLE = """
    <Style x:Key="base" TargetType="{x:Type Button}">
      <Setter Property="Height" Value="30" />
      <Setter Property="Template">
        <Setter.Value>
          <ControlTemplate TargetType="{x:Type Button}">
            <Border Background="{TemplateBinding Background}"
                    BorderBrush="{TemplateBinding BorderBrush}"
                    BorderThickness="{TemplateBinding BorderThickness}"
                    Padding="{TemplateBinding Padding}">
              <ContentPresenter
                HorizontalAlignment="{TemplateBinding HorizontalContentAlignment}"
                VerticalAlignment="{Binding VerticalContentAlignment,
                                    RelativeSource={RelativeSource TemplatedParent}}" />
            </Border>
          </ControlTemplate>
        </Setter.Value>
      </Setter>
    </Style>
    <Style x:Key="accent" TargetType="{x:Type Button}" BasedOn="{StaticResource base}">
      <Setter Property="Background" Value="Blue" />
      <Setter Property="BorderBrush" Value="Orange" />
      <Setter Property="BorderThickness" Value="3" />
      <Setter Property="Foreground" Value="White" />
    </Style>"""


def test_template_binding_reads_local_style_based_on_and_theme_values(tmp_path):
    feature = window(
        BOUND_STYLE,
        """
      <Button Style="{StaticResource accent}" Content="One" />
      <Button Style="{StaticResource base}" Content="Two" />
      <Button Style="{StaticResource accent}" Background="Yellow" Content="Three" />""",
    )

    def twin_button(text, bg, bb, bt, fg):
        fg = f' Foreground="{fg}"' if fg else ""
        return f"""
      <ContentControl Height="30"{fg}>
        <Border Background="{bg}" BorderBrush="{bb}" BorderThickness="{bt}" Padding="1">
          <ContentPresenter HorizontalAlignment="Center" VerticalAlignment="Center">
            <TextBlock Text="{text}" />
          </ContentPresenter>
        </Border>
      </ContentControl>"""

    twin = window("", twin_button("One", "Blue", "Orange", 3, "White")
                  # the theme's (Aero2) Button values where neither the Button nor its Style set one
                  + twin_button("Two", "#FFDDDDDD", "#FF707070", 1, None)
                  + twin_button("Three", "Yellow", "Orange", 3, "White"))  # fmt: skip
    px = _same(tmp_path, feature, twin)
    assert tuple(px[35, 40][:3]) == (221, 221, 221)
    assert tuple(px[64, 6][:3]) == (255, 255, 0)


TOGGLE_STYLE = """
    <Style TargetType="ToggleButton">
      <Setter Property="Height" Value="30" />
      <Setter Property="Background" Value="Yellow" />
      <Setter Property="BorderBrush" Value="Blue" />
      <Setter Property="Template">
        <Setter.Value>
          <ControlTemplate TargetType="ToggleButton">
            <Border x:Name="face" Background="{TemplateBinding Background}"
                    BorderBrush="{TemplateBinding BorderBrush}" BorderThickness="2">
              <ContentPresenter HorizontalAlignment="Center" VerticalAlignment="Center" />
            </Border>
            <ControlTemplate.Triggers>
              <Trigger Property="IsChecked" Value="True">
                <Setter TargetName="face" Property="Background" Value="Lime" />
              </Trigger>
              <Trigger Property="IsMouseOver" Value="True">
                <Setter TargetName="face" Property="Background" Value="Cyan" />
              </Trigger>
            </ControlTemplate.Triggers>
          </ControlTemplate>
        </Setter.Value>
      </Setter>
      <Style.Triggers>
        <Trigger Property="IsEnabled" Value="False">
          <Setter Property="Background" Value="Gray" />
        </Trigger>
        <MultiTrigger>
          <MultiTrigger.Conditions>
            <Condition Property="IsChecked" Value="False" />
            <Condition Property="Tag" Value="x" />
          </MultiTrigger.Conditions>
          <Setter Property="BorderBrush" Value="Magenta" />
        </MultiTrigger>
      </Style.Triggers>
    </Style>"""


def test_triggers_known_at_load(tmp_path):
    feature = window(
        TOGGLE_STYLE,
        """
      <ToggleButton IsChecked="True" Content="On" />
      <ToggleButton Tag="x" Content="Off" />
      <ToggleButton IsEnabled="False" Content="No" />""",
    )

    def twin_toggle(text, bg, bb):
        return f"""
      <ContentControl Height="30">
        <Border Background="{bg}" BorderBrush="{bb}" BorderThickness="2">
          <ContentPresenter HorizontalAlignment="Center" VerticalAlignment="Center">
            <TextBlock Text="{text}" />
          </ContentPresenter>
        </Border>
      </ContentControl>"""

    twin = window("", twin_toggle("On", "Lime", "Blue") + twin_toggle("Off", "Yellow", "Magenta")
                  + twin_toggle("No", "Gray", "Blue"))  # fmt: skip
    px = _same(tmp_path, feature, twin)
    assert tuple(px[4, 4][:3]) == (0, 255, 0)
    assert tuple(px[30, 0][:3]) == (255, 0, 255)
    assert tuple(px[64, 4][:3]) == (128, 128, 128)


def test_local_value_beats_triggers_and_template_names_stay_private(tmp_path):
    # a part named like an element of the window: no duplicate name, and the storyboard
    # target is the window's element
    feature = window(
        TOGGLE_STYLE,
        """
      <ToggleButton IsChecked="True" Content="A" />
      <Border x:Name="face" Height="10" Background="Blue" />""",
    )
    path = tmp_path / "names.xaml"
    path.write_text(feature, encoding="utf-8")
    scene = load(path)
    assert not [d for d in scene.diagnostics if d.severity != "info"]
    px = _window_pixels(path)
    assert tuple(px[35, 40][:3]) == (0, 0, 255)


def test_merged_dictionary_theme(tmp_path):
    (tmp_path / "theme.xaml").write_text(
        """<ResourceDictionary xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation">
  <Style TargetType="Button">
    <Setter Property="Template">
      <Setter.Value>
        <ControlTemplate TargetType="Button">
          <Border BorderBrush="{TemplateBinding Foreground}" BorderThickness="1">
            <ContentPresenter Margin="4,2" />
          </Border>
        </ControlTemplate>
      </Setter.Value>
    </Setter>
  </Style>
</ResourceDictionary>""",
        encoding="utf-8",
    )
    merged = """<ResourceDictionary><ResourceDictionary.MergedDictionaries>
      <ResourceDictionary Source="theme.xaml" /></ResourceDictionary.MergedDictionaries>
    </ResourceDictionary>"""
    feature = window(merged, '<Button Height="24" Foreground="Blue">Theme</Button>')
    twin = window(
        "",
        """
      <ContentControl Height="24" Foreground="Blue">
        <Border BorderBrush="Blue" BorderThickness="1">
          <ContentPresenter Margin="4,2"><TextBlock Text="Theme" /></ContentPresenter>
        </Border>
      </ContentControl>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[0, 40][:3]) == (0, 0, 255)


def test_a_bound_resource_reference_resolves_where_the_control_is(tmp_path):
    # the template lives in a merged dictionary's file, the brush in the window: WPF resolves
    # the Button's own StaticResource in the Button's scope, then the Border binds its value
    (tmp_path / "look.xaml").write_text(
        """<ResourceDictionary xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation">
  <Style TargetType="Button">
    <Setter Property="Template">
      <Setter.Value>
        <ControlTemplate TargetType="Button">
          <Border Background="{TemplateBinding Background}" BorderBrush="Black"
                  BorderThickness="2" />
        </ControlTemplate>
      </Setter.Value>
    </Setter>
  </Style>
</ResourceDictionary>""",
        encoding="utf-8",
    )
    merged = """<ResourceDictionary><ResourceDictionary.MergedDictionaries>
      <ResourceDictionary Source="look.xaml" /></ResourceDictionary.MergedDictionaries>
      <SolidColorBrush x:Key="known" Color="Red" />
    </ResourceDictionary>"""
    feature = window(merged, '<Button Height="24" Background="{StaticResource known}" />')
    twin = window(
        "",
        """
      <ContentControl Height="24">
        <Border Background="Red" BorderBrush="Black" BorderThickness="2" />
      </ContentControl>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[12, 40][:3]) == (255, 0, 0)
    assert not [d for d in load(tmp_path / "feature.xaml").diagnostics if d.code == "RES001"]


def test_unsupported_template_is_said(tmp_path):
    feature = window(
        "",
        """
      <Slider Height="30">
        <Slider.Template>
          <ControlTemplate TargetType="Slider"><Border Background="Blue" /></ControlTemplate>
        </Slider.Template>
      </Slider>
      <ToggleButton Height="20" Content="x">
        <ToggleButton.Template>
          <ControlTemplate TargetType="ToggleButton">
            <Border x:Name="b"><ContentPresenter /></Border>
            <ControlTemplate.Triggers>
              <DataTrigger Binding="{Binding Busy}" Value="True">
                <Setter TargetName="b" Property="Background" Value="Red" />
              </DataTrigger>
              <Trigger Property="IsChecked" Value="False">
                <Setter TargetName="nothere" Property="Background" Value="Red" />
              </Trigger>
            </ControlTemplate.Triggers>
          </ControlTemplate>
        </ToggleButton.Template>
      </ToggleButton>""",
    )
    path = tmp_path / "unsupported.xaml"
    path.write_text(feature, encoding="utf-8")
    codes = {(d.code, d.line) for d in load(path).diagnostics}
    assert ("TPL001", _line(feature, "<Slider ")) in codes
    assert ("BND001", _line(feature, "<DataTrigger")) in codes  # its binding needs code
    assert ("TPL005", _line(feature, 'TargetName="nothere"')) in codes
    px = _window_pixels(path)
    assert not ((px[..., 0] == 255) & (px[..., 1] == 0) & (px[..., 2] == 0)).any()


def test_diagnostics_inside_a_template_point_into_it(tmp_path):
    feature = window(FLAT_STYLE.replace('BorderThickness="4"', 'BorderThickness="4x"'),
                     '<Button Height="40" Style="{StaticResource flat}">Go</Button>')  # fmt: skip
    path = tmp_path / "bad.xaml"
    path.write_text(feature, encoding="utf-8")
    found = [(d.code, d.line) for d in load(path).diagnostics if d.code.startswith("VAL")]
    # once, in the template's text (where the copy the window draws comes from)
    assert found == [("VAL001", _line(feature, 'BorderThickness="4x"'))]


def test_cli_window_render_of_a_templated_button(tmp_path):
    path = tmp_path / "b.xaml"
    path.write_text(
        window(FLAT_STYLE, '<Button Height="40" Style="{StaticResource flat}">Go</Button>'),
        encoding="utf-8",
    )
    out = tmp_path / "b.png"
    run = subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", str(path), "--window", "-o", str(out)],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    assert "Traceback" not in run.stderr
    from PIL import Image

    px = np.asarray(Image.open(out).convert("RGBA"))
    assert tuple(px[6, 10]) == (0, 0, 255, 255)


@pytest.mark.parametrize("markup", ["<Grid/>", "<Border><Viewport3D/></Border>"])
def test_a_document_without_controls_is_untouched(markup):
    from lxml import etree

    from xaml3d.framework import templates

    root = etree.fromstring(
        f'<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation">{markup}</Window>'
    )
    before = etree.tostring(root)

    class Nothing:
        def __getattr__(self, name):
            raise AssertionError(f"services.{name} called")

    templates.instantiate(root, Nothing())
    assert etree.tostring(root) == before


def test_content_template_of_a_content_control(tmp_path):
    resources = """
    <DataTemplate x:Key="card">
      <Border Background="{Binding Color}" Padding="4"><TextBlock Text="{Binding Name}" /></Border>
    </DataTemplate>
    <DataTemplate x:Key="shout"><TextBlock Text="{Binding}" Foreground="Blue" /></DataTemplate>
    <local:Person x:Key="ann" Name="Ann" Color="Orange" />"""
    feature = window(
        resources,
        """
      <ContentControl Content="{StaticResource ann}" ContentTemplate="{StaticResource card}" />
      <ContentControl Content="Hey" ContentTemplate="{StaticResource shout}" />""",
    )
    # ContentControl's default template: a ContentPresenter holding the DataTemplate's content
    twin = window(
        "",
        """
      <ContentControl><ContentPresenter>
        <Border Background="Orange" Padding="4"><TextBlock Text="Ann" /></Border>
      </ContentPresenter></ContentControl>
      <ContentControl><ContentPresenter>
        <TextBlock Text="Hey" Foreground="Blue" />
      </ContentPresenter></ContentControl>""",
    )
    local = 'xmlns:local="clr-namespace:Demo" xmlns:x='
    feature, twin = (t.replace("xmlns:x=", local, 1) for t in (feature, twin))
    px = _same(tmp_path, feature, twin)
    assert tuple(px[2, 40][:3]) == (255, 165, 0)


REFERENCE = Path(__file__).resolve().parent / "reference" / "layout"


def test_cli_window_whose_only_viewport_is_in_a_template(tmp_path):
    case = REFERENCE / "window-template-viewport.xaml"
    out = tmp_path / "w.png"
    run = subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", str(case), "--window", "-o", str(out)],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    from PIL import Image

    px = np.asarray(Image.open(out).convert("RGBA"))
    assert px.shape == (100, 160, 4)
    assert tuple(px[50, 80]) == (0, 255, 0, 255)  # the template's viewport draws its square
    assert tuple(px[4, 4]) == (255, 255, 0, 255)  # the template's Border
    info = subprocess.run(
        [sys.executable, "-m", "xaml3d", "info", str(case)], capture_output=True, text=True
    )
    assert info.returncode == 0, info.stderr
    assert "1 viewport(s)" in info.stdout
    assert "viewport 0: 144 x 84" in info.stdout
    assert "XAML015" not in info.stderr + run.stderr


def test_a_data_template_viewport_per_item():
    text = f"""{HEAD}
  <ItemsControl>
    <ItemsControl.ItemTemplate>
      <DataTemplate>
        <Viewport3D Width="60" Height="40">
          <Viewport3D.Camera><OrthographicCamera Width="4" /></Viewport3D.Camera>
          <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight />
            <GeometryModel3D>
              <GeometryModel3D.Geometry>
                <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2" />
              </GeometryModel3D.Geometry>
              <GeometryModel3D.Material>
                <DiffuseMaterial Brush="{{Binding}}" />
              </GeometryModel3D.Material>
            </GeometryModel3D>
          </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
        </Viewport3D>
      </DataTemplate>
    </ItemsControl.ItemTemplate>
    <x:String>Red</x:String>
    <x:String>Blue</x:String>
  </ItemsControl>
</Window>"""
    scene = load(text, text=True)
    assert len(scene.viewports) == 2
    colours = [vp.models[0].material[0].brush.color for vp in scene.viewports]
    assert colours[0][:3] == (1.0, 0.0, 0.0) and colours[1][:3] == (0.0, 0.0, 1.0)
    assert not [d for d in scene.diagnostics if d.code == "XAML015"]


def test_style_trigger_on_a_control_in_the_theme_look(tmp_path):
    style = """
    <Style TargetType="Button">
      <Style.Triggers>
        <Trigger Property="IsEnabled" Value="False">
          <Setter Property="Opacity" Value="0.4" />
          <Setter Property="Foreground" Value="Blue" />
        </Trigger>
      </Style.Triggers>
    </Style>"""
    buttons = '<Button Height="24" Content="On" /><Button Height="24" Content="Off" {} />'
    feature = window(style, buttons.format('IsEnabled="False"'))
    twin = window("", buttons.format('IsEnabled="False" Opacity="0.4" Foreground="Blue"'))
    plain = window("", buttons.format('IsEnabled="False"'))
    px = _same(tmp_path, feature, twin)
    (tmp_path / "plain.xaml").write_text(plain, encoding="utf-8")
    assert not np.array_equal(px, _window_pixels(tmp_path / "plain.xaml"))


def test_a_template_that_holds_itself_twice_is_an_error_and_draws_nothing(tmp_path):
    style = """
    <Style TargetType="Button">
      <Setter Property="Template">
        <Setter.Value>
          <ControlTemplate TargetType="Button">
            <StackPanel><Button /><Button /></StackPanel>
          </ControlTemplate>
        </Setter.Value>
      </Setter>
    </Style>"""
    path = tmp_path / "self.xaml"
    text = window(style, '<Button Height="20" />')
    path.write_text(text, encoding="utf-8")
    scene = load(path)
    at = _line(text, '<Button Height="20"')  # the document's Button, the cycle's outermost
    found = [(d.code, d.severity, d.line) for d in scene.diagnostics if d.severity != "info"]
    assert found == [("TPL004", "error", at)]  # no DRW002 follow-on
    # WPF overflows its stack: the Button draws nothing, only the window's StackPanel is left
    assert sum(b.type == "StackPanel" for b in scene.layout.boxes) == 1


def test_a_template_copy_resolves_resources_in_the_template_scope(tmp_path):
    style = """
    <Style x:Key="s" TargetType="Button">
      <Style.Resources>
        <SolidColorBrush x:Key="edge" Color="Orange" />
      </Style.Resources>
      <Setter Property="Template">
        <Setter.Value>
          <ControlTemplate TargetType="Button">
            <ControlTemplate.Resources>
              <SolidColorBrush x:Key="face" Color="Blue" />
            </ControlTemplate.Resources>
            <Border Background="{StaticResource face}" BorderBrush="{StaticResource edge}"
                    BorderThickness="4" />
          </ControlTemplate>
        </Setter.Value>
      </Setter>
    </Style>"""
    feature = window(style, '<Button Height="40" Style="{StaticResource s}" />')
    twin = window(
        "",
        '<ContentControl Height="40"><Border Background="Blue" BorderBrush="Orange" '
        'BorderThickness="4" /></ContentControl>',
    )
    path = tmp_path / "scope.xaml"
    path.write_text(feature, encoding="utf-8")
    assert not [d for d in load(path).diagnostics if d.severity != "info"]
    _same(tmp_path, feature, twin)


def test_theme_template_draws_the_button_family_with_its_states(tmp_path):
    # no template of the document's: the theme's (a Border around a ContentPresenter at
    # Padding 1, content centred), the user Style's Setter above the theme's Background; the
    # theme's triggers: IsEnabled False inherited from the panel, IsChecked, IsDefaulted
    style = '<Style TargetType="Button"><Setter Property="Background" Value="Yellow" /></Style>'
    buttons = """
      <Button Height="24">Go</Button>
      <StackPanel IsEnabled="False"><RepeatButton Height="24">No</RepeatButton></StackPanel>
      <ToggleButton Height="24" IsChecked="True">On</ToggleButton>
      <Button Height="24" IsDefault="True">OK</Button>"""

    def twin(text, face, band, foreground=""):
        return f"""
      <ContentControl Height="24"{foreground}>
        <Border Background="{face}" BorderBrush="{band}" BorderThickness="1">
          <ContentPresenter Margin="1" HorizontalAlignment="Center" VerticalAlignment="Center">
            <TextBlock Text="{text}" />
          </ContentPresenter>
        </Border>
      </ContentControl>"""

    twins = "".join((
        twin("Go", "Yellow", "#FF707070"),
        twin("No", "#FFF4F4F4", "#FFADB2B5", ' Foreground="#FF838383"'),
        twin("On", "#FFBCDDEE", "#FF245A83"),
        twin("OK", "Yellow", "#FF0078D7"),
    ))  # fmt: skip
    px = _same(tmp_path, window(style, buttons), window("", twins))
    assert tuple(px[12, 3]) == (255, 255, 0, 255) and tuple(px[0, 40]) == (112, 112, 112, 255)
    assert tuple(px[27, 3]) == (244, 244, 244, 255) and tuple(px[24, 40]) == (173, 178, 181, 255)
    assert tuple(px[51, 3]) == (188, 221, 238, 255) and tuple(px[48, 40]) == (36, 90, 131, 255)
    assert tuple(px[72, 40]) == (0, 120, 215, 255)
    # the disabled text is grey (#FF838383 at its darkest), the enabled text black
    assert 125 <= px[26:46, 2:78, :3].min() <= 140 and px[2:22, 2:78, :3].min() < 60


def test_theme_template_not_for_a_tool_bar_nor_over_a_default_style(tmp_path):
    doc = window("", '<ToolBar><Button Content="Open" /></ToolBar>'
                     '<Button Height="24" OverridesDefaultStyle="True">Go</Button>')  # fmt: skip
    scene = load(doc, text=True)
    types = [b.type for b in scene.layout.boxes]
    # the ToolBar's button keeps the ToolBar's Style (drawn by the reader's ToolBar); a Button
    # over no default Style has no template: nothing of the theme's is built for either
    assert "Border" not in types and "ContentPresenter" not in types


CHECK_GLYPH = (
    "F1 M 9.97498,1.22334L 4.6983,9.09834L 4.52164,9.09834L 0,5.19331L 1.27664,3.52165"
    "L 4.255,6.08833L 8.33331,1.52588e-005L 9.97498,1.22334 Z"
)


def _option_twin(mark: str, text: str | None, margin: str = "1") -> str:
    """What WPF builds from a CheckBox or RadioButton in the theme's look: the two-column Grid,
    the mark's Border in column 0, the ContentPresenter (Padding 4,-1,0,0 when it has content)
    in column 1."""
    presenter = (
        '<ContentPresenter Grid.Column="1" Margin="4,-1,0,0" HorizontalAlignment="Left" '
        f'VerticalAlignment="Top"><TextBlock Text="{text}" /></ContentPresenter>'
        if text is not None
        else '<ContentPresenter Grid.Column="1" HorizontalAlignment="Left" '
        'VerticalAlignment="Top" />'
    )
    return f"""
      <ContentControl>
        <Grid Background="Transparent">
          <Grid.ColumnDefinitions>
            <ColumnDefinition Width="Auto" /><ColumnDefinition Width="*" />
          </Grid.ColumnDefinitions>
          {mark}
          {presenter}
        </Grid>
      </ContentControl>"""


def _check_mark(face, band, glyph, check, square) -> str:
    return f"""<Border Margin="1" HorizontalAlignment="Left" VerticalAlignment="Top"
                  BorderThickness="1" Background="{face}" BorderBrush="{band}">
            <Grid>
              <Path Opacity="{check}" Stretch="None" Margin="1" Fill="{glyph}"
                    Data="{CHECK_GLYPH}" />
              <Rectangle Margin="2" Opacity="{square}" Fill="{glyph}" />
            </Grid>
          </Border>"""


def _radio_mark(face, band, glyph, dot) -> str:
    return f"""<Border Margin="1,1,2,1" CornerRadius="100" HorizontalAlignment="Left"
                  VerticalAlignment="Top" BorderThickness="1" Background="{face}"
                  BorderBrush="{band}">
            <Grid Margin="2">
              <Ellipse Opacity="{dot}" MinWidth="6" MinHeight="6" Fill="{glyph}" />
            </Grid>
          </Border>"""


def test_theme_template_draws_check_boxes_and_radio_buttons_with_their_states(tmp_path):
    # the theme's templates: the mark's Border at Margin 1 (the check Path's natural size, its
    # geometry's extent from the origin), the content at the HasContent trigger's Padding; the
    # triggers IsChecked True and {x:Null}, IsEnabled False (from a disabled panel too), and a
    # local Background above the theme Style's
    controls = """
      <CheckBox IsChecked="True" Background="Yellow">On</CheckBox>
      <CheckBox IsThreeState="True" IsChecked="{x:Null}" IsEnabled="False">Mid</CheckBox>
      <CheckBox />
      <StackPanel IsEnabled="False"><RadioButton IsChecked="True">No</RadioButton></StackPanel>
      <RadioButton IsChecked="{x:Null}" Content="Any" />"""
    twins = "".join((
        _option_twin(_check_mark("Yellow", "#FF707070", "#FF212121", 1, 0), "On"),
        _option_twin(_check_mark("#FFE6E6E6", "#FFBCBCBC", "#FF707070", 0, 1), "Mid"),
        _option_twin(_check_mark("#FFFFFFFF", "#FF707070", "#FF212121", 0, 0), None),
        '<StackPanel IsEnabled="False">'
        + _option_twin(_radio_mark("#FFE6E6E6", "#FFBCBCBC", "#FF707070", 1), "No")
        + "</StackPanel>",
        _option_twin(_radio_mark("#FFFFFFFF", "#FF707070", "#FF212121", 0.56), "Any"),
    ))  # fmt: skip
    px = _same(tmp_path, window("", controls), window("", twins))
    # the first box: its border at (1,1), yellow inside, the dark check mark
    assert tuple(px[1, 1]) == (112, 112, 112, 255) and tuple(px[2, 2]) == (255, 255, 0, 255)
    assert px[3:12, 3:13, 0].min() == 33
    # the second (disabled, indeterminate): the grey square of the indeterminate mark
    top = 15  # the first CheckBox is as tall as its box, 13.1 px, and its margins
    assert tuple(px[top + 6, 6]) == (112, 112, 112, 255) and tuple(px[top + 2, 2]) == (
        230, 230, 230, 255)  # fmt: skip
    # text 20 px in (the mark's column is 15.97 px, the Padding 4)
    assert px[0:15, 15:19, :3].min() > 200 and px[0:15, 19:30, :3].min() < 80


def test_theme_template_not_for_the_option_controls_of_a_tool_bar(tmp_path):
    doc = window("", '<ToolBar><CheckBox Content="Bold" IsChecked="True" /></ToolBar>')
    scene = load(doc, text=True)
    types = [b.type for b in scene.layout.boxes]
    # the ToolBar's CheckBox keeps the ToolBar's own Style (drawn by the reader's ToolBar)
    assert "Path" not in types and "ContentPresenter" not in types


def test_a_presenters_text_takes_the_applications_implicit_text_style_not_the_windows(tmp_path):
    # WPF stops the implicit Style look-up of the TextBlock a ContentPresenter makes at its
    # templated parent: the window's TextBlock Style paints the plain TextBlock only; the
    # application's (a resource file given as App.xaml's) reaches the CheckBox's text too
    style = '<Style TargetType="TextBlock"><Setter Property="Background" Value="Red" /></Style>'
    body = '<CheckBox Content="c" /><TextBlock Text="x" />'
    twin = '<CheckBox Content="c" /><TextBlock Text="x" Background="Red" />'
    _same(tmp_path, window(style, body), window("", twin))
    app = tmp_path / "app.xaml"
    app.write_text(
        '<ResourceDictionary xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation">'
        f"{style}</ResourceDictionary>",
        encoding="utf-8",
    )
    doc = tmp_path / "w.xaml"
    doc.write_text(window("", body), encoding="utf-8")
    rgba, _ = compose_window(load(doc, [app]))
    px = np.asarray(rgba)
    # the CheckBox's text (from x = 20, 1 px above its row) and the TextBlock below: red
    assert tuple(px[13, 22][:3]) == (255, 0, 0) and tuple(px[20, 40][:3]) == (255, 0, 0)


def test_theme_template_draws_label_text_box_and_password_box(tmp_path):
    # no template of the document's: the theme's. A Label: a Border at Padding 5 around a
    # presenter top left (its access key hidden). A TextBox and a PasswordBox: a white Border
    # (#FFABADB3, 1 px) around PART_ContentHost, which holds the text view: a TextBlock 2 px in
    # from each side showing Text (TextWrapping and TextAlignment passed on), or PasswordChar
    # for each character of Password. IsEnabled False: Label's grey text, the box's Border at
    # Opacity 0.56; IsReadOnly shows nothing
    controls = """
      <Label Content="_Name" />
      <TextBox Text="Hello" IsReadOnly="True" />
      <TextBox Width="60" TextWrapping="Wrap" TextAlignment="Center">one two three</TextBox>
      <PasswordBox Password="abc" />
      <PasswordBox Password="xy" PasswordChar="*" />
      <StackPanel IsEnabled="False"><TextBox Text="Off" /><Label>Off</Label></StackPanel>
      <TextBox Padding="4,1" Text="pad" />"""

    def label(text, foreground="#FF000000"):
        return f"""
      <ContentControl Foreground="{foreground}">
        <Border Background="Transparent" Padding="5">
          <ContentPresenter HorizontalAlignment="Left" VerticalAlignment="Top">
            <TextBlock Text="{text}" />
          </ContentPresenter>
        </Border>
      </ContentControl>"""

    def box(text, own="", opacity="1", view=""):
        return f"""
      <ContentControl Foreground="#FF000000"{own}>
        <Border Background="#FFFFFFFF" BorderBrush="#FFABADB3" BorderThickness="1"
                Opacity="{opacity}">
          <ContentPresenter><TextBlock Text="{text}" Margin="2,0,2,0"{view} /></ContentPresenter>
        </Border>
      </ContentControl>"""

    twins = "".join((
        label("Name"),
        box("Hello"),
        box("one two three", ' Width="60"', view=' TextWrapping="Wrap" TextAlignment="Center"'),
        box("\u25cf\u25cf\u25cf"),
        box("**"),
        box("Off", opacity="0.56"),
        label("Off", "#FF6D6D6D"),
        box("pad", view=' Margin="6,1,6,1"').replace(' Margin="2,0,2,0"', ""),
    ))  # fmt: skip
    feature = window("", controls).replace('Height="139"', 'Height="239"')
    px = _same(tmp_path, feature, window("", twins).replace('Height="139"', 'Height="239"'))
    scene = load(feature, text=True)
    boxes = [b for b in scene.layout.boxes if b.type in ("Label", "TextBox", "PasswordBox")]
    rects = [b.rect for b in boxes]
    line = 12 * 2724 / 2048  # Segoe UI's line at 12 px
    # Label: a line and Padding 5 each side; TextBox, PasswordBox: a line and the 1 px border
    assert rects[0][3] == line + 10 and rects[1][3] == line + 2
    # wrapped in 60 - 2 - 4 px: "one two" | "three"
    assert rects[2][2] == 60 and rects[2][3] == 2 * line + 2
    # the box's white face and border; the disabled box's border at Opacity 0.56 on white
    y = round(rects[1][1])
    assert tuple(px[y, 40]) == (171, 173, 179, 255) and tuple(px[y + 8, 70]) == (255,) * 4
    y = round(rects[5][1])
    assert tuple(px[y, 40][:3]) == tuple(round(255 - 0.56 * (255 - c)) for c in (171, 173, 179))
    # the text view starts 2 px inside the border: nothing inked at the first 2 columns in
    y = round(rects[1][1])
    assert (px[y + 2 : y + 15, 1:3, :3] == 255).all() and px[y + 2 : y + 15, 3:40, :3].min() < 80
    # a Padding insets the text view inside the border, beside its own 2 px
    assert rects[7][3] == line + 4
    # the password's marks are drawn (black), the empty part of the box white
    y = round(rects[3][1])
    assert px[y + 2 : y + 15, 3:30, :3].min() < 60 and (px[y + 2 : y + 15, 50:78] == 255).all()


def test_text_host_in_a_users_template_and_inside_a_visual(tmp_path):
    # a user's TextBox template: its PART_ContentHost (a ScrollViewer) holds the text view, as
    # WPF's TextBoxBase fills it; no TPL001
    feature = window(
        "",
        """
      <TextBox Text="mine" Height="30">
        <TextBox.Template>
          <ControlTemplate TargetType="TextBox">
            <Border Background="Yellow" BorderBrush="Blue" BorderThickness="2">
              <ScrollViewer x:Name="PART_ContentHost" Margin="3" />
            </Border>
          </ControlTemplate>
        </TextBox.Template>
      </TextBox>""",
    )
    twin = window(
        "",
        """
      <ContentControl Height="30" Foreground="#FF000000">
        <Border Background="Yellow" BorderBrush="Blue" BorderThickness="2">
          <ContentPresenter Margin="3"><TextBlock Text="mine" Margin="2,0,2,0" /></ContentPresenter>
        </Border>
      </ContentControl>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[0, 40]) == (0, 0, 255, 255) and tuple(px[4, 40]) == (255, 255, 0, 255)
    assert not [d for d in load(feature, text=True).diagnostics if d.code == "TPL001"]
    # a PasswordBox, a TextBox and a Label inside a VisualBrush's visual: drawn from the theme
    visual = """<StackPanel Width="64" Background="White">
      <PasswordBox Password="ab" /><TextBox Text="x" /><Label Content="L" /></StackPanel>"""
    twin = """<StackPanel Width="64" Background="White">
      <ContentControl Foreground="#FF000000">
        <Border Background="#FFFFFFFF" BorderBrush="#FFABADB3" BorderThickness="1">
          <ContentPresenter><TextBlock Text="\u25cf\u25cf" Margin="2,0,2,0" /></ContentPresenter>
        </Border>
      </ContentControl>
      <ContentControl Foreground="#FF000000">
        <Border Background="#FFFFFFFF" BorderBrush="#FFABADB3" BorderThickness="1">
          <ContentPresenter><TextBlock Text="x" Margin="2,0,2,0" /></ContentPresenter>
        </Border>
      </ContentControl>
      <ContentControl Foreground="#FF000000">
        <Border Background="Transparent" Padding="5">
          <ContentPresenter HorizontalAlignment="Left" VerticalAlignment="Top">
            <TextBlock Text="L" />
          </ContentPresenter>
        </Border>
      </ContentControl></StackPanel>"""
    doc = in_brush("", visual)
    px = _same(tmp_path, doc, in_brush("", twin), _viewport_pixels)
    assert px[2:14, 3:20, :3].min() < 60  # the password's marks
    assert not [d for d in load(doc, text=True).diagnostics if d.code in ("DRW002", "LAY003")]


def test_theme_separator_and_grid_splitter_are_their_templates(tmp_path):
    # Aero2: a Separator is a 1 px Border (SystemColors.ControlDark) inside the Style's
    # Margin 0,2,0,2, centred in a taller Separator; a GridSplitter a Border of its Background
    # (SystemColors.Control), BorderBrush and BorderThickness, on the right by default
    feature = window(
        "",
        """
      <Separator />
      <Separator Background="Red" Height="9" />
      <Grid Height="50">
        <GridSplitter Width="6" />
        <GridSplitter Width="8" HorizontalAlignment="Center" Background="Yellow"
                      BorderBrush="Blue" BorderThickness="1,2,1,2" />
      </Grid>""",
    )
    twin = window(
        "",
        """
      <ContentControl Margin="0,2,0,2"><Border Background="#FFA0A0A0" Height="1" /></ContentControl>
      <ContentControl Margin="0,2,0,2" Height="9"><Border Background="Red" Height="1" />
      </ContentControl>
      <Grid Height="50">
        <ContentControl Width="6" HorizontalAlignment="Right">
          <Border Background="#FFF0F0F0" />
        </ContentControl>
        <ContentControl Width="8" HorizontalAlignment="Center">
          <Border Background="Yellow" BorderBrush="Blue" BorderThickness="1,2,1,2" />
        </ContentControl>
      </Grid>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[2, 40][:3]) == (160, 160, 160) and tuple(px[1, 40][:3]) == (255, 255, 255)
    assert tuple(px[11, 40][:3]) == (255, 0, 0)  # 5 + 2 + 4: the 1 px Border centred in 9
    assert tuple(px[40, 77][:3]) == (240, 240, 240) and tuple(px[40, 73][:3]) == (255, 255, 255)
    assert tuple(px[40, 40][:3]) == (255, 255, 0) and tuple(px[40, 36][:3]) == (0, 0, 255)
    assert not [d for d in load(feature, text=True).diagnostics if d.code in ("DRW002", "LAY003")]


def test_grid_splitter_template_of_the_users_is_instantiated(tmp_path):
    # a GridSplitter restyled as a thin centred grip: its template is drawn, not the theme's
    feature = window(
        "",
        """
      <Grid Height="40">
        <GridSplitter Width="10" HorizontalAlignment="Center" Background="Orange">
          <GridSplitter.Template>
            <ControlTemplate TargetType="{x:Type GridSplitter}">
              <Grid Background="{TemplateBinding Background}">
                <Border Width="2" Background="Blue" />
              </Grid>
            </ControlTemplate>
          </GridSplitter.Template>
        </GridSplitter>
      </Grid>""",
    )
    twin = window(
        "",
        """
      <Grid Height="40">
        <ContentControl Width="10" HorizontalAlignment="Center">
          <Grid Background="Orange"><Border Width="2" Background="Blue" /></Grid>
        </ContentControl>
      </Grid>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[20, 36][:3]) == (255, 165, 0) and tuple(px[20, 40][:3]) == (0, 0, 255)
    assert not [d for d in load(feature, text=True).diagnostics if d.code == "TPL001"]


def test_theme_progress_bar_indicator_is_its_share_of_the_track(tmp_path):
    # Aero2: a Grid of the Border, PART_Track and PART_Indicator (HorizontalAlignment Left),
    # the indicator as wide as Value's share of the track (WPF sets that Width in code);
    # Orientation Vertical turns the Grid by -90 (a LayoutTransform); IsIndeterminate shows
    # the still frame: no indicator
    feature = window(
        "",
        """
      <ProgressBar Value="25" Height="10" />
      <ProgressBar Value="3" Minimum="2" Maximum="6" Height="10" Foreground="Blue" />
      <ProgressBar IsIndeterminate="True" Value="50" Height="10" />
      <ProgressBar Orientation="Vertical" Value="75" Width="10" Height="40"
                   HorizontalAlignment="Left" />""",
    )

    def twin_bar(width, fill, turned=""):
        turn = "<Grid.LayoutTransform><RotateTransform Angle='-90' /></Grid.LayoutTransform>"
        indicator = (f'<Grid Width="{width}" HorizontalAlignment="Left"><Rectangle Fill="{fill}" />'
                     f'<Rectangle Fill="{fill}" /></Grid>' if width else "")  # fmt: skip
        return f"""<Grid>{turn if turned else ""}
          <Border Background="#FFE6E6E6" BorderBrush="#FFBCBCBC" BorderThickness="1" />
          <Rectangle />{indicator}</Grid>"""

    twin = window(
        "",
        f"""
      <ContentControl Height="10">{twin_bar(20, "#FF06B025")}</ContentControl>
      <ContentControl Height="10">{twin_bar(20, "Blue")}</ContentControl>
      <ContentControl Height="10">{twin_bar(0, "")}</ContentControl>
      <ContentControl Width="10" Height="40" HorizontalAlignment="Left">
        {twin_bar(30, "#FF06B025", turned=True)}</ContentControl>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[5, 0][:3]) == (6, 176, 37) and tuple(px[5, 19][:3]) == (6, 176, 37)
    assert tuple(px[5, 20][:3]) == (230, 230, 230) and tuple(px[0, 40][:3]) == (188, 188, 188)
    assert tuple(px[15, 10][:3]) == (0, 0, 255)  # (3 - 2) / (6 - 2) of 80 px
    assert tuple(px[25, 10][:3]) == (230, 230, 230)  # indeterminate: the still frame
    assert tuple(px[35, 5][:3]) == (230, 230, 230) and tuple(px[45, 5][:3]) == (6, 176, 37)
    assert not [d for d in load(feature, text=True).diagnostics if d.code in ("DRW002", "LAY003")]


def test_users_progress_bar_template_gets_its_indicator_width(tmp_path):
    feature = window(
        "",
        """
      <ProgressBar Value="50" Height="10">
        <ProgressBar.Template>
          <ControlTemplate TargetType="{x:Type ProgressBar}">
            <Grid Background="Yellow">
              <Rectangle x:Name="PART_Track" />
              <Border x:Name="PART_Indicator" HorizontalAlignment="Left" Background="Red" />
            </Grid>
          </ControlTemplate>
        </ProgressBar.Template>
      </ProgressBar>""",
    )
    twin = window(
        "",
        """
      <ContentControl Height="10">
        <Grid Background="Yellow">
          <Rectangle /><Border Width="40" HorizontalAlignment="Left" Background="Red" />
        </Grid>
      </ContentControl>""",
    )
    px = _same(tmp_path, feature, twin)
    assert tuple(px[5, 39][:3]) == (255, 0, 0) and tuple(px[5, 40][:3]) == (255, 255, 0)
