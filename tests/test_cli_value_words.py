"""What ``validate`` and ``camera`` print about values, word for word, as a real process: a bad
colour names its property once (``SolidColorBrush.Color: '#GG1122' ...``), and ``camera`` marks
``(default)`` only what the markup does not give, not a written value equal to WPF's default.
"""

from __future__ import annotations

import json
import subprocess
import sys

SCENE = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" Width="64"
  Height="48">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1"
    NearPlaneDistance="0.125"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="White"/>
    <GeometryModel3D><GeometryModel3D.Geometry>
      <MeshGeometry3D Positions="-1,-1,0 1,-1,0 0,1,0" TriangleIndices="0 1 2"/>
    </GeometryModel3D.Geometry><GeometryModel3D.Material><DiffuseMaterial>
      <DiffuseMaterial.Brush><SolidColorBrush Color="BRUSH"/></DiffuseMaterial.Brush>
    </DiffuseMaterial></GeometryModel3D.Material></GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>
"""


def xaml3d(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "xaml3d", *map(str, args)], capture_output=True,
                          text=True, cwd=cwd, timeout=300)  # fmt: skip


def _write(tmp_path, colour: str) -> str:
    (tmp_path / "s.xaml").write_text(SCENE.replace("BRUSH", colour))
    return "s.xaml"


def test_a_bad_colour_names_its_property_once(tmp_path):
    p = xaml3d("validate", _write(tmp_path, "#GG1122"), cwd=tmp_path)
    assert p.returncode == 1
    errors = [ln for ln in p.stdout.splitlines() if " error " in ln]
    assert errors == [
        "s.xaml:10:47: error VAL004 SolidColorBrush.Color: '#GG1122' is not a colour "
        "('#AARRGGBB', 'sc#a,r,g,b' or one of WPF's names)"
    ]


def test_camera_marks_default_only_what_the_markup_does_not_give(tmp_path):
    p = xaml3d("camera", _write(tmp_path, "Red"), cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert p.stdout.splitlines()[:8] == [
        "viewport 0: PerspectiveCamera (line 3)",
        "  Position = 0,0,5",
        "  LookDirection = 0,0,-1",
        "  UpDirection = 0,1,0 (default)",
        "  NearPlaneDistance = 0.125",
        "  FarPlaneDistance = Infinity (default)",
        "  Transform = Identity (default)",
        "  FieldOfView = 45 (default)",
    ]
    p = xaml3d("camera", "s.xaml", "--json", cwd=tmp_path)
    props = json.loads(p.stdout)["camera"]["properties"]
    assert {n: v["default"] for n, v in props.items()} == {
        "Position": False, "LookDirection": False, "UpDirection": True,
        "NearPlaneDistance": False, "FarPlaneDistance": True, "Transform": True,
        "FieldOfView": True,
    }  # fmt: skip


def test_a_refused_value_is_marked_default(tmp_path):
    # WPF's loader refuses it: its default stands in (and validate says so)
    text = SCENE.replace('LookDirection="0,0,-1"', 'LookDirection="0,0,x"').replace("BRUSH", "Red")
    (tmp_path / "s.xaml").write_text(text)
    p = xaml3d("camera", "s.xaml", cwd=tmp_path)
    assert p.stdout.splitlines()[2] == "  LookDirection = 0,0,-1 (default)", p.stderr
