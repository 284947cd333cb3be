"""What each command costs before its work begins: imports, as whole processes.

For each case (a command line), first ``python -X importtime`` of the command ``--runs`` times:
the median over runs of the summed self time of xaml3d's own modules, of all modules, and how
many modules are imported; then the whole process ``--repeat`` times (after one untimed run, so
Python's bytecode caches are written, as on a user's second run): median wall seconds with
min..max, and the median user and system CPU seconds (``os.wait4``'s rusage, what
``/usr/bin/time`` prints). With ``--base TREE`` another source tree's xaml3d is measured the
same way, run by run in turn with this one (a fair before/after on a shared, noisy machine).

    python benchmarks/bench_startup.py
    python benchmarks/bench_startup.py --only render-002 validate-cube --repeat 9
    git archive main | tar -x -C /tmp/b && python benchmarks/bench_startup.py --base /tmp/b
    python benchmarks/bench_startup.py --only render-002 --top 20   # the slowest modules too

The corpus cases are skipped when ``../shared/corpus`` is absent.
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
CORPUS_002 = ROOT.parent / "shared/corpus/002_wpfsamples-hexsphere.xaml"
CUBE = ROOT / "samples/cube.xaml"
LINE = re.compile(r"import time:\s+(\d+) \|\s+(\d+) \| *(\S+)")


def cases(out: str) -> list[tuple[str, list[str]]]:
    found = [
        ("render-cube", ["render", str(CUBE), "-o", out]),
        ("validate-cube", ["validate", str(CUBE)]),
        ("info-cube", ["info", str(CUBE)]),
        ("camera-cube", ["camera", str(CUBE)]),
    ]
    if CORPUS_002.is_file():
        c2 = str(CORPUS_002)
        found += [
            ("render-002", ["render", c2, "-o", out, "--width", "1024", "--height", "768"]),
            ("validate-002", ["validate", c2]),
            ("info-002", ["info", c2]),
            ("camera-002", ["camera", c2]),
        ]
    return found


def _env(tree: str | None) -> dict[str, str]:
    # Bytecode caches as on a user's machine (a shell's PYTHONDONTWRITEBYTECODE would make each
    # run compile every module again, and the import times measure the compiler).
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if tree:
        env["PYTHONPATH"] = tree
    return env


def timed(args: list[str], tree: str | None) -> tuple[float, float, float]:
    """Wall, user CPU and system CPU seconds of one whole ``python -m xaml3d`` process."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(
        [sys.executable, "-m", "xaml3d", *args],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=_env(tree), cwd=tree,
    )  # fmt: skip
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) not in (0, 1):  # 1: a scene with findings
        raise SystemExit(f"failed: xaml3d {' '.join(args)}")
    return wall, usage.ru_utime, usage.ru_stime


def import_times(args: list[str], tree: str | None) -> dict[str, int]:
    """Self microseconds of every module one process imports (``-X importtime``)."""
    proc = subprocess.run(
        [sys.executable, "-X", "importtime", "-m", "xaml3d", *args],
        capture_output=True, text=True, env=_env(tree), cwd=tree,
    )  # fmt: skip
    return {m.group(3): int(m.group(1)) for m in map(LINE.match, proc.stderr.splitlines()) if m}


def summary(runs: list[dict[str, int]]) -> tuple[float, float, int, dict[str, float]]:
    """(xaml3d self ms, all self ms, module count, median self ms per module) over runs."""
    mods = set().union(*runs)
    med = {m: statistics.median(r.get(m, 0) for r in runs) / 1000 for m in mods}
    own = sum(v for m, v in med.items() if m == "xaml3d" or m.startswith("xaml3d."))
    return own, sum(med.values()), len(mods), med


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5, help="whole processes per case")
    ap.add_argument("--runs", type=int, default=5, help="-X importtime processes per case")
    ap.add_argument("--only", nargs="+", help="case names to run (default: all)")
    ap.add_argument("--top", type=int, default=0, help="also list the N slowest modules")
    ap.add_argument("--base", metavar="TREE", help="also measure another source tree's xaml3d")
    args = ap.parse_args()
    base = str(Path(args.base).resolve()) if args.base else None
    trees = [("now", None)] + ([("base", base)] if base else [])
    with tempfile.TemporaryDirectory() as tmp:
        for name, cmd in cases(f"{tmp}/out.png"):
            if args.only and name not in args.only:
                continue
            for _, tree in trees:
                timed(cmd, tree)  # untimed: bytecode caches, the OS's file cache
            imports = {label: [] for label, _ in trees}
            walls = {label: [] for label, _ in trees}
            cpus = {label: [] for label, _ in trees}
            for _ in range(max(args.runs, args.repeat)):
                for label, tree in trees:  # interleaved: both see the same minutes
                    if len(imports[label]) < args.runs:
                        imports[label].append(import_times(cmd, tree))
                    if len(walls[label]) < args.repeat:
                        wall, user, system = timed(cmd, tree)
                        walls[label].append(wall)
                        cpus[label].append((user, system))
            for label, _ in trees:
                own, total, count, med = summary(imports[label])
                w = walls[label]
                user = statistics.median(u for u, _ in cpus[label])
                system = statistics.median(s for _, s in cpus[label])
                print(
                    f"{name:14} {label:4}  xaml3d self {own:6.1f} ms  all {total:6.1f} ms  "
                    f"{count:4d} modules  wall {statistics.median(w):.3f} s "
                    f"({min(w):.3f}..{max(w):.3f})  user {user:.3f} s  sys {system:.3f} s"
                )
                for m, v in sorted(med.items(), key=lambda kv: -kv[1])[: args.top]:
                    print(f"{'':20}{v:7.2f} ms  {m}")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
