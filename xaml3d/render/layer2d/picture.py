"""A Viewport3D's own 2D properties applied to its rendered picture (scene Viewport2D).

Pipeline step: after the 3D picture is resolved, before it is composed over the background.
WPF draws a UIElement's content, clips it (Clip), applies its Effect to the clipped content,
fades it (Opacity, OpacityMask) and places the result by its RenderTransform, all in the
element's own coordinates (DIPs; ``scale`` gives image pixels per DIP). The picture keeps its
box: what a transform or a shadow moves beyond the viewport's rectangle is cut off.

BlurEffect's Radius and DropShadowEffect's BlurRadius are taken as a Gaussian of standard
deviation Radius / 3 (WPF's kernel reaches about three deviations); a drop shadow is offset by
ShadowDepth along Direction (degrees counter-clockwise from +x, y up on screen).
"""

from __future__ import annotations

import math

import numpy as np
import skia

from xaml3d.render.layer2d.paths import matrix, path_of
from xaml3d.render.layer2d.shaders import image_of, paint_of
from xaml3d.scene.drawing import Viewport2D


def _filter(effect, scale: float):
    if effect is None:
        return None
    sigma = max(0.0, float(effect.radius)) / 3.0
    if effect.kind == "Blur":
        return skia.ImageFilters.Blur(sigma, sigma) if sigma > 0 else None
    a = math.radians(float(effect.direction))
    dx = float(effect.shadow_depth) * math.cos(a)
    dy = -float(effect.shadow_depth) * math.sin(a)
    r, g, b, alpha = (float(c) for c in effect.color)
    color = skia.Color4f(r, g, b, alpha * float(effect.opacity)).toColor()
    return skia.ImageFilters.DropShadow(dx, dy, sigma, sigma, color)


def apply_picture(rgba: np.ndarray, picture: Viewport2D, scale: tuple[float, float]):
    """``rgba``: the viewport's straight-alpha uint8 picture (H, W, 4) on a transparent
    background; returns the picture WPF shows in the same box (straight-alpha uint8)."""
    h, w = rgba.shape[:2]
    sx, sy = scale
    info = skia.ImageInfo.Make(
        w, h, skia.ColorType.kRGBA_8888_ColorType, skia.AlphaType.kUnpremul_AlphaType
    )
    surface = skia.Surface.MakeRaster(info)
    canvas = surface.getCanvas()
    canvas.clear(skia.ColorTRANSPARENT)
    canvas.scale(sx, sy)
    if picture.render_transform is not None:
        canvas.concat(matrix(picture.render_transform))
    clip = path_of(picture.clip)
    if clip is not None:
        canvas.clipPath(clip, skia.ClipOp.kIntersect, True)
    box = skia.Rect.MakeWH(w / sx, h / sy)
    layer = skia.Paint()
    layer.setAlphaf(min(1.0, max(0.0, float(picture.opacity))))
    f = _filter(picture.effect, sx)
    if f is not None:
        layer.setImageFilter(f)
    canvas.saveLayer(None, layer)
    canvas.save()
    canvas.scale(1.0 / sx, 1.0 / sy)
    canvas.drawImage(image_of(rgba), 0, 0)
    canvas.restore()
    if picture.opacity_mask is not None:
        mask = paint_of(picture.opacity_mask, box)
        if mask is None:  # a mask that paints nothing hides everything
            mask = skia.Paint()
            mask.setColor(skia.ColorTRANSPARENT)
        mask.setBlendMode(skia.BlendMode.kDstIn)
        canvas.drawRect(box, mask)
    canvas.restore()
    return surface.makeImageSnapshot().toarray(
        colorType=skia.ColorType.kRGBA_8888_ColorType, alphaType=skia.AlphaType.kUnpremul_AlphaType
    )
