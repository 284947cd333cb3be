"""``camera --point``: a depth outside the documented range [-1, 0] is marked, in a real
process. With FarPlaneDistance = Infinity the effective far plane only encloses the scene
(camera-math.md section 9): a point beyond it is drawn by WPF, its depth below -1, and the
output says so; a finite far plane clips it."""

from __future__ import annotations

import json

import pytest
from test_cli_subprocess import xaml3d

SCENE = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="40" Height="30">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5" FAR/></Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material><EmissiveMaterial Brush="Red"/></GeometryModel3D.Material>
      </GeometryModel3D>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""
NEAR = 0.125
FAR = 5 * 1.001  # the scene's far side (z = 0, 5 from the eye) and 0.1 % more
NOTE = (
    "beyond the effective far plane, which only encloses the scene: FarPlaneDistance is "
    "Infinity, so WPF draws it"
)


def _depth(d: float) -> float:
    """z' of a point d from the eye along the look direction: f (n - d) / (d (f - n))."""
    return FAR * (NEAR - d) / (d * (FAR - NEAR))


def test_a_point_beyond_the_effective_far_plane_is_marked(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE.replace("FAR", ""))
    args = ["camera", "s.xaml", "--point", "0,0,-5", "--point", "0,0,0", "--point", "0,0,4"]
    p = xaml3d(*args, "--json", cwd=tmp_path)
    assert p.returncode == 0
    beyond, on, near = json.loads(p.stdout)["points"]
    assert beyond["visible"] and beyond["reason"] is None and beyond["note"] == NOTE
    assert beyond["depth"] == pytest.approx(_depth(10.0), abs=1e-12)  # -1.0127...
    assert beyond["depth"] < -1.0
    assert on["depth"] == pytest.approx(_depth(5.0), abs=1e-12) and on["note"] is None
    assert near["depth"] == pytest.approx(_depth(1.0), abs=1e-12) and near["note"] is None
    p = xaml3d(*args, cwd=tmp_path)
    assert p.stdout.decode().splitlines()[-3:] == [
        f"point 0,0,-5 -> pixel (20, 15), depth {_depth(10.0):.6g} ({NOTE})",
        f"point 0,0,0 -> pixel (20, 15), depth {_depth(5.0):.6g}",
        f"point 0,0,4 -> pixel (20, 15), depth {_depth(1.0):.6g}",
    ]


def test_a_finite_far_plane_clips_the_point_beyond_it(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE.replace("FAR", 'FarPlaneDistance="8"'))
    p = xaml3d("camera", "s.xaml", "--point", "0,0,-5", cwd=tmp_path)
    assert p.stdout.decode().splitlines()[-1] == "point 0,0,-5 -> clipped: beyond the far plane"
