"""Findings that an option makes moot are not printed, in a real process: ``render --fit``
checks the camera it draws (the moved one), so the markup camera's CAM107 is gone;
``--storyboard NAME`` begins a keyed storyboard, so its ANIM007 ("no trigger begins it") is
gone, for ``render`` and ``animate`` alike, while the other storyboards keep theirs."""

from __future__ import annotations

from test_cli_subprocess import xaml3d

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)

# The camera stands in front of the triangle and looks away from it.
AWAY = f"""<Viewport3D {NS} Width="40" Height="30">
  <Viewport3D.Camera>
    <PerspectiveCamera Position="0,0,-5" LookDirection="0,0,-1"/>
  </Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material>
          <EmissiveMaterial Brush="Red"/>
        </GeometryModel3D.Material>
      </GeometryModel3D>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""

STORYBOARDS = f"""<Viewport3D {NS} Width="40" Height="30">
  <Viewport3D.Resources>
    <Storyboard x:Key="Spin">
      <DoubleAnimation Storyboard.TargetName="turn" Storyboard.TargetProperty="Angle" To="90"/>
    </Storyboard>
    <Storyboard x:Key="Other">
      <DoubleAnimation Storyboard.TargetName="turn" Storyboard.TargetProperty="Angle" To="45"/>
    </Storyboard>
  </Viewport3D.Resources>
  <Viewport3D.Camera>
    <PerspectiveCamera Position="0,0,5" LookDirection="0,0,-1"/>
  </Viewport3D.Camera>
  <ModelVisual3D>
    <ModelVisual3D.Content>
      <GeometryModel3D>
        <GeometryModel3D.Geometry>
          <MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0" TriangleIndices="0 1 2"/>
        </GeometryModel3D.Geometry>
        <GeometryModel3D.Material>
          <EmissiveMaterial Brush="Red"/>
        </GeometryModel3D.Material>
        <GeometryModel3D.Transform>
          <RotateTransform3D>
            <RotateTransform3D.Rotation>
              <AxisAngleRotation3D x:Name="turn" Axis="0,0,1" Angle="0"/>
            </RotateTransform3D.Rotation>
          </RotateTransform3D>
        </GeometryModel3D.Transform>
      </GeometryModel3D>
    </ModelVisual3D.Content>
  </ModelVisual3D>
</Viewport3D>
"""

CAM107 = (
    "s.xaml:3:5: warning CAM107 the scene's bounding box lies behind the camera (entirely at or "
    "behind the eye, along LookDirection): the image will be empty"
)


def _anim007(line: int, name: str) -> str:
    return (
        f"s.xaml:{line}:5: warning ANIM007 storyboard '{name}' is in resources but no trigger "
        "begins it (--storyboard starts it)"
    )


def test_fit_reports_the_camera_it_draws(tmp_path):
    (tmp_path / "s.xaml").write_text(AWAY)
    p = xaml3d("render", "s.xaml", "-o", "o.png", cwd=tmp_path)
    assert p.returncode == 0
    assert p.stderr.decode().splitlines() == [CAM107, "s.xaml: warning RND002 nothing was drawn "
                                              "in the image"]  # fmt: skip
    p = xaml3d("render", "s.xaml", "-o", "o.png", "--fit", cwd=tmp_path)
    assert p.returncode == 0 and p.stderr == b""
    # r = sqrt(2) * 1.05 (half the diagonal, with the margin) seen in the narrower half-angle
    # atan(tan(22.5 deg) / (40 / 30)): the camera stands r / sin(that) = 5.00524 from the centre
    p = xaml3d("render", "s.xaml", "-o", "o.png", "--fit", "-v", cwd=tmp_path)
    assert p.stderr.decode().splitlines() == [
        "s.xaml:1:1: info SCN003 Viewport3D #0 size 40 x 30 from its own Width/Height",
        "s.xaml:3:5: info FIT004 --fit moved the camera to Position = 0, 0, 5.00524",
    ]
    # validate checks the markup's camera: the warning stands there
    p = xaml3d("validate", "s.xaml", cwd=tmp_path)
    assert CAM107 in p.stdout.decode().splitlines()


def test_storyboard_option_silences_the_warning_of_the_one_it_begins(tmp_path):
    (tmp_path / "s.xaml").write_text(STORYBOARDS)
    both = [_anim007(3, "Spin"), _anim007(6, "Other")]
    p = xaml3d("render", "s.xaml", "-o", "o.png", cwd=tmp_path)
    assert p.returncode == 0 and p.stderr.decode().splitlines() == both
    p = xaml3d("render", "s.xaml", "-o", "o.png", "--storyboard", "Spin", cwd=tmp_path)
    assert p.returncode == 0 and p.stderr.decode().splitlines() == [_anim007(6, "Other")]
    args = ["--duration", "0.2", "--fps", "5"]
    p = xaml3d("animate", "s.xaml", "-o", "o.gif", *args, "--storyboard", "Other", cwd=tmp_path)
    assert p.returncode == 0 and p.stderr.decode().splitlines() == [_anim007(3, "Spin")]
