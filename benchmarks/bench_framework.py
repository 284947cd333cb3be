"""What the framework step (styles, templates, triggers, items, load-time bindings) costs a load.

For ``samples/cube.xaml`` and every shared corpus file (``../shared/corpus``, skipped when absent)
one process loads the document, interleaved run by run, three ways:

- ``load``: the whole load as users get it (parse, read, the framework step, layout, the Scene);
- ``without``: the same load with the framework step replaced by a no-op (the time the step
  adds is the difference; for documents with controls the Scene then differs, the time is what
  is compared);
- ``floor``: the Python floor's reading (``floor.py``: parse with lxml, convert the number
  lists), the baseline every figure is a ratio to.

The step's own time is also taken inside ``load`` (a wrapper around ``xaml3d.framework.expand``).
Printed: per document the medians and min..max in milliseconds, then the sums over the corpus.
The machine is shared and noisy: compare the ratios of one run, not figures of two runs.

    python benchmarks/bench_framework.py [--repeat 7] [--corpus ../shared/corpus]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import xaml3d.framework
from xaml3d.errors import XamlError
from xaml3d.pipeline import load

sys.path.insert(0, str(Path(__file__).resolve().parent))
from floor import read as floor_read  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent


def _callers() -> list:
    """The loaded modules that call the framework step by the name ``expand``."""
    real = xaml3d.framework.expand
    return [m for name, m in list(sys.modules.items())
            if name.startswith("xaml3d.") and getattr(m, "expand", None) is real]  # fmt: skip


class Step:
    """Swaps the framework step for a timed wrapper or a no-op in every module that calls it."""

    def __init__(self) -> None:
        self.real = xaml3d.framework.expand
        self.modules = _callers()
        self.spent = 0.0

    def _timed(self, root, services) -> None:
        t0 = time.perf_counter()
        self.real(root, services)
        self.spent += time.perf_counter() - t0

    def use(self, skip: bool) -> None:
        fn = (lambda root, services: None) if skip else self._timed
        for m in self.modules:
            m.expand = fn


def _load(path: Path) -> None:
    try:
        load(path)
    except XamlError:
        pass  # a corpus file the reader refuses still costs its reading


def measure(path: Path, step: Step, repeat: int) -> dict[str, list[float]]:
    times: dict[str, list[float]] = {"load": [], "without": [], "step": [], "floor": []}
    for _ in range(repeat):
        step.use(skip=False)
        step.spent = 0.0
        t0 = time.perf_counter()
        _load(path)
        times["load"].append(time.perf_counter() - t0)
        times["step"].append(step.spent)
        step.use(skip=True)
        t0 = time.perf_counter()
        _load(path)
        times["without"].append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        floor_read(str(path))
        times["floor"].append(time.perf_counter() - t0)
    step.use(skip=False)
    return times


def _fmt(values: list[float]) -> str:
    ms = [v * 1000 for v in values]
    return f"{statistics.median(ms):8.2f} ({min(ms):.2f}..{max(ms):.2f})"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--corpus", type=Path, default=ROOT.parent / "shared" / "corpus")
    args = ap.parse_args()
    _load(ROOT / "samples" / "cube.xaml")  # imports and compiled kernels out of the figures
    step = Step()
    if not step.modules:
        sys.exit("the framework step is not called through a name 'expand': update this script")
    docs = [ROOT / "samples" / "cube.xaml"]
    corpus = sorted(args.corpus.glob("*.xaml")) if args.corpus.is_dir() else []
    if not corpus:
        print(f"corpus: {args.corpus} not found, cube only")
    print(f"{'document':34} {'load ms':>24} {'without step':>24} {'step':>22} "
          f"{'floor':>22} {'load/floor':>10}")  # fmt: skip
    sums = {"load": 0.0, "without": 0.0, "step": 0.0, "floor": 0.0}
    for path in docs + corpus:
        t = measure(path, step, args.repeat)
        ratio = statistics.median(t["load"]) / statistics.median(t["floor"])
        print(f"{path.name[:34]:34} {_fmt(t['load']):>24} {_fmt(t['without']):>24} "
              f"{_fmt(t['step']):>22} {_fmt(t['floor']):>22} {ratio:10.2f}")  # fmt: skip
        if path in corpus:
            for k in sums:
                sums[k] += statistics.median(t[k])
    if corpus:
        print(f"corpus ({len(corpus)} files), sums of medians: load {sums['load'] * 1000:.1f} ms, "
              f"without the step {sums['without'] * 1000:.1f} ms, the step itself "
              f"{sums['step'] * 1000:.2f} ms, floor {sums['floor'] * 1000:.1f} ms; "
              f"load/without {sums['load'] / sums['without']:.3f}")  # fmt: skip


if __name__ == "__main__":
    main()
