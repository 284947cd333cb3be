"""``animate`` of a scene where nothing animates at load (ANIM015) draws its one picture once
and repeats it: the same frames, files and GIF as drawing each frame, one render."""

from __future__ import annotations

from click.testing import CliRunner

from xaml3d.cli import main
from xaml3d.render import frames as frames_module

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
# a Storyboard that no trigger begins at load: nothing moves
WINDOW = f"""<Window {NS} Width="120" Height="90">
<Window.Resources>
  <Storyboard x:Key="grow">
    <DoubleAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="FieldOfView"
                     From="30" To="60" Duration="0:0:1"/>
  </Storyboard>
</Window.Resources>
<StackPanel>
  <Button x:Name="b" Content="Go" Width="40"/>
  <Viewport3D Width="40" Height="40">
    <Viewport3D.Camera><PerspectiveCamera x:Name="cam" Position="0,0,5"/></Viewport3D.Camera>
    <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
      <AmbientLight Color="White"/>
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="0,0,0 1,0,0 0,1,0" TriangleIndices="0 1 2"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material><DiffuseMaterial Brush="Red"/></GeometryModel3D.Material>
      </GeometryModel3D>
    </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  </Viewport3D>
</StackPanel>
</Window>
"""


def _counted(monkeypatch) -> list:
    drawn = []
    real = frames_module._draw

    def draw(*args, **kwargs):
        drawn.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(frames_module, "_draw", draw)
    return drawn


def test_a_still_window_is_drawn_once_and_repeated(tmp_path, monkeypatch):
    (tmp_path / "s.xaml").write_text(WINDOW, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    drawn = _counted(monkeypatch)
    for out in ("f/", "still.gif", "still.webp"):
        r = CliRunner().invoke(main, ["animate", "s.xaml", "--window", "-o", out, "-j", "2"])
        assert r.exit_code == 0, r.output
        assert "ANIM015" in r.stderr
    assert len(drawn) == 3  # once for each file
    files = sorted((tmp_path / "f").iterdir())
    assert len(files) == 30 and len({f.read_bytes() for f in files}) == 1
    # the same bytes as each of the 30 frames drawn (in two worker processes)
    real = frames_module.render_frames

    def every_frame(*args, still=False, **kwargs):
        return real(*args, **kwargs)

    monkeypatch.setattr(frames_module, "render_frames", every_frame)
    for out in ("each.gif", "each.webp"):
        r = CliRunner().invoke(main, ["animate", "s.xaml", "--window", "-o", out, "-j", "2"])
        assert r.exit_code == 0, r.output
    assert (tmp_path / "each.gif").read_bytes() == (tmp_path / "still.gif").read_bytes()
    assert (tmp_path / "each.webp").read_bytes() == (tmp_path / "still.webp").read_bytes()


def test_a_scene_that_animates_is_drawn_frame_by_frame(tmp_path, monkeypatch):
    moving = WINDOW.replace(
        "<StackPanel>",
        '<Window.Triggers><EventTrigger RoutedEvent="Window.Loaded"><BeginStoryboard '
        'Storyboard="{StaticResource grow}"/></EventTrigger></Window.Triggers>\n<StackPanel>',
    )
    (tmp_path / "s.xaml").write_text(moving, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    drawn = _counted(monkeypatch)
    r = CliRunner().invoke(main, ["animate", "s.xaml", "--window", "-o", "f/", "-j", "1"])
    assert r.exit_code == 0, r.output
    assert "ANIM015" not in r.stderr and len(drawn) > 1
