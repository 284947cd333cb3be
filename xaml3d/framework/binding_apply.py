"""Bindings evaluated and written back (bindings.py says what becomes of each): the value as
attribute text, an object as ``{StaticResource key}`` or a copy in the property's element form,
FallbackValue or the default with what is said (BND001, BND003), cycles cut (BND002)."""

from __future__ import annotations

import copy

from xaml3d.framework.binding_eval import Cycle, Evaluator
from xaml3d.framework.binding_sites import Site
from xaml3d.framework.binding_tree import (
    BINDINGS,
    is_element,
    is_wpf,
    local,
    name_of,
    name_scope,
)
from xaml3d.framework.binding_values import Unresolved, Value, clr_of, to_target
from xaml3d.framework.markup_syntax import Extension, MarkupSyntaxError, parse, to_text

# WPF's types whose objects are values a property holds (Freezables), not elements of the tree
_VALUE_OBJECTS = ("Brush", "Geometry", "Transform", "Effect", "Pen", "Drawing", "Material",
                  "Transform3D", "Camera", "DoubleCollection", "PointCollection")  # fmt: skip
_KEEP = object()  # the binding stays as written
_REMOVE = object()  # the property keeps its default


def apply(root, services, sites: list[Site]) -> list[Site]:
    """Evaluate the ``sites`` of the tree under ``root`` and write their outcomes; the
    DataContext bindings kept for the items below them (nodes of XML data) are returned."""
    index = {(id(s.el), s.prop): s for s in sites if s.ext is not None}
    ev = Evaluator(services, name_scope(root), index)
    _cut_visual_cycles(sites, ev, services)
    pinned = False
    contexts: list[Site] = []
    for site in sites:
        if site.ext is None:
            outcome = "{x:Null}" if site.cut else _REMOVE
        else:
            outcome = _outcome(site, ev, services)
        if outcome is _KEEP:
            if site.prop == "DataContext" and _xml_nodes(site.value):
                contexts.append(site)
            continue
        if (site.prop_el is not None or isinstance(outcome, tuple)) and not pinned:
            services.pin(root)  # a property element goes: the tree changes shape
            pinned = True
        _write(site, outcome)
    return contexts


def spend(contexts: list[Site]) -> None:
    """Remove the DataContext bindings ``apply`` kept, once the items they fed are made: the
    framework evaluated them; the reader has nothing left to evaluate."""
    for site in contexts:
        if site.prop_el is not None:
            if site.prop_el.getparent() is site.el:
                site.el.remove(site.prop_el)
        else:
            site.el.attrib.pop(site.key, None)


def _xml_nodes(v: Value | None) -> bool:
    return v is not None and v.items is not None and v.el is not None and (
        local(v.el) == "XmlDataProvider")  # fmt: skip


def value_text(root, services, el, text: str, prop: str = "") -> str | None:
    """The value WPF gives the binding ``text`` (``{Binding ...}``) set on ``el`` at load, as
    attribute text (a DataTrigger's condition compares it), or None when it needs code, fails,
    or is an object; nothing is said. ``root``: the tree whose name scope ``ElementName``
    names."""
    try:
        ext = parse(text)
    except MarkupSyntaxError:
        return None
    if ext.name not in BINDINGS:
        return None
    ev = Evaluator(services, name_scope(root), {})
    try:
        v = ev.binding_value(el, prop, ext)
        if v.null:
            return "{x:Null}"
        return None if v.el is not None or v.items is not None else to_target(v, prop)
    except (Cycle, Unresolved):
        return None


def bound_items(root, services, el, text: str) -> list | None:
    """The items an ``ItemsSource="{Binding ...}"`` on ``el`` gives at load (the nodes of an
    XmlDataProvider's inline data an XPath selects), or None when they are not known (what
    the bindings pass said already, or a binding to no collection). Nothing is said."""
    try:
        ext = parse(text)
    except MarkupSyntaxError:
        return None
    if ext.name not in BINDINGS:
        return None
    ev = Evaluator(services, name_scope(root), {})
    try:
        v = ev.binding_value(el, "ItemsSource", ext)
    except (Cycle, Unresolved):
        return None
    xml = ext.arg("XPath", None) is not None or _xml_nodes(v)  # the provider's own XPath
    return list(v.items) if v.items is not None and xml else None


def _outcome(site: Site, ev: Evaluator, services):
    """The text the site's property takes, or _KEEP / _REMOVE; diagnostics said."""
    try:
        v = ev.site_value(site)
    except Cycle as c:
        if c.site is site:
            chain = " -> ".join(f"{local(s.el)}.{s.prop}" for s in reversed(c.chain))
            msg = (f"{_where(site)}: the binding's source is its own value through "
                   f"{chain} (a cycle): {_fallback_said(site)}")  # fmt: skip
            _say(services, "BND002", msg, site)
        return _fallback(site, ev)
    except Unresolved as u:
        _report(services, u, site)
        return _fallback(site, ev)
    if v.visual or (v.el is not None and v.items is not None):
        # an element of the tree: the reader follows the binding itself, in attribute form
        return _attribute_form(site)
    if v.null:
        return "{x:Null}" if _nullable(site.prop) else _failed(services, site, ev, "null")
    if v.el is not None:
        return _element_text(site, v, ev, services)
    try:
        text = to_target(v, site.prop)
    except Unresolved as u:
        _report(services, u, site)
        return _fallback(site, ev)
    text = _content_format(site, v, text, services)
    return "{}" + text if text.startswith("{") else text


def _content_format(site: Site, v: Value, text: str, services) -> str:
    """A bound number as a control's Content or Header, formatted by the control's own
    ``ContentStringFormat`` (``HeaderStringFormat``) while it is still a number (written
    back, it is text, which takes no number format); the format is then spent."""
    attr = f"{site.prop}StringFormat"
    fmt = site.el.get(attr) if site.prop in ("Content", "Header") else None
    if fmt is None or v.clr not in ("Double", "Int32"):
        return text
    from xaml3d.framework.string_formats import format_text

    out = format_text(services, fmt, text, True, site.el, attr)
    del site.el.attrib[attr]
    return out


def _attribute_form(site: Site):
    """``<VisualBrush.Visual><Binding ElementName="x"/></VisualBrush.Visual>`` as the
    attribute the reader follows (``Visual="{Binding ElementName=x}"``); any other binding to
    an element stays as written."""
    ext = site.ext
    name = ext.named.get("ElementName") if ext is not None else None
    if site.prop_el is None or set(ext.named) != {"ElementName"} or ext.positional:
        return _KEEP
    return "{Binding ElementName=" + to_text(name) + "}" if isinstance(name, str) else _KEEP


def _element_text(site: Site, v: Value, ev: Evaluator, services):
    """An object value (a brush...): ``{StaticResource key}`` when its key finds the same
    object from the target, else a copy of it as the property's element (WPF shares the one
    object; drawn, the two are the same); an element of the tree stays the reader's."""
    if v.key is not None and services.find(v.key, site.el) is v.el:
        return "{StaticResource " + to_text(v.key) + "}"
    if not is_wpf(v.el) and local(v.el) != "Array":
        u = Unresolved("BND001", "code type", f"the value is a {local(v.el)}, a type of the "
                                              "application")  # fmt: skip
        _report(services, u, site)
        return _fallback(site, ev)
    if is_wpf(v.el) and local(v.el).endswith(_VALUE_OBJECTS) and "." not in site.prop:
        return ("copy", v.el)
    return _KEEP


def _failed(services, site: Site, ev: Evaluator, what: str):
    u = Unresolved("BND003", "conversion", f"{what} cannot be a {site.prop}")
    _report(services, u, site)
    return _fallback(site, ev)


def _nullable(prop: str) -> bool:
    return clr_of(prop) in ("Object", "Brush", "String")


def _fallback(site: Site, ev: Evaluator):
    fb = site.ext.arg("FallbackValue", None) if site.ext is not None else None
    if fb is None:
        return _REMOVE
    if isinstance(fb, str):
        return "{}" + fb if fb.startswith("{") else fb
    if isinstance(fb, Extension):
        return to_text(fb)
    try:
        v = ev.element_value(fb)
    except Unresolved:
        return _REMOVE
    return v.text if v.text is not None and not v.null else _REMOVE


def _fallback_said(site: Site) -> str:
    fb = site.ext.arg("FallbackValue", None) if site.ext is not None else None
    if fb is None:
        return "the property keeps its default"
    shown = to_text(fb) if isinstance(fb, (str, Extension)) else local(fb)
    return f"FallbackValue {shown} used"


def _where(site: Site) -> str:
    return f"{local(site.el)}.{site.prop}"


def _report(services, u: Unresolved, site: Site) -> None:
    if u.code is None:
        return  # said where it happened
    if u.code == "BND001":
        msg = (f"{_where(site)}: {u.detail}: {_fallback_said(site)} (said once for every "
               "binding that needs this)")  # fmt: skip
        _say(services, "BND001", msg, site, once=("BND001", u.kind))
    else:
        msg = f"{_where(site)}: the binding fails in WPF too ({u.detail}): {_fallback_said(site)}"
        _say(services, "BND003", msg, site)


def _say(services, code: str, msg: str, site: Site, once=None) -> None:
    if site.binding_el is not None:
        services.diag(code, msg, site.binding_el, once=once)
    else:
        services.diag(code, msg, site.el, attr=site.key, once=once)


def _write(site: Site, outcome) -> None:
    el = site.el
    if site.prop_el is not None:
        el.remove(site.prop_el)
    elif outcome is _REMOVE or isinstance(outcome, tuple):
        del el.attrib[site.key]
    if isinstance(outcome, tuple):  # ("copy", element): the property's element form
        el.insert(0, _property_element(el, site.prop, outcome[1]))
    elif outcome is not _REMOVE:
        el.set(site.prop if site.prop_el is not None else site.key, outcome)


def _property_element(el, prop: str, value):
    """``<Type.Prop>`` holding a copy of ``value`` (without its key and names: one object of
    the name scope)."""
    ns = el.tag[1:].partition("}")[0] if el.tag.startswith("{") else None
    tag = f"{{{ns}}}{local(el)}.{prop}" if ns else f"{local(el)}.{prop}"
    holder = el.makeelement(tag, {})
    dup = copy.deepcopy(value)
    dup.tail = None
    for node in dup.iter():
        if not is_element(node):
            continue
        for key in ("{http://schemas.microsoft.com/winfx/2006/xaml}Key",
                    "{http://schemas.microsoft.com/winfx/2006/xaml}Name", "Name"):  # fmt: skip
            node.attrib.pop(key, None)
    holder.append(dup)
    return holder


def _cut_visual_cycles(sites: list[Site], ev: Evaluator, services) -> None:
    """A VisualBrush whose Visual (an element binding) draws the brush itself, directly or
    through other such brushes: reported and cut (the brush draws nothing), as the reader
    would otherwise follow it forever."""
    brushes: list[tuple[Site, object]] = []
    for site in sites:
        if site.ext is None or local(site.el) != "VisualBrush" or site.prop != "Visual":
            continue
        try:
            v = ev.site_value(site)
        except (Cycle, Unresolved):
            continue
        if v.visual and v.el is not None:
            brushes.append((site, v.el))
    while brushes:
        cut = _cycle_start(brushes)
        if cut is None:
            return
        site, target = brushes[cut]
        name = name_of(target) or local(target)
        msg = (f"VisualBrush.Visual draws {name}, which holds this brush (a cycle): the brush "
               "draws nothing")  # fmt: skip
        _say(services, "BND002", msg, site)
        site.ext, site.cut = None, True  # written {x:Null} with the others
        del brushes[cut]


def _cycle_start(brushes: list[tuple[Site, object]]) -> int | None:
    """The index of the first brush that reaches itself through the brushes inside the visual
    it draws, or None."""
    inside = [
        [j for j, (other, _) in enumerate(brushes)
         if other.el is target or any(a is target for a in other.el.iterancestors())]
        for _, target in brushes
    ]  # fmt: skip
    for start in range(len(brushes)):
        seen: set[int] = set()
        stack = list(inside[start])
        while stack:
            j = stack.pop()
            if j == start:
                return start
            if j not in seen:
                seen.add(j)
                stack.extend(inside[j])
    return None
