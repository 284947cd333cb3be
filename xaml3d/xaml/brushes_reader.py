"""Reading brushes, materials and 2D brush transforms (wpf3d.md sections 6, 7).

Covers SolidColorBrush, LinearGradientBrush, RadialGradientBrush (+ GradientStop), ImageBrush
(ImageSource resolved relative to the XAML file that holds it, pack URIs reduced, loaded with
Pillow, never from the network), VisualBrush / DrawingBrush / BitmapCacheBrush (placeholders),
a colour string where a Brush is expected; DiffuseMaterial, SpecularMaterial, EmissiveMaterial and
MaterialGroup (flattened into a tuple of leaf passes, nested groups too); and the 2D transforms
TranslateTransform, ScaleTransform, RotateTransform, SkewTransform, MatrixTransform and
TransformGroup as 3x3 column-form matrices (p' = M @ (x, y, 1)).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from xaml3d.errors import ValueSyntaxError
from xaml3d.scene.types import (
    DiffuseMaterial,
    EmissiveMaterial,
    GradientStop,
    ImageBrush,
    LinearGradientBrush,
    PlaceholderBrush,
    RadialGradientBrush,
    SolidColorBrush,
    SpecularMaterial,
    frozen_array,
    placeholder_image,
)
from xaml3d.xaml import values as V
from xaml3d.xaml.context import as_written
from xaml3d.xaml.resources import reduce_uri

_MAPPING = ("RelativeToBoundingBox", "Absolute")
_SPREAD = ("Pad", "Reflect", "Repeat")
_INTERP = ("SRgbLinearInterpolation", "ScRgbLinearInterpolation")
_STRETCH = ("None", "Fill", "Uniform", "UniformToFill")
_TILE = ("None", "Tile", "FlipX", "FlipY", "FlipXY")
_ALIGN_X = ("Left", "Center", "Right")
_ALIGN_Y = ("Top", "Center", "Bottom")


def _enum(allowed):
    return lambda s: V.parse_enum(s, allowed)


def brush_from_string(s: str) -> SolidColorBrush:
    """A colour string where a Brush is expected means a SolidColorBrush."""
    return SolidColorBrush(color=V.parse_color(s))


def brush_property(r, p, prop: str):
    """Read a Brush-valued property (element, resource, colour string or {x:Null})."""
    return p.obj(prop, lambda el: brush(r, el), None, from_string=brush_from_string)


def _common(r, p) -> dict:
    return {
        "opacity": p.value("Opacity", V.parse_double, 1.0),
        "transform": p.obj(
            "Transform", lambda el: transform2d(r, el), None, from_string=transform2d_text
        ),
        "relative_transform": p.obj(
            "RelativeTransform", lambda el: transform2d(r, el), None, from_string=transform2d_text
        ),
        **r.ctx.position(p.el),
    }


def _stops(r, p) -> tuple[GradientStop, ...]:
    if "GradientStops" in p.attrs:  # "{StaticResource stops}" naming a GradientStopCollection
        kind, entry = p.markup("GradientStops", p.attrs["GradientStops"])
        kids = [k for k in entry if isinstance(k.tag, str)] if kind == "element" else []
    else:
        kids = p.items("GradientStops")
    out = []
    for k in kids:
        stop = r.build_node(k, lambda el: _stop(r, el), None)
        if stop is not None:
            out.append(stop)
    return tuple(out)


def _stop(r, el) -> GradientStop | None:
    p = r.props(el)
    if p.type != "GradientStop":
        r.ctx.diag("XAML013", f"{p.type} is not a GradientStop: ignored", el)
        return None
    return GradientStop(
        color=p.value("Color", V.parse_color, (1.0, 1.0, 1.0, 0.0)),
        offset=p.value("Offset", V.parse_double, 0.0),
    )


def brush(r, el):
    """Any Brush element -> a scene brush (None when it cannot be read)."""
    p = r.props(el)
    t = p.type
    if t == "SolidColorBrush":
        c = _common(r, p)
        return SolidColorBrush(
            color=p.value("Color", V.parse_color, (1.0, 1.0, 1.0, 0.0)),
            opacity=c["opacity"],
            line=c["line"],
            column=c["column"],
        )
    if t in ("LinearGradientBrush", "RadialGradientBrush"):
        common = dict(
            stops=_stops(r, p),
            mapping_mode=p.value("MappingMode", _enum(_MAPPING), "RelativeToBoundingBox"),
            spread_method=p.value("SpreadMethod", _enum(_SPREAD), "Pad"),
            color_interpolation_mode=p.value(
                "ColorInterpolationMode", _enum(_INTERP), "SRgbLinearInterpolation"
            ),
            **_common(r, p),
        )
        if t == "LinearGradientBrush":
            return LinearGradientBrush(
                start_point=p.value("StartPoint", V.parse_point, (0.0, 0.0)),
                end_point=p.value("EndPoint", V.parse_point, (1.0, 1.0)),
                **common,
            )
        return RadialGradientBrush(
            center=p.value("Center", V.parse_point, (0.5, 0.5)),
            gradient_origin=p.value("GradientOrigin", V.parse_point, (0.5, 0.5)),
            radius_x=p.value("RadiusX", V.parse_double, 0.5),
            radius_y=p.value("RadiusY", V.parse_double, 0.5),
            **common,
        )
    if t == "ImageBrush":
        return _image_brush(r, p)
    if t in ("VisualBrush", "DrawingBrush", "BitmapCacheBrush"):
        r.ctx.diag("BRU001", f"{t} content cannot be drawn: a neutral placeholder is used", el)
        return PlaceholderBrush(
            kind=t, opacity=p.value("Opacity", V.parse_double, 1.0), **r.ctx.position(el)
        )
    r.ctx.diag("XAML013", f"{t} is not a Brush: ignored", el)
    return None


def _image_brush(r, p) -> ImageBrush:
    el = p.el
    source = p.string("ImageSource")
    path = image = None
    if source:
        path, image = load_image(r, source, el, p.attr_keys.get("ImageSource"))
    # A missing picture would make the surface vanish; a grey checker keeps the model visible.
    is_placeholder = bool(source) and image is None
    if is_placeholder:
        image = placeholder_image()
    return ImageBrush(
        source=source,
        path=path,
        image=image,
        is_placeholder=is_placeholder,
        viewport=p.value("Viewport", V.parse_rect, (0.0, 0.0, 1.0, 1.0)),
        viewport_units=p.value("ViewportUnits", _enum(_MAPPING), "RelativeToBoundingBox"),
        viewbox=p.value("Viewbox", V.parse_rect, (0.0, 0.0, 1.0, 1.0)),
        viewbox_units=p.value("ViewboxUnits", _enum(_MAPPING), "RelativeToBoundingBox"),
        stretch=p.value("Stretch", _enum(_STRETCH), "Fill"),
        tile_mode=p.value("TileMode", _enum(_TILE), "None"),
        alignment_x=p.value("AlignmentX", _enum(_ALIGN_X), "Center"),
        alignment_y=p.value("AlignmentY", _enum(_ALIGN_Y), "Center"),
        **_common(r, p),
    )


def load_image(r, source: str, el, attr: str | None = None) -> tuple[str | None, np.ndarray | None]:
    """Resolve and decode an ImageSource; diagnostics (located at ``el``'s attribute ``attr``
    when the source is an attribute) say why when there is no image. Animation frames reuse
    the first frame's decoded image."""
    key = ("image", id(el), source)
    hit = r.cache.get(key) if r.cache is not None else None
    if hit is not None and hit[0] is el:
        return hit[1]
    found = _load_image(r, source, el, attr)
    if r.cache is not None:
        r.cache[key] = (el, found)  # the element kept: its id stays its own
    return found


def _load_image(r, source: str, el, attr: str | None) -> tuple[str | None, np.ndarray | None]:
    rel = reduce_uri(source)
    if rel is None:
        r.ctx.diag(
            "BRU004",
            f"ImageSource {as_written(source)}: network URIs are never fetched; "
            "a grey checker stands in",
            el,
            attr=attr,
        )
        return None, None
    doc = r.ctx.doc_of(el)
    base = doc.directory if doc is not None and doc.directory is not None else Path.cwd()
    path = (base / rel).resolve()
    if not r.ctx.path_allowed(path):
        r.ctx.diag(
            "BRU005",
            f"ImageSource {as_written(source)} leaves the scene's folder tree; "
            "a grey checker stands in",
            el,
            attr=attr,
        )
        return None, None
    if not path.is_file():
        # Windows file names are case-insensitive: try a case-insensitive match
        alt = _case_insensitive(path)
        if alt is None:
            msg = f"image {as_written(source)} not found ({path}); a grey checker stands in"
            r.ctx.diag("BRU002", msg, el, attr=attr)
            return str(path), None
        path = alt
    r.ctx.images_used.append(str(path))
    try:
        from PIL import Image

        with Image.open(path) as im:
            arr = np.asarray(im.convert("RGBA"), dtype=np.uint8)
    except Exception as exc:  # Pillow raises many kinds for a corrupt or unknown file
        msg = f"image {as_written(source)} cannot be decoded ({exc}); a grey checker stands in"
        r.ctx.diag("BRU003", msg, el, attr=attr)
        return str(path), None
    return str(path), frozen_array(arr, dtype=np.uint8)


def _case_insensitive(path: Path) -> Path | None:
    cur = Path(path.anchor)
    for part in path.parts[1:]:
        try:
            names = {n.lower(): n for n in (p.name for p in cur.iterdir())}
        except OSError:
            return None
        real = names.get(part.lower())
        if real is None:
            return None
        cur = cur / real
    return cur if cur.is_file() else None


# --------------------------------------------------------------------------- materials


def _located(r, p) -> dict:
    """A material pass's position and the properties read so far that WPF refuses (keyword
    arguments come last, so every property of the pass has been read)."""
    return {**r.ctx.position(p.el), "rejected": frozenset(p.rejected)}


def material(r, el) -> tuple:
    """A Material element -> tuple of leaf passes (MaterialGroup flattened, in order). Built
    once however many models share it, unless an animation frame may change it."""
    shared = not r.overrides
    if shared:
        hit = r.cache.get(("material", id(el)))
        if hit is not None and hit[0] is el:
            return hit[1]
    out = _material(r, el)
    if shared:
        r.cache["material", id(el)] = (el, out)  # the element kept: its id stays its own
    return out


def _material(r, el) -> tuple:
    p = r.props(el)
    t = p.type
    if t == "MaterialGroup":
        out: list = []
        for k in p.items("Children"):
            out.extend(r.build_node(k, lambda e: material(r, e), ()))
        return tuple(out)
    white = (1.0, 1.0, 1.0, 1.0)
    if t == "DiffuseMaterial":
        return (
            DiffuseMaterial(
                brush=brush_property(r, p, "Brush"),
                color=p.value("Color", V.parse_color, white),
                ambient_color=p.value("AmbientColor", V.parse_color, white),
                **_located(r, p),
            ),
        )
    if t == "SpecularMaterial":
        return (
            SpecularMaterial(
                brush=brush_property(r, p, "Brush"),
                color=p.value("Color", V.parse_color, white),
                specular_power=p.value("SpecularPower", V.parse_double, 40.0),
                **_located(r, p),
            ),
        )
    if t == "EmissiveMaterial":
        return (
            EmissiveMaterial(
                brush=brush_property(r, p, "Brush"),
                color=p.value("Color", V.parse_color, white),
                **_located(r, p),
            ),
        )
    r.ctx.diag("XAML013", f"{t} is not a Material: ignored", el)
    return ()


# --------------------------------------------------------------------------- 2D transforms


def _about(linear: np.ndarray, cx: float, cy: float) -> np.ndarray:
    m = np.eye(3)
    m[:2, :2] = linear
    m[:2, 2] = np.array([cx, cy]) - linear @ np.array([cx, cy])
    return m


def _matrix2d(s: str) -> np.ndarray:
    if s.strip() == "Identity":
        return np.eye(3)
    v = V.parse_double_collection(s)
    if v.shape[0] != 6:
        raise ValueSyntaxError(f"Matrix needs 6 numbers, got {v.shape[0]}", code="VAL003")
    m11, m12, m21, m22, ox, oy = (float(x) for x in v)
    # WPF row form p' = p M: x' = m11 x + m21 y + ox, y' = m12 x + m22 y + oy
    return np.array([[m11, m21, ox], [m12, m22, oy], [0.0, 0.0, 1.0]])


def transform2d_text(s: str) -> np.ndarray:
    """A 2D Transform written as text (WPF's TransformConverter): "Identity" or the six numbers
    of a Matrix, as a MatrixTransform."""
    return frozen_array(_matrix2d(s))


def transform2d(r, el) -> np.ndarray | None:
    """A 2D Transform element -> read-only 3x3 column-form matrix (None when unreadable)."""
    p = r.props(el)
    t = p.type
    d = V.parse_double
    cx, cy = p.value("CenterX", d, 0.0), p.value("CenterY", d, 0.0)
    if t == "TranslateTransform":
        m = np.eye(3)
        m[:2, 2] = (p.value("X", d, 0.0), p.value("Y", d, 0.0))
    elif t == "ScaleTransform":
        m = _about(np.diag([p.value("ScaleX", d, 1.0), p.value("ScaleY", d, 1.0)]), cx, cy)
    elif t == "RotateTransform":
        a = math.radians(p.value("Angle", d, 0.0))
        # positive angles turn clockwise on screen (y down): x' = x cos - y sin
        m = _about(np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]), cx, cy)
    elif t == "SkewTransform":
        ax, ay = math.radians(p.value("AngleX", d, 0.0)), math.radians(p.value("AngleY", d, 0.0))
        m = _about(np.array([[1.0, math.tan(ax)], [math.tan(ay), 1.0]]), cx, cy)
    elif t == "MatrixTransform":
        m = p.value("Matrix", _matrix2d, np.eye(3))
    elif t == "TransformGroup":
        m = np.eye(3)
        for k in p.items("Children"):
            child = r.build_node(k, lambda e: transform2d(r, e), None)
            if child is not None:
                m = child @ m  # children apply first to last
    else:
        r.ctx.diag("BRU006", f"{t} is not a 2D Transform: ignored", el)
        return None
    return frozen_array(m)
