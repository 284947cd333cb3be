"""Building the normalized Scene from a parsed XAML tree (architecture: markup -> Scene).

Covers finding every Viewport3D (in document order, whatever the root: Window, Page,
UserControl, a custom control, a bare Viewport3D; those the framework step instantiated from
a control's template or an item's DataTemplate too, not those of templates and styles nothing
applies), the
viewport's size and rectangle from WPF's layout of the panels around it (layout_step.py,
docs/layout.md), camera (WPF's default PerspectiveCamera when none is given), background (the
nearest laid-out ancestor's Background brush) and ClipToBounds; the model tree flattened in
draw order (ModelVisual3D: Content before Children) with each model's and light's world matrix
(p_world = p_local * M_model * M_group... * M_visual... in WPF row terms); ModelUIElement3D,
ContainerUIElement3D and Viewport2DVisual3D (a placeholder brush); and the storyboards, read
before the viewports so that the build notes where what they animate lands (the Scene's
animation tracks, animation_tracks.py).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from xaml3d.scene import transforms as T
from xaml3d.scene.tracks import WorldChain, slots_in
from xaml3d.scene.types import (
    Model,
    PerspectiveCamera,
    Scene,
    Viewport,
)
from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.animation_reader import read_storyboard, read_trigger
from xaml3d.xaml.animation_tracks import Slots, resolve_targets, tracks
from xaml3d.xaml.brushes_reader import material
from xaml3d.xaml.content_check import check_content
from xaml3d.xaml.context import (
    ReadContext,
    a_an,
    element_name,
    is_presentation,
    markup_key,
    namespace_typo,
    qname,
    split_markup,
    x_attr,
)
from xaml3d.xaml.directives import check_directives
from xaml3d.xaml.framework_check import check_framework
from xaml3d.xaml.layout_step import lay_out, unreached
from xaml3d.xaml.models_reader import LIGHT_TYPES, camera, light, mesh, world_of
from xaml3d.xaml.names import check_names
from xaml3d.xaml.panels_reader import element_style, style_value_element
from xaml3d.xaml.parser import PRESENTATION_NS, XAML_NS, ParsedDocument
from xaml3d.xaml.props import Props
from xaml3d.xaml.resource_check import check_dictionary
from xaml3d.xaml.resources import Resources
from xaml3d.xaml.styles_check import check_styles
from xaml3d.xaml.values import parse_bool
from xaml3d.xaml.wpf_types import NAMES as WPF_TYPES

_TEMPLATES = {"Style", "ControlTemplate", "DataTemplate", "ItemsPanelTemplate",
              "ItemContainerTemplate", "HierarchicalDataTemplate"}  # fmt: skip
_REFERENCE = {"StaticResource", "DynamicResource"}
# the root types of a file of 3D content without a viewport (SCN013, not SCN001)
_FRAGMENT_KINDS = {"visual3d", "model3d", "light", "geometry", "material", "transform3d"}


def no_namespace(local: str) -> str:
    """XAML021's message: an element without an XML namespace (its xmlns is missing)."""
    return (f"element {local!r} has no XML namespace: WPF cannot resolve its type; "
            f'add xmlns="{PRESENTATION_NS}" to the root element')  # fmt: skip


class Reader:
    """Builds scene objects from elements: property access, references, dispatch."""

    def __init__(self, ctx: ReadContext, resources: Resources) -> None:
        self.ctx = ctx
        self.resources = resources
        self._props: dict[int, Props] = {}
        # the properties the storyboards animate (animation_tracks.Slots), None when none:
        # the build notes where their values land in the Scene
        self.slots: Slots | None = None
        # what is built once however often it is used (a mesh, material or image resource
        # shared by thousands of models)
        self.cache: dict = {}

    def read(self, el, prop: str) -> None:
        """``el``'s property ``prop`` has been read (an animated one must land in the Scene)."""
        s = self.slots
        if s is not None:
            for _, k in s.of(el, prop):
                s.read.add(k)

    def tag(self, obj, el, fields: dict[str, str]):
        """``obj``, a scene object built from ``el``, holds ``el``'s properties ``fields``
        (XAML property -> field of ``obj``): note those that animate. Returns ``obj``."""
        s = self.slots
        if s is not None and obj is not None:
            s.tag(obj, [(field, k) for prop, field in fields.items() if hasattr(obj, field)
                        for f, k in s.of(el, prop) if f is None])  # fmt: skip
        return obj

    def world(self, obj, field: str, prefix, factors: tuple):
        """``obj``'s matrix ``field`` is the product of a chain an animation moves: noted.
        Returns ``obj``."""
        if self.slots is not None:
            slots = frozenset().union(*(slots_in(f) for f in factors))
            self.slots.world(obj, field, WorldChain(None, prefix, factors, slots))
        return obj

    # The 2D readers recurse through each other (a brush holds a drawing, a drawing a visual,
    # a visual's Background a brush): they reach the reader of a nested element through these
    # methods, so that no reader module imports one above it. The 2D readers are imported
    # when a document first has 2D content: a 3D scene does not load them.

    def drawing(self, el):
        """The scene Drawing of a Drawing element (``drawings_reader.drawing``)."""
        from xaml3d.xaml.drawings_reader import drawing

        return drawing(self, el)

    def drawing_brush(self, p: Props, common: dict):
        """A DrawingBrush or VisualBrush (``drawings_reader.drawing_brush``)."""
        from xaml3d.xaml.drawings_reader import drawing_brush

        return drawing_brush(self, p, common)

    def visual_drawing(self, el):
        """(Drawing, bounds) of a visual laid out at its desired size
        (``visuals_reader.visual_drawing``)."""
        from xaml3d.xaml.visuals_reader import visual_drawing

        return visual_drawing(self, el)

    def props(self, el) -> Props:
        """The element's properties (read once: diagnostics are not repeated on reuse)."""
        hit = self._props.get(id(el))
        if hit is None or hit.el is not el:
            hit = Props(self, self.ctx.keep(el))
            self._props[id(el)] = hit
        return hit

    def build_node(self, el, build, default=None):
        """Build a child element, following ``<StaticResource ResourceKey=.../>`` elements and
        skipping (with one diagnostic) elements of unknown namespaces."""
        ns, local = qname(el.tag)
        if not is_presentation(ns):
            wpf = namespace_typo(ns)
            if ns is None:
                self.ctx.diag("XAML021", no_namespace(local), el, once="no namespace")
            elif wpf is not None:
                msg = f"namespace {ns!r} is not WPF's (did you mean {wpf!r}?): {local!r} skipped"
                self.ctx.diag("XAML018", msg, el)
            else:
                self.ctx.diag("XAML001", f"element {local!r} from namespace {ns!r} skipped", el)
            return default
        if local in _REFERENCE:
            key = el.get("ResourceKey")
            if key is None:
                self.ctx.diag("RES001", f"<{local}> without ResourceKey", el)
                return default
            dynamic = local == "DynamicResource"
            entry = self.resources.lookup(key, el, dynamic=dynamic, attr="ResourceKey")
            if entry is None:
                return default
            return self.build_resource(entry, build, default, el, "ResourceKey")
        et = voc.lookup(local)
        if et is None:
            hint = voc.did_you_mean(local, voc.known_types())
            self.ctx.diag("XAML003", f"unknown element {local!r}{hint}: skipped", el)
            return default
        return build(el)

    def build_resource(self, entry, build, default, ref_el, attr=None):
        """Build a resource entry referred to from ``ref_el`` (its attribute ``attr``)."""
        if not self.ctx.enter_building(entry):
            key = x_attr(entry, "Key")
            msg = f"resource {key!r} refers to itself (cycle)"
            self.ctx.diag("RES003", msg, ref_el, attr=attr)
            return default
        try:
            return self.build_node(entry, build, default)
        finally:
            self.ctx.leave_building()


class _Acc:
    def __init__(self) -> None:
        self.models: list[Model] = []
        self.lights: list = []


# --------------------------------------------------------------------------- 3D tree


def walk_model3d(r: Reader, el, parent: np.ndarray, acc: _Acc, chain=None) -> None:
    """A Model3D under ``parent`` (its world matrix; ``chain``: that matrix's chain when an
    animated transform is above, else None)."""
    p = r.props(el)
    t = p.type
    if t == "Model3DGroup":
        world, chain = world_of(r, p, parent, chain)
        for k in p.items("Children"):
            r.build_node(k, lambda e: walk_model3d(r, e, world, acc, chain))
    elif t == "GeometryModel3D":
        _geometry_model(r, p, parent, acc, chain)
    elif t in LIGHT_TYPES:
        acc.lights.append(light(r, el, parent, chain))
    else:
        r.ctx.diag("SCN008", f"{t} is not a Model3D: skipped", el)


def _geometry_model(r: Reader, p: Props, parent: np.ndarray, acc: _Acc, chain) -> None:
    el = p.el
    if not p.has("Geometry"):
        r.ctx.diag("SCN005", "GeometryModel3D without Geometry: skipped", el)
        return
    m = p.obj("Geometry", lambda e: mesh(r, e), None)
    if m is None:
        return
    mat = p.obj("Material", lambda e: material(r, e), ())
    back = p.obj("BackMaterial", lambda e: material(r, e), ())
    # no Material and no BackMaterial: the scene checks' CHK005 says it (one finding per fact)
    world, chain = world_of(r, p, parent, chain)
    name, rejected = element_name(el), frozenset(p.rejected)
    model = Model(
        m,
        tuple(mat or ()),
        tuple(back or ()),
        world,
        name,
        **r.ctx.position(el),
        rejected=rejected,
    )  # fmt: skip
    acc.models.append(model if chain is None else r.world(model, "world", *chain))


def walk_visual3d(r: Reader, el, parent: np.ndarray, acc: _Acc, chain=None) -> None:
    p = r.props(el)
    t = p.type
    if p.etype is None or p.etype.kind != "visual3d":
        kind = "a Model3D (WPF requires a ModelVisual3D around it)" if (
            p.etype is not None and p.etype.kind in ("model3d", "light")
        ) else "not a Visual3D"  # fmt: skip
        r.ctx.diag("SCN008", f"{t} is {kind}: skipped", el)
        return
    world, chain = world_of(r, p, parent, chain)
    if t == "ModelVisual3D":
        p.obj("Content", lambda e: walk_model3d(r, e, world, acc, chain))
    elif t == "ModelUIElement3D":
        p.obj("Model", lambda e: walk_model3d(r, e, world, acc, chain))
    elif t == "Viewport2DVisual3D":
        _viewport2d(r, p, world, acc, chain)
        return
    for k in p.items("Children"):
        r.build_node(k, lambda e: walk_visual3d(r, e, world, acc, chain))


def _viewport2d(r: Reader, p: Props, world: np.ndarray, acc: _Acc, chain) -> None:
    """A Viewport2DVisual3D: its Visual laid out and drawn (visuals_reader) as the brush of
    the material passes marked Viewport2DVisual3D.IsVisualHostMaterial="True", texture
    coordinates (0,0)-(1,1) spanning the visual's bounds (WPF's internal VisualBrush)."""
    from xaml3d.xaml.drawings_reader import visual_host_brush

    el = p.el
    m = p.obj("Geometry", lambda e: mesh(r, e), None)
    if m is None:
        return
    brush = visual_host_brush(r, p)
    mat = p.obj("Material", lambda e: material(r, e), ()) or ()
    hosts = _host_flags(r, p)
    if len(hosts) != len(mat):
        hosts = [False] * len(mat)
    if brush is not None:
        pairs = zip(mat, hosts, strict=True)
        mat = tuple(replace(x, brush=brush) if host else x for x, host in pairs)
    if not any(hosts):
        msg = (
            "no material of this Viewport2DVisual3D has "
            'Viewport2DVisual3D.IsVisualHostMaterial="True": its Visual is not shown'
        )
        r.ctx.diag("DRW005", msg, el)
    model = Model(m, tuple(mat), (), world, element_name(el), **r.ctx.position(el))
    acc.models.append(model if chain is None else r.world(model, "world", *chain))


def _host_flags(r: Reader, p: Props) -> list[bool]:
    """Per leaf material pass (MaterialGroup flattened in order): is it the visual's host?"""
    from xaml3d.xaml.values import parse_bool

    out: list[bool] = []

    def walk(el) -> None:
        el = _referenced(r, el)
        if el is None or not is_presentation(qname(el.tag)[0]):
            return
        q = r.props(el)
        if q.type == "MaterialGroup":
            for k in q.items("Children"):
                walk(k)
            return
        raw = q.attached.get("Viewport2DVisual3D.IsVisualHostMaterial", "False")
        try:
            out.append(parse_bool(raw))
        except Exception:  # a markup extension or a bad value: not the host
            out.append(False)

    if "Material" in p.attrs:
        # Material="{StaticResource key}": the flag is on the dictionary's entry (a host
        # material is commonly shared by several Viewport2DVisual3Ds this way)
        kind, entry = _reference_in(r, p, p.attrs["Material"])
        if kind == "element":
            walk(entry)
    for k in p.elems.get("Material", ()):
        walk(k)
    return out


def _reference_in(r: Reader, p: Props, value: str):
    """("element", entry) when ``value`` is {StaticResource key} / {DynamicResource key} whose
    entry is in scope, else (None, None); silent: the material's own reading reported any miss."""
    m = split_markup(value)
    if m is None or m[0] not in _REFERENCE:
        return None, None
    entry = r.resources.find(markup_key(m[1]), p.el)
    return ("element", entry) if entry is not None else (None, None)


def _referenced(r: Reader, el):
    """``el``, or the entry a ``<StaticResource ResourceKey=.../>`` element names (None when
    it names nothing in scope; the material's own reading reported that)."""
    ns, local = qname(el.tag)
    if is_presentation(ns) and local in _REFERENCE:
        key = el.get("ResourceKey")
        return r.resources.find(key, el) if key is not None else None
    return el


# --------------------------------------------------------------------------- viewports


def _styled_camera(r: Reader, el):
    """The camera a Setter of the viewport's Style gives (a camera in ``<Setter.Value>``, or a
    ``{StaticResource}`` Value naming one), None when its Style sets none."""
    given = style_value_element(r, el, "Camera")
    if given is None:
        value = element_style(r, el).get("Camera")
        m = split_markup(value) if value else None
        if m is not None and m[0] in _REFERENCE:
            given = r.resources.find(markup_key(m[1]), el)
    return None if given is None else r.build_node(given, lambda e: camera(r, e), None)


def build_viewport(r: Reader, el, index: int, lay=None) -> Viewport:
    p = r.props(el)
    lay = lay or unreached(r, el)
    w, h, source = lay.width, lay.height, lay.source
    how = {"viewport": "its own Width/Height", "default": "the default size"}.get(source, source)
    r.ctx.diag("SCN003", f"Viewport3D #{index} size {w:g} x {h:g} from {how}", el)

    if p.has("Camera"):
        cam = p.obj("Camera", lambda e: camera(r, e), None)
        if cam is None and "Camera" in p.attrs and split_markup(p.attrs["Camera"]) is not None:
            if split_markup(p.attrs["Camera"])[0] == "Null":
                msg = "Camera is {x:Null}: WPF draws nothing"
                r.ctx.diag("SCN009", msg, el, attr=p.attr_keys.get("Camera"))
            else:
                cam = PerspectiveCamera(is_default=True)
    else:
        cam = _styled_camera(r, el)
        if cam is None:
            cam = PerspectiveCamera(is_default=True)
            r.ctx.diag("SCN004", "no Camera: WPF's default PerspectiveCamera is used", el)

    background = lay.background

    acc = _Acc()
    for k in p.items("Children"):
        r.build_node(k, lambda e: walk_visual3d(r, e, T.identity(), acc))
    from xaml3d.xaml.picture_reader import report_ancestors, viewport_picture

    picture = viewport_picture(r, p, w, h, lay.around, lay.layout_transform)
    report_ancestors(r, el, lay.laid_out)
    return Viewport(
        index=index,
        # one in a template's instance: its name in the template (the framework step takes the
        # parts' names out, as WPF keeps them in the template's own name scope)
        name=element_name(el) or element_name(r.ctx.original(el)),
        picture=picture,
        width=w,
        height=h,
        size_source=source,
        layout_rect=lay.rect,
        camera=cam,
        models=tuple(acc.models),
        lights=tuple(acc.lights),
        background=background,
        clip_to_bounds=p.value("ClipToBounds", parse_bool, True),
        **r.ctx.position(el),
    )


# --------------------------------------------------------------------------- document walk


class _Walk:
    """One pass over the main document: viewports, triggers, unresolved markup reported."""

    def __init__(self, r: Reader) -> None:
        self.r = r
        self.viewports: list = []
        self.triggers: list = []

    def visit(self, el) -> None:
        r = self.r
        ns, local = qname(el.tag)
        if el.tag == f"{{{XAML_NS}}}XData":
            return  # plain XML data, not XAML
        if not is_presentation(ns):
            wpf = namespace_typo(ns)
            if ns is None:  # a snippet pasted without its xmlns: WPF resolves none of its types
                r.ctx.diag("XAML021", no_namespace(local), el, once="no namespace")
            elif wpf is not None:
                msg = f"namespace {ns!r} is not WPF's (did you mean {wpf!r}?): {local!r} skipped"
                r.ctx.diag("XAML018", msg, el, once=ns)
            else:
                msg = f"element {local!r} from namespace {ns!r} skipped (children searched)"
                r.ctx.diag("XAML001", msg, el, once=(ns, local))
            if x_attr(el, "Class") is not None:
                msg = f"x:Class={x_attr(el, 'Class')!r}: code-behind is not run"
                r.ctx.diag("XAML007", msg, el, attr=f"{{{XAML_NS}}}Class")
            for child in el:
                if isinstance(child.tag, str) and "." not in qname(child.tag)[1]:
                    self.visit(child)
            return
        if local in _TEMPLATES:
            if r.ctx.instantiated.get(id(el)) is el:
                return  # its instance, in the control that uses it, is walked there
            if any(_wpf(v) for v in el.iter("{*}Viewport3D")):
                r.ctx.diag("XAML015", f"Viewport3D inside {a_an(local)} is not instantiated", el)
            return
        if local == "Viewport3D":
            self.viewports.append(el)
            self._triggers(el)
            return
        et = voc.lookup(local)
        if et is None and local not in WPF_TYPES:
            # no WPF type: the loader refuses it (XAML003 when it misspells a 3D type, the
            # vocabulary xaml3d reads); under --lenient it is walked through for what it
            # holds, without the findings of its own estimated size or missing drawing
            near = voc.suggest(local, voc.closed_types())
            if near is not None:
                hint = voc.did_you_mean(local, voc.known_types())
            else:
                hint = voc.did_you_mean(local, (*voc.known_types(), *WPF_TYPES))
                r.ctx.refused_elements[id(el)] = el
            code = "XAML003" if near is not None else "XAML017"
            r.ctx.diag(code, f"unknown element {local!r}{hint}", el)
        elif et is None:
            pass  # a WPF type xaml3d does not read: walked through for what it holds
        elif et.kind not in ("framework", "resource"):
            return  # 3D/brush objects outside a Viewport3D (resources, effects...)
        p = r.props(el)
        r.resources.dictionary_of(el)  # reads merged dictionaries now: their problems are reported
        for prop, value in p.attrs.items():
            if prop not in ("Width", "Height", "Background"):
                m = split_markup(value)
                if m and m[0] in ("Binding", "Static", "TemplateBinding", "RelativeSource"):
                    p.markup(prop, value)  # reports it
        self._triggers(el)
        for child in el:
            if not isinstance(child.tag, str):
                continue
            cns, cl = qname(child.tag)
            if "." in cl:
                # WPF's own Resources and Triggers are read elsewhere; another assembly's
                # property element of that name (<i:Interaction.Triggers>) is walked as any
                # other: its elements are skipped with XAML001
                wpf = is_presentation(cns)
                if wpf and cl.endswith((".Resources", ".Triggers", ".MergedDictionaries")):
                    continue
                for g in child:
                    if isinstance(g.tag, str):
                        self.visit(g)
            else:
                self.visit(child)

    def _triggers(self, el) -> None:
        # WPF's own <X.Triggers> only: <i:Interaction.Triggers> (Microsoft.Xaml.Behaviors, a
        # clr-namespace) holds that library's EventTrigger, another type of the same name,
        # reported and skipped by visit() as every element of another namespace is
        for child in el:
            if not isinstance(child.tag, str):
                continue
            ns, local = qname(child.tag)
            if is_presentation(ns) and local.endswith(".Triggers"):
                for k in child:
                    if not isinstance(k.tag, str):
                        continue
                    if is_presentation(qname(k.tag)[0]):
                        self.triggers.append(k)
                    else:
                        self.visit(k)  # a trigger of another assembly: XAML001, skipped


def _wpf(el) -> str | None:
    """The local name of a WPF (presentation namespace) element, None for another namespace's
    (whose types merely share names with WPF's)."""
    ns, local = qname(el.tag)
    return local if is_presentation(ns) else None


def _templated_viewport(root):
    """(the template's type, the Viewport3D element) of the first WPF Viewport3D inside a
    template or Style (in resources or in the tree), or None."""
    for el in root.iter("{*}Viewport3D"):
        if not is_presentation(qname(el.tag)[0]):
            continue
        for up in el.iterancestors():
            if isinstance(up.tag, str) and _wpf(up) in _TEMPLATES:
                return qname(up.tag)[1], el
    return None


def _foreign_viewport(root) -> str | None:
    """The prefixed name of the first element of a non-WPF namespace whose name ends in
    Viewport3D (h:HelixViewport3D), or None."""
    for el in root.iter():
        if not isinstance(el.tag, str):
            continue
        ns, local = qname(el.tag)
        if ns is not None and not is_presentation(ns) and local.endswith("Viewport3D"):
            return f"{el.prefix}:{local}" if el.prefix else local
    return None


def check_document(ctx: ReadContext, resources: Resources, doc: ParsedDocument) -> None:
    """What WPF's loader refuses or warns of in the document as written (names, directives,
    styles, content, the 2D framework types' members), before the framework step changes it."""
    check_names(ctx, doc.root)
    check_directives(ctx, doc.root)
    check_styles(ctx, resources, doc.root)
    check_content(ctx, doc.root)
    check_framework(ctx, doc.root)


def build_scene(
    ctx: ReadContext, resources: Resources, doc: ParsedDocument, window_size=None
) -> Scene:
    """The Scene of the checked tree the framework step has instantiated (``xaml3d.pipeline``
    runs them in that order), laid out at ``window_size`` (the root's client size) or the
    markup's size, with its storyboards and their tracks (animation_tracks.py)."""
    r = Reader(ctx, resources)
    walk = _Walk(r)
    walk.visit(doc.root)
    # the storyboards first: the viewports' build notes where what they animate lands
    storyboards: list = []
    begun: set[int] = set()
    hosts: dict[int, object] = {}  # id(storyboard) -> the element whose trigger begins it
    for t in walk.triggers:
        read_trigger(r, t, storyboards, begun, hosts)
    d = resources.dictionary_of(doc.root)
    for key, entry in d.entries.items() if d else ():
        if _wpf(entry) == "Storyboard" and id(entry) not in begun:
            storyboards.append(read_storyboard(r, entry, None, key))
    ns, root_type = qname(doc.root.tag)
    # a ResourceDictionary or Application file: what it holds is used by scenes (SCN013)
    library = root_type in ("ResourceDictionary", "Application")
    resolution = None
    if storyboards:
        resolution = resolve_targets(
            Reader(ctx, resources), doc.root, storyboards, doc.file, hosts, library=library
        )
        r.slots = resolution.slots

    lays, laid_out = lay_out(r, doc.root, walk.viewports, window_size)
    viewports = tuple(build_viewport(r, el, i, lays[i]) for i, el in enumerate(walk.viewports))
    if not viewports:
        et = voc.lookup(root_type) if is_presentation(ns) else None
        if library:  # a valid WPF file, not a scene: its resources are checked one by one
            msg = f"{a_an(root_type)} holds no Viewport3D: nothing to render (use it with -r)"
            ctx.diag("SCN013", msg, doc.root)
            check_dictionary(
                r,
                resources.dictionary_of(doc.root),
                lambda e: walk_model3d(r, e, T.identity(), _Acc()),
                lambda e: walk_visual3d(r, e, T.identity(), _Acc()),
            )
        elif et is not None and et.kind in _FRAGMENT_KINDS:
            # 3D content as the root (a ModelVisual3D component with x:Class, a model or mesh
            # loaded by XamlReader.Load): WPF loads it; it is drawn in the Viewport3D that the
            # application's code puts it in, so there is no scene here either
            msg = (f"{a_an(root_type)} holds no Viewport3D: nothing to render (3D content that "
                   "code adds to a Viewport3D)")  # fmt: skip
            ctx.diag("SCN013", msg, doc.root)
        elif ns is not None:  # else XAML021 says why nothing could be read
            msg = "the document holds no Viewport3D: nothing to render"
            other = _foreign_viewport(doc.root)
            templated = _templated_viewport(doc.root)
            if templated is not None:
                # a DataTemplate's Viewport3D (an ItemsControl's items) is in the document,
                # and WPF draws it once per item; say where it is rather than that it is absent
                where, el = templated
                msg = (
                    "the document holds no Viewport3D outside templates: nothing to render "
                    f"(the Viewport3D at line {ctx.locate(el)[0]} is inside {a_an(where)}: "
                    "no control or item instantiates it)"
                )
            elif other is not None:
                # a toolkit's viewport control (Helix Toolkit's HelixViewport3D ...): WPF loads
                # it with that assembly; its own visuals are that toolkit's, not WPF's
                msg += (
                    f" ({other} is a control of another assembly; xaml3d draws WPF's own "
                    "Viewport3D only)"
                )
            ctx.diag("SCN001", msg, doc.root)

    resources.report_unresolved(doc.root)  # also where xaml3d reads nothing (2D, styles)
    resources.finish_hints()
    found = None if resolution is None else tracks(resolution, viewports, laid_out)
    extra = () if resolution is None else resolution.diagnostics
    diags = sorted((*ctx.diagnostics, *extra),
                   key=lambda g: (g.file or "", g.line or 0, g.column or 0))  # fmt: skip
    return Scene(
        file=doc.file,
        viewports=viewports,
        storyboards=tuple(storyboards),
        diagnostics=tuple(diags),
        resources_used=tuple(dict.fromkeys(ctx.files_used)),
        images_used=tuple(dict.fromkeys(ctx.images_used)),
        layout=laid_out,
        tracks=found,
    )
