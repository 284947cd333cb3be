"""GIF's matte under its former module name: see ``xaml3d.output.gif_matte``."""

from __future__ import annotations

from xaml3d.output.gif_matte import flatten, frames_for_gif, needs_matte  # noqa: F401
