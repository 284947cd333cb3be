"""Animations of the 2D elements around a viewport, as ``animate --window`` and ``validate``
report them in a real process: a Border's Background colour follows its ColorAnimation in every
frame (a track of the laid-out box), and what the window picture does not follow (a Rectangle's
Opacity, a shape's brush) is warning ANIM014, worded as what the picture shows.

Scene: a 200x150 Window, a horizontal StackPanel holding a 120x100 Border (White background
brush ``bg``, a blue triangle in its Viewport3D) and a green 50x50 Rectangle ``rect``; the
Window's Loaded trigger turns ``bg`` from White to Red and ``rect``'s Opacity from 1 to 0 in 1 s.
Frames 0, 10 and 20 of the GIF were checked by eye (white, pink, deeper pink Border).
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
from PIL import Image, ImageSequence

SCENE = """<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
        xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="200" Height="150">
  <Window.Triggers>
    <EventTrigger RoutedEvent="Window.Loaded">
      <BeginStoryboard>
        <Storyboard>
          <ColorAnimation Storyboard.TargetName="bg" Storyboard.TargetProperty="Color"
                          From="White" To="Red" Duration="0:0:1"/>
          <DoubleAnimation Storyboard.TargetName="rect" Storyboard.TargetProperty="Opacity"
                          From="1" To="0" Duration="0:0:1"/>
        </Storyboard>
      </BeginStoryboard>
    </EventTrigger>
  </Window.Triggers>
  <StackPanel Orientation="Horizontal">
  <Border Width="120" Height="100">
    <Border.Background><SolidColorBrush x:Name="bg" Color="White"/></Border.Background>
    <Viewport3D>
      <Viewport3D.Camera><PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1"/>
      </Viewport3D.Camera>
      <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
        <AmbientLight Color="White"/>
        <GeometryModel3D><GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="-1,-1,0 1,-1,0 0,1,0" TriangleIndices="0 1 2"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial Brush="Blue"/></GeometryModel3D.Material>
        </GeometryModel3D>
      </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
    </Viewport3D>
  </Border>
  RECT
  </StackPanel>
</Window>
"""
RECT = '<Rectangle x:Name="rect" Width="50" Height="50" Fill="Green"/>'
OPACITY = (
    "s.xaml:9:11: warning ANIM014 DoubleAnimation -> rect.Opacity: the picture shows "
    "Rectangle.Opacity at its value at load, not animated: it is not a track of the scene, "
    "so xaml3d draws it once, at load"
)


def xaml3d(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "xaml3d", *map(str, args)], capture_output=True,
                          text=True, cwd=cwd, timeout=300)  # fmt: skip


def _write(tmp_path, rect: str = RECT) -> str:
    (tmp_path / "s.xaml").write_text(SCENE.replace("RECT", rect))
    return "s.xaml"


def _warnings(text: str) -> list[str]:
    return [ln for ln in text.splitlines() if " warning " in ln]


def test_a_borders_background_colour_follows_its_animation_in_the_window(tmp_path):
    p = xaml3d("animate", "--window", _write(tmp_path), "-o", "x.gif", "--fps", "10",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    # the Border's colour is a track: only the Rectangle's Opacity is reported
    assert _warnings(p.stderr) == [OPACITY]
    frames = [np.asarray(f.convert("RGB")) for f in ImageSequence.Iterator(Image.open(
        tmp_path / "x.gif"))]  # fmt: skip
    assert len(frames) == 10
    # a Border pixel clear of the triangle: White, then redder in every frame
    # (WPF's Color arithmetic is in scRGB: half-way is linear 0.5, sRGB 188)
    greens = [255, 243, 231, 218, 203, 188, 170, 149, 124, 89]
    assert [tuple(int(c) for c in f[20, 3]) for f in frames] == [(255, g, g) for g in greens]
    # the Rectangle keeps its load Opacity: green in every frame
    assert all(tuple(int(c) for c in f[55, 145]) == (0, 128, 0) for f in frames)


def test_validate_reports_the_opacity_the_window_draws_at_load(tmp_path):
    p = xaml3d("validate", _write(tmp_path), cwd=tmp_path)
    assert p.returncode == 0, p.stdout
    assert _warnings(p.stdout) == [OPACITY]


def test_an_animated_brush_of_a_shape_is_reported(tmp_path):
    rect = ('<Rectangle Width="50" Height="50"><Rectangle.Fill><SolidColorBrush x:Name="rect" '
            'Color="Green"/></Rectangle.Fill></Rectangle>')  # fmt: skip
    p = xaml3d("validate", _write(tmp_path, rect), cwd=tmp_path)
    assert p.returncode == 0, p.stdout
    assert _warnings(p.stdout) == [
        "s.xaml:9:11: warning ANIM014 DoubleAnimation -> rect.Opacity: the picture shows "
        "SolidColorBrush.Opacity at its value at load, not animated: it is not a track of the "
        "scene, so xaml3d draws it once, at load"
    ]


def test_an_animated_canvas_offset_is_a_double_the_layout_reads_once(tmp_path):
    """``(Canvas.Left)`` is Canvas's attached Double on any element: a DoubleAnimation of it is
    valid (not ANIM003) and the picture shows its value at load (ANIM014, the layout's reason);
    a ColorAnimation of it is ANIM003, naming the attached property's kind."""

    def validate(animation: str) -> str:
        (tmp_path / "a.xaml").write_text(
            '<Canvas xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
            'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="200" Height="100">\n'
            '<Canvas.Triggers><EventTrigger RoutedEvent="Canvas.Loaded"><BeginStoryboard>\n'
            f"<Storyboard>{animation}</Storyboard>\n"
            "</BeginStoryboard></EventTrigger></Canvas.Triggers>\n"
            '<Rectangle x:Name="rect" Width="20" Height="20" Fill="Red"/>\n'
            '<Viewport3D Canvas.Left="120" Width="40" Height="40"/></Canvas>'
        )
        p = subprocess.run([sys.executable, "-m", "xaml3d", "validate", "a.xaml"],
                           cwd=tmp_path, capture_output=True, text=True)  # fmt: skip
        return p.stdout + p.stderr

    left = 'Storyboard.TargetName="rect" Storyboard.TargetProperty="(Canvas.Left)"'
    out = validate(f'<DoubleAnimation {left} To="100" Duration="0:0:1"/>')
    assert "ANIM003" not in out
    assert (
        "a.xaml:3:13: warning ANIM014 DoubleAnimation -> rect.(Canvas.Left): the picture shows "
        "Rectangle's Canvas.Left at its value at load, not animated: xaml3d lays the window out "
        "once, at load"
    ) in out
    out = validate(f'<ColorAnimation {left} To="Red" Duration="0:0:1"/>')
    said = "ANIM003 ColorAnimation -> rect.(Canvas.Left): Color animation on Canvas.Left, a double"
    assert said in out
