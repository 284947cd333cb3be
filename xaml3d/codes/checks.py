"""The scene checks' codes: what a render of the scene would show (or not).

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import INFO, WARNING

CHECK_CODES: dict[str, tuple[str, str]] = {
    "CHK001": (WARNING, "a model's mesh has no triangles: it draws nothing"),
    "CHK002": (WARNING, "no lights and only diffuse materials: the models render black"),
    "CHK003": (WARNING, "the camera sees none of the scene's geometry (try --fit)"),
    "CHK004": (WARNING, "a material pass has no brush: it draws nothing"),
    "CHK005": (WARNING, "a model has neither Material nor BackMaterial: it draws nothing"),
    "CHK006": (WARNING, "a viewport holds no models: it draws nothing"),
    "CHK007": (INFO, "only ambient light: every surface is lit flat, without shading"),
    "CHK008": (
        WARNING,
        "a brush that varies over the surface on a mesh without TextureCoordinates: nothing drawn",
    ),  # fmt: skip
    "CHK009": (
        WARNING,
        "the camera is inside a closed or emissive model: it fills the view (try --fit)",
    ),  # fmt: skip
}
