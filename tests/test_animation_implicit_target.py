"""Animations without Storyboard.TargetName: WPF's BeginStoryboard begins the storyboard with
the element that holds the trigger as the target, and the property path starts there
(``(Viewport3D.Camera).(PerspectiveCamera.FieldOfView)`` from a Viewport3D,
``(Window.Content)...`` from a Window). A storyboard no trigger begins has no such element:
ANIM005 as before.

The camera is a PerspectiveCamera of FieldOfView 30 animated to 60 over 2 s (linear: 30 + 15 t);
the first visual's translation OffsetX 1 animated from 0 to 4 over 2 s (2 t).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from test_cli_subprocess import xaml3d as run_xaml3d

import xaml3d

NS = ('xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
      'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"')  # fmt: skip

FOV = "(Viewport3D.Camera).(PerspectiveCamera.FieldOfView)"
OFFSET = "(Viewport3D.Children)[0].(ModelVisual3D.Transform).(TranslateTransform3D.OffsetX)"

VIEWPORT = """<Viewport3D {ns} {name} Width="64" Height="48">
  {resources}
  <Viewport3D.Camera><PerspectiveCamera x:Name="cam" Position="0,0,10" LookDirection="0,0,-1"
      FieldOfView="30"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="White"/>
    <GeometryModel3D><GeometryModel3D.Geometry><MeshGeometry3D
        Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0" TriangleIndices="0 1 2 0 2 3"/>
    </GeometryModel3D.Geometry>
    <GeometryModel3D.Material><DiffuseMaterial Brush="Lime"/></GeometryModel3D.Material>
    <GeometryModel3D.Transform><Transform3DGroup>
      <ScaleTransform3D ScaleX="2"/><TranslateTransform3D x:Name="shift" OffsetY="3"/>
    </Transform3DGroup></GeometryModel3D.Transform>
    </GeometryModel3D></Model3DGroup></ModelVisual3D.Content>
    <ModelVisual3D.Transform><TranslateTransform3D x:Name="move" OffsetX="1"/>
    </ModelVisual3D.Transform>
  </ModelVisual3D>
  {triggers}
</Viewport3D>"""


def anim(path: str, frm: float, to: float, name: str = "") -> str:
    target = f'Storyboard.TargetName="{name}" ' if name else ""
    return (f'<DoubleAnimation {target}Storyboard.TargetProperty="{path}" From="{frm}" '
            f'To="{to}" Duration="0:0:2"/>')  # fmt: skip


def loaded(owner: str, body: str, storyboard_attrs: str = "") -> str:
    return (f'<{owner}.Triggers><EventTrigger RoutedEvent="{owner}.Loaded"><BeginStoryboard>'
            f"<Storyboard {storyboard_attrs}>{body}</Storyboard></BeginStoryboard></EventTrigger>"
            f"</{owner}.Triggers>")  # fmt: skip


def viewport(triggers: str, resources: str = "", name: str = "", ns: str = NS) -> str:
    nm = f'x:Name="{name}"' if name else ""
    return VIEWPORT.format(ns=ns, name=nm, resources=resources, triggers=triggers)


def fov(s, t) -> float:
    return xaml3d.scene_at(s, t).viewport().camera.field_of_view


def offset_x(s, t) -> float:
    return float(xaml3d.scene_at(s, t).viewport().models[0].world[0, 3])


def anim_codes(s) -> list[str]:
    return [d.code for d in s.diagnostics if d.code.startswith(("ANIM", "ANI0"))]


def test_viewport3d_trigger_animates_its_camera_and_a_child_by_index():
    body = anim(FOV, 30, 60) + anim(OFFSET, 0, 4)
    s = xaml3d.load(viewport(loaded("Viewport3D", body)), text=True)
    assert anim_codes(s) == []
    assert s.storyboards[0].owner == "Viewport3D"
    assert [t.target for t in s.tracks.tracks] == [f"Viewport3D.{FOV}", f"Viewport3D.{OFFSET}"]
    assert [fov(s, t) for t in (0.0, 0.5, 1.0, 2.0, 5.0)] == [30.0, 37.5, 45.0, 60.0, 60.0]
    assert [offset_x(s, t) for t in (0.0, 0.5, 1.0, 2.0)] == [0.0, 1.0, 2.0, 4.0]
    assert fov(s, None) == 30.0 and offset_x(s, None) == 1.0  # the base values
    # the scale and OffsetY inside the model stay composed after the animated visual transform
    w = xaml3d.scene_at(s, 1.0).viewport().models[0].world
    assert w[0, 0] == 2.0 and w[1, 3] == 3.0


def test_implicit_target_draws_what_the_named_target_draws():
    implicit = xaml3d.load(viewport(loaded("Viewport3D", anim(FOV, 30, 60))), text=True)
    named = xaml3d.load(viewport(loaded("Viewport3D", anim("FieldOfView", 30, 60, "cam"))),
                        text=True)  # fmt: skip
    for t in (0.25, 1.5):
        a = xaml3d.render_arrays(implicit, time=t).rgba
        b = xaml3d.render_arrays(named, time=t).rgba
        assert np.array_equal(a, b)
    before = xaml3d.render_arrays(implicit, time=0.0).rgba
    assert not np.array_equal(before, xaml3d.render_arrays(implicit, time=2.0).rgba)


def test_a_named_viewport_labels_the_track_with_its_name():
    s = xaml3d.load(viewport(loaded("Viewport3D", anim(FOV, 30, 60)), name="view"), text=True)
    assert s.storyboards[0].owner == "view"
    assert [t.target for t in s.tracks.tracks] == [f"view.{FOV}"]


def test_a_target_name_on_the_storyboard_is_the_target_of_its_animations():
    body = anim("OffsetX", 0, 4)  # no TargetName of its own: the Storyboard's
    s = xaml3d.load(viewport(loaded("Viewport3D", body, 'Storyboard.TargetName="move"')),
                    text=True)  # fmt: skip
    assert anim_codes(s) == []
    assert [t.target for t in s.tracks.tracks] == ["move.OffsetX"]
    assert offset_x(s, 1.0) == 2.0


def test_a_window_trigger_path_starts_at_the_window():
    path = ("(Window.Content).(Grid.Children)[1].(Viewport3D.Children)[0]."
            "(ModelVisual3D.Transform).(TranslateTransform3D.OffsetX)")  # fmt: skip
    dotted = "Content.Children[1].Camera.FieldOfView"
    inner = viewport("", ns="").replace(' Width="64" Height="48"', "")
    doc = (f'<Window {NS} x:Name="main" Width="64" Height="48">'
           + loaded("Window", anim(path, 0, 4) + anim(dotted, 30, 60))
           + f"<Grid><Border/>{inner}</Grid></Window>")  # fmt: skip
    s = xaml3d.load(doc, text=True)
    assert anim_codes(s) == []
    assert [t.target for t in s.tracks.tracks] == [f"main.{path}", f"main.{dotted}"]
    assert offset_x(s, 0.5) == 1.0 and fov(s, 0.5) == 37.5


def test_a_resource_storyboard_begun_by_a_trigger_targets_the_trigger_holder():
    res = (f'<Viewport3D.Resources><Storyboard x:Key="zoom">{anim(FOV, 30, 60)}</Storyboard>'
           "</Viewport3D.Resources>")  # fmt: skip
    trig = ('<Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded">'
            '<BeginStoryboard Storyboard="{StaticResource zoom}"/></EventTrigger>'
            "</Viewport3D.Triggers>")  # fmt: skip
    s = xaml3d.load(viewport(trig, resources=res), text=True)
    assert anim_codes(s) == []
    assert fov(s, 1.0) == 45.0


def test_a_storyboard_no_trigger_begins_still_needs_a_target_name():
    res = (f'<Viewport3D.Resources><Storyboard x:Key="zoom">{anim(FOV, 30, 60)}</Storyboard>'
           "</Viewport3D.Resources>")  # fmt: skip
    s = xaml3d.load(viewport("", resources=res), text=True)
    (d,) = [d for d in s.diagnostics if d.code == "ANIM005"]
    assert d.severity == "error" and d.line is not None
    assert "no trigger begins its storyboard" in d.message
    assert s.timeline.at(1.0, "zoom").viewports[0].camera.field_of_view == 30.0


@pytest.mark.parametrize(
    ("path", "code"),
    [
        ("(Viewport3D.Camera).(PerspectiveCamera.Position)", "ANIM003"),
        ("(Viewport3D.Children)[3].(ModelVisual3D.Transform).(TranslateTransform3D.OffsetX)",
         "ANIM002"),
        ("(Viewport3D.Camera).(PerspectiveCamera.FieldOfVue)", "ANIM002"),
    ],
)  # fmt: skip
def test_a_path_that_does_not_resolve_from_the_holder_is_reported(path, code):
    s = xaml3d.load(viewport(loaded("Viewport3D", anim(path, 0, 1))), text=True)
    (d,) = [d for d in s.diagnostics if d.code.startswith("ANIM")]
    assert d.code == code and f"DoubleAnimation -> Viewport3D.{path}:" in d.message
    assert fov(s, 1.0) == 30.0


def test_validate_exit_codes(tmp_path):
    (tmp_path / "ok.xaml").write_text(viewport(loaded("Viewport3D", anim(FOV, 30, 60))))
    p = run_xaml3d("validate", "ok.xaml", cwd=tmp_path)
    assert p.returncode == 0, p.stdout.decode() + p.stderr.decode()
    assert b"ANIM" not in p.stdout + p.stderr
    res = (f'<Viewport3D.Resources><Storyboard x:Key="zoom">{anim(FOV, 30, 60)}</Storyboard>'
           "</Viewport3D.Resources>")  # fmt: skip
    (tmp_path / "coded.xaml").write_text(viewport("", resources=res))
    p = run_xaml3d("validate", "coded.xaml", cwd=tmp_path)
    assert p.returncode == 1
    assert b"error ANIM005" in p.stdout


@pytest.mark.parametrize(
    "ref", ["{x:Reference cam}", "{x:Reference Name=cam}", "{Binding ElementName=cam}"]
)
def test_storyboard_target_names_the_object(ref):
    body = (f'<DoubleAnimation Storyboard.Target="{ref}" Storyboard.TargetProperty="FieldOfView" '
            'From="30" To="60" Duration="0:0:2"/>')  # fmt: skip
    s = xaml3d.load(viewport(loaded("Viewport3D", body)), text=True)
    assert anim_codes(s) == []
    assert fov(s, 1.0) == 45.0


def test_an_inherited_storyboard_target_wins_over_a_target_name_below_it():
    # WPF's clock tree walk: the object the Storyboard targets stays the target of a child
    # that names another one
    body = anim("FieldOfView", 30, 60, name="move")
    s = xaml3d.load(viewport(loaded("Viewport3D", body, 'Storyboard.Target="{x:Reference cam}"')),
                    text=True)  # fmt: skip
    assert anim_codes(s) == []
    assert fov(s, 1.0) == 45.0


def test_a_storyboard_target_xaml3d_cannot_follow_is_not_evaluated():
    body = (
        '<DoubleAnimation Storyboard.Target="{Binding Camera, ElementName=view}" '
        'Storyboard.TargetProperty="FieldOfView" From="30" To="60" Duration="0:0:2"/>'
    )
    s = xaml3d.load(viewport(loaded("Viewport3D", body), name="view"), text=True)
    assert anim_codes(s) == ["ANI001"]
    assert fov(s, 1.0) == 30.0


def test_info_names_the_trigger_holder_as_the_target(tmp_path):
    (tmp_path / "s.xaml").write_text(viewport(loaded("Viewport3D", anim(FOV, 30, 60))))
    p = run_xaml3d("info", "s.xaml", "--json", cwd=tmp_path)
    assert p.returncode == 0, p.stderr.decode()
    (a,) = json.loads(p.stdout)["animations"]["storyboards"][0]["animations"]
    assert a["target"] == f"Viewport3D.{FOV}" and a["resolves"] is True


def test_the_holders_own_size_is_drawn_at_its_load_value():
    s = xaml3d.load(viewport(loaded("Viewport3D", anim("Width", 64, 128))), text=True)
    (d,) = [d for d in s.diagnostics if d.code.startswith("ANIM")]
    assert d.code == "ANIM014" and d.message.startswith("DoubleAnimation -> Viewport3D.Width:")
    assert xaml3d.render_arrays(s, time=1.0).width == 64


def test_a_storyboard_target_naming_nothing_is_located_at_the_attribute():
    body = ('<DoubleAnimation Storyboard.Target="{x:Reference nobody}" '
            'Storyboard.TargetProperty="FieldOfView" To="60"/>')  # fmt: skip
    doc = viewport(loaded("Viewport3D", body))
    s = xaml3d.load(doc, text=True)
    (d,) = [d for d in s.diagnostics if d.code.startswith("ANIM")]
    where = doc.splitlines()[d.line - 1].index('Storyboard.Target="') + 1
    assert d.code == "ANIM001" and d.line == 17 and d.column == where
