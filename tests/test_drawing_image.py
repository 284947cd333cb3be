"""An Image whose Source is a DrawingImage (inside a visual, beside the viewports) and an
ImageBrush of one: sized by the Drawing's bounds, stretched as WPF's Image stretches."""

from __future__ import annotations

import numpy as np

import xaml3d
from xaml3d.scene.drawing import DrawingBrush

_HEAD = """xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml\""""
_ARROW = """<DrawingImage x:Key="arrow"><DrawingImage.Drawing>
      <GeometryDrawing Brush="Blue" Geometry="M0,0 L16,8 0,16Z"/>
    </DrawingImage.Drawing></DrawingImage>"""


def _visual_scene(tmp_path, visual: str):
    """A Viewport2DVisual3D of ``visual`` on a 64x32 quad, 1 px per DIP."""
    path = tmp_path / "s.xaml"
    path.write_text(f"""<Viewport3D {_HEAD} Width="64" Height="32">
  <Viewport3D.Resources>{_ARROW}</Viewport3D.Resources>
  <Viewport3D.Camera><OrthographicCamera Position="0,0,10" Width="64"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><AmbientLight Color="White"/></ModelVisual3D.Content>
  </ModelVisual3D>
  <Viewport2DVisual3D><Viewport2DVisual3D.Geometry>
      <MeshGeometry3D Positions="-32,-16,0 32,-16,0 32,16,0 -32,16,0"
          TriangleIndices="0 1 2  0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
    </Viewport2DVisual3D.Geometry>
    <Viewport2DVisual3D.Material>
      <DiffuseMaterial Viewport2DVisual3D.IsVisualHostMaterial="True"/>
    </Viewport2DVisual3D.Material>{visual}</Viewport2DVisual3D>
</Viewport3D>""")
    return xaml3d.load(path)


def test_image_of_a_drawing_image_takes_the_drawings_size_in_a_visual(tmp_path):
    # a 64x32 white Canvas; the arrow's Image without a size at 8,8: 16x16, natural size
    scene = _visual_scene(
        tmp_path,
        """<Canvas Width="64" Height="32" Background="White">
      <Image Canvas.Left="8" Canvas.Top="8" Source="{StaticResource arrow}"/></Canvas>""",
    )
    assert not [d for d in scene.diagnostics if d.code.startswith(("DRW", "XAML", "RES"))]
    rgba = xaml3d.render_arrays(scene).rgba
    assert (rgba[16, 9] == (0, 0, 255, 255)).all()  # inside the arrow, near its base
    assert rgba[16, 20, 2] == 255 and rgba[16, 20, 0] < 40  # near its tip at 24,16
    assert (rgba[16, 26] == (255, 255, 255, 255)).all()  # past the tip
    assert (rgba[9, 20] == (255, 255, 255, 255)).all()  # above the slanted edge
    assert (rgba[4, 4] == (255, 255, 255, 255)).all()


def test_a_drawing_image_stretches_uniformly_into_the_room_given(tmp_path):
    # Width 32 only: the height follows (Uniform), 32x32 from the top of a 64x32 Canvas
    scene = _visual_scene(
        tmp_path,
        """<Canvas Width="64" Height="32" Background="White">
      <Image Width="32" Source="{StaticResource arrow}"/></Canvas>""",
    )
    rgba = xaml3d.render_arrays(scene).rgba
    row = rgba[16, :, :3].astype(int)
    blue = np.flatnonzero((row == (0, 0, 255)).all(axis=1))
    assert blue[0] == 0 and 29 <= blue[-1] <= 31  # the tip at x = 32


def test_image_brush_of_a_drawing_image_is_its_drawings_brush(tmp_path):
    path = tmp_path / "s.xaml"
    path.write_text(f"""<Viewport3D {_HEAD} Width="64" Height="48">
  <Viewport3D.Resources>{_ARROW}</Viewport3D.Resources>
  <Viewport3D.Camera><OrthographicCamera Position="0,0,10" Width="64"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
    <GeometryModel3D><GeometryModel3D.Geometry>
      <MeshGeometry3D Positions="-16,-16,0 16,-16,0 16,16,0 -16,16,0"
          TriangleIndices="0 1 2 0 2 3" TextureCoordinates="0,1 1,1 1,0 0,0"/>
    </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial>
      <DiffuseMaterial.Brush><ImageBrush ImageSource="{{StaticResource arrow}}" Opacity="0.5"/>
      </DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>""")
    scene = xaml3d.load(path)
    brush = scene.viewports[0].models[0].material[0].brush
    assert isinstance(brush, DrawingBrush) and brush.opacity == 0.5
    rgba = xaml3d.render_arrays(scene).rgba
    assert rgba[24, 18, 3] > 100 and rgba[24, 18, 2] > 100  # the arrow's base, left of centre
    assert rgba[9, 46, 3] == 0  # the top right of the square: outside the arrow
