"""A TextBlock's measure and its lines (``scene.text_runs``): text measured by layout.

Widths are the advance widths of the face that draws each run, line heights and baselines its
family's (``xaml3d.text_metrics``), as WPF's text formatter sets a line. Plain text breaks at
spaces into lines no wider than the width offered (a word wider than the line keeps a line of
its own; a line feed starts a line); TextTrimming cuts each line to the width with an ellipsis.
Inline runs flow on the lines LineBreak starts, each in its own font; they wrap at spaces, a
line as tall as its tallest run's line, its runs on the lowest baseline.

The measure pass (``measure``) breaks the lines at the width offered, less the Padding; the
arrange pass (``lines``) breaks them again at the width arranged, as WPF formats the text again
in ArrangeOverride, and leaves them on the Node for the drawing.
"""

from __future__ import annotations

import math
from dataclasses import replace

from xaml3d.scene.text_runs import Run, TextContent, TextLine
from xaml3d.text_metrics import baseline, line_height, text_width

ELLIPSIS = "\u2026"
# a line laid out again at its arranged width may meet a width rounded to whole pixels below
# the measured one (UseLayoutRounding): so much is let through rather than wrapped or trimmed
SLACK = 0.5


def _width(run: Run, text: str | None = None) -> float:
    return text_width(run.text if text is None else text, run.size, run.weight, run.italic,
                      run.family)  # fmt: skip


# ------------------------------------------------------------------ plain text


def wrapped_lines(text: str, fmt: Run, width: float) -> list[str]:
    """``text`` broken into lines no wider than ``width`` at spaces (a word wider than the
    line keeps a line of its own). A line feed (kept by xml:space="preserve") starts a new
    line, as it does in WPF's text formatter."""
    if "\n" in text:
        return [x for part in text.split("\n") for x in (wrapped_lines(part, fmt, width) or [""])]
    if not text or not math.isfinite(width):
        return [text] if text else []
    lines: list[str] = []
    cur = ""
    for word in text.split(" "):
        trial = f"{cur} {word}" if cur else word
        if cur and _width(fmt, trial) > width:
            lines.append(cur)
            cur = word
        else:
            cur = trial
    lines.append(cur)
    return lines


def trim(line: str, fmt: Run, width: float, mode: str) -> str:
    """A line cut to ``width`` as TextTrimming does: the longest start of it (whole words for
    WordEllipsis, when one fits) followed by an ellipsis; the line itself when it fits."""
    if mode == "None" or _width(fmt, line) <= width + SLACK:
        return line

    def fits(k: int) -> bool:
        return _width(fmt, line[:k].rstrip() + ELLIPSIS) <= width + SLACK

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


# ------------------------------------------------------------------ inline runs


# A line being wrapped is a list of (text, run) pieces: the run gives the piece's format (its
# own text is ignored), so that words are split and joined without copying runs.


def _piece_width(piece: tuple[str, Run]) -> float:
    return _width(piece[1], piece[0])


def _line_width(line: list) -> float:
    return sum(_piece_width(p) for p in line)


def _line_metrics(line: tuple[Run, ...], base: Run) -> tuple[float, float]:
    """(height, baseline from the top) of a line: its tallest run's (the base font's when
    empty)."""
    fonts = [(r.size, r.family) for r in line] or [(base.size, base.family)]
    return max(line_height(*f) for f in fonts), max(baseline(*f) for f in fonts)


def _wrap(line: list, width: float) -> list[list]:
    """A line of pieces broken at spaces into lines no wider than ``width`` (a word wider than
    the line keeps a line of its own)."""
    if not math.isfinite(width) or _line_width(line) <= width:
        return [line]
    words: list[list] = [[]]  # each word: its pieces; words are separated by one space
    for text, fmt in line:
        for i, piece in enumerate(text.split(" ")):
            if i > 0:
                words.append([])
            if piece:
                words[-1].append((piece, fmt))
    words = [w for w in words if w]
    out: list[list] = []
    cur: list = []
    for word in words:
        trial = cur + [(" ", cur[-1][1])] + word if cur else word
        if cur and _line_width(trial) > width:
            out.append(cur)
            cur = list(word)
        else:
            cur = trial
    out.append(cur)
    return [_merged(x) for x in out]


def _merged(line: list) -> list:
    """Adjacent pieces of one format joined (one TextDrawing each)."""
    out: list = []
    for text, fmt in line:
        if out and (out[-1][1] is fmt or out[-1][1].same_format(fmt)):
            out[-1] = (out[-1][0] + text, out[-1][1])
        else:
            out.append((text, fmt))
    return out


def _inline_lines(t: TextContent, width: float) -> list[TextLine]:
    out = []
    for line in t.inlines or ():
        for part in _wrap([(r.text, r) for r in line], width):
            runs = tuple(r if r.text == text else replace(r, text=text) for text, r in part)
            h, b = _line_metrics(runs, t.base)
            advances = tuple(_piece_width(p) for p in part)
            out.append(TextLine(runs, advances, sum(advances), h, b))
    return out


# ------------------------------------------------------------------ the passes


def measure(t: TextContent, room: float) -> tuple[float, float]:
    """(width, height) a TextBlock asks for, its lines broken (and trimmed) at ``room`` (the
    width offered, infinite: none) less its Padding; the Padding included."""
    pad = t.padding
    inner = max(0.0, room - pad[0] - pad[2]) if math.isfinite(room) else math.inf
    b = t.base
    if t.inlines is not None:
        lines = _inline_lines(t, inner if t.wrapping else math.inf)
        w = max((x.width for x in lines), default=0.0)
        h = sum(x.height for x in lines)
        return w + pad[0] + pad[2], max(h, line_height(b.size, b.family)) + pad[1] + pad[3]
    texts = wrapped_lines(b.text, b, inner if t.wrapping else math.inf)
    if math.isfinite(inner):  # a trimmed line is as wide as what is shown of it
        texts = [trim(x, b, inner, t.trimming) for x in texts]
    w = max((_width(b, x) for x in texts), default=0.0)
    h = line_height(b.size, b.family) * max(1, len(texts))
    return w + pad[0] + pad[2], h + pad[1] + pad[3]


def lines(t: TextContent, width: float) -> tuple[TextLine, ...]:
    """The lines drawn in ``width`` (the arranged width less the Padding): wrapped there (with
    ``SLACK``) and trimmed to it. An empty line (between two line feeds) is kept for its
    height."""
    wrap_at = width + SLACK if t.wrapping else math.inf
    if t.inlines is not None:
        return tuple(_inline_lines(t, wrap_at))
    b = t.base
    lh, bl = line_height(b.size, b.family), baseline(b.size, b.family)
    out = []
    for text in wrapped_lines(b.text, b, wrap_at):
        text = trim(text, b, width, t.trimming)
        w = _width(b, text)
        out.append(TextLine((replace(b, text=text),), (w,), w, lh, bl))
    return tuple(out)


def overflows(t: TextContent, w: float, h: float) -> bool:
    """Whether the text needs more than the box (w, h) it is arranged in, broken at ``w``:
    WPF's layout clip then cuts it at the box."""
    need = measure(t, w)
    return need[0] > w + 1e-9 or need[1] > h + 1e-9
