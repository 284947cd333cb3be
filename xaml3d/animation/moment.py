"""The Scene at one moment of its storyboards: ``scene_at(scene, t)``.

Pipeline step: (Scene, t) -> Scene, before any render or export. The storyboards are
evaluated from the scene's typed tracks (``xaml3d.animation.timeline``); a frame of an
animation is an ordinary render of the Scene this returns. ``scene_and_values_at`` also gives
the exact animated values that made it, so that a frame already drawn for the same values need
not be drawn again (``xaml3d.render.frames.FrameSession``).
"""

from __future__ import annotations

from xaml3d.animation import timeline
from xaml3d.animation.timeline import scene_at as frame_at
from xaml3d.errors import SceneError
from xaml3d.scene.types import Scene


def scene_at(scene: Scene, time: float | None = 0.0, storyboard: str | None = None) -> Scene:
    """The scene ``time`` seconds after load (None: the base values). Raises SceneError when
    ``storyboard`` names no storyboard, ValueError for a time that is not finite."""
    if time is None:
        return scene
    if scene.tracks is None:
        if storyboard is not None:
            raise SceneError(f"no storyboard named {storyboard!r} (the document has none)",
                             code="ANIM010", file=scene.file)  # fmt: skip
        return scene
    return frame_at(scene, float(time), storyboard)


def scene_and_values_at(
    scene: Scene, time: float | None = 0.0, storyboard: str | None = None
) -> tuple:
    """(``scene_at(scene, time, storyboard)``, the exact animated values that made it: equal
    values, equal Scenes; ``timeline.scene_and_values_at``). A scene without storyboards, or
    ``time`` None: (the scene, ())."""
    if time is None:
        return scene, ()
    if scene.tracks is None:
        return scene_at(scene, time, storyboard), ()
    return timeline.scene_and_values_at(scene, float(time), storyboard)
