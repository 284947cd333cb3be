"""``--viewport NAME`` finds a Viewport3D named inside a template, as a user naming it there
expects (WPF keeps the name in the template's name scope): when one instance holds it; two
instances are told apart by index, and ``--viewport all`` names their files by index."""

from __future__ import annotations

import subprocess
import sys

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
VIEWPORT = """<Viewport3D x:Name="vp" Width="40" Height="40">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="White"/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
        <MeshGeometry3D Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 2"/>
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>"""
CONTROL = '<ContentControl Template="{StaticResource scene}"/>'


def _window(controls: int) -> str:
    return f"""<Window {NS} Width="200" Height="120">
<Window.Resources>
  <ControlTemplate x:Key="scene" TargetType="ContentControl">{VIEWPORT}</ControlTemplate>
</Window.Resources>
<StackPanel>{CONTROL * controls}</StackPanel>
</Window>
"""


def _run(*args: str, cwd) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "xaml3d", *args], capture_output=True, text=True, cwd=cwd
    )


def test_the_name_of_a_viewport_in_a_template_picks_it(tmp_path):
    (tmp_path / "s.xaml").write_text(_window(1), encoding="utf-8")
    r = _run("render", "s.xaml", "--viewport", "vp", "-o", "vp.png", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    by_index = _run("render", "s.xaml", "--viewport", "0", "-o", "0.png", cwd=tmp_path)
    assert by_index.returncode == 0, by_index.stderr
    assert (tmp_path / "vp.png").read_bytes() == (tmp_path / "0.png").read_bytes()
    info = _run("info", "s.xaml", cwd=tmp_path)
    assert "viewport 0 'vp'" in info.stdout


def test_a_name_two_instances_share_asks_for_an_index(tmp_path):
    (tmp_path / "s.xaml").write_text(_window(2), encoding="utf-8")
    r = _run("render", "s.xaml", "--viewport", "vp", "-o", "vp.png", cwd=tmp_path)
    assert r.returncode == 1
    assert "error SCN002 2 viewports are named 'vp'" in r.stderr and "(0, 1)" in r.stderr
    assert "Traceback" not in r.stderr and not (tmp_path / "vp.png").exists()
    every = _run("render", "s.xaml", "--viewport", "all", "-o", "out.png", cwd=tmp_path)
    assert every.returncode == 0, every.stderr
    assert sorted(p.name for p in tmp_path.glob("out-*.png")) == ["out-0.png", "out-1.png"]
