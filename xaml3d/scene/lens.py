"""The thin lens and the stereo pair as cameras: sheared (off-axis) PerspectiveCamera projections.

Pipeline step: before rendering, one pinhole ``PerspectiveCamera`` becomes several
``MatrixCamera``s (WPF row-vector view and projection matrices, Direct3D clip space
0 <= z <= w), each an ordinary camera the renderer already draws. See docs/lens.md.

The chapter's lens (section 13.9): a real camera gathers light over an aperture, so only the
points on one plane, the focal plane at distance D along the look direction, are sharp. A
rasterizer gets it "by sampling many rays per pixel": it renders the scene from eye points
E = P + s_x u + s_y v spread over the lens disk of radius A (in the camera's u, v plane) and
averages. Each eye keeps the pinhole's axes (u, v, w) but its frustum is sheared so that it
passes through the SAME rectangle on the focal plane: the rectangle centred at P - D w with
half-width D tan(fov_h / 2) and half-height that / aspect. A point on the focal plane then
lands on the same pixel from every eye; a point off it moves by an amount proportional to
A |z - D| / z, the blur circle.

In terms of the eye's own view space (x along u, y along v, looking down -z), the sheared
projection of an eye offset (s_x, s_y) is Direct3D's off-centre perspective with
x_ndc = (x / tan(fov_h / 2) - z s_x / (D tan(fov_h / 2))) / -z: the pinhole's m11, m22 and the
shear terms m31 = -s_x / (D tan(fov_h / 2)), m32 = -s_y aspect / (D tan(fov_h / 2)). Offsets
(0, 0) give the pinhole's own projection.

The stereo pair is the same construction with two eye offsets (-S/2, 0) and (+S/2, 0): parallel
axes, off-axis frusta converging at the focal distance (not toed-in, so no vertical parallax).

Eye-space depth: ``eye_distance`` inverts the depth the renderer stores (z_ndc, WPF's normalized
device depth) to the distance from the eye plane along the look direction, exactly.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from xaml3d.codes.lens import LENS_CODES  # noqa: F401 (the stage's table)
from xaml3d.errors import RenderError
from xaml3d.scene.camera_math import camera_frame, camera_pipeline
from xaml3d.scene.types import MatrixCamera, PerspectiveCamera, frozen_array

GOLDEN_ANGLE = math.pi * (3.0 - math.sqrt(5.0))  # radians, about 137.5 degrees
FRAME_WIDTH_MM = 36.0  # the 35 mm film frame is 36 mm x 24 mm
MM_PER_SCENE_UNIT = 1000.0  # --fstop/--focal-length: one scene unit is taken as one metre
STEREO_FRACTION = 1.0 / 30.0  # default eye separation: focal distance / 30 (the "1/30 rule")
STEREO_MODES = ("anaglyph", "side-by-side", "over-under")
MAX_LENS_SAMPLES = 4096  # eye points on the lens disk, each a full render


def lens_pattern(n: int) -> np.ndarray:
    """``n`` points (n, 2) on the unit disk, a Vogel (Fibonacci) spiral: point k at radius
    sqrt((k + 0.5) / n) and angle k * golden angle. Deterministic and low-discrepancy: equal
    areas hold nearly equal counts, for every n. n = 1 gives the centre."""
    if not (isinstance(n, int) and n >= 1):
        raise RenderError(f"lens samples must be an integer >= 1, got {n!r}", code="RND005")
    if n == 1:
        return np.zeros((1, 2))
    k = np.arange(n, dtype=np.float64)
    r = np.sqrt((k + 0.5) / n)
    t = k * GOLDEN_ANGLE
    return np.stack([r * np.cos(t), r * np.sin(t)], axis=1)


def focal_length_of_fov(fov_h_deg: float) -> float:
    """The focal length (mm) whose 36 mm wide frame sees the horizontal field of view
    ``fov_h_deg``: F = 18 / tan(fov_h / 2)."""
    return (FRAME_WIDTH_MM / 2.0) / math.tan(math.radians(fov_h_deg) / 2.0)


def aperture_of_fstop(fstop: float, focal_length_mm: float) -> float:
    """Lens RADIUS in scene units for f-number N and focal length F (mm): the entrance pupil's
    diameter is F / N mm, and a scene unit is taken as a metre (docs/lens.md)."""
    if not (fstop > 0 and math.isfinite(fstop)):
        raise RenderError(f"f-number must be finite and > 0, got {fstop!r}", code="RND005")
    if not (focal_length_mm > 0 and math.isfinite(focal_length_mm)):
        raise RenderError(
            f"focal length must be finite and > 0 mm, got {focal_length_mm!r}", code="RND005"
        )
    return focal_length_mm / fstop / 2.0 / MM_PER_SCENE_UNIT


def default_focus(camera: PerspectiveCamera, bounds) -> float:
    """The focal distance used when none is given: the distance along the look direction from
    the eye to the centre of the scene's bounding box (camera space, Camera.Transform
    included), or 1 when that is not in front of the eye (or there are no bounds)."""
    if bounds is None:
        return 1.0
    lo, hi = (np.asarray(b, dtype=np.float64).reshape(3) for b in bounds)
    centre = np.append(lo / 2.0 + hi / 2.0, 1.0)  # halves first: no overflow near 1e308
    view = camera_view(camera)
    with np.errstate(over="ignore", invalid="ignore"):  # far out: not finite, 1 is used
        d = -float((view @ centre)[2])
    return d if d > 0 and math.isfinite(d) else 1.0


def camera_view(camera) -> np.ndarray:
    """World -> camera space (column form) of a projection camera: frame rows, the eye moved
    to the origin, inverse(Camera.Transform) first."""
    u, v, w = camera_frame(camera.look_direction, camera.up_direction)
    P = np.asarray(camera.position, dtype=np.float64)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = u, v, w
    m[:3, 3] = -(m[:3, :3] @ P)
    return m @ np.linalg.inv(np.asarray(camera.transform, dtype=np.float64))


@dataclass(frozen=True)
class LensFrame:
    """What every eye of one lens (or stereo pair) shares: the pinhole camera, its frame, the
    aspect, the focal distance and the near/far planes actually used (far effective)."""

    camera: PerspectiveCamera
    aspect: float
    focus: float
    near: float
    far: float

    def eye_camera(self, sx: float, sy: float) -> MatrixCamera:
        """The MatrixCamera of the eye at P + sx u + sy v (camera space) whose sheared frustum
        keeps the focal plane's rectangle fixed (module docstring)."""
        cam = self.camera
        u, v, w = camera_frame(cam.look_direction, cam.up_direction)
        eye = np.asarray(cam.position, dtype=np.float64) + sx * u + sy * v
        view = np.zeros((4, 4))  # LookAtRH, row-vector form: columns u, v, w
        view[:3, 0], view[:3, 1], view[:3, 2] = u, v, w
        view[3, :3] = (-(u @ eye), -(v @ eye), -(w @ eye))
        view[3, 3] = 1.0
        t = math.tan(math.radians(cam.field_of_view) / 2.0)
        n, f = self.near, self.far
        proj = np.zeros((4, 4))
        proj[0, 0], proj[1, 1] = 1.0 / t, self.aspect / t
        proj[2, 0] = -sx / (self.focus * t)
        proj[2, 1] = -sy * self.aspect / (self.focus * t)
        proj[2, 2], proj[2, 3], proj[3, 2] = f / (n - f), -1.0, n * f / (n - f)
        return MatrixCamera(
            view_matrix=frozen_array(view),
            projection_matrix=frozen_array(proj),
            transform=cam.transform,
            name=cam.name,
            line=cam.line,
            column=cam.column,
        )


def lens_frame(
    camera, width: float, height: float, focus: float | None, bounds=None, aspect=None
) -> LensFrame:
    """The shared frame of a lens or stereo pair for ``camera`` rendering ``width`` x ``height``
    (``aspect``: the projection's aspect ratio as ``camera_pipeline`` takes it).
    Only a PerspectiveCamera has a lens: others raise RenderError LNS001. ``focus`` None: the
    distance to the scene's centre (``default_focus``)."""
    if not isinstance(camera, PerspectiveCamera):
        kind = type(camera).__name__ if camera is not None else "no camera"
        raise RenderError(
            f"a lens aperture or stereo pair needs a PerspectiveCamera; the viewport has {kind}",
            code="LNS001",
        )
    # The pinhole's own pipeline: CameraError (with the camera's line) for every camera that
    # cannot produce an image, and the near / effective far planes the renderer uses.
    pipe = camera_pipeline(camera, width, height, bounds=bounds, aspect=aspect)
    if focus is None:
        focus = default_focus(camera, bounds)
    if not (focus > 0 and math.isfinite(focus)):
        raise RenderError(f"focal distance must be finite and > 0, got {focus!r}", code="RND005")
    return LensFrame(camera, pipe.aspect, float(focus), pipe.near, pipe.far)


def eye_distance(z_ndc, near: float, far: float, kind: str = "perspective") -> np.ndarray:
    """WPF normalized device depth -> distance from the eye plane along the look direction.

    Perspective: z_ndc = f (d - n) / (d (f - n)), so d = n f / (f - z_ndc (f - n)).
    Orthographic: z_ndc = (d - n) / (f - n), so d = n + z_ndc (f - n).
    Non-finite z_ndc (nothing drawn) gives NaN."""
    z = np.asarray(z_ndc, dtype=np.float64)
    # Computed everywhere, then NaN where z is not finite: the same numbers where it is, without
    # gathering and scattering through a mask (three times faster on a 1920x1080 frame).
    with np.errstate(divide="ignore", invalid="ignore", over="ignore", under="ignore"):
        if kind == "perspective":
            out = near * far / (far - z * (far - near))
        elif kind == "orthographic":
            out = near + z * (far - near)
        else:
            raise ValueError(f"eye distance of a {kind} camera needs its matrices")
    out[~np.isfinite(z)] = np.nan
    return out


def eye_distance_matrix(z_ndc, projection_row) -> np.ndarray:
    """``eye_distance`` for a MatrixCamera: the view-space depth -z_v recovered from WPF's
    projection matrix (row form) when its z and w columns do not depend on x and y (every
    perspective or orthographic projection, sheared or not): z_ndc = (m33 z + m43) /
    (m34 z + m44), so z = (m43 - m44 z_ndc) / (m34 z_ndc - m33). A distance in view units
    (scene units when the view matrix is rigid). Other projections: all NaN."""
    m = np.asarray(projection_row, dtype=np.float64)
    z = np.asarray(z_ndc, dtype=np.float64)
    out = np.full(z.shape, np.nan)
    if m[0, 2] != 0 or m[1, 2] != 0 or m[0, 3] != 0 or m[1, 3] != 0:
        return out
    ok = np.isfinite(z)
    den = m[2, 3] * z[ok] - m[2, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        zv = np.where(den != 0, (m[3, 2] - m[3, 3] * z[ok]) / np.where(den != 0, den, 1.0), np.nan)
    out[ok] = -zv
    return out
