"""Frames per second of an animation, and whole ``animate`` processes against ``render``.

    python benchmarks/bench_animate.py [--frames 30] [--runs 5] [--triangles 10000] [--ssaa 2]
    python benchmarks/bench_animate.py --whole [--runs 3] [--base TREE]
        [--animate-option=OPT ...] [FILE ...]

``--whole``: for each FILE (default: the shared corpus's 005 spinning cubes, 543 frames at
600x600; ``samples/spinning-cube.xaml``; the corpus's textured 001), whole processes of ``python
-m xaml3d animate FILE -o x.gif`` (its defaults) and ``python -m xaml3d render FILE -o x.png``,
run by run interleaved; printed: the animate/render ratio of each run (median, min..max), both
wall times, animate's peak RSS (``os.wait4``: on Linux the largest of the process and of its
worker processes) and the GIF's size; then the same ratio of CPU seconds (user + system, the
workers included), which the other jobs of a shared machine disturb far less than wall times,
and the load average during the runs. ``--base TREE``: the xaml3d of another source tree (``git
archive main | tar -x -C /tmp/before``) is timed too, interleaved run by run, so that a
before/after is measured in the same minutes. ``--animate-option``: an option of ``animate``
(repeatable: ``--animate-option=--background --animate-option=White`` for opaque frames).
Targets: 005 within 12x one render, under 500 MB.

Without ``--whole``:
The scene is a UV sphere of about 10k triangles (a DiffuseMaterial, a DirectionalLight), turned
by a Loaded-trigger DoubleAnimation on an AxisAngleRotation3D (one turn in 4 s, for ever),
viewed by a PerspectiveCamera. Each run renders ``--frames`` consecutive frames at 30 fps
(``xaml3d.render_frames``: the scene at t, then an ordinary render) and reports frames per
second; printed: the median and the min..max over the runs, and the share of a frame spent
building the scene at t (``scene_at``) rather than drawing it. The machine is a shared 2-core
VM: read the figures as +-30 %.
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

import numpy as np  # noqa: E402

import xaml3d  # noqa: E402


def sphere_xaml(triangles: int) -> str:
    """A UV sphere with about ``triangles`` triangles, spinning about y."""
    stacks = max(3, round(math.sqrt(triangles / 4)))  # stacks x (2 stacks) slices x 2 triangles
    slices = max(3, triangles // (2 * stacks))
    th = np.linspace(0, math.pi, stacks + 1)
    ph = np.linspace(0, 2 * math.pi, slices + 1)
    t, p = np.meshgrid(th, ph, indexing="ij")
    pos = np.stack([np.sin(t) * np.cos(p), np.cos(t), np.sin(t) * np.sin(p)], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(stacks), np.arange(slices), indexing="ij")
    a = (i * (slices + 1) + j).ravel()
    b, c, d = a + slices + 1, a + 1, a + slices + 2
    tri = np.stack([a, c, b, c, d, b], -1).reshape(-1, 3)
    positions = " ".join(f"{x:.5f},{y:.5f},{z:.5f}" for x, y, z in pos)
    indices = " ".join(str(k) for k in tri.ravel())
    return f"""<Viewport3D xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml" Width="640" Height="480">
  <Viewport3D.Camera><PerspectiveCamera Position="0,0.5,3" LookDirection="0,-0.5,-3"
      FieldOfView="50"/></Viewport3D.Camera>
  <ModelVisual3D><ModelVisual3D.Content><Model3DGroup>
    <DirectionalLight Color="White" Direction="-1,-1,-2"/>
    <AmbientLight Color="#404040"/>
    <GeometryModel3D>
      <GeometryModel3D.Geometry><MeshGeometry3D Positions="{positions}"
          TriangleIndices="{indices}"/></GeometryModel3D.Geometry>
      <GeometryModel3D.Material><DiffuseMaterial Brush="SteelBlue"/></GeometryModel3D.Material>
      <GeometryModel3D.Transform><RotateTransform3D><RotateTransform3D.Rotation>
        <AxisAngleRotation3D x:Name="spin" Axis="0.2,1,0"/>
      </RotateTransform3D.Rotation></RotateTransform3D></GeometryModel3D.Transform>
    </GeometryModel3D>
  </Model3DGroup></ModelVisual3D.Content></ModelVisual3D>
  <Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded"><BeginStoryboard>
    <Storyboard><DoubleAnimation Storyboard.TargetName="spin" Storyboard.TargetProperty="Angle"
        From="0" To="360" Duration="0:0:4" RepeatBehavior="Forever"/></Storyboard>
  </BeginStoryboard></EventTrigger></Viewport3D.Triggers>
</Viewport3D>"""


ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "corpus"
WHOLE = [CORPUS / "005_wpfsamples-spinningcube.xaml", ROOT / "samples" / "spinning-cube.xaml",
         CORPUS / "001_wpfsamples-cubeanimation.xaml"]  # fmt: skip


def process(cmd: list[str], tree: Path | None = None) -> tuple[float, float, float]:
    """Wall seconds, peak RSS (MiB: the process, or the largest of its workers) and CPU
    seconds (user + system, the workers included) of one run; ``tree``: a source tree whose
    ``xaml3d`` runs instead of the installed one."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if tree is not None:
        env["PYTHONPATH"] = str(tree)
    t0 = time.perf_counter()
    # run from the temporary folder: the current folder would come first on the module path
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env,
                            cwd=tempfile.gettempdir())  # fmt: skip
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"failed: {' '.join(cmd)}\n{err.decode()}")
    # Linux's wait4 reports the child with its reaped children (the workers) included
    return wall, usage.ru_maxrss / 1024.0, usage.ru_utime + usage.ru_stime


def whole(files: list[Path], runs: int, base: Path | None = None, extra=()) -> int:
    """Whole ``animate`` and ``render`` processes of each file, run by run interleaved (with
    ``base``: the same of that source tree too, in the same minutes); ``extra``: more options
    of ``animate`` (``--background White``...)."""
    xaml3d_cmd = [sys.executable, "-m", "xaml3d"]
    extra = list(extra)
    trees = [("now", None)] + ([("base", base)] if base is not None else [])
    with tempfile.TemporaryDirectory() as tmp:
        for f in files:
            if not f.is_file():
                print(f"{f.name}: not found (the shared corpus is absent)")
                continue
            got = {name: ([], [], [], [], [], [], [0.0]) for name, _ in trees}
            loads = []
            for _, tree in trees:  # caches warm (bytecode, numba's kernels)
                process([*xaml3d_cmd, "render", str(f), "-o", f"{tmp}/x.png"], tree)
                process([*xaml3d_cmd, "animate", str(f), "-o", f"{tmp}/x.gif", "-q", *extra], tree)
            sizes = {}
            for _ in range(runs):
                for name, tree in trees:
                    anim, rend, ratio, anim_cpu, rend_cpu, cpu_ratio, peak = got[name]
                    r, _, rc = process([*xaml3d_cmd, "render", str(f), "-o", f"{tmp}/x.png"], tree)
                    a, m, ac = process(
                        [*xaml3d_cmd, "animate", str(f), "-o", f"{tmp}/x.gif", "-q", *extra], tree
                    )
                    sizes[name] = (Path(tmp) / "x.gif").stat().st_size
                    anim.append(a)
                    rend.append(r)
                    ratio.append(a / r)
                    anim_cpu.append(ac)
                    rend_cpu.append(rc)
                    cpu_ratio.append(ac / rc)
                    peak[0] = max(peak[0], m)
                    loads.append(os.getloadavg()[0])
            for name, _ in trees:
                anim, rend, ratio, anim_cpu, rend_cpu, cpu_ratio, peak = got[name]
                print(f"{f.name} [{name}]: animate / render {_span(ratio, 'x')}; animate "
                      f"{_span(anim, 's')}, render {_span(rend, 's')}; animate peak RSS "
                      f"{peak[0]:.0f} MiB; GIF {sizes[name]} bytes")  # fmt: skip
                print(f"{f.name} [{name}]: CPU (user + system, workers included): animate / "
                      f"render {_span(cpu_ratio, 'x')}; animate {_span(anim_cpu, 's')}, "
                      f"render {_span(rend_cpu, 's')}")  # fmt: skip
            print(f"{f.name}: load average (1 min) during the runs {min(loads):.1f}.."
                  f"{max(loads):.1f}")  # fmt: skip
    return 0


def _span(xs: list[float], unit: str) -> str:
    return f"median {statistics.median(xs):.3g} {unit} ({min(xs):.3g}..{max(xs):.3g})"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--frames", type=int, default=30)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--triangles", type=int, default=10000)
    ap.add_argument("--ssaa", type=int, default=None, help="supersampling (default: msaa 2)")
    ap.add_argument("--whole", action="store_true", help="whole animate vs render processes")
    ap.add_argument("files", nargs="*", type=Path, help="with --whole (default: see above)")
    ap.add_argument("--base", type=Path, help="with --whole: a source tree to time as well "
                    "(git archive main | tar -x -C /tmp/before)")  # fmt: skip
    ap.add_argument("--animate-option", action="append", default=[], metavar="OPT",
                    help="with --whole: an option given to animate (repeatable), e.g. "
                    "--animate-option=--background --animate-option=White")  # fmt: skip
    args = ap.parse_args(argv)
    if args.whole:
        files = [f.resolve() for f in args.files] or WHOLE
        base = args.base.resolve() if args.base else None
        return whole(files, args.runs, base, args.animate_option)
    scene = xaml3d.load(sphere_xaml(args.triangles), text=True)
    tris = scene.viewports[0].triangle_count
    times = xaml3d.frame_times(0.0, args.frames / 30.0, 30.0)
    fps, build_share = [], []
    for _ in range(args.runs):
        t0 = time.perf_counter()
        build = 0.0
        for t in times:
            b0 = time.perf_counter()
            frame = xaml3d.scene_at(scene, t)
            build += time.perf_counter() - b0
            xaml3d.render_arrays(frame, 640, 480, ssaa=args.ssaa, time=None)  # default: msaa 2
        total = time.perf_counter() - t0
        fps.append(len(times) / total)
        build_share.append(build / total)
    aa = f"ssaa {args.ssaa}" if args.ssaa else "msaa 2 (default)"
    print(f"{tris} triangles, 640x480, {aa}, {len(times)} frames x {args.runs} runs")
    print(f"frames per second: median {statistics.median(fps):.1f} "
          f"(min {min(fps):.1f} .. max {max(fps):.1f})")  # fmt: skip
    print(f"scene at t: {100 * statistics.median(build_share):.1f} % of a frame (median)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
