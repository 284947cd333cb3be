"""Animated image files: GIF, APNG (.png), WebP, or numbered PNGs in a directory.

``save_animation`` writes GIF (one adaptive palette per frame; empty pixels become GIF
transparency, any other pixel is opaque; frames with translucent surfaces are flattened first,
``xaml3d.output.gif_matte``), APNG (.png), WebP, or numbered PNGs in a directory
(``frame_names``), atomically: a temporary file in the target's folder is written, fsynced and
renamed, so a failure leaves no partial file and an existing one untouched.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
from PIL import Image

from xaml3d.errors import RenderError
from xaml3d.output.atomic import write_atomically
from xaml3d.output.gif_matte import frames_for_gif
from xaml3d.output.images import save_image

ANIMATED_FORMATS = {".gif": "GIF", ".png": "PNG", ".apng": "PNG", ".webp": "WEBP"}
# The files of a numbered sequence: frame_0000.png ... (4 digits at least, more when needed).
FRAME_FILE = re.compile(r"frame_[0-9]{4,}\.png")


def frame_durations(count: int, total: float, unit: float) -> list[int]:
    """Display time of each of ``count`` frames in whole ``unit``s (seconds per unit), summing
    to ``total`` seconds rounded to the unit."""
    units = total / unit
    return [round((i + 1) * units / count) - round(i * units / count) for i in range(count)]


def frame_names(count: int) -> list[str]:
    """The file names of a sequence of ``count`` frames, in order."""
    digits = max(4, len(str(count - 1)))
    return [f"frame_{i:0{digits}d}.png" for i in range(count)]


def _gif_frame(rgba: np.ndarray):
    """A palette image for GIF: 255 adaptive colours, index 255 for transparent pixels. GIF
    has no partial transparency: a pixel with any coverage keeps its (straight) colour, fully,
    so translucent surfaces stay visible; only empty pixels become transparent."""
    alpha = rgba[..., 3]
    rgb = Image.fromarray(np.ascontiguousarray(rgba[..., :3]), mode="RGB")
    clear = alpha == 0
    if not clear.any():
        return rgb.quantize(256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE), None
    # the colours of visible pixels only choose the palette
    q = rgb.quantize(255, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    idx = np.array(q, dtype=np.uint8)
    idx[clear] = 255
    out = Image.fromarray(idx, mode="P")
    pal = q.getpalette()[: 255 * 3]
    out.putpalette(pal + [0, 0, 0] * (256 - len(pal) // 3))
    return out, 255


def save_animation(
    frames: list[np.ndarray],
    path,
    total: float,
    *,
    loop: int = 0,
    directory: bool = False,
    matte: tuple[int, int, int] = (255, 255, 255),
) -> list[Path]:
    """Write (H, W, 4) uint8 RGBA frames lasting ``total`` seconds in all. ``loop``: 0 for
    ever, else the number of plays. ``directory``: numbered PNGs ``frame_0000.png``... in the
    folder ``path``. ``matte``: the opaque RGB (0..255) a GIF's frames are flattened onto when
    they show translucent surfaces (``gif_matte.frames_for_gif``). Returns the files written.
    Raises RenderError (RND006 format, RND007)."""
    path = Path(path)
    if directory:
        path.mkdir(parents=True, exist_ok=True)
        out = []
        for name, f in zip(frame_names(len(frames)), frames, strict=True):
            target = path / name
            save_image(f, target, format="PNG")
            out.append(target)
        return out
    fmt = ANIMATED_FORMATS.get(path.suffix.lower())
    if fmt is None:
        raise RenderError(
            f"cannot write {path.name!r}: unknown animation format "
            "(use .gif, .png (APNG), .webp, or a directory ending in /)",
            code="RND006",
        )
    if fmt == "GIF":
        frames, _ = frames_for_gif(frames, matte)
        pairs = [_gif_frame(f) for f in frames]
        images = [p[0] for p in pairs]
        durations = [10 * d for d in frame_durations(len(frames), total, 0.01)]
        transparent = any(p[1] is not None for p in pairs)
        extra = {"transparency": 255, "disposal": 2} if transparent else {}
        # GIF's loop count is the number of REPEATS (0: for ever); no count plays once
        if loop != 1:
            extra["loop"] = 0 if loop == 0 else loop - 1

        def write(fh):
            images[0].save(fh, format="GIF", save_all=True, append_images=images[1:],
                           duration=durations, optimize=False, **extra)  # fmt: skip
    else:
        images = [Image.fromarray(f, mode="RGBA") for f in frames]
        durations = frame_durations(len(frames), total, 0.001)
        opts = {"lossless": False, "quality": 90} if fmt == "WEBP" else {"default_image": False}

        def write(fh):
            images[0].save(fh, format=fmt, save_all=True, append_images=images[1:],
                           duration=durations, loop=loop, **opts)  # fmt: skip

    write_atomically(path, write)
    return [path]
