"""A viewport whose own RenderTransform only translates it: its render is its own picture, in
place (DRW008 says so); the window picture draws it where the translation puts it; a
transform that is animated, or that turns or flips the picture, is still drawn."""

from __future__ import annotations

import numpy as np

import xaml3d
from xaml3d.render.window import compose_window

_GRID = """<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="128" Height="96">
  <Viewport3D Width="64" Height="48" HorizontalAlignment="Left" VerticalAlignment="Top"
      RenderTransformOrigin="0.5,0.5">
    <Viewport3D.RenderTransform>{transform}</Viewport3D.RenderTransform>
    <Viewport3D.Camera><OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" Width="64"/>
    </Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
      <GeometryModel3D><GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,0,0 -16,0,0"
            TriangleIndices="0 1 2 0 2 3"/>
      </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/>
      </GeometryModel3D.Material></GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</Grid>"""


def _scene(tmp_path, transform: str):
    path = tmp_path / "s.xaml"
    path.write_text(_GRID.format(transform=transform))
    return xaml3d.load(path)


def _box(alpha: np.ndarray) -> tuple[int, int, int, int]:
    ys, xs = np.nonzero(alpha)
    return int(xs.min()), int(ys.min()), int(xs.max()), int(ys.max())


def test_a_translation_is_the_windows_business(tmp_path):
    scene = _scene(tmp_path, '<TranslateTransform X="10" Y="20"/>')
    r = xaml3d.render_arrays(scene)
    # the lime half-square (the lower half of the standard frame's square) where it is drawn
    assert _box(r.rgba[..., 3]) == (16, 24, 47, 39)
    (info,) = [d for d in r.diagnostics if d.code == "DRW008"]
    assert "by 10, 20" in info.message and info.line == 3
    rgba, _ = compose_window(scene)
    assert _box(rgba[..., 3]) == (26, 44, 57, 59)  # moved by 10, 20 over the window


def test_a_flip_is_still_drawn_in_the_viewports_own_picture(tmp_path):
    scene = _scene(tmp_path, '<ScaleTransform ScaleY="-1"/>')
    r = xaml3d.render_arrays(scene)
    assert _box(r.rgba[..., 3]) == (16, 8, 47, 23)  # flipped about the centre: the upper half
    assert not [d for d in r.diagnostics if d.code == "DRW008"]
    rgba, _ = compose_window(scene)
    assert _box(rgba[..., 3]) == (16, 8, 47, 23)


def test_an_identity_transform_says_nothing(tmp_path):
    scene = _scene(
        tmp_path, "<TransformGroup><ScaleTransform/><TranslateTransform/></TransformGroup>"
    )
    r = xaml3d.render_arrays(scene)
    assert _box(r.rgba[..., 3]) == (16, 24, 47, 39)
    assert not [d for d in r.diagnostics if d.code == "DRW008"]


_STYLED = """<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="128" Height="96">
  <Grid.Resources><Style x:Key="s" TargetType="Viewport3D">{setters}</Style></Grid.Resources>
  <Viewport3D Width="64" Height="48" HorizontalAlignment="Left" VerticalAlignment="Top"
      Style="{{StaticResource s}}">{own}
    <Viewport3D.Camera><OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" Width="64"/>
    </Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
      <GeometryModel3D><GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,0,0 -16,0,0"
            TriangleIndices="0 1 2 0 2 3"/>
      </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/>
      </GeometryModel3D.Material></GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</Grid>"""
_ORIGIN = '<Setter Property="RenderTransformOrigin" Value="0.5,0.5"/>'
_FLIP = '<ScaleTransform ScaleY="-1"/>'


def test_a_flip_about_the_origin_its_style_sets(tmp_path):
    # the Style sets the origin, the viewport its own flip: turned about the centre, in view
    path = tmp_path / "s.xaml"
    own = f"<Viewport3D.RenderTransform>{_FLIP}</Viewport3D.RenderTransform>"
    path.write_text(_STYLED.format(setters=_ORIGIN, own=own))
    scene = xaml3d.load(path)
    assert _box(xaml3d.render_arrays(scene).rgba[..., 3]) == (16, 8, 47, 23)
    assert _box(compose_window(scene)[0][..., 3]) == (16, 8, 47, 23)


def test_a_flip_its_style_sets(tmp_path):
    path = tmp_path / "s.xaml"
    setter = f'<Setter Property="RenderTransform"><Setter.Value>{_FLIP}</Setter.Value></Setter>'
    path.write_text(_STYLED.format(setters=_ORIGIN + setter, own=""))
    scene = xaml3d.load(path)
    assert _box(xaml3d.render_arrays(scene).rgba[..., 3]) == (16, 8, 47, 23)
    assert _box(compose_window(scene)[0][..., 3]) == (16, 8, 47, 23)
