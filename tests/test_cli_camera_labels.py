"""``xaml3d camera`` labels the world -> pixel product with the matrices the camera really
multiplies (camera-pipeline.md sections 4-6, camera-math.md section 11): Mwind Mpp Mper for a
PerspectiveCamera, Mwind Morth for an OrthographicCamera, WPF's own matrices for a MatrixCamera,
inverse(Camera.Transform) last when the camera has a transform."""

from __future__ import annotations

import json

import numpy as np
import pytest
from test_cli import NS
from test_cli_subprocess import xaml3d

from xaml3d.scene.camera_math import world_to_pixel_factors

CAMERAS = {
    "perspective": '<PerspectiveCamera Position="0,0,5" FieldOfView="60"/>',
    "orthographic": '<OrthographicCamera Position="0,0,5" Width="4"/>',
    "matrix": '<MatrixCamera ViewMatrix="1,0,0,0 0,1,0,0 0,0,1,0 0,0,-5,1" '
    'ProjectionMatrix="2,0,0,0 0,2,0,0 0,0,-1,-1 0,0,-1,0"/>',
    "moved": '<OrthographicCamera Position="0,0,5" Width="4">'
    '<OrthographicCamera.Transform><TranslateTransform3D OffsetX="1"/>'
    "</OrthographicCamera.Transform></OrthographicCamera>",
}
LABELS = {
    "perspective": "Mwind Mpp Mper (divide by w)",
    "orthographic": "Mwind Morth (w = 1: nothing to divide)",
    "matrix": "Mwind diag(1,1,-1,1) ProjectionMatrix^T ViewMatrix^T (divide by w)",
    "moved": "Mwind Morth inverse(Camera.Transform) (w = 1: nothing to divide)",
}


def scene(camera: str) -> str:
    return (f'<Viewport3D {NS} Width="40" Height="30">\n'
            f"  <Viewport3D.Camera>{camera}</Viewport3D.Camera>\n</Viewport3D>\n")  # fmt: skip


@pytest.mark.parametrize("kind", CAMERAS)
def test_camera_labels_the_product_with_the_cameras_own_matrices(kind, tmp_path):
    (tmp_path / "s.xaml").write_text(scene(CAMERAS[kind]))
    p = xaml3d("camera", "s.xaml", cwd=tmp_path)
    assert p.returncode == 0, p.stderr.decode()
    (line,) = [ln for ln in p.stdout.decode().splitlines() if "world -> pixel" in ln]
    assert line == f"  world -> pixel (column vectors): {LABELS[kind]}:"
    j = json.loads(xaml3d("camera", "s.xaml", "--json", cwd=tmp_path).stdout)["pipeline"]
    assert j["world_to_pixel_factors"] == LABELS[kind].split(" (")[0]


def test_the_labelled_factors_multiply_to_the_product(tmp_path):
    # the label is the truth: its matrices, multiplied, give world_to_pixel
    def pipeline(kind):
        (tmp_path / f"{kind}.xaml").write_text(scene(CAMERAS[kind]))
        out = xaml3d("camera", f"{kind}.xaml", "--json", cwd=tmp_path).stdout
        return {k: np.array(v, dtype=float) if isinstance(v, list) else v
                for k, v in json.loads(out)["pipeline"].items()}  # fmt: skip

    wind4 = np.array([[20, 0, 0, 20], [0, -15, 0, 15], [0, 0, 1, 0], [0, 0, 0, 1]], float)
    p = pipeline("perspective")
    np.testing.assert_allclose(wind4 @ p["m_pp"] @ p["m_per"], p["world_to_pixel"], atol=1e-12)
    o = pipeline("orthographic")
    np.testing.assert_allclose(wind4 @ o["m_ortho"], o["world_to_pixel"], atol=1e-12)
    m = pipeline("matrix")
    view = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, -5, 1]], float)
    proj = np.array([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, -1, -1], [0, 0, -1, 0]], float)
    z = np.diag([1.0, 1.0, -1.0, 1.0])
    np.testing.assert_allclose(wind4 @ z @ proj.T @ view.T, m["world_to_pixel"], atol=1e-12)
    moved = pipeline("moved")
    t_inv = np.eye(4)
    t_inv[0, 3] = -1.0
    np.testing.assert_allclose(wind4 @ moved["m_ortho"] @ t_inv, moved["world_to_pixel"])


def test_factors_text():
    assert world_to_pixel_factors("orthographic") == "Mwind Morth"
    assert world_to_pixel_factors("perspective", True) == "Mwind Mpp Mper inverse(Camera.Transform)"
