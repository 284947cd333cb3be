"""Effects on elements inside a visual: a Button's BitmapEffect, written as a property
element, is its effect and not its content, and the visual's bounds grow by the blur."""

from __future__ import annotations

from pathlib import Path

import xaml3d
from xaml3d.scene.drawing import DrawingGroup, GeometryDrawing, TextDrawing

CASE = Path(__file__).parent / "reference" / "drawing" / "viewport2d-blurred-button.xaml"


def _walk(d):
    yield d
    for c in getattr(d, "children", ()):
        yield from _walk(c)


def test_bitmap_effect_property_element_is_not_content():
    scene = xaml3d.load(CASE)
    brush = next(m.material[0].brush for m in scene.viewports[0].models if m.material)
    groups = [d for d in _walk(brush.drawing) if isinstance(d, DrawingGroup) and d.effect]
    (blurred,) = groups
    assert (blurred.effect.kind, blurred.effect.radius) == ("Blur", 6.0)
    # the button's look and its text (element text after the property element) are blurred
    texts = [d.text for d in _walk(blurred) if isinstance(d, TextDrawing)]
    assert texts == ["Click me"]
    fills = [d.brush.color[:3] for d in _walk(blurred) if isinstance(d, GeometryDrawing)]
    assert fills[0] == (221 / 255,) * 3  # Aero2's face, the theme template's Border
    assert not [d for d in scene.diagnostics if d.code.startswith(("DRW", "LAY"))]


def test_the_visuals_bounds_grow_by_the_blur():
    from xaml3d.render.layer2d.paint import drawing_bounds

    scene = xaml3d.load(CASE)
    brush = next(m.material[0].brush for m in scene.viewports[0].models if m.material)
    r = drawing_bounds(brush.drawing)
    assert (r.left(), r.top(), r.right(), r.bottom()) == (-6.0, -6.0, 106.0, 36.0)
