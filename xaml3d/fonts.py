"""The font xaml3d sets text in, and the line metrics of the font WPF would use.

WPF's default font is Segoe UI (12 px), which is not free to ship. xaml3d draws every FontFamily
with Open Sans (Apache 2.0, the ``ttf-opensans`` package): a humanist sans serif whose advance
widths are within a few percent of Segoe UI's ("Hello World" at 12 px: 65.7 px against Segoe
UI's 63.8). Lines are laid out with Segoe UI's own line metrics (below), so a TextBlock's box
and its baseline sit where WPF puts them whatever the glyph shapes. docs/layer2d.md says more.

Only file names and numbers live here; ``typeface`` imports skia when text is measured or drawn.
"""

from __future__ import annotations

import functools
import os

# Segoe UI's hhea metrics in em units (2048 per em): WPF's FontFamily.LineSpacing is
# (ascender + descender) / em = 1.33, and the first baseline sits at ascender / em below the top.
SEGOE_UI_LINE_SPACING = (2210 + 514) / 2048
SEGOE_UI_BASELINE = 2210 / 2048
DEFAULT_FONT_SIZE = 12.0  # WPF's default FontSize (px)

WEIGHTS = {
    "Thin": 100, "ExtraLight": 200, "UltraLight": 200, "Light": 300, "Normal": 400,
    "Regular": 400, "Medium": 500, "DemiBold": 600, "SemiBold": 600, "Bold": 700,
    "ExtraBold": 800, "UltraBold": 800, "Black": 900, "Heavy": 900, "ExtraBlack": 950,
    "UltraBlack": 950,
}  # fmt: skip


# The files of the ``ttf-opensans`` package, by (weight, italic). They are found in its folder
# without importing it: its module imports Pillow's ImageFont (with PIL.Image about 10 ms),
# which a command that only lays text out (``validate`` of a window with a Button) never needs.
_FILES = {
    (300, False): "OpenSans-Light", (300, True): "OpenSans-LightItalic",
    (400, False): "OpenSans-Regular", (400, True): "OpenSans-Italic",
    (600, False): "OpenSans-SemiBold", (600, True): "OpenSans-SemiBoldItalic",
    (700, False): "OpenSans-Bold", (700, True): "OpenSans-BoldItalic",
    (800, False): "OpenSans-ExtraBold", (800, True): "OpenSans-ExtraBoldItalic",
}  # fmt: skip


@functools.lru_cache(maxsize=64)
def font_file(weight: int = 400, italic: bool = False) -> str:
    """The Open Sans file nearest ``weight`` (and italic or not): ``ttf_opensans.opensans``'s
    choice (the nearest weight, the heavier of two as near)."""
    weight, italic = int(weight), bool(italic)
    _, name = min(
        ((w, n) for (w, i), n in _FILES.items() if i == italic),
        key=lambda f: (abs(f[0] - weight), f[0] < weight),
    )
    import importlib.util

    spec = importlib.util.find_spec("ttf_opensans")
    for folder in (spec and spec.submodule_search_locations) or ():
        path = os.path.join(folder, "ttf", name + ".ttf")
        if os.path.isfile(path):
            return path
    import ttf_opensans  # a layout of the package other than this one's

    return str(ttf_opensans.opensans(font_weight=weight, italic=italic).path)


@functools.lru_cache(maxsize=16)
def typeface(weight: int = 400, italic: bool = False):
    """A skia Typeface of the package's font. Loaded through an empty font manager: the
    system's fontconfig is never asked (it prints warnings on some machines, and a system font
    would make pictures differ between machines)."""
    import skia

    return skia.FontMgr.New_Custom_Empty().makeFromFile(font_file(weight, italic))
