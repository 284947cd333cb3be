"""The animation codes (ANIMxxx): storyboards, targets, clocks.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import ERROR, INFO, WARNING

ANIM_CODES: dict[str, tuple[str, str]] = {
    "ANIM001": (ERROR, "Storyboard.TargetName names no object of the document"),
    "ANIM002": (
        ERROR,
        "Storyboard.TargetProperty does not resolve on the target (no such "
        "property, no object at a step, index out of range)",
    ),  # fmt: skip
    "ANIM003": (
        ERROR,
        "animation type does not match the property's type (a DoubleAnimation "
        "on a Point3D property)",
    ),  # fmt: skip
    "ANIM004": (
        ERROR,
        "the path goes through an object made from a string (frozen: WPF cannot animate it)",
    ),  # fmt: skip
    "ANIM005": (
        ERROR,
        "animation without Storyboard.TargetProperty, or without Storyboard.TargetName in a "
        "storyboard no trigger begins (nothing for the path to start from)",
    ),  # fmt: skip
    "ANIM006": (WARNING, "a time without a colon is a number of DAYS ('5' = five days)"),
    "ANIM007": (
        WARNING,
        "storyboard that can never start (no trigger begins it, or BeginTime is {x:Null})",
    ),  # fmt: skip
    "ANIM008": (
        WARNING,
        "animation that never has an effect (BeginTime {x:Null}, or a zero-length active period)",
    ),  # fmt: skip
    "ANIM010": (ERROR, "--storyboard names no storyboard of the document"),
    "ANIM014": (
        WARNING,
        "animation of a property the picture shows at its value at load: laid out once (a "
        "panel's or viewport's size, a LayoutTransform) or not a track of the scene (the "
        "RenderTransform or Opacity of a shape, of an element inside a visual or one the layout "
        "does not reach, a shape's or text's brush): its value at load is drawn in every frame",
    ),  # fmt: skip
    "ANIM011": (INFO, "animate: what length is drawn when it is not one whole cycle"),
    "ANIM015": (
        WARNING,
        "animate: there is no cycle to draw (nothing animates at load, a Duration is Forever, "
        "or the animations take no time): a fixed length is drawn",
    ),
    "ANIM016": (
        WARNING,
        "animate: the viewport is moved by its own RenderTransform (or an element's around it): "
        "the frames show its box, which the picture slides out of (--window draws the window)",
    ),  # fmt: skip
    "ANIM017": (
        ERROR,
        "animate: the length and --fps ask for more frames than --max-frames: nothing is drawn",
    ),
    "ANIM012": (
        WARNING,
        "animate: GIF frames shorter than 20 ms (over 50 fps), which most viewers slow to 100 ms",
    ),  # fmt: skip
    "ANIM020": (
        WARNING,
        "animation target on an object of another assembly (clr-namespace): not evaluated",
    ),  # fmt: skip
}
