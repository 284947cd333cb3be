"""Reading brushes, materials and 2D brush transforms (wpf3d.md sections 6, 7).

Covers SolidColorBrush, LinearGradientBrush, RadialGradientBrush (+ GradientStop), ImageBrush
(ImageSource resolved relative to the XAML file that holds it, pack URIs reduced, loaded with
Pillow, never from the network), DrawingBrush and VisualBrush (drawings_reader.py),
BitmapCacheBrush (a placeholder),
a colour string where a Brush is expected; DiffuseMaterial, SpecularMaterial, EmissiveMaterial and
MaterialGroup (flattened into a tuple of leaf passes, nested groups too); and the 2D transforms
TranslateTransform, ScaleTransform, RotateTransform, SkewTransform, MatrixTransform and
TransformGroup as 3x3 column-form matrices (p' = M @ (x, y, 1)).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from xaml3d.errors import ValueSyntaxError
from xaml3d.scene import tracks as K
from xaml3d.scene import transforms as T
from xaml3d.scene.drawing import DrawingBrush
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
from xaml3d.xaml.animation_tracks import built, group_of, node_of
from xaml3d.xaml.context import as_written, markup_key, qname, split_markup
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


def tile_properties(r, p) -> dict:
    """TileBrush's properties (ImageBrush, DrawingBrush, VisualBrush), WPF's defaults."""
    return dict(
        viewport=p.value("Viewport", V.parse_rect, (0.0, 0.0, 1.0, 1.0)),
        viewport_units=p.value("ViewportUnits", _enum(_MAPPING), "RelativeToBoundingBox"),
        viewbox=p.value("Viewbox", V.parse_rect, (0.0, 0.0, 1.0, 1.0)),
        viewbox_units=p.value("ViewboxUnits", _enum(_MAPPING), "RelativeToBoundingBox"),
        stretch=p.value("Stretch", _enum(_STRETCH), "Fill"),
        tile_mode=p.value("TileMode", _enum(_TILE), "None"),
        alignment_x=p.value("AlignmentX", _enum(_ALIGN_X), "Center"),
        alignment_y=p.value("AlignmentY", _enum(_ALIGN_Y), "Center"),
    )


def brush_from_string(s: str) -> SolidColorBrush:
    """A colour string where a Brush is expected means a SolidColorBrush."""
    return SolidColorBrush(color=V.parse_color(s))


def brush_property(r, p, prop: str):
    """Read a Brush-valued property (element, resource, colour string or {x:Null})."""
    return p.obj(prop, lambda el: brush(r, el), None, from_string=brush_from_string)


def _common(r, p, nodes: list) -> dict:
    """What every brush has; ``nodes`` receives (field, typed node) of an animated Transform
    or RelativeTransform."""
    return {
        "opacity": p.value("Opacity", V.parse_double, 1.0),
        "transform": _transform_property(r, p, "Transform", "transform", nodes),
        "relative_transform": _transform_property(
            r, p, "RelativeTransform", "relative_transform", nodes
        ),
        **r.ctx.position(p.el),
    }


def _transform_property(r, p, prop: str, field: str, nodes: list):
    got = p.obj(
        prop, lambda el: built(transform2d_parts(r, el)), None, from_string=transform2d_text
    )
    if isinstance(got, tuple):  # built from an element: (matrix, node)
        m, node = got
        if node is not None:
            nodes.append((field, node))
        return m
    return got  # a matrix string, {x:Null} or nothing


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
    stop = GradientStop(
        color=p.value("Color", V.parse_color, (1.0, 1.0, 1.0, 0.0)),
        offset=p.value("Offset", V.parse_double, 0.0),
    )
    return r.tag(stop, el, _STOP_FIELDS)


# XAML property -> scene field, of the objects animations reach (wpf3d.md section 8)
_BRUSH_FIELDS = {"Color": "color", "Opacity": "opacity", "StartPoint": "start_point",
                 "EndPoint": "end_point", "Center": "center", "GradientOrigin": "gradient_origin",
                 "RadiusX": "radius_x", "RadiusY": "radius_y"}  # fmt: skip
_STOP_FIELDS = {"Color": "color", "Offset": "offset"}
_PASS_FIELDS = {"Color": "color", "AmbientColor": "ambient_color",
                "SpecularPower": "specular_power"}  # fmt: skip


def brush(r, el):
    """Any Brush element -> a scene brush (None when it cannot be read)."""
    nodes: list = []
    obj = r.tag(_brush(r, el, nodes), el, _BRUSH_FIELDS)
    for field, node in nodes:
        if obj is not None and hasattr(obj, field):  # a 2D transform an animation drives
            r.world(obj, field, None, (node,))
    return obj


def _brush(r, el, nodes: list):
    p = r.props(el)
    t = p.type
    if t == "SolidColorBrush":
        c = _common(r, p, nodes)
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
            **_common(r, p, nodes),
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
        return _image_brush(r, p, nodes)
    if t in ("DrawingBrush", "VisualBrush"):
        return r.drawing_brush(p, _common(r, p, nodes))  # a brush holding a drawing
    if t == "BitmapCacheBrush":
        r.ctx.diag("BRU001", f"{t} content cannot be drawn: a neutral placeholder is used", el)
        return PlaceholderBrush(
            kind=t, opacity=p.value("Opacity", V.parse_double, 1.0), **r.ctx.position(el)
        )
    r.ctx.diag("XAML013", f"{t} is not a Brush: ignored", el)
    return None


def image_source(r, p, prop: str) -> tuple[str | None, object, str | None]:
    """(URI, element, attribute) of the image an ImageSource-typed property names: a plain
    string, or a BitmapImage's UriSource, the BitmapImage given as a property element or as a
    resource (``ImageSource="{StaticResource photo}"``). The element and attribute locate the
    diagnostics, and a relative URI is resolved against the element's own document, as WPF
    resolves it against the markup that holds it. (None, ...) when there is no such URI."""
    if prop in p.attrs:
        kind, payload = p.markup(prop, p.attrs[prop])
        if kind == "plain":
            return payload, p.el, p.attr_keys.get(prop)
        if kind == "element":
            return _bitmap_uri(r, payload)
        return None, p.el, None
    kids = p.items(prop)
    if kids:
        return _bitmap_uri(r, kids[-1])
    return p.elem_text.get(prop), p.el, None


_REFERENCES = ("StaticResource", "DynamicResource")


def drawing_image_element(r, p, prop: str = "Source"):
    """The DrawingImage element an ImageSource-typed property holds (through a resource), or
    None for any other source (a URI, a BitmapImage). Reports nothing: a missing resource is
    said where the bitmap source is read."""
    el = None
    if prop in p.attrs:
        m = split_markup(p.attrs[prop])
        if m is not None and m[0] in _REFERENCES:
            el = _entry(r, p.el, markup_key(m[1]))
    else:
        kids = p.items(prop)
        if kids:
            el = kids[-1]
            if isinstance(el.tag, str) and qname(el.tag)[1] in _REFERENCES:
                el = _entry(r, el, el.get("ResourceKey"))
    if el is None or not isinstance(el.tag, str) or qname(el.tag)[1] != "DrawingImage":
        return None
    return el


def _entry(r, at, key: str):
    """A resource entry by key as seen from ``at``, without a diagnostic when it is missing."""
    return r.resources.find(key, at) if key else None


def drawing_image(r, el):
    """The Drawing of a DrawingImage element (None: nothing drawn)."""
    return r.build_node(el, r.drawing, None)


def _bitmap_uri(r, el) -> tuple[str | None, object, str | None]:
    """The UriSource of a BitmapImage element (through a <StaticResource/> element)."""
    if isinstance(el.tag, str) and qname(el.tag)[1] in ("StaticResource", "DynamicResource"):
        key = el.get("ResourceKey")
        found = r.resources.lookup(key, el, attr="ResourceKey") if key else None
        if found is None:
            return None, el, None
        el = found
    if not isinstance(el.tag, str) or qname(el.tag)[1] != "BitmapImage":
        return None, el, None  # a DrawingImage, a BitmapSource of code: not a file to read
    uri = el.get("UriSource")
    if uri is None or split_markup(uri) is not None:
        return None, el, None
    return uri, el, "UriSource"


def _image_brush(r, p, nodes: list) -> ImageBrush | DrawingBrush:
    held = drawing_image_element(r, p, "ImageSource")
    if held is not None:
        # a DrawingImage: its size is its Drawing's bounds, which a relative Viewbox then
        # refers to, so the brush is its Drawing's DrawingBrush
        content = drawing_image(r, held)
        return DrawingBrush(drawing=content, **tile_properties(r, p), **_common(r, p, nodes))
    source, where, attr = image_source(r, p, "ImageSource")
    path = image = None
    if source:
        path, image = load_image(r, source, where, attr)
    # A missing picture would make the surface vanish; a grey checker keeps the model visible.
    is_placeholder = bool(source) and image is None
    if is_placeholder:
        image = placeholder_image()
    return ImageBrush(
        source=source,
        path=path,
        image=image,
        is_placeholder=is_placeholder,
        **tile_properties(r, p),
        **_common(r, p, nodes),
    )


def load_image(r, source: str, el, attr: str | None = None) -> tuple[str | None, np.ndarray | None]:
    """Resolve and decode an ImageSource; diagnostics (located at ``el``'s attribute ``attr``
    when the source is an attribute) say why when there is no image. Decoded once per element
    however many models use it."""
    key = ("image", id(el), source)
    hit = r.cache.get(key)
    if hit is not None and hit[0] is el:
        return hit[1]
    found = _load_image(r, source, el, attr)
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
    # Pillow only for a scene that has an image to decode: ``validate``, ``info`` and
    # ``camera`` of the others never import it (about 10 ms of a process's start)
    from PIL import Image

    try:
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
    once however many models share it (a resource used by thousands of models)."""
    hit = r.cache.get(("material", id(el)))
    if hit is not None and hit[0] is el:
        return hit[1]  # already tagged for the animation tracks when first built
    passes = _material(r, el)
    if r.props(el).type != "MaterialGroup":
        for ps in passes:
            r.tag(ps, el, _PASS_FIELDS)
    r.cache["material", id(el)] = (el, passes)  # the element kept: its id stays its own
    return passes


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
    return transform2d_parts(r, el)[0]


def transform2d_parts(r, el) -> tuple[np.ndarray | None, object]:
    """A 2D Transform element -> (its matrix or None, its typed node when an animation drives
    part of it; its slots count as drawn only where a brush holds it, ``Reader.world``)."""
    p = r.props(el)
    t = p.type
    d = V.parse_double
    cx, cy = p.value("CenterX", d, 0.0), p.value("CenterY", d, 0.0)
    centers = {"center_x": ("CenterX", cx), "center_y": ("CenterY", cy)}

    def node(cls, values: dict, **parts):
        return node_of(r, el, cls, values, place=False, **parts)

    if t == "TranslateTransform":
        x, y = p.value("X", d, 0.0), p.value("Y", d, 0.0)
        return T.translation_2d(x, y), node(K.Translate2D, {"x": ("X", x), "y": ("Y", y)})
    if t == "ScaleTransform":
        sx, sy = p.value("ScaleX", d, 1.0), p.value("ScaleY", d, 1.0)
        n = node(K.Scale2D, {"scale_x": ("ScaleX", sx), "scale_y": ("ScaleY", sy), **centers})
        return T.scaling_2d(sx, sy, cx, cy), n
    if t == "RotateTransform":
        a = p.value("Angle", d, 0.0)
        return T.rotation_2d(a, cx, cy), node(K.Rotate2D, {"angle": ("Angle", a), **centers})
    if t == "SkewTransform":
        ax, ay = p.value("AngleX", d, 0.0), p.value("AngleY", d, 0.0)
        n = node(K.Skew2D, {"angle_x": ("AngleX", ax), "angle_y": ("AngleY", ay), **centers})
        return T.skew_2d(ax, ay, cx, cy), n
    if t == "MatrixTransform":
        return frozen_array(p.value("Matrix", _matrix2d, np.eye(3))), None
    if t == "TransformGroup":
        return group_of(r, p, transform2d_parts, K.TransformGroup2D, T.compose_2d)
    r.ctx.diag("BRU006", f"{t} is not a 2D Transform: ignored", el)
    return None, None
