"""The Scene at one moment of its storyboards: ``scene_at(scene, t)``.

Pipeline step: (Scene, t) -> Scene, before any render or export. What evaluates the
storyboards is the scene's ``timeline`` (made by the reader); a frame of an animation is an
ordinary render of the Scene this returns.
"""

from __future__ import annotations

from dataclasses import replace

from xaml3d.errors import SceneError
from xaml3d.scene.types import Scene


def scene_at(scene: Scene, time: float | None = 0.0, storyboard: str | None = None) -> Scene:
    """The scene ``time`` seconds after load (None: the base values). Raises SceneError when
    ``storyboard`` names no storyboard, ValueError for a time that is not finite."""
    if time is None:
        return scene
    if scene.timeline is None:
        if storyboard is not None:
            raise SceneError(f"no storyboard named {storyboard!r} (the document has none)",
                             code="ANIM010", file=scene.file)  # fmt: skip
        return scene
    try:
        frame = scene.timeline.at(float(time), storyboard)
    except SceneError as exc:
        exc.file = scene.file  # the name the caller knows the scene by (stdin...)
        raise
    if frame is scene.timeline.base:
        return scene  # nothing animates at that time
    # the caller's scene keeps its own file name and diagnostics (stdin renames them); the
    # frame is a finished moment: rendering it again must not evaluate the storyboards again
    return replace(scene, viewports=frame.viewports, timeline=None)
