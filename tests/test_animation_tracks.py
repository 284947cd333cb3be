"""Animation as typed data in the Scene: tracks made at load, frames computed from them alone.

Scenes use the standard orthographic frame (64x48, 1 world unit = 1 pixel).
"""

from __future__ import annotations

import math
import pickle
from pathlib import Path

import numpy as np
import pytest

import xaml3d
from xaml3d.scene.tracks import ScenePath, Tracks

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "corpus"
SPINNING = CORPUS / "005_wpfsamples-spinningcube.xaml"

NS = ('xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
      'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"')  # fmt: skip

QUAD = """<GeometryModel3D.Geometry><MeshGeometry3D Positions="-8,-8,0 8,-8,0 8,8,0 -8,8,0"
    TriangleIndices="0 1 2 0 2 3"/></GeometryModel3D.Geometry>"""


def scene(body: str, storyboard: str, resources: str = "", extra: str = "") -> str:
    return f"""<Viewport3D {NS} Width="64" Height="48">
  <Viewport3D.Resources>{resources}</Viewport3D.Resources>
  <Viewport3D.Camera><OrthographicCamera x:Name="cam" Position="0,0,10" LookDirection="0,0,-1"
      Width="64"/></Viewport3D.Camera>
  {body}
  <Viewport3D.Triggers>
    <EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard><Storyboard>
      {storyboard}
    </Storyboard></BeginStoryboard></EventTrigger>
    {extra}
  </Viewport3D.Triggers>
</Viewport3D>"""


# a model under a visual and a group, each with a transform; the model's own transform group
# holds a constant scale AFTER the animated rotation, so the chain keeps constant factors
NESTED = """<ModelVisual3D x:Name="visual">
  <ModelVisual3D.Transform><TranslateTransform3D OffsetY="1.25"/></ModelVisual3D.Transform>
  <ModelVisual3D.Content><Model3DGroup x:Name="group">
    <Model3DGroup.Transform><ScaleTransform3D x:Name="grow" ScaleX="{sx}" CenterX="0.5"/>
    </Model3DGroup.Transform>
    <AmbientLight x:Name="amb" Color="White"/>
    <PointLight x:Name="lamp" Position="1,2,3"/>
    <GeometryModel3D x:Name="quad">{quad}
      <GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/></GeometryModel3D.Material>
      <GeometryModel3D.Transform><Transform3DGroup>
        <TranslateTransform3D x:Name="move" OffsetX="{ox}"/>
        <RotateTransform3D CenterX="0.3"><RotateTransform3D.Rotation>
          <AxisAngleRotation3D x:Name="rot" Axis="0.2,0.1,1" Angle="{angle}"/>
        </RotateTransform3D.Rotation></RotateTransform3D>
        <ScaleTransform3D ScaleX="1.1" ScaleY="0.7"/>
      </Transform3DGroup></GeometryModel3D.Transform>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>"""


def nested(sx="1", ox="4", angle="0") -> str:
    return NESTED.format(sx=sx, ox=ox, angle=angle, quad=QUAD)


def hold(name: str, prop: str, value: str, kind: str = "Double") -> str:
    """An animation that holds ``value`` from t = 0 (a discrete key frame)."""
    return (f'<{kind}AnimationUsingKeyFrames Storyboard.TargetName="{name}" '
            f'Storyboard.TargetProperty="{prop}"><Discrete{kind}KeyFrame KeyTime="0:0:0" '
            f'Value="{value}"/></{kind}AnimationUsingKeyFrames>')  # fmt: skip


def test_frames_are_computed_without_the_reader(monkeypatch):
    anim = ('<DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX" '
            'From="-10" To="10" Duration="0:0:2"/>'
            '<Point3DAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="Position" '
            'From="0,0,10" To="0,0,30" Duration="0:0:2"/>')  # fmt: skip
    s = xaml3d.load(scene(nested(), anim), text=True)

    def refuse(*a, **k):
        raise AssertionError("the reader ran while a frame was computed")

    import lxml.etree

    import xaml3d.xaml.builder as builder
    import xaml3d.xaml.parser as parser

    monkeypatch.setattr(builder, "build_scene", refuse)
    monkeypatch.setattr(builder.Reader, "__init__", refuse)
    monkeypatch.setattr(parser, "parse_document", refuse)
    monkeypatch.setattr(lxml.etree, "XMLParser", refuse)
    monkeypatch.setattr(lxml.etree, "fromstring", refuse)
    for t, x, z in ((0.0, -10.0, 10.0), (0.5, -5.0, 15.0), (1.5, 5.0, 25.0), (9.0, 10.0, 30.0)):
        f = xaml3d.scene_at(s, t)
        # translation first in the model's group, then the rotation (angle 0), the scale
        assert f.viewports[0].models[0].world[0, 3] == x * 1.1
        assert f.viewports[0].camera.position == (0.0, 0.0, z)
    assert xaml3d.render(s, time=1.0) is not None


def test_unanimated_objects_are_the_loaded_ones():
    body = (
        nested()
        + f"""<ModelVisual3D><ModelVisual3D.Content><GeometryModel3D>{QUAD}
      <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
      </GeometryModel3D></ModelVisual3D.Content></ModelVisual3D>"""
    )
    anim = ('<DoubleAnimation Storyboard.TargetName="rot" Storyboard.TargetProperty="Angle" '
            'To="90" Duration="0:0:1"/>')  # fmt: skip
    s = xaml3d.load(scene(body, anim), text=True)
    still = s.viewports[0].models[1]
    for t in (0.25, 0.5, 0.75):
        f = xaml3d.scene_at(s, t)
        moving, other = f.viewports[0].models
        assert moving.mesh is s.viewports[0].models[0].mesh  # meshes are never rebuilt
        assert moving.material is s.viewports[0].models[0].material
        assert other is still  # nothing moves it: the very object
        assert f.viewports[0].lights is s.viewports[0].lights
        assert not np.array_equal(moving.world, s.viewports[0].models[0].world)


@pytest.mark.parametrize(
    ("prop", "value", "static"),
    [
        ("Angle", "37.5", {"angle": "37.5"}),
        ("OffsetX", "-2.75", {"ox": "-2.75"}),
        ("ScaleX", "1.7", {"sx": "1.7"}),
    ],
)
def test_animated_matrices_equal_the_loaded_ones_bit_for_bit(prop, value, static):
    name = {"Angle": "rot", "OffsetX": "move", "ScaleX": "grow"}[prop]
    s = xaml3d.load(scene(nested(), hold(name, prop, value)), text=True)
    want = xaml3d.load(scene(nested(**static), ""), text=True).viewports[0]
    got = xaml3d.scene_at(s, 0.5).viewports[0]
    for a, b in zip(got.models + got.lights, want.models + want.lights, strict=True):
        assert a.world.tobytes() == b.world.tobytes()
    chains = s.tracks.worlds
    # the model and both lights under the group; their chains start below the visual's
    # constant transform (pre-multiplied) when only the model's own transform animates
    assert len(chains) == (1 if prop != "ScaleX" else 3)


def test_rotation3d_animation_over_an_animated_angle():
    # the AxisAngleRotation3D's Angle animates, and the whole Rotation too: WPF's Rotation
    # animation takes the angle-animated rotation as its base (From omitted) and, at its end,
    # replaces it; the matrix is then the quaternion's
    anims = (
        hold("rot", "Angle", "90")
        + """<Rotation3DAnimation Storyboard.TargetName="quad"
        Storyboard.TargetProperty="Transform.Children[1].Rotation" Duration="0:0:1">
        <Rotation3DAnimation.To><QuaternionRotation3D Quaternion="0,0,0,1"/>
        </Rotation3DAnimation.To></Rotation3DAnimation>"""
    )
    body = nested().replace('Axis="0.2,0.1,1"', 'Axis="0,0,1"').replace('CenterX="0.3"', "")
    s = xaml3d.load(scene(body, anims), text=True)
    assert not [d for d in s.diagnostics if d.code.startswith("ANIM")]
    w0 = xaml3d.scene_at(s, 0.0).viewports[0].models[0].world
    w1 = xaml3d.scene_at(s, 1.0).viewports[0].models[0].world
    # t = 0: a quarter turn about z (x -> y), then the scale (1.1, 0.7)
    assert np.allclose(w0[:2, :2], [[0.0, -1.1], [0.7, 0.0]], atol=1e-12)
    assert np.allclose(w1[:2, :2], [[1.1, 0.0], [0.0, 0.7]], atol=1e-12)  # identity rotation


def test_shared_brush_has_a_path_per_model():
    res = '<SolidColorBrush x:Key="paint" x:Name="paint" Color="Red"/>'
    quad = f"""<GeometryModel3D>{QUAD}<GeometryModel3D.Material><DiffuseMaterial
        Brush="{{StaticResource paint}}"/></GeometryModel3D.Material></GeometryModel3D>"""
    glow = quad.replace("DiffuseMaterial", "EmissiveMaterial")
    body = f"""<ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
        <AmbientLight Color="White"/>{quad}{quad}{glow}
        </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>"""
    anim = ('<ColorAnimation Storyboard.TargetName="paint" Storyboard.TargetProperty="Color" '
            'To="Blue" Duration="0:0:2"/>')  # fmt: skip
    s = xaml3d.load(scene(body, anim, res), text=True)
    (track,) = s.tracks.tracks
    assert track.paths == tuple(
        ScenePath(0, (("models", i), ("material", 0), ("brush", None)), "color") for i in range(3)
    )
    assert str(track.paths[1]) == "viewport 0 / models[1] / material[0] / brush . color"
    from xaml3d.animation.interpolate import interpolate

    half = interpolate("Color", (1.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 1.0), 0.5, True)
    f = xaml3d.scene_at(s, 1.0)
    for m in f.viewports[0].models:
        assert m.material[0].brush.color == half and half[1] == 0.0 and 0 < half[0] < 1
    for m in s.viewports[0].models:
        assert m.material[0].brush.color == (1.0, 0.0, 0.0, 1.0)  # the loaded scene unchanged


def test_handoff_compose_on_tracks():
    first = ('<Point3DAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="Position" '
             'To="0,0,20" Duration="0:0:1"/>')  # fmt: skip
    second = """<EventTrigger RoutedEvent="Button.Click"><BeginStoryboard x:Name="more"
        HandoffBehavior="{h}"><Storyboard><Point3DAnimation Storyboard.TargetName="cam"
        Storyboard.TargetProperty="Position" By="0,2,0" Duration="0:0:1"/></Storyboard>
        </BeginStoryboard></EventTrigger>"""
    compose = xaml3d.load(scene(nested(), first, extra=second.format(h="Compose")), text=True)
    replace = xaml3d.load(scene(nested(), first, extra=second.format(h="SnapshotAndReplace")),
                          text=True)  # fmt: skip
    (track,) = compose.tracks.tracks
    assert len(track.animations) == 2 and track.paths == (ScenePath(0, (("camera", None),),
                                                                    "position"),)  # fmt: skip
    at = lambda s, t, sb=None: xaml3d.scene_at(s, t, sb).viewports[0].camera.position  # noqa: E731
    assert at(compose, 0.5) == (0.0, 0.0, 15.0)  # the click storyboard does not run
    assert at(compose, 0.5, "more") == (0.0, 1.0, 15.0)  # 10 -> 20 in z, then + 0..2 in y
    assert at(compose, 1.0, "more") == (0.0, 2.0, 20.0)
    assert at(replace, 1.0, "more") == (0.0, 2.0, 10.0)  # the first one's animation replaced


def test_light_camera_transform_and_gradient_stop_tracks():
    body = nested().replace(
        '<GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/>',
        """<GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush>
        <LinearGradientBrush><GradientStop Color="Red" Offset="0"/>
        <GradientStop x:Name="stop" Color="Red" Offset="1"/></LinearGradientBrush>
        </DiffuseMaterial.Brush></DiffuseMaterial>""",
    )
    cam = """<Viewport3D.Camera><OrthographicCamera Position="0,0,10" LookDirection="0,0,-1"
        Width="64"><OrthographicCamera.Transform><TranslateTransform3D x:Name="dolly"/>
        </OrthographicCamera.Transform></OrthographicCamera></Viewport3D.Camera>"""
    anims = (hold("lamp", "Position", "4,5,6", "Point3D") + hold("grow", "ScaleX", "2")
             + hold("dolly", "OffsetY", "3") + hold("stop", "Color", "#0000FF", "Color")
             + hold("amb", "Color", "#808080", "Color"))  # fmt: skip
    start = '<Viewport3D.Camera><OrthographicCamera x:Name="cam"'
    text = scene(body, anims)
    i, j = text.index(start), text.index("</Viewport3D.Camera>") + len("</Viewport3D.Camera>")
    text = text[:i] + cam + text[j:]
    s = xaml3d.load(text, text=True)
    assert not [d for d in s.diagnostics if d.code.startswith("ANIM")]
    vp = xaml3d.scene_at(s, 0.1).viewports[0]
    amb, lamp = vp.lights
    assert lamp.position == (4.0, 5.0, 6.0) and amb.color == (128 / 255, 128 / 255, 128 / 255, 1)
    assert lamp.world[0, 0] == 2.0 and lamp.world[0, 3] == -0.5  # ScaleX 2 about x = 0.5
    assert vp.camera.transform[1, 3] == 3.0
    assert vp.models[0].material[0].brush.stops[1].color == (0.0, 0.0, 1.0, 1.0)
    assert vp.models[0].material[0].brush.stops[0] is s.viewports[0].models[0].material[
        0].brush.stops[0]  # fmt: skip


def test_layout_animation_is_reported_not_drawn():
    text = f"""<Grid {NS} Width="200" Height="100"><Grid.ColumnDefinitions>
      <ColumnDefinition Width="Auto"/><ColumnDefinition/></Grid.ColumnDefinitions>
      <Viewport3D x:Name="view" Width="64">
        <Viewport3D.Camera><OrthographicCamera Position="0,0,10" LookDirection="0,0,-1"
            Width="64"/></Viewport3D.Camera>
        <Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
          <Storyboard><DoubleAnimation Storyboard.TargetName="view"
              Storyboard.TargetProperty="Width" To="128" Duration="0:0:1"/></Storyboard>
        </BeginStoryboard></EventTrigger></Viewport3D.Triggers>
      </Viewport3D></Grid>"""
    s = xaml3d.load(text, text=True)
    (d,) = [d for d in s.diagnostics if d.code == "ANIM014"]
    assert d.severity == "warning" and (d.line, d.column) == (7, 23)
    assert "view.Width" in d.message
    assert xaml3d.scene_at(s, 1.0).viewports[0].width == 64.0  # laid out once


def test_scene_pickles_small_and_renders_the_same_frames():
    anim = ('<DoubleAnimation Storyboard.TargetName="rot" Storyboard.TargetProperty="Angle" '
            'To="90" Duration="0:0:1"/>')  # fmt: skip
    s = xaml3d.load(scene(nested(), anim), text=True)
    data = pickle.dumps(s)
    copy = pickle.loads(data)
    assert isinstance(copy.tracks, Tracks)
    assert [t.target for t in copy.tracks.tracks] == ["rot.Angle"]
    for t in (0.0, 0.3, 0.8):
        a = xaml3d.render_arrays(s, time=t).rgba
        b = xaml3d.render_arrays(copy, time=t).rgba
        assert np.array_equal(a, b)
    assert copy.timeline.running_animations()[0].target_name == "rot"


@pytest.mark.skipif(not SPINNING.is_file(), reason="shared corpus absent")
def test_corpus_spinning_cube_pickles_small():
    s = xaml3d.load(SPINNING)
    data = pickle.dumps(s)
    assert len(data) < 40_000, len(data)
    assert b"lxml" not in data and b"xaml3d.xaml" not in data
    copy = pickle.loads(data)
    for t in (0.0, 1.7, 6.25):
        a = xaml3d.render_arrays(s, 96, 72, time=t).rgba
        b = xaml3d.render_arrays(copy, 96, 72, time=t).rgba
        assert np.array_equal(a, b)
        assert a[:, :, 3].any()
    f = xaml3d.scene_at(copy, 2.0)
    assert f.tracks is None and math.isfinite(f.viewports[0].models[0].world.sum())


def test_panel_background_colour_animates():
    text = f"""<Grid {NS} Width="64" Height="48"><Grid.Background>
        <SolidColorBrush x:Name="paper" Color="White"/></Grid.Background>
      <Viewport3D><Viewport3D.Camera><OrthographicCamera Position="0,0,10"
          LookDirection="0,0,-1" Width="64"/></Viewport3D.Camera>
        <Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
          <Storyboard>{hold("paper", "Color", "#000000", "Color")}</Storyboard>
        </BeginStoryboard></EventTrigger></Viewport3D.Triggers>
      </Viewport3D></Grid>"""
    s = xaml3d.load(text, text=True)
    (track,) = s.tracks.tracks
    # the viewport's background and the Grid's box, which render --window paints
    assert track.paths == (
        ScenePath(0, (("background", None),), "color"),
        ScenePath(None, (("boxes", 0), ("background", None)), "color"),
    )
    frame = xaml3d.scene_at(s, 0.0)
    assert frame.viewports[0].background.color == (0.0, 0.0, 0.0, 1.0)
    assert frame.layout.boxes[0].background.color == (0.0, 0.0, 0.0, 1.0)
    assert s.viewports[0].background.color == (1.0, 1.0, 1.0, 1.0)
    assert s.layout.boxes[0].background.color == (1.0, 1.0, 1.0, 1.0)


@pytest.mark.parametrize(
    ("transform", "name", "prop", "value"),
    [
        ('<RotateTransform x:Name="turn" Angle="{v}" CenterX="0.5" CenterY="0.25"/>', "turn",
         "Angle", "33"),
        ('<TransformGroup><ScaleTransform ScaleX="2"/><SkewTransform x:Name="turn" AngleX="{v}"/>'
         '<TranslateTransform X="0.1"/></TransformGroup>', "turn", "AngleX", "12.5"),
    ],
)  # fmt: skip
def test_brush_2d_transform_animates_bit_for_bit(transform, name, prop, value):
    def body(v: str) -> str:
        brush = f"""<LinearGradientBrush><LinearGradientBrush.RelativeTransform>
            {transform.format(v=v)}</LinearGradientBrush.RelativeTransform>
            <GradientStop Color="Red"/><GradientStop Color="Blue" Offset="1"/>
            </LinearGradientBrush>"""
        return nested().replace(
            '<DiffuseMaterial Brush="Lime"/>',
            f"<DiffuseMaterial><DiffuseMaterial.Brush>{brush}</DiffuseMaterial.Brush>"
            "</DiffuseMaterial>",
        )

    s = xaml3d.load(scene(body("0"), hold(name, prop, value)), text=True)
    assert not [d for d in s.diagnostics if d.code.startswith("ANIM")]
    (track,) = s.tracks.tracks
    assert [str(p) for p in track.moves] == [
        "viewport 0 / models[0] / material[0] / brush . relative_transform"
    ]
    want = xaml3d.load(scene(body(value), ""), text=True).viewports[0].models[0]
    got = xaml3d.scene_at(s, 0.5).viewports[0].models[0]
    m = got.material[0].brush.relative_transform
    assert m.shape == (3, 3)
    assert m.tobytes() == want.material[0].brush.relative_transform.tobytes()
    assert not np.array_equal(m, s.viewports[0].models[0].material[0].brush.relative_transform)


@pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus absent")
def test_every_corpus_scene_pickles_and_its_frames_survive():
    from xaml3d.errors import XamlError

    animated = 0
    for path in sorted(CORPUS.glob("*.xaml")):
        try:
            s = xaml3d.load(path)
        except XamlError:
            continue
        data = pickle.dumps(s)
        assert b"lxml" not in data, path.name
        copy = pickle.loads(data)
        animated += s.tracks is not None and xaml3d.scene_at(s, 1.3) is not s
        for t in (0.0, 1.3):
            a, b = xaml3d.scene_at(s, t), xaml3d.scene_at(copy, t)
            for va, vb in zip(a.viewports, b.viewports, strict=True):
                assert _same(va.camera, vb.camera), path.name
                assert _same(va.lights, vb.lights), path.name
                for ma, mb in zip(va.models, vb.models, strict=True):
                    assert _same((ma.world, ma.material), (mb.world, mb.material)), path.name
    assert animated >= 10  # the corpus's animated scenes were among them (14 today)


def _same(a, b) -> bool:
    """Equal values, arrays bit for bit, through dataclasses and tuples."""
    import dataclasses

    if isinstance(a, np.ndarray):
        return isinstance(b, np.ndarray) and a.tobytes() == b.tobytes() and a.shape == b.shape
    if dataclasses.is_dataclass(a):
        return type(a) is type(b) and all(
            _same(getattr(a, f.name), getattr(b, f.name)) for f in dataclasses.fields(a)
        )
    if isinstance(a, tuple):
        return isinstance(b, tuple) and len(a) == len(b) and all(map(_same, a, b))
    return a == b


def test_decoded_images_are_reused_by_frames(tmp_path):
    from PIL import Image

    Image.new("RGBA", (4, 4), (255, 0, 0, 255)).save(tmp_path / "red.png")
    body = nested().replace(
        '<DiffuseMaterial Brush="Lime"/>',
        '<DiffuseMaterial><DiffuseMaterial.Brush><ImageBrush x:Name="photo" ImageSource="red.png"'
        "/></DiffuseMaterial.Brush></DiffuseMaterial>",
    )
    anim = ('<DoubleAnimation Storyboard.TargetName="photo" Storyboard.TargetProperty="Opacity" '
            'To="0" Duration="0:0:1"/>')  # fmt: skip
    (tmp_path / "s.xaml").write_text(scene(body, anim))
    s = xaml3d.load(tmp_path / "s.xaml")
    loaded = s.viewports[0].models[0].material[0].brush
    assert loaded.image is not None and not loaded.is_placeholder
    for t in (0.25, 0.5):
        brush = xaml3d.scene_at(s, t).viewports[0].models[0].material[0].brush
        assert brush.opacity == 1.0 - t and brush.image is loaded.image


def test_brushes_inside_a_drawing_brush_animate():
    # a DrawingBrush is drawn again in every frame: the fill and pen brushes of its drawings
    # are tracks as a material's own brush is (WPF animates them), not ANIM014
    body = """<ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
      <AmbientLight Color="White"/>
      <GeometryModel3D><GeometryModel3D.Geometry><MeshGeometry3D TriangleIndices="0 1 2 0 2 3"
          Positions="-8,-8,0 8,-8,0 8,8,0 -8,8,0" TextureCoordinates="0,1 1,1 1,0 0,0"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush><DrawingBrush><DrawingBrush.Drawing><DrawingGroup>
          <GeometryDrawing><GeometryDrawing.Brush><LinearGradientBrush EndPoint="1,0">
              <GradientStop Color="Red" Offset="0"/>
              <GradientStop x:Name="stop" Color="Red" Offset="1"/></LinearGradientBrush>
            </GeometryDrawing.Brush>
            <GeometryDrawing.Geometry><RectangleGeometry Rect="0,0,1,1"/>
            </GeometryDrawing.Geometry></GeometryDrawing>
          <GeometryDrawing><GeometryDrawing.Pen><Pen Thickness="0.01">
              <Pen.Brush><SolidColorBrush x:Name="ink" Color="Black"/></Pen.Brush></Pen>
            </GeometryDrawing.Pen>
            <GeometryDrawing.Geometry><LineGeometry StartPoint="0,0.5" EndPoint="1,0.5"/>
            </GeometryDrawing.Geometry></GeometryDrawing>
        </DrawingGroup></DrawingBrush.Drawing></DrawingBrush>
      </DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>"""
    anims = (hold("stop", "Color", "#0000FF", "Color")
             + hold("ink", "Color", "#00FF00", "Color"))  # fmt: skip
    s = xaml3d.load(scene(body, anims), text=True)
    assert not [d for d in s.diagnostics if d.code.startswith("ANIM")]
    drawing = xaml3d.scene_at(s, 0.1).viewports[0].models[0].material[0].brush.drawing
    fill, line = drawing.children
    assert fill.brush.stops[1].color == (0.0, 0.0, 1.0, 1.0)
    assert line.pen.brush.color == (0.0, 1.0, 0.0, 1.0)
    base = s.viewports[0].models[0].material[0].brush.drawing
    assert base.children[0].brush.stops[1].color == (1.0, 0.0, 0.0, 1.0)
    # the picture follows: the quad's right edge is blue at t, red as loaded
    img = np.asarray(xaml3d.render(s, time=0.1))
    loaded = np.asarray(xaml3d.render(s, time=None))
    assert img[24, 39, 2] > 200 and img[24, 39, 0] < 60
    assert loaded[24, 39, 0] > 200 and loaded[24, 39, 2] < 60
