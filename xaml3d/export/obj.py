"""Wavefront OBJ + MTL: the viewport's models in world space, one group per model (and one per
BackMaterial, its faces reversed), with positions, normals and texture coordinates (v flipped:
OBJ's origin is the bottom-left corner), and one MTL material per model side: Kd (the diffuse
passes' mean colour), Ke (emissive), Ks / Ns (specular colour, SpecularPower), d (opacity).
OBJ has no lights, camera or animation and the brushes are kept as colours (EXP016)."""

from __future__ import annotations

import numpy as np

from xaml3d.export.codes import diag
from xaml3d.export.world_mesh import world_parts
from xaml3d.render.brushes import brush_average, brush_is_uniform
from xaml3d.scene.types import DiffuseMaterial, EmissiveMaterial, SpecularMaterial


def _rows(fmt: str, values: np.ndarray) -> str:
    """Every row of ``values`` formatted with ``fmt`` (one format operation, not a loop)."""
    if values.shape[0] == 0:
        return ""
    return (fmt * values.shape[0]) % tuple(values.ravel().tolist())


def _mean_colour(passes, kind) -> np.ndarray | None:
    """Straight sRGB rgba of the passes of ``kind`` (their brushes' mean colour times Color)."""
    cols = []
    for p in passes:
        if isinstance(p, kind) and p.brush is not None:
            c = brush_average(p.brush) * np.array([*(np.array(p.color[:3]) * p.color[3]),
                                                   p.color[3]])  # fmt: skip
            cols.append(c)
    if not cols:
        return None
    c = np.clip(np.sum(cols, axis=0), 0.0, 1.0)
    rgb = c[:3] / c[3] if c[3] > 0 else np.zeros(3)
    return np.array([*rgb, c[3]])


def _triple(c) -> str:
    return " ".join(f"{float(v):.6g}" for v in c[:3])


def _mtl(name: str, passes) -> tuple[str, bool]:
    diffuse = _mean_colour(passes, DiffuseMaterial)
    emissive = _mean_colour(passes, EmissiveMaterial)
    specular = _mean_colour(passes, SpecularMaterial)
    kd = diffuse if diffuse is not None else np.array([0.0, 0.0, 0.0, 1.0])
    lines = [f"newmtl {name}", "Ka 0 0 0", "Kd " + _triple(kd), f"d {kd[3]:.6g}"]
    if emissive is not None:
        lines.append("Ke " + _triple(emissive))
    if specular is not None:
        power = next(p.specular_power for p in passes if isinstance(p, SpecularMaterial))
        lines += ["Ks " + _triple(specular), f"Ns {power:.6g}", "illum 2"]
    else:
        lines += ["Ks 0 0 0", "illum 1"]
    textured = any(p.brush is not None and not brush_is_uniform(p.brush) for p in passes)
    return "\n".join(lines) + "\n\n", textured


def obj_files(scene, vp, diagnostics: list, animated: bool = False, stem: str = "scene") -> dict:
    """{'': the .obj text, '.mtl': the material library (``stem``.mtl) as bytes."""
    parts = world_parts(vp)
    out = [
        "# xaml3d export: world space, WPF's normals and texture coordinates\n",
        f"mtllib {stem}.mtl\n",
    ]
    mtl = ["# xaml3d export\n\n"]
    base = 1
    textured = False
    for k, part in enumerate(parts):
        model = part.model
        label = (model.name or f"model{part.model_index}") + ("_back" if part.back else "")
        mat = f"m{k}_{label}"
        text, tex = _mtl(mat, model.back_material if part.back else model.material)
        textured = textured or tex
        mtl.append(text)
        tc = part.texcoords.copy()
        tc[:, 1] = 1.0 - tc[:, 1]
        f = part.triangles + base
        faces = np.repeat(f, 3, axis=1)  # v/vt/vn share the index
        out.append(f"g {label}\nusemtl {mat}\n")
        out.append(_rows("v %.9g %.9g %.9g\n", part.positions))
        out.append(_rows("vt %.9g %.9g\n", tc))
        out.append(_rows("vn %.9g %.9g %.9g\n", part.normals))
        out.append(_rows("f %d/%d/%d %d/%d/%d %d/%d/%d\n", faces))
        base += part.positions.shape[0]
    lost = ["lights", "the camera"] + (["the animation"] if animated else [])
    if textured:
        lost.append("gradient and image brushes (as their mean colour)")
    if any(isinstance(q, SpecularMaterial) for p in parts for q in p.model.material):
        lost.append("WPF's specular lighting (as Ks/Ns)")
    diagnostics.append(diag("EXP016", "OBJ cannot carry " + ", ".join(lost), scene.file))
    return {"": "".join(out).encode("utf-8"), ".mtl": "".join(mtl).encode("utf-8")}
