"""A visual's Effect as a skia image filter (the 2D layer): BlurEffect and DropShadowEffect.

BlurEffect's Radius and DropShadowEffect's BlurRadius are taken as a Gaussian of standard
deviation Radius / 3 (WPF's kernel reaches about three deviations); a drop shadow is offset by
ShadowDepth along Direction (degrees counter-clockwise from +x, y up on screen). Used by the
drawings a visual's effect applies to (``paint``) and by the element layers (``picture``).
"""

from __future__ import annotations

import math

import skia

from xaml3d.scene import trig


def effect_filter(effect):
    """The skia image filter of a scene Effect (None: nothing to do)."""
    if effect is None:
        return None
    sigma = max(0.0, float(effect.radius)) / 3.0
    if effect.kind == "Blur":
        return skia.ImageFilters.Blur(sigma, sigma) if sigma > 0 else None
    a = math.radians(float(effect.direction))
    dx = float(effect.shadow_depth) * trig.cos(a)
    dy = -float(effect.shadow_depth) * trig.sin(a)
    r, g, b, alpha = (float(c) for c in effect.color)
    color = skia.Color4f(r, g, b, alpha * float(effect.opacity)).toColor()
    return skia.ImageFilters.DropShadow(dx, dy, sigma, sigma, color)
