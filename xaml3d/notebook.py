"""Scenes in Jupyter notebooks (and any IPython display): a Scene shows its picture, and
``show(scene)`` its interactive view.

- ``Scene._repr_png_``: the picture ``xaml3d.render`` draws of the first viewport, at its own
  size and WPF's first frame, as PNG bytes (None when the scene cannot be drawn: IPython then
  shows the short ``repr`` text alone). The scene layer cannot import the renderer, so the
  method is defined here, above it, and attached to ``Scene`` when ``xaml3d`` is imported.
- ``show(scene)``: a ``View`` whose ``_repr_html_`` is the HTML export's page
  (``xaml3d export -o x.html``: three.js, orbit controls, playback, the camera pipeline's
  matrices) in an ``<iframe srcdoc>``, self-contained like the exported file.

The renderer and the exporters are imported when a picture or a view is first asked for:
importing this module (``import xaml3d`` does) costs nothing more.
"""

from __future__ import annotations

import html
import io

from xaml3d.errors import Diagnostic, XamlError
from xaml3d.scene.types import Scene


def scene_png(scene: Scene) -> bytes | None:
    """The PNG of ``scene``'s first viewport as ``xaml3d.render`` draws it; None when it
    cannot be drawn (no viewport, a camera that gives no image...)."""
    from xaml3d.api import render  # the renderer, when a picture is asked for

    if not scene.viewports:
        return None
    try:
        image = render(scene)
    except XamlError:
        return None
    out = io.BytesIO()
    image.save(out, format="PNG")
    return out.getvalue()


def _repr_png_(self: Scene) -> bytes | None:
    return scene_png(self)


Scene._repr_png_ = _repr_png_

# the frame around the exported page's view: its bar above, its matrices panel beside it
_BAR_HEIGHT = 72
_PANEL_WIDTH = 560


class View:
    """The HTML export's interactive page of one viewport, shown inline by IPython.

    ``html``: the page itself (str); ``diagnostics``: what the export could not carry
    (EXPxxx); ``width``, ``height``: the iframe's size in CSS pixels."""

    def __init__(self, page: str, diagnostics, width: int, height: int) -> None:
        self.html = page
        self.diagnostics: list[Diagnostic] = list(diagnostics)
        self.width = width
        self.height = height

    def _repr_html_(self) -> str:
        return (
            f'<iframe srcdoc="{html.escape(self.html, quote=True)}" width="{self.width}" '
            f'height="{self.height}" style="border: 1px solid #ccc" '
            'sandbox="allow-scripts"></iframe>'
        )

    def __repr__(self) -> str:
        return (
            f"<View of the HTML export: {len(self.html)} characters, "
            f"{self.width}x{self.height} frame, {len(self.diagnostics)} diagnostic(s)>"
        )


def show(
    scene_or_path,
    *,
    viewport=None,
    storyboard: str | None = None,
    width: int | None = None,
    height: int | None = None,
) -> View:
    """The interactive view of a Scene (or of the XAML file at a path): the HTML export's page
    of ``viewport`` (index or x:Name; default the first) with ``storyboard``'s playback (as
    ``xaml3d export --storyboard``), in a frame ``width`` x ``height`` CSS pixels (default:
    the viewport's size with room for the page's bar and matrices panel). Raises XamlError
    as ``xaml3d.export`` does (EXP001..., SCN002 for an unknown viewport)."""
    from xaml3d.export import export_bytes  # the exporters, when a view is asked for

    if isinstance(scene_or_path, Scene):
        scene = scene_or_path
    else:
        from xaml3d.pipeline import load

        scene = load(scene_or_path)
    files, notes = export_bytes(scene, "html", viewport=viewport, storyboard=storyboard)
    vp = scene.viewport(viewport)
    w = width or int(vp.width) + _PANEL_WIDTH
    h = height or int(vp.height) + _BAR_HEIGHT
    return View(files[""].decode("utf-8"), notes, w, h)
