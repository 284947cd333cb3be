"""Styles as WPF's loader checks them, wherever they are (what the layout reads of them is in
panels_reader.py).

- A Style ``BasedOn`` a StaticResource that is the Style itself: WPF looks the key up while it
  creates that Style, before it is in the dictionary, and fails (RES003, a cycle). One based on
  a key not found is RES001, on a key defined only later in scope RES002.
- A MultiTrigger or MultiDataTrigger without Conditions (XAML025).
- A Setter whose ``Property`` names no property of the Style's ``TargetType``, when that type is
  one whose properties xaml3d lists in full (the 3D types, not the open framework ones): WPF
  cannot resolve the property and refuses the file (XAML004, with the closest name).
- A Setter, Trigger or Condition whose ``Property`` names no dependency property of a 2D
  framework type xaml3d has a table for (the Style's TargetType, or the owner written in
  ``Button.Background``), or a bare name in a Style without TargetType: XAML024
  (framework_check.py). The same for the Triggers of a ControlTemplate with a TargetType (its
  Triggers are read at load, its content when it is applied). Styles and templates inside
  template content are built when that template is applied and are not checked.
"""

from __future__ import annotations

from xaml3d.errors import ValueSyntaxError
from xaml3d.xaml import framework_members as fm
from xaml3d.xaml import values as V
from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.context import ReadContext, is_presentation, markup_key, qname, split_markup
from xaml3d.xaml.framework_check import check_style_property
from xaml3d.xaml.resources import Resources, type_name

_SETTER_HOLDERS = {"Style.Setters", "Style.Triggers", "Trigger", "MultiTrigger", "DataTrigger",
                   "MultiDataTrigger", "Trigger.Setters", "MultiTrigger.Setters",
                   "DataTrigger.Setters", "MultiDataTrigger.Setters",
                   "ControlTemplate.Triggers"}  # fmt: skip
_CONDITION_HOLDERS = {"MultiTrigger.Conditions", "MultiDataTrigger.Conditions"}
_TEMPLATES = {"ControlTemplate", "DataTemplate", "ItemsPanelTemplate",
              "HierarchicalDataTemplate", "ItemContainerTemplate"}  # fmt: skip


def check_styles(ctx: ReadContext, resources: Resources, root) -> None:
    """Report Styles based on themselves and Setters naming no property of a known type."""
    for style in root.iter("{*}Style"):
        if not is_presentation(qname(style.tag)[0]):
            continue
        _based_on_itself(ctx, resources, style)
        if not _in_template(style):
            _based_on_found(resources, style)
        target = style.get("TargetType")
        etype = voc.lookup(type_name(target)) if target else None
        if etype is not None and not etype.open:
            for setter in _setters(style):
                _check_setter(ctx, etype, setter)
        elif not _in_template(style):
            for node, what in _members_named(style):
                check_style_property(ctx, style, node, what)
                if what == "Setter" and target:
                    _check_setter_value(ctx, type_name(target), node)
    for trigger in root.iter("{*}MultiTrigger", "{*}MultiDataTrigger"):
        if is_presentation(qname(trigger.tag)[0]) and not _in_template(trigger):
            _conditions_given(ctx, trigger)
    for template in root.iter("{*}ControlTemplate"):
        # without a TargetType WPF resolves the names on the template's default type, and only
        # once its content is read: not checked
        if (is_presentation(qname(template.tag)[0]) and template.get("TargetType")
                and not _in_template(template)):  # fmt: skip
            triggers = [k for k in template if qname(str(k.tag))[1] == "ControlTemplate.Triggers"]
            for node, what in _members_named(template, triggers):
                check_style_property(ctx, template, node, what)


def _conditions_given(ctx: ReadContext, trigger) -> None:
    """A MultiTrigger or MultiDataTrigger without a Condition: WPF refuses it when it seals the
    Style or template ("must have at least one condition")."""
    local = qname(trigger.tag)[1]
    for k in trigger:
        if isinstance(k.tag, str) and qname(k.tag)[1] == f"{local}.Conditions":
            if any(isinstance(c.tag, str) for c in k):
                return
    msg = f"this {local} has no Condition: WPF requires at least one"
    ctx.diag("XAML025", msg, trigger)


# the Boolean and enumeration properties of the 2D framework types whose Setter Value is checked
# as an attribute of that name is: WPF converts a Setter's Value with the property's converter
# while it reads the Style
_BOOLEANS = frozenset("""
IsEnabled IsChecked IsThreeState Focusable IsHitTestVisible ClipToBounds SnapsToDevicePixels
IsTabStop IsDefault IsCancel IsReadOnly AcceptsReturn AcceptsTab ShowGridLines IsExpanded
IsSelected IsEditable IsIndeterminate OverridesDefaultStyle UseLayoutRounding StaysOpen
""".split())  # fmt: skip
_ALIGN_H = ("Left", "Center", "Right", "Stretch")
_ALIGN_V = ("Top", "Center", "Bottom", "Stretch")
_ENUMS = {
    "HorizontalAlignment": _ALIGN_H, "HorizontalContentAlignment": _ALIGN_H,
    "VerticalAlignment": _ALIGN_V, "VerticalContentAlignment": _ALIGN_V,
    "Visibility": ("Visible", "Hidden", "Collapsed"), "Orientation": ("Horizontal", "Vertical"),
    "TextWrapping": ("NoWrap", "Wrap", "WrapWithOverflow"),
    "TextAlignment": ("Left", "Right", "Center", "Justify"),
    "TextTrimming": ("None", "CharacterEllipsis", "WordEllipsis"),
    "FlowDirection": ("LeftToRight", "RightToLeft"),
    "Stretch": ("None", "Fill", "Uniform", "UniformToFill"),
    "FontStyle": ("Normal", "Italic", "Oblique"),
    "DockPanel.Dock": ("Left", "Top", "Right", "Bottom"),
}  # fmt: skip


def _check_setter_value(ctx: ReadContext, target: str, setter) -> None:
    """A Setter's Value (attribute) that the property's converter refuses: VAL005, as the same
    value written as the attribute is."""
    prop, value = (setter.get("Property") or "").strip(), setter.get("Value")
    if value is None or not prop or setter.get("TargetName") is not None:
        return
    owner, _, name = prop.rpartition(".")
    owner = owner.split(":")[-1]
    if owner == "DockPanel":
        name = prop.split(":")[-1]
    elif owner and fm.derives(target, owner) is not True:
        return  # another owner's property: not checked here
    v = value.strip()
    if split_markup(v) is not None or v.lstrip("-").isdigit():
        return  # a markup extension, or an enumeration's number
    members = fm.members(target)
    if members is None or (name not in members and name != "DockPanel.Dock"):
        return
    try:
        if name in _BOOLEANS:
            if name == "IsChecked" and not v:
                return  # Nullable<bool>: empty is null
            V.parse_bool(v)
        elif name in _ENUMS:
            V.parse_enum(v, _ENUMS[name])
    except ValueSyntaxError as exc:
        ctx.diag(exc.code, f"Setter {target}.{name}: {exc.message}", setter, attr="Value")


def _in_template(el) -> bool:
    return any(isinstance(up.tag, str) and qname(up.tag)[1] in _TEMPLATES
               for up in el.iterancestors())  # fmt: skip


def _members_named(holder, roots=None):
    """The Setters, Triggers and Conditions of a Style (of ``roots``, its elements to search,
    when given), with what they are (not those of nested Styles, nor what a Setter's Value
    holds)."""
    stack = [k for k in (holder if roots is None else roots) if isinstance(k.tag, str)]
    while stack:
        el = stack.pop()
        if not is_presentation(qname(el.tag)[0]):
            continue
        local = qname(el.tag)[1]
        if local in ("Setter", "Condition"):
            yield el, local
            continue
        if local == "Trigger":
            yield el, local
        if local in _SETTER_HOLDERS or local in _CONDITION_HOLDERS:
            stack.extend(k for k in el if isinstance(k.tag, str))


def _based_on_itself(ctx: ReadContext, resources: Resources, style) -> None:
    based = style.get("BasedOn")
    m = split_markup(based) if based else None
    if m is None or m[0] != "StaticResource":
        return
    key = markup_key(m[1])
    if key.startswith("{"):
        return  # BasedOn="{StaticResource {x:Type T}}": the theme's Style of T, WPF finds it
    if resources.find(key, style) is not style:
        return
    # an outer scope's entry of that key is what WPF finds then: no error
    node = style.getparent()  # <X.Resources> or the ResourceDictionary
    node = None if node is None else node.getparent()
    outer = None if node is None else node.getparent()
    if outer is not None:
        other = resources.find(key, outer)
    else:  # the root's resources: the application's come next
        hits = (d.find(key) for _, d in reversed(resources.app))
        other = next((h[0] for h in hits if h is not None and h[0] is not style), None)
    if other in (None, style):
        msg = (f"Style {key!r} is BasedOn itself: WPF looks the key up while creating the Style, "
               "before it is defined, and fails (cycle)")  # fmt: skip
        ctx.diag("RES003", msg, style, attr="BasedOn")


def _based_on_found(resources: Resources, style) -> None:
    """The Style's ``BasedOn`` StaticResource looked up as WPF does while it creates the Style:
    a key not found (RES001) or defined only later in scope (RES002, WPF does not see it yet)
    is an error. A Style based on itself is RES003 (``_based_on_itself``)."""
    based = style.get("BasedOn")
    m = split_markup(based) if based else None
    if m is None or m[0] != "StaticResource":
        return
    key = markup_key(m[1])
    if key.startswith("{") or resources.find(key, style) is style:
        return
    resources.lookup(key, style, attr="BasedOn")


def _setters(style):
    """The Setters of a Style and of its triggers (not those naming a TargetName in a template,
    nor those of nested Styles)."""
    stack = [k for k in style if isinstance(k.tag, str)]
    while stack:
        el = stack.pop()
        local = qname(el.tag)[1]
        if local == "Setter":
            if el.get("TargetName") is None:
                yield el
        elif local in _SETTER_HOLDERS:
            stack.extend(k for k in el if isinstance(k.tag, str))


def _check_setter(ctx: ReadContext, etype, setter) -> None:
    prop = (setter.get("Property") or "").strip()
    if not prop or prop.startswith("{"):
        return
    owner, _, name = prop.rpartition(".")
    if owner and owner.split(":")[-1] != etype.name:
        return  # an attached property or another owner's: not checked
    if name in etype.properties:
        return
    hint = voc.did_you_mean(name, etype.properties)
    msg = f"Setter Property {prop!r}: {etype.name} has no property {name!r}{hint}"
    ctx.diag("XAML004", msg, setter, attr="Property")
