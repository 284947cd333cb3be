"""Make the small PNG textures used by xaml3d's samples and reference-image suite.

Run from the repository root (Pillow only, deterministic, no network):

    python tools/make_sample_texture.py

Writes two files:

- ``samples/textures/checker.png``: 64x64, an 8x8 checkerboard of light and dark grey squares
  with a bold orange letter "F" in the upper-left area. The "F" has no mirror or rotation
  symmetry, so a flipped or rotated texture mapping is obvious at a glance.
- ``tests/reference/brush/textures/quadrants.png``: 32x32, four flat 16x16 quadrants (top-left
  blue #0000FF, top-right lime #00FF00, bottom-left yellow #FFFF00, bottom-right magenta
  #FF00FF). Flat colours make the expected pictures of the ImageBrush reference cases exact
  (only pixels at a quadrant boundary may blend, depending on texture filtering).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from PIL import Image, ImageDraw

ROOT = Path(__file__).resolve().parent.parent

LIGHT = (224, 224, 224, 255)
DARK = (96, 96, 96, 255)
MARK = (255, 128, 0, 255)

QUADRANT_COLOURS = {
    "top_left": (0, 0, 255, 255),
    "top_right": (0, 255, 0, 255),
    "bottom_left": (255, 255, 0, 255),
    "bottom_right": (255, 0, 255, 255),
}


def make_checker(size: int = 64, cells: int = 8) -> Image.Image:
    """The checkerboard with an orientation mark ("F", upper left, upright when u right, v down)."""
    img = Image.new("RGBA", (size, size), LIGHT)
    draw = ImageDraw.Draw(img)
    cell = size // cells
    for row in range(cells):
        for col in range(cells):
            if (row + col) % 2:
                x0, y0 = col * cell, row * cell
                draw.rectangle([x0, y0, x0 + cell - 1, y0 + cell - 1], fill=DARK)
    # The "F": a vertical stem and two arms of different lengths, in texture pixels.
    unit = size // 16
    draw.rectangle([2 * unit, 2 * unit, 4 * unit - 1, 12 * unit - 1], fill=MARK)  # stem
    draw.rectangle([4 * unit, 2 * unit, 10 * unit - 1, 4 * unit - 1], fill=MARK)  # top arm
    draw.rectangle([4 * unit, 6 * unit, 8 * unit - 1, 8 * unit - 1], fill=MARK)  # middle arm
    return img


def make_quadrants(size: int = 32) -> Image.Image:
    """Four flat quadrants; see the module docstring for the colours."""
    half = size // 2
    img = Image.new("RGBA", (size, size))
    draw = ImageDraw.Draw(img)
    draw.rectangle([0, 0, half - 1, half - 1], fill=QUADRANT_COLOURS["top_left"])
    draw.rectangle([half, 0, size - 1, half - 1], fill=QUADRANT_COLOURS["top_right"])
    draw.rectangle([0, half, half - 1, size - 1], fill=QUADRANT_COLOURS["bottom_left"])
    draw.rectangle([half, half, size - 1, size - 1], fill=QUADRANT_COLOURS["bottom_right"])
    return img


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=ROOT, help="repository root to write into")
    args = parser.parse_args(argv)
    outputs = {
        args.root / "samples" / "textures" / "checker.png": make_checker(),
        args.root / "tests" / "reference" / "brush" / "textures" / "quadrants.png": (
            make_quadrants()
        ),
    }
    for path, img in outputs.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        # optimize=False and no metadata keep the bytes identical from run to run.
        img.save(path, format="PNG")
        print(f"wrote {path.relative_to(args.root)} ({img.width}x{img.height})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
