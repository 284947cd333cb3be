"""Brushes (gradients, images, placeholders, 2D transforms) and storyboards read from markup."""

from __future__ import annotations

import numpy as np
from PIL import Image

from xaml3d.pipeline import load
from xaml3d.scene.drawing import DrawingBrush, GeometryDrawing
from xaml3d.scene.types import (
    ImageBrush,
    LinearGradientBrush,
    placeholder_image,
)

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
MESH = "<MeshGeometry3D Positions='0,0,0 1,0,0 0,1,0'/>"


def with_brush(brush: str, *, path=None, extra: str = ""):
    xml = (f"<Viewport3D {NS}><ModelVisual3D><ModelVisual3D.Content><GeometryModel3D x:Name='m'>"
           f"<GeometryModel3D.Geometry>{MESH}</GeometryModel3D.Geometry><GeometryModel3D.Material>"
           f"<DiffuseMaterial><DiffuseMaterial.Brush>{brush}</DiffuseMaterial.Brush>"
           "</DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>"
           f"</ModelVisual3D.Content></ModelVisual3D>{extra}</Viewport3D>")  # fmt: skip
    if path is not None:
        path.write_text(xml)
        return load(path)
    return load(xml, text=True)


def brush_of(s):
    return s.viewports[0].models[0].material[0].brush


def codes(s):
    return [d.code for d in s.diagnostics]


def test_linear_gradient_with_rotated_transform():
    b = brush_of(with_brush(
        "<LinearGradientBrush StartPoint='0,0.5' EndPoint='1,0.5' SpreadMethod='Reflect'>"
        "<LinearGradientBrush.Transform><RotateTransform Angle='90' CenterX='0.5' CenterY='0.5'/>"
        "</LinearGradientBrush.Transform><GradientStop Color='Red' Offset='0'/>"
        "<GradientStop Color='#800000FF' Offset='1'/></LinearGradientBrush>"
    ))  # fmt: skip
    assert isinstance(b, LinearGradientBrush)
    assert b.start_point == (0.0, 0.5) and b.end_point == (1.0, 0.5)
    assert b.spread_method == "Reflect"
    assert [s.offset for s in b.stops] == [0.0, 1.0]
    assert b.stops[1].color == (0.0, 0.0, 1.0, 128 / 255)
    # 90 degrees about (0.5, 0.5), y down: (1, 0.5) -> (0.5, 1)
    assert np.allclose(b.transform @ (1.0, 0.5, 1.0), (0.5, 1.0, 1.0))


def test_transform_group_and_skew():
    b = brush_of(with_brush(
        "<LinearGradientBrush><LinearGradientBrush.RelativeTransform><TransformGroup>"
        "<ScaleTransform ScaleX='2'/><TranslateTransform X='1' Y='3'/></TransformGroup>"
        "</LinearGradientBrush.RelativeTransform></LinearGradientBrush>"
    ))  # fmt: skip
    # scale first: (1,1) -> (2,1), then translate -> (3,4)
    assert np.allclose(b.relative_transform @ (1.0, 1.0, 1.0), (3.0, 4.0, 1.0))


def test_brush_transforms_written_as_text():
    # WPF's 2D Transform has a TypeConverter: "Identity" or a Matrix's six numbers (only 3D
    # transforms need an element)
    s = with_brush("<LinearGradientBrush Transform='Identity' RelativeTransform='2 0 0 1 1 3'/>")
    b = brush_of(s)
    assert [d for d in s.diagnostics if d.severity == "error"] == []
    assert np.array_equal(b.transform, np.eye(3))
    # M11=2 M12=0 M21=0 M22=1 OffsetX=1 OffsetY=3: (1, 1) -> (3, 4)
    assert np.allclose(b.relative_transform @ (1.0, 1.0, 1.0), (3.0, 4.0, 1.0))
    s = with_brush("<SolidColorBrush Color='Red' Transform='1,0,0,1,5,5'/>")
    assert "XAML013" not in codes(s)
    s = with_brush("<SolidColorBrush Color='Red' Transform='1,0,0'/>")
    assert "VAL003" in codes(s)


def test_drawing_brush_is_read_as_a_drawing():
    s = with_brush("<DrawingBrush><DrawingBrush.Drawing><GeometryDrawing Brush='Red'/>"
                   "</DrawingBrush.Drawing></DrawingBrush>")  # fmt: skip
    b = brush_of(s)
    assert isinstance(b, DrawingBrush) and "BRU001" not in codes(s)
    assert b.kind == "DrawingBrush" and isinstance(b.drawing, GeometryDrawing)
    assert b.drawing.geometry is None and b.drawing.brush.color == (1.0, 0.0, 0.0, 1.0)


def test_image_brush_loads_relative_and_pack_uri(tmp_path):
    (tmp_path / "img").mkdir()
    Image.new("RGBA", (2, 1), (255, 0, 0, 128)).save(tmp_path / "img" / "pic.png")
    s = with_brush("<ImageBrush ImageSource='img\\pic.png' TileMode='Tile' "
                   "ViewportUnits='Absolute' Viewport='0,0,0.5,0.5'/>",
                   path=tmp_path / "a.xaml")  # fmt: skip
    b = brush_of(s)
    assert isinstance(b, ImageBrush) and b.image.shape == (1, 2, 4)
    assert tuple(b.image[0, 0]) == (255, 0, 0, 128) and not b.image.flags.writeable
    assert b.tile_mode == "Tile" and b.viewport == (0.0, 0.0, 0.5, 0.5)
    s = with_brush("<ImageBrush ImageSource='pack://application:,,,/App;component/img/pic.png'/>",
                   path=tmp_path / "b.xaml")  # fmt: skip
    assert brush_of(s).image is not None


def _placeholder(brush) -> bool:
    # A missing picture is replaced by the grey checker, flagged as a placeholder.
    return brush.is_placeholder and np.array_equal(brush.image, placeholder_image())


def test_image_missing_network_and_outside(tmp_path):
    (tmp_path / "s").mkdir()
    Image.new("RGB", (1, 1)).save(tmp_path / "out.png")
    s = with_brush("<ImageBrush ImageSource='nope.png'/>", path=tmp_path / "s" / "a.xaml")
    assert _placeholder(brush_of(s)) and "BRU002" in codes(s)
    s = with_brush(
        "<ImageBrush ImageSource='http://example.com/x.png'/>", path=tmp_path / "s" / "b.xaml"
    )
    assert _placeholder(brush_of(s)) and "BRU004" in codes(s)
    s = with_brush("<ImageBrush ImageSource='../out.png'/>", path=tmp_path / "s" / "c.xaml")
    assert _placeholder(brush_of(s)) and "BRU005" in codes(s)
    (tmp_path / "s" / "bad.png").write_bytes(b"not a png")
    s = with_brush("<ImageBrush ImageSource='bad.png'/>", path=tmp_path / "s" / "d.xaml")
    assert _placeholder(brush_of(s)) and "BRU003" in codes(s)


TRIGGERS = """
<Viewport3D.Triggers>
  <EventTrigger RoutedEvent="Viewport3D.Loaded">
    <BeginStoryboard>
      <Storyboard x:Name="sb">
        <ParallelTimeline Storyboard.TargetName="rot" Storyboard.TargetProperty="Angle"
                          RepeatBehavior="Forever" BeginTime="0:0:1">
          <DoubleAnimation From="0" To="360" Duration="0:0:10" AutoReverse="True"/>
        </ParallelTimeline>
        <Point3DAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="Position"
                          By="1,2,3" BeginTime="{x:Null}"/>
        <Rotation3DAnimationUsingKeyFrames Storyboard.TargetName="rt"
                                           Storyboard.TargetProperty="Rotation">
          <SplineRotation3DKeyFrame KeyTime="0:0:2" KeySpline="0.6,0 0.9,0">
            <SplineRotation3DKeyFrame.Value>
              <AxisAngleRotation3D Axis="0,0,2" Angle="180"/>
            </SplineRotation3DKeyFrame.Value>
          </SplineRotation3DKeyFrame>
          <DiscreteRotation3DKeyFrame KeyTime="50%"/>
        </Rotation3DAnimationUsingKeyFrames>
      </Storyboard>
    </BeginStoryboard>
  </EventTrigger>
  <EventTrigger RoutedEvent="Button.Click"><BeginStoryboard Storyboard="{StaticResource later}"/>
    <PauseStoryboard BeginStoryboardName="x"/></EventTrigger>
</Viewport3D.Triggers>
"""


def test_storyboards_read():
    res = ("<Viewport3D.Resources><Storyboard x:Key='later'><ColorAnimation "
           "Storyboard.TargetName='b' Storyboard.TargetProperty='Color' To='Red'/></Storyboard>"
           "<Storyboard x:Key='unused'/></Viewport3D.Resources>")  # fmt: skip
    xml = f"<Viewport3D {NS}>{res}{TRIGGERS}</Viewport3D>"
    s = load(xml, text=True)
    loaded, click, unused = s.storyboards
    assert loaded.trigger == "Viewport3D.Loaded" and loaded.starts_at_load and loaded.name == "sb"
    d, p3, rot = loaded.animations
    assert (d.type, d.target_name, d.target_property) == ("DoubleAnimation", "rot", "Angle")
    assert (d.from_value, d.to_value, d.duration) == (0.0, 360.0, 10.0)
    # the group's timing stays on the group (WPF's clock tree), the animation keeps its own
    assert d.repeat_behavior == 1.0 and d.begin_time == 0.0 and d.auto_reverse
    group = loaded.root.children[0]
    assert group.type == "ParallelTimeline" and group.children == (d,)
    assert group.timing.repeat_behavior == "Forever" and group.timing.begin_time == 1.0
    assert p3.by_value == (1.0, 2.0, 3.0) and p3.begin_time is None
    assert p3.duration == "Automatic" and p3.repeat_behavior == 1.0
    k1, k2 = rot.key_frames
    # axis (0,0,2) normalized, 180 degrees: (0, 0, sin 90, cos 90) = (0, 0, 1, 0)
    assert k1.kind == "Spline" and np.allclose(k1.value, (0, 0, 1, 0), atol=1e-12)
    assert k1.key_time == "0:0:2" and k1.key_spline == (0.6, 0.0, 0.9, 0.0)
    assert k1.time == ("time", 2.0) and k2.time == ("percent", 0.5)
    assert k2.kind == "Discrete" and k2.key_time == "50%" and k2.value is None
    assert click.trigger == "Button.Click" and not click.starts_at_load
    assert click.animations[0].to_value == (1.0, 0.0, 0.0, 1.0)
    assert unused.trigger is None and unused.name == "unused"
    assert "ANI002" in codes(s)


def test_static_scene_keeps_base_values():
    triggers = TRIGGERS.replace("{StaticResource later}", "{x:Null}")
    xml = (f"<Viewport3D {NS}><Viewport3D.Camera><PerspectiveCamera x:Name='cam' "
           f"Position='0,0,9'/></Viewport3D.Camera>{triggers}</Viewport3D>")  # fmt: skip
    s = load(xml, text=True)
    assert s.viewports[0].camera.position == (0.0, 0.0, 9.0)


def test_storyboard_target_written_without_owner_prefix():
    # XAML resolves an unqualified attribute that is no member of Storyboard to its attachable
    # member: <Storyboard TargetName=..> is <Storyboard Storyboard.TargetName=..>
    xml = f"""<Viewport3D {NS}>
  <Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
    <Storyboard TargetName="rot" TargetProperty="Angle">
      <DoubleAnimation From="0" To="90" Duration="0:0:2"/>
    </Storyboard>
  </BeginStoryboard></EventTrigger></Viewport3D.Triggers>
  <ModelVisual3D><ModelVisual3D.Transform><RotateTransform3D><RotateTransform3D.Rotation>
    <AxisAngleRotation3D x:Name="rot" Axis="0,1,0"/>
  </RotateTransform3D.Rotation></RotateTransform3D></ModelVisual3D.Transform></ModelVisual3D>
</Viewport3D>"""
    s = load(xml, text=True)
    assert [d for d in s.diagnostics if d.severity == "error"] == []
    (anim,) = s.storyboards[0].animations
    assert (anim.target_name, anim.target_property) == ("rot", "Angle")
    # another type's attachable member still needs its owner: an error, as in WPF
    s = load(xml.replace('<DoubleAnimation From="0"', '<DoubleAnimation TargetName="rot" From="0"'),
             text=True)  # fmt: skip
    assert [d.code for d in s.diagnostics if d.severity == "error"] == ["XAML004"]
