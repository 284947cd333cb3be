"""GroupBox drawn by the theme's template (xaml3d/data/themes/aero2.xaml): the control beside
a hand-written twin of the tree WPF builds from Aero2's template (the Grid of columns 6,Auto,*,6
and rows Auto,Auto,*,6, the Background's Border, the frame's three nested Borders, the header's
Border at Padding 3,1,3,0 and the content's presenter at the Padding), the same pixels in the
window and inside a VisualBrush; the frame's line cut under the header as
BorderGapMaskConverter's mask does (the twin writes that cut as the frame's Clip)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import xaml3d
from xaml3d.pipeline import load
from xaml3d.render.window import compose_window

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
VIEWPORT = """
      <Viewport3D>
        <Viewport3D.Camera>
          <OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" Width="80" />
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
GROUP_BOX = f"""
    <GroupBox Header="View" Padding="4" Background="#FFFFF0E0">{VIEWPORT}
    </GroupBox>"""


def _twin(header_w: float, frame_w: float, frame_h: float) -> str:
    """What WPF builds from the GroupBox above with Aero2's template; the frame's mask (from
    7 px, the header's width wide, over its top half) written as a Clip."""
    cut = f"""
          <Border.Clip>
            <CombinedGeometry GeometryCombineMode="Exclude">
              <CombinedGeometry.Geometry1>
                <RectangleGeometry Rect="0,0,{frame_w!r},{frame_h!r}" />
              </CombinedGeometry.Geometry1>
              <CombinedGeometry.Geometry2>
                <RectangleGeometry Rect="7,0,{header_w!r},{frame_h / 2!r}" />
              </CombinedGeometry.Geometry2>
            </CombinedGeometry>
          </Border.Clip>"""
    return f"""
    <ContentControl>
      <Grid SnapsToDevicePixels="True">
        <Grid.ColumnDefinitions>
          <ColumnDefinition Width="6" /><ColumnDefinition Width="Auto" />
          <ColumnDefinition Width="*" /><ColumnDefinition Width="6" />
        </Grid.ColumnDefinitions>
        <Grid.RowDefinitions>
          <RowDefinition Height="Auto" /><RowDefinition Height="Auto" />
          <RowDefinition Height="*" /><RowDefinition Height="6" />
        </Grid.RowDefinitions>
        <Border Grid.Row="1" Grid.RowSpan="3" Grid.ColumnSpan="4" CornerRadius="4"
                BorderBrush="Transparent" BorderThickness="1" Background="#FFFFF0E0" />
        <Border Grid.Row="1" Grid.RowSpan="3" Grid.ColumnSpan="4" CornerRadius="4"
                BorderBrush="White" BorderThickness="1">{cut}
          <Border BorderBrush="#FFD5DFE5" BorderThickness="1" CornerRadius="3">
            <Border BorderBrush="White" BorderThickness="1" CornerRadius="2" />
          </Border>
        </Border>
        <Border Grid.Column="1" Grid.Row="0" Grid.RowSpan="2" Padding="3,1,3,0">
          <ContentPresenter><TextBlock Text="View" /></ContentPresenter>
        </Border>
        <ContentPresenter Grid.Row="2" Grid.Column="1" Grid.ColumnSpan="2" Margin="4">
          {VIEWPORT}
        </ContentPresenter>
      </Grid>
    </ContentControl>"""


def _window(inner: str) -> str:
    return f"""<Window {NS} Width="216" Height="140" Background="White">
  <Grid Margin="4">{inner}
  </Grid>
</Window>"""


def _in_brush(inner: str) -> str:
    return f"""<Viewport3D {NS} Width="200" Height="120">
  <Viewport3D.Camera>
    <OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" Width="200" />
  </Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="White" />
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-100,-60,0 100,-60,0 100,60,0 -100,60,0"
                        TextureCoordinates="0,1 1,1 1,0 0,0" TriangleIndices="0 1 2  0 2 3" />
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material>
        <DiffuseMaterial><DiffuseMaterial.Brush>
          <VisualBrush><VisualBrush.Visual>
            <Grid Width="200" Height="120" Background="White">{inner}</Grid>
          </VisualBrush.Visual></VisualBrush>
        </DiffuseMaterial.Brush></DiffuseMaterial>
      </GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>"""


def _sizes(text: str) -> tuple[float, float, float]:
    """The header Border's width and the frame's size, as the feature's layout gives them."""
    s = load(text, text=True)
    borders = [b for b in s.layout.boxes if b.type == "Border"]
    frame, header = borders[1], borders[-1]
    return header.rect[2], frame.rect[2], frame.rect[3]


def _window_pixels(path: Path) -> np.ndarray:
    rgba, _ = compose_window(load(path))
    return np.asarray(rgba)


def _viewport_pixels(path: Path) -> np.ndarray:
    return np.asarray(xaml3d.render(str(path)).convert("RGBA"))


@pytest.mark.parametrize("where", ["window", "brush"])
def test_group_box_is_the_theme_templates_tree(tmp_path, where):
    header_w, frame_w, frame_h = _sizes(_window(GROUP_BOX))
    assert header_w == pytest.approx(32.244140625)  # 'View' at 12 px and the 3+3 padding
    wrap, pixels = (_window, _window_pixels) if where == "window" else (_in_brush, _viewport_pixels)
    if where == "brush":  # the visual's Grid is 200 x 120: the frame below the header's half
        frame_w, frame_h = 200.0, 120 - 16.9609375 / 2
    a, b = tmp_path / "feature.xaml", tmp_path / "twin.xaml"
    a.write_text(wrap(GROUP_BOX), encoding="utf-8")
    b.write_text(wrap(_twin(header_w, frame_w, frame_h)), encoding="utf-8")
    pa, pb = pixels(a), pixels(b)
    assert pa.shape == pb.shape
    assert np.array_equal(pa, pb), f"{int((pa != pb).any(axis=-1).sum())} pixels differ"


def test_the_frames_line_is_cut_under_the_header_alone(tmp_path):
    p = tmp_path / "g.xaml"
    p.write_text(
        f"""<Window {NS} Width="216" Height="140" Background="White" UseLayoutRounding="True">
  <GroupBox Header="View"><Viewport3D /></GroupBox>
</Window>""",
        encoding="utf-8",
    )
    px = _window_pixels(p)
    line = px[10, :, :3]  # the frame's top line: the header row is 17 px, its half rounded
    frame = (213, 223, 229)  # #FFD5DFE5
    assert tuple(line[100]) == frame and tuple(line[5]) == frame
    # from 7 px, the header's 32 px: no line beside the text (cols 9..35)
    assert (line[7:9] == 255).all() and (line[36:39] == 255).all()
    assert tuple(line[40]) == frame


USER_TEMPLATE = """<Window {ns} Width="216" Height="140" Background="White">
  <Window.Resources><BorderGapMaskConverter x:Key="gap" /></Window.Resources>
  <GroupBox Header="Hi">
    <GroupBox.Template>
      <ControlTemplate TargetType="GroupBox">
        <Grid>
          <Grid.RowDefinitions>
            <RowDefinition Height="Auto" /><RowDefinition />
          </Grid.RowDefinitions>
          <Border Grid.RowSpan="2" BorderBrush="Red" BorderThickness="2">
            <Border.OpacityMask>
              <MultiBinding Converter="{{StaticResource gap}}" ConverterParameter="20">
                <Binding ElementName="H" Path="ActualWidth" />
                <Binding Path="ActualWidth" RelativeSource="{{RelativeSource Self}}" />
                <Binding Path="ActualHeight" RelativeSource="{{RelativeSource Self}}" />
              </MultiBinding>
            </Border.OpacityMask>
          </Border>
          <Border x:Name="H" Width="30" Height="10" HorizontalAlignment="Left" />
          <ContentPresenter Grid.Row="1" />
        </Grid>
      </ControlTemplate>
    </GroupBox.Template>
    <Viewport3D />
  </GroupBox>
</Window>"""


def test_a_users_template_masked_by_border_gap_mask_converter(tmp_path):
    p = tmp_path / "u.xaml"
    p.write_text(USER_TEMPLATE.format(ns=NS), encoding="utf-8")
    s = load(p)
    assert not {d.code for d in s.diagnostics} & {"XAML009", "XAML011", "TPL002"}
    px = _window_pixels(p)[:, :, :3]
    red = (255, 0, 0)
    top = px[0]  # the frame's 2 px top line, cut from 20 px for the 30 px header's width
    assert tuple(top[10]) == red and tuple(top[19]) == red
    assert (top[20:50] == 255).all()
    assert tuple(top[50]) == red and tuple(top[150]) == red
    assert tuple(px[60, 0]) == red  # the left line below the top half: not cut
