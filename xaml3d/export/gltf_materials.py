"""WPF materials as glTF materials (docs/export.md, "Materials").

A Scene material is a tuple of passes (MaterialGroup flattened in document order). glTF has one
metallic-roughness material per primitive, so the passes are folded into one:

- DiffuseMaterial passes: composited over each other (premultiplied "over", the order WPF draws
  them) into the base colour; Color, the brush and its Opacity are multiplied in sRGB as WPF
  does. A uniform result is ``baseColorFactor`` (converted to glTF's linear values); anything
  else (gradients, images, 2D brushes) is baked into ``baseColorTexture`` by the renderer's own
  brush sampler over the box of the mesh's texture coordinates, which is exactly the box WPF
  stretches a brush over (RelativeToBoundingBox), so the texture coordinates are rescaled to it.
- EmissiveMaterial passes: added (WPF adds them) into ``emissiveFactor`` / ``emissiveTexture``.
- SpecularMaterial passes: KHR_materials_specular's specular colour (their average colour), and a
  roughness from SpecularPower (the Blinn-Phong exponent n as a microfacet roughness,
  ``(2 / (n + 2)) ** 0.25``): an approximation, always reported (EXP005).
- Without a SpecularMaterial the material has ``specularFactor`` 0: WPF's diffuse lighting has no
  highlight at all, which glTF's default dielectric would add.
- Any alpha below 1 (a colour's, a brush's, a texel's): ``alphaMode`` BLEND.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from xaml3d.render.brushes import brush_bounds, brush_is_uniform, sample_brush
from xaml3d.scene.types import DiffuseMaterial, EmissiveMaterial, SpecularMaterial

GRADIENT_TEXELS = 256  # a baked gradient's longest side
MAX_TEXELS = 1024  # a baked image brush's longest side
CLAMP, LINEAR, LINEAR_MIPMAP = 33071, 9729, 9987


def srgb_to_linear(c) -> np.ndarray:
    c = np.clip(np.asarray(c, dtype=np.float64), 0.0, 1.0)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


@dataclass(frozen=True)
class Bake:
    """Where a mesh's brushes are sampled: the texel grid over its texture-coordinate box."""

    lo: np.ndarray
    hi: np.ndarray
    shape: tuple[int, int]  # texels (height, width)

    def uv_grid(self) -> np.ndarray:
        h, w = self.shape
        size = self.hi - self.lo
        # a flat axis (every coordinate equal) is one texel sampled at that coordinate; a
        # denormal one's steps round to 0 (every texel at its low end)
        with np.errstate(under="ignore"):
            xs, ys = (
                self.lo[k] + (np.arange(n) + 0.5) / n * size[k]
                if size[k] > 0
                else self.lo[k : k + 1]
                for k, n in ((0, w), (1, h))
            )
        gx, gy = np.meshgrid(xs, ys)
        return np.stack([gx.ravel(), gy.ravel()], axis=1)

    def texcoords(self, tc: np.ndarray) -> np.ndarray:
        """The mesh's texture coordinates in the baked texture's 0..1 space."""
        size = self.hi - self.lo
        safe = np.where(size > 0, size, 1.0)
        # coordinates near the doubles' range (the box is clipped to +-1e300) overflow on the
        # way: they land at the box's edges, where the bake's edge texels are
        with np.errstate(over="ignore", invalid="ignore", under="ignore"):
            out = np.where(size > 0, (tc - self.lo) / safe, 0.5)
            # NaN stays NaN (no place on the brush); a tiny fraction is 0 in single precision
            return np.clip(out, 0.0, 1.0).astype(np.float32)


def bake_for(texcoords: np.ndarray, brushes) -> Bake:
    # the box of the coordinates WPF can sample: infinite ones kept far but finite (the box's
    # size stays a number), NaN ones (no place on the brush) left out
    tc = np.clip(texcoords, -1e300, 1e300)
    known = tc[~np.isnan(tc).any(axis=1)] if tc.shape[0] else tc
    lo = known.min(axis=0) if known.shape[0] else np.zeros(2)
    hi = known.max(axis=0) if known.shape[0] else np.zeros(2)
    side = GRADIENT_TEXELS
    for b in brushes:
        image = getattr(b, "image", None)
        if image is not None:
            side = max(side, min(MAX_TEXELS, max(image.shape[:2])))
    size = hi - lo
    h = side if size[1] > 0 else 1
    w = side if size[0] > 0 else 1
    return Bake(lo, hi, (h, w))


def _layer(p, bake: Bake, bounds) -> np.ndarray:
    """Premultiplied rgba (texels, 4) of one pass: brush times Color (both in sRGB, as WPF)."""
    color = np.array(p.color, dtype=np.float64)
    mult = np.concatenate([color[:3] * color[3], color[3:]])  # premultiplied Color
    if brush_is_uniform(p.brush):
        c = sample_brush(p.brush, np.zeros((1, 2)), bounds)
        return c * mult
    return sample_brush(p.brush, bake.uv_grid(), bounds) * mult


def _over(top: np.ndarray, bottom: np.ndarray) -> np.ndarray:
    return top + bottom * (1.0 - top[:, 3:4])


@dataclass
class MaterialResult:
    index: int | None  # the glTF material, None: WPF draws nothing with these passes
    textured: bool  # the primitive needs TEXCOORD_0 (rescaled to the bake box)
    notes: list  # (code, message) approximations made


def _straight_png(premul: np.ndarray, shape) -> np.ndarray:
    a = premul[:, 3:4]
    with np.errstate(divide="ignore", invalid="ignore"):
        rgb = np.where(a > 0, premul[:, :3] / np.where(a > 0, a, 1.0), 0.0)
    rgba = np.concatenate([rgb, a], axis=1)
    return np.round(np.clip(rgba, 0, 1) * 255).astype(np.uint8).reshape(*shape, 4)


class Materials:
    """Builds (and shares) glTF materials and textures for one document."""

    def __init__(self, doc) -> None:
        self.doc = doc
        self.sampler: int | None = None
        self.cache: dict = {}

    def _texture(self, premul: np.ndarray, shape) -> int:
        if self.sampler is None:
            self.sampler = self.doc.add(
                "samplers",
                {"magFilter": LINEAR, "minFilter": LINEAR, "wrapS": CLAMP, "wrapT": CLAMP},
            )
        image = self.doc.image_png(_straight_png(premul, shape))
        return self.doc.add("textures", {"sampler": self.sampler, "source": image})

    def material(self, passes, mesh, name: str | None, back: bool = False) -> MaterialResult:
        key = (id(passes), id(mesh) if passes else None)
        if key in self.cache:
            return self.cache[key]
        result = self._build(passes, mesh, name, back)
        self.cache[key] = result
        return result

    def _build(self, passes, mesh, name, back) -> MaterialResult:
        notes: list = []
        drawn = [p for p in passes if p.brush is not None]
        if not drawn:
            return MaterialResult(None, False, notes)
        diffuse = [p for p in drawn if isinstance(p, DiffuseMaterial)]
        emissive = [p for p in drawn if isinstance(p, EmissiveMaterial)]
        specular = [p for p in drawn if isinstance(p, SpecularMaterial)]
        tc = np.asarray(mesh.texcoords, dtype=np.float64)
        bake = bake_for(tc, [p.brush for p in drawn])
        bounds = brush_bounds(tc)
        textured = False
        pbr: dict = {"metallicFactor": 0.0}
        mat: dict = {"pbrMetallicRoughness": pbr}
        if name:
            mat["name"] = name + (" (back)" if back else "")

        base = np.zeros((1, 4))
        uniform = True
        for p in diffuse:
            layer = _layer(p, bake, bounds)
            uniform = uniform and layer.shape[0] == 1
            base = _over(layer, base)
        if not diffuse:
            base = np.array([[0.0, 0.0, 0.0, 1.0]])
            if emissive:
                notes.append(
                    (
                        "EXP004",
                        "an EmissiveMaterial without a DiffuseMaterial is added "
                        "to what lies behind it in WPF; glTF draws it opaque over black",
                    )
                )
        alpha_blend = bool(np.any(base[:, 3] < 1.0 - 1e-6))
        if uniform:
            c = base[0]
            rgb = c[:3] / c[3] if c[3] > 0 else np.zeros(3)
            pbr["baseColorFactor"] = [*map(float, srgb_to_linear(rgb)), float(c[3])]
        else:
            pbr["baseColorTexture"] = {"index": self._texture(base, bake.shape)}
            textured = True

        if emissive:
            glow = np.zeros((1, 4))
            for p in emissive:
                glow = glow + _layer(p, bake, bounds)
            glow = np.clip(glow, 0.0, 1.0)
            if glow.shape[0] == 1:
                mat["emissiveFactor"] = [float(v) for v in srgb_to_linear(glow[0, :3])]
            else:
                glow[:, 3] = 1.0
                mat["emissiveTexture"] = {"index": self._texture(glow, bake.shape)}
                mat["emissiveFactor"] = [1.0, 1.0, 1.0]
                textured = True

        spec: dict = {"specularFactor": 0.0}
        pbr["roughnessFactor"] = 1.0
        if specular:
            cols = []
            for p in specular:
                c = _layer(p, bake, bounds).mean(axis=0)
                cols.append(c[:3])
                if not brush_is_uniform(p.brush):
                    notes.append(
                        (
                            "EXP005",
                            f"the {type(p.brush).__name__} of a "
                            "SpecularMaterial is exported as its average colour",
                        )
                    )
            colour = np.clip(np.sum(cols, axis=0), 0.0, 1.0)
            power = max(float(specular[0].specular_power), 0.0)
            pbr["roughnessFactor"] = roughness_of_power(power)
            spec = {
                "specularFactor": 1.0,
                "specularColorFactor": [float(v) for v in srgb_to_linear(colour)],
            }
            notes.append(
                (
                    "EXP005",
                    f"SpecularMaterial (SpecularPower {power:g}) is exported as "
                    "KHR_materials_specular with a roughness of "
                    f"{pbr['roughnessFactor']:.3f}: the highlight's shape differs",
                )
            )
        mat["extensions"] = {"KHR_materials_specular": spec}
        self.doc.use_extension("KHR_materials_specular")
        if alpha_blend:
            mat["alphaMode"] = "BLEND"
        ambient = [p for p in diffuse if tuple(p.ambient_color) != (1.0, 1.0, 1.0, 1.0)]
        if ambient:
            notes.append(
                (
                    "EXP006",
                    "DiffuseMaterial.AmbientColor has no glTF equivalent: "
                    "ambient light is not scaled by it",
                )
            )
        index = self.doc.add("materials", mat)
        return MaterialResult(index, textured, notes)


def roughness_of_power(power: float) -> float:
    """SpecularPower n -> glTF roughness (documented approximation)."""
    return float(min(1.0, (2.0 / (max(power, 0.0) + 2.0)) ** 0.25)) if math.isfinite(power) else 0.0
