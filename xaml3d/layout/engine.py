"""WPF's two-pass layout (measure, then arrange) over a layout tree (tree.py).

Per element, FrameworkElement's MeasureCore/ArrangeCore: the Margin is taken off the room
offered; Width/Height/Min/Max clamp it (an explicit size wins within Min/Max); the panel rule
(MeasureOverride) gives the desired size, which is clamped again and, with the margin, never
exceeds the room offered. Arrange gives an element its slot; an element that is not Stretch in
a direction takes its desired size there and is aligned in the slot (Stretch that does not fit
aligns Left/Top, as WPF does); Max sizes cap the arranged size. Collapsed elements take no room
and are not arranged; Hidden ones take their room and are not drawn.

Panel rules: Window/Page/UserControl/Border/containers (one content inside BorderThickness and
Padding; several children of an unknown container overlap), Grid (grid.py), DockPanel,
StackPanel, Canvas (children at their own size, at Left/Top/Right/Bottom), Viewbox (its child
at its own size, scaled by Stretch/StretchDirection), ScrollViewer (content measured with
infinite room in each scrolling direction, arranged at least as large as the view; a Visible
scroll bar takes 17 px, an Auto one when the content overflows), UniformGrid (equal cells),
WrapPanel (wrap.py: children in lines, a new line where the next would not fit),
Viewport3D (no content size of its own: 0 x 0 unless sized), controls
(their measured or estimated content size; a TextBlock's text measured by text.py in the
fonts that draw it, its lines broken at the width offered, and again at the width arranged).
UseLayoutRounding (inherited) rounds margins, desired sizes, arranged sizes and offsets to whole
pixels as WPF does at 96 dpi.

LayoutTransform (transform.py): an element with one is measured and arranged in its own space,
in the largest box whose transformed bounds fit the room offered; its parent sees and aligns the
bounds of its transformed size.

``layout(root, client)`` lays the tree out and returns a ``LayoutResult``; every element is
measured once and arranged once, so the work is linear in the number of elements.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field

from xaml3d.layout.grid import GridLayout
from xaml3d.layout.transform import bounds, maximal_local_size
from xaml3d.layout.wrap import wrap_arrange, wrap_measure
from xaml3d.scene.element_tree import (
    BORDER,
    CANVAS,
    CONTAINER,
    CONTROL,
    DEFAULT_CLIENT,
    DOCK,
    GRID,
    INF,
    PAGE,
    SCROLL,
    SCROLLBAR,
    STACK,
    UNIFORM,
    USER_CONTROL,
    VIEWBOX,
    VIEWPORT,
    WINDOW,
    WRAP,
    Node,
)


def _is_set(v: float) -> bool:
    return v == v  # not NaN


def _zero(v: float) -> bool:
    return abs(v) < 1e-12


def _round(v: float) -> float:
    # Math.Round at 96 dpi: to the nearest whole pixel, halves to even (as Python's round).
    return float(round(v)) if v not in (INF, -INF) else v


@dataclass
class LayoutResult:
    root: Node
    client: tuple[float, float]  # the root's client area
    how: str  # where the client size came from
    measure_calls: int = 0
    arrange_calls: int = 0
    viewports: list[Node] = field(default_factory=list)  # in document order

    def nodes(self):
        return self.root.walk()


def min_max(n: Node) -> tuple[float, float, float, float]:
    """(min_w, max_w, min_h, max_h) as FrameworkElement's MinMax: an explicit Width/Height
    within [Min, Max] becomes both bounds."""
    out = []
    for size, lo, hi in (
        (n.width, n.min_width, n.max_width),
        (n.height, n.min_height, n.max_height),
    ):
        hi2 = max(min(size if _is_set(size) else INF, hi), lo)
        lo2 = max(min(hi2, size if _is_set(size) else 0.0), lo)
        out += [lo2, hi2]
    return out[0], out[1], out[2], out[3]


def _align(align: str, client: float, ink: float, far: str) -> float:
    if align == "Stretch" and ink > client:
        align = "Left"
    if align in ("Center", "Stretch"):
        return (client - ink) * 0.5
    if align == far:
        return client - ink
    return 0.0


def _layout_clip(slot_box, rw: float, rh: float, iw: float, ih: float):
    """FrameworkElement.GetLayoutClip: the element's Max/explicit size (``ink``) when its
    RenderSize is larger, its slot when that is smaller than the ink, both when both."""
    local = iw < rw - 1e-9 or ih < rh - 1e-9
    if slot_box is None:
        return (0.0, 0.0, iw, ih) if local else None
    if not local:
        return slot_box
    sx, sy, sw, sh = slot_box
    x0, y0 = max(0.0, sx), max(0.0, sy)
    x1, y1 = min(iw, sx + sw), min(ih, sy + sh)
    return (x0, y0, max(0.0, x1 - x0), max(0.0, y1 - y0))


def _thick(t, rounding: bool) -> tuple[float, float, float, float]:
    return tuple(_round(v) for v in t) if rounding else tuple(t)


class Engine:
    def __init__(self, root: Node) -> None:
        self.root = root
        self.measure_calls = 0
        self.arrange_calls = 0
        self.client = (0.0, 0.0)
        self.grid = GridLayout(self)
        self._rounding: dict[int, bool] = {}
        self._frameless = root if root.kind == WINDOW else None  # a root Window's size is outer
        for n in root.walk():  # parent links, inherited UseLayoutRounding
            p = n.parent
            inherited = self._rounding[id(p)] if p is not None else False
            self._rounding[id(n)] = inherited if n.rounding is None else n.rounding
            for k in n.children:
                k.parent = n

    def rounds(self, n: Node) -> bool:
        return self._rounding[id(n)]

    def _limits(self, n: Node):
        if n is self._frameless:
            return 0.0, INF, 0.0, INF
        return min_max(n)

    def _margin(self, n: Node):
        """(left, top, width, height) of the margin; with layout rounding the sums are rounded
        (as WPF does), the left and top offsets are not."""
        if n is self._frameless:
            return 0.0, 0.0, 0.0, 0.0
        ml, mt, mr, mb = n.margin
        mw, mh = ml + mr, mt + mb
        if self.rounds(n):
            mw, mh = _round(mw), _round(mh)
        return ml, mt, mw, mh

    # ----------------------------------------------------------------- measure
    def measure(self, n: Node, aw: float, ah: float) -> None:
        # Like UIElement.Measure: measuring again with the same available size in the same
        # pass changes nothing and is skipped (a Grid's cyclic groups measure cells twice).
        if n.measured_with == (self, aw, ah):
            return
        n.measured_with = (self, aw, ah)
        self.measure_calls += 1
        if n.visibility == "Collapsed":
            n.desired = n.unclipped = (0.0, 0.0)
            return
        rounding = self.rounds(n)
        _, _, mw, mh = self._margin(n)
        lo_w, hi_w, lo_h, hi_h = self._limits(n)
        fw, fh = max(aw - mw, 0.0), max(ah - mh, 0.0)
        lt = n.layout_transform
        if lt is not None:  # the room in the element's own space
            fw, fh = maximal_local_size(lt, fw, fh)
        fw = max(lo_w, min(fw, hi_w))
        fh = max(lo_h, min(fh, hi_h))
        if rounding:
            fw, fh = _round(fw), _round(fh)
        dw, dh = _MEASURE[n.kind](self, n, fw, fh)
        uw, uh = max(dw, lo_w), max(dh, lo_h)
        dw, dh = min(uw, hi_w), min(uh, hi_h)
        clipped = dw < uw or dh < uh
        if lt is not None:  # the parent sees the transformed sizes' bounding boxes
            n.local_desired = (uw, uh)
            uw, uh = bounds(lt, uw, uh)[2:]
            dw, dh = bounds(lt, dw, dh)[2:]
        cw, ch = dw + mw, dh + mh
        if cw > aw or ch > ah:
            cw, ch, clipped = min(cw, aw), min(ch, ah), True
        if rounding:
            cw, ch = _round(cw), _round(ch)
        n.desired = (max(0.0, cw), max(0.0, ch))
        # the size arrange never goes below: kept as measured when clipped, else (like WPF,
        # which does not store it then) recovered from the desired size
        if clipped or cw < 0 or ch < 0:
            n.unclipped = (uw, uh)
        else:
            n.unclipped = (max(0.0, cw - mw), max(0.0, ch - mh))

    # ----------------------------------------------------------------- arrange
    def arrange(self, n: Node, x: float, y: float, w: float, h: float, slot: str = "") -> None:
        self.arrange_calls += 1
        n.slot = slot
        if n.visibility == "Collapsed":
            n.size, n.ink, n.offset, n.arranged = (0.0, 0.0), (0.0, 0.0), (x, y), False
            return
        n.arranged = True
        rounding = self.rounds(n)
        ml, mt, mw, mh = self._margin(n)
        aw, ah = max(0.0, w - mw), max(0.0, h - mh)
        uw, uh = n.unclipped
        aw, ah = max(aw, uw), max(ah, uh)  # never below the desired size (it is clipped)
        if n.h_align != "Stretch":
            aw = uw
        if n.v_align != "Stretch":
            ah = uh
        if n.width_share is not None:  # the indicator's Width, set from the track's width
            aw = n.width_share * max(0.0, w - mw)
        lt = n.layout_transform
        if lt is not None:
            # arranged in its own space: the largest box whose transformed bounds fit, unless
            # that is smaller than its own desired size in a direction
            pw, ph = maximal_local_size(lt, aw, ah)
            aw, ah = pw, ph
            uw, uh = n.local_desired
            if not (_zero(pw) or _zero(ph)) and (pw < uw - 1e-9 or ph < uh - 1e-9):
                aw, ah = uw, uh
            aw, ah = max(aw, uw), max(ah, uh)
        lo_w, hi_w, lo_h, hi_h = self._limits(n)
        if rounding:
            hi_w, hi_h = _round(hi_w), _round(hi_h)
        aw, ah = min(aw, max(uw, hi_w)), min(ah, max(uh, hi_h))
        if rounding:
            aw, ah = _round(aw), _round(ah)
        rw, rh = _ARRANGE[n.kind](self, n, aw, ah)
        iw, ih = min(rw, hi_w), min(rh, hi_h)
        cw, ch = max(0.0, w - mw), max(0.0, h - mh)
        if rounding:
            rw, rh, iw, ih = _round(rw), _round(rh), _round(iw), _round(ih)
            cw, ch = _round(cw), _round(ch)
        n.size = (rw, rh)
        n.ink = (iw, ih)  # WPF clips a larger render to the element's Max/explicit size
        bw, bh = iw, ih
        if lt is not None:  # alignment places the transformed box's bounds
            bw, bh = bounds(lt, iw, ih)[2:]
            if rounding:
                bw, bh = _round(bw), _round(bh)
        ox = _align(n.h_align, cw, bw, "Right") + x + ml
        oy = _align(n.v_align, ch, bh, "Bottom") + y + mt
        if rounding:
            ox, oy = _round(ox), _round(oy)
        fits = lt is not None or (bw <= cw + 1e-9 and bh <= ch + 1e-9)
        n.slot_box = None if fits else (x + ml - ox, y + mt - oy, cw, ch)
        n.clip_box = _layout_clip(n.slot_box, rw, rh, iw, ih)
        # the element's own box starts where its transformed bounds are aligned; the turn
        # (less the bounds' corner) is drawn about that point (scene Layer2D.layout_transform)
        n.offset = (ox, oy)


# --------------------------------------------------------------------------- panel rules


def _inset(e: Engine, n: Node) -> tuple[float, float, float, float]:
    """BorderThickness (rounded with layout rounding, as Border does) plus Padding (never)."""
    b = _thick(n.border, e.rounds(n))
    return tuple(a + p for a, p in zip(b, n.padding, strict=True))


def _content_measure(e: Engine, n: Node, w: float, h: float):
    """Border and every single-content element: content inside BorderThickness + Padding."""
    bl, bt, br, bb = _inset(e, n)
    cw, ch = max(0.0, w - bl - br), max(0.0, h - bt - bb)
    dw = dh = 0.0
    for k in n.children:
        e.measure(k, cw, ch)
        dw, dh = max(dw, k.desired[0]), max(dh, k.desired[1])
    return dw + bl + br, dh + bt + bb


def _content_arrange(e: Engine, n: Node, w: float, h: float):
    bl, bt, br, bb = _inset(e, n)
    for k in n.children:
        e.arrange(k, bl, bt, max(0.0, w - bl - br), max(0.0, h - bt - bb), "content")
    return w, h


def _dock_measure(e: Engine, n: Node, w: float, h: float):
    pw = ph = aw = ah = 0.0  # the panel's size so far, the room docked children took
    for k in n.children:
        e.measure(k, max(0.0, w - aw), max(0.0, h - ah))
        dw, dh = k.desired
        if k.dock in ("Left", "Right"):
            ph = max(ph, ah + dh)
            aw += dw
        else:
            pw = max(pw, aw + dw)
            ah += dh
    return max(pw, aw), max(ph, ah)


def _dock_arrange(e: Engine, n: Node, w: float, h: float):
    kids = n.children
    docked = len(kids) - 1 if n.last_child_fill else len(kids)
    left = top = right = bottom = 0.0
    for i, k in enumerate(kids):
        dw, dh = k.desired
        x, y = left, top
        cw, ch = max(0.0, w - left - right), max(0.0, h - top - bottom)
        slot = "the remaining space (LastChildFill)"
        if i < docked:
            slot = f"DockPanel.Dock={k.dock}"
            if k.dock == "Left":
                left += dw
                cw = dw
            elif k.dock == "Right":
                right += dw
                x, cw = max(0.0, w - right), dw
            elif k.dock == "Top":
                top += dh
                ch = dh
            else:
                bottom += dh
                y, ch = max(0.0, h - bottom), dh
        e.arrange(k, x, y, cw, ch, slot)
    return w, h


def _stack_measure(e: Engine, n: Node, w: float, h: float):
    vertical = n.orientation != "Horizontal"
    sw = sh = 0.0
    for k in n.children:
        if vertical:
            e.measure(k, w, INF)
            sw, sh = max(sw, k.desired[0]), sh + k.desired[1]
        else:
            e.measure(k, INF, h)
            sw, sh = sw + k.desired[0], max(sh, k.desired[1])
    return sw, sh


def _stack_arrange(e: Engine, n: Node, w: float, h: float):
    vertical = n.orientation != "Horizontal"
    pos = 0.0
    for i, k in enumerate(n.children):
        dw, dh = k.desired
        if vertical:
            e.arrange(k, 0.0, pos, max(w, dw), dh, f"StackPanel item {i} (its desired height)")
            pos += dh
        else:
            e.arrange(k, pos, 0.0, dw, max(h, dh), f"StackPanel item {i} (its desired width)")
            pos += dw
    return w, h


def _canvas_measure(e: Engine, n: Node, w: float, h: float):
    for k in n.children:
        e.measure(k, INF, INF)
    return 0.0, 0.0


def _canvas_arrange(e: Engine, n: Node, w: float, h: float):
    for k in n.children:
        dw, dh = k.desired
        x = k.left if _is_set(k.left) else (w - dw - k.right if _is_set(k.right) else 0.0)
        y = k.top if _is_set(k.top) else (h - dh - k.bottom if _is_set(k.bottom) else 0.0)
        e.arrange(k, x, y, dw, dh, "Canvas (its own size)")
    return w, h


def scale_factor(avail: tuple[float, float], content: tuple[float, float], stretch: str,
                 direction: str) -> tuple[float, float]:  # fmt: skip
    """Viewbox.ComputeScaleFactor: the scale of content in the room available."""
    sx = sy = 1.0
    free_w, free_h = avail[0] == INF, avail[1] == INF
    if stretch in ("Uniform", "UniformToFill", "Fill") and not (free_w and free_h):
        sx = 0.0 if content[0] == 0 else avail[0] / content[0]
        sy = 0.0 if content[1] == 0 else avail[1] / content[1]
        if free_w:
            sx = sy
        elif free_h:
            sy = sx
        elif stretch == "Uniform":
            sx = sy = min(sx, sy)
        elif stretch == "UniformToFill":
            sx = sy = max(sx, sy)
        if direction == "UpOnly":
            sx, sy = max(1.0, sx), max(1.0, sy)
        elif direction == "DownOnly":
            sx, sy = min(1.0, sx), min(1.0, sy)
    return sx, sy


def _viewbox_measure(e: Engine, n: Node, w: float, h: float):
    dw = dh = 0.0
    for k in n.children:
        e.measure(k, INF, INF)
        dw, dh = max(dw, k.desired[0]), max(dh, k.desired[1])
    sx, sy = scale_factor((w, h), (dw, dh), n.stretch, n.stretch_direction)
    return sx * dw, sy * dh


def _viewbox_arrange(e: Engine, n: Node, w: float, h: float):
    dw = dh = 0.0
    for k in n.children:
        dw, dh = max(dw, k.desired[0]), max(dh, k.desired[1])
    sx, sy = scale_factor((w, h), (dw, dh), n.stretch, n.stretch_direction)
    n.child_scale = (sx, sy)
    for k in n.children:
        e.arrange(k, 0.0, 0.0, dw, dh, f"Viewbox (its own size, scaled {sx:g} x {sy:g})")
    return sx * dw, sy * dh


def _scroll_bars(n: Node, content=None, view=None) -> tuple[float, float]:
    """(width taken by the vertical bar, height taken by the horizontal bar): a Visible bar
    always, an Auto one when the content (its desired size, at arrange) overflows the view."""
    vb = SCROLLBAR if n.scroll_v == "Visible" else 0.0
    hb = SCROLLBAR if n.scroll_h == "Visible" else 0.0
    if content is not None:
        if n.scroll_v == "Auto" and content[1] > view[1] - hb:
            vb = SCROLLBAR
        if n.scroll_h == "Auto" and content[0] > view[0] - vb:
            hb = SCROLLBAR
    return vb, hb


def _scroll_measure(e: Engine, n: Node, w: float, h: float):
    vb, hb = _scroll_bars(n)
    cw = max(0.0, w - vb) if n.scroll_h == "Disabled" else INF
    ch = max(0.0, h - hb) if n.scroll_v == "Disabled" else INF
    dw = dh = 0.0
    for k in n.children:
        e.measure(k, cw, ch)
        dw, dh = max(dw, k.desired[0]), max(dh, k.desired[1])
    # the view never wants more than it is offered: the content scrolls inside it
    return min(dw + vb, w), min(dh + hb, h)


def _scroll_arrange(e: Engine, n: Node, w: float, h: float):
    dw = max((k.desired[0] for k in n.children), default=0.0)
    dh = max((k.desired[1] for k in n.children), default=0.0)
    vb, hb = _scroll_bars(n, (dw, dh), (w, h))
    vw, vh = max(0.0, w - vb), max(0.0, h - hb)
    if (vb, hb) != _scroll_bars(n):  # an Auto bar appeared: measure again beside it, as WPF does
        for k in n.children:
            e.measure(k, vw if n.scroll_h == "Disabled" else INF,
                      vh if n.scroll_v == "Disabled" else INF)  # fmt: skip
    dw = max((k.desired[0] for k in n.children), default=0.0)
    dh = max((k.desired[1] for k in n.children), default=0.0)
    n.scrolled = (vb, hb, dw, dh)
    for k in n.children:
        # a direction that does not scroll (Disabled) gives the content the view's size (WPF
        # measures it again when an Auto bar appears); one that scrolls, at least that size
        cw = vw if n.scroll_h == "Disabled" else max(k.desired[0], vw)
        ch = vh if n.scroll_v == "Disabled" else max(k.desired[1], vh)
        e.arrange(k, 0.0, 0.0, cw, ch, "ScrollViewer content (at least the view's size)")
        if k.size[0] > vw + 1e-9 or k.size[1] > vh + 1e-9:
            # WPF's ScrollContentPresenter clips what does not fit to the view
            ox, oy = k.offset
            view = (-ox, -oy, vw, vh)
            k.clip_box = view if k.clip_box is None else _overlap(k.clip_box, view)
    return w, h


def _overlap(a, b) -> tuple[float, float, float, float]:
    """The intersection of two (x, y, w, h) boxes (empty: zero size)."""
    x0, y0 = max(a[0], b[0]), max(a[1], b[1])
    x1, y1 = min(a[0] + a[2], b[0] + b[2]), min(a[1] + a[3], b[1] + b[3])
    return (x0, y0, max(0.0, x1 - x0), max(0.0, y1 - y0))


def _uniform_shape(n: Node) -> tuple[int, int, int]:
    """(rows, columns, first column) of a UniformGrid, as WPF completes unset ones."""
    rows, cols, first = n.uniform
    count = sum(1 for k in n.children if k.visibility != "Collapsed")
    first = first if cols > 0 and first < cols else 0
    if rows <= 0 and cols <= 0:
        rows = math.isqrt(count)
        rows += rows * rows < count
        cols = rows
    elif rows <= 0:
        rows = (count + first + cols - 1) // cols
    elif cols <= 0:
        cols = (count + rows - 1) // rows
    return max(rows, 1), max(cols, 1), first


def _uniform_measure(e: Engine, n: Node, w: float, h: float):
    rows, cols, _ = _uniform_shape(n)
    dw = dh = 0.0
    for k in n.children:
        e.measure(k, w / cols, h / rows)
        dw, dh = max(dw, k.desired[0]), max(dh, k.desired[1])
    return dw * cols, dh * rows


def _uniform_arrange(e: Engine, n: Node, w: float, h: float):
    rows, cols, first = _uniform_shape(n)
    cw, ch = w / cols, h / rows
    col, row = first, 0
    for k in n.children:
        e.arrange(k, col * cw, row * ch, cw, ch, f"UniformGrid cell {row}, {col}")
        if k.visibility != "Collapsed":
            col += 1
            if col >= cols:  # next row
                col, row = 0, row + 1
    return w, h


def _leaf_measure(e: Engine, n: Node, w: float, h: float):
    if n.text is not None:  # a TextBlock: its lines broken at the width offered (text.py)
        from xaml3d.layout import text  # the fonts load with the first text, not before

        return text.measure(n.text, w)
    if n.measure is not None:  # wrapping text: its lines depend on the width offered
        return n.measure(w, h)
    return n.estimate if n.estimate is not None else (0.0, 0.0)


def _leaf_arrange(e: Engine, n: Node, w: float, h: float):
    if n.arrange_size is not None:  # a stretched shape: its geometry's stretched size
        return n.arrange_size(w, h)
    return w, h


_MEASURE = {
    WINDOW: _content_measure, PAGE: _content_measure, USER_CONTROL: _content_measure,
    BORDER: _content_measure, CONTAINER: _content_measure,
    GRID: lambda e, n, w, h: e.grid.measure(n, w, h), DOCK: _dock_measure,
    STACK: _stack_measure, CANVAS: _canvas_measure, VIEWBOX: _viewbox_measure,
    SCROLL: _scroll_measure, VIEWPORT: _leaf_measure, CONTROL: _leaf_measure,
    UNIFORM: _uniform_measure, WRAP: wrap_measure,
}  # fmt: skip
_ARRANGE = {
    WINDOW: _content_arrange, PAGE: _content_arrange, USER_CONTROL: _content_arrange,
    BORDER: _content_arrange, CONTAINER: _content_arrange,
    GRID: lambda e, n, w, h: e.grid.arrange(n, w, h), DOCK: _dock_arrange,
    STACK: _stack_arrange, CANVAS: _canvas_arrange, VIEWBOX: _viewbox_arrange,
    SCROLL: _scroll_arrange, VIEWPORT: _leaf_arrange, CONTROL: _leaf_arrange,
    UNIFORM: _uniform_arrange, WRAP: wrap_arrange,
}  # fmt: skip


# --------------------------------------------------------------------------- the root


def root_client(root: Node, override: tuple[float, float] | None = None):
    """(width, height, how) of the root's client area; INF in a direction the root sizes to
    its content (Window.SizeToContent). ``override`` is a client size given by the user."""
    if override is not None:
        return override[0], override[1], f"--window-size {override[0]:g}x{override[1]:g}"
    dw, dh = DEFAULT_CLIENT
    if root.kind == WINDOW:
        fw, fh = root.frame
        stc = root.size_to_content
        lo_w, hi_w, lo_h, hi_h = min_max(root)
        w = INF if stc in ("Width", "WidthAndHeight") else (
            max(lo_w, min(root.width, hi_w)) - fw if _is_set(root.width) else dw)  # fmt: skip
        h = INF if stc in ("Height", "WidthAndHeight") else (
            max(lo_h, min(root.height, hi_h)) - fh if _is_set(root.height) else dh)  # fmt: skip
        parts = []
        if _is_set(root.width) or _is_set(root.height):
            parts.append(f"Window {root.width:g} x {root.height:g} less the frame {fw:g} x {fh:g}")
        if stc != "Manual":
            parts.append(f"SizeToContent={stc}")
        if not (_is_set(root.width) and _is_set(root.height)) and stc != "WidthAndHeight":
            parts.append(f"the default client size {dw:g} x {dh:g} where not given")
        return max(0.0, w), max(0.0, h), "; ".join(parts)
    w = root.width if _is_set(root.width) else None
    h = root.height if _is_set(root.height) else None
    how = f"{root.type} Width/Height"
    if (w is None or h is None) and root.design_size is not None:
        # the designer size (d:DesignWidth/Height; a Page's WindowWidth/Height less the frame)
        w = root.design_size[0] if w is None else w
        h = root.design_size[1] if h is None else h
        how = f"{root.type} design size"
    if w is None or h is None:
        how = f"the default size {dw:g} x {dh:g}" if w is None and h is None else (
            f"{how}, the default {dw:g} x {dh:g} where not given")  # fmt: skip
    return (dw if w is None else w), (dh if h is None else h), how


def layout(root: Node, client: tuple[float, float] | None = None) -> LayoutResult:
    """Measure and arrange the tree in the root's client area (``client`` overrides it)."""
    w, h, how = root_client(root, client)
    e = Engine(root)
    # measure/arrange recurse a few frames per nesting level (as WPF's do); the reader bounds
    # the depth (parser limit), so room for that depth is made rather than failing
    depth, stack = 0, [(root, 1)]
    while stack:
        n, d = stack.pop()
        depth = max(depth, d)
        stack.extend((k, d + 1) for k in n.children)
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, 8 * depth + 200))
    try:
        _run(e, root, w, h, how)
    finally:
        sys.setrecursionlimit(old)
    return _result(e, root, how)


def _run(e: Engine, root: Node, w: float, h: float, how: str) -> None:
    e.measure(root, w, h)
    if w == INF or h == INF:  # SizeToContent: the client area is the content's size
        w = root.desired[0] if w == INF else w
        h = root.desired[1] if h == INF else h
    e.arrange(root, 0.0, 0.0, w, h, how)
    e.client = (w, h)


def _result(e: Engine, root: Node, how: str) -> LayoutResult:
    result = LayoutResult(root, e.client, how, e.measure_calls, e.arrange_calls)
    _absolute(root)
    _text_lines(root)
    result.viewports = [n for n in root.walk() if n.kind == VIEWPORT]
    return result


def _text_lines(root: Node) -> None:
    """Each arranged TextBlock's lines at its arranged width (WPF formats the text again in
    ArrangeOverride), which its drawing sets as they are, and whether they overflow its box."""
    texts = [n for n in root.walk() if n.text is not None and n.kind == CONTROL and n.arranged]
    if not texts:
        return
    from xaml3d.layout import text

    for n in texts:
        w, h = n.ink
        pad = n.text.padding
        n.text_lines = text.lines(n.text, w - pad[0] - pad[2])
        n.text_overflow = text.overflows(n.text, w, h)


def _absolute(root: Node) -> None:
    """Every node's visible rectangle in the root's client area (offsets accumulated, Viewbox
    scales applied), parents first."""
    frame = {id(root): (0.0, 0.0, 1.0, 1.0)}  # origin x, y and scale of a node's parent space
    for n in root.walk():
        px, py, sx, sy = frame[id(n)]
        x, y = px + sx * n.offset[0], py + sy * n.offset[1]
        n.rect = (x, y, sx * n.ink[0], sy * n.ink[1])
        cx, cy = n.child_scale
        for k in n.children:
            frame[id(k)] = (x, y, sx * cx, sy * cy)
