"""Per-vertex lighting: WPF's exact Gouraud lighting (wpf3d.md section 6).

Covers AmbientLight, DirectionalLight, PointLight, SpotLight and the three material pass kinds
(DiffuseMaterial, SpecularMaterial, EmissiveMaterial). Pipeline step: after the vertices of a
model are in VIEW space (eye at the origin) and before rasterization; the rasterizer interpolates
the premultiplied colours returned here and multiplies them by the brush sample per pixel.

What WPF's native lighting code does, and therefore what this module does:

- Every light is moved once per frame into view space by M = view @ world (light's own chain).
  Directions (directional and spot) are transformed as vectors by M's upper 3x3 and normalized;
  positions as points (with the homogeneous divide). A light whose direction or position is not
  finite after that (e.g. a zero Direction) is dropped, as WPF drops it.
- "Attenuations are rescaled by the transform's uniform scale": with s = |det(M[:3, :3])|^(1/3),
  a point/spot light's Range becomes Range * s, LinearAttenuation c1 / s and QuadraticAttenuation
  c2 / s^2 (ConstantAttenuation unchanged). Distances are then measured in view space, so the
  attenuation is that of the light's own units: c0 + c1 (d/s) + c2 (d/s)^2. s == 0 drops the light.
- A point/spot light is dropped unless every attenuation is finite and >= 0, at least one is > 0,
  and Range > 0.
- Spot cones: outer clamped to [0, 180] degrees, inner to [0, outer]; cos of the half angles.
- Diffuse and specular contributions of a light only count where N.L > 0; a point light exactly
  at the vertex (d = 0) contributes nothing; specular also needs N.H > 0.
- Light colour alpha is ignored; material colours are premultiplied by their alpha.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from xaml3d.scene.types import (
    AmbientLight,
    DiffuseMaterial,
    DirectionalLight,
    EmissiveMaterial,
    Light,
    MaterialPass,
    PointLight,
    SpecularMaterial,
    SpotLight,
)

# N.H^power for a negative SpecularPower can be huge; cap it so sums stay finite (the result is
# clamped to 1 anyway).
_POW_CAP = 1e30


def _empty(cols: int) -> np.ndarray:
    return np.zeros((0, cols), dtype=np.float64)


@dataclass(frozen=True)
class PreparedLights:
    """All lights of a viewport in view space, grouped by type (one frame's worth).

    ``ambient`` is the summed AmbientLight rgb. Directional lights: ``dir_color`` (K, 3) and
    ``dir_to_light`` (K, 3), the unit vector towards the light (= normalize(-Direction)).
    Point and spot lights share one group (``pos_*`` arrays, length K); for point lights
    ``pos_is_spot`` is False and the spot fields are unused.
    ``count`` is how many lights the scene declared (any kind, including dropped ones).
    """

    ambient: np.ndarray = field(default_factory=lambda: np.zeros(3))
    dir_color: np.ndarray = field(default_factory=lambda: _empty(3))
    dir_to_light: np.ndarray = field(default_factory=lambda: _empty(3))
    pos_color: np.ndarray = field(default_factory=lambda: _empty(3))
    pos_position: np.ndarray = field(default_factory=lambda: _empty(3))
    pos_range: np.ndarray = field(default_factory=lambda: np.zeros(0))
    pos_atten: np.ndarray = field(default_factory=lambda: _empty(3))  # c0, c1, c2 (view space)
    pos_is_spot: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    pos_spot_axis: np.ndarray = field(default_factory=lambda: _empty(3))  # normalize(-SpotDir)
    pos_cos_outer: np.ndarray = field(default_factory=lambda: np.zeros(0))
    pos_cos_inner: np.ndarray = field(default_factory=lambda: np.zeros(0))
    count: int = 0

    @property
    def directional_count(self) -> int:
        return int(self.dir_color.shape[0])

    @property
    def positional_count(self) -> int:
        return int(self.pos_color.shape[0])


SINGLE_MAX = float(np.finfo(np.float32).max)


def _unit(v: np.ndarray) -> np.ndarray | None:
    """v normalized, or None when v is zero, not finite or beyond single precision (WPF's
    renderer cannot use such a light: it is dropped). Divided by its largest component first,
    so the length cannot overflow."""
    v = np.asarray(v, dtype=np.float64)
    big = float(np.max(np.abs(v)))
    if not big <= SINGLE_MAX or big == 0.0:
        return None
    with np.errstate(under="ignore"):
        s = v / big
    return s / float(np.sqrt(s @ s))


def _transform_point(m: np.ndarray, p) -> np.ndarray | None:
    """A light's position in view space, or None when it is not finite or beyond single
    precision (then WPF's renderer drops the light)."""
    with np.errstate(over="ignore", invalid="ignore"):
        h = m @ np.array([p[0], p[1], p[2], 1.0], dtype=np.float64)
        out = h[:3] / h[3] if h[3] != 0.0 else None
    if out is None or not np.all(np.abs(out) <= SINGLE_MAX):
        return None
    return out


def prepare_lights(lights: Sequence[Light], view_matrix: np.ndarray) -> PreparedLights:
    """Move every light into view space once per frame (see the module docstring for the rules)."""
    view = np.asarray(view_matrix, dtype=np.float64)
    ambient = np.zeros(3)
    dcol, ddir = [], []
    pcol, ppos, prange, patt, pspot, paxis, pco, pci = [], [], [], [], [], [], [], []
    for light in lights:
        rgb = np.array(light.color[:3], dtype=np.float64)
        if isinstance(light, AmbientLight):
            ambient = ambient + rgb
            continue
        with np.errstate(over="ignore", invalid="ignore"):
            m = view @ np.asarray(light.world, dtype=np.float64)
        if not np.all(np.isfinite(m)):
            continue  # a light whose transform passes the range lights nothing (as in WPF)
        m3 = m[:3, :3]
        if isinstance(light, DirectionalLight):
            with np.errstate(over="ignore", invalid="ignore"):  # out of range: _unit drops it
                d = -(m3 @ np.array(light.direction, dtype=np.float64))
            to_light = _unit(d)
            if to_light is not None:
                dcol.append(rgb)
                ddir.append(to_light)
            continue
        if not isinstance(light, (PointLight, SpotLight)):
            continue
        with np.errstate(all="ignore"):  # past the range (or a denormal): no light, below
            det = float(np.linalg.det(m3)) if np.all(np.isfinite(m3)) else math.nan
        s = abs(det) ** (1.0 / 3.0) if math.isfinite(det) else 0.0
        c = (light.constant_attenuation, light.linear_attenuation, light.quadratic_attenuation)
        ok = all(math.isfinite(x) and x >= 0.0 for x in c) and any(x > 0.0 for x in c)
        if s == 0.0 or not ok or not light.range > 0.0:
            continue
        pos = _transform_point(m, light.position)
        if pos is None:
            continue
        axis = np.zeros(3)
        cos_o = cos_i = -2.0  # unused for point lights
        if isinstance(light, SpotLight):
            with np.errstate(over="ignore", invalid="ignore"):
                d = -(m3 @ np.array(light.direction, dtype=np.float64))
            a = _unit(d)
            if a is None:
                continue
            axis = a
            outer = min(max(light.outer_cone_angle, 0.0), 180.0)
            inner = min(max(light.inner_cone_angle, 0.0), outer)
            cos_o = math.cos(math.radians(outer) / 2.0)
            cos_i = math.cos(math.radians(inner) / 2.0)
        pcol.append(rgb)
        ppos.append(pos)
        prange.append(light.range * s)
        patt.append((c[0], c[1] / s, c[2] / (s * s)))
        pspot.append(isinstance(light, SpotLight))
        paxis.append(axis)
        pco.append(cos_o)
        pci.append(cos_i)

    def arr(rows, cols):
        return np.array(rows, dtype=np.float64).reshape(-1, cols)

    return PreparedLights(
        ambient=ambient,
        dir_color=arr(dcol, 3),
        dir_to_light=arr(ddir, 3),
        pos_color=arr(pcol, 3),
        pos_position=arr(ppos, 3),
        pos_range=np.array(prange, dtype=np.float64),
        pos_atten=arr(patt, 3),
        pos_is_spot=np.array(pspot, dtype=bool),
        pos_spot_axis=arr(paxis, 3),
        pos_cos_outer=np.array(pco, dtype=np.float64),
        pos_cos_inner=np.array(pci, dtype=np.float64),
        count=len(lights),
    )


def has_any_light(lights: PreparedLights | Sequence[Light]) -> bool:
    """True when the scene declares at least one light of any kind (WPF: no light at all draws
    diffuse surfaces opaque black, which ``shade_vertices`` already gives)."""
    if isinstance(lights, PreparedLights):
        return lights.count > 0
    return len(lights) > 0


def _premultiplied_rgb(color) -> np.ndarray:
    return np.array(color[:3], dtype=np.float64) * float(color[3])


def _normalize_rows(v: np.ndarray) -> np.ndarray:
    """Rows of v scaled to unit length; zero rows stay zero (no division by zero)."""
    n = np.sqrt(np.einsum("ij,ij->i", v, v))
    safe = np.where(n > 0.0, n, 1.0)
    return np.where((n > 0.0)[:, None], v / safe[:, None], 0.0)


def _spot_factor(rho: np.ndarray, cos_o: float, cos_i: float) -> np.ndarray:
    """1 inside the inner cone, 0 outside the outer, linear in rho between (D3D9's formula)."""
    span = cos_i - cos_o
    # The middle branch only happens when cos_o < rho <= cos_i, so span > 0 there.
    mid = (rho - cos_o) / span if span > 0.0 else np.zeros_like(rho)
    return np.where(rho > cos_i, 1.0, np.where(rho <= cos_o, 0.0, mid))


def _accumulate(
    positions: np.ndarray, normals: np.ndarray, lights: PreparedLights, power: float | None
) -> tuple[np.ndarray, np.ndarray]:
    """Sum over lights of colour * max(N.L,0) * atten * spot (diffuse) and, when ``power`` is
    given, of colour * max(N.H,0)^power * atten * spot where N.L > 0 (specular)."""
    n = positions.shape[0]
    diffuse = np.zeros((n, 3))
    specular = np.zeros((n, 3))
    to_eye = _normalize_rows(-positions) if power is not None else None

    def add(color, to_light, scale):
        # scale: per-vertex atten * spot (1 for directional lights); to_light: (N,3) unit or 0
        ndl = np.einsum("ij,ij->i", normals, to_light)
        lit = ndl > 0.0
        diffuse[:] += color[None, :] * (np.where(lit, ndl, 0.0) * scale)[:, None]
        if power is not None:
            h = _normalize_rows(to_eye + to_light)
            ndh = np.einsum("ij,ij->i", normals, h)
            ok = lit & (ndh > 0.0)
            base = np.where(ok, ndh, 1.0)
            with np.errstate(over="ignore", divide="ignore"):
                p = np.minimum(np.power(base, power), _POW_CAP)
            specular[:] += color[None, :] * (np.where(ok, p, 0.0) * scale)[:, None]

    ones = np.ones(n)
    for k in range(lights.directional_count):
        to_light = np.broadcast_to(lights.dir_to_light[k], (n, 3))
        add(lights.dir_color[k], to_light, ones)

    for k in range(lights.positional_count):
        v = lights.pos_position[k][None, :] - positions
        d = np.sqrt(np.einsum("ij,ij->i", v, v))
        present = d > 0.0  # a light exactly at the vertex contributes nothing (L undefined)
        safe_d = np.where(present, d, 1.0)
        to_light = np.where(present[:, None], v / safe_d[:, None], 0.0)
        c0, c1, c2 = lights.pos_atten[k]
        with np.errstate(over="ignore"):
            denom = c0 + c1 * d + c2 * d * d
        atten = 1.0 / np.maximum(denom, 1.0)
        in_range = present & (d <= lights.pos_range[k])
        scale = np.where(in_range, atten, 0.0)
        if lights.pos_is_spot[k]:
            rho = to_light @ lights.pos_spot_axis[k]
            scale = scale * _spot_factor(
                rho, float(lights.pos_cos_outer[k]), float(lights.pos_cos_inner[k])
            )
        add(lights.pos_color[k], to_light, scale)
    return diffuse, specular


def shade_vertices(
    material: MaterialPass,
    positions: np.ndarray,
    normals: np.ndarray,
    lights: PreparedLights,
) -> np.ndarray:
    """Per-vertex PREMULTIPLIED rgba (N, 4) of one material pass, WPF's formulas exactly.

    ``positions`` (N, 3) view space; ``normals`` (N, 3) unit view-space normals (zero allowed:
    ambient only), already negated by the caller for the BackMaterial pass.
    Diffuse: rgb = min(1, sum(light * max(N.L,0) * atten * spot) * Kd + ambient * Ka), a = Kd.a.
    Specular: rgb = min(1, sum(light * max(N.H,0)^power * atten * spot) * Ks), a = 0.
    Emissive: rgb = Ke, a = 0. (K* are premultiplied material colours.)
    """
    positions = np.asarray(positions, dtype=np.float64).reshape(-1, 3)
    normals = np.asarray(normals, dtype=np.float64).reshape(-1, 3)
    n = positions.shape[0]
    out = np.zeros((n, 4))
    # Tiny products (N.L * atten ...) may underflow to 0: harmless, so do not raise on it.
    with np.errstate(under="ignore"):
        if isinstance(material, EmissiveMaterial):
            out[:, :3] = np.minimum(_premultiplied_rgb(material.color), 1.0)
            return out
        if isinstance(material, DiffuseMaterial):
            kd = _premultiplied_rgb(material.color)
            ka = _premultiplied_rgb(material.ambient_color)
            diffuse, _ = _accumulate(positions, normals, lights, None)
            out[:, :3] = np.minimum(diffuse * kd[None, :] + (lights.ambient * ka)[None, :], 1.0)
            out[:, 3] = float(material.color[3])
            return out
        if isinstance(material, SpecularMaterial):
            ks = _premultiplied_rgb(material.color)
            power = float(material.specular_power)
            if power != power:  # a NaN SpecularPower (WPF takes any double): no highlight
                return out
            _, specular = _accumulate(positions, normals, lights, power)
            out[:, :3] = np.minimum(specular * ks[None, :], 1.0)
            return out
    raise TypeError(f"not a material pass: {type(material).__name__}")
