"""Expander drawn by the theme's template (xaml3d/data/themes/aero2.xaml): the control beside a
hand-written twin of the tree WPF builds from Aero2's template (ExpandDirection Down: a Border
around a DockPanel of the header ToggleButton, ExpanderDownHeaderStyle's 19 px circle, the
arrow Path and the header's presenter, and the ContentPresenter "ExpandSite", Collapsed until
IsExpanded), the same pixels in the window and inside a VisualBrush."""

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
DOWN, UP = "M 1,1.5 L 4.5,5 L 8,1.5", "M 1,4.5 L 4.5,1 L 8,4.5"


def _expander(expanded: bool) -> str:
    return f"""
    <Expander Header="_More" IsExpanded="{expanded}" Padding="2">
      <TextBlock Text="details" />
    </Expander>"""


def _twin(expanded: bool) -> str:
    """What WPF builds from the Expander above with Aero2's template."""
    site = "Visible" if expanded else "Collapsed"
    return f"""
    <ContentControl>
      <Border BorderBrush="Transparent" BorderThickness="1" Background="Transparent"
              CornerRadius="3" SnapsToDevicePixels="True">
        <DockPanel>
          <ContentControl DockPanel.Dock="Top" Margin="1" Foreground="#FF000000">
            <Border Padding="2">
              <Grid Background="Transparent" SnapsToDevicePixels="False">
                <Grid.ColumnDefinitions>
                  <ColumnDefinition Width="19" /><ColumnDefinition Width="*" />
                </Grid.ColumnDefinitions>
                <Ellipse Width="19" Height="19" HorizontalAlignment="Center"
                         VerticalAlignment="Center" Fill="#FFFFFFFF" Stroke="#FF333333" />
                <Path Data="{UP if expanded else DOWN}" HorizontalAlignment="Center"
                      VerticalAlignment="Center" SnapsToDevicePixels="False"
                      Stroke="#FF333333" StrokeThickness="2" />
                <ContentPresenter Grid.Column="1" Margin="4,0,0,0" HorizontalAlignment="Left"
                                  VerticalAlignment="Center" SnapsToDevicePixels="True">
                  <TextBlock Text="More" />
                </ContentPresenter>
              </Grid>
            </Border>
          </ContentControl>
          <ContentPresenter DockPanel.Dock="Bottom" Visibility="{site}" Margin="2">
            <TextBlock Text="details" />
          </ContentPresenter>
        </DockPanel>
      </Border>
    </ContentControl>"""


def _window(inner: str) -> str:
    return f"""<Window {NS} Width="216" Height="140" Background="White">
  <Grid>
    <Grid.ColumnDefinitions>
      <ColumnDefinition Width="100" /><ColumnDefinition />
    </Grid.ColumnDefinitions>
    <StackPanel>{inner}</StackPanel>
    <Viewport3D Grid.Column="1" />
  </Grid>
</Window>"""


def _in_brush(inner: str) -> str:
    return f"""<Viewport3D {NS} Width="100" Height="60">
  <Viewport3D.Camera>
    <OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" Width="100" />
  </Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="White" />
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-50,-30,0 50,-30,0 50,30,0 -50,30,0"
                        TextureCoordinates="0,1 1,1 1,0 0,0" TriangleIndices="0 1 2  0 2 3" />
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material>
        <DiffuseMaterial><DiffuseMaterial.Brush>
          <VisualBrush><VisualBrush.Visual>
            <StackPanel Width="100" Height="60" Background="White">{inner}</StackPanel>
          </VisualBrush.Visual></VisualBrush>
        </DiffuseMaterial.Brush></DiffuseMaterial>
      </GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>"""


def _window_pixels(path: Path) -> np.ndarray:
    rgba, _ = compose_window(load(path))
    return np.asarray(rgba)


def _viewport_pixels(path: Path) -> np.ndarray:
    return np.asarray(xaml3d.render(str(path)).convert("RGBA"))


@pytest.mark.parametrize("expanded", [True, False])
@pytest.mark.parametrize("where", ["window", "brush"])
def test_expander_is_the_theme_templates_tree(tmp_path, where, expanded):
    wrap, pixels = (_window, _window_pixels) if where == "window" else (_in_brush, _viewport_pixels)
    a, b = tmp_path / "feature.xaml", tmp_path / "twin.xaml"
    a.write_text(wrap(_expander(expanded)), encoding="utf-8")
    b.write_text(wrap(_twin(expanded)), encoding="utf-8")
    pa, pb = pixels(a), pixels(b)
    assert pa.shape == pb.shape
    assert np.array_equal(pa, pb), f"{int((pa != pb).any(axis=-1).sum())} pixels differ"
    # the content shows when expanded alone: dark text below the 19 px circle's row
    below = pa[25:45, 5:60, :3]
    assert (below < 128).any() == expanded
