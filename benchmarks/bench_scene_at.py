"""The scene at t: seconds per ``scene_at`` frame, and whole ``xaml3d animate`` processes.

    python benchmarks/bench_scene_at.py [--runs 3] [--frames 90] [--base TREE] [FILE]

FILE defaults to the shared corpus's 005_wpfsamples-spinningcube.xaml (two 12-triangle cubes
turned by six Forever DoubleAnimations; ``animate`` draws 543 frames of it). Two measures, each
in whole processes (``--base TREE``: also the xaml3d of another source tree, e.g. ``git archive
main | tar -x -C /tmp/before``, run by run interleaved with this one):

- ``scene_at``: one process loads FILE and times ``xaml3d.scene_at(scene, t)`` for ``--frames``
  consecutive frames at 30 fps (the first one included); printed: median, min..max seconds
  per frame over every frame of every run;
- ``animate``: ``python -m xaml3d animate FILE -o x.gif``, wall seconds (median, min..max) and
  the largest peak RSS (``os.wait4``).

``--tree TREE`` measures that source tree as "now" instead of the installed xaml3d.

The machine is a 2-core VM shared with other jobs: compare only pairs measured in one run.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DEFAULT = ROOT.parent / "shared" / "corpus" / "005_wpfsamples-spinningcube.xaml"

PER_FRAME = """
import json, sys, time
import xaml3d
sys.stderr.write(xaml3d.__file__)
scene = xaml3d.load(sys.argv[1])
out = []
for i in range(int(sys.argv[2])):
    t0 = time.perf_counter()
    xaml3d.scene_at(scene, i / 30.0)
    out.append(time.perf_counter() - t0)
print(json.dumps(out))
"""


def _env(tree: str | None) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if tree:
        env["PYTHONPATH"] = tree
    return env


def per_frame(file: Path, frames: int, tree: str | None) -> tuple[list[float], str]:
    """Seconds of each ``scene_at`` frame, and the xaml3d module that ran."""
    # cwd: ``python -c`` puts the current folder first on sys.path, before PYTHONPATH
    p = subprocess.run([sys.executable, "-c", PER_FRAME, str(file.resolve()), str(frames)],
                       capture_output=True, env=_env(tree), cwd=tree, check=True)  # fmt: skip
    return json.loads(p.stdout), p.stderr.decode().strip()


def animate(file: Path, out: Path, tree: str | None) -> tuple[float, float]:
    """Wall seconds and peak RSS (MiB) of one ``xaml3d animate`` process."""
    cmd = [sys.executable, "-m", "xaml3d", "animate", str(file.resolve()), "-o", str(out)]
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            env=_env(tree), cwd=tree)  # fmt: skip
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"failed: {' '.join(cmd)}")
    return wall, usage.ru_maxrss / 1024.0


def _span(xs: list[float], unit: str = "s", scale: float = 1.0) -> str:
    xs = [x * scale for x in xs]
    return f"median {statistics.median(xs):.4g} {unit} ({min(xs):.4g}..{max(xs):.4g})"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file", nargs="?", type=Path, default=DEFAULT)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--frames", type=int, default=90)
    ap.add_argument("--base", help="another source tree to measure alongside")
    ap.add_argument("--tree", help="measure this source tree as 'now' (default: the installed)")
    ap.add_argument("--skip-animate", action="store_true")
    args = ap.parse_args(argv)
    if not args.file.is_file():
        print(f"{args.file}: not found (the shared corpus is absent)")
        return 1
    now = str(Path(args.tree).resolve()) if args.tree else None
    trees = {"now": now} | ({"base": str(Path(args.base).resolve())} if args.base else {})
    frames = {k: [] for k in trees}
    walls = {k: [] for k in trees}
    rss = {k: 0.0 for k in trees}
    used = {}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(args.runs):
            for name, tree in trees.items():  # interleaved: the same minutes for both
                seconds, used[name] = per_frame(args.file, args.frames, tree)
                frames[name] += seconds
                if not args.skip_animate:
                    w, m = animate(args.file, Path(tmp) / f"{name}.gif", tree)
                    walls[name].append(w)
                    rss[name] = max(rss[name], m)
    print(f"{args.file.name}: {args.runs} runs")
    for name in trees:
        print(f"  {name}: {used[name]}")
        print(f"  {name}: scene_at per frame {_span(frames[name], 'ms', 1e3)} "
              f"over {len(frames[name])} frames")  # fmt: skip
        if walls[name]:
            print(f"  {name}: animate whole process {_span(walls[name])}, "
                  f"peak RSS {rss[name]:.0f} MiB")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
