"""``render --window``: the root's client area drawn as one picture, from the laid-out boxes the
Scene holds (``xaml3d.scene.boxes``: the reader ran the layout).

Paints, in WPF's order (parents before children, children in document order): the Window's
background (WPF's default is the system window colour, white), every panel's and Border's
Background (solid, gradient, image, drawing and visual brushes, in the element's own
coordinates, a drawn tile at one texel a pixel: a brush's relative units refer to the element's
box; a Border's Background fills, and maps to, the box inside its BorderThickness), each
Border's BorderBrush band of BorderThickness (both rounded by its CornerRadius), and every
visible Viewport3D rendered at its laid-out rectangle with its own camera and aspect ratio
(``render_scene``), composited over what lies beneath. The 2D controls the 2D layer draws
(TextBlock, Label, Button, TextBox, CheckBox, RadioButton, ComboBox, Slider, ProgressBar,
Separator, ScrollBar, shapes, Image, the parts of ListBox, TabControl, GroupBox, Expander and
content controls: ``Box.drawing``, docs/layer2d.md) are drawn placed at their laid-out boxes
(all of a drawing shows, a shape's beyond its box too: only its layout clip cuts it);
``outline_controls`` draws a one-pixel outline of each control's layout box. An element with
Opacity, OpacityMask, Clip, RenderTransform or an Effect (``Box.layer``) is drawn with
everything inside it into a layer of its own, which the 2D layer then transforms, clips, filters
and fades over what lies beneath, as WPF composes a visual's subtree; the canvas reaches past
the client area where such an element holds what its transform, effect or LayoutTransform can
bring into view (``_layer_canvas``). Hidden and Collapsed
elements and their content are left out. A pixel belongs to a box when its centre lies inside
it.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from xaml3d.animation.moment import scene_at
from xaml3d.errors import Diagnostic, RenderError
from xaml3d.render.brushes import sample_brush
from xaml3d.render.frame import straight_uint8
from xaml3d.render.pipeline import render_scene
from xaml3d.render.settings import (
    MAX_SUPERSAMPLED_PIXELS,
    FrameSize,
    RenderSettings,
    settings_of,
)
from xaml3d.scene.boxes import BORDER, CONTROL, VIEWPORT, WINDOW, Box
from xaml3d.scene.drawing import Layer2D, Viewport2D
from xaml3d.scene.types import Scene, SolidColorBrush

WINDOW_BACKGROUND = SolidColorBrush(color=(1.0, 1.0, 1.0, 1.0))
OUTLINE = (0.0, 120 / 255, 215 / 255, 1.0)  # the Windows accent blue, premultiplied (opaque)
MAX_WINDOW_SIDE = 16384  # pixels per side, as a plain render's default max_size


def _clamped(v: float, limit: int) -> float:
    """``v`` within [-1, limit + 1]: the same pixels, and never an infinite or huge number
    (a Canvas.Top of 1e308 puts an element far outside, not into an OverflowError)."""
    return min(max(v, -1.0), limit + 1.0) if not math.isnan(v) else -1.0


def _span(a: float, length: float, limit: int) -> tuple[int, int]:
    """Pixels [i0, i1) whose centres lie in [a, a + length)."""
    i0 = max(0, math.ceil(_clamped(a - 0.5, limit)))
    i1 = min(limit, math.ceil(_clamped(a + length - 0.5, limit)))
    return i0, max(i0, i1)


def client_pixels(client, max_size: int = MAX_WINDOW_SIDE) -> tuple[int, int]:
    """The picture's size for a client area of ``client`` (width, height), with the limits of
    a plain render: RND001 past ``max_size`` pixels per side or MAX_SUPERSAMPLED_PIXELS."""
    cw, ch = (float(v) for v in client)
    if not (math.isfinite(cw) and math.isfinite(ch)) or cw > max_size or ch > max_size:
        raise RenderError(
            f"window client area {cw:g} x {ch:g} exceeds the limit of {max_size} pixels per "
            "side (lower --window-size, or render one viewport)",
            code="RND001",
        )
    w, h = max(1, round(cw)), max(1, round(ch))
    if w * h > MAX_SUPERSAMPLED_PIXELS:
        raise RenderError(
            f"window client area {w} x {h} is over the limit of {MAX_SUPERSAMPLED_PIXELS} "
            "pixels (lower --window-size)",
            code="RND001",
        )
    return w, h


def _over(canvas: np.ndarray, y0: int, x0: int, premul: np.ndarray) -> None:
    h, w = premul.shape[:2]
    dst = canvas[y0 : y0 + h, x0 : x0 + w]
    dst *= 1.0 - premul[..., 3:4]
    dst += premul


def _fill(canvas: np.ndarray, rect, brush, mask=None) -> None:
    x, y, w, h = rect
    if not all(math.isfinite(float(v)) for v in rect):
        return  # a box at or of infinite extent: WPF's layout never arranges one on screen
    H, W = canvas.shape[:2]
    c0, c1 = _span(x, w, W)
    r0, r1 = _span(y, h, H)
    if c1 <= c0 or r1 <= r0 or w <= 0 or h <= 0:
        return
    px, py = np.meshgrid(np.arange(c0, c1) + 0.5 - x, np.arange(r0, r1) + 0.5 - y)
    uv = np.stack([px.ravel(), py.ravel()], axis=1)
    bounds = (np.zeros(2), np.array([w, h], dtype=np.float64))
    # element coordinates are pixels: a drawn tile (DrawingBrush) needs one texel per unit
    color = sample_brush(brush, uv, bounds, 1.0).reshape(r1 - r0, c1 - c0, 4).astype(np.float32)
    if mask is not None:
        color *= mask(px, py)[..., None]
    _over(canvas, r0, c0, color)


def _radii(b: Box, outer: bool) -> list[tuple[float, float]]:
    """A Border's corner radii (TopLeft, TopRight, BottomRight, BottomLeft) as WPF's Border
    draws them: CornerRadius is the radius of the band's centre line, so the outer edge's is
    half a thickness more (a zero radius stays square) and the inner edge's half a thickness
    less."""
    left, top, right, bottom = b.border
    sides = ((left, top), (right, top), (right, bottom), (left, bottom))
    out = []
    for (cx, cy), (tx, ty) in zip(b.corner, sides, strict=True):
        if outer:
            out.append((cx + tx / 2, cy + ty / 2) if cx > 0 and cy > 0 else (0.0, 0.0))
        else:
            out.append((max(0.0, cx - tx / 2), max(0.0, cy - ty / 2)))
    return out


def _rounded(w: float, h: float, radii):
    """The coverage (0..1) of the rectangle (0, 0, w, h) with elliptical corners ``radii``
    (TopLeft, TopRight, BottomRight, BottomLeft), over element coordinates: pixel centres
    inside the straight edges, anti-aliased along the arcs (radii that do not fit are scaled
    down in proportion, as WPF's Border does)."""
    (a, b), (c, d), (e, f), (g, k) = radii
    sums = ((w, a + c), (w, g + e), (h, b + k), (h, d + f))
    fit = min([1.0, *(length / both for length, both in sums if both > length)])
    rs = [(rx * fit, ry * fit) for rx, ry in radii]
    # each corner: its ellipse's centre and the quadrant it rounds (sign of x, y from it)
    centres = [(rs[0][0], rs[0][1], -1, -1), (w - rs[1][0], rs[1][1], 1, -1),
               (w - rs[2][0], h - rs[2][1], 1, 1), (rs[3][0], h - rs[3][1], -1, 1)]  # fmt: skip

    def mask(px, py):
        cov = ((px >= 0) & (px < w) & (py >= 0) & (py < h)).astype(np.float32)
        for (rx, ry), (cx, cy, sx, sy) in zip(rs, centres, strict=True):
            if rx <= 0 or ry <= 0:
                continue
            dx, dy = (px - cx) * sx, (py - cy) * sy
            corner = (dx > 0) & (dy > 0)
            with np.errstate(over="ignore"):  # a radius far below a pixel: outside (inf)
                q = np.hypot(dx / rx, dy / ry)
            # the distance past the arc in pixels, near enough for a pixel's coverage
            edge = np.clip(0.5 - (q - 1.0) * min(rx, ry), 0.0, 1.0).astype(np.float32)
            cov = np.where(corner, np.minimum(cov, edge), cov)
        return cov

    return mask


def _band(b: Box):
    """The BorderThickness band of a Border, as a mask over element coordinates (rounded by
    its CornerRadius)."""
    left, top, right, bottom = b.border
    w, h = b.rect[2], b.rect[3]
    outer = _rounded(w, h, _radii(b, True))
    inner = _rounded(max(0.0, w - left - right), max(0.0, h - top - bottom), _radii(b, False))

    def mask(px, py):
        return np.clip(outer(px, py) - inner(px - left, py - top), 0.0, 1.0)

    return mask


def _background_mask(b: Box):
    """Where a Border's Background shows: the box inside the band, its corners rounded by the
    inner radii (None: square, nothing to mask)."""
    if b.kind != BORDER or not any(r > 0 for c in b.corner for r in c):
        return None
    x, y, w, h = b.inner
    return _rounded(w, h, _radii(b, False))


def _outline(canvas: np.ndarray, rect) -> None:
    x, y, w, h = rect
    if not all(math.isfinite(float(v)) for v in rect):
        return
    H, W = canvas.shape[:2]
    c0, c1 = _span(x, w, W)
    r0, r1 = _span(y, h, H)
    if c1 <= c0 or r1 <= r0:
        return
    color = np.array(OUTLINE, dtype=np.float32)
    canvas[r0, c0:c1] = color
    canvas[r1 - 1, c0:c1] = color
    canvas[r0:r1, c0] = color
    canvas[r0:r1, c1 - 1] = color


def _draw_control(canvas: np.ndarray, b: Box) -> None:
    """A control's drawing (the 2D layer, skia: imported only when a control is drawn) over
    the canvas, placed at its laid-out box. What it draws beyond the box shows (a Path's curve
    or a pen's half outside its layout size, in a Canvas): WPF cuts an element's drawing only
    by its layout clip, which the drawing carries (``DrawingGroup.clip``)."""
    from xaml3d.render.layer2d.paint import drawing_bounds, rasterize

    x, y, w, h = b.rect
    sx = w / b.ink[0] if b.ink[0] > 0 else 1.0
    sy = h / b.ink[1] if b.ink[1] > 0 else 1.0
    ink = drawing_bounds(b.drawing)
    if ink is None:
        return
    left, top = x + sx * ink.left(), y + sy * ink.top()
    right, bottom = x + sx * ink.right(), y + sy * ink.bottom()
    H, W = canvas.shape[:2]
    x0, y0 = max(0, math.floor(_clamped(left, W))), max(0, math.floor(_clamped(top, H)))
    x1, y1 = min(W, math.ceil(_clamped(right, W))), min(H, math.ceil(_clamped(bottom, H)))
    if x1 <= x0 or y1 <= y0:
        return
    m = np.array([[sx, 0.0, x - x0], [0.0, sy, y - y0], [0.0, 0.0, 1.0]])
    _over(canvas, y0, x0, rasterize(b.drawing, x1 - x0, y1 - y0, m))


def _overlaps(rect, W: int, H: int) -> bool:
    """Whether a laid-out box (finite) covers part of the client area: a viewport wholly
    outside it is not rendered (nothing of it would show)."""
    x, y, w, h = (float(v) for v in rect)
    if not all(math.isfinite(v) for v in (x, y, w, h)):
        return False
    c0, c1 = _span(x, w, W)
    r0, r1 = _span(y, h, H)
    return c1 > c0 and r1 > r0


def _subtree_ends(boxes) -> list[int]:
    """For each box, the index just past its last descendant (boxes are in paint order: a
    subtree is a run of boxes)."""
    ends = list(range(1, len(boxes) + 1))
    for i in range(len(boxes) - 1, 0, -1):
        p = boxes[i].parent
        if p is not None:
            ends[p] = max(ends[p], ends[i])
    return ends


def _close_layer(
    layer2d: Layer2D, rect, unit, end: int, beneath: np.ndarray, layer: np.ndarray
) -> np.ndarray:
    """What an element drew into ``layer`` (a premultiplied float canvas of the client area)
    composed with its Layer2D about its box ``rect``, as WPF composes the element (the 2D
    layer, skia), over ``beneath``; returns ``beneath``."""
    from xaml3d.render.layer2d.picture import compose_layers

    drawn = compose_layers(straight_uint8(layer), [(layer2d, rect, unit)], (1.0, 1.0))
    hb, wb = beneath.shape[:2]  # the layer may reach past the canvas beneath (_layer_canvas)
    premul = drawn[:hb, :wb].astype(np.float32) / 255.0
    premul[..., :3] *= premul[..., 3:4]
    _over(beneath, 0, 0, premul)
    return beneath


# how far past the client area a layer's canvas grows to hold an element's own box: four
# client sizes a side (a LayoutTransform shrinking it to a quarter still shows whole), and at
# most so many pixels in all (a float canvas of 16 M pixels is 256 MB)
MAX_LAYER_GROWTH = 4
MAX_LAYER_PIXELS = 1 << 24


def _layer_canvas(canvas: np.ndarray, layer, rect) -> np.ndarray:
    """An empty canvas for an element's layer, large enough for its own (untransformed) box
    when a LayoutTransform places it: one that shrinks the element arranges it larger than
    the room it fills (a 0.7 scale in a 280 x 360 cell: 400 x 514), and what of it lay past
    the client area would otherwise be lost before the transform brings it back in."""
    H, W = canvas.shape[:2]
    if getattr(layer, "layout_transform", None) is None:
        return np.zeros_like(canvas)
    x, y, w, h = (_clamped(float(v), 1 << 30) for v in rect)
    need_w = min(max(W, math.ceil(x + w)), MAX_LAYER_GROWTH * W)
    need_h = min(max(H, math.ceil(y + h)), MAX_LAYER_GROWTH * H)
    if need_w * need_h > max(W * H, MAX_LAYER_PIXELS):
        need_w, need_h = W, H  # too large to hold: drawn within the client area, as before
    return np.zeros((need_h, need_w, 4), dtype=canvas.dtype)


def _window_pictures(scene: Scene) -> tuple[Scene, dict[int, Layer2D]]:
    """The scene with each viewport's picture reduced to how its 3D is drawn (EdgeMode), and
    each viewport's own Opacity, OpacityMask, Clip, RenderTransform and Effect as a Layer2D by
    viewport index: the window composes them over the whole client area, so what the viewport's
    RenderTransform moves out of its box still shows (the elements around are boxes' layers)."""
    own: dict[int, Layer2D] = {}
    vps = []
    for i, vp in enumerate(scene.viewports):
        pic = vp.picture
        if pic is not None:
            layer = Layer2D(opacity=pic.opacity, opacity_mask=pic.opacity_mask, clip=pic.clip,
                            render_transform=pic.render_transform, effect=pic.effect)  # fmt: skip
            if layer.changes_picture:
                own[i] = layer
            edge = pic.edge_mode
            vp = replace(vp, picture=Viewport2D(edge_mode=edge) if edge != "Unspecified" else None)
        vps.append(vp)
    return replace(scene, viewports=tuple(vps)), own


def _layer_of(b: Box, own: dict[int, Layer2D]) -> Layer2D | None:
    """A box's layer; a viewport's own properties join its LayoutTransform's placement."""
    if b.kind != VIEWPORT or b.viewport not in own:
        return b.layer
    placed = b.layer.layout_transform if b.layer is not None else None
    return replace(own[b.viewport], layout_transform=placed)


def _reach(boxes, W: int, H: int) -> tuple[int, int, int, int]:
    """(left, top, right, bottom) whole pixels the canvas reaches beyond the client area: what
    lies outside it but inside an element whose layer turns, moves or spreads what it holds
    (RenderTransform, LayoutTransform, Effect) can be carried back into view, so it is drawn
    too; at most one client area each way, and none past the pixel limit."""
    ends = _subtree_ends(boxes)
    x0, y0, x1, y1 = 0.0, 0.0, float(W), float(H)
    for i, b in enumerate(boxes):
        layer = b.layer
        moves = layer is not None and any(
            v is not None for v in (layer.render_transform, layer.layout_transform, layer.effect)
        )  # fmt: skip
        if not (moves and b.shown):
            continue
        for k in boxes[i : ends[i]]:
            x, y, w, h = _drawn_rect(k)
            if k.shown and all(math.isfinite(v) for v in (x, y, w, h)):
                x0, y0 = min(x0, x), min(y0, y)
                x1, y1 = max(x1, x + w), max(y1, y + h)
        pad = _spread(layer.effect)
        x0, y0, x1, y1 = x0 - pad, y0 - pad, x1 + pad, y1 + pad
    left, top = _whole(-x0, W), _whole(-y0, H)
    right, bottom = _whole(x1 - W, W), _whole(y1 - H, H)
    if (W + left + right) * (H + top + bottom) > MAX_SUPERSAMPLED_PIXELS:
        return 0, 0, 0, 0
    return left, top, right, bottom


def _whole(v: float, cap: int) -> int:
    """``v`` rounded up to whole pixels, at most ``cap``: a box at the doubles' edge (its right
    side overflows to infinity) reaches ``cap``."""
    return cap if v >= cap else math.ceil(v)


def _drawn_rect(b: Box) -> tuple[float, float, float, float]:
    """A box, grown by what its control's drawing reaches beyond it (a shape's curve or pen)."""
    x, y, w, h = (float(v) for v in b.rect)
    if b.drawing is None:
        return x, y, w, h
    from xaml3d.render.layer2d.paint import drawing_bounds

    ink = drawing_bounds(b.drawing)
    if ink is None:
        return x, y, w, h
    sx = w / b.ink[0] if b.ink[0] > 0 else 1.0
    sy = h / b.ink[1] if b.ink[1] > 0 else 1.0
    left, top = min(x, x + sx * ink.left()), min(y, y + sy * ink.top())
    right, bottom = max(x + w, x + sx * ink.right()), max(y + h, y + sy * ink.bottom())
    return left, top, right - left, bottom - top


def _spread(effect) -> float:
    """How far an Effect reaches beyond what it is applied to (a blur's radius, a shadow's
    blur and depth)."""
    if effect is None:
        return 0.0
    depth = float(effect.shadow_depth) if effect.kind == "DropShadow" else 0.0
    v = max(0.0, float(effect.radius)) + abs(depth)
    return v if math.isfinite(v) else 0.0


def _shifted(b: Box, dx: int, dy: int) -> Box:
    x, y, w, h = b.rect
    return replace(b, rect=(x + dx, y + dy, w, h))


def compose_window(
    scene: Scene,
    settings: RenderSettings | None = None,
    *,
    outline_controls: bool = False,
    **options,
) -> tuple[np.ndarray, list[Diagnostic]]:
    """(straight-alpha rgba uint8 (H, W, 4), diagnostics) of the scene's whole client area.
    ``settings`` (or its fields as keyword arguments): ``mode``, ``ssaa``/``msaa``, ``time``/
    ``storyboard`` (the moment drawn) and ``background`` (fills the picture first; default
    transparent), the same for every viewport; each viewport is drawn at its laid-out
    rectangle (its size and exact aspect ratio replace the settings' own)."""
    settings = settings_of(settings, **options)
    scene = scene_at(scene, settings.time, settings.storyboard)
    background = settings.background
    each = settings.replace(background=None, time=None, storyboard=None, width=None, height=None,
                            scale=None)  # fmt: skip

    result = scene.layout
    W, H = client_pixels(result.client)
    # the canvas reaches past the client area where a turned or moved element may bring what
    # lies there into view (its layer is drawn whole, then transformed); cut back at the end
    left, top, right, bottom = _reach(result.boxes, W, H)
    boxes = result.boxes
    if left or top:
        boxes = tuple(_shifted(b, left, top) for b in boxes)
    client_w, client_h = W, H
    W, H = W + left + right, H + top + bottom
    canvas = np.zeros((H, W, 4), dtype=np.float32)
    if background is not None:
        bg = np.array(background, dtype=np.float32)
        bg[:3] *= bg[3]
        canvas[...] = bg
    diags: list[Diagnostic] = []
    # the window composes every layer itself (below), a viewport's own ones too: its picture
    # keeps only how its 3D is drawn
    scene, own = _window_pictures(scene)
    ends = _subtree_ends(boxes)
    open_layers: list = []  # (box, end, the canvas beneath), innermost last
    for i, b in enumerate(boxes):  # paint order: parents before children
        while open_layers and open_layers[-1][3] <= i:
            canvas = _close_layer(*open_layers.pop(), canvas)
        if not b.shown:
            continue
        layer = _layer_of(b, own)
        if layer is not None:
            # the element and everything inside it are drawn into a layer of their own, which
            # its Clip, Effect, Opacity and OpacityMask and RenderTransform then act on
            open_layers.append((layer, b.rect, b.unit, ends[i], canvas))
            canvas = _layer_canvas(canvas, layer, b.rect)
        brush = b.background
        if brush is None and b.kind == WINDOW and i == 0:
            brush = WINDOW_BACKGROUND
        if b.kind == BORDER and b.border_brush is not None and any(b.border):
            _fill(canvas, b.rect, b.border_brush, _band(b))
        if brush is not None:
            # a Border paints its Background inside the border band (its brush maps there)
            _fill(canvas, b.inner if b.kind == BORDER else b.rect, brush, _background_mask(b))
        if b.kind == VIEWPORT and _overlaps(b.rect, canvas.shape[1], canvas.shape[0]):
            w, h = round(b.rect[2]), round(b.rect[3])
            if w >= 1 and h >= 1:
                r = render_scene(
                    scene,
                    each.replace(viewport=b.viewport),
                    size=FrameSize(w, h, b.rect[2] / b.rect[3]),  # the exact laid-out aspect
                )
                diags.extend(r.diagnostics)
                premul = r.rgba.astype(np.float32) / 255.0
                premul[..., :3] *= premul[..., 3:4]
                x0, y0 = round(b.rect[0]), round(b.rect[1])
                # the part inside the client area (a viewport may overhang it)
                ys, xs = max(0, -y0), max(0, -x0)
                ye, xe = min(h, canvas.shape[0] - y0), min(w, canvas.shape[1] - x0)
                if ye > ys and xe > xs:
                    _over(canvas, y0 + ys, x0 + xs, premul[ys:ye, xs:xe])
        if b.drawing is not None:  # a control's look (a GroupBox's frame over its panel)
            _draw_control(canvas, b)
        if b.kind == CONTROL and outline_controls:
            _outline(canvas, b.rect)
    while open_layers:
        canvas = _close_layer(*open_layers.pop(), canvas)
    canvas = canvas[top : top + client_h, left : left + client_w]
    return straight_uint8(np.ascontiguousarray(canvas)), diags
