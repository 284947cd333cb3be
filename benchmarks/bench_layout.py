"""Layout benchmark: reading and laying out about 10 000 nested panels.

The markup nests 100 Grids, each with an Auto row of 98 small sized Borders and a star row
holding a Border (Margin 0.5) that holds the next Grid; a Viewport3D sits at the bottom. Reported:
the element count of the layout tree, the seconds of ``load`` (parse, read, lay out, build the
scene) and of one more ``layout`` of the same tree, and the number of measure/arrange calls
(one each per element: the work is linear).

    python benchmarks/bench_layout.py [--depth 100] [--siblings 98]
"""

from __future__ import annotations

import argparse
import time

from xaml3d import pipeline
from xaml3d.pipeline import load

NS = 'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"'


def markup(depth: int, siblings: int) -> str:
    inner = "<Viewport3D/>"
    rows = (
        '<Grid.RowDefinitions><RowDefinition Height="Auto"/><RowDefinition/></Grid.RowDefinitions>'
    )
    for _ in range(depth):
        sib = '<Border Width="2" Height="2"/>' * siblings
        inner = f'<Grid>{rows}{sib}<Border Grid.Row="1" Margin="0.5">{inner}</Border></Grid>'
    return f'<Window {NS} Width="800" Height="600">{inner}</Window>'


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--depth", type=int, default=100)
    ap.add_argument("--siblings", type=int, default=98)
    args = ap.parse_args()
    text = markup(args.depth, args.siblings)
    # The scene holds the laid-out boxes, not the layout tree: keep the tree the reader hands
    # to the layout engine, to lay it out once more on its own.
    engine, trees = pipeline.STAGES.layout, []
    pipeline.STAGES = pipeline.STAGES._replace(
        layout=lambda root, size=None: engine(trees.append((root, size)) or root, size)
    )
    t0 = time.perf_counter()
    scene = load(text, text=True)
    t1 = time.perf_counter()
    result = engine(*trees[0])
    t2 = time.perf_counter()
    n = sum(1 for _ in result.nodes())
    vp = scene.viewports[0]
    print(f"{n} elements: load {t1 - t0:.3f} s, layout {t2 - t1:.3f} s, "
          f"{result.measure_calls} measure / {result.arrange_calls} arrange calls; "
          f"viewport {vp.width:g} x {vp.height:g}")  # fmt: skip


if __name__ == "__main__":
    main()
