"""Text metrics of the faces text is set in (font facts, for layout and the 2D drawings): a
TextBlock's (and a control's text's) width and line height.

Widths are the advance widths of the face the FontFamily is set in (``xaml3d.fonts``: Open Sans
for Segoe UI, within a few percent of its widths; the metric-compatible Liberation faces for
Arial, Times New Roman, Courier New); the line height and baseline are that family's, as WPF lays
a line out (FontFamily.LineSpacing x FontSize). Widths come from the face's own tables
(``xaml3d.text_advances``: skia's numbers without importing skia); skia is imported only for
an underline's metrics, for a size those tables do not cover (not above 0, or not finite) and
for characters the face lacks, measured in the system's font that has them
(``xaml3d.font_fallback``), as they are drawn.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

from xaml3d.fonts import face_of

UI = "Segoe UI"  # WPF's default FontFamily


def _missing(text: str, weight: int, italic: bool, family: str) -> list[bool] | None:
    """One bool per character of ``text``, whether the face lacks it; None when it has all."""
    from xaml3d.fonts import font_file
    from xaml3d.text_advances import font_tables

    glyphs = font_tables(font_file(weight, italic, family)).glyphs
    missing = [ord(c) not in glyphs for c in text]
    return missing if any(missing) else None


def _skia_width(text: str, size: float, typeface) -> float:
    import skia

    font = skia.Font(typeface, float(size))
    font.setSubpixel(True)
    font.setHinting(skia.FontHinting.kNone)
    return float(font.measureText(text))


@functools.lru_cache(maxsize=4096)
def text_width(
    text: str, size: float, weight: int = 400, italic: bool = False, family: str = UI
) -> float:
    """The advance width (DIPs) of one line of ``text`` at ``size`` px in ``family``."""
    if not text:
        return 0.0
    from xaml3d.fonts import font_file, typeface

    if not 0 < size < 3e38:  # not finite in float32, as skia holds a size
        return _skia_width(text, size, typeface(weight, italic, family))
    from xaml3d.text_advances import measure

    path = font_file(weight, italic, family)
    missing = _missing(text, weight, italic, family)
    if missing is None:
        return measure(path, text, size)
    from xaml3d.font_fallback import runs

    return sum(
        measure(path, run, size) if tf is None else _skia_width(run, size, tf)
        for run, tf in runs(text, missing, weight, italic)
    )


def uncovered(text: str, weight: int = 400, italic: bool = False, family: str = UI) -> str:
    """The characters of ``text`` that neither ``family``'s face nor any installed font has
    (drawn as the face's empty box)."""
    missing = _missing(text, weight, italic, family) if text else None
    if missing is None:
        return ""
    from xaml3d.font_fallback import uncovered as lacking

    return lacking(text, missing, weight, italic)


def line_height(size: float, family: str = UI) -> float:
    """WPF's height of one line of text at ``size`` px (the family's LineSpacing)."""
    return face_of(family).line_spacing * size


def baseline(size: float, family: str = UI) -> float:
    """Distance from the top of a line to its baseline at ``size`` px."""
    return face_of(family).baseline * size


@functools.lru_cache(maxsize=256)
def underline(
    size: float, weight: int = 400, italic: bool = False, family: str = UI
) -> tuple[float, float]:
    """(offset below the baseline, thickness) of an underline at ``size`` px: the face's own
    underline metrics."""
    import skia

    from xaml3d.fonts import typeface

    m = skia.Font(typeface(weight, italic, family), float(size)).getMetrics()
    return float(m.fUnderlinePosition), float(m.fUnderlineThickness)


class DecorationMetrics(NamedTuple):
    """A face's text-decoration metrics at one size, in px: offsets from the baseline (down
    positive), thicknesses, and its ascent (positive, above the baseline)."""

    underline: float
    underline_thickness: float
    strikeout: float
    strikeout_thickness: float
    ascent: float


def decoration_metrics(
    size: float, weight: int = 400, italic: bool = False, family: str = UI
) -> DecorationMetrics:
    """The face's own underline and strikeout metrics at ``size`` px (skia's FontMetrics: the
    font's post and OS/2 tables), and its ascent; a face without strikeout metrics takes the
    usual place, 0.3 em above the baseline, in the underline's thickness."""
    import skia

    from xaml3d.fonts import typeface

    m = skia.Font(typeface(weight, italic, family), float(size)).getMetrics()
    thick = float(m.fUnderlineThickness)
    strike, strike_thick = float(m.fStrikeoutPosition), float(m.fStrikeoutThickness)
    if not strike_thick:
        strike, strike_thick = -0.3 * float(size), thick
    return DecorationMetrics(float(m.fUnderlinePosition), thick, strike, strike_thick,
                             -float(m.fAscent))  # fmt: skip
