"""A Viewport3D's Style given as the ``<Viewport3D.Style>`` property element acts as one named by
``Style="{StaticResource ...}"``: its Setters size and place the viewport, set its Camera (a
camera in ``<Setter.Value>`` or a resource named by the Value) and its RenderTransform."""

from __future__ import annotations

import numpy as np

import xaml3d
from xaml3d.pipeline import load
from xaml3d.render.window import compose_window

_HEAD = """xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml\""""
_CAMERA = '<OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" Width="{w}"/>'
_SIZE = """<Setter Property="Width" Value="64"/><Setter Property="Height" Value="48"/>
  <Setter Property="Margin" Value="4,6,0,0"/><Setter Property="HorizontalAlignment" Value="Left"/>
  <Setter Property="VerticalAlignment" Value="Top"/>"""
_MODELS = """<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
      <GeometryModel3D><GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,0,0 -16,0,0"
            TriangleIndices="0 1 2 0 2 3"/>
      </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/>
      </GeometryModel3D.Material></GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>"""


def _doc(style: str, resources: str = "", own: str = "") -> str:
    return f"""<Grid {_HEAD} Width="128" Height="96">
  <Grid.Resources>{resources}</Grid.Resources>
  <Viewport3D{own}><Viewport3D.Style>{style}</Viewport3D.Style>{_MODELS}</Viewport3D>
</Grid>"""


def _camera_setter(w: int = 64) -> str:
    return f'<Setter Property="Camera"><Setter.Value>{_CAMERA.format(w=w)}</Setter.Value></Setter>'


def test_a_style_property_element_sizes_places_and_sets_the_camera():
    s = load(_doc(f'<Style TargetType="Viewport3D">{_SIZE}{_camera_setter()}</Style>'), text=True)
    box = next(b for b in s.layout.boxes if b.type == "Viewport3D")
    assert box.rect == (4.0, 6.0, 64.0, 48.0)
    v = s.viewports[0]
    assert (v.width, v.height) == (64.0, 48.0)
    assert type(v.camera).__name__ == "OrthographicCamera" and v.camera.width == 64.0
    codes = {d.code for d in s.diagnostics}
    assert "SCN004" not in codes and not {c for c in codes if c.startswith(("XAML", "RES"))}


def test_a_style_property_element_naming_a_resource_and_based_on_one():
    base = f'<Style x:Key="base" TargetType="Viewport3D">{_SIZE}</Style>'
    named = '<Style x:Key="s" TargetType="Viewport3D" BasedOn="{StaticResource base}">' + (
        f"{_camera_setter(32)}</Style>"
    )
    for style, resources in (
        ('<StaticResource ResourceKey="s"/>', base + named),
        (f'<Style BasedOn="{{StaticResource base}}" TargetType="Viewport3D">'
         f"{_camera_setter(32)}</Style>", base),
    ):  # fmt: skip
        s = load(_doc(style, resources), text=True)
        box = next(b for b in s.layout.boxes if b.type == "Viewport3D")
        assert box.rect == (4.0, 6.0, 64.0, 48.0)
        assert s.viewports[0].camera.width == 32.0


def test_a_camera_setter_naming_a_resource_and_the_viewports_own_camera_winning():
    cam = '<OrthographicCamera x:Key="cam" Position="0,0,10" LookDirection="0,0,-1" Width="40"/>'
    style = f'<Style TargetType="Viewport3D">{_SIZE}'
    style += '<Setter Property="Camera" Value="{StaticResource cam}"/></Style>'
    s = load(_doc(style, cam), text=True)
    assert s.viewports[0].camera.width == 40.0
    own = _doc(style, cam).replace(
        "</Viewport3D.Style>",
        f"</Viewport3D.Style><Viewport3D.Camera>{_CAMERA.format(w=50)}</Viewport3D.Camera>",
    )
    assert load(own, text=True).viewports[0].camera.width == 50.0


def test_an_implicit_style_sets_the_camera_too():
    style = f'<Style TargetType="Viewport3D">{_camera_setter(24)}</Style>'
    doc = f"""<Grid {_HEAD} Width="128" Height="96"><Grid.Resources>{style}</Grid.Resources>
  <Viewport3D>{_MODELS}</Viewport3D></Grid>"""
    assert load(doc, text=True).viewports[0].camera.width == 24.0


def test_a_style_property_element_of_another_target_type_is_refused():
    s = load(_doc(f'<Style TargetType="Button">{_SIZE}</Style>'), text=True)
    (d,) = [d for d in s.diagnostics if d.code == "XAML022"]
    assert d.line == 4  # at the Viewport3D
    assert (s.viewports[0].width, s.viewports[0].height) == (128.0, 96.0)


def test_a_flip_its_style_property_element_sets(tmp_path):
    flip = '<ScaleTransform ScaleY="-1"/>'
    style = (f'<Style TargetType="Viewport3D">{_SIZE}{_camera_setter()}'
             '<Setter Property="RenderTransformOrigin" Value="0.5,0.5"/>'
             f'<Setter Property="RenderTransform"><Setter.Value>{flip}</Setter.Value></Setter>'
             "</Style>")  # fmt: skip
    path = tmp_path / "s.xaml"
    path.write_text(_doc(style))
    scene = xaml3d.load(path)
    # the lime lower half of the square, flipped about the viewport's centre: its upper half
    ys, xs = np.nonzero(xaml3d.render_arrays(scene).rgba[..., 3])
    assert (xs.min(), ys.min(), xs.max(), ys.max()) == (16, 8, 47, 23)
    ys, xs = np.nonzero(compose_window(scene)[0][..., 3])
    assert (xs.min(), ys.min(), xs.max(), ys.max()) == (20, 14, 51, 29)  # at its Margin 4,6


def test_a_style_property_element_of_a_panel_around_the_viewport():
    style = (
        '<Style TargetType="Border"><Setter Property="Padding" Value="10,5,0,0"/>'
        '<Setter Property="BorderThickness" Value="2"/></Style>'
    )
    doc = f"""<Grid {_HEAD} Width="128" Height="96"><Border><Border.Style>{style}</Border.Style>
  <Viewport3D/></Border></Grid>"""
    box = next(b for b in load(doc, text=True).layout.boxes if b.type == "Viewport3D")
    assert box.rect == (12.0, 7.0, 114.0, 87.0)
