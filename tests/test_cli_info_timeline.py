"""``xaml3d info`` shows a storyboard's clock tree: a ParallelTimeline's repeat is printed on
the group, with the animations it repeats nested under it (their own timing says 1x)."""

from __future__ import annotations

import json

import pytest
from conftest import CORPUS
from test_cli import NS, NSX
from test_cli_subprocess import xaml3d

SCENE = f"""<Viewport3D {NS} {NSX} Width="40" Height="30">
  <Viewport3D.Triggers>
    <EventTrigger RoutedEvent="Viewport3D.Loaded">
      <BeginStoryboard>
        <Storyboard x:Name="spin" SpeedRatio="2">
          <ParallelTimeline RepeatBehavior="Forever" Storyboard.TargetName="rot"
                            Storyboard.TargetProperty="Angle">
            <DoubleAnimation From="0" To="360" Duration="0:0:30"/>
          </ParallelTimeline>
          <DoubleAnimation Storyboard.TargetName="rot" Storyboard.TargetProperty="Angle"
                           BeginTime="0:0:1" To="90" Duration="0:0:2" RepeatBehavior="3x"/>
        </Storyboard>
      </BeginStoryboard>
    </EventTrigger>
  </Viewport3D.Triggers>
  <ModelVisual3D>
    <ModelVisual3D.Transform>
      <RotateTransform3D><RotateTransform3D.Rotation>
        <AxisAngleRotation3D x:Name="rot" Axis="0,1,0"/>
      </RotateTransform3D.Rotation></RotateTransform3D>
    </ModelVisual3D.Transform>
  </ModelVisual3D>
</Viewport3D>
"""


def test_info_nests_the_animations_under_the_timeline_that_repeats_them(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    p = xaml3d("info", "s.xaml", cwd=tmp_path)
    assert p.returncode == 0, p.stderr.decode()
    lines = p.stdout.decode().splitlines()
    start = lines.index("  animations: 2 run at load (for ever)")
    assert lines[start + 1 : start + 5] == [
        "    storyboard 'spin': starts at load (begin 0 s, period Forever, repeat 1x)",
        "      ParallelTimeline: begin 0 s, period 30 s, repeat Forever",
        "        DoubleAnimation -> rot.Angle: begin 0 s, period 30 s, repeat 1x",
        "      DoubleAnimation -> rot.Angle: begin 1 s, period 2 s, repeat 3x",
    ]


def test_info_json_has_the_timeline_tree(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    p = xaml3d("info", "s.xaml", "--json", cwd=tmp_path)
    (sb,) = json.loads(p.stdout)["animations"]["storyboards"]
    tree = sb["timeline"]
    assert (tree["type"], tree["sets_timing"], tree["repeat"]) == ("Storyboard", True, 1.0)
    group, last = tree["children"]
    assert (group["type"], group["repeat"], group["period"]) == (
        "ParallelTimeline",
        "Forever",
        30.0,
    )
    (inner,) = group["children"]
    assert inner == sb["animations"][0] and inner["repeat"] == 1.0
    assert last == sb["animations"][1] and (last["begin"], last["repeat"]) == (1.0, 3.0)


@pytest.mark.skipif(not CORPUS.is_dir(), reason="the shared corpus is not present")
def test_info_on_the_corpus_cube_shows_the_forever_parallel_timeline():
    (path,) = CORPUS.glob("001_*.xaml")
    lines = xaml3d("info", path).stdout.decode().splitlines()
    i = lines.index("    storyboard 'RotateStoryboard': starts never (no trigger)")
    assert lines[i + 1 : i + 3] == [
        "      ParallelTimeline: begin 0 s, period 30 s, repeat Forever",
        "        DoubleAnimation -> myRotate.Angle: begin 0 s, period 30 s, repeat 1x",
    ]
