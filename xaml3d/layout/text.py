"""Measuring text for layout: a TextBlock's (and a control's text's) width and line height.

Widths are the advance widths of the package's font (``xaml3d.fonts``: Open Sans, within a few
percent of Segoe UI's); the line height and baseline are Segoe UI's, as WPF lays a line out
(FontFamily.LineSpacing x FontSize). Widths come from the font's own tables
(``xaml3d.layout.advances``: skia's numbers without importing skia); skia is imported only for
an underline's metrics and for a size those tables do not cover (not above 0, or not finite).
"""

from __future__ import annotations

import functools

from xaml3d.fonts import SEGOE_UI_BASELINE, SEGOE_UI_LINE_SPACING


@functools.lru_cache(maxsize=4096)
def text_width(text: str, size: float, weight: int = 400, italic: bool = False) -> float:
    """The advance width (DIPs) of one line of ``text`` at ``size`` px."""
    if not text:
        return 0.0
    if 0 < size < 3e38:  # finite in float32, as skia holds a size
        from xaml3d.fonts import font_file
        from xaml3d.layout.advances import measure

        return measure(font_file(weight, italic), text, size)
    import skia

    from xaml3d.fonts import typeface

    font = skia.Font(typeface(weight, italic), float(size))
    font.setSubpixel(True)
    font.setHinting(skia.FontHinting.kNone)
    return float(font.measureText(text))


def line_height(size: float) -> float:
    """WPF's height of one line of text at ``size`` px (Segoe UI's LineSpacing)."""
    return SEGOE_UI_LINE_SPACING * size


def baseline(size: float) -> float:
    """Distance from the top of a line to its baseline at ``size`` px."""
    return SEGOE_UI_BASELINE * size


@functools.lru_cache(maxsize=256)
def underline(size: float, weight: int = 400, italic: bool = False) -> tuple[float, float]:
    """(offset below the baseline, thickness) of an underline at ``size`` px: the package
    font's own underline metrics."""
    import skia

    from xaml3d.fonts import typeface

    m = skia.Font(typeface(weight, italic), float(size)).getMetrics()
    return float(m.fUnderlinePosition), float(m.fUnderlineThickness)
