"""Members of WPF's 2D framework types as WPF's XAML loader resolves them (XAML024).

WPF's loader refuses a member its type does not have: ``<TextBlock Foregrund="Red"/>``
("The property 'Foregrund' was not found in type 'TextBlock'"), ``<TextBlock.Foregrund>``, and a
Setter or Trigger of a Style whose ``Property`` names no dependency property of the Style's
TargetType or of the owner it names ("Cannot resolve the Style Property 'FontWieght'"). This
module checks these against the tables of framework_members.py, wherever the element is in
the document:

- an attribute or property element of a type that has a table: its own member or a base's
  (``Control.Background`` on a Button), an event (``Click="OnClick"``: a handler name is
  legal markup), or an attached property: ``Owner.Name`` where the owner is another type is
  refused only when that owner has a table and no member of that name (``Grid.Rwo``); owners
  without a table (``ToolTipService``, ``KeyboardNavigation``, ``TextOptions`` ...) are accepted;
- an unknown name that reads like an event (``...Changed``, ``...Click``) whose value is a
  handler name is not refused: WPF's events are many and xaml3d does not run them;
- types without a table, types of other namespaces (``local:``, ``clr-namespace:``) and the
  closed 3D types (whose members props.py checks as XAML004) are not checked here.

What WPF's loader does not read at load is not checked: template content (ControlTemplate,
DataTemplate ... bodies, built when the template is applied), ``x:XData``, ``mc:AlternateContent``
and elements of mc:Ignorable namespaces.
"""

from __future__ import annotations

import re

from lxml import etree

from xaml3d.xaml import framework_members as fm
from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.context import ReadContext, ignorable_namespaces, is_presentation, qname
from xaml3d.xaml.parser import MC_NS, XAML_NS

CODE = "XAML024"
_TEMPLATES = {"ControlTemplate", "DataTemplate", "ItemsPanelTemplate",
              "HierarchicalDataTemplate", "ItemContainerTemplate"}  # fmt: skip
_UNREAD = {f"{{{XAML_NS}}}XData", f"{{{MC_NS}}}AlternateContent"}
_REFUSED = "; WPF refuses this file"


def _hint(name: str, candidates) -> str:
    meant = voc.suggest(name, candidates)
    return f" (did you mean {meant!r}?)" if meant else ""


def not_a_member(type_name: str, prop: str) -> str | None:
    """The message when ``prop`` is no member of ``type_name`` (a type with a table), else
    None (a member, or a type whose vocabulary is open)."""
    names = fm.members(type_name)
    if names is None or prop in names:
        return None
    return f"{prop!r} is not a property of {type_name}{_hint(prop, names)}"


def check_framework(ctx: ReadContext, root: etree._Element) -> None:
    """Report the members WPF cannot resolve on framework elements (module docstring)."""
    # one pass in lxml's walker, what a tag says computed once per tag: a document may hold a
    # million elements, nearly all of them 3D objects with nothing to check here
    known: dict[str, tuple[str | None, str, bool]] = {}
    walk = etree.iterwalk(root, events=("start",))
    for _, el in walk:
        tag = el.tag
        if not isinstance(tag, str):
            continue  # a comment or processing instruction
        info = known.get(tag)
        if info is None:
            ns, local = qname(tag)
            info = known[tag] = (ns, local, is_presentation(ns))
        ns, local, presentation = info
        if not presentation:
            if tag in _UNREAD or (ns is not None and ns in ignorable_namespaces(el)):
                walk.skip_subtree()  # WPF's loader does not read it
            continue
        if "." in local:
            parent = el.getparent()
            if parent is not None and isinstance(parent.tag, str):
                pns, plocal = qname(parent.tag)
                closed = voc.lookup(plocal)
                # a closed 3D type's property elements are its reader's (XAML004)
                if is_presentation(pns) and "." not in plocal and (closed is None or closed.open):
                    _check_property_element(ctx, el, plocal, local)
            continue
        _check_attributes(ctx, el, local)
        if local in _TEMPLATES:
            # the template's own members only: its body is built when it is applied
            for k in el:
                kns, klocal = qname(k.tag) if isinstance(k.tag, str) else (None, "")
                if "." in klocal and is_presentation(kns):
                    _check_property_element(ctx, k, local, klocal)
            walk.skip_subtree()


def _check_attributes(ctx: ReadContext, el, local: str) -> None:
    own = fm.members(local)
    for key, value in el.attrib.items():
        if value[:1] == "{" and "AncestorLevel" in value:  # a {Binding ...}: never a mesh's
            _ancestor_level(ctx, el, key, value)
        if own is None and (key[0] == "{" or "." not in key):
            continue  # a type without a table: only Owner.Name attributes are checked
        ans, name = qname(key)
        if ans is not None and not is_presentation(ans):
            continue  # x:, xml:, mc:, d: and other namespaces' attributes
        msg = _member_problem(local, own, fm.bases(local), name, value)
        if msg is not None:
            ctx.diag(CODE, f"property {msg}{_REFUSED}", el, attr=key)


_ANCESTOR_LEVEL = re.compile(r"\bAncestorLevel\s*=\s*([^,}\s]*)")


def _ancestor_level(ctx: ReadContext, el, key: str, value: str) -> None:
    """A ``{RelativeSource FindAncestor, AncestorLevel=N}`` below 1: RelativeSource's
    AncestorLevel refuses it while the markup is read (VAL008)."""
    for m in _ANCESTOR_LEVEL.finditer(value):
        try:
            level = int(m.group(1))
        except ValueError:
            continue  # not a number: the binding says it
        if level < 1:
            msg = (f"AncestorLevel={level} in {key!r}: WPF's RelativeSource accepts an "
                   "AncestorLevel of 1 or more (the parent's level is 1)")  # fmt: skip
            ctx.diag("VAL008", msg, el, attr=key)


def _check_property_element(ctx: ReadContext, el, local: str, written: str) -> None:
    msg = _member_problem(local, fm.members(local), fm.bases(local), written, None)
    if msg is not None:
        ctx.diag(CODE, f"property element <{written}>: {msg}{_REFUSED}", el)


def _member_problem(local, own, chain, name: str, value: str | None) -> str | None:
    """Why ``name`` (``Prop`` or ``Owner.Prop``) cannot be set on a ``local`` element, or None."""
    owner, _, prop = name.rpartition(".")
    if ":" in owner:
        return None  # a prefixed owner: another namespace's type
    if owner and owner != local and owner not in chain:
        # an attached property (or event) of another type: refused when that type is one
        # whose members are all known and it has none of that name
        msg = not_a_member(owner, prop)
        if msg is None or _event_like(prop, value):
            return None
        return msg
    if own is None or prop in own or _event_like(prop, value):
        return None
    return f"{prop!r} is not a property of {local}{_hint(prop, own)}"


def _event_like(prop: str, value: str | None) -> bool:
    """An event handler attribute of an event the tables may not list (``Foo="OnFoo"``)."""
    return value is not None and voc.is_event_name(prop) and value.strip().isidentifier()


# --------------------------------------------------------------------------- styles


def presentation_type(node: etree._Element, written: str) -> str | None:
    """The WPF type a TargetType or owner names (``Button``, ``{x:Type Button}``,
    ``{x:Type TypeName=Button}``), or None when it is of another namespace or not a name."""
    t = written.strip()
    if t.startswith("{") and t.endswith("}"):
        body = t[1:-1].split(None, 1)
        if len(body) != 2 or body[0].rpartition(":")[2] != "Type":
            return None
        t = body[1].strip()
        if t.startswith("TypeName="):
            t = t[len("TypeName=") :].strip()
    prefix, _, name = t.rpartition(":")
    if not name.isidentifier() or not is_presentation(node.nsmap.get(prefix or None)):
        return None
    return name


def check_style_property(
    ctx: ReadContext, style: etree._Element, node: etree._Element, what: str
) -> None:
    """Report a Setter's, Trigger's or Condition's ``Property`` (``node``, inside ``style``, a
    Style or a ControlTemplate) that WPF cannot resolve as a dependency property:
    ``Owner.Name`` against the owner when it has a table, a bare name against the TargetType
    (a Style without one: WPF cannot resolve it)."""
    written = (node.get("Property") or "").strip()
    if not written or written.startswith("{"):
        return
    if node.get("SourceName") is not None or node.get("TargetName") is not None:
        return  # resolved on the named element's type, which a Style does not have
    owner, _, name = written.rpartition(".")
    if owner:
        typ = presentation_type(node, owner)
        msg = not_a_member(typ, name) if typ is not None else None
        if msg is not None:
            ctx.diag(CODE, f"{what} Property {written!r}: {msg}{_REFUSED}", node, attr="Property")
        return
    target = style.get("TargetType")
    if target is None:
        msg = (f"{what} Property {written!r} names no owner type and the Style has no "
               "TargetType: WPF cannot resolve it (write Owner.Property, e.g. "
               f"'Control.{written}', or give the Style a TargetType){_REFUSED}")  # fmt: skip
        ctx.diag(CODE, msg, node, attr="Property")
        return
    typ = presentation_type(style, target)
    msg = not_a_member(typ, name) if typ is not None else None
    if msg is not None:
        holder = qname(style.tag)[1]
        msg = msg.replace(f"of {typ}", f"of {typ}, the {holder}'s TargetType", 1)
        ctx.diag(CODE, f"{what} Property {written!r}: {msg}{_REFUSED}", node, attr="Property")
