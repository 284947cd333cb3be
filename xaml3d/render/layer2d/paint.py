"""Drawing the scene's 2D content with skia: geometries, pens, brushes, drawings, text.

Pipeline step: the 2D layer. A ``scene.drawing`` Drawing is played onto a skia Canvas in
device-independent pixels (96 dpi: one DIP is one pixel at scale 1), anti-aliased, blended as
WPF blends (premultiplied sRGB, source over). Brushes become skia shaders: SolidColorBrush,
LinearGradientBrush and RadialGradientBrush (stops interpolated in straight alpha as WPF does;
SpreadMethod Pad / Reflect / Repeat; MappingMode and the brush transforms through the same
matrices as the 3D brushes, ``render.brushes.brush_to_texture_matrix``), and the tile brushes
ImageBrush and DrawingBrush (their tile recorded as a skia Picture and repeated by a picture
shader: TileMode None / Tile / FlipX / FlipY / FlipXY). Relative brush units refer to the
bounds of the geometry (or text) being filled.

Pens: StartLineCap and EndLineCap (Flat, Square, Round, Triangle) are drawn as each end's own
shape when they differ or one is Triangle (skia strokes with one cap); dashed lines use DashCap.
PathFigure.IsFilled="False" figures are stroked, never filled.
"""

from __future__ import annotations

import math

import numpy as np
import skia

from xaml3d.fonts import typeface
from xaml3d.render.brushes import brush_to_texture_matrix
from xaml3d.scene.drawing import (
    CombinedGeometry,
    DrawingBrush,
    DrawingGroup,
    EllipseGeometry,
    GeometryDrawing,
    GeometryGroup,
    ImageDrawing,
    LineGeometry,
    PathGeometry,
    RectangleGeometry,
    TextDrawing,
)
from xaml3d.scene.types import (
    ImageBrush,
    LinearGradientBrush,
    PlaceholderBrush,
    RadialGradientBrush,
    SolidColorBrush,
)

_OPS = {
    "Union": skia.PathOp.kUnion_PathOp,
    "Intersect": skia.PathOp.kIntersect_PathOp,
    "Xor": skia.PathOp.kXOR_PathOp,
    "Exclude": skia.PathOp.kDifference_PathOp,
}
_SPREAD = {
    "Pad": skia.TileMode.kClamp,
    "Reflect": skia.TileMode.kMirror,
    "Repeat": skia.TileMode.kRepeat,
}
_CAPS = {
    "Flat": skia.Paint.Cap.kButt_Cap,
    "Triangle": skia.Paint.Cap.kButt_Cap,
    "Square": skia.Paint.Cap.kSquare_Cap,
    "Round": skia.Paint.Cap.kRound_Cap,
}
_JOINS = {
    "Miter": skia.Paint.Join.kMiter_Join,
    "Bevel": skia.Paint.Join.kBevel_Join,
    "Round": skia.Paint.Join.kRound_Join,
}
_ALIGN = {"Left": 0.0, "Top": 0.0, "Center": 0.5, "Right": 1.0, "Bottom": 1.0}


def matrix(m) -> skia.Matrix:
    """A 3x3 column-form affine matrix (or None: identity) as a skia Matrix."""
    if m is None:
        return skia.Matrix()
    a = np.asarray(m, dtype=np.float64)
    return skia.Matrix.MakeAll(
        float(a[0, 0]), float(a[0, 1]), float(a[0, 2]),
        float(a[1, 0]), float(a[1, 1]), float(a[1, 2]), 0.0, 0.0, 1.0,
    )  # fmt: skip


def _color4f(rgba, opacity: float = 1.0) -> skia.Color4f:
    r, g, b, a = (float(c) for c in rgba)
    return skia.Color4f(r, g, b, a * opacity)


def _color(rgba) -> int:
    r, g, b, a = (int(round(min(1.0, max(0.0, float(c))) * 255)) for c in rgba)
    return skia.ColorSetARGB(a, r, g, b)


# --------------------------------------------------------------------------- geometry


def path_of(geometry, filled: bool = False) -> skia.Path | None:
    """A scene geometry as a skia Path (its own Transform applied), None for no geometry.
    ``filled``: only the figures a fill covers (PathFigure.IsFilled="False" ones left out)."""
    if geometry is None:
        return None
    p = skia.Path()
    if isinstance(geometry, RectangleGeometry):
        x, y, w, h = geometry.rect
        r = skia.Rect.MakeXYWH(x, y, max(w, 0.0), max(h, 0.0))
        rx, ry = min(abs(geometry.radius_x), w / 2), min(abs(geometry.radius_y), h / 2)
        if rx > 0 and ry > 0:
            p.addRRect(skia.RRect.MakeRectXY(r, rx, ry))
        else:
            p.addRect(r)
    elif isinstance(geometry, EllipseGeometry):
        cx, cy = geometry.center
        rx, ry = abs(geometry.radius_x), abs(geometry.radius_y)
        p.addOval(skia.Rect.MakeLTRB(cx - rx, cy - ry, cx + rx, cy + ry))
    elif isinstance(geometry, LineGeometry):
        p.moveTo(*geometry.start)
        p.lineTo(*geometry.end)
    elif isinstance(geometry, PathGeometry):
        _commands(p, _filled_figures(geometry.commands) if filled else geometry.commands)
        p.setFillType(_fill(geometry.fill_rule))
    elif isinstance(geometry, GeometryGroup):
        for child in geometry.children:
            cp = path_of(child, filled)
            if cp is not None:
                p.addPath(cp)
        p.setFillType(_fill(geometry.fill_rule))
    elif isinstance(geometry, CombinedGeometry):
        a = path_of(geometry.geometry1, filled) or skia.Path()
        b = path_of(geometry.geometry2, filled) or skia.Path()
        p = skia.Op(a, b, _OPS.get(geometry.mode, skia.PathOp.kUnion_PathOp)) or skia.Path()
    else:
        return None
    if geometry.transform is not None:
        p.transform(matrix(geometry.transform))
    return p


def _filled_figures(commands) -> tuple:
    out, keep = [], True
    for c in commands:
        if c[0] in ("M", "M-"):
            keep = c[0] == "M"
        if keep:
            out.append(c)
    return tuple(out)


def _fill(rule: str):
    return skia.PathFillType.kEvenOdd if rule == "EvenOdd" else skia.PathFillType.kWinding


def _commands(p: skia.Path, commands) -> None:
    for c in commands:
        verb = c[0]
        if verb in ("M", "M-"):
            p.moveTo(c[1], c[2])
        elif verb == "L":
            p.lineTo(c[1], c[2])
        elif verb == "Q":
            p.quadTo(*c[1:5])
        elif verb == "C":
            p.cubicTo(*c[1:7])
        elif verb == "A":
            rx, ry, rot, large, sweep, x, y = c[1:8]
            if rx == 0 or ry == 0:
                p.lineTo(x, y)  # WPF draws a degenerate arc as a straight line
                continue
            size = skia.Path.ArcSize.kLarge_ArcSize if large else skia.Path.ArcSize.kSmall_ArcSize
            # y points down in both: WPF's Clockwise sweep is skia's clockwise direction
            direction = skia.PathDirection.kCW if sweep else skia.PathDirection.kCCW
            p.arcTo(rx, ry, rot, size, direction, x, y)
        elif verb == "Z":
            p.close()


# --------------------------------------------------------------------------- brushes


def _gradient_stops(brush) -> tuple[list, list]:
    order = sorted(range(len(brush.stops)), key=lambda i: brush.stops[i].offset)
    stops = [brush.stops[i] for i in order]
    colors = [_color(s.color) for s in stops]
    offsets = [min(1.0, max(0.0, float(s.offset))) for s in stops]
    return colors, offsets


def _bounds(rect: skia.Rect) -> tuple[np.ndarray, np.ndarray]:
    lo = np.array([rect.left(), rect.top()], dtype=np.float64)
    hi = np.array([rect.right(), rect.bottom()], dtype=np.float64)
    # an empty box (a horizontal line) keeps relative units invertible, as the 3D brushes do
    return lo, np.where(hi - lo > 0.0, hi, lo + 1.0)


def shader_of(brush, box: skia.Rect) -> skia.Shader | None:
    """The brush as a skia shader over the element box ``box`` (relative units refer to it);
    None: a flat colour (or nothing) is enough, see ``paint_of``."""
    bounds = _bounds(box)
    if isinstance(brush, LinearGradientBrush) and brush.stops:
        m = brush_to_texture_matrix(brush, bounds, brush.mapping_mode != "Absolute")
        colors, offsets = _gradient_stops(brush)
        pts = [skia.Point(*brush.start_point), skia.Point(*brush.end_point)]
        return skia.GradientShader.MakeLinear(
            pts, colors, offsets, _SPREAD[brush.spread_method], 0, matrix(m)
        )
    if isinstance(brush, RadialGradientBrush) and brush.stops:
        m = brush_to_texture_matrix(brush, bounds, brush.mapping_mode != "Absolute")
        rx, ry = float(brush.radius_x), float(brush.radius_y)
        if rx == 0 or ry == 0:
            return None
        cx, cy = brush.center
        ellipse = np.array([[rx, 0.0, cx], [0.0, ry, cy], [0.0, 0.0, 1.0]])
        ox, oy = (brush.gradient_origin[0] - cx) / rx, (brush.gradient_origin[1] - cy) / ry
        colors, offsets = _gradient_stops(brush)
        return skia.GradientShader.MakeTwoPointConical(
            skia.Point(ox, oy), 0.0, skia.Point(0.0, 0.0), 1.0, colors, offsets,
            _SPREAD[brush.spread_method], 0, matrix(m @ ellipse),
        )  # fmt: skip
    if isinstance(brush, (ImageBrush, DrawingBrush)):
        return _tile_shader(brush, bounds)
    return None


def paint_of(brush, box: skia.Rect, opacity: float = 1.0) -> skia.Paint | None:
    """A fill Paint for ``brush`` over ``box``; None when the brush draws nothing."""
    if brush is None:
        return None
    paint = skia.Paint(AntiAlias=True)
    op = float(getattr(brush, "opacity", 1.0)) * opacity
    if isinstance(brush, (SolidColorBrush, PlaceholderBrush)):
        paint.setColor4f(_color4f(brush.color, op))
        return paint
    if isinstance(brush, (LinearGradientBrush, RadialGradientBrush)) and not brush.stops:
        return None  # no stops: transparent
    shader = shader_of(brush, box)
    if shader is None:
        if isinstance(brush, (LinearGradientBrush, RadialGradientBrush)):
            # a degenerate gradient paints its last stop's colour, as the 3D brushes do
            colors, _ = _gradient_stops(brush)
            paint.setColor(colors[-1])
            paint.setAlphaf(paint.getAlphaf() * op)
            return paint
        return None
    paint.setShader(shader)
    paint.setAlphaf(op)
    return paint


def tile_layout(brush, bounds, content: tuple[float, float, float, float]):
    """TileBrush layout (wpf3d.md section 7, as ``render.brushes`` does for images): the
    viewport (x, y, w, h) in brush space and the 3x3 matrix taking content coordinates into
    brush space (Viewbox stretched into the Viewport by Stretch and the alignments); None when
    the viewbox or viewport is empty."""
    cx, cy, cw, ch = content
    vbx, vby, vbw, vbh = (float(v) for v in brush.viewbox)
    if brush.viewbox_units != "Absolute":
        vbx, vbw, vby, vbh = cx + vbx * cw, vbw * cw, cy + vby * ch, vbh * ch
    vpx, vpy, vpw, vph = (float(v) for v in brush.viewport)
    if brush.viewport_units != "Absolute":
        lo, hi = bounds
        size = hi - lo
        vpx, vpw = lo[0] + vpx * size[0], vpw * size[0]
        vpy, vph = lo[1] + vpy * size[1], vph * size[1]
    if min(vbw, vbh, vpw, vph) <= 0.0 or not all(map(math.isfinite, (vbw, vbh, vpw, vph))):
        return None
    sx, sy = vpw / vbw, vph / vbh
    if brush.stretch == "Uniform":
        sx = sy = min(sx, sy)
    elif brush.stretch == "UniformToFill":
        sx = sy = max(sx, sy)
    elif brush.stretch == "None":
        sx = sy = 1.0
    ox = vpx + (vpw - vbw * sx) * _ALIGN.get(brush.alignment_x, 0.5)
    oy = vpy + (vph - vbh * sy) * _ALIGN.get(brush.alignment_y, 0.5)
    m = np.array([[sx, 0.0, ox - vbx * sx], [0.0, sy, oy - vby * sy], [0.0, 0.0, 1.0]])
    return (vpx, vpy, vpw, vph), m


def content_bounds(brush) -> tuple[float, float, float, float] | None:
    """The box relative Viewbox units refer to: an ImageBrush's picture (one pixel per DIP),
    a drawing's bounds, or the bounds the reader gave (a Viewport2DVisual3D's visual)."""
    if isinstance(brush, ImageBrush):
        if brush.image is None or brush.image.size == 0:
            return None
        h, w = brush.image.shape[:2]
        return (0.0, 0.0, float(w), float(h))
    if brush.content_bounds is not None:
        return brush.content_bounds
    r = drawing_bounds(brush.drawing)
    if r is None or r.isEmpty():
        return None
    return (r.left(), r.top(), r.width(), r.height())


def draw_content(canvas: skia.Canvas, brush) -> None:
    """A tile brush's content in its own coordinates."""
    if isinstance(brush, ImageBrush):
        img = image_of(brush.image)
        if img is not None:
            canvas.drawImage(img, 0, 0, skia.SamplingOptions(skia.FilterMode.kLinear))
    else:
        draw(canvas, brush.drawing)


def _tile_shader(brush, bounds) -> skia.Shader | None:
    content = content_bounds(brush)
    if content is None:
        return None
    found = tile_layout(brush, bounds, content)
    if found is None:
        return None
    (vpx, vpy, vpw, vph), m = found
    rec = skia.PictureRecorder()
    canvas = rec.beginRecording(skia.Rect.MakeXYWH(vpx, vpy, vpw, vph))
    canvas.clipRect(skia.Rect.MakeXYWH(vpx, vpy, vpw, vph))
    canvas.concat(matrix(m))
    draw_content(canvas, brush)
    picture = rec.finishRecordingAsPicture()
    mode = brush.tile_mode
    tx, ty = (_tile_mode(mode, flip) for flip in (("FlipX", "FlipXY"), ("FlipY", "FlipXY")))
    local = brush_to_texture_matrix(brush, bounds, False)
    return picture.makeShader(
        tx, ty, skia.FilterMode.kLinear, matrix(local), skia.Rect.MakeXYWH(vpx, vpy, vpw, vph)
    )


def _tile_mode(mode: str, flips: tuple[str, ...]):
    if mode == "None":
        return skia.TileMode.kDecal
    return skia.TileMode.kMirror if mode in flips else skia.TileMode.kRepeat


def image_of(arr) -> skia.Image | None:
    """A straight-alpha (H, W, 4) uint8 array as a skia Image."""
    if arr is None or arr.size == 0:
        return None
    return skia.Image.fromarray(
        np.ascontiguousarray(arr, dtype=np.uint8),
        colorType=skia.ColorType.kRGBA_8888_ColorType,
        alphaType=skia.AlphaType.kUnpremul_AlphaType,
    )


# --------------------------------------------------------------------------- drawings


def _stroke_paint(pen, box: skia.Rect, dashed: bool = True) -> skia.Paint | None:
    if pen is None or pen.brush is None or not (pen.thickness > 0):
        return None
    paint = paint_of(pen.brush, box)
    if paint is None:
        return None
    paint.setStyle(skia.Paint.kStroke_Style)
    paint.setStrokeWidth(float(pen.thickness))
    paint.setStrokeCap(_CAPS[pen.dash_cap if pen.dashes else pen.start_cap])
    paint.setStrokeJoin(_JOINS[pen.line_join])
    # WPF's MiterLimit is a ratio to half the thickness, skia's to the whole thickness
    paint.setStrokeMiter(max(1.0, float(pen.miter_limit) / 2.0))
    if pen.dashes and dashed:
        t = float(pen.thickness)
        intervals = [max(0.0, d) * t for d in pen.dashes]
        if len(intervals) % 2:
            intervals = intervals * 2
        if sum(intervals) > 0:
            paint.setPathEffect(skia.DashPathEffect.Make(intervals, float(pen.dash_offset) * t))
    return paint


def _cap(out: skia.Path, kind: str, pos, tan, half: float) -> None:
    """One line cap at ``pos`` facing outwards along the unit vector ``tan``."""
    x, y, tx, ty = pos.x(), pos.y(), tan.x(), tan.y()
    nx, ny = -ty * half, tx * half  # the half-thickness across the line
    if kind == "Round":
        out.addCircle(x, y, half)
    elif kind == "Square":
        fx, fy = tx * half, ty * half
        out.moveTo(x + nx, y + ny)
        out.lineTo(x + nx + fx, y + ny + fy)
        out.lineTo(x - nx + fx, y - ny + fy)
        out.lineTo(x - nx, y - ny)
        out.close()
    elif kind == "Triangle":
        out.moveTo(x + nx, y + ny)
        out.lineTo(x + tx * half, y + ty * half)
        out.lineTo(x - nx, y - ny)
        out.close()


def _caps(path: skia.Path, pen) -> skia.Path:
    """The StartLineCap and EndLineCap shapes of every open figure of ``path``."""
    out = skia.Path()
    out.setFillType(skia.PathFillType.kWinding)
    half = float(pen.thickness) / 2.0
    measure = skia.PathMeasure(path, False)
    while True:
        length = measure.getLength()
        if length > 0 and not measure.isClosed():
            pos, tan = measure.getPosTan(0.0)
            _cap(out, pen.start_cap, pos, skia.Point(-tan.x(), -tan.y()), half)
            pos, tan = measure.getPosTan(length)
            _cap(out, pen.end_cap, pos, tan, half)
        if not measure.nextContour():
            return out


def _font(d: TextDrawing) -> skia.Font:
    font = skia.Font(typeface(d.weight, d.italic), float(d.font_size))
    font.setEdging(skia.Font.Edging.kAntiAlias)
    font.setSubpixel(True)
    font.setHinting(skia.FontHinting.kNone)
    return font


def _text_box(d: TextDrawing, font: skia.Font) -> skia.Rect:
    from xaml3d.fonts import SEGOE_UI_BASELINE, SEGOE_UI_LINE_SPACING

    width = font.measureText(d.text)
    top = d.origin[1] - SEGOE_UI_BASELINE * d.font_size
    return skia.Rect.MakeXYWH(d.origin[0], top, width, SEGOE_UI_LINE_SPACING * d.font_size)


def draw(canvas: skia.Canvas, d) -> None:
    """Play one scene drawing onto ``canvas`` (in the canvas's current coordinates)."""
    if d is None:
        return
    if isinstance(d, GeometryDrawing):
        path = path_of(d.geometry)
        if path is None:
            return
        box = path.computeTightBounds()
        fill = paint_of(d.brush, box)
        if fill is not None:
            canvas.drawPath(path_of(d.geometry, filled=True), fill)
        stroke = _stroke_paint(d.pen, box)
        if stroke is not None:
            pen = d.pen
            own_caps = not pen.dashes and (
                pen.start_cap != pen.end_cap or "Triangle" in (pen.start_cap, pen.end_cap)
            )
            if own_caps:  # skia has one cap for both ends: flat ends, then each end's cap
                stroke.setStrokeCap(skia.Paint.Cap.kButt_Cap)
            canvas.drawPath(path, stroke)
            if own_caps:
                stroke.setStyle(skia.Paint.kFill_Style)
                canvas.drawPath(_caps(path, pen), stroke)
    elif isinstance(d, TextDrawing):
        font = _font(d)
        paint = paint_of(d.brush, _text_box(d, font))
        if paint is not None and d.text:
            canvas.drawString(d.text, float(d.origin[0]), float(d.origin[1]), font, paint)
    elif isinstance(d, ImageDrawing):
        img = image_of(d.image)
        x, y, w, h = d.rect
        if img is not None and w > 0 and h > 0:
            canvas.drawImageRect(
                img, skia.Rect.MakeXYWH(x, y, w, h), skia.SamplingOptions(skia.FilterMode.kLinear)
            )
    elif isinstance(d, DrawingGroup):
        _draw_group(canvas, d)


def _draw_group(canvas: skia.Canvas, g: DrawingGroup) -> None:
    if g.opacity <= 0:
        return
    canvas.save()
    canvas.concat(matrix(g.transform))
    clip = path_of(g.clip)
    if clip is not None:
        canvas.clipPath(clip, skia.ClipOp.kIntersect, True)
    layered = g.opacity < 1.0 or g.opacity_mask is not None
    if layered:
        # the group is composed first, then faded as a whole (not each child on its own)
        layer = skia.Paint()
        layer.setAlphaf(min(1.0, float(g.opacity)))
        canvas.saveLayer(None, layer)
    for child in g.children:
        draw(canvas, child)
    if g.opacity_mask is not None:
        # the mask's relative units refer to the group's content, in the group's coordinates
        box = drawing_bounds(DrawingGroup(children=g.children))
        mask = paint_of(g.opacity_mask, box) if box is not None else None
        if mask is not None:
            mask.setBlendMode(skia.BlendMode.kDstIn)
            canvas.drawRect(box, mask)
    if layered:
        canvas.restore()
    canvas.restore()


def drawing_bounds(d) -> skia.Rect | None:
    """A drawing's bounds in its own coordinates (WPF's Drawing.Bounds: pens included,
    clips applied), None for nothing drawn."""
    if d is None:
        return None
    if isinstance(d, GeometryDrawing):
        path = path_of(d.geometry)
        if path is None or (d.brush is None and d.pen is None):
            return None
        r = path.computeTightBounds()
        stroke = _stroke_paint(d.pen, r, dashed=False)
        if stroke is not None:
            wide = skia.Path()
            if stroke.getFillPath(path, wide):
                r = skia.Rect(r.left(), r.top(), r.right(), r.bottom())
                r.join(wide.computeTightBounds())
        return r
    if isinstance(d, TextDrawing):
        return _text_box(d, _font(d)) if d.text else None
    if isinstance(d, ImageDrawing):
        return skia.Rect.MakeXYWH(*d.rect)
    if isinstance(d, DrawingGroup):
        out = None
        for child in d.children:
            r = drawing_bounds(child)
            if r is None:
                continue
            if out is None:
                out = skia.Rect(r.left(), r.top(), r.right(), r.bottom())
            else:
                out.join(r)
        if out is None:
            return None
        clip = path_of(d.clip)
        if clip is not None and not out.intersect(clip.computeTightBounds()):
            return None
        return matrix(d.transform).mapRect(out)
    return None


def rasterize(drawing, width: int, height: int, transform=None) -> np.ndarray:
    """``drawing`` played onto a transparent ``width`` x ``height`` picture through the 3x3
    ``transform`` (drawing coordinates -> pixels): premultiplied float32 (H, W, 4) in 0..1."""
    info = skia.ImageInfo.Make(
        width, height, skia.ColorType.kRGBA_8888_ColorType, skia.AlphaType.kPremul_AlphaType
    )
    surface = skia.Surface.MakeRaster(info)
    canvas = surface.getCanvas()
    canvas.clear(skia.ColorTRANSPARENT)
    canvas.concat(matrix(transform))
    draw(canvas, drawing)
    arr = surface.makeImageSnapshot().toarray(
        colorType=skia.ColorType.kRGBA_8888_ColorType, alphaType=skia.AlphaType.kPremul_AlphaType
    )
    return arr.astype(np.float32) / 255.0
