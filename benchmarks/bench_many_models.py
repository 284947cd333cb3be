"""Loading benchmark: N GeometryModel3D sharing one mesh and one material resource.

Each model is ``<GeometryModel3D Geometry="{StaticResource g}" Material="{StaticResource m}"/>``
(79 bytes). Reported per N: the file's size, the seconds of ``xaml3d validate`` as a whole
process (read, build, checks, print), seconds per MB and microseconds per model. Loading is
linear: the shared mesh and material are built once, resource lookups and source positions
cost O(1) each (no walk over earlier siblings or earlier positions).

    python benchmarks/bench_many_models.py [--counts 10000 40000 400000]
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HEAD = """<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
 xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="100" Height="100">
<Viewport3D.Resources><MeshGeometry3D x:Key="g" Positions="0,0,0 1,0,0 0,1,0"/>
<DiffuseMaterial x:Key="m" Brush="Red"/></Viewport3D.Resources>
<Viewport3D.Camera><PerspectiveCamera Position="0,0,5"/></Viewport3D.Camera>
<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight/>
"""
MODEL = '<GeometryModel3D Geometry="{StaticResource g}" Material="{StaticResource m}"/>\n'
TAIL = "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D></Viewport3D>\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--counts", type=int, nargs="+", default=[10_000, 40_000, 400_000])
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        for n in args.counts:
            path = Path(tmp) / f"many{n}.xaml"
            path.write_text(HEAD + MODEL * n + TAIL, encoding="utf-8")
            mb = path.stat().st_size / 1e6
            t0 = time.perf_counter()
            run = subprocess.run([sys.executable, "-m", "xaml3d", "validate", str(path)],
                                 capture_output=True)  # fmt: skip
            dt = time.perf_counter() - t0
            print(f"{n:>8} models  {mb:6.1f} MB  {dt:7.2f} s  {dt / mb:5.2f} s/MB  "
                  f"{dt / n * 1e6:6.1f} us/model  exit {run.returncode}")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
