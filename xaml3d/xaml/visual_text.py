"""The text and boxes of a visual's elements, as WPF's OnRender draws them (visuals_reader).

Covers a TextBlock's (and a control's) text: its content (Text, Content, as attributes or
property elements, white space as XAML reads it, access keys: ``text_content``; a TextBlock's
inlines in their own formats: ``inline_text``), the inherited Foreground, FontSize,
FontWeight, FontStyle and FontFamily, TextAlignment, TextWrapping and TextTrimming. A
TextBlock's lines are the ones layout broke (and trimmed) at its arranged width
(``Node.text_lines``, ``xaml3d.layout.text``): ``block_drawing`` sets them as they are, one
TextDrawing per run of a line. A control's text (``text_drawing``) is set here, one TextDrawing
per line at its font's line metrics (``xaml3d.text_metrics``). The brushes, the inherited font
and a Border-like box's Background / BorderBrush band are ``visual_style``'s.
"""

from __future__ import annotations

from xaml3d.access_text import access_text
from xaml3d.scene.drawing import (
    DrawingGroup,
    GeometryDrawing,
    RectangleGeometry,
    TextDrawing,
)
from xaml3d.text_metrics import baseline, line_height, text_width, uncovered
from xaml3d.xaml import values as V
from xaml3d.xaml.context import qname, split_markup
from xaml3d.xaml.inline_text import Format
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


def wraps(v) -> bool:
    """Whether a TextBlock breaks its text into lines (TextWrapping Wrap or WrapWithOverflow)."""
    return v.get("TextWrapping", lambda s: V.parse_enum(s, _WRAPS), "NoWrap") != "NoWrap"


def trimming(v) -> str:
    return v.get("TextTrimming", lambda s: V.parse_enum(s, _TRIMS), "None")


def text_lines(text: str) -> list[str]:
    """A control's one-line text split where a line feed (kept by xml:space="preserve") starts
    a new line, as WPF's text formatter does; none for no text. (Lines broken to a width are a
    TextBlock's, broken by layout: ``xaml3d.layout.text``.)"""
    return text.split("\n") if text else []


def text_drawing(r, el, v, font: float, x: float, y: float, w: float, align_center: bool = False):
    """A control's text (a ToolBar's buttons, a ComboBox's selection...) as one TextDrawing
    per line (a DrawingGroup of several lines)."""
    text = text_of(el)
    if not text:
        return None
    weight, italic, family = font_style(el, r)
    alignment = _alignment(v)
    brush = foreground_brush(r, el)
    out = []
    for i, line in enumerate(text_lines(text)):
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


def block_drawing(r, el, v, n, x: float, y: float, w: float):
    """A TextBlock's text in ``w`` (its arranged width less its Padding) as the lines layout
    broke it (``Node.text_lines``, ``xaml3d.layout.text``): one TextDrawing per run of a
    line, on the line's baseline, aligned by TextAlignment; a run's TextDecorations as bars in
    its brush (``decoration_bars``)."""

    alignment = _alignment(v)
    plain = n.text is not None and n.text.inlines is None
    brush = foreground_brush(r, el) if plain else None  # a plain text's: the TextBlock's
    out = []
    top = y
    for i, line in enumerate(n.text_lines):
        lx = x
        if alignment == "Center":
            lx += (w - line.width) / 2
        elif alignment == "Right":
            lx += w - line.width
        # plain text: its i-th line at i line heights; inlines: under the lines above
        ly = y + i * line.height if plain else top
        for run, tw in zip(line.runs, line.advances, strict=True):
            if plain and not run.text:
                continue  # an empty line (between two line feeds) takes its height only
            out.append(TextDrawing(
                text=run.text, origin=(lx, ly + line.baseline), font_size=run.size,
                weight=run.weight, italic=run.italic, family=run.family,
                brush=brush if plain else run.brush, **r.ctx.position(el),
            ))  # fmt: skip
            warn_uncovered(r, el, run.text, run.weight, run.italic, run.family)
            if run.decorations and tw > 0:
                for at, thick in decoration_bars(run):
                    bar = RectangleGeometry((lx, ly + line.baseline + at, tw, thick))
                    out.append(GeometryDrawing(bar, brush=brush if plain else run.brush))
            lx += tw
        top += line.height
    if not out:
        return None
    return out[0] if len(out) == 1 else DrawingGroup(children=tuple(out))


def decoration_bars(run) -> list[tuple[float, float]]:
    """(offset from the baseline, thickness) of each of the run's TextDecorations at the font's
    recommended place and thickness, as WPF draws them: Underline at the face's underline
    position, Strikethrough at its strikeout position, OverLine at its ascent above the
    baseline, Baseline on it; Strikethrough in its strikeout thickness, the others in the
    underline thickness."""
    from xaml3d.text_metrics import decoration_metrics

    m = decoration_metrics(run.size, run.weight, run.italic, run.family)
    places = {
        "Underline": (m.underline, m.underline_thickness),
        "Strikethrough": (m.strikeout, m.strikeout_thickness),
        "OverLine": (-m.ascent, m.underline_thickness),
        "Baseline": (0.0, m.underline_thickness),
    }
    return [places[d] for d in ("OverLine", "Strikethrough", "Baseline", "Underline")
            if d in run.decorations]  # fmt: skip


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
