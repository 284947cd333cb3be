"""Renderer benchmark: seconds and peak memory per case, each in a fresh subprocess.

Cases: a UV sphere filling most of a 1920x1080 view and a random triangle soup, with about 1k,
10k, 100k and 1M triangles, rendered in every mode (shaded, flat, wireframe) with ssaa=1 and
with the mode's default ssaa. Each case runs ``python -c`` in a new process that builds the
mesh, renders and writes the PNG; the child reports its wall time for build+render+save and its
peak RSS (resource.getrusage ru_maxrss). The baseline, measured the same way in the same run, is
writing a blank 1920x1080 PNG; ratios are against it.

    python benchmarks/bench_render.py                      # everything
    python benchmarks/bench_render.py --sizes 1000 10000 --modes flat --kinds sphere
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile

import numpy as np

from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    DirectionalLight,
    Mesh,
    Model,
    PerspectiveCamera,
    Scene,
    SolidColorBrush,
    Viewport,
    frozen_array,
)

W, H = 1920, 1080


def uv_sphere(triangles: int) -> Mesh:
    """A unit UV sphere with about ``triangles`` triangles (2 * rings * segments)."""
    rings = max(3, int(round(np.sqrt(triangles / 4.0))))
    segs = 2 * rings
    theta = np.linspace(0.0, np.pi, rings + 1)
    phi = np.linspace(0.0, 2.0 * np.pi, segs + 1)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    pos = np.stack([np.sin(t) * np.cos(p), np.cos(t), -np.sin(t) * np.sin(p)], axis=-1)
    pos = pos.reshape(-1, 3)
    r, s = np.meshgrid(np.arange(rings), np.arange(segs), indexing="ij")
    a = (r * (segs + 1) + s).ravel()
    b, c, d = a + segs + 1, a + 1, a + segs + 2
    idx = np.concatenate([np.stack([a, b, c], 1), np.stack([c, b, d], 1)])
    uv = np.stack([p / (2 * np.pi), t / np.pi], axis=-1).reshape(-1, 2)
    return Mesh(frozen_array(pos), frozen_array(idx, np.int64), frozen_array(pos), frozen_array(uv))


def soup(triangles: int, seed: int = 1) -> Mesh:
    """Random small triangles scattered in a box in front of the camera."""
    rng = np.random.default_rng(seed)
    centre = rng.uniform((-1.6, -0.9, -1.0), (1.6, 0.9, 1.0), size=(triangles, 1, 3))
    size = 3.0 / np.sqrt(triangles)
    pos = (centre + rng.normal(scale=size, size=(triangles, 3, 3))).reshape(-1, 3)
    nrm = rng.normal(size=pos.shape)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    idx = np.arange(3 * triangles).reshape(-1, 3)
    return Mesh(
        frozen_array(pos), frozen_array(idx, np.int64), frozen_array(nrm),
        frozen_array(np.zeros((pos.shape[0], 2))),
    )  # fmt: skip


def scene(kind: str, triangles: int) -> Scene:
    mesh = uv_sphere(triangles) if kind == "sphere" else soup(triangles)
    mat = DiffuseMaterial(brush=SolidColorBrush((0.2, 0.5, 0.9, 1.0)))
    model = Model(mesh, material=(mat,), back_material=(mat,) if kind == "soup" else ())
    cam = PerspectiveCamera(position=(0.0, 0.0, 2.6), field_of_view=60.0)
    lights = (AmbientLight(color=(0.2, 0.2, 0.2, 1.0)), DirectionalLight(direction=(-1, -1, -1)))
    vp = Viewport(0, None, W, H, "viewport", cam, (model,), lights)
    return Scene(None, (vp,))


CHILD = """
import json, resource, sys, time
t0 = time.perf_counter()
from benchmarks.bench_render import scene
from xaml3d.api import render, save_image
kind, n, mode, ssaa, out = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
t1 = time.perf_counter()
sc = scene(kind, n)
t2 = time.perf_counter()
img = render(sc, mode=mode, ssaa=None if ssaa == "default" else int(ssaa))
t3 = time.perf_counter()
save_image(img, out)
t4 = time.perf_counter()
print(json.dumps({"build": t2 - t1, "render": t3 - t2, "save": t4 - t3, "total": t4 - t1,
                  "rss_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""

BASELINE = """
import json, resource, sys, time
t1 = time.perf_counter()
import numpy as np
from xaml3d.api import save_image
save_image(np.zeros((1080, 1920, 4), np.uint8), sys.argv[1])
t2 = time.perf_counter()
print(json.dumps({"total": t2 - t1,
                  "rss_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""


def run(code: str, *args: str) -> dict:
    out = subprocess.run(
        [sys.executable, "-c", code, *args], capture_output=True, text=True, check=True
    )
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 100000, 1000000])
    ap.add_argument("--modes", nargs="+", default=["shaded", "flat", "wireframe"])
    ap.add_argument("--kinds", nargs="+", default=["sphere", "soup"])
    ap.add_argument("--ssaa", nargs="+", default=["1", "default"])
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        out = f"{tmp}/out.png"
        base = run(BASELINE, out)
        print(f"baseline: blank {W}x{H} PNG in {base['total']:.3f} s, {base['rss_mib']:.0f} MiB")
        print(f"{'kind':7}{'tris':>9} {'mode':10}{'ssaa':>8}{'render s':>10}{'total s':>9}"
              f"{'x base':>8}{'peak MiB':>10}")  # fmt: skip
        for kind in args.kinds:
            for n in args.sizes:
                for mode in args.modes:
                    for ssaa in args.ssaa:
                        r = run(CHILD, kind, str(n), mode, ssaa, out)
                        print(f"{kind:7}{n:>9} {mode:10}{ssaa:>8}{r['render']:>10.3f}"
                              f"{r['total']:>9.3f}{r['total'] / base['total']:>8.1f}"
                              f"{r['rss_mib']:>10.0f}", flush=True)  # fmt: skip


if __name__ == "__main__":
    main()
