"""A big render through the compiled kernels prints nothing with ``-q``, whatever numba and
llvmlite are installed, and draws the same picture with all of them.

The command line runs in processes of its own with a fresh cache folder: the first process
compiles the kernels with numba and keeps their machine code (the native loading builds its
trampolines: IR the installed LLVM must parse, ``xaml3d.native.abi.typed_pointers``), the second
links that machine code without numba. Neither may write a byte to stdout or stderr (LLVM's own
messages go to a debug log, the first run's note is not printed with ``-q``), and both draw the
stored picture. CI runs this file with the newest dependencies and again with the lowest ones
``pyproject.toml`` allows, so the picture is the same for both.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

ROOT = Path(__file__).resolve().parent.parent
EXPECTED = ROOT / "tests" / "reference" / "_native" / "big-sphere.png"

pytest.importorskip("numba", reason="numba is not installed")

HEADER = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="1200" Height="900">
  <Viewport3D.Camera>
    <PerspectiveCamera Position="0,0,2.6" LookDirection="0,0,-1" UpDirection="0,1,0"
        FieldOfView="60" />
  </Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <AmbientLight Color="#333333" />
    <DirectionalLight Color="#DDDDDD" Direction="-1,-1,-1" />
    <PointLight Color="#808080" Position="1.5,1,2" />
    <GeometryModel3D>
      <GeometryModel3D.Geometry>
"""
FOOTER = """
      </GeometryModel3D.Geometry>
      <GeometryModel3D.Material>
        <MaterialGroup>
          <DiffuseMaterial Brush="#FF3380E6" />
          <SpecularMaterial Brush="#80FFFFFF" SpecularPower="30" />
        </MaterialGroup>
      </GeometryModel3D.Material>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
</Viewport3D>
"""


def _sphere(rings: int) -> str:
    """A lit UV sphere of 4 * rings**2 triangles (with normals), written as markup."""
    segs = 2 * rings
    t, p = np.meshgrid(np.linspace(0, np.pi, rings + 1), np.linspace(0, 2 * np.pi, segs + 1),
                       indexing="ij")  # fmt: skip
    pos = np.stack([np.sin(t) * np.cos(p), np.cos(t), -np.sin(t) * np.sin(p)], -1).reshape(-1, 3)
    r, s = np.meshgrid(np.arange(rings), np.arange(segs), indexing="ij")
    a = (r * (segs + 1) + s).ravel()
    b, c, d = a + segs + 1, a + 1, a + segs + 2
    idx = np.concatenate([np.stack([a, b, c], 1), np.stack([c, b, d], 1)])
    points = " ".join(f"{x:.5f},{y:.5f},{z:.5f}" for x, y, z in pos.tolist())
    indices = " ".join(map(str, idx.ravel().tolist()))
    mesh = (f'<MeshGeometry3D Positions="{points}"\n Normals="{points}"\n'
            f' TriangleIndices="{indices}" />')  # fmt: skip
    return HEADER + mesh + FOOTER


def _render(scene: Path, out: Path, env: dict) -> None:
    # 1200 x 900 at --ssaa 4: work far above the bar where the kernels pay (render.accel)
    proc = subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", "-q", str(scene), "-o", str(out), "--ssaa",
         "4"],
        env=env, capture_output=True, timeout=900, cwd=scene.parent,
    )  # fmt: skip
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")
    assert proc.stdout == b""
    assert proc.stderr == b"", proc.stderr.decode(errors="replace")[:2000]


def test_a_big_render_prints_nothing_and_draws_the_same_picture(tmp_path):
    scene = tmp_path / "sphere.xaml"
    scene.write_text(_sphere(100), encoding="utf-8")  # 40,000 triangles
    cache = tmp_path / "cache"
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), XAML3D_NATIVE="1", XAML3D_KERNELS="auto",
               PYTHONPATH=str(ROOT))  # fmt: skip
    env.pop("XAML3D_REGENERATE", None)
    first, second = tmp_path / "first.png", tmp_path / "second.png"
    _render(scene, first, env)  # numba compiles the kernels; their machine code is kept
    (kept,) = (cache / "native").glob("xaml3d.render.kernels-*")
    manifest = json.loads((kept / "manifest.json").read_text())
    assert {"draw_pass", "resolve"} <= set(manifest["kernels"])
    _render(scene, second, env)  # the kept machine code, linked without numba
    picture = np.asarray(Image.open(first))
    assert np.array_equal(np.asarray(Image.open(second)), picture)
    assert (picture[..., 3] > 0).mean() > 0.3  # the sphere fills much of the view
    if os.environ.get("XAML3D_REGENERATE", "").lower() not in ("", "0", "false", "no"):
        EXPECTED.parent.mkdir(parents=True, exist_ok=True)
        Image.open(first).save(EXPECTED)
        pytest.fail(f"{EXPECTED} written: look at it, then run again without XAML3D_REGENERATE")
    assert np.array_equal(picture, np.asarray(Image.open(EXPECTED)))


def test_what_llvm_prints_goes_to_the_debug_log(tmp_path):
    """Descriptor 2 (where LLVM writes) goes to the log inside the block and comes back after:
    a C library's write and a parse in the pointer form the installed LLVM refuses print
    nothing; Python's own stderr before and after is untouched."""
    code = (
        "import os, sys\n"
        "from xaml3d.native import abi, quiet\n"
        "import llvmlite.binding as llvm\n"
        "print('before', file=sys.stderr, flush=True)\n"
        "with quiet.llvm_output():\n"
        "    os.write(2, b'from C\\n')\n"
        "    wrong = abi.trampoline_ir('t', 'k', [['s', 'int64']], llvm.get_process_triple(), '',"
        " typed=not abi.typed_pointers())\n"
        "    try:\n"
        "        llvm.parse_assembly(wrong)\n"
        "    except RuntimeError:\n"
        "        pass\n"
        "print('after', file=sys.stderr, flush=True)\n"
        "print(quiet.log_path())\n"
    )
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                          timeout=120)  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == "before\nafter\n"
    log = Path(proc.stdout.strip())
    assert log == tmp_path / "cache" / "native" / "llvm.log"
    assert log.read_text().startswith("from C\n")


@pytest.mark.parametrize("command", ["render", "export"])
def test_a_batch_with_q_prints_nothing_when_every_scene_went_well(tmp_path, command):
    scenes = [str(ROOT / "samples" / n) for n in ("cube.xaml", "materials.xaml")]
    out = tmp_path / "out"
    args = [sys.executable, "-m", "xaml3d", command, "-q", *scenes, "-o", f"{out}/"]
    if command == "export":
        args += ["--format", "obj"]
    proc = subprocess.run(args, capture_output=True, timeout=300, cwd=tmp_path,
                          env=dict(os.environ, PYTHONPATH=str(ROOT)))  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == b"" and proc.stderr == b""
    assert len(list(out.iterdir())) >= 2
    bad = tmp_path / "bad.xaml"
    bad.write_text("<Viewport3D")
    with_bad = [*args[:5], *scenes, str(bad), *args[5 + len(scenes) :]]  # still -q
    proc = subprocess.run(with_bad,
                          capture_output=True, timeout=300, cwd=tmp_path,
                          env=dict(os.environ, PYTHONPATH=str(ROOT)))  # fmt: skip
    assert proc.returncode == 1
    assert f" of 3 scenes; failed: {bad}" in proc.stderr.decode()
