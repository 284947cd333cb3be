"""Storyboard target typos: ANIM001 and ANIM002 name the closest name / property (the reader's
did-you-mean), and each points at the attribute that holds the typo (TargetName, TargetProperty:
the animation's own or the enclosing timeline's it inherits)."""

from __future__ import annotations

import json

from test_cli import NS, NSX
from test_cli_subprocess import xaml3d

SCENE = f"""<Viewport3D {NS} {NSX} Width="40" Height="30">
  <Viewport3D.Triggers>
    <EventTrigger RoutedEvent="Viewport3D.Loaded">
      <BeginStoryboard>
        <Storyboard>
          <DoubleAnimation Storyboard.TargetName="Spinn" Storyboard.TargetProperty="Angle" To="90"/>
          <DoubleAnimation Storyboard.TargetName="Bob"
                           Storyboard.TargetProperty="OfsetY" To="1"/>
          <ParallelTimeline Storyboard.TargetProperty="OffsetZZ">
            <DoubleAnimation Storyboard.TargetName="Bob" To="1"/>
          </ParallelTimeline>
          <DoubleAnimation Storyboard.TargetName="Nothing" Storyboard.TargetProperty="X" To="1"/>
        </Storyboard>
      </BeginStoryboard>
    </EventTrigger>
  </Viewport3D.Triggers>
  <ModelVisual3D>
    <ModelVisual3D.Transform>
      <Transform3DGroup>
        <RotateTransform3D><RotateTransform3D.Rotation>
          <AxisAngleRotation3D x:Name="Spin" Axis="0,1,0"/>
        </RotateTransform3D.Rotation></RotateTransform3D>
        <TranslateTransform3D x:Name="Bob"/>
      </Transform3DGroup>
    </ModelVisual3D.Transform>
  </ModelVisual3D>
</Viewport3D>
"""


def test_target_typos_say_did_you_mean_at_the_attribute(tmp_path):
    (tmp_path / "s.xaml").write_text(SCENE)
    p = xaml3d("validate", "s.xaml", "--format", "json", cwd=tmp_path)
    assert p.returncode == 1 and b"Traceback" not in p.stderr
    got = [(d["line"], d["column"], d["code"], d["message"]) for d in json.loads(p.stdout)
           if d["code"].startswith("ANIM")]  # fmt: skip
    assert got == [
        (6, 28, "ANIM001", "DoubleAnimation -> Spinn.Angle: Storyboard.TargetName 'Spinn' "
         "names no object (did you mean Spin?)"),
        (8, 28, "ANIM002", "DoubleAnimation -> Bob.OfsetY: TranslateTransform3D has no "
         "property 'OfsetY' (did you mean OffsetY?) (path 'OfsetY')"),
        # the path inherited from the ParallelTimeline: located where it is written
        (9, 29, "ANIM002", "DoubleAnimation -> Bob.OffsetZZ: TranslateTransform3D has no "
         "property 'OffsetZZ' (did you mean OffsetZ?) (path 'OffsetZZ')"),
        # nothing close: no suggestion
        (12, 28, "ANIM001", "DoubleAnimation -> Nothing.X: Storyboard.TargetName 'Nothing' "
         "names no object"),
    ]  # fmt: skip
