"""A TextBlock's inlines as WPF reads them: Run, Span, Bold, Italic, Underline, Hyperlink and
LineBreak (visuals_reader, text_block; the TextBlock step of the 2D layer), written in the
TextBlock or in a ``<TextBlock.Inlines>`` property element.

Each inline takes its own FontFamily, FontWeight, FontStyle, FontSize, Foreground and
TextDecorations (Underline) over those it inherits; Bold, Italic and Underline set theirs, a
Hyperlink draws in WPF's #FF0066CC, underlined. A Run's text is its Text attribute, its
``<Run.Text>`` or its content. The text is collapsed as XAML collapses it (runs of white space
become one space, across the inlines; none at the start and the end of the TextBlock, nor
around a LineBreak), unless xml:space="preserve" keeps it as written (a line feed then breaks
the line). The result is the runs of each line a LineBreak starts, in their formats: layout
measures and wraps them (``xaml3d.layout.text``), each in its own font.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from xaml3d.fonts import WEIGHTS
from xaml3d.scene.text_runs import UI
from xaml3d.scene.types import SolidColorBrush
from xaml3d.xaml import values as V
from xaml3d.xaml.brushes_reader import brush_property
from xaml3d.xaml.context import qname, split_markup
from xaml3d.xaml.text_content import (
    holder_text,
    is_white,
    preserves_space,
    property_element,
    split_words,
)

# the inline elements; any other element inside a TextBlock (InlineUIContainer...) is skipped
_INLINES = {"Run", "Span", "Bold", "Italic", "Underline", "Hyperlink", "LineBreak"}
HYPERLINK = SolidColorBrush(color=(0.0, 0x66 / 255, 0xCC / 255, 1.0))  # WPF's Hyperlink style


@dataclass(frozen=True)
class Format:
    """How a run is drawn: FontSize, FontWeight (OpenType number), italic, brush, the
    TextDecorations in effect (its own and its enclosing inlines'), FontFamily."""

    size: float
    weight: int
    italic: bool
    brush: object
    decorations: frozenset = frozenset()
    family: str = UI


Line = list  # of (text, Format) runs, left to right


def has_inlines(el) -> bool:
    """Whether a TextBlock's content holds inline elements, directly or in a
    ``<TextBlock.Inlines>`` property element (else its text is plain)."""
    if el.get("Text") is not None or property_element(el, "Text") is not None:
        return False
    return any(isinstance(k.tag, str) and (qname(k.tag)[1] in _INLINES
                                           or qname(k.tag)[1].endswith(".Inlines"))
               for k in el)  # fmt: skip


def _own(r, el, fmt: Format) -> Format:
    """``fmt`` with what the inline element ``el`` sets itself."""
    local = qname(el.tag)[1]
    if local == "Bold":
        fmt = replace(fmt, weight=700)
    elif local == "Italic":
        fmt = replace(fmt, italic=True)
    elif local in ("Underline", "Hyperlink"):
        fmt = replace(fmt, decorations=fmt.decorations | {"Underline"})
    if local == "Hyperlink":
        fmt = replace(fmt, brush=HYPERLINK)
    w = el.get("FontWeight")
    if w is not None and split_markup(w) is None:
        fmt = replace(fmt, weight=WEIGHTS.get(w.strip(), fmt.weight))
    family = el.get("FontFamily")
    if family is not None and split_markup(family) is None and family.strip():
        fmt = replace(fmt, family=family.strip())
    s = el.get("FontStyle")
    if s is not None and split_markup(s) is None:
        fmt = replace(fmt, italic=s.strip() in ("Italic", "Oblique"))
    size = el.get("FontSize")
    if size is not None and split_markup(size) is None:
        from xaml3d.xaml.panels_reader import parse_length

        try:
            value = parse_length(size)
        except ValueError:
            value = math.nan
        if value == value and 0 < value < math.inf:
            fmt = replace(fmt, size=value)
    p = r.props(el)
    # an inline's TextDecorations draw over its text and its children's, with those of the
    # inlines around it (WPF gathers every enclosing level's when it sets a run)
    own = p.value("TextDecorations", V.parse_text_decorations, frozenset())
    if own:
        fmt = replace(fmt, decorations=fmt.decorations | own)
    if "Foreground" in p.attrs or "Foreground" in p.elems:
        brush = brush_property(r, p, "Foreground")
        if brush is not None:
            fmt = replace(fmt, brush=brush)
    return fmt


def _tokens(r, el, fmt: Format, out: list) -> None:
    """The text and breaks of an inline element's content, in order: (text, Format) or None
    for a LineBreak."""
    if el.text:
        out.append((el.text, fmt))
    for k in el:
        if isinstance(k.tag, str):
            local = qname(k.tag)[1]
            if local == "LineBreak":
                out.append(None)
            elif local in _INLINES:
                own = _own(r, k, fmt)
                text = k.get("Text") if local == "Run" else None
                holder = property_element(k, "Text") if local == "Run" else None
                if text is not None and split_markup(text) is None:
                    out.append((text, own))
                elif holder is not None:  # <Run.Text>...</Run.Text>
                    out.append((holder_text(holder) or "", own))
                else:
                    _tokens(r, k, own, out)
            elif local.endswith(".Inlines"):  # <TextBlock.Inlines>, <Span.Inlines>...
                _tokens(r, k, fmt, out)
        if k.tail:
            out.append((k.tail, fmt))


def inline_lines(r, el, base: Format) -> list[Line]:
    """A TextBlock's inlines as lines of runs (white space collapsed as XAML does, or kept as
    written under xml:space="preserve", a line feed then starting a line)."""
    tokens: list = []
    _tokens(r, el, base, tokens)
    if preserves_space(el):
        return _preserved(tokens)
    lines: list[Line] = [[]]
    space = True  # after the start of a line: leading white space goes
    for t in tokens:
        if t is None:
            lines.append([])
            space = True
            continue
        text, fmt = t
        parts = split_words(text)
        if not parts:
            if not space and text:
                lines[-1].append((" ", fmt))
                space = True
            continue
        s = (" " if is_white(text[0]) and not space else "") + " ".join(parts)
        s += " " if is_white(text[-1]) else ""
        lines[-1].append((s, fmt))
        space = s.endswith(" ")
    out = []
    for line in lines:  # no white space at a line's end (before a LineBreak or the end)
        while line and line[-1][0].endswith(" "):
            text = line[-1][0].rstrip(" ")
            line[-1:] = [(text, line[-1][1])] if text else []
        out.append(line)
    return out


def _preserved(tokens: list) -> list[Line]:
    """The runs as written (xml:space="preserve"): a LineBreak or a line feed starts a line."""
    lines: list[Line] = [[]]
    for t in tokens:
        if t is None:
            lines.append([])
            continue
        text, fmt = t
        for i, part in enumerate(text.split("\n")):
            if i:
                lines.append([])
            if part:
                lines[-1].append((part, fmt))
    return lines
