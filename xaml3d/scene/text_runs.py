"""A TextBlock's text as layout measures it: plain data the reader records on an element-tree
Node (``Node.text``), and the lines layout breaks it into (``Node.text_lines``).

The reader (xaml/visuals_reader, control_content) reads what the text is: its runs with their
FontFamily, FontSize, FontWeight, FontStyle (and, opaque to layout, the brush and text
decorations the drawing needs), its TextWrapping, TextTrimming and Padding. The layout engine
(``xaml3d.layout.text``) measures it with the font metrics of the faces that draw it, at the
width each pass offers, and leaves the lines it broke at the arranged width here; the drawing
sets those lines as they are, so text is broken in one place only. Nothing here measures.
"""

from __future__ import annotations

from dataclasses import dataclass

UI = "Segoe UI"  # WPF's default FontFamily


@dataclass(frozen=True)
class Run:
    """A stretch of text in one format: its FontSize (px), FontWeight (OpenType number),
    italic, FontFamily; ``brush`` and ``decorations`` (the TextDecorations in effect: names of
    OverLine, Baseline, Underline, Strikethrough) are the drawing's (layout ignores them)."""

    text: str
    size: float
    weight: int = 400
    italic: bool = False
    family: str = UI
    brush: object = None
    decorations: frozenset = frozenset()

    def same_format(self, other: Run) -> bool:
        return (self.size, self.weight, self.italic, self.family, self.decorations) == (
            other.size, other.weight, other.italic, other.family, other.decorations
        ) and self.brush == other.brush  # fmt: skip


@dataclass(frozen=True)
class TextContent:
    """What a TextBlock's measure needs. ``base``: the TextBlock's own format; its ``text`` is
    the plain text (a line feed, kept by xml:space="preserve", starts a line). ``inlines``:
    the text as inline runs instead (Run, Bold, Italic, Span...), one tuple of runs per line a
    LineBreak starts (None: plain text). TextTrimming applies to plain text only."""

    base: Run
    inlines: tuple[tuple[Run, ...], ...] | None = None
    wrapping: bool = False  # TextWrapping Wrap or WrapWithOverflow
    trimming: str = "None"  # None | CharacterEllipsis | WordEllipsis
    padding: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)


@dataclass(frozen=True)
class TextLine:
    """One line as layout broke it: its runs (a trimmed line's text ends in the ellipsis),
    each run's advance width, the line's width, height and baseline (from the line's top)."""

    runs: tuple[Run, ...]
    advances: tuple[float, ...]
    width: float
    height: float
    baseline: float
