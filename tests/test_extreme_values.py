"""Extreme values through the Python API: a scene whose numbers reach 1e308 (or 1e-300, or
past single precision) loads, validates, renders in every mode and through the lens, and
exports, with no RuntimeWarning and no floating-point error (numpy raises on each here). What
WPF's single-precision renderer cannot draw is left out with a diagnostic (RND004, CAM008,
EXP017); nothing is hidden behind a numpy error state. Only an underflow to 0 (a 1e-300 cast
to single precision), which numpy ignores by default and which never changes a picture, is let
through."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from xaml3d.api import render_arrays
from xaml3d.errors import XamlError
from xaml3d.export import export_bytes
from xaml3d.findings import scene_findings
from xaml3d.pipeline import load

NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'
BASE = dict(POS="-1,-1,0 1,-1,0 0,1,0", TC="0,0 1,0 0,1", NRM="0,0,1 0,0,1 0,0,1", LP="0,0,3",
            LD="-1,-1,-1", RANGE="10", ATT="1", SCALE="1", OFF="0", SP="0,0", EP="1,1",
            RAD="0.5", CAMPOS="0,0,5", FOV="45", OPAC="1")  # fmt: skip
SCENE = """<Viewport3D {NS} Width="40" Height="30"><Viewport3D.Camera>
<PerspectiveCamera Position="{CAMPOS}" FieldOfView="{FOV}"/></Viewport3D.Camera>
<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight Color="#404040"/>
<DirectionalLight Direction="{LD}"/>
<PointLight Position="{LP}" Range="{RANGE}" ConstantAttenuation="{ATT}"
 QuadraticAttenuation="{ATT}"/>
<SpotLight Position="{LP}" Direction="{LD}" Range="{RANGE}"/>
<GeometryModel3D><GeometryModel3D.Transform><Transform3DGroup>
<ScaleTransform3D ScaleX="{SCALE}" ScaleY="{SCALE}" ScaleZ="{SCALE}"/>
<TranslateTransform3D OffsetX="{OFF}"/></Transform3DGroup></GeometryModel3D.Transform>
<GeometryModel3D.Geometry><MeshGeometry3D Positions="{POS}" TextureCoordinates="{TC}"
 Normals="{NRM}"/></GeometryModel3D.Geometry>
<GeometryModel3D.Material><MaterialGroup><DiffuseMaterial><DiffuseMaterial.Brush>
<LinearGradientBrush StartPoint="{SP}" EndPoint="{EP}" Opacity="{OPAC}"><GradientStop Color="Red"/>
<GradientStop Color="Blue" Offset="1"/></LinearGradientBrush></DiffuseMaterial.Brush>
</DiffuseMaterial><DiffuseMaterial><DiffuseMaterial.Brush><RadialGradientBrush RadiusX="{RAD}"
 RadiusY="{RAD}"><GradientStop Color="Red"/><GradientStop Color="Blue" Offset="1"/>
</RadialGradientBrush></DiffuseMaterial.Brush></DiffuseMaterial>
<SpecularMaterial Brush="White" SpecularPower="40"/><EmissiveMaterial Brush="#202020"/>
</MaterialGroup></GeometryModel3D.Material></GeometryModel3D></Model3DGroup>
</ModelVisual3D.Content></ModelVisual3D></Viewport3D>"""
SIZES = {"POS": 3, "NRM": 3, "TC": 2, "LP": 3, "LD": 3, "CAMPOS": 3, "SP": 2, "EP": 2}
CASES = [(k, v) for k in BASE for v in ("1e308", "-1e308", "1e200", "3e38", "1e-300")]


def scene_with(key: str, value: str) -> str:
    values = dict(BASE)
    n = SIZES.get(key, 0)
    if key in ("POS", "NRM", "TC"):  # the first vertex's components
        values[key] = " ".join([",".join([value] * n), *values[key].split()[1:]])
    else:
        values[key] = ",".join([value] * n) if n else value
    return SCENE.format(NS=NS, **values)


@pytest.mark.parametrize("key, value", CASES, ids=[f"{k}={v}" for k, v in CASES])
def test_extreme_value_runs_clean(key, value):
    with warnings.catch_warnings(), np.errstate(under="ignore"):
        warnings.simplefilter("error")
        scene = load(scene_with(key, value), text=True)
        assert all(d.code for d in scene_findings(scene))
        for kwargs in ({}, {"mode": "flat"}, {"mode": "wireframe"},
                       {"aperture": 0.1, "lens_samples": 3}):  # fmt: skip
            try:
                render_arrays(scene, ssaa=1, **kwargs)
            except XamlError:
                pass  # a camera WPF cannot draw with (CAM008): a clean error
        try:
            export_bytes(scene, "glb")
        except XamlError:
            pass  # a camera that cannot be built (FieldOfView 1e-300): a clean error


def test_positions_past_single_precision_are_reported_not_drawn():
    # the triangle: RND004 in the render, EXP017 in the export, no numpy error
    scene = load(scene_with("POS", "1e308").replace(
        'Positions="1e308,1e308,1e308', 'Positions="-1e308,-1,0 1e308,-1,0 1,1e308,0'
    ), text=True)  # fmt: skip
    r = render_arrays(scene, ssaa=1)
    assert [d.code for d in r.diagnostics][:1] == ["RND004"]
    assert "beyond single precision" in r.diagnostics[0].message
    _, diags = export_bytes(scene, "glb")
    assert "EXP017" in [d.code for d in diags]


def test_a_transform_that_overflows_leaves_its_model_out():
    # a QuaternionRotation3D of 1e308 gives a matrix that is not finite (found by fuzzing): the
    # scene loads, and the model is left out where it is drawn (RND004), no numpy error
    quaternion = (
        "<RotateTransform3D><RotateTransform3D.Rotation>"
        '<QuaternionRotation3D Quaternion="1e308,0,0,1"/>'
        "</RotateTransform3D.Rotation></RotateTransform3D>"
    )
    xml = scene_with("SCALE", "1").replace('<TranslateTransform3D OffsetX="0"/>', quaternion)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scene = load(xml, text=True)
        assert all(d.code for d in scene_findings(scene))
        r = render_arrays(scene, ssaa=1)
    assert "RND004" in [d.code for d in r.diagnostics]
