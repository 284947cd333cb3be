"""Drawing the scene's 2D content with skia: drawings and text (the 2D layer).

Pipeline step: the 2D layer. A ``scene.drawing`` Drawing is played onto a skia Canvas in
device-independent pixels (96 dpi: one DIP is one pixel at scale 1), anti-aliased, blended as
WPF blends (premultiplied sRGB, source over): GeometryDrawing (fill, then pen: ``paths``,
``shaders``, ``pens``), ImageDrawing, TextDrawing (the face its FontFamily is set in,
``xaml3d.fonts``; characters the face lacks in the system's font that has them,
``xaml3d.font_fallback``) and
DrawingGroup (Transform, ClipGeometry, Opacity and OpacityMask on the composed group); and a
drawing's bounds (WPF's Drawing.Bounds: pens included, clips applied; a visual's effects
spread them as WPF's Effect.GetRenderBounds).
"""

from __future__ import annotations

import math

import numpy as np
import skia

from xaml3d.fonts import face_of, typeface
from xaml3d.render.layer2d.effects import effect_filter
from xaml3d.render.layer2d.paths import matrix, path_of
from xaml3d.render.layer2d.pens import caps_path, stroke_paint
from xaml3d.render.layer2d.shaders import DrawingPlayer, image_of, paint_of
from xaml3d.scene import trig
from xaml3d.scene.drawing import (
    DrawingGroup,
    GeometryDrawing,
    ImageDrawing,
    TextDrawing,
)


def _font(d: TextDrawing, face=None) -> skia.Font:
    """The skia Font of ``d``: its family's face, or ``face`` (a system font's typeface)."""
    if face is None:
        face = typeface(d.weight, d.italic, d.family)
    font = skia.Font(face, float(d.font_size))
    font.setEdging(skia.Font.Edging.kAntiAlias)
    font.setSubpixel(True)
    font.setHinting(skia.FontHinting.kNone)
    return font


def _text_runs(d: TextDrawing) -> list[tuple[str, skia.Font]]:
    """``d``'s text cut into runs of one font: the face's, and the system's fonts for the
    characters the face lacks (as layout measured them)."""
    font = _font(d)
    glyphs = font.getTypeface().unicharsToGlyphs([ord(c) for c in d.text])
    if all(glyphs):
        return [(d.text, font)]
    from xaml3d.font_fallback import runs

    missing = [g == 0 for g in glyphs]
    return [
        (t, font if tf is None else _font(d, tf))
        for t, tf in runs(d.text, missing, d.weight, d.italic)
    ]


def _text_box(d: TextDrawing, runs: list[tuple[str, skia.Font]]) -> skia.Rect:
    """The line box of ``d``: its runs' advances wide, its family's line tall."""
    face = face_of(d.family)
    width = sum(font.measureText(t) for t, font in runs)
    top = d.origin[1] - face.baseline * d.font_size
    return skia.Rect.MakeXYWH(d.origin[0], top, width, face.line_spacing * d.font_size)


def draw(canvas: skia.Canvas, d) -> None:
    """Play one scene drawing onto ``canvas`` (in the canvas's current coordinates)."""
    if d is None:
        return
    if isinstance(d, GeometryDrawing):
        path = path_of(d.geometry)
        if path is None:
            return
        box = path.computeTightBounds()
        fill = paint_of(d.brush, box, player=PLAYER)
        if fill is not None:
            canvas.drawPath(path_of(d.geometry, filled=True), fill)
        stroke = stroke_paint(d.pen, box, player=PLAYER)
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
                canvas.drawPath(caps_path(path, pen), stroke)
    elif isinstance(d, TextDrawing):
        if not d.text:
            return
        runs = _text_runs(d)
        paint = paint_of(d.brush, _text_box(d, runs), player=PLAYER)
        if paint is not None:
            x = float(d.origin[0])
            for text, font in runs:
                canvas.drawString(text, x, float(d.origin[1]), font, paint)
                x += font.measureText(text)
    elif isinstance(d, ImageDrawing):
        img = image_of(d.image)
        x, y, w, h = d.rect
        if img is not None and w > 0 and h > 0:
            canvas.drawImageRect(img, skia.Rect.MakeXYWH(x, y, w, h), _sampling(d.scaling))
    elif isinstance(d, DrawingGroup):
        _draw_group(canvas, d)


def _sampling(scaling: str) -> skia.SamplingOptions:
    """How an image is resampled under RenderOptions.BitmapScalingMode."""
    if scaling == "NearestNeighbor":
        return skia.SamplingOptions(skia.FilterMode.kNearest)
    if scaling in ("Fant", "HighQuality"):  # WPF's Fant scaler averages when it shrinks
        return skia.SamplingOptions(skia.FilterMode.kLinear, skia.MipmapMode.kLinear)
    return skia.SamplingOptions(skia.FilterMode.kLinear)


def _draw_group(canvas: skia.Canvas, g: DrawingGroup) -> None:
    if g.opacity <= 0:
        return
    canvas.save()
    canvas.concat(matrix(g.transform))
    clip = path_of(g.clip)
    if clip is not None:
        canvas.clipPath(clip, skia.ClipOp.kIntersect, True)
    layered = g.opacity < 1.0 or g.opacity_mask is not None or g.effect is not None
    if layered:
        # the group is composed first, then filtered and faded as a whole (not each child)
        layer = skia.Paint()
        layer.setAlphaf(min(1.0, float(g.opacity)))
        f = effect_filter(g.effect)
        if f is not None:
            layer.setImageFilter(f)
        canvas.saveLayer(None, layer)
    for child in g.children:
        draw(canvas, child)
    if g.opacity_mask is not None:
        # the mask's relative units refer to the group's content, in the group's coordinates
        box = drawing_bounds(DrawingGroup(children=g.children))
        mask = paint_of(g.opacity_mask, box, player=PLAYER) if box is not None else None
        if mask is not None:
            mask.setBlendMode(skia.BlendMode.kDstIn)
            # over the whole layer, as WPF multiplies the content by the mask brush wherever it
            # is (a gradient pads beyond its box): a rectangle's own antialiased edge would
            # leave the content's edge pixels outside it, and half of those on it, unmasked
            canvas.drawPaint(mask)
    if layered:
        canvas.restore()
    canvas.restore()


def drawing_bounds(d) -> skia.Rect | None:
    """A drawing's bounds in its own coordinates (WPF's Drawing.Bounds: pens included,
    clips applied, an element's effect spread), None for nothing drawn."""
    if d is None:
        return None
    if isinstance(d, GeometryDrawing):
        if d.brush is None and d.pen is None:
            return None
        b = render_bounds(d.geometry, d.pen)
        return None if b is None else skia.Rect(*b)
    if isinstance(d, TextDrawing):
        return _text_box(d, _text_runs(d)) if d.text else None
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
        if d.effect is not None:
            out = _effect_bounds(out, d.effect)
        clip = path_of(d.clip)
        if clip is not None and not out.intersect(clip.computeTightBounds()):
            return None
        return matrix(d.transform).mapRect(out)
    return None


# how the brushes (``shaders``, ``pens``) play and measure a DrawingBrush's drawing: with the
# functions above, which call them in turn
PLAYER = DrawingPlayer(draw=draw, bounds=drawing_bounds)


def render_bounds(geometry, pen=None) -> tuple[float, float, float, float] | None:
    """WPF's Geometry.GetRenderBounds(pen): (left, top, right, bottom) of what the geometry
    covers drawn with ``pen`` (its dashes ignored: the whole line), curves and arcs at their
    extrema rather than their control points, joins (miters) and both ends' caps counted;
    without a pen, Geometry.Bounds. None for no geometry."""
    path = path_of(geometry)
    if path is None:
        return None
    r = path.computeTightBounds()
    out = [r.left(), r.top(), r.right(), r.bottom()]
    stroke = stroke_paint(pen, r, dashed=False, player=PLAYER)
    if stroke is not None:
        own_caps = pen.start_cap != pen.end_cap or "Triangle" in (pen.start_cap, pen.end_cap)
        if own_caps:  # as drawn: flat ends, then each end's own cap
            stroke.setStrokeCap(skia.Paint.Cap.kButt_Cap)
        wide = skia.Path()
        if stroke.getFillPath(path, wide):
            _join(out, wide.computeTightBounds())
        if own_caps:
            _join(out, caps_path(path, pen).computeTightBounds())
    return tuple(float(v) for v in out)


def _join(out: list, r: skia.Rect) -> None:
    if r.isEmpty():
        return
    out[0], out[1] = min(out[0], r.left()), min(out[1], r.top())
    out[2], out[3] = max(out[2], r.right()), max(out[3], r.bottom())


def _effect_bounds(r: skia.Rect, effect) -> skia.Rect:
    """What an Effect draws of content within ``r``, as WPF's Effect.GetRenderBounds counts it
    (a visual's bounds include it): a blur spreads Radius every way; a drop shadow spreads
    BlurRadius every way and reaches ShadowDepth further along Direction (y up on screen)."""
    spread = max(0.0, float(effect.radius))
    left, top = r.left() - spread, r.top() - spread
    right, bottom = r.right() + spread, r.bottom() + spread
    if effect.kind == "DropShadow":
        a = math.radians(float(effect.direction))
        dx = float(effect.shadow_depth) * trig.cos(a)
        dy = float(effect.shadow_depth) * trig.sin(a)
        left, right = (left, right + dx) if dx >= 0 else (left + dx, right)
        top, bottom = (top - dy, bottom) if dy >= 0 else (top, bottom - dy)
    return skia.Rect(left, top, right, bottom)


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
