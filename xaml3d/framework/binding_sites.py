"""Where a document's bindings are: each ``{Binding}`` attribute and each property element
holding a ``<Binding>`` (``<MultiBinding>``, ``<PriorityBinding>``), outside Style and template
bodies and resource dictionaries, as ``Site``s; the element form read as the Extension its
attribute form would be. A malformed one is reported (XAML016) and becomes a site without an
extension (its property keeps its default)."""

from __future__ import annotations

from dataclasses import dataclass

from xaml3d.framework.binding_tree import (
    BINDINGS,
    TEMPLATES,
    children,
    is_property_element,
    is_wpf,
    local,
)
from xaml3d.framework.markup_syntax import (
    Extension,
    MarkupSyntaxError,
    is_extension,
    literal,
    parse,
)

# attributes whose binding is an object the element keeps, not a value of the property
_BINDING_OBJECTS = frozenset({"Binding", "Storyboard.Target"})
_OWNER_BASES = frozenset({"FrameworkElement", "UIElement", "Control", "Panel", "ContentControl",
                          "ItemsControl", "TextElement", "Shape"})  # fmt: skip
# bulk data (a mesh's, a path's): a binding there needs code; the reader says so (XAML009)
_DATA = frozenset({"Positions", "Normals", "TextureCoordinates", "TriangleIndices", "Points",
                   "Data", "Figures"})  # fmt: skip
_BINDING_TAGS = tuple(f"}}{name}" for name in BINDINGS)
# the members of WPF's binding classes (BindingBase and its three kinds): a name WPF's loader
# cannot resolve refuses the file
_BASE_MEMBERS = ("FallbackValue TargetNullValue StringFormat BindingGroupName Delay "
                 "Converter ConverterParameter ConverterCulture Mode UpdateSourceTrigger "
                 "NotifyOnSourceUpdated NotifyOnTargetUpdated NotifyOnValidationError "
                 "ValidatesOnDataErrors ValidatesOnExceptions ValidatesOnNotifyDataErrors "
                 "ValidationRules UpdateSourceExceptionFilter").split()  # fmt: skip
MEMBERS = {
    "Binding": frozenset(_BASE_MEMBERS + "Path ElementName RelativeSource Source XPath "
                         "BindsDirectlyToSource IsAsync AsyncState".split()),
    "MultiBinding": frozenset(_BASE_MEMBERS + ["Bindings"]),
    "PriorityBinding": frozenset(_BASE_MEMBERS + ["Bindings"]),
}  # fmt: skip


@dataclass(eq=False)
class Site:
    """A binding set on a property: ``el``'s attribute ``key`` (property ``prop``), or a
    property element ``prop_el`` holding the Binding element ``binding_el``."""

    el: object
    prop: str
    key: str | None = None
    ext: Extension | None = None
    prop_el: object = None
    binding_el: object = None
    state: str = "new"  # new | busy | done
    value: object = None  # its Value, once evaluated
    error: Exception | None = None
    cut: bool = False  # a VisualBrush drawing its own holder: its Visual becomes null


def collect(root, services) -> list[Site]:
    """The binding sites in document order (outside templates and resources)."""
    sites: list[Site] = []
    for el in root.iter():
        tag = el.tag
        if type(tag) is not str:  # noqa: E721 (a comment's tag is a function)
            continue
        if tag.endswith(_BINDING_TAGS):
            holder = el.getparent()
            if is_wpf(el) and holder is not None and is_property_element(holder) and (
                    not _set_aside(holder)):  # fmt: skip
                _element_site(holder, el, services, sites)
        elif any("{" in v for v in el.values()) and not is_property_element(el):
            found = _attribute_sites(el, services)
            if found and not _set_aside(el):
                sites.extend(found)
    return sites


def _set_aside(el) -> bool:
    """Whether ``el`` is in a Style or template body or a resource dictionary (or is a
    binding's own argument)."""
    for up in el.iterancestors():
        name = local(up)
        if name.endswith(".Resources") or is_wpf(up) and (
            name in TEMPLATES or name in BINDINGS or name == "ResourceDictionary"):  # fmt: skip
            return True
    return False


def _attribute_sites(el, services) -> list[Site]:
    sites: list[Site] = []
    for key in el.attrib:
        if key.startswith("{") or key in _BINDING_OBJECTS or key in _DATA:
            continue
        raw = el.get(key)
        if not is_extension(raw):
            continue
        words = raw.lstrip()[1:].split(None, 1)
        head = words[0].split(",")[0].split("}")[0] if words else ""
        if head.split(":")[-1] not in BINDINGS:
            continue
        try:
            ext = parse(raw)
        except MarkupSyntaxError as exc:
            msg = f"{local(el)}.{key}={raw!r}: malformed markup extension ({exc})"
            services.diag("XAML016", msg, el, attr=key)
            sites.append(Site(el, key, key=key))
            continue
        if _unknown_member(ext, services, el, key):
            sites.append(Site(el, key, key=key))
            continue
        sites.append(Site(el, key, key=key, ext=ext))
    return sites


def _unknown_member(ext: Extension, services, el, attr: str | None) -> bool:
    """Report (XAML024) an argument the binding's class does not have; True if one is found."""
    known = MEMBERS.get(ext.name)
    if known is None:
        return False
    for name in ext.named:
        if name not in known:
            import difflib  # only for a name that is wrong

            near = difflib.get_close_matches(name, sorted(known), 1, 0.7)
            hint = f" (did you mean {near[0]}?)" if near else ""
            msg = f"{ext.name} has no property {name!r}{hint}: WPF refuses the file"
            services.diag("XAML024", msg, el, attr=attr)
            return True
    return False


def _element_site(pe, b, services, sites: list[Site]) -> None:
    """``<X.Prop><Binding .../></X.Prop>``: the Binding ``b`` as the only child of ``pe``."""
    el = pe.getparent()
    if el is None or len(children(pe)) != 1 or is_property_element(el):
        return
    owner, _, short = local(pe).rpartition(".")
    prop = short if owner == local(el) or owner in _OWNER_BASES else f"{owner}.{short}"
    if prop in _BINDING_OBJECTS:
        return
    try:
        ext = binding_element_extension(b)
    except MarkupSyntaxError as exc:
        msg = f"<{local(b)}> of {local(el)}.{prop}: malformed markup extension ({exc})"
        services.diag("XAML016", msg, b)
        sites.append(Site(el, prop, prop_el=pe, binding_el=b))
        return
    if _unknown_member(ext, services, b, None):
        sites.append(Site(el, prop, prop_el=pe, binding_el=b))
        return
    sites.append(Site(el, prop, prop_el=pe, binding_el=b, ext=ext))


def binding_element_extension(b) -> Extension:
    """A ``<Binding .../>`` (``<MultiBinding>``, ``<PriorityBinding>``) element as the
    Extension its attribute form would be: attributes parsed as attributes are, property
    elements (``<Binding.Source>``...) as their single object, child bindings as
    ``Bindings``."""
    ext = Extension(local(b))
    for key, raw in b.attrib.items():
        if key.startswith("{"):
            continue
        ext.named[key] = parse(raw) if is_extension(raw) else literal(raw)
    nested = []
    for k in children(b):
        name = local(k)
        if is_property_element(k):
            prop = name.rpartition(".")[2]
            kids = children(k)
            if len(kids) == 1:
                ext.named[prop] = _object_argument(kids[0])
            elif not kids:
                ext.named[prop] = (k.text or "").strip()
        elif name in BINDINGS:
            nested.append(binding_element_extension(k))
    if nested:
        ext.named["Bindings"] = nested
    return ext


def _object_argument(el):
    """An object written as an argument's property element: an extension element as its
    Extension (``<RelativeSource Mode="Self"/>``, ``<StaticResource ResourceKey="k"/>``),
    anything else as the element itself."""
    name = local(el)
    if is_wpf(el) and name == "RelativeSource":
        ext = Extension("RelativeSource")
        for key, raw in el.attrib.items():
            ext.named[key] = parse(raw) if is_extension(raw) else literal(raw)
        return ext
    if name in BINDINGS:
        return binding_element_extension(el)
    return el
