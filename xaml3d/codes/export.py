"""The exporters' codes (EXPxxx): what a file format cannot carry, and export failures.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import ERROR, INFO, WARNING

EXPORT_CODES: dict[str, tuple[str, str]] = {
    "EXP001": (ERROR, "unknown export format (use .glb, .gltf, .obj, .stl or .html)"),
    "EXP002": (ERROR, "the exported file cannot be written"),
    "EXP003": (
        WARNING,
        "the camera is exported as the closest camera glTF has (what differs "
        "is named: a MatrixCamera's off-centre terms, a negative orthographic near "
        "plane, a shearing Camera.Transform)",
    ),
    "EXP004": (
        WARNING,
        "an EmissiveMaterial without a DiffuseMaterial: WPF adds it to what "
        "lies behind, glTF draws it opaque",
    ),
    "EXP005": (
        INFO,
        "SpecularMaterial exported as KHR_materials_specular with a roughness "
        "from SpecularPower: the highlight's shape differs",
    ),
    "EXP006": (INFO, "DiffuseMaterial.AmbientColor has no glTF equivalent"),
    "EXP007": (WARNING, "AmbientLight has no glTF equivalent: kept in the scene's extras"),
    "EXP008": (
        WARNING,
        "a point or spot light's attenuation or Range is approximated by "
        "glTF's inverse-square falloff",
    ),
    "EXP009": (
        WARNING,
        "an animated property glTF cannot animate (camera FieldOfView or "
        "Width, colours, materials, meshes, lights' colours): its animation is lost",
    ),
    "EXP010": (INFO, "storyboards exported as transforms sampled at a fixed rate (LINEAR)"),
    "EXP011": (WARNING, "an animation that never ends: only its first seconds are exported"),
    "EXP012": (
        INFO,
        "a model's transform shears (no translation-rotation-scale form): "
        "exported as two nested nodes, a scale between two rotations",
    ),
    "EXP013": (WARNING, "a model is left out: its transform is singular or projective"),
    "EXP014": (INFO, "the document has several viewports: one is exported (--viewport)"),
    "EXP015": (WARNING, "the camera cannot be exported (WPF draws nothing with it)"),
    "EXP016": (
        WARNING,
        "the format cannot carry part of the scene (OBJ: lights, camera, "
        "animation, specular; STL: everything but the triangles)",
    ),
    "EXP017": (
        WARNING,
        "a model or light is left out: values beyond single precision (3.4e38, glTF's floats)",
    ),  # fmt: skip
}
