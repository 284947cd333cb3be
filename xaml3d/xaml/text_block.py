"""A TextBlock's text recorded for layout (``scene.text_runs.TextContent``): read, not measured.

The reader records what a TextBlock shows and in which fonts: its plain text (``visual_text``)
in the FontFamily, FontSize, FontWeight and FontStyle in effect, or its inlines as runs in their
own formats, one tuple per line a LineBreak starts (``inline_text``); its TextWrapping,
TextTrimming and Padding. The layout engine measures it (``xaml3d.layout.text``) and breaks its
lines; the drawing (``visual_text.block_drawing``) sets the lines layout left on the Node.
"""

from __future__ import annotations

from dataclasses import replace

from xaml3d.scene.text_runs import Run, TextContent
from xaml3d.xaml import values as V
from xaml3d.xaml.inline_text import has_inlines, inline_lines
from xaml3d.xaml.panels_reader import parse_thickness
from xaml3d.xaml.visual_style import font_style
from xaml3d.xaml.visual_text import base_format, text_of, trimming, wraps


def text_content(v, el, font: float) -> TextContent:
    """The TextBlock ``el``'s text at FontSize ``font``, as layout measures it."""
    r = v.r
    pad = v.get("Padding", parse_thickness, (0.0,) * 4)
    # its TextDecorations (local, Style, trigger) draw over all its text, inlines included
    deco = v.get("TextDecorations", V.parse_text_decorations, frozenset())
    if has_inlines(el):  # runs in their own fonts, LineBreaks (inline_text)
        base = replace(base_format(r, el, font), decorations=deco)
        lines = tuple(tuple(_run(text, f) for text, f in line)
                      for line in inline_lines(r, el, base))  # fmt: skip
        return TextContent(base=_run("", base), inlines=lines, wrapping=wraps(v), padding=pad)
    weight, italic, family = font_style(el, r)
    base = Run(text_of(el), font, weight, italic, family, decorations=deco)
    return TextContent(base=base, wrapping=wraps(v), trimming=trimming(v), padding=pad)


def _run(text: str, f) -> Run:
    return Run(text, f.size, f.weight, f.italic, f.family, f.brush, f.decorations)
