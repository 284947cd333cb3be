"""From storyboards to the Scene's animation tracks, once per load (``xaml3d.scene.tracks``).

Before the viewports are built, every animation's target is resolved to a (markup element,
property) pair (animation_targets.py, with its ANIM diagnostics) and each distinct pair becomes
a track index ("slot"). While the viewports are built, the reader notes which slots it reads
(``Slots.read``) and which scene objects hold their values (``Slots.tag``: a camera, light,
material pass, brush or gradient stop built from the animated element; ``Slots.world``: a
matrix made from an animated transform, with its chain). ``tracks`` then walks the built
viewports once and turns each tagged object into the paths where it lands.

A slot read while building but held by no scene object is a property xaml3d evaluates only at
load: a panel's or Viewport3D's size, a LayoutTransform (the layout is done once), a shape's
Opacity. So is a slot held only by objects the walk does not reach (a shape's or text's brush in
the window's 2D drawings). WPF would show it change; ANIM014 says that xaml3d draws its value
at load instead. A laid-out box's Background and BorderBrush are tracks (``render --window``).
A Viewport3D's own RenderTransform and Opacity are tracks (its picture's ``render_transform``
and ``opacity``), and so are those of a laid-out element around it: its ``Around`` layer in each
viewport's picture it encloses and its ``Box.layer`` in the Scene's layout (``render
--window``).

What runs (storyboard checks): ANIM007 for a storyboard no trigger begins or whose BeginTime
is {x:Null}, ANIM008 for an animation whose BeginTime is {x:Null}.
"""

from __future__ import annotations

from typing import NamedTuple

from xaml3d.errors import Diagnostic
from xaml3d.scene.tracks import ScenePath, Track, Tracks, WorldChain
from xaml3d.scene.types import Animation, Storyboard, Viewport
from xaml3d.xaml.animation_targets import ANIM_CODES, Target, TargetError, name_map, resolve


class _At(NamedTuple):
    """A place in the file (what ``Resolution.diag`` needs of a scene object)."""

    line: int | None
    column: int | None


class Slots:
    """The animated (element, property) pairs of a load and what the build did with them."""

    def __init__(self) -> None:
        self.by_key: dict[tuple[int, str], list[tuple[str | None, int]]] = {}
        self.targets: list[Target] = []
        self._index: dict[tuple, int] = {}  # Target.key -> its slot
        self.animations: list[list[Animation]] = []
        self.read: set[int] = set()
        self.placed: set[int] = set()
        # id(scene object) -> (object, [(field, slot)]): the object kept, so its id stays its own
        self.tags: dict[int, tuple[object, list[tuple[str, int]]]] = {}
        self.worlds: dict[int, tuple[object, list[tuple[str, WorldChain]]]] = {}

    def add(self, target: Target, anim: Animation) -> None:
        k = self._index.get(target.key)
        if k is not None:
            self.animations[k].append(anim)
            return
        k = self._index[target.key] = len(self.targets)
        self.targets.append(target)
        self.animations.append([anim])
        self.by_key.setdefault((id(target.element), target.prop), []).append((target.field, k))

    def of(self, el, prop: str) -> list[tuple[str | None, int]]:
        return self.by_key.get((id(el), prop), [])

    def tag(self, obj, pairs: list[tuple[str, int]]) -> None:
        if not pairs or obj is None:
            return
        self.placed.update(s for _, s in pairs)
        self.tags.setdefault(id(obj), (obj, []))[1].extend(pairs)

    def world(self, obj, field: str, chain: WorldChain) -> None:
        self.placed.update(chain.slots)
        self.worlds.setdefault(id(obj), (obj, []))[1].append((field, chain))


def built(pair):
    """A (value, typed node) pair as a property's built object: None when there is no value,
    as the plain value would be (so Props sees an unreadable object as before)."""
    return None if pair is None or pair[0] is None else pair


def node_of(r, el, cls, values: dict, *, place: bool = True, **parts):
    """The typed node (scene.tracks) of a transform built from ``el`` when one of its own
    properties (``values``: field -> (XAML property, value)) or one of its ``parts`` (inner
    nodes) animates, else None. ``place``: its slots count as drawn (a 3D transform lands in
    the Scene through the models under it, or moves nothing drawn; a 2D one counts where a
    brush holds it)."""
    s = r.slots
    if s is None:
        return None
    slots = tuple(
        (field, k) for field, (prop, _) in values.items() for f, k in s.of(el, prop) if f is None
    )
    if not slots and all(v is None for v in parts.values()):
        return None
    if place:
        s.placed.update(k for _, k in slots)
    return cls(**{**{f: v for f, (_, v) in values.items()}, **parts}, slots=slots)


def group_of(r, p, read, cls, compose):
    """A transform group (Transform3DGroup, TransformGroup): its children read by ``read``
    (each a (matrix, node) pair; unreadable ones left out), the matrix ``compose`` makes of
    theirs, and its typed node ``cls`` when a child animates (else None)."""
    parts = [
        r.build_node(k, lambda e: read(r, e), None) or (None, None) for k in p.items("Children")
    ]
    kept = [(m, n) for m, n in parts if m is not None]
    node = None
    if any(n is not None for _, n in kept):
        node = cls(tuple(m if n is None else n for m, n in kept))
    return compose(*[m for m, _ in kept]), node


# --------------------------------------------------------------------------- resolution


class Resolution:
    """Targets of a document's storyboards and the diagnostics about them."""

    def __init__(self, file) -> None:
        self.file = file
        self.diagnostics: list[Diagnostic] = []
        self.slots = Slots()
        # id(animation) -> what its target is called when it names none (its storyboard's owner)
        self.owners: dict[int, str] = {}

    def label(self, a: Animation) -> str:
        """``name.Property``: the animation's TargetName, else its storyboard's owner."""
        return f"{a.target_name or self.owners.get(id(a))}.{a.target_property}"

    def diag(self, code: str, message: str, where) -> None:
        sev = ANIM_CODES[code][0]
        self.diagnostics.append(Diagnostic(code, sev, message, self.file, where.line, where.column))


def resolve_targets(
    r, root, storyboards: list[Storyboard], file, hosts: dict | None = None, *, library=False
) -> Resolution:
    """Resolve every animation's target with the reader ``r`` (a reader of its own: what its
    lookups report is reported again, or was already, by the build). ``hosts``: id(storyboard)
    -> the element whose trigger begins it, the target of animations that name none.
    ``library``: the document is a resource dictionary (or an Application) read on its own:
    its storyboards are begun by the scenes that use it, on their elements, so a name it does
    not hold, a missing TargetName and no trigger are not findings (ANIM001, ANIM005, ANIM007)."""
    res = Resolution(file)
    names = name_map(root)
    ctx = r.ctx
    with ctx.muted():  # lookups repeat what the build reports
        for sb in storyboards:
            if not library:
                _check_start(res, sb)
            host = (hosts or {}).get(id(sb))
            for a in sb.animations:
                if sb.owner is not None and not a.target_name:
                    res.owners[id(a)] = sb.owner
                target = _resolve(res, r, names, a, host, library)
                if target is not None:
                    res.slots.add(target, a)
                if a.begin_time is None:
                    res.diag("ANIM008", f"{a.type} has BeginTime {{x:Null}}: it never begins", a)
    return res


def _check_start(res: Resolution, sb: Storyboard) -> None:
    label = f"storyboard {sb.name!r}" if sb.name else "a storyboard"
    if sb.trigger is None:
        msg = f"{label} is in resources but no trigger begins it (--storyboard starts it)"
        res.diag("ANIM007", msg, sb)
    elif sb.root is not None and sb.root.timing.begin_time is None:
        res.diag("ANIM007", f"{label} has BeginTime {{x:Null}}: it never starts", sb)


def _resolve(res: Resolution, r, names, a: Animation, host, library=False) -> Target | None:
    if not a.evaluated:
        return None
    try:
        return resolve(r, names, a.target_name, a.target_property, a.value_type, host)
    except TargetError as exc:
        if library and (exc.code == "ANIM001" or (exc.code == "ANIM005" and a.target_property)):
            return None  # the target is in the scene that will use the dictionary
        what = f"{a.type} -> {res.label(a)}"
        where = a
        if exc.code == "ANIM001" and a.target_name_at is not None:
            where = _At(*a.target_name_at)  # the Storyboard.TargetName attribute
        elif exc.code == "ANIM002" and a.target_property_at is not None:
            where = _At(*a.target_property_at)  # the Storyboard.TargetProperty attribute
        res.diag(exc.code, f"{what}: {exc.message}", where)
        return None


# --------------------------------------------------------------------------- the tracks

# properties the layout reads: xaml3d lays the window out once, at load
_LAID_OUT = frozenset({
    "Width", "Height", "MinWidth", "MinHeight", "MaxWidth", "MaxHeight", "Margin", "Padding",
    "BorderThickness", "LayoutTransform", "HorizontalAlignment", "VerticalAlignment",
    "Visibility", "FontSize",
})  # fmt: skip


def at_load(a: Animation, label: str, target: Target, held: bool) -> str:
    """ANIM014's message: the picture shows the property's value at load, and why."""
    tag = getattr(target.element, "tag", "")
    owner = tag.rpartition("}")[2] if isinstance(tag, str) else ""
    what = f"{owner}.{target.prop}" if owner else target.prop
    if "." in target.prop:  # an attached property: (Canvas.Left) of a Rectangle
        what = f"{owner}'s {target.prop}" if owner else target.prop
    if target.field is not None:  # a brush made from a colour string: its Color or Opacity
        what = f"{what} ({target.field})"
    if not held and (target.prop in _LAID_OUT or "." in target.prop):  # or (Canvas.Left)
        why = "xaml3d lays the window out once, at load"
    else:
        why = "it is not a track of the scene, so xaml3d draws it once, at load"
    return (
        f"{a.type} -> {label}: the picture shows {what} at its value at load, not animated: {why}"
    )


def tracks(res: Resolution, viewports: tuple[Viewport, ...], layout=None) -> Tracks:
    """The tracks of the built viewports and of the laid-out boxes (``layout``, the Scene's
    WindowLayout or None); ANIM014 for slots read but held by no scene object."""
    slots = res.slots
    paths: list[list[ScenePath]] = [[] for _ in slots.targets]
    worlds: list[WorldChain] = []

    reached: set[int] = set()  # id() of the scene objects the walk visits

    def visit(obj, vi: int, steps: tuple) -> None:
        reached.add(id(obj))
        hit = slots.tags.get(id(obj))
        if hit is not None and hit[0] is obj:
            for field, slot in hit[1]:
                paths[slot].append(ScenePath(vi, steps, field))
        w = slots.worlds.get(id(obj))
        if w is not None and w[0] is obj:
            for field, chain in w[1]:
                worlds.append(WorldChain(ScenePath(vi, steps, field), chain.prefix,
                                         chain.factors, chain.slots))  # fmt: skip

    def visit_brush(brush, vi: int, steps: tuple) -> None:
        visit(brush, vi, steps)
        for si, stop in enumerate(getattr(brush, "stops", ())):
            visit(stop, vi, (*steps, ("stops", si)))
        # a DrawingBrush (or a VisualBrush turned into a drawing) is drawn again in every
        # frame, so the brushes its drawing paints with animate as WPF animates them
        if getattr(brush, "drawing", None) is not None:
            visit_drawing(brush.drawing, vi, (*steps, ("drawing", None)))

    def visit_drawing(drawing, vi: int, steps: tuple) -> None:
        visit(drawing, vi, steps)
        for ci, child in enumerate(getattr(drawing, "children", ())):
            visit_drawing(child, vi, (*steps, ("children", ci)))
        for side in ("brush", "opacity_mask"):
            if getattr(drawing, side, None) is not None:
                visit_brush(getattr(drawing, side), vi, (*steps, (side, None)))
        pen = getattr(drawing, "pen", None)
        if pen is not None:
            visit(pen, vi, (*steps, ("pen", None)))
            if pen.brush is not None:
                visit_brush(pen.brush, vi, (*steps, ("pen", None), ("brush", None)))

    for vi, vp in enumerate(viewports):
        if vp.camera is not None:
            visit(vp.camera, vi, (("camera", None),))
        for li, light in enumerate(vp.lights):
            visit(light, vi, (("lights", li),))
        for mi, model in enumerate(vp.models):
            visit(model, vi, (("models", mi),))
            for side in ("material", "back_material"):
                for pi, ps in enumerate(getattr(model, side)):
                    steps = (("models", mi), (side, pi))
                    visit(ps, vi, steps)
                    if ps.brush is not None:
                        visit_brush(ps.brush, vi, (*steps, ("brush", None)))
        if vp.background is not None:
            visit_brush(vp.background, vi, (("background", None),))
        if vp.picture is not None:  # an animated RenderTransform or Opacity of the viewport
            visit(vp.picture, vi, (("picture", None),))
            # and of the elements around it, as they act on its picture
            for ai, a in enumerate(vp.picture.around):
                visit(a.layer, vi, (("picture", None), ("around", ai), ("layer", None)))
    # the elements' layers that render --window composes (ScenePath.viewport None: the layout)
    for bi, box in enumerate(layout.boxes if layout is not None else ()):
        if box.layer is not None:
            visit(box.layer, None, (("boxes", bi), ("layer", None)))
        # a panel's or Border's Background and BorderBrush, which the window paints itself
        for side in ("background", "border_brush"):
            if getattr(box, side) is not None:
                visit_brush(getattr(box, side), None, (("boxes", bi), (side, None)))

    moves: list[list[ScenePath]] = [[] for _ in slots.targets]
    for chain in worlds:
        for k in sorted(chain.slots):
            moves[k].append(chain.path)
    # the slots of tagged objects the walk above did not reach: a brush or layer of the 2D
    # picture (drawn once, at load) rather than of a viewport or a laid-out box's layer
    unfollowed = {
        k for obj, pairs in slots.tags.values() if id(obj) not in reached for _, k in pairs
    } | {
        k for obj, pairs in slots.worlds.values() if id(obj) not in reached
        for _, chain in pairs for k in chain.slots
    }  # fmt: skip
    unfollowed -= {k for k, m in enumerate(moves) if m}
    out = []
    for k, (target, anims) in enumerate(zip(slots.targets, slots.animations, strict=True)):
        first = anims[0]
        label = res.label(first)
        # read but held by no scene object (a size, a LayoutTransform), or held by one that
        # no frame evaluates again (a shape's brush in the window's 2D drawings)
        held = k in slots.placed
        # an attached layout property ((Canvas.Left) ...): the layout reads it, once
        attached = "." in target.prop and not held
        if (
            (k in slots.read and not held)
            or attached
            or (held and k in unfollowed and not paths[k])
        ):
            for a in anims:
                res.diag("ANIM014", at_load(a, label, target, held), a)
        out.append(Track(label, first.value_type, tuple(anims), tuple(paths[k]),
                         tuple(moves[k]), first.line, first.column))  # fmt: skip
    return Tracks(tuple(out), tuple(worlds))
