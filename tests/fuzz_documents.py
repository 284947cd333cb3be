"""Structured fuzzing: XAML documents built from the reader's vocabulary, and the pipeline they
are run through.

``document(pick)`` writes one document: a Viewport3D (alone, or in a Grid / Border / Viewbox /
Canvas with 2D elements beside it) with a camera, lights, meshes, materials and brushes (solid,
gradients with any number of stops, a VisualBrush, possibly of the element it paints, an
ImageBrush of a missing file, which the reader's checker replaces),
transforms (2D and 3D), a Viewport2DVisual3D with a small 2D visual, and a Loaded storyboard
of nested timelines and animations (From/To/By, key frames, easing functions). Every property
of those elements is taken from ``xaml3d.xaml.vocabulary`` and given a value of its kind, often
one at the edge of its domain: 0, -0, denormals, 1e308, Infinity, NaN, huge counts and times,
empty strings, other scripts' digits. ``pick`` draws the choices: ``random_picker`` (a seeded
``random.Random``, for the long runs of ``tools/fuzz.py``) or ``hypothesis_picker`` (a
hypothesis ``data`` object, so that a failure shrinks to a small document).

``run_document(text)`` runs a document through load, validate (the findings), a render at a
moment of its storyboard, the window picture, and the glTF export, and the frame count
``animate`` would plan: it returns normally or raises what escaped (anything but a located
``XamlError``, under ``warnings`` turned into errors by the caller).
"""

from __future__ import annotations

import random
from collections.abc import Callable, Sequence

from xaml3d.xaml import vocabulary as voc

NS = (
    'xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation" '
    'xmlns:x="http://schemas.microsoft.com/winfx/2006/xaml"'
)

# numbers at the edges of a double's domain, and a few ordinary ones
EDGE_NUMBERS = ("0", "-0", "5e-324", "1e-300", "1e-45", "1e308", "-1e308",
                "1.7976931348623157E+308", "Infinity", "-Infinity", "NaN", "3.5e38", "-3.5e38",
                "1e20", "65536",
                "2147483647", "-2147483648", "2147483648", "1e9", "-1", "0.5", "1", "2", "45",
                "90", "180", "360", "1000")  # fmt: skip
ODD_TEXT = ("", " ", "1e", "--1", "1,", ",", "\u0663", "\uff11", "1\u00a0", "0x10", "1_0", "+1",
            ".5", "5.", "1e+", "\u200b1", "\U0001d7d9")  # fmt: skip
NAMES = ("A", "B", "C", "D")  # x:Names given to elements; TargetName picks among them


class Pick:
    """The choices a document is written from (one interface for random and hypothesis)."""

    def __init__(self, choose: Callable[[Sequence], object], integer: Callable[[int, int], int]):
        self.choose = choose
        self.integer = integer
        self.names: set[str] = set()  # the x:Names given so far: each once (XAML020 else)

    def chance(self, percent: int) -> bool:
        return self.integer(0, 99) < percent


def random_picker(seed: int) -> Pick:
    rng = random.Random(seed)
    return Pick(lambda seq: seq[rng.randrange(len(seq))], rng.randint)


def hypothesis_picker(data) -> Pick:
    from hypothesis import strategies as st

    return Pick(
        lambda seq: data.draw(st.sampled_from(list(seq))),
        lambda lo, hi: data.draw(st.integers(lo, hi)),
    )


# --------------------------------------------------------------------------- values by kind


def number(p: Pick) -> str:
    if p.chance(55):
        return p.choose(EDGE_NUMBERS)
    if p.chance(15):
        return p.choose(ODD_TEXT)
    return str(p.choose((0.25, 1.5, 3, 10, 0.001, 7, 12.5, 100)))


def numbers(p: Pick, n: int) -> str:
    sep = p.choose((",", " ", ", "))
    return sep.join(number(p) if p.chance(40) else p.choose(("0", "1", "-1", "0.5"))
                    for _ in range(n))  # fmt: skip


def timespan(p: Pick) -> str:
    return p.choose(("0:0:1", "0:0:0", "0:0:0.5", "0:0:2", "1", "10675199", "10675199.23:59:59",
                     "100.0:0:0", "0:0:0.0000001", "-0:0:1", "0:0:60", "24:0:0", "1e9", "",
                     "0:0:1.12345678", "0:0:1", "0:0:3"))  # fmt: skip


def duration(p: Pick) -> str:
    return p.choose(("Automatic", "Forever", "automatic")) if p.chance(20) else timespan(p)


def repeat(p: Pick) -> str:
    return p.choose(("Forever", "1e9x", "2x", "0x", "0.5x", "Infinityx", "NaNx", "1e308x",
                     "-1x", "3x", "x")) if p.chance(70) else timespan(p)  # fmt: skip


def color(p: Pick) -> str:
    return p.choose(("Red", "#80FF0000", "#F00", "#12345678", "sc#1,0.5,0.5,0.5",
                     "sc#NaN,1,1,1", "sc#1,1e308,0,0", "sc#-1,-1,-1,-1", "Transparent",
                     "#GG0000", "", "White"))  # fmt: skip


def value_of(kind: str, p: Pick) -> str | None:
    """A value written for a property of ``kind`` (None: leave the property out)."""
    if kind == "double":
        return number(p)
    if kind == "bool":
        return p.choose(("True", "False", "true", "yes"))
    if kind in ("point3d", "vector3d"):
        return numbers(p, p.choose((3, 3, 3, 2)))
    if kind == "point":
        return numbers(p, 2)
    if kind == "quaternion":
        return numbers(p, 4)
    if kind == "size":
        return numbers(p, 2)
    if kind == "rect":
        return numbers(p, 4) if p.chance(80) else "Empty"
    if kind == "matrix3d":
        return numbers(p, 16) if p.chance(80) else "Identity"
    if kind == "matrix":
        return numbers(p, 6)
    if kind == "color":
        return color(p)
    if kind == "timespan":
        return timespan(p)
    if kind == "duration":
        return duration(p)
    if kind == "repeat":
        return repeat(p)
    if kind == "keytime":
        return p.choose(("0:0:0.5", "50%", "Uniform", "Paced", "100%", "1e308%", "0:0:1e9"))
    if kind == "keyspline":
        return numbers(p, 4)
    if kind == "point3d[]":
        return " ".join(numbers(p, 3) for _ in range(p.integer(0, 5)))
    if kind == "vector3d[]":
        return " ".join(numbers(p, 3) for _ in range(p.integer(0, 4)))
    if kind == "point[]":
        return " ".join(numbers(p, 2) for _ in range(p.integer(0, 5)))
    if kind == "int[]":
        return " ".join(p.choose(("0", "1", "2", "3", "-1", "2147483647", "4")) for _ in
                        range(p.integer(0, 9)))  # fmt: skip
    if kind == "brush":
        return color(p)
    if kind == "string":
        return None
    return None


ENUMS = {
    "EasingMode": ("EaseIn", "EaseOut", "EaseInOut"),
    "FillBehavior": ("HoldEnd", "Stop"),
    "SpreadMethod": ("Pad", "Reflect", "Repeat"),
    "MappingMode": ("RelativeToBoundingBox", "Absolute"),
    "Stretch": ("None", "Fill", "Uniform", "UniformToFill"),
    "TileMode": ("None", "Tile", "FlipX", "FlipY", "FlipXY"),
    "ColorInterpolationMode": ("SRgbLinearInterpolation", "ScRgbLinearInterpolation"),
}


def attributes(p: Pick, type_name: str, skip: Sequence[str] = (), most: int = 4) -> str:
    """Up to ``most`` of the type's value properties, each with a value of its kind."""
    et = voc.lookup(type_name)
    if et is None:
        return ""
    probe = Pick(lambda s: s[0], lambda a, b: a)  # which kinds get a value at all
    props = [k for k, kind in et.properties.items()
             if k not in skip and (k in ENUMS or value_of(kind, probe) is not None)]  # fmt: skip
    out = []
    for _ in range(p.integer(0, min(most, len(props)))):
        prop = p.choose(props)
        if any(a.startswith(f' {prop}="') for a in out):
            continue
        value = p.choose(ENUMS[prop]) if prop in ENUMS else value_of(et.properties[prop], p)
        if value is not None:
            out.append(f' {prop}="{value}"')
    return "".join(out)


def named(p: Pick) -> str:
    if not p.chance(30):
        return ""
    name = p.choose(NAMES)
    if name in p.names:
        return ""
    p.names.add(name)
    return f' x:Name="{name}"'


# --------------------------------------------------------------------------- elements


def transform3d(p: Pick, depth: int = 0) -> str:
    kind = p.choose(("TranslateTransform3D", "ScaleTransform3D", "RotateTransform3D",
                     "MatrixTransform3D", "Transform3DGroup"))  # fmt: skip
    if kind == "Transform3DGroup" and depth < 2:
        kids = "".join(transform3d(p, depth + 1) for _ in range(p.integer(0, 3)))
        return f"<Transform3DGroup>{kids}</Transform3DGroup>"
    if kind == "RotateTransform3D":
        rot = p.choose(("AxisAngleRotation3D", "QuaternionRotation3D"))
        inner = f"<{rot}{named(p)}{attributes(p, rot)}/>"
        return (f"<RotateTransform3D{attributes(p, kind)}><RotateTransform3D.Rotation>{inner}"
                "</RotateTransform3D.Rotation></RotateTransform3D>")  # fmt: skip
    if kind == "Transform3DGroup":
        kind = "TranslateTransform3D"
    return f"<{kind}{named(p)}{attributes(p, kind)}/>"


def transform2d(p: Pick) -> str:
    kind = p.choose(("TranslateTransform", "ScaleTransform", "RotateTransform", "SkewTransform",
                     "MatrixTransform"))  # fmt: skip
    return f"<{kind}{named(p)}{attributes(p, kind)}/>"


def gradient_stops(p: Pick) -> str:
    return "".join(f'<GradientStop Color="{color(p)}" Offset="{number(p)}"/>'
                   for _ in range(p.integer(0, 3)))  # fmt: skip


def brush(p: Pick, depth: int = 0) -> str:
    kind = p.choose(("SolidColorBrush", "LinearGradientBrush", "RadialGradientBrush",
                     "VisualBrush", "SolidColorBrush", "ImageBrush"))  # fmt: skip
    own = attributes(p, kind, skip=("Transform", "RelativeTransform", "Visual", "ImageSource"))
    if kind == "SolidColorBrush":
        return f'<SolidColorBrush{named(p)} Color="{color(p)}"{own.replace(" Color=", " X=")}/>'
    if kind == "ImageBrush":  # a file that is not there: the reader's checker stands in
        extra = (
            f"<ImageBrush.Transform>{transform2d(p)}</ImageBrush.Transform>" if p.chance(30) else ""
        )
        return f'<ImageBrush ImageSource="absent.png"{own}>{extra}</ImageBrush>'
    if kind == "VisualBrush":
        if depth > 0 or p.chance(40):
            return f'<VisualBrush{own} Visual="{{Binding ElementName={p.choose(NAMES)}}}"/>'
        inner = visual2d(p, depth + 1)
        return f"<VisualBrush{own}><VisualBrush.Visual>{inner}</VisualBrush.Visual></VisualBrush>"
    extra = f"<{kind}.Transform>{transform2d(p)}</{kind}.Transform>" if p.chance(20) else ""
    return f"<{kind}{own}>{extra}{gradient_stops(p)}</{kind}>"


def material(p: Pick, depth: int = 0) -> str:
    kind = p.choose(("DiffuseMaterial", "SpecularMaterial", "EmissiveMaterial", "MaterialGroup"))
    if kind == "MaterialGroup" and depth == 0:
        kids = "".join(material(p, 1) for _ in range(p.integer(0, 3)))
        return f"<MaterialGroup>{kids}</MaterialGroup>"
    if kind == "MaterialGroup":
        kind = "DiffuseMaterial"
    own = attributes(p, kind, skip=("Brush",))
    return f"<{kind}{own}><{kind}.Brush>{brush(p)}</{kind}.Brush></{kind}>"


def mesh(p: Pick) -> str:
    if p.chance(60):  # a usable triangle or two, then a value replaced
        pos = "-1,-1,0 1,-1,0 1,1,0 -1,1,0"
        if p.chance(30):
            pos = " ".join([numbers(p, 3), *pos.split()[1:]])
        tc = "0,1 1,1 1,0 0,0" if p.chance(70) else value_of("point[]", p)
        idx = "0 1 2 0 2 3" if p.chance(80) else value_of("int[]", p)
        nrm = f' Normals="{value_of("vector3d[]", p)}"' if p.chance(20) else ""
        return (f'<MeshGeometry3D Positions="{pos}" TextureCoordinates="{tc}" '
                f'TriangleIndices="{idx}"{nrm}/>')  # fmt: skip
    return f"<MeshGeometry3D{attributes(p, 'MeshGeometry3D', most=4)}/>"


def model(p: Pick, depth: int = 0) -> str:
    kind = p.choose(("GeometryModel3D", "GeometryModel3D", "AmbientLight", "DirectionalLight",
                     "PointLight", "SpotLight", "Model3DGroup"))  # fmt: skip
    tf = f"<{kind}.Transform>{transform3d(p)}</{kind}.Transform>" if p.chance(35) else ""
    if kind == "Model3DGroup" and depth < 2:
        kids = "".join(model(p, depth + 1) for _ in range(p.integer(0, 3)))
        return f"<Model3DGroup{named(p)}>{tf}{kids}</Model3DGroup>"
    if kind in ("GeometryModel3D", "Model3DGroup"):
        back = (f"<GeometryModel3D.BackMaterial>{material(p)}</GeometryModel3D.BackMaterial>"
                if p.chance(15) else "")  # fmt: skip
        return (f"<GeometryModel3D{named(p)}>{tf}<GeometryModel3D.Geometry>{mesh(p)}"
                f"</GeometryModel3D.Geometry><GeometryModel3D.Material>{material(p)}"
                f"</GeometryModel3D.Material>{back}</GeometryModel3D>")  # fmt: skip
    return f"<{kind}{named(p)}{attributes(p, kind, skip=('Transform',))}>{tf}</{kind}>"


def camera(p: Pick) -> str:
    kind = p.choose(("PerspectiveCamera", "PerspectiveCamera", "OrthographicCamera",
                     "MatrixCamera"))  # fmt: skip
    base = ' Position="0,0,4" LookDirection="0,0,-1"' if kind != "MatrixCamera" else ""
    own = attributes(p, kind, skip=("Transform",))
    if " Position=" in own or " LookDirection=" in own:
        base = ""
    tf = f"<{kind}.Transform>{transform3d(p)}</{kind}.Transform>" if p.chance(15) else ""
    return f"<{kind}{named(p)}{base}{own}>{tf}</{kind}>"


FRAMEWORK_2D = ("Border", "Grid", "Viewbox", "Canvas", "StackPanel", "TextBlock", "Rectangle",
                "Ellipse", "Button", "Label")  # fmt: skip
SIZES_2D = (" Width", " Height", " MinWidth", " MaxHeight", " Opacity", " Margin",
            " BorderThickness", " CornerRadius", " FontSize", " StrokeThickness")  # fmt: skip


def attributes_2d(p: Pick) -> str:
    out = []
    for _ in range(p.integer(0, 3)):
        prop = p.choose(SIZES_2D)
        if prop in (" Margin", " BorderThickness", " CornerRadius"):
            value = numbers(p, p.choose((1, 2, 4)))
        else:
            value = number(p)
        if f'{prop}="' not in "".join(out):
            out.append(f'{prop}="{value}"')
    return "".join(out)


def visual2d(p: Pick, depth: int = 0, inner: str = "") -> str:
    """A 2D element; ``inner`` (a Viewport3D) goes inside it, which is then a container."""
    kind = p.choose(FRAMEWORK_2D[:5] if inner else FRAMEWORK_2D)
    own = named(p) + attributes_2d(p)
    parts = []
    if p.chance(25):
        parts.append(f"<{kind}.RenderTransform>{transform2d(p)}</{kind}.RenderTransform>")
    if p.chance(15):
        parts.append(f"<{kind}.OpacityMask>{brush(p, depth + 1)}</{kind}.OpacityMask>")
    if kind in ("Border", "Grid", "Canvas", "StackPanel", "Button", "Label") and p.chance(30):
        prop = "Background"
        parts.append(f"<{kind}.{prop}>{brush(p, depth + 1)}</{kind}.{prop}>")
    if kind in ("Rectangle", "Ellipse"):
        own += f' Fill="{color(p)}" Stroke="Black"'
    if kind == "TextBlock":
        own += f' Text="{p.choose(("hi", "", "ة", "𝟙", "a" * 40))}"'
    if kind == "Grid" and p.chance(30):
        widths = ("*", "1e308*", "Auto", "0*", "2*")
        cols = "".join(f'<ColumnDefinition Width="{p.choose((*widths, number(p)))}"/>'
                       for _ in range(p.integer(0, 3)))  # fmt: skip
        parts.append(f"<Grid.ColumnDefinitions>{cols}</Grid.ColumnDefinitions>")
    kids = ""
    if kind in ("Border", "Viewbox", "Button", "Label"):
        kids = inner or (visual2d(p, depth + 1) if depth < 2 and p.chance(50) else "")
    elif kind in ("Grid", "Canvas", "StackPanel"):
        kids = inner + "".join(
            visual2d(p, depth + 1) for _ in range(p.integer(0, 2 if depth < 2 else 0))
        )
    return f"<{kind}{own}>{''.join(parts)}{kids}</{kind}>"


def viewport2d_visual(p: Pick) -> str:
    return ("<Viewport2DVisual3D><Viewport2DVisual3D.Geometry>"
            '<MeshGeometry3D Positions="-1,-1,0 1,-1,0 1,1,0 -1,1,0" '
            'TextureCoordinates="0,1 1,1 1,0 0,0" TriangleIndices="0 1 2 0 2 3"/>'
            "</Viewport2DVisual3D.Geometry><Viewport2DVisual3D.Material>"
            '<DiffuseMaterial Viewport2DVisual3D.IsVisualHostMaterial="True"/>'
            f"</Viewport2DVisual3D.Material>{visual2d(p, 1)}</Viewport2DVisual3D>")  # fmt: skip


# --------------------------------------------------------------------------- storyboards

TARGETS = (("Angle", "Double"), ("OffsetX", "Double"), ("ScaleY", "Double"),
           ("Position", "Point3D"), ("LookDirection", "Vector3D"), ("FieldOfView", "Double"),
           ("Color", "Color"), ("Quaternion", "Quaternion"), ("Opacity", "Double"),
           ("Width", "Double"), ("Direction", "Vector3D"), ("Range", "Double"),
           ("(UIElement.Opacity)", "Double"), ("Rotation", "Rotation3D"))  # fmt: skip


def easing(p: Pick, owner: str) -> str:
    kind = p.choose(sorted(voc.known_types()))
    if not kind.endswith("Ease"):
        kind = p.choose(("BounceEase", "ElasticEase", "ExponentialEase", "BackEase", "PowerEase"))
    return f"<{owner}.EasingFunction><{kind}{attributes(p, kind)}/></{owner}.EasingFunction>"


def timeline_value(p: Pick, vtype: str) -> str:
    return {"Double": number(p), "Point3D": numbers(p, 3), "Vector3D": numbers(p, 3),
            "Color": color(p), "Quaternion": numbers(p, 4)}.get(vtype, number(p))  # fmt: skip


def animation(p: Pick) -> str:
    prop, vtype = p.choose(TARGETS)
    keyed = p.chance(30) and vtype != "Rotation3D"
    kind = f"{vtype}AnimationUsingKeyFrames" if keyed else f"{vtype}Animation"
    head = (f'<{kind} Storyboard.TargetName="{p.choose(NAMES)}" '
            f'Storyboard.TargetProperty="{prop}"')  # fmt: skip
    head += attributes(p, kind, skip=("From", "To", "By"))
    if keyed:
        frames = "".join(
            f"<{p.choose(('Linear', 'Discrete', 'Spline', 'Easing'))}{vtype}KeyFrame "
            f'KeyTime="{value_of("keytime", p)}" Value="{timeline_value(p, vtype)}"/>'
            for _ in range(p.integer(0, 3))
        )
        return f"{head}>{frames}</{kind}>"
    if vtype == "Rotation3D":
        return (f'{head}><{kind}.To><AxisAngleRotation3D Axis="{numbers(p, 3)}" '
                f'Angle="{number(p)}"/></{kind}.To></{kind}>')  # fmt: skip
    ends = "".join(f' {e}="{timeline_value(p, vtype)}"' for e in ("From", "To", "By")
                   if p.chance(50))  # fmt: skip
    ease = easing(p, kind) if p.chance(40) else ""
    return f"{head}{ends}>{ease}</{kind}>"


def timeline(p: Pick, depth: int) -> str:
    if depth < 6 and p.chance(25):
        kind = p.choose(("ParallelTimeline", "Storyboard"))
        kids = "".join(timeline(p, depth + 1) for _ in range(p.integer(0, 2)))
        return f"<{kind}{attributes(p, kind)}>{kids}</{kind}>"
    return animation(p)


def triggers(p: Pick, owner: str) -> str:
    body = "".join(timeline(p, 1) for _ in range(p.integer(1, 3)))
    sb = f"<Storyboard{attributes(p, 'Storyboard')}>{body}</Storyboard>"
    return (f'<{owner}.Triggers><EventTrigger RoutedEvent="{owner}.Loaded"><BeginStoryboard>'
            f"{sb}</BeginStoryboard></EventTrigger></{owner}.Triggers>")  # fmt: skip


# --------------------------------------------------------------------------- the document


def viewport3d(p: Pick, ns: str = "") -> str:
    size = (f' Width="{p.choose(("40", "40", number(p)))}" '
            f'Height="{p.choose(("30", "30", number(p)))}"')  # fmt: skip
    cam = f"<Viewport3D.Camera>{camera(p)}</Viewport3D.Camera>" if p.chance(90) else ""
    models = "".join(model(p) for _ in range(p.integer(1, 4)))
    content = (f"<ModelVisual3D{named(p)}><ModelVisual3D.Content><Model3DGroup>{models}"
               "</Model3DGroup></ModelVisual3D.Content></ModelVisual3D>")  # fmt: skip
    v2d = viewport2d_visual(p) if p.chance(20) else ""
    anim = triggers(p, "Viewport3D") if p.chance(60) else ""
    return f"<Viewport3D{ns}{named(p)}{size}>{cam}{content}{v2d}{anim}</Viewport3D>"


def document(p: Pick) -> str:
    """One XAML document (see module docstring)."""
    if p.chance(60):
        return viewport3d(p, " " + NS)
    size = f' Width="{p.choose(("60", "60", number(p)))}" Height="45"'
    return f"<Grid {NS}{size}>{visual2d(p, 1, inner=viewport3d(p))}</Grid>"


# --------------------------------------------------------------------------- the pipeline


def run_document(text: str) -> None:
    """``text`` through load, validate, a render at a moment of its storyboards, the window,
    the glTF export and animate's frame count (see module docstring)."""
    from xaml3d.animation.timeline import one_cycle
    from xaml3d.api import render_arrays
    from xaml3d.errors import XamlError
    from xaml3d.export import export_bytes
    from xaml3d.findings import scene_findings
    from xaml3d.pipeline import load
    from xaml3d.render.frames import frame_count
    from xaml3d.render.window import compose_window

    try:
        scene = load(text.encode("utf-8"), text=True)
    except XamlError:
        return  # refused cleanly: file:line:col: error CODE message
    for d in scene_findings(scene):
        assert d.code and d.severity in ("error", "warning", "info"), d
    length = one_cycle(scene)
    frame_count(0.0, length if length > 0 else 1.0, 30.0)
    for t in (0.0, min(length, 1e9) * 0.37 if length == length else 0.5):
        for vp in scene.viewports[:2]:
            try:
                render_arrays(scene, 16, 12, viewport=vp.index, ssaa=1, time=t)
            except XamlError:
                pass  # a camera WPF cannot draw with: a clean error
    if scene.layout is not None and scene.layout.boxes:
        try:
            compose_window(scene, ssaa=1, time=0.5, max_size=256)
        except XamlError:
            pass
    if scene.viewports:
        try:
            export_bytes(scene, "glb")
        except XamlError:
            pass
