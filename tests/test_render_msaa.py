"""Multisampling (the default anti-aliasing): coverage and depth per sample, shading once per
pixel per triangle at the pixel centre; supersampling stays available."""

from __future__ import annotations

import numpy as np
import pytest

from xaml3d.api import render_arrays
from xaml3d.errors import RenderError
from xaml3d.pipeline import load

TEXTURED = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
  Width="64" Height="48">
  <Viewport3D.Camera><PerspectiveCamera Position="0.3,0.2,3" LookDirection="-0.1,-0.07,-1"
    FieldOfView="50" /></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="#404040" /><DirectionalLight Color="#C0C0C0" Direction="-1,-1,-2" />
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="-1,-1,0 1,-1,-0.5 1,1,0 -1,1,0.4"
          Normals="0,0,1 0.3,0,1 0,0,1 0,0.2,1"
          TextureCoordinates="0,1 1,1 1,0 0,0" TriangleIndices="0 1 2 0 2 3" />
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material>
        <DiffuseMaterial><DiffuseMaterial.Brush>
          <LinearGradientBrush StartPoint="0,0" EndPoint="1,1">
            <GradientStop Color="Orange" Offset="0" /><GradientStop Color="Navy" Offset="1" />
          </LinearGradientBrush>
        </DiffuseMaterial.Brush></DiffuseMaterial>
      </GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>"""


@pytest.fixture(scope="module")
def scene():
    return load(TEXTURED.encode())


def test_default_is_msaa_2(scene):
    default = render_arrays(scene).rgba
    assert np.array_equal(default, render_arrays(scene, msaa=2).rgba)
    assert not np.array_equal(default, render_arrays(scene, ssaa=2).rgba)


def test_flat_uniform_msaa_equals_ssaa(scene):
    """Per-face colours need no attributes: multisampling and supersampling agree exactly."""
    flat = load(
        TEXTURED.encode()
        .replace(b"<DiffuseMaterial><DiffuseMaterial.Brush>", b'<DiffuseMaterial Brush="Teal">')
        .split(b"<LinearGradientBrush")[0]
        + b"</DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>"
        b"</Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D>"
    )
    a = render_arrays(flat, mode="flat", msaa=2).rgba
    b = render_arrays(flat, mode="flat", ssaa=2).rgba
    assert np.array_equal(a, b)
    assert ((a[..., 3] > 0) & (a[..., 3] < 255)).any()  # there are anti-aliased edge pixels


def test_msaa_shades_at_the_pixel_centre(scene):
    """Pixels whose four samples are all covered take exactly the colour an unsupersampled
    render computes at the pixel centre (up to float rounding)."""
    ms = render_arrays(scene, msaa=2).rgba.astype(int)
    one = render_arrays(scene, ssaa=1).rgba.astype(int)
    inner = ms[..., 3] == 255
    assert inner.sum() > 500
    assert np.abs(ms[inner] - one[inner]).max() <= 1


@pytest.mark.parametrize(
    "kwargs", [{"msaa": 2, "ssaa": 2}, {"msaa": 0}, {"msaa": 5}, {"msaa": 2.0}]
)
def test_bad_aa_arguments(scene, kwargs):
    with pytest.raises(RenderError) as e:
        render_arrays(scene, **kwargs)
    assert e.value.code == "RND005"


def test_aa_sample_budget_names_msaa(scene):
    with pytest.raises(RenderError) as e:
        render_arrays(scene, 16000, 16000, msaa=4)
    assert e.value.code == "RND001" and "msaa=4" in e.value.message


def test_passes_rasterized_again_draw_the_same(monkeypatch):
    """Multi-pass materials keep their fragments between passes only up to a memory bound;
    beyond it every pass rasterizes again, with the same picture."""
    from pathlib import Path

    from xaml3d.render import draw

    ref = Path(__file__).resolve().parent / "reference"
    for case in ("material/group-order", "material/group-translucent-layer", "material/emissive"):
        scene = load(ref / f"{case}.xaml")
        kept = render_arrays(scene)
        monkeypatch.setattr(draw, "KEEP_BYTES", 0)
        again = render_arrays(scene)
        monkeypatch.undo()
        assert np.array_equal(kept.rgba, again.rgba) and np.array_equal(kept.depth, again.depth)


@pytest.mark.parametrize(
    "brush",
    [
        '<ImageBrush ImageSource="blue.png"/>',
        '<DrawingBrush><DrawingBrush.Drawing><GeometryDrawing Brush="#000080">'
        '<GeometryDrawing.Geometry><RectangleGeometry Rect="0,0,8,8"/>'
        "</GeometryDrawing.Geometry></GeometryDrawing></DrawingBrush.Drawing></DrawingBrush>",
    ],
)
def test_a_brush_extends_its_edge_texels_at_multisampled_edges(tmp_path, brush):
    # Two quads meeting at x = 0.3 (between pixel centres), each with the whole of one opaque
    # brush (TileMode None). A pixel of the shared edge is shaded at its centre, outside one of
    # the two triangles: the texture coordinates there leave the mesh's box by a fraction of a
    # pixel. WPF samples the brush with Extend addressing (its edge texels continue), so the
    # edge is as opaque and blue as the rest; the transparency beyond the tile made a light seam.
    from PIL import Image

    Image.new("RGB", (8, 8), (0, 0, 128)).save(tmp_path / "blue.png")
    quad = """<GeometryModel3D><GeometryModel3D.Geometry><MeshGeometry3D Positions="{x0},-10,0
        {x1},-10,0 {x1},10,0 {x0},10,0" TextureCoordinates="0,1 1,1 1,0 0,0"
        TriangleIndices="0 1 2 0 2 3"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial><DiffuseMaterial.Brush>{brush}
        </DiffuseMaterial.Brush></DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>"""
    path = tmp_path / "seam.xaml"
    path.write_text(f"""<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
  Width="64" Height="48">
  <Viewport3D.Camera><OrthographicCamera Position="0,0,10" LookDirection="0,0,-1" Width="64"/>
  </Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
    {quad.format(x0=-20.3, x1=0.3, brush=brush)}{quad.format(x0=0.3, x1=20.3, brush=brush)}
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>""")
    rgba = render_arrays(load(path)).rgba
    inside = rgba[16:32, 13:52]  # rows y -8..8, columns x -19..20: away from the outer edges
    assert (inside == [0, 0, 128, 255]).all()
