"""The Scene at one moment of its storyboards: ``scene_at(scene, t)``.

Pipeline step: (Scene, t) -> Scene, before any render or export. The storyboards are
evaluated from the scene's typed tracks (``xaml3d.animation.timeline``); a frame of an
animation is an ordinary render of the Scene this returns. ``scene_and_values_at`` also gives
the exact animated values that made it, so that a frame already drawn for the same values need
not be drawn again (``xaml3d.render.frames.FrameSession``). ``picture_moves`` tells whether a
viewport's own RenderTransform (or an element's around it) moves its picture over a stretch of
time: a picture of the viewport's box alone then shows it sliding out of that box.
"""

from __future__ import annotations

import numpy as np

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


def picture_moves(scene: Scene, index: int, times, storyboard: str | None = None):
    """(the first track that moves it, whether it is the viewport's own RenderTransform) when
    the RenderTransform of viewport ``index``'s picture, or of an element around it, differs
    between the moments ``times`` (a few of them are compared); else None."""
    tracks = scene.tracks.tracks if scene.tracks is not None else ()
    moving = [t for t in tracks for p in (*t.paths, *t.moves)
              if p.viewport == index and p.steps[:1] == (("picture", None),)
              and p.field == "render_transform"]  # fmt: skip
    times = list(times)
    if not moving or len(times) < 2:
        return None
    step = max(1, len(times) // 8)  # a few moments suffice to see it move

    def matrices(t) -> list:
        """The picture's RenderTransform, then each surrounding element's."""
        picture = scene_at(scene, t, storyboard).viewports[index].picture
        if picture is None:
            return []
        return [picture.render_transform, *(a.layer.render_transform for a in picture.around)]

    def same(a, b) -> bool:
        return (a is None) == (b is None) and (a is None or np.array_equal(a, b))

    first = matrices(times[0])
    for t in times[step::step]:
        now = matrices(t)
        if len(now) != len(first) or not all(map(same, now, first)):
            own = any(p.steps == (("picture", None),) and p.field == "render_transform"
                      for k in moving for p in (*k.paths, *k.moves))  # fmt: skip
            return moving[0], own
    return None
