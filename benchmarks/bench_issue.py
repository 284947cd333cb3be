"""The speed figures of the renderer, each as a whole process against the Python floor.

Every case is a whole ``xaml3d`` process (interpreter start, imports, reading, rendering, PNG),
run once untimed (so Python's bytecode caches are written and the files are in the OS's cache,
as on a user's machine; ``PYTHONDONTWRITEBYTECODE`` is removed from the children's environment),
then ``--repeat`` times (default 5) interleaved with its floor (``floor.py``: read + lxml parse +
numpy number conversion + a blank PNG of the same size, for the same file) measured in the same
run. Printed per case: median wall seconds with min..max, the floor's median, their ratio, the
peak resident memory of the case's process (``os.wait4``'s ru_maxrss, largest of the runs), and
the median CPU seconds (user + system) of the case and of the floor with their ratio: on a
machine shared with other work, CPU time moves less than wall time.
A last table gives shaded samples per second (samples written by the material passes divided by
the time of the ``render_arrays`` call, one core) for the lit scenes, textured and not: by wall
time and by the process's CPU time in the call (which a loaded machine moves less), and with
``--base`` the same for the other tree, run by run in turn.

    python benchmarks/bench_issue.py                 # everything, about 3 minutes
    python benchmarks/bench_issue.py --only sphere1m-flat cube --repeat 3
    git worktree add /tmp/before HEAD~5 && python benchmarks/bench_issue.py --base /tmp/before

The machine is shared: read the min..max spread before comparing two runs.
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

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
CORPUS_002 = ROOT.parent / "shared/corpus/002_wpfsamples-hexsphere.xaml"
XAML3D = [sys.executable, "-m", "xaml3d"]
FLOOR = [sys.executable, str(HERE / "floor.py")]


def timed(cmd: list[str], tree: str | None = None) -> tuple[float, float, float]:
    """Wall seconds, peak RSS (MiB) and CPU seconds (user + system) of one whole process
    (``tree``: run the xaml3d of that source tree instead of the installed one)."""
    # As on a user's machine, Python keeps its compiled bytecode (a shell that sets
    # PYTHONDONTWRITEBYTECODE would make every run compile xaml3d's modules again).
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if tree:
        env["PYTHONPATH"] = tree
    t0 = time.perf_counter()
    proc = subprocess.Popen(
        cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd=tree, env=env
    )
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    err = proc.stderr.read().decode() if proc.stderr else ""
    proc.stderr.close()
    if proc.returncode not in (0,):
        raise SystemExit(f"failed ({proc.returncode}): {' '.join(cmd)}\n{err}")
    return wall, usage.ru_maxrss / 1024.0, usage.ru_utime + usage.ru_stime


def cases(files: dict[str, Path], out: str) -> list[tuple[str, list[str], list[str] | None]]:
    s1m, s200k, tex = files["sphere1m"], files["sphere200k"], files["textured"]
    hd = [out, "1920", "1080"]
    found = [
        ("sphere1m-flat", [*XAML3D, "render", "--mode", "flat", str(s1m), "-o", out],
         [*FLOOR, str(s1m), *hd]),
        ("sphere1m-flat-ssaa1", [*XAML3D, "render", "--mode", "flat", "--ssaa", "1", str(s1m),
                                 "-o", out], [*FLOOR, str(s1m), *hd]),
        ("sphere1m-shaded", [*XAML3D, "render", str(s1m), "-o", out], [*FLOOR, str(s1m), *hd]),
        ("sphere1m-info", [*XAML3D, "info", str(s1m)], [*FLOOR, str(s1m), "-"]),
        ("sphere1m-validate", [*XAML3D, "validate", str(s1m)], [*FLOOR, str(s1m), "-"]),
        ("sphere200k-default", [*XAML3D, "render", str(s200k), "-o", out],
         [*FLOOR, str(s200k), *hd]),
        ("sphere200k-ssaa4", [*XAML3D, "render", "--ssaa", "4", str(s200k), "-o", out],
         [*FLOOR, str(s200k), *hd]),
        ("textured-default", [*XAML3D, "render", str(tex), "-o", out], [*FLOOR, str(tex), *hd]),
        ("textured-ssaa4", [*XAML3D, "render", "--ssaa", "4", str(tex), "-o", out],
         [*FLOOR, str(tex), *hd]),
        ("cube", [*XAML3D, "render", str(ROOT / "samples/cube.xaml"), "-o", out],
         [*FLOOR, str(ROOT / "samples/cube.xaml"), out, "640", "480"]),
    ]  # fmt: skip
    if CORPUS_002.is_file():
        found.insert(
            5,
            ("corpus002-hexsphere", [*XAML3D, "render", str(CORPUS_002), "-o", out],
             [*FLOOR, str(CORPUS_002), out, "1024", "768"]),
        )  # fmt: skip
    return found


SAMPLES_CHILD = """
import json, sys, time
from xaml3d.render import frame
made = []
class Counting(frame.Framebuffer):
    def __init__(self, *a, **k):
        super().__init__(*a, **k)
        made.append(self)
from xaml3d.render import api, rendering
rendering.Framebuffer = Counting
from xaml3d.pipeline import load
scene = load(sys.argv[1])
opts = json.loads(sys.argv[2])
api.render_arrays(scene, **opts)  # warm: imports, caches
made.clear()
t0, c0 = time.perf_counter(), time.process_time()
api.render_arrays(scene, **opts)
dt, dc = time.perf_counter() - t0, time.process_time() - c0
print(json.dumps({"samples": sum(f.fragments_drawn for f in made), "seconds": dt, "cpu": dc}))
"""


def shaded_rate(path: Path, opts: dict, tree: str | None = None):
    """(samples, wall M/s per run, CPU M/s per run) of 3 runs (``tree``: another source tree)."""
    rates, cpus, samples = [], [], 0
    env = dict(os.environ, PYTHONPATH=tree) if tree else None
    for _ in range(3):
        out = subprocess.run(
            [sys.executable, "-c", SAMPLES_CHILD, str(path), json.dumps(opts)],
            capture_output=True, text=True, check=True, env=env, cwd=tree,
        )  # fmt: skip
        r = json.loads(out.stdout.strip().splitlines()[-1])
        samples = r["samples"]
        rates.append(r["samples"] / r["seconds"] / 1e6)
        cpus.append(r["samples"] / r["cpu"] / 1e6)
    return samples, rates, cpus


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--only", nargs="+", help="case names to run (default: all)")
    ap.add_argument(
        "--base",
        metavar="TREE",
        help="also time the xaml3d of another source tree (e.g. `git worktree add` of an older "
        "commit), interleaved run by run with this one: a fair before/after on a noisy machine",
    )
    args = ap.parse_args()
    base = str(Path(args.base).resolve()) if args.base else None
    with tempfile.TemporaryDirectory() as tmp:
        # Written by a child: a forked child's ru_maxrss counts its parent's memory up to exec,
        # so this process stays small.
        subprocess.run(
            [sys.executable, str(HERE / "scenes.py"), tmp], check=True, stdout=subprocess.DEVNULL
        )
        files = {
            "sphere1m": Path(tmp, "sphere-1m.xaml"),
            "sphere200k": Path(tmp, "sphere-200k.xaml"),
            "textured": Path(tmp, "textured-lit-translucent.xaml"),
        }
        out = f"{tmp}/out.png"
        head = (f"{'case':22}{'median s':>9}  {'min..max':13}{'floor s':>8}{'ratio':>7}"
                f"{'peak MiB':>10}{'cpu s':>7}{'floor':>6}{'ratio':>6}")  # fmt: skip
        if base:
            head += f"{'base s':>9}  {'min..max':13}{'ratio':>6}{'MiB':>6}"
        print(head)
        results: dict[str, tuple[float, float, float, float]] = {}
        for name, cmd, floor in cases(files, out):
            if args.only and name not in args.only:
                continue
            runs, floors, peak, bruns, bpeak, cpus, fcpus = [], [], 0.0, [], 0.0, [], []
            # untimed first runs: bytecode and file caches, as on a user's machine
            timed(cmd)
            if floor:
                timed(floor)
            if base:
                timed(cmd, base)
            for _ in range(args.repeat):
                wall, rss, cpu = timed(cmd)
                runs.append(wall)
                cpus.append(cpu)
                peak = max(peak, rss)
                if floor:
                    wall, _, cpu = timed(floor)
                    floors.append(wall)
                    fcpus.append(cpu)
                if base:
                    wall, rss, _ = timed(cmd, base)
                    bruns.append(wall)
                    bpeak = max(bpeak, rss)
            med = statistics.median(runs)
            fl = statistics.median(floors) if floors else float("nan")
            results[name] = (med, min(runs), max(runs), fl)
            if base:
                results[name + "@base"] = (statistics.median(bruns), min(bruns), max(bruns), fl)
            cpu, fcpu = statistics.median(cpus), statistics.median(fcpus) if fcpus else float("nan")
            line = (f"{name:22}{med:>9.3f}  {min(runs):.2f}..{max(runs):<7.2f}{fl:>8.3f}"
                    f"{med / fl:>7.2f}{peak:>10.0f}"
                    f"{cpu:>7.2f}{fcpu:>6.2f}{cpu / fcpu:>6.2f}")  # fmt: skip
            if base:
                bmed = statistics.median(bruns)
                line += (f"{bmed:>9.3f}  {min(bruns):.2f}..{max(bruns):<7.2f}{bmed / fl:>6.2f}"
                         f"{bpeak:>6.0f}")  # fmt: skip
            print(line, flush=True)
        if not args.only or "samples" in args.only:
            print(f"\n{'shaded samples/s (1 core)':40}{'samples':>11}  M/s median (min..max)"
                  "  CPU M/s" + ("  | base M/s, CPU M/s" if base else ""))  # fmt: skip
            for label, path, opts in (
                ("textured+lit+translucent, default AA", files["textured"], {}),
                ("textured+lit+translucent, ssaa 1", files["textured"], {"ssaa": 1}),
                ("lit sphere 200k shaded, default AA", files["sphere200k"], {}),
            ):
                samples, rates, cpus = shaded_rate(path, opts)
                line = (f"{label:40}{samples:>11}  {statistics.median(rates):.1f} "
                        f"({min(rates):.1f}..{max(rates):.1f})"
                        f"  {statistics.median(cpus):.1f}")  # fmt: skip
                if base:
                    _, brates, bcpus = shaded_rate(path, opts, base)
                    line += (f"  | {statistics.median(brates):.1f} "
                             f"({min(brates):.1f}..{max(brates):.1f}), "
                             f"{statistics.median(bcpus):.1f}")  # fmt: skip
                print(line, flush=True)
                rate = (statistics.median(rates), min(rates), max(rates), float("nan"))
                results["rate:" + label] = rate
        print_targets(results)


# (case, bound, what): a ratio to the floor at most ``bound``, or (rate) at least ``bound``.
TARGETS = (
    ("sphere1m-flat", 1.2, "1M sphere 1920x1080 flat, ratio to the floor <="),
    ("sphere1m-info", 0.8, "`info` of the 1M sphere, ratio to the read floor <="),
    ("corpus002-hexsphere", 4.0, "corpus 002 at its size, ratio to the floor <="),
    ("rate:textured+lit+translucent, default AA", 50.0,
     "lit textured translucent 1920x1080, M shaded samples/s (1 core) >="),
)  # fmt: skip


def print_targets(results: dict[str, tuple[float, float, float, float]]) -> None:
    """Every target of the speed work with the figure measured in this run, met or not."""
    print("\ntargets (median, min..max of this run)")
    for name, bound, what in TARGETS:
        if name not in results:
            continue
        med, lo, hi, floor = results[name]
        if name.startswith("rate:"):
            ok = med >= bound
            line = f"{med:.1f} M/s ({lo:.1f}..{hi:.1f})"
        else:
            ok = med / floor <= bound
            line = f"{med / floor:.2f}x ({lo / floor:.2f}..{hi / floor:.2f})"
        print(f"  {what} {bound:g}: {line}  {'met' if ok else 'MISSED'}")
    if "cube" in results:
        med, lo, hi, floor = results["cube"]
        line = f"  samples/cube.xaml: {med:.3f} s ({lo:.3f}..{hi:.3f}), {med / floor:.2f}x floor"
        if "cube@base" in results:
            bmed = results["cube@base"][0]
            line += f"; base {bmed:.3f} s: {'met' if med <= bmed * 1.05 else 'MISSED'} (no slower)"
        print(line)


if __name__ == "__main__":
    main()
