"""glTF animation sampling (``export.gltf_animation``): each sample costs what the animated
values cost. Only the models and lights a track reaches are looked at per sample, the still
models are measured once for the camera's planes, and a moment whose values equal an earlier
one's is not evaluated again; the file is the one a sampler looking at everything writes."""

from __future__ import annotations

import numpy as np
import pytest

import xaml3d.scene.types as scene_types
from xaml3d.export import export_bytes, gltf_animation
from xaml3d.export import timeline as export_timeline
from xaml3d.pipeline import load

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)


def scene_text(count: int, animation: str) -> str:
    """``count`` quads in a row (the first one turned by ``Spin``), two lights (the second
    named ``Lamp``), a camera named ``Cam``; ``animation`` begun at load."""
    models = []
    for i in range(count):
        turn = (
            '<RotateTransform3D><RotateTransform3D.Rotation><AxisAngleRotation3D x:Name="Spin" '
            'Axis="0,1,0"/></RotateTransform3D.Rotation></RotateTransform3D>'
            if i == 0
            else ""
        )
        models.append(
            '<GeometryModel3D Geometry="{StaticResource g}" Material="{StaticResource m}">'
            f"<GeometryModel3D.Transform><Transform3DGroup>{turn}<TranslateTransform3D "
            f'OffsetX="{1.5 * i - count}"/></Transform3DGroup></GeometryModel3D.Transform>'
            "</GeometryModel3D>"
        )
    return (
        f'<Viewport3D {NS} Width="80" Height="60"><Viewport3D.Resources><MeshGeometry3D '
        'x:Key="g" Positions="0,0,0 1,0,0 1,1,0 0,1,0" TriangleIndices="0 1 2 0 2 3"/>'
        '<DiffuseMaterial x:Key="m" Brush="SteelBlue"/></Viewport3D.Resources>'
        '<Viewport3D.Camera><PerspectiveCamera x:Name="Cam" Position="0,0,60" '
        'LookDirection="0,0,-1" NearPlaneDistance="0"/></Viewport3D.Camera>'
        '<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="#404040"/>'
        '<PointLight x:Name="Lamp" Position="0,0,5"/>'
        f"{''.join(models)}</Model3DGroup></ModelVisual3D.Content></ModelVisual3D>"
        '<Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>'
        f"<Storyboard>{animation}</Storyboard></BeginStoryboard></EventTrigger>"
        "</Viewport3D.Triggers></Viewport3D>"
    )


SPIN = (
    '<DoubleAnimation Storyboard.TargetName="Spin" Storyboard.TargetProperty="Angle" From="0" '
    'To="90" Duration="0:0:2"/>'
)
CAMERA = (
    '<Point3DAnimation Storyboard.TargetName="Cam" Storyboard.TargetProperty="Position" '
    'From="0,0,60" To="5,2,40" Duration="0:0:2"/>'
)
LAMP = (
    '<Point3DAnimation Storyboard.TargetName="Lamp" Storyboard.TargetProperty="Position" '
    'From="0,0,5" To="3,0,5" Duration="0:0:2"/>'
)


def test_moving_names_the_models_and_lights_a_track_reaches():
    scene = load(scene_text(6, SPIN + LAMP + CAMERA), text=True)
    assert export_timeline.moving(scene, 0) == (frozenset({0}), frozenset({1}))
    still = load(scene_text(6, CAMERA), text=True)
    assert export_timeline.moving(still, 0) == (frozenset(), frozenset())


@pytest.mark.parametrize("animation", [SPIN, CAMERA, SPIN + CAMERA + LAMP],
                         ids=["transform", "camera", "all"])  # fmt: skip
def test_the_file_is_the_one_sampling_everything_writes(animation, monkeypatch):
    scene = load(scene_text(12, animation), text=True)
    files, diags = export_bytes(scene, "glb")
    assert "EXP010" in [d.code for d in diags]  # the animation is exported
    everything = (frozenset(range(12)), frozenset(range(2)))
    monkeypatch.setattr(export_timeline, "moving", lambda scene, vi: everything)
    again, diags_again = export_bytes(scene, "glb")
    assert again[""] == files[""]
    assert [d.message for d in diags_again] == [d.message for d in diags]


def test_the_camera_planes_measure_the_still_models_once(monkeypatch):
    # a near plane of 0 takes its place from the models' bounds at every camera sample: the
    # 40 still models are measured once, not at each of the 61 samples
    measured = []
    real = scene_types._shifted_bounds
    monkeypatch.setattr(scene_types, "_shifted_bounds",
                        lambda p, world: measured.append(1) or real(p, world))  # fmt: skip
    scene = load(scene_text(40, CAMERA + SPIN), text=True)
    measured.clear()
    export_bytes(scene, "glb")
    samples = 61  # 2 s at 30 per second, both ends
    assert 40 <= len(measured) < 3 * 40 + 2 * samples, len(measured)


def test_moments_with_equal_values_are_evaluated_once(monkeypatch):
    # the camera moves for 2 s, then holds its end for the 2 s its timeline lasts on: the 60
    # samples of the hold have the values of the end, and are its very viewport; a camera is
    # made once for all of them
    calls = []
    real = gltf_animation.gltf_camera
    monkeypatch.setattr(gltf_animation, "gltf_camera",
                        lambda vp, *a, **k: calls.append(vp) or real(vp, *a, **k))  # fmt: skip
    held = f'<ParallelTimeline Duration="0:0:4">{CAMERA}</ParallelTimeline>'
    scene = load(scene_text(3, held), text=True)
    times, frames = gltf_animation.sample(export_timeline.clip_of(scene), 0)
    assert len(times) == 121 and times[60] == 2.0
    assert all(f is frames[60] for f in frames[60:])
    assert len({id(f) for f in frames}) == 61
    np.testing.assert_array_equal(frames[-1].camera.position, [5.0, 2.0, 40.0])
    export_bytes(scene, "glb")
    assert len(calls) == 61
