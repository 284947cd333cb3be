"""A Viewport3D that WPF's layout leaves empty (no Height in a vertical StackPanel), in a real
process: ``validate`` warns (LAY001); ``render`` prints the same warning at the same place, in
line order, then one render error of its own (RND008, never the camera's CAM010), exit 1 and no
file; ``-W``/``-H`` render at that size (one alone: a square, there is no aspect ratio to
follow) and ``--window`` draws the window around the empty area."""

from __future__ import annotations

import numpy as np
from PIL import Image
from test_cli_subprocess import xaml3d

SCENE = """<Window xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="400" Height="300">
  <StackPanel>
    <Viewport3D>
      <Viewport3D.Camera>
        <PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1" />
      </Viewport3D.Camera>
      <ModelVisual3D>
        <ModelVisual3D.Content>
          <GeometryModel3D>
            <GeometryModel3D.Geometry>
              <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2 3" />
            </GeometryModel3D.Geometry>
            <GeometryModel3D.Material>
              <EmissiveMaterial Brush="Red" />
            </GeometryModel3D.Material>
          </GeometryModel3D>
        </ModelVisual3D.Content>
      </ModelVisual3D>
    </Viewport3D>
  </StackPanel>
</Window>
"""

LAY001 = (
    "s.xaml:4:5: warning LAY001 Viewport3D #0 is laid out with height 0 (a vertical StackPanel "
    "gives each child its desired height, and a Viewport3D without Height wants 0): WPF draws "
    "nothing"
)
# the mesh's own warnings come after the viewport's line: the order is the line order; both
# point at the index at fault, the 4th (the first ignored, and the first out of range)
MESH = [
    "s.xaml:12:87: warning MSH002 TriangleIndices has 4 entries, not a multiple of 3; the last 1 "
    "are ignored",
    "s.xaml:12:87: warning MSH001 TriangleIndices[3] = 3 is out of range (0..2 for 3 positions): "
    "WPF draws only the 1 triangle(s) before it, 1 of 4 indices ignored",
]
RND008 = (
    "s.xaml:4:5: error RND008 Viewport3D #0 is laid out 384 x 0 (see LAY001): nothing to draw; "
    "give -W/-H to render it at a size, or --window to render the window as WPF shows it"
)


def _lines(data: bytes) -> list[str]:
    return data.decode().splitlines()


def test_validate_warns_and_render_refuses_with_one_render_error(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert p.returncode == 0
    found = [line for line in _lines(p.stdout) if " info " not in line]  # validate shows infos
    assert found == [LAY001, *MESH]
    for extra in ([], ["--lenient"], ["--scale", "2"]):
        p = xaml3d("render", "s.xaml", "-o", "out.png", *extra, cwd=tmp_path)
        assert p.returncode == 1, extra
        assert _lines(p.stderr) == [LAY001, *MESH, RND008], extra
        assert not (tmp_path / "out.png").exists()


def test_width_and_height_render_it_at_that_size(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    p = xaml3d("render", "s.xaml", "-o", "out.png", "-W", "50", "-H", "40", cwd=tmp_path)
    assert p.returncode == 0
    assert _lines(p.stderr) == [LAY001, *MESH]
    with Image.open(tmp_path / "out.png") as im:
        assert im.size == (50, 40)
        assert int(np.count_nonzero(np.asarray(im)[..., 0] == 255)) > 0  # the red triangle


def test_window_draws_the_empty_area_as_wpf_does(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    p = xaml3d("render", "s.xaml", "-o", "win.png", "--window", cwd=tmp_path)
    assert p.returncode == 0
    assert _lines(p.stderr) == [LAY001, *MESH]
    with Image.open(tmp_path / "win.png") as im:
        # the client area (400 x 300 less the frame 16 x 39), all the Window's white background
        assert im.size == (384, 261)
        assert np.unique(np.asarray(im).reshape(-1, 4), axis=0).tolist() == [[255] * 4]


def test_one_of_width_and_height_gives_a_square(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    for option in ("-W", "-H"):
        p = xaml3d("render", "s.xaml", "-o", "out.png", option, "30", cwd=tmp_path)
        assert p.returncode == 0
        assert _lines(p.stderr) == [LAY001, *MESH]
        with Image.open(tmp_path / "out.png") as im:
            assert im.size == (30, 30)


def test_animate_and_camera_say_the_same_render_error(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    rnd008 = (
        "s.xaml:4:5: error RND008 Viewport3D #0 is laid out 384 x 0 (see LAY001/LAY002): "
        "nothing to draw; give -W/-H to render it at a size"
    )
    p = xaml3d("animate", "s.xaml", "-o", "a.gif", "--duration", "0.2", cwd=tmp_path)
    assert p.returncode == 1 and _lines(p.stderr) == [LAY001, *MESH, rnd008]
    assert not (tmp_path / "a.gif").exists()
    p = xaml3d("camera", "s.xaml", cwd=tmp_path)
    assert p.returncode == 1 and _lines(p.stderr)[-1] == rnd008
    p = xaml3d("camera", "s.xaml", "-W", "30", cwd=tmp_path)  # a square: no aspect to follow
    assert p.returncode == 0 and "Pipeline for a 30 x 30 image" in p.stdout.decode()
