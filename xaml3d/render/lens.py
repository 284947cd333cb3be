"""Depth of field and stereo pairs: many ordinary renders through sheared cameras, combined.

Pipeline step: around one render (``xaml3d.render.rendering.draw_viewport``). The pinhole
camera of the viewport becomes one ``MatrixCamera`` per eye point (``xaml3d.scene.lens``);
each is rendered as an ordinary scene (``dataclasses.replace`` of the viewport's camera: the
loaded Scene is reused, never re-read), and the images are combined in LINEAR light with
premultiplied alpha:

- depth of field: the mean of the lens samples (a box filter over the lens disk);
- stereo: a left and a right eye (each itself a lens average when there is an aperture),
  put side by side (left eye on the left), over-under (left eye on top) or composed as a
  half-colour red/cyan anaglyph: red = the left eye's luminance (Rec. 709 weights), green and
  blue = the right eye's.

The depth buffer, the eye distances and the model ids of the result are those of the pinhole
camera (the centre of the lens, between the eyes), rendered once more for them. That pinhole
render also lights the scene, once: every sample reuses its lit colours (``draw.Shading``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from xaml3d.errors import ERROR, WARNING, Diagnostic, RenderError
from xaml3d.render.draw import Shading
from xaml3d.render.settings import FrameSize, RenderSettings
from xaml3d.scene.lens import (
    STEREO_FRACTION,
    aperture_of_fstop,
    focal_length_of_fov,
    lens_frame,
    lens_pattern,
)
from xaml3d.scene.types import PerspectiveCamera

LUMINANCE = np.array([0.2126, 0.7152, 0.0722])  # Rec. 709 / sRGB primaries, linear light


def srgb_to_linear(c: np.ndarray) -> np.ndarray:
    """sRGB-encoded values 0..1 -> linear light (IEC 61966-2-1)."""
    c = np.asarray(c, dtype=np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((np.maximum(c, 0.04045) + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(c: np.ndarray) -> np.ndarray:
    """Linear light 0..1 -> sRGB-encoded values (IEC 61966-2-1)."""
    c = np.clip(np.asarray(c, dtype=np.float64), 0.0, 1.0)
    return np.where(
        c <= 0.0031308, c * 12.92, 1.055 * np.maximum(c, 0.0031308) ** (1.0 / 2.4) - 0.055
    )


_LINEAR8 = srgb_to_linear(np.arange(256) / 255.0)  # every 8-bit sRGB value, decoded once


def to_linear_premultiplied(rgba: np.ndarray) -> np.ndarray:
    """(H, W, 4) uint8 straight sRGB -> float64 premultiplied linear RGBA (a table lookup)."""
    out = np.empty(rgba.shape, dtype=np.float64)
    out[..., 3] = rgba[..., 3] / 255.0
    out[..., :3] = _LINEAR8[rgba[..., :3]] * out[..., 3:4]
    return out


def to_straight_srgb8(premul: np.ndarray) -> np.ndarray:
    """Float premultiplied linear RGBA -> (H, W, 4) uint8 straight sRGB."""
    a = np.clip(premul[..., 3:4], 0.0, 1.0)
    safe = np.where(a > 0, a, 1.0)
    rgb = np.where(a > 0, premul[..., :3] / safe, 0.0)
    out = np.concatenate([linear_to_srgb(rgb), a], axis=-1)
    return np.round(out * 255.0).astype(np.uint8)


def anaglyph(left: np.ndarray, right: np.ndarray) -> np.ndarray:
    """Half-colour red/cyan anaglyph of two premultiplied linear images (module docstring)."""
    out = np.empty_like(left)
    out[..., 0] = left[..., :3] @ LUMINANCE
    out[..., 1:3] = right[..., 1:3]
    out[..., 3] = np.maximum(left[..., 3], right[..., 3])
    return out


def eye_offsets(aperture: float, samples: int, stereo: str | None, separation: float):
    """[(eye name, [(sx, sy) offsets of its lens samples])] in camera-space units."""
    disk = lens_pattern(samples) * aperture if aperture > 0 else np.zeros((1, 2))
    if stereo is None:
        return [("centre", disk)]
    half = np.array([separation / 2.0, 0.0])
    return [("left", disk - half), ("right", disk + half)]


def render_through_lens(vp, size: FrameSize, settings: RenderSettings, draw, *, progress=None):
    """Depth of field and/or a stereo pair of the viewport ``vp`` (module docstring), with the
    lens of ``settings`` (``aperture`` or ``fstop`` with ``focal_length``, ``focus``,
    ``lens_samples``, ``stereo``, ``eye_separation``, ``ids``).

    ``draw(viewport, shading, ids)`` renders one viewport (the pinhole's, or a copy whose camera
    is a lens sample's) at ``size``, the size of ONE eye's image, and returns a ``Rendering``.
    The scene is lit ONCE: the pinhole render fills a ``draw.Shading`` cache of lit colours
    that every sample reuses, so the lighting is the lens centre's (specular highlights are
    evaluated from the centre of the lens, as diffuse light is the same from every eye point).
    ``progress(done, total)`` is called after every sample render. ``fstop``/``focal_length``:
    the aperture as an f-number (``xaml3d.scene.lens.aperture_of_fstop``). Returns a
    ``Rendering`` whose rgba is the combined picture (side-by-side: 2W x H; over-under: W x 2H)
    and whose depth, distance and ids are the pinhole camera's. Raises RenderError (LNS001: not
    a PerspectiveCamera; RND005: bad argument)."""
    width, height, aspect = size.width, size.height, size.aspect
    aperture, focus, fstop = settings.aperture, settings.focus, settings.fstop
    stereo, eye_separation = settings.stereo, settings.eye_separation
    aperture = 0.0 if aperture is None else aperture
    if not (aperture >= 0 and np.isfinite(aperture)):
        raise RenderError(f"aperture must be finite and >= 0, got {aperture!r}", code="RND005")
    if not isinstance(vp.camera, PerspectiveCamera):
        lens_frame(vp.camera, width, height, focus)  # raises LNS001
    shading = Shading()
    pinhole = draw(vp, shading, settings.ids)
    if any(d.severity == ERROR for d in pinhole.diagnostics):
        # a camera that cannot produce an image: WPF draws nothing; a pair keeps its shape
        if stereo in ("side-by-side", "over-under"):
            rgba = np.concatenate([pinhole.rgba] * 2, axis=1 if stereo == "side-by-side" else 0)
            return replace(pinhole, rgba=rgba, width=rgba.shape[1], height=rgba.shape[0])
        return pinhole
    frame = lens_frame(vp.camera, width, height, focus, vp.bounds(), aspect)
    if fstop is not None:
        if aperture:
            raise RenderError("give either aperture or fstop, not both", code="RND005")
        focal = settings.focal_length or focal_length_of_fov(float(vp.camera.field_of_view))
        aperture = aperture_of_fstop(fstop, focal)
    if eye_separation is None:
        eye_separation = frame.focus * STEREO_FRACTION
    if not (eye_separation >= 0 and np.isfinite(eye_separation)):
        raise RenderError(
            f"eye separation must be finite and >= 0, got {eye_separation!r}", code="RND005"
        )
    plan = eye_offsets(float(aperture), settings.lens_samples, stereo, float(eye_separation))
    total = sum(len(offsets) for _, offsets in plan)
    done = blank = 0
    images = []
    for _, offsets in plan:
        acc = np.zeros((pinhole.height, pinhole.width, 4))
        for sx, sy in offsets:
            eye_vp = replace(vp, camera=frame.eye_camera(float(sx), float(sy)))
            sample = draw(eye_vp, shading, False)
            acc += to_linear_premultiplied(sample.rgba)
            blank += any(d.code == "RND002" or d.severity == ERROR for d in sample.diagnostics)
            done += 1
            if progress is not None:
                progress(done, total)
        images.append(acc / len(offsets))
    if stereo is None:
        combined = images[0]
    elif stereo == "anaglyph":
        combined = anaglyph(images[0], images[1])
    elif stereo == "side-by-side":
        combined = np.concatenate(images, axis=1)
    else:
        combined = np.concatenate(images, axis=0)
    rgba = to_straight_srgb8(combined)
    diagnostics = list(pinhole.diagnostics)
    if blank == total and not any(d.code in ("RND002", "RND003") for d in diagnostics):
        # The pinhole sees the scene but no eye point does: extreme lens values.
        values = f"aperture radius {float(aperture):g}, focal distance {frame.focus:g}"
        if stereo is not None:
            values += f", eye separation {float(eye_separation):g}"
        diagnostics.append(Diagnostic("RND002", WARNING, (
            f"nothing was drawn through the lens: the pinhole camera sees the scene, but from "
            f"none of the {total} eye point(s) is any of it in view ({values}): the eye points "
            "lie too far from the camera, or the focal distance is too small, for the sheared "
            "frusta to hold the scene"), None,
            vp.camera.line, vp.camera.column))  # fmt: skip
    return replace(pinhole, rgba=rgba, width=rgba.shape[1], height=rgba.shape[0],
                   diagnostics=diagnostics)  # fmt: skip
