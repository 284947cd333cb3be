"""The Scene at time t: targets resolved from markup, values applied, frames, the CLI.

Scenes use the standard orthographic frame (64x48, 1 world unit = 1 pixel) where pixels are
checked.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest
from PIL import Image

import xaml3d
from xaml3d.output.animation import frame_durations
from xaml3d.render.frames import frame_times

NS = ('xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
      'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"')  # fmt: skip


def scene(storyboard: str, extra_triggers: str = "", resources: str = "") -> str:
    return f"""<Viewport3D {NS} Width="64" Height="48">
  {resources}
  <Viewport3D.Camera><OrthographicCamera x:Name="cam" Position="0,0,10" LookDirection="0,0,-1"
      Width="64"/></Viewport3D.Camera>
  <ModelVisual3D x:Name="visual"><ModelVisual3D.Content><Model3DGroup x:Name="group">
    <AmbientLight x:Name="amb" Color="White"/>
    <GeometryModel3D x:Name="quad">
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="-8,-8,0 8,-8,0 8,8,0 -8,8,0"
          TriangleIndices="0 1 2 0 2 3"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/></GeometryModel3D.Material>
      <GeometryModel3D.Transform><Transform3DGroup>
        <TranslateTransform3D x:Name="move" OffsetX="4"/>
        <RotateTransform3D><RotateTransform3D.Rotation>
          <AxisAngleRotation3D x:Name="rot" Axis="0,0,1" Angle="0"/>
        </RotateTransform3D.Rotation></RotateTransform3D>
      </Transform3DGroup></GeometryModel3D.Transform>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  <Viewport3D.Triggers>
    <EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard><Storyboard>
      {storyboard}
    </Storyboard></BeginStoryboard></EventTrigger>
    {extra_triggers}
  </Viewport3D.Triggers>
</Viewport3D>"""


def offset_x(s, t):
    return s.timeline.at(t).viewports[0].models[0].world[0, 3]


def codes(s):
    return [d.code for d in s.diagnostics]


def test_first_frame_is_wpfs_and_time_none_the_base_value():
    s = xaml3d.load(scene('<DoubleAnimation Storyboard.TargetName="move" '
                          'Storyboard.TargetProperty="OffsetX" From="-10" To="10" '
                          'Duration="0:0:2"/>'), text=True)  # fmt: skip
    assert s.viewports[0].models[0].world[0, 3] == 4.0  # the loaded scene keeps the base value
    assert offset_x(s, 0.0) == -10.0  # WPF's first frame shows From
    assert offset_x(s, 1.5) == 5.0
    assert xaml3d.scene_at(s, None) is s
    assert xaml3d.scene_at(s, 1.0).viewports[0].models[0].world[0, 3] == 0.0
    # render: default time 0, time=None for the base value (the quad's left edge at -18 / -8+4)
    left = lambda img: int(np.nonzero(np.array(img)[24, :, 3])[0][0])  # noqa: E731
    assert left(xaml3d.render(s)) == 32 - 18
    assert left(xaml3d.render(s, time=None)) == 32 - 4
    assert s.timeline.cycle() == 2.0


@pytest.mark.parametrize(
    "path",
    [
        "(ModelVisual3D.Content).(Model3DGroup.Children)[1].(GeometryModel3D.Transform)"
        ".(Transform3DGroup.Children)[0].(TranslateTransform3D.OffsetX)",
        "Content.Children[1].Transform.Children[0].OffsetX",
    ],
)
def test_property_paths_with_indexers(path):
    anim = (f'<DoubleAnimation Storyboard.TargetName="visual" Storyboard.TargetProperty="{path}" '
            'To="14" Duration="0:0:1"/>')  # fmt: skip
    s = xaml3d.load(scene(anim), text=True)
    assert not [c for c in codes(s) if c.startswith("ANIM")]
    assert offset_x(s, 0.5) == 9.0  # base 4 -> 14


def test_rotation_and_camera_and_light_targets():
    anims = """
      <DoubleAnimation Storyboard.TargetName="rot" Storyboard.TargetProperty="Angle"
                       From="0" To="90" Duration="0:0:1"/>
      <Point3DAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="Position"
                        To="0,0,20" Duration="0:0:1"/>
      <ColorAnimation Storyboard.TargetName="amb" Storyboard.TargetProperty="Color"
                      To="Black" Duration="0:0:1"/>"""
    s = xaml3d.load(scene(anims), text=True)
    f = s.timeline.at(0.5)
    vp = f.viewports[0]
    # 45 degrees about z after the translation: the world x axis turns into (c, s)
    c = math.sqrt(0.5)
    assert np.allclose(vp.models[0].world[:2, :2], [[c, -c], [c, c]])
    assert vp.camera.position == (0.0, 0.0, 15.0)
    assert vp.lights[0].color[3] == 1.0 and vp.lights[0].color[0] < 0.75


def test_rotation3d_animation_slerps():
    anim = """<Rotation3DAnimation Storyboard.TargetName="visual"
        Storyboard.TargetProperty="Content.Children[1].Transform.Children[1].Rotation"
        Duration="0:0:1"><Rotation3DAnimation.To>
        <AxisAngleRotation3D Axis="0,0,1" Angle="90"/></Rotation3DAnimation.To>
      </Rotation3DAnimation>"""
    s = xaml3d.load(scene(anim), text=True)
    assert not [c for c in codes(s) if c.startswith("ANIM")]
    w = s.timeline.at(0.5).viewports[0].models[0].world
    c = math.sqrt(0.5)
    assert np.allclose(w[:2, :2], [[c, -c], [c, c]])  # 45 degrees


def test_later_storyboard_replaces_and_named_storyboard_starts():
    first = ('<DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX" '
             'To="10" Duration="0:0:1"/>')  # fmt: skip
    click = """<EventTrigger RoutedEvent="Button.Click"><BeginStoryboard><Storyboard
        x:Name="onclick"><DoubleAnimation Storyboard.TargetName="move"
        Storyboard.TargetProperty="OffsetX" To="-20" Duration="0:0:1"/></Storyboard>
        </BeginStoryboard></EventTrigger>"""
    s = xaml3d.load(scene(first, click), text=True)
    assert offset_x(s, 0.5) == 7.0  # only the Loaded storyboard runs: 4 -> 10
    f = s.timeline.at(0.5, "onclick")  # begun after it: it replaces the animation: 4 -> -20
    assert f.viewports[0].models[0].world[0, 3] == -8.0
    with pytest.raises(xaml3d.XamlError) as exc:
        s.timeline.at(0.5, "nope")
    assert exc.value.code == "ANIM010"


def test_two_animations_of_one_storyboard_compose():
    anims = """
      <DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX"
                       To="10" Duration="0:0:1"/>
      <DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX"
                       By="1" Duration="0:0:1"/>"""
    s = xaml3d.load(scene(anims), text=True)
    assert offset_x(s, 1.0) == 11.0  # the second builds on the first's output (By: + 1)


@pytest.mark.parametrize(
    ("anim", "code"),
    [
        ('Storyboard.TargetName="nobody" Storyboard.TargetProperty="OffsetX"', "ANIM001"),
        ('Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetW"', "ANIM002"),
        ('Storyboard.TargetName="visual" Storyboard.TargetProperty="Content.Children[5].Transform"',
         "ANIM002"),
        ('Storyboard.TargetName="cam" Storyboard.TargetProperty="Position"', "ANIM003"),
        ('Storyboard.TargetName="quad" Storyboard.TargetProperty="(GeometryModel3D.Material).'
         '(DiffuseMaterial.Brush).(Brush.RelativeTransform).(ScaleTransform.ScaleX)"',
         "ANIM004"),
        ('Storyboard.TargetName="move"', "ANIM005"),
    ],
)  # fmt: skip
def test_unresolvable_targets_are_reported(anim, code):
    s = xaml3d.load(scene(f'<DoubleAnimation {anim} To="1"/>'), text=True)
    d = next(d for d in s.diagnostics if d.code.startswith("ANIM"))
    assert d.code == code and d.severity == "error" and d.line is not None
    assert s.timeline.running_animations() == []
    assert xaml3d.render(s, time=0.5) is not None  # the frame keeps the base value


def test_days_warning_and_storyboard_that_never_starts():
    res = ("<Viewport3D.Resources><Storyboard x:Key='later'><DoubleAnimation "
           "Storyboard.TargetName='move' Storyboard.TargetProperty='OffsetX' To='1'/>"
           "</Storyboard></Viewport3D.Resources>")  # fmt: skip
    anim = ('<DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX" '
            'To="1" Duration="5" BeginTime="{x:Null}"/>')  # fmt: skip
    s = xaml3d.load(scene(anim, resources=res), text=True)
    got = codes(s)
    assert "ANIM006" in got and "ANIM007" in got and "ANIM008" in got
    assert next(d for d in s.diagnostics if d.code == "ANIM006").column is not None


def test_easing_and_key_frames_read_from_markup():
    anim = """<DoubleAnimationUsingKeyFrames Storyboard.TargetName="move"
        Storyboard.TargetProperty="OffsetX">
        <EasingDoubleKeyFrame KeyTime="0:0:2" Value="8">
          <EasingDoubleKeyFrame.EasingFunction><QuadraticEase EasingMode="EaseIn"/>
          </EasingDoubleKeyFrame.EasingFunction></EasingDoubleKeyFrame>
      </DoubleAnimationUsingKeyFrames>
      <DoubleAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="Width" To="80"
          Duration="0:0:2"><DoubleAnimation.EasingFunction><PowerEase Power="3"
          EasingMode="EaseIn"/></DoubleAnimation.EasingFunction></DoubleAnimation>"""
    s = xaml3d.load(scene(anim), text=True)
    a1, a2 = s.storyboards[0].animations
    assert a2.easing.kind == "Power" and a2.easing.params == (("Power", 3.0),)
    # offset: 4 + (8 - 4) * 0.5^2 = 5 at t = 1; camera width 64 + 16 * 0.5^3 = 66
    assert offset_x(s, 1.0) == 5.0
    assert s.timeline.at(1.0).viewports[0].camera.width == 66.0


def test_frame_times_and_durations():
    assert frame_times(0.0, 1.0, 4) == [0.0, 0.25, 0.5, 0.75]
    assert frame_times(1.0, 1.1, 30) == [1.0, 1.0 + 1 / 30, 1.0 + 2 / 30]
    # 30 fps in GIF's 10 ms units: 3, 4, 3 ... summing to exactly 100 units per second
    d = frame_durations(30, 1.0, 0.01)
    assert sum(d) == 100 and set(d) == {3, 4}
    assert sum(frame_durations(7, 2.0, 0.001)) == 2000


def _cli(*args, cwd=None):
    """The command as a real process (formats, no traceback, exit codes)."""
    return subprocess.run([sys.executable, "-m", "xaml3d", *map(str, args)], capture_output=True,
                          cwd=cwd, timeout=120)  # fmt: skip


class _Run:
    def __init__(self, result) -> None:
        self.returncode = result.exit_code
        self.stderr = result.stderr_bytes
        self.stdout = result.stdout_bytes


def _run(*args, cwd):
    """The command in this process (click's runner): quicker for many small checks."""
    import os

    from click.testing import CliRunner

    from xaml3d.cli import main

    old = os.getcwd()
    os.chdir(cwd)
    try:
        return _Run(CliRunner().invoke(main, [str(a) for a in args]))
    finally:
        os.chdir(old)


ANIM = ('<DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX" '
        'From="-16" To="16" Duration="0:0:1" RepeatBehavior="Forever"/>')  # fmt: skip


@pytest.mark.parametrize("suffix", [".gif", ".png", ".webp"])
def test_cli_animate_formats(tmp_path, suffix):
    (tmp_path / "s.xaml").write_text(scene(ANIM))
    p = _cli("animate", "s.xaml", "-o", f"out{suffix}", "--fps", "10", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert b"Traceback" not in p.stderr
    with Image.open(tmp_path / f"out{suffix}") as im:
        assert im.n_frames == 10 and im.size == (64, 48)
        if suffix == ".webp":
            return  # Pillow does not read WebP frame durations back
        total = 0
        for i in range(im.n_frames):
            im.seek(i)
            total += im.info["duration"]
        assert total == 1000  # one iteration of the Forever repeat: one second
    assert not [f for f in tmp_path.iterdir() if f.name.startswith(".")]  # no temporary left


def test_cli_animate_gif_transparency_and_frames_dir(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(ANIM))
    p = _cli("animate", "s.xaml", "-o", "a.gif", "--end", "0.5", "--fps", "4", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    with Image.open(tmp_path / "a.gif") as im:
        assert im.info.get("transparency") == 255
        first = np.array(im.convert("RGBA"))
        # t = 0: offset -16, the quad spans x -24..-8: cols 8..23
        assert first[0, 0, 3] == 0 and tuple(first[24, 16]) == (0, 255, 0, 255)
    p = _cli("animate", "s.xaml", "-o", "frames/", "--start", "0:0:0.5", "--duration", "0.5",
             "--fps", "4", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    names = sorted(f.name for f in (tmp_path / "frames").iterdir())
    assert names == ["frame_0000.png", "frame_0001.png"]
    # t = 0.5: offset 0, the 16-px quad centred: cols 24..39
    a = np.array(Image.open(tmp_path / "frames" / "frame_0000.png"))
    assert list(np.nonzero(a[24, :, 3])[0][[0, -1]]) == [24, 39]


def test_cli_animate_errors(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(ANIM))
    p = _run("animate", "s.xaml", "-o", "a.gif", "--storyboard", "nope", cwd=tmp_path)
    assert p.returncode == 1 and b"error ANIM010" in p.stderr and b"Traceback" not in p.stderr
    assert not (tmp_path / "a.gif").exists()
    p = _run("animate", "s.xaml", "-o", "a.bmp", cwd=tmp_path)
    assert p.returncode == 2 and b"cannot tell the animation format" in p.stderr  # as render
    (tmp_path / "s.png").write_text(scene(ANIM))  # a scene whose name looks like an APNG
    p = _run("animate", "s.png", "-o", "s.png", cwd=tmp_path)
    assert p.returncode == 1 and b"IO002" in p.stderr
    p = _run("animate", "s.xaml", "-o", "a.gif", "--start", "2", "--end", "1", cwd=tmp_path)
    assert p.returncode == 2


def test_cli_render_time(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(ANIM))
    cols = {}
    for t in ("0", "0:0:0.25", "none"):
        p = _run("render", "s.xaml", "-o", "r.png", "--time", t, cwd=tmp_path)
        assert p.returncode == 0, p.stderr
        a = np.array(Image.open(tmp_path / "r.png"))
        cols[t] = int(np.nonzero(a[24, :, 3])[0][0])
    # From -16 at t=0: left edge at -24; t=0.25: -8 -> -16; base OffsetX 4: -4
    assert cols == {"0": 8, "0:0:0.25": 16, "none": 28}
    p = _run("render", "s.xaml", "-o", "r.png", "--time", "soon", cwd=tmp_path)
    assert p.returncode == 2 and b"--time" in p.stderr


def test_cli_info_lists_animations(tmp_path):
    (tmp_path / "s.xaml").write_text(scene(ANIM))
    p = _run("info", "s.xaml", cwd=tmp_path)
    out = p.stdout.decode()
    assert "animations: 1 run at load (for ever)" in out
    assert "DoubleAnimation -> move.OffsetX: begin 0 s, period 1 s, repeat Forever" in out


def test_cli_validate_reports_animation_targets(tmp_path):
    bad = ('<DoubleAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="Position" '
           'To="1" Duration="5"/>')  # fmt: skip
    (tmp_path / "s.xaml").write_text(scene(bad))
    p = _run("validate", "s.xaml", cwd=tmp_path)
    err = p.stderr.decode() + p.stdout.decode()
    assert p.returncode == 1
    assert "error ANIM003 DoubleAnimation -> cam.Position" in err
    assert "warning ANIM006 DoubleAnimation.Duration='5' is 5 day(s)" in err


def test_a_frame_is_a_finished_moment():
    s = xaml3d.load(scene(ANIM), text=True)
    f = xaml3d.scene_at(s, 0.25)
    assert f.timeline is None and f.diagnostics == s.diagnostics
    assert f.viewports[0].models[0].world[0, 3] == -8.0
    # rendering the frame at the default time keeps it (no second evaluation at t = 0)
    left = int(np.nonzero(np.array(xaml3d.render(f))[24, :, 3])[0][0])
    assert left == 32 - 16


def test_brush_made_from_a_string_animates_its_color_and_opacity():
    # WPF's storyboard animates a copy of the frozen brush Brush="Lime" makes
    anims = """
      <ColorAnimation Storyboard.TargetName="quad" To="Blue" Duration="0:0:1"
        Storyboard.TargetProperty="(GeometryModel3D.Material).(DiffuseMaterial.Brush).(SolidColorBrush.Color)"/>
      <DoubleAnimation Storyboard.TargetName="quad" To="0" Duration="0:0:1"
        Storyboard.TargetProperty="Material.Brush.Opacity"/>"""
    s = xaml3d.load(scene(anims), text=True)
    assert not [c for c in codes(s) if c.startswith("ANIM")]
    brush = s.timeline.at(1.0).viewports[0].models[0].material[0].brush
    assert brush.color == (0.0, 0.0, 1.0, 1.0) and brush.opacity == 0.0
    assert s.viewports[0].models[0].material[0].brush.color == (0.0, 1.0, 0.0, 1.0)


def test_loop_counts_are_plays(tmp_path):
    frames = [np.full((4, 4, 4), (40 * i, 0, 0, 255), np.uint8) for i in range(3)]
    for loop, gif_count in ((0, 0), (1, None), (3, 2)):  # GIF counts repeats after the first
        xaml3d.save_animation(frames, tmp_path / "l.gif", 0.3, loop=loop)
        xaml3d.save_animation(frames, tmp_path / "l.png", 0.3, loop=loop)
        with Image.open(tmp_path / "l.gif") as g, Image.open(tmp_path / "l.png") as p:
            assert g.info.get("loop") == gif_count and p.info.get("loop") == loop


def test_handoff_compose_builds_on_the_earlier_storyboard():
    first = ('<DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX" '
             'To="10" Duration="0:0:1"/>')  # fmt: skip
    second = """<EventTrigger RoutedEvent="FrameworkElement.Loaded"><BeginStoryboard
        HandoffBehavior="Compose"><Storyboard><DoubleAnimation Storyboard.TargetName="move"
        Storyboard.TargetProperty="OffsetX" By="2" Duration="0:0:1"/></Storyboard>
        </BeginStoryboard></EventTrigger>"""
    s = xaml3d.load(scene(first, second), text=True)
    assert s.storyboards[1].handoff == "Compose"
    assert offset_x(s, 1.0) == 12.0  # 10 from the first, + 2 on top
    replaced = xaml3d.load(scene(first, second.replace("Compose", "SnapshotAndReplace")),
                           text=True)  # fmt: skip
    assert offset_x(replaced, 1.0) == 6.0  # only the second: base 4 + 2


def test_camera_and_validate_see_wpfs_first_frame(tmp_path):
    """`camera` shows the camera at --time (default the first frame), and `validate` checks the
    first frame, as `render` draws and checks it."""
    dolly = ('<Point3DAnimation Storyboard.TargetName="cam" Storyboard.TargetProperty="Position" '
             'From="0,0,-10" To="0,0,10" Duration="0:0:2"/>')  # fmt: skip
    (tmp_path / "s.xaml").write_text(scene(dolly))
    positions = {}
    for t in ("0", "1", "none"):
        p = _run("camera", "s.xaml", "--json", "--time", t, cwd=tmp_path)
        assert p.returncode == 0, p.stderr
        positions[t] = json.loads(p.stdout)["camera"]["properties"]["Position"]["value"]
    assert positions == {"0": [0, 0, -10], "1": [0, 0, 0], "none": [0, 0, 10]}
    # at t = 0 the camera stands behind the quad, looking away from it: render and validate
    # report the same findings about that first frame
    v = _run("validate", "s.xaml", cwd=tmp_path)
    r = _run("render", "s.xaml", "-o", "r.png", "-v", cwd=tmp_path)
    found = [ln for ln in v.stdout.decode().splitlines() if " CHK" in ln or " CAM" in ln]
    assert found and all(ln in r.stderr.decode() for ln in found)


def test_storyboard_option_accepts_the_storyboards_own_name(tmp_path):
    # --storyboard takes the BeginStoryboard's x:Name or the Storyboard's own
    first = ('<DoubleAnimation Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX" '
             'To="10" Duration="0:0:1"/>')  # fmt: skip
    click = """<EventTrigger RoutedEvent="Button.Click"><BeginStoryboard x:Name="begin"><Storyboard
        x:Name="story"><DoubleAnimation Storyboard.TargetName="move"
        Storyboard.TargetProperty="OffsetX" To="-20" Duration="0:0:1"/></Storyboard>
        </BeginStoryboard></EventTrigger>"""
    s = xaml3d.load(scene(first, click), text=True)
    for name in ("begin", "story"):
        assert s.timeline.at(0.5, name).viewports[0].models[0].world[0, 3] == -8.0
    (tmp_path / "s.xaml").write_text(scene(first, click))
    for name in ("begin", "story"):
        p = _run("render", "s.xaml", "-o", f"{name}.png", "--storyboard", name, "--time", "0.5",
                 cwd=tmp_path)  # fmt: skip
        assert p.returncode == 0, p.stderr
    a, b = (np.array(Image.open(tmp_path / f"{n}.png")) for n in ("begin", "story"))
    assert np.array_equal(a, b)
    p = _cli("render", "s.xaml", "-o", "x.png", "--storyboard", "nope", cwd=tmp_path)
    assert p.returncode == 1 and not (tmp_path / "x.png").exists()
    assert p.stderr.decode() == (
        "s.xaml: error ANIM010 no storyboard named 'nope': the storyboards are named: "
        "'begin', 'story'\n"
    )


def test_anim001_points_at_the_target_name_attribute_and_storyboard_passes_it_on(tmp_path):
    text = f"""<Viewport3D {NS} Width="64" Height="48">
  <ModelVisual3D><ModelVisual3D.Transform><TranslateTransform3D x:Name="move"/>
  </ModelVisual3D.Transform></ModelVisual3D>
  <Viewport3D.Triggers>
    <EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard><Storyboard>
      <DoubleAnimation Storyboard.TargetProperty="OffsetX"
          Storyboard.TargetName="rot" To="10"/>
    </Storyboard></BeginStoryboard></EventTrigger>
    <EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
      <Storyboard Storyboard.TargetName="gone"><DoubleAnimation
          Storyboard.TargetProperty="OffsetX" To="10"/></Storyboard></BeginStoryboard>
    </EventTrigger>
    <EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
      <Storyboard Storyboard.TargetName="move" Storyboard.TargetProperty="OffsetX">
        <DoubleAnimation To="10" Duration="0:0:1"/></Storyboard></BeginStoryboard>
    </EventTrigger>
  </Viewport3D.Triggers>
</Viewport3D>"""
    (tmp_path / "s.xaml").write_text(text)
    p = _cli("validate", "s.xaml", cwd=tmp_path)
    errors = [ln for ln in p.stdout.decode().splitlines() if " error " in ln]
    # WPF's Storyboard.TargetName is attached: written on the Storyboard, its animations
    # inherit it (no XAML004); ANIM001 is at the attribute that names the missing object
    assert p.returncode == 1 and errors == [
        "s.xaml:7:11: error ANIM001 DoubleAnimation -> rot.OffsetX: Storyboard.TargetName 'rot' "
        "names no object",
        "s.xaml:10:19: error ANIM001 DoubleAnimation -> gone.OffsetX: Storyboard.TargetName "
        "'gone' names no object",
    ]
    s = xaml3d.load(text, text=True)
    third = s.storyboards[2].animations[0]
    assert (third.target_name, third.target_property) == ("move", "OffsetX")
    assert s.timeline.targets[id(third)] is not None


def test_time_option_forms():
    import click

    from xaml3d.cli_animate import parse_time

    assert [parse_time(v) for v in ("1.5", "1.5s", "5s", "0:0:1.5", "0:1", "none")] == [
        1.5, 1.5, 5.0, 1.5, 60.0, None
    ]  # fmt: skip
    for bad in ("5ss", "-1", "1.5m", "s"):
        with pytest.raises(click.BadParameter):
            parse_time(bad)
