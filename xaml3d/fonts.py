"""The faces xaml3d sets text in, chosen by FontFamily, and the line metrics WPF lays them out by.

WPF's default font is Segoe UI (12 px), which is not free to ship. xaml3d draws it with Open Sans
(Apache 2.0, the ``ttf-opensans`` package): a humanist sans serif whose advance widths are within
a few percent of Segoe UI's ("Hello World" at 12 px: 65.7 px against Segoe UI's 63.8); lines are
laid out with Segoe UI's own line metrics (below), so a TextBlock's box and its baseline sit where
WPF puts them whatever the glyph shapes. WPF's common families are set in the metric-compatible
Liberation faces shipped in ``xaml3d/data/fonts`` (SIL OFL 1.1, unmodified): Arial and Helvetica
in Liberation Sans, Times New Roman in Liberation Serif, Courier New in Liberation Mono: the same
advance of every character and the same vertical metrics, so text lands where WPF puts it, and
those families' line metrics are read from the faces as WPF reads them. docs/layer2d.md says more.

Only file names and numbers live here; ``typeface`` imports skia when text is measured or drawn.
"""

from __future__ import annotations

import functools
import os
import struct
from dataclasses import dataclass

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


FONT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "fonts")


@dataclass(frozen=True)
class Face:
    """A face xaml3d sets a FontFamily in: its name and WPF's line metrics for it, in ems
    (FontFamily.LineSpacing: a line's height; FontFamily.Baseline: the first baseline's depth
    below the line's top)."""

    name: str
    line_spacing: float
    baseline: float


SEGOE_UI = Face("Segoe UI", SEGOE_UI_LINE_SPACING, SEGOE_UI_BASELINE)

# WPF family names (lower case) -> the shipped face: the metric-compatible ones; WPF's composite
# fonts, whose Latin is Arial, Times New Roman or Courier New ("Global User Interface" sets Latin
# in Times New Roman); then Windows families with no free metric-compatible face, set in the
# shipped face of their kind (monospaced, serif; sans serif ones in Segoe UI's stand-in): found
# on any Windows machine, each ends a fallback list there as it does in WPF.
_UI, _SANS, _SERIF, _MONO = "Segoe UI", "Liberation Sans", "Liberation Serif", "Liberation Mono"
_FAMILIES = {
    "segoe ui": _UI, "segoe ui semibold": _UI, "segoe ui light": _UI, "segoe ui semilight": _UI,
    "segoe ui black": _UI, "verdana": _UI, "tahoma": _UI, "calibri": _UI, "trebuchet ms": _UI,
    "microsoft sans serif": _UI, "lucida sans unicode": _UI, "candara": _UI, "corbel": _UI,
    "georgia": _SERIF, "cambria": _SERIF, "constantia": _SERIF, "palatino linotype": _SERIF,
    "book antiqua": _SERIF,
    "arial": _SANS, "helvetica": _SANS, "arimo": _SANS, "liberation sans": _SANS,
    "global sans serif": _SANS,
    "times new roman": _SERIF, "times": _SERIF, "tinos": _SERIF, "liberation serif": _SERIF,
    "global serif": _SERIF, "global user interface": _SERIF,
    "courier new": _MONO, "courier": _MONO, "cousine": _MONO, "liberation mono": _MONO,
    "global monospace": _MONO, "consolas": _MONO, "lucida console": _MONO,
}  # fmt: skip


def family_names(family: str) -> list[str]:
    """The family names of a FontFamily value, in order: its comma-separated fallback list,
    each name without the location before a ``#`` (``./Fonts/#My Font``), lower case."""
    return [n.rpartition("#")[2].strip().lower() for n in family.split(",") if n.strip()]


@functools.lru_cache(maxsize=256)
def face_of(family: str = "Segoe UI") -> Face:
    """The face ``family`` is set in: the first name of its fallback list that xaml3d ships a
    face for, else Segoe UI's stand-in (any family xaml3d has no face for, as WPF's default)."""
    for name in family_names(family or ""):
        if _FAMILIES.get(name) == _UI:
            return SEGOE_UI
        if name in _FAMILIES:
            path = os.path.join(FONT_DIR, _FAMILIES[name].replace(" ", "") + "-Regular.ttf")
            return Face(_FAMILIES[name], *_line_metrics(path))
    return SEGOE_UI


@functools.lru_cache(maxsize=8)
def _line_metrics(path: str) -> tuple[float, float]:
    """(LineSpacing, Baseline) in ems as WPF (DirectWrite) reads them from a face: the
    Windows ascent and descent of OS/2, plus the line gap by which hhea's line is taller."""
    with open(path, "rb") as f:
        data = f.read()
    tables = {}
    for i in range(struct.unpack_from(">H", data, 4)[0]):
        tag, _, offset, _ = struct.unpack_from(">4sIII", data, 12 + 16 * i)
        tables[tag] = offset
    em = struct.unpack_from(">H", data, tables[b"head"] + 18)[0]
    ascender, descender, gap = struct.unpack_from(">hhh", data, tables[b"hhea"] + 4)
    win_ascent, win_descent = struct.unpack_from(">HH", data, tables[b"OS/2"] + 74)
    line_gap = max(0, ascender - descender + gap - win_ascent - win_descent)
    return (win_ascent + win_descent + line_gap) / em, win_ascent / em


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
def font_file(weight: int = 400, italic: bool = False, family: str = "Segoe UI") -> str:
    """The file of ``family``'s face (``face_of``) nearest ``weight``, italic or not. Segoe UI's
    stand-in: the Open Sans file ``ttf_opensans.opensans`` would choose (the nearest weight, the
    heavier of two as near); a Liberation family: its Bold face from weight 600 (SemiBold) up,
    as WPF's font matching takes the heavier face above Medium, else its Regular."""
    weight, italic = int(weight), bool(italic)
    face = face_of(family)
    if face is not SEGOE_UI:
        style = ("Bold" if weight >= 600 else "") + ("Italic" if italic else "")
        return os.path.join(FONT_DIR, f"{face.name.replace(' ', '')}-{style or 'Regular'}.ttf")
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


@functools.lru_cache(maxsize=32)
def typeface(weight: int = 400, italic: bool = False, family: str = "Segoe UI"):
    """A skia Typeface of the package's face for ``family``. Loaded through an empty font
    manager: the system's fontconfig is never asked (it prints warnings on some machines, and a
    system font would make pictures differ between machines)."""
    import skia

    return skia.FontMgr.New_Custom_Empty().makeFromFile(font_file(weight, italic, family))
