"""glTF export of an animated scene: what the animation costs beyond the still scene.

    python benchmarks/bench_export.py [--repeat 3] [--models 1000] [--seconds 120] [--base TREE]

Writes its inputs into a temporary folder: ``--models`` quads sharing one mesh and one
material, each placed by its own TranslateTransform3D, and

- ``camera``: a Point3DAnimation of the camera's Position over ``--seconds`` (the camera's
  NearPlaneDistance is 0, so that its near plane is taken from the models' bounds at every
  sample);
- ``transform``: one RotateTransform3D of the first model turned over ``--seconds``;
- ``still``: the same models without a storyboard, the baseline: the export of the scene
  itself, which the animated exports add their samples to.

At 30 samples per second up to 3600 samples (``export.gltf_animation``), the default is 3600
samples. Times whole ``python -m xaml3d export FILE -o x.glb`` processes (after one untimed
warm-up per tree), ``--repeat`` times each, interleaved (with ``--base TREE``, e.g. ``git
archive <commit> | tar -x -C /tmp/before``, the xaml3d of that source tree too, run by run
beside this one). Printed per case and tree: median seconds, min..max, the median minus the
baseline's median (what the animation costs), that per sample in ms, and the peak RSS of the
process (``os.wait4``).

The machine is a 2-core VM shared with other jobs: compare only pairs measured in one run.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)
SAMPLE_RATE, MAX_SAMPLES = 30.0, 3600  # export.gltf_animation's


def scene(models: int, case: str, seconds: float) -> str:
    """The markup of one case (see the module docstring)."""
    out = [
        f'<Viewport3D {NS} Width="320" Height="240"><Viewport3D.Resources><MeshGeometry3D '
        'x:Key="g" Positions="0,0,0 1,0,0 1,1,0 0,1,0" TriangleIndices="0 1 2 0 2 3"/>'
        '<DiffuseMaterial x:Key="m" Brush="SteelBlue"/></Viewport3D.Resources>'
        '<Viewport3D.Camera><PerspectiveCamera x:Name="Cam" Position="0,0,60" '
        'LookDirection="0,0,-1" NearPlaneDistance="0"/></Viewport3D.Camera>'
        "<ModelVisual3D><ModelVisual3D.Content><Model3DGroup><AmbientLight/>"
        '<DirectionalLight Direction="-1,-1,-1"/>'
    ]
    for i in range(models):
        place = f'<TranslateTransform3D OffsetX="{(i % 40 - 20) * 1.2:g}" ' + (
            f'OffsetY="{(i // 40 - 12) * 1.2:g}"/>'
        )
        if case == "transform" and i == 0:
            place = (
                f"<Transform3DGroup>{place}<RotateTransform3D><RotateTransform3D.Rotation>"
                '<AxisAngleRotation3D x:Name="Spin" Axis="0,1,0"/>'
                "</RotateTransform3D.Rotation></RotateTransform3D></Transform3DGroup>"
            )
        out.append(
            '<GeometryModel3D Geometry="{StaticResource g}" Material="{StaticResource m}">'
            f"<GeometryModel3D.Transform>{place}</GeometryModel3D.Transform></GeometryModel3D>"
        )
    out.append("</Model3DGroup></ModelVisual3D.Content></ModelVisual3D>")
    if case != "still":
        animation = {
            "camera": '<Point3DAnimation Storyboard.TargetName="Cam" '
            'Storyboard.TargetProperty="Position" From="0,0,60" To="10,5,40"',
            "transform": '<DoubleAnimation Storyboard.TargetName="Spin" '
            'Storyboard.TargetProperty="Angle" From="0" To="360"',
        }[case]
        out.append(
            '<Viewport3D.Triggers><EventTrigger RoutedEvent="Viewport3D.Loaded">'
            f'<BeginStoryboard><Storyboard>{animation} Duration="{_timespan(seconds)}"/>'
            "</Storyboard></BeginStoryboard></EventTrigger></Viewport3D.Triggers>"
        )
    out.append("</Viewport3D>")
    return "".join(out)


def _timespan(seconds: float) -> str:
    """``seconds`` as a XAML TimeSpan (hours:minutes:seconds)."""
    minutes, rest = divmod(seconds, 60.0)
    return f"{int(minutes // 60)}:{int(minutes % 60)}:{rest:g}"


def _env(tree: str | None) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if tree:
        env["PYTHONPATH"] = tree
    return env


def export(file: Path, out: Path, tree: str | None) -> tuple[float, float]:
    """Wall seconds and peak RSS (MiB) of one ``xaml3d export`` process."""
    cmd = [sys.executable, "-m", "xaml3d", "export", str(file), "-o", str(out)]
    t0 = time.perf_counter()
    # cwd: ``python -m`` puts the current folder first on sys.path, before PYTHONPATH
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            env=_env(tree), cwd=tree or file.parent)  # fmt: skip
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"failed: {' '.join(cmd)}")
    return wall, usage.ru_maxrss / 1024.0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--models", type=int, default=1000)
    ap.add_argument("--seconds", type=float, default=120.0)
    ap.add_argument("--base", help="another source tree to measure alongside")
    args = ap.parse_args(argv)
    trees = {"now": None} | ({"base": str(Path(args.base).resolve())} if args.base else {})
    cases = ("still", "camera", "transform")
    samples = min(MAX_SAMPLES, max(2, int(args.seconds * SAMPLE_RATE) + 1))
    walls = {(c, t): [] for c in cases for t in trees}
    rss = dict.fromkeys(walls, 0.0)
    with tempfile.TemporaryDirectory() as tmp:
        files = {}
        for c in cases:
            files[c] = Path(tmp) / f"{c}.xaml"
            files[c].write_text(scene(args.models, c, args.seconds), encoding="utf-8")
        for tree in trees.values():  # warm-up, untimed: bytecode and caches written
            export(files["still"], Path(tmp) / "warm.glb", tree)
        for _ in range(args.repeat):
            for c in cases:
                for name, tree in trees.items():  # interleaved: the same minutes for each
                    w, m = export(files[c], Path(tmp) / f"{c}-{name}.glb", tree)
                    walls[c, name].append(w)
                    rss[c, name] = max(rss[c, name], m)
    print(f"{args.models} models, {args.seconds:g} s animations ({samples} samples), "
          f"{args.repeat} runs each; baseline: the still scene's export")  # fmt: skip
    for c in cases:
        for name in trees:
            xs = walls[c, name]
            med = statistics.median(xs)
            line = f"  {c:9s} {name:4s} median {med:7.2f} s ({min(xs):.2f}..{max(xs):.2f})"
            if c != "still":
                extra = med - statistics.median(walls["still", name])
                line += f", {extra:+.2f} s over still ({extra / samples * 1e3:+.2f} ms/sample)"
            print(f"{line}, peak RSS {rss[c, name]:.0f} MiB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
