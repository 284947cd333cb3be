"""The one place the exporters read animation state from a Scene.

Everything the exporters know about storyboards comes through ``clip_of``: how long the
animation runs and the Scene at a moment of it, from the Scene's animation tracks evaluated by
``xaml3d.animation.timeline`` (as ``xaml3d.render(scene, time=...)`` evaluates them).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

from xaml3d.animation import timeline as A
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
    if scene.tracks is None:
        if storyboard is not None:
            raise SceneError(f"no storyboard named {storyboard!r} (the document has none)",
                             code="ANIM010", file=scene.file)  # fmt: skip
        return None
    if not A.running_animations(scene, storyboard):
        return None
    seconds = float(A.one_cycle(scene, storyboard))
    endless = not math.isfinite(seconds)
    if not math.isfinite(seconds):
        seconds = ENDLESS_SECONDS
    return Clip(seconds, endless, partial(_at, scene, storyboard))


def _at(scene: Scene, storyboard: str | None, t: float) -> Scene:
    return A.scene_at(scene, float(t), storyboard)


def scene_at_start(scene: Scene, storyboard: str | None = None) -> Scene:
    """The scene as WPF first shows it (t = 0, Loaded storyboards begun): what is exported as
    the static state."""
    clip = clip_of(scene, storyboard)
    return scene if clip is None else clip.at(0.0)
