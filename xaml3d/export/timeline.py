"""The one place the exporters read animation state from a Scene.

Everything the exporters know about storyboards comes through ``clip_of``: how long the
animation runs and the Scene at a moment of it. Today that is the Scene's ``timeline`` (the same
object ``xaml3d.render(scene, time=...)`` evaluates); when the Scene carries typed animation
tracks this module is the only one to change.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from xaml3d.errors import SceneError
from xaml3d.scene.types import Scene

ENDLESS_SECONDS = 10.0  # how much of an animation that never ends is exported


@dataclass(frozen=True)
class Clip:
    """The animation of a scene: ``seconds`` exported (one cycle, Forever repeats counted once:
    players loop an animation), ``endless`` when a Duration is Forever (only ``ENDLESS_SECONDS``
    are exported), and ``at(t)``, the Scene t seconds after load."""

    seconds: float
    endless: bool
    at: Callable[[float], Scene]


def clip_of(scene: Scene, storyboard: str | None = None) -> Clip | None:
    """The running animation of ``scene`` (Loaded storyboards, plus ``storyboard``), or None
    when nothing animates. SceneError ANIM010 when ``storyboard`` names none."""
    timeline = scene.timeline
    if timeline is None:
        if storyboard is not None:
            raise SceneError(f"no storyboard named {storyboard!r} (the document has none)",
                             code="ANIM010", file=scene.file)  # fmt: skip
        return None
    if not timeline.running_animations(storyboard):
        return None
    seconds = float(timeline.one_cycle(storyboard))
    endless = not math.isfinite(seconds)
    if not math.isfinite(seconds):
        seconds = ENDLESS_SECONDS
    base = timeline.base

    def at(t: float) -> Scene:
        frame = timeline.at(float(t), storyboard)
        return scene if frame is base else frame

    return Clip(seconds, endless, at)


def scene_at_start(scene: Scene, storyboard: str | None = None) -> Scene:
    """The scene as WPF first shows it (t = 0, Loaded storyboards begun): what is exported as
    the static state."""
    clip = clip_of(scene, storyboard)
    return scene if clip is None else clip.at(0.0)
