"""The 2D layer's cost: a scene with 2D content against the same scene's 3D alone.

    python benchmarks/bench_layer2d.py [--repeat N]

Times, in one process after a warm-up, ``render_arrays`` of:

- ``figure``: docs/figures/src/layer2d.xaml (a VisualBrush with text and shapes, a
  Viewport2DVisual3D Button, a tiled DrawingBrush floor) at its 400 x 260;
- ``figure-cold``: the same with the drawn tiles forgotten first (each render rasterizes them
  again, as a render of a new scene does; ``figure`` reuses them, as the frames of one scene's
  lens samples do);
- ``figure-3d``: the same scene with every 2D brush replaced by a SolidColorBrush (what the 2D
  layer costs is the difference);
- ``cube``: samples/cube.xaml, which has no 2D content (skia is not imported for it: checked by
  tests/test_layer2d.py);

and the import time of skia itself (a fresh process). Medians and min..max in milliseconds; the
machine is shared, so compare only numbers of one run.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import xaml3d  # noqa: E402
from xaml3d.render.layer2d import surface  # noqa: E402
from xaml3d.scene.drawing import DrawingBrush  # noqa: E402
from xaml3d.scene.types import SolidColorBrush  # noqa: E402


def _flat(scene):
    grey = SolidColorBrush(color=(0.7, 0.7, 0.7, 1.0))
    vps = []
    for vp in scene.viewports:
        models = []
        for m in vp.models:
            mat = tuple(
                replace(p, brush=grey) if isinstance(p.brush, DrawingBrush) else p
                for p in m.material
            )
            models.append(replace(m, material=mat))
        vps.append(replace(vp, models=tuple(models)))
    return replace(scene, viewports=tuple(vps))


def _time(fn, repeat: int) -> list[float]:
    fn()  # warm-up: imports, compiled kernels
    out = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        out.append((time.perf_counter() - t) * 1000.0)
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    figure = xaml3d.load(ROOT / "docs" / "figures" / "src" / "layer2d.xaml")
    cube = xaml3d.load(ROOT / "samples" / "cube.xaml")
    cases = {
        "figure": lambda: xaml3d.render_arrays(figure),
        "figure-cold": lambda: (surface._CACHE.clear(), xaml3d.render_arrays(figure)),
        "figure-3d": lambda: xaml3d.render_arrays(_flat(figure)),
        "cube": lambda: xaml3d.render_arrays(cube),
    }
    for name, fn in cases.items():
        ms = _time(fn, args.repeat)
        print(f"{name:12s} median {statistics.median(ms):8.1f} ms  ({min(ms):.1f}..{max(ms):.1f})")
    code = "import time; t = time.perf_counter(); import skia; print(time.perf_counter() - t)"
    s = float(subprocess.run([sys.executable, "-c", code], capture_output=True).stdout)
    print(f"import skia {s * 1000:8.1f} ms (fresh process)")


if __name__ == "__main__":
    main()
