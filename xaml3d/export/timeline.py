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
    # viewport index -> (model indices, light indices) some track can replace: every other
    # model and light of a sample is the start's own object (``moving``)
    moving: Callable[[int], tuple[frozenset[int], frozenset[int]]] = lambda vi: (
        frozenset(),
        frozenset(),
    )
    # t -> (the Scene at t, a hashable of every animated value at t): equal values, the same
    # Scene (``animation.timeline.scene_and_values_at``); None: ``at`` alone
    at_values: Callable[[float], tuple[Scene, object]] | None = None


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
    return Clip(seconds, endless, partial(_at, scene, storyboard), partial(moving, scene),
                partial(_at_values, scene, storyboard))  # fmt: skip


def moving(scene: Scene, vp_index: int) -> tuple[frozenset[int], frozenset[int]]:
    """(model indices, light indices) of viewport ``vp_index`` whose objects a track of
    ``scene`` can replace: a field of the model or light (or of something inside it) or its
    world matrix. The scene at any moment shares every other model and light with ``scene``
    (``animation.timeline`` replaces only what a track reaches), so a sampler looks at these
    alone, not at the whole scene at each sample."""
    models: set[int] = set()
    lights: set[int] = set()
    if scene.tracks is not None:
        paths = [p for tr in scene.tracks.tracks for p in (*tr.paths, *tr.moves)]
        paths += [w.path for w in scene.tracks.worlds]
        vp = scene.viewports[vp_index]
        for p in paths:
            if p.viewport != vp_index:
                continue
            # the first step names the model or light; a field of the viewport itself, or a
            # step without an index, may replace the whole tuple: all of them
            name, i = p.steps[0] if p.steps else (p.field, None)
            if name == "models":
                models.update(range(len(vp.models)) if i is None else (i,))
            elif name == "lights":
                lights.update(range(len(vp.lights)) if i is None else (i,))
    return frozenset(models), frozenset(lights)


def _at(scene: Scene, storyboard: str | None, t: float) -> Scene:
    return A.scene_at(scene, float(t), storyboard)


def _at_values(scene: Scene, storyboard: str | None, t: float) -> tuple[Scene, object]:
    return A.scene_and_values_at(scene, float(t), storyboard)


def scene_at_start(scene: Scene, storyboard: str | None = None) -> Scene:
    """The scene as WPF first shows it (t = 0, Loaded storyboards begun): what is exported as
    the static state."""
    clip = clip_of(scene, storyboard)
    return scene if clip is None else clip.at(0.0)
