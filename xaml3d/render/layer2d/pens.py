"""Pens as skia stroke paints, and the line caps skia cannot draw itself (the 2D layer).

Pen Thickness, Brush, LineJoin, MiterLimit (WPF's is a ratio to half the thickness, skia's to
the whole), DashStyle (dashes in multiples of the thickness, DashCap on every dash), and
StartLineCap / EndLineCap (Flat, Square, Round, Triangle) drawn as each end's own shape when
they differ or one is Triangle: skia strokes a path with one cap for both ends.
"""

from __future__ import annotations

import skia

from xaml3d.render.layer2d.shaders import DrawingPlayer, paint_of

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


def stroke_paint(
    pen, box: skia.Rect, dashed: bool = True, *, player: DrawingPlayer
) -> skia.Paint | None:
    if pen is None or pen.brush is None or not (pen.thickness > 0):
        return None
    paint = paint_of(pen.brush, box, player=player)
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


def caps_path(path: skia.Path, pen) -> skia.Path:
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
