"""The 2D layer's codes (drawings, visuals, the viewport's picture).

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import INFO, WARNING

DRAWING_CODES: dict[str, tuple[str, str]] = {
    "DRW001": (WARNING, "a geometry or path segment xaml3d does not draw: skipped"),
    "DRW002": (
        WARNING,
        "a Drawing or visual element xaml3d does not draw: skipped (the rest "
        "of the brush is drawn)",
    ),  # fmt: skip
    "DRW003": (INFO, "a 2D effect, mask or property of the viewport's picture not applied"),
    "DRW004": (WARNING, "VisualBrush without a Visual: it draws nothing"),
    "DRW009": (
        WARNING,
        "a VisualBrush that shows the element it paints (or one around it): the cycle's inner "
        "copy is not drawn",
    ),
    "DRW007": (INFO, "a control beside the viewports that render --window does not draw"),
    "DRW008": (
        INFO,
        "the viewport's own RenderTransform only translates it: render draws its picture in "
        "place, render --window where the translation puts it",
    ),  # fmt: skip
    "DRW006": (
        WARNING,
        "an element around a viewport the layout does not reach sets Opacity, OpacityMask, Clip, "
        "RenderTransform or an effect: WPF applies it to the viewport's picture, xaml3d cannot",
    ),  # fmt: skip
    "DRW005": (
        WARNING,
        "a Viewport2DVisual3D with no material marked IsVisualHostMaterial: "
        "its Visual is not shown (as in WPF)",
    ),  # fmt: skip
    "TXT001": (
        WARNING,
        "text with characters that neither its face nor any installed font has: drawn as "
        "empty boxes",
    ),  # fmt: skip
}
