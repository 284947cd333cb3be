"""A UIElement's 2D layer (scene Layer2D): a Viewport3D's own properties and those of the
elements around it applied to its rendered picture (scene Viewport2D), and any element's layer
over what ``render --window`` drew inside it.

Pipeline step: after the 3D picture is resolved, before it is composed over the background.
WPF draws a UIElement's content, applies its Effect, clips the result (Clip: a shadow or a
blur is cut too), fades it (Opacity, OpacityMask) and places it by its RenderTransform, all in the
element's own coordinates (DIPs; ``scale`` gives image pixels per DIP). The layers of nested
elements nest: each parent's applies to its child's composed layer. The picture keeps its
box: what a transform or a shadow moves beyond the viewport's rectangle is cut off.

BlurEffect and DropShadowEffect are applied as the image filters of ``effects``.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import skia

from xaml3d.render.layer2d.effects import effect_filter
from xaml3d.render.layer2d.paint import PLAYER
from xaml3d.render.layer2d.paths import matrix, path_of
from xaml3d.render.layer2d.shaders import image_of, paint_of
from xaml3d.scene.drawing import Viewport2D


def compose_layers(rgba: np.ndarray, levels, scale: tuple[float, float], place=None) -> np.ndarray:
    """``rgba``: a straight-alpha uint8 picture (H, W, 4) on a transparent background, drawn
    in coordinates of ``scale`` image pixels per DIP; ``levels``: (Layer2D, (x, y, w, h),
    (sx, sy)) from the outermost element in, each element's box in the picture's coordinates
    (DIPs) and the size of one of its own units there (a Viewbox around it scales them). Each
    element's layer nests inside its parent's, as WPF renders a visual tree: the parent's
    RenderTransform about its own box, its Clip, then the children drawn into one layer that
    takes its Effect, Opacity and OpacityMask, all in the element's own units. A clip set before
    a filtered layer cuts the filter's output only (skia's saveLayer), so the Effect acts on the
    unclipped content and the Clip on its result, as WPF's Visual composes them. Returns the
    straight-alpha uint8 picture in the same box, or with ``place`` (``placement.Placement``:
    the LayoutTransforms in ``levels`` turn the box) in the box they turn it into."""
    h, w = rgba.shape[:2]
    sx, sy = scale
    out_w, out_h = (w, h) if place is None else (place.width, place.height)
    info = skia.ImageInfo.Make(
        out_w, out_h, skia.ColorType.kRGBA_8888_ColorType, skia.AlphaType.kUnpremul_AlphaType
    )
    surface = skia.Surface.MakeRaster(info)
    canvas = surface.getCanvas()
    canvas.clear(skia.ColorTRANSPARENT)
    canvas.scale(sx, sy)
    if place is not None:  # the turned box's corner at the output's
        canvas.translate(-place.origin[0], -place.origin[1])
    if not all(u != 0.0 and math.isfinite(u) for _, _, unit in levels for u in unit):
        # an element scaled to nothing (a Viewbox of a zero-sized child...): WPF draws nothing
        return _pixels(surface)
    at, unit = (0.0, 0.0), (1.0, 1.0)  # the canvas's origin and unit, in picture DIPs
    for layer, (x, y, _, _), (ux, uy) in levels:
        canvas.save()
        # each element's coordinates start at its box's corner: the layout offsets nest
        canvas.translate((x - at[0]) / unit[0], (y - at[1]) / unit[1])
        canvas.scale(ux / unit[0], uy / unit[1])
        at, unit = (x, y), (ux, uy)
        if layer.layout_transform is not None:  # placed by the layout, then render-transformed
            canvas.concat(matrix(layer.layout_transform))
        if layer.render_transform is not None:
            canvas.concat(matrix(layer.render_transform))
        clip = path_of(layer.clip)
        if clip is not None:
            canvas.clipPath(clip, skia.ClipOp.kIntersect, True)
        paint = skia.Paint()
        paint.setAlphaf(min(1.0, max(0.0, float(layer.opacity))))
        f = effect_filter(layer.effect)
        if f is not None:
            paint.setImageFilter(f)
        canvas.saveLayer(None, paint)
    canvas.save()
    canvas.scale(1.0 / unit[0], 1.0 / unit[1])
    canvas.translate(-at[0], -at[1])
    canvas.scale(1.0 / sx, 1.0 / sy)
    canvas.drawImage(image_of(rgba), 0, 0)
    canvas.restore()
    for layer, (_, _, bw, bh), (ux, uy) in reversed(levels):
        if layer.opacity_mask is not None:
            box = skia.Rect.MakeWH(bw / ux, bh / uy)  # the element's own box, in its units
            mask = paint_of(layer.opacity_mask, box, player=PLAYER)
            if mask is None:  # a mask that paints nothing hides everything
                mask = skia.Paint()
                mask.setColor(skia.ColorTRANSPARENT)
            mask.setBlendMode(skia.BlendMode.kDstIn)
            canvas.drawPaint(mask)  # the whole layer: its edge pixels too (paint._draw_group)
        canvas.restore()  # the layer: faded and filtered into its parent
        canvas.restore()
    return _pixels(surface)


def _pixels(surface) -> np.ndarray:
    """The surface as straight-alpha RGBA bytes."""
    return surface.makeImageSnapshot().toarray(
        colorType=skia.ColorType.kRGBA_8888_ColorType, alphaType=skia.AlphaType.kUnpremul_AlphaType
    )


def apply_picture(rgba: np.ndarray, picture: Viewport2D, scale: tuple[float, float], place=None):
    """``rgba``: the viewport's straight-alpha uint8 picture (H, W, 4) on a transparent
    background; returns the picture WPF shows in the same box (straight-alpha uint8): the
    layers of the elements around it (outermost first), then its own; with ``place``
    (``placement.placement`` of the same picture) in the box its LayoutTransforms turn it to."""
    h, w = rgba.shape[:2]
    sx, sy = scale
    levels = [(a.layer, a.rect, a.unit) for a in reversed(picture.around)]
    levels.append((picture, (0.0, 0.0, w / sx, h / sy), (1.0, 1.0)))
    if place is None:  # without a placement, a LayoutTransform in the levels is not drawn
        levels = [(replace(lay, layout_transform=None), r, u) for lay, r, u in levels]
    return compose_layers(rgba, levels, scale, place)
