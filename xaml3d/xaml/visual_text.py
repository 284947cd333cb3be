"""The text and boxes of a visual's elements, as WPF's OnRender draws them (visuals_reader).

Covers a TextBlock's (and a control's) text: its content (Text, Content, as attributes or
property elements, white space as XAML reads it, access keys: ``text_content``; a TextBlock's
inlines in their own formats and lines: ``inline_text``), the inherited
Foreground, FontSize, FontWeight, FontStyle and FontFamily, TextAlignment, TextWrapping and
TextTrimming (CharacterEllipsis, WordEllipsis) to the width the layout gives the TextBlock, and
one TextDrawing per line at Segoe UI's line metrics (``xaml3d.text_metrics``). The brushes,
the inherited font and a Border-like box's Background / BorderBrush band are ``visual_style``'s.
"""

from __future__ import annotations

import math

from xaml3d.access_text import access_text
from xaml3d.scene.drawing import (
    DrawingGroup,
    GeometryDrawing,
    RectangleGeometry,
    TextDrawing,
)
from xaml3d.text_metrics import UI, baseline, line_height, text_width, uncovered
from xaml3d.xaml import values as V
from xaml3d.xaml.context import qname, split_markup
from xaml3d.xaml.inline_text import Format, has_inlines, laid_out, line_width
from xaml3d.xaml.text_content import (
    ACCESS_KEY_CONTROLS,
    content_text,
    holder_text,
    property_element,
)
from xaml3d.xaml.visual_style import (
    font_style,
    foreground_brush,
)

# Aero2 (PresentationFramework.Aero2, themes/Aero2.NormalColor.xaml): the resting state.


def text_of(el) -> str:
    """The text an element shows: its Text or Content, as an attribute or a property element
    (``text_content``), else its content's text; through AccessText for the controls whose
    template recognizes access keys (``_Name`` shows ``Name``)."""
    text = _plain_text(el)
    if isinstance(el.tag, str) and qname(el.tag)[1] in ACCESS_KEY_CONTROLS:
        return access_text(text)
    return text


def _plain_text(el) -> str:
    for prop in ("Text", "Content"):
        s = el.get(prop)
        if s is not None and split_markup(s) is None:
            return " ".join(s.split())
        if s is not None:
            return ""
        holder = property_element(el, prop)
        if holder is not None:
            return holder_text(holder) or ""
    return content_text(el)


_WRAPS = ("NoWrap", "Wrap", "WrapWithOverflow")
_TRIMS = ("None", "CharacterEllipsis", "WordEllipsis")
ELLIPSIS = "\u2026"
# a line laid out again at its arranged width may meet a width rounded to whole pixels below
# the measured one (UseLayoutRounding): so much is let through rather than wrapped or trimmed
_SLACK = 0.5


def wraps(v) -> bool:
    """Whether a TextBlock breaks its text into lines (TextWrapping Wrap or WrapWithOverflow)."""
    return v.get("TextWrapping", lambda s: V.parse_enum(s, _WRAPS), "NoWrap") != "NoWrap"


def trimming(v) -> str:
    return v.get("TextTrimming", lambda s: V.parse_enum(s, _TRIMS), "None")


def trim(
    line: str, font: float, weight: int, italic: bool, width: float, mode: str, family: str = UI
) -> str:
    """A line cut to ``width`` as TextTrimming does: the longest start of it (whole words for
    WordEllipsis, when one fits) followed by an ellipsis; the line itself when it fits."""
    if mode == "None" or text_width(line, font, weight, italic, family) <= width + _SLACK:
        return line

    def fits(k: int) -> bool:
        ellipsized = line[:k].rstrip() + ELLIPSIS
        return text_width(ellipsized, font, weight, italic, family) <= width + _SLACK

    if mode == "WordEllipsis":
        ends = [i for i in range(1, len(line)) if line[i] == " " and line[i - 1] != " "]
        best = max((k for k in ends if fits(k)), default=None)
        if best is not None:
            return line[:best].rstrip() + ELLIPSIS
    lo, hi = 0, len(line)  # the longest start that fits with the ellipsis (bisection)
    while lo < hi:
        mid = (lo + hi + 1) // 2
        if fits(mid):
            lo = mid
        else:
            hi = mid - 1
    return line[:lo].rstrip() + ELLIPSIS


def wrapped_lines(
    text: str, font: float, weight: int, italic: bool, width: float, family: str = UI
) -> list[str]:
    """``text`` broken into lines no wider than ``width`` at spaces (a word wider than the
    line keeps a line of its own). A line feed (kept by xml:space="preserve") starts a new
    line, as it does in WPF's text formatter."""
    if "\n" in text:
        return [x for part in text.split("\n") for x in (wrapped_lines(part, font, weight, italic,
                                                               width, family) or [""])]  # fmt: skip
    if not text or not math.isfinite(width):
        return [text] if text else []
    lines: list[str] = []
    cur = ""
    for word in text.split(" "):
        trial = f"{cur} {word}" if cur else word
        if cur and text_width(trial, font, weight, italic, family) > width:
            lines.append(cur)
            cur = word
        else:
            cur = trial
    lines.append(cur)
    return lines


def text_drawing(r, el, v, font: float, x: float, y: float, w: float, align_center: bool = False):
    """The element's text as one TextDrawing per line (a DrawingGroup when it wraps). ``w``:
    the width laid out for it: a TextBlock wraps (TextWrapping) and trims (TextTrimming) its
    lines to it, as WPF formats the text again at the arranged width."""
    block = qname(el.tag)[1] == "TextBlock"
    if block and has_inlines(el):
        return _inline_text(r, el, v, font, x, y, w, align_center)
    text = text_of(el)
    if not text:
        return None
    weight, italic, family = font_style(el, r)
    wrapping = block and wraps(v)
    width = w + _SLACK if wrapping else math.inf
    mode = trimming(v) if block else "None"
    alignment = v.get("TextAlignment", lambda s: V.parse_enum(s, ("Left", "Center", "Right",
                                                                 "Justify")), "Left")  # fmt: skip
    brush = foreground_brush(r, el)
    out = []
    for i, line in enumerate(wrapped_lines(text, font, weight, italic, width, family)):
        line = trim(line, font, weight, italic, w, mode, family)
        if not line:
            continue  # an empty line (between two line feeds) takes its height only
        tw = text_width(line, font, weight, italic, family)
        lx = x
        if align_center or alignment == "Center":
            lx += (w - tw) / 2
        elif alignment == "Right":
            lx += w - tw
        ly = y + i * line_height(font, family) + baseline(font, family)
        warn_uncovered(r, el, line, weight, italic, family)
        out.append(TextDrawing(
            text=line, origin=(lx, ly), font_size=font, weight=weight, italic=italic,
            family=family, brush=brush, **r.ctx.position(el),
        ))  # fmt: skip
    if not out:
        return None
    return out[0] if len(out) == 1 else DrawingGroup(children=tuple(out))


def warn_uncovered(r, el, text: str, weight: int, italic: bool, family: str) -> None:
    """TXT001, once per script in a document: characters of ``text`` that neither the face
    nor any installed font has (drawn as the face's empty box)."""
    lacking = uncovered(text, weight, italic, family)
    if not lacking:
        return
    from xaml3d.font_fallback import script_of

    for script in dict.fromkeys(script_of(c) for c in lacking):
        chars = "".join(dict.fromkeys(c for c in lacking if script_of(c) == script))
        codes = " ".join(f"U+{ord(c):04X}" for c in chars[:4]) + (" ..." if len(chars) > 4 else "")
        r.ctx.diag(
            "TXT001",
            f'no installed font has the {script} characters of "{text}" ({codes}): '
            "they are drawn as empty boxes (install a font that covers the script)",
            el,
            once=("TXT001", script),
        )


def _alignment(v) -> str:
    return v.get("TextAlignment", lambda s: V.parse_enum(s, ("Left", "Center", "Right",
                                                            "Justify")), "Left")  # fmt: skip


def base_format(r, el, font: float) -> Format:
    """The TextBlock's own text format, that its inlines start from."""
    weight, italic, family = font_style(el, r)
    return Format(
        size=font, weight=weight, italic=italic, brush=foreground_brush(r, el), family=family
    )


def _inline_text(r, el, v, font: float, x: float, y: float, w: float, align_center: bool):
    """A TextBlock's inlines (``inline_text``): one TextDrawing per run of a line, on the
    line's shared baseline, an underlined run over a bar at the font's underline metrics."""
    from xaml3d.text_metrics import underline

    alignment = _alignment(v)
    width = w + _SLACK if wraps(v) else math.inf
    out = []
    top = y
    for line, height, base in laid_out(r, el, base_format(r, el, font), width):
        lx = x
        if align_center or alignment == "Center":
            lx += (w - line_width(line)) / 2
        elif alignment == "Right":
            lx += w - line_width(line)
        for text, fmt in line:
            tw = fmt.width(text)
            out.append(TextDrawing(
                text=text, origin=(lx, top + base), font_size=fmt.size, weight=fmt.weight,
                italic=fmt.italic, family=fmt.family, brush=fmt.brush, **r.ctx.position(el),
            ))  # fmt: skip
            warn_uncovered(r, el, text, fmt.weight, fmt.italic, fmt.family)
            if fmt.underline and tw > 0:
                at, thick = underline(fmt.size, fmt.weight, fmt.italic, fmt.family)
                bar = RectangleGeometry((lx, top + base + at, tw, thick))
                out.append(GeometryDrawing(bar, brush=fmt.brush))
            lx += tw
        top += height
    if not out:
        return None
    return out[0] if len(out) == 1 else DrawingGroup(children=tuple(out))
