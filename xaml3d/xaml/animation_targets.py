"""Resolving what an animation animates: Storyboard.TargetName + TargetProperty -> (markup
element, property), once per load (wpf3d.md section 8).

TargetName is an x:Name / Name anywhere in the document (resources included: WPF's name scope
of a window reaches them); without one, the path starts at the element whose
``<X.Triggers>`` begins the storyboard (WPF's containing object, e.g. the Viewport3D:
``(Viewport3D.Camera).(PerspectiveCamera.FieldOfView)``; a framework container's content
children are its Content, Child or Children). TargetProperty is a property path: a simple
name (``Angle``), an owner-qualified chain such as
``(ModelVisual3D.Transform).(RotateTransform3D.Rotation).(AxisAngleRotation3D.Angle)``,
dotted names (``Transform.Rotation.Angle``), indexers into collections
(``(Transform3DGroup.Children)[1]``, ``Children[0]``). Each step but the last must lead to an
object written as an element (or a ``{StaticResource}``), or be a brush made from a colour
string (``Brush="Red"``): WPF's storyboard animates a copy of such a frozen brush, so its Color
or Opacity animates (the target is then that field of the built brush); any other object made
from a string cannot be animated. The last step must be a property
of the element's type whose value type is the animation's (a DoubleAnimation on a Point3D
property is WPF's error). Problems are ANIM codes, reported by ``validate``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from xaml3d.codes.animation import ANIM_CODES  # noqa: F401 (the stage's table)
from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.context import (
    a_an,
    element_name,
    is_presentation,
    markup_key,
    qname,
    split_markup,
)

# the value kind (vocabulary) each animation value type may target
_KINDS = {
    "Double": ("double",),
    "Point3D": ("point3d",),
    "Vector3D": ("vector3d",),
    "Quaternion": ("quaternion",),
    "Rotation3D": ("rotation3d",),
    "Color": ("color",),
    "Point": ("point",),
    "Size": ("size",),
}
# Attached properties of the panels that a Double animation may drive (Canvas's offsets: WPF
# moves the element within its Canvas); the path names them "(Canvas.Left)" on any element
_ATTACHED_KINDS = {
    ("Canvas", "Left"): "double",
    ("Canvas", "Top"): "double",
    ("Canvas", "Right"): "double",
    ("Canvas", "Bottom"): "double",
}
_STEP = re.compile(r"\s*(?:\(\s*([\w.:]+)\s*\)|([\w]+))\s*((?:\[\s*\d+\s*\])*)")


@dataclass(frozen=True)
class Target:
    """A resolved target: the element whose property is animated, and the property."""

    element: object  # lxml element (kept alive: overrides are keyed by its id)
    prop: str
    kind: str  # the property's value kind in the vocabulary
    field: str | None = None  # a field of the object the property holds (a string-made brush)

    @property
    def key(self) -> tuple[int, str, str | None]:
        return (id(self.element), self.prop, self.field)


class TargetError(Exception):
    def __init__(self, code: str, message: str) -> None:
        super().__init__(message)
        self.code = code
        self.message = message


def parse_path(path: str) -> list[tuple[str, str | None, list[int]]]:
    """``(Owner.Prop)[1].Prop2`` -> [(prop, owner, [indices]), ...]."""
    steps = []
    pos = 0
    s = path.strip()
    while pos < len(s):
        m = _STEP.match(s, pos)
        if not m or m.end() == pos:
            raise TargetError("ANIM002", f"property path {path!r} cannot be read")
        name = m.group(1) or m.group(2)
        owner, _, prop = name.rpartition(".")
        owner = owner.split(":")[-1] or None
        idx = [int(x) for x in re.findall(r"\d+", m.group(3))]
        steps.append((prop, owner, idx))
        pos = m.end()
        if pos < len(s):
            if s[pos] != ".":
                raise TargetError("ANIM002", f"property path {path!r} cannot be read")
            pos += 1
    if not steps:
        raise TargetError("ANIM002", "empty property path")
    return steps


def name_map(root) -> dict[str, object]:
    """x:Name / Name -> element, first in document order."""
    out: dict[str, object] = {}
    for el in root.iter():
        # elements of other assemblies (clr-namespace) are in the namescope too
        if isinstance(el.tag, str):
            n = element_name(el)
            if n and n not in out:
                out[n] = el
    return out


def _follow(r, el):
    """An element standing for a <StaticResource ResourceKey=.../>: the entry it names."""
    if isinstance(el.tag, str) and qname(el.tag)[1] in ("StaticResource", "DynamicResource"):
        key = el.get("ResourceKey")
        entry = r.resources.lookup(key, el, dynamic=False) if key else None
        if entry is None:
            raise TargetError("ANIM002", f"resource {key!r} not found on the path")
        return entry
    return el


_STRING_BRUSH_FIELDS = {"Color": ("color", "color"), "Opacity": ("opacity", "double")}


def _string_brush(el, prop: str, rest: list, vtype: str) -> Target | None:
    """``Brush="Red"`` then ``(SolidColorBrush.Color)`` / ``Opacity``: that field of the brush."""
    if len(rest) != 1 or rest[0][2]:
        return None
    name, owner, _ = rest[0]
    if owner not in (None, "SolidColorBrush", "Brush") or name not in _STRING_BRUSH_FIELDS:
        return None
    field, kind = _STRING_BRUSH_FIELDS[name]
    if kind not in _KINDS.get(vtype, ()):
        raise TargetError("ANIM003", f"{vtype} animation on SolidColorBrush.{name}, {a_an(kind)}")
    return Target(el, prop, kind, field)


# WPF's content property of the framework containers a trigger's path may start from (the
# vocabulary keeps these types open, without a content property): their child elements are
# that property's value ("(Window.Content).(Grid.Children)[0]...")
_FRAMEWORK_CONTENT = {
    **dict.fromkeys(
        "Window Page UserControl ContentControl Button ToggleButton RepeatButton Label "
        "ScrollViewer GroupBox Expander TabItem HeaderedContentControl Frame ToolTip "
        "NavigationWindow ContentPresenter".split(),
        "Content",
    ),
    **dict.fromkeys("Border Viewbox Decorator AdornerDecorator".split(), "Child"),
    **dict.fromkeys("Grid Canvas StackPanel DockPanel WrapPanel UniformGrid".split(), "Children"),
}


def _step_objects(r, el, prop: str) -> list:
    p = r.props(el)
    if prop not in p.elems and prop not in p.attrs and _FRAMEWORK_CONTENT.get(p.type) == prop:
        return [_follow(r, k) for k in p.content]
    if prop in p.attrs:
        m = split_markup(p.attrs[prop])
        if m is not None and m[0] in ("StaticResource", "DynamicResource"):
            entry = r.resources.lookup(markup_key(m[1]), el, dynamic=False)
            if entry is None:
                raise TargetError("ANIM002", f"{p.type}.{prop}: its resource is not found")
            return [entry]
        raise TargetError(
            "ANIM004", f"{p.type}.{prop} is made from the string {p.attrs[prop]!r}: frozen"
        )
    return [_follow(r, k) for k in p.items(prop)]


def resolve(
    r, names: dict, target_name: str | None, path: str | None, vtype: str, host=None
) -> Target:
    """Resolve one animation's target (raises TargetError). Without a TargetName the path
    starts at ``host``, the element whose trigger begins the storyboard (WPF's Storyboard
    takes its containing object then); with no host either (a storyboard no trigger begins,
    which code would begin) there is nothing to start from."""
    if not path:
        raise TargetError("ANIM005", "no Storyboard.TargetProperty")
    if not target_name and host is None:
        raise TargetError(
            "ANIM005",
            "no Storyboard.TargetName, and no trigger begins its storyboard (the element that "
            "code would begin it on is unknown)",
        )
    el = names.get(target_name) if target_name else host
    if el is None:
        hint = voc.did_you_mean(target_name, names) if target_name else ""
        raise TargetError("ANIM001", f"Storyboard.TargetName {target_name!r} names no object{hint}")
    steps = parse_path(path)
    for n, (prop, _owner, indices) in enumerate(steps):
        if not is_presentation(qname(el.tag)[0]):
            # WPF animates it through that assembly's own properties, which xaml3d cannot see
            shown = f"{el.prefix}:{qname(el.tag)[1]}" if el.prefix else qname(el.tag)[1]
            raise TargetError(
                "ANIM020", f"{shown} is a type of another assembly: its animation is not evaluated"
            )
        et = voc.lookup(qname(el.tag)[1])
        tname = qname(el.tag)[1]
        attached = _ATTACHED_KINDS.get((_owner, prop)) if _owner != tname else None
        if attached is not None and n == len(steps) - 1 and not indices:
            if attached not in _KINDS.get(vtype, ()):
                raise TargetError(
                    "ANIM003", f"{vtype} animation on {_owner}.{prop}, {a_an(attached)} property"
                )
            return Target(el, f"{_owner}.{prop}", attached)
        if et is None or (not et.open and prop not in et.properties):
            hint = "" if et is None else voc.did_you_mean(prop, et.properties)
            raise TargetError("ANIM002", f"{tname} has no property {prop!r}{hint} (path {path!r})")
        last = n == len(steps) - 1
        if last and not indices:
            kind = et.property_kind(prop)
            if kind is None and et.kind == "framework":  # a panel's or control's UIElement part
                kind = voc.UI_PROPS.get(prop)
            kind = kind or "object"
            if kind not in _KINDS.get(vtype, ()):
                raise TargetError(
                    "ANIM003",
                    f"{vtype} animation on {tname}.{prop}, {a_an(kind)} property",
                )
            return Target(el, prop, kind)
        if not indices and (et.property_kind(prop) or "").startswith("brush"):
            attr = r.props(el).attrs.get(prop)
            if attr is not None and split_markup(attr) is None:
                hit = _string_brush(el, prop, steps[n + 1 :], vtype)
                if hit is not None:
                    return hit
        objs = _step_objects(r, el, prop)
        if indices:
            i = indices[0]
            if i >= len(objs):
                raise TargetError(
                    "ANIM002", f"{tname}.{prop}[{i}]: the collection has {len(objs)} items"
                )
            el = objs[i]
        elif objs:
            el = objs[-1]
        else:
            raise TargetError("ANIM002", f"{tname}.{prop} is not set: nothing to animate in it")
        if last:
            raise TargetError("ANIM003", f"{path!r} ends at an object, not {a_an(vtype)} value")
    raise TargetError("ANIM002", f"property path {path!r} cannot be read")
