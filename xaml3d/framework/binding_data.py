"""Bindings to the data context inside a DataTemplate's copy (an item's ItemTemplate, a
ContentTemplate): ``{Binding}``, ``{Binding Path}``, ``{Binding XPath=...}`` read from the
item, with the arguments WPF applies without code: ``StringFormat`` (to text targets: a
``sys:Double`` item is a number, XML data and text are strings), ``FallbackValue`` (when the
path finds nothing), ``Mode`` and ``TargetNullValue`` (an item is never null). A binding with
any other argument (a Converter, a Source...) is not the item's: ``item_binding`` leaves it.

A ``StringFormat`` .NET refuses throws in WPF when the value is shown: the binding fails,
said (BND003), and the property keeps its default."""

from __future__ import annotations

from xaml3d.framework import binding_format as F
from xaml3d.framework import markup, xml_data
from xaml3d.framework.binding_values import Value, as_number, clr_of, primitive
from xaml3d.framework.markup_syntax import MarkupSyntaxError, parse

_ARGUMENTS = frozenset({"Path", "XPath", "Mode", "StringFormat", "FallbackValue",
                        "TargetNullValue", "Converter", "ConverterParameter"})  # fmt: skip
NOT_THE_ITEMS = object()  # item_binding's answer for a binding that does not read the item


def item_binding(value: str, item, item_property, sv=None, where=None, attr: str = "",
                 scope=None):  # fmt: skip
    """The text the binding ``value`` (an attribute's text) takes from ``item`` (see
    items.py), None when it takes none (the property keeps its default), NOT_THE_ITEMS when
    it is no binding to the data context. ``item_property(item, path)`` reads a path; a
    Converter resource is looked up from ``where`` then ``scope`` (the control showing the
    item: the template's copy is not in the tree yet)."""
    m = markup.split(value)
    if m is None or m[0] != "Binding":
        return NOT_THE_ITEMS
    try:
        ext = parse(value)
    except MarkupSyntaxError:
        return NOT_THE_ITEMS  # the reader says what is malformed
    if len(ext.positional) > 1 or set(ext.named) - _ARGUMENTS:
        return NOT_THE_ITEMS
    args = dict(ext.named)
    converter = args.pop("Converter", None)
    if converter is not None:
        args.pop("ConverterParameter", None)  # BooleanToVisibilityConverter reads none
        if sv is None or _framework_converter(sv, converter, where, scope) is None:
            return NOT_THE_ITEMS  # an application's converter: code
    if not all(isinstance(v, str) for v in args.values()) or (
        ext.positional and not isinstance(ext.positional[0], str)
    ):
        return NOT_THE_ITEMS  # an argument that is an extension ({x:Static}...): not the item's
    xpath = args.get("XPath")
    path = args.get("Path", ext.positional[0] if ext.positional else "").strip()
    number = False
    if xpath is not None:
        if path:
            return NOT_THE_ITEMS  # a Path after an XPath reads a node's members: not evaluated
        node = item[2]
        data = node is not None and xml_data.is_data(node)
        text = xml_data.item_text(node, xpath.strip()) if data else None
    else:
        text = item_property(item, path)
        if path == "" and item[0] == "text" and item[2] is not None:
            p = primitive(item[2])
            number = p is not None and p.clr in ("Double", "Int32")
    if text is None:
        return args.get("FallbackValue")
    if converter is not None:
        # WPF's converter: a bool True is Visible, anything else Collapsed; XML data is text
        # (never a bool), an object's property written "True" is read as the bool it holds
        flag = xpath is None and item[0] == "data" and text.strip().lower() == "true"
        return "Visible" if flag else "Collapsed"
    fmt = args.get("StringFormat")
    if not fmt or clr_of(attr) != "String":  # WPF formats for a text target only
        return text
    shown: object = text
    if number:
        x = as_number(primitive(item[2]))
        shown, number = (x, True) if x is not None else (text, False)
    try:
        return F.composite(fmt, shown, number)
    except F.FormatError as exc:
        if sv is not None:
            msg = (f"{attr}={value!r}: the binding fails in WPF too (StringFormat "
                   f"{fmt!r} is refused by .NET: {exc}): the property keeps its "
                   "default")  # fmt: skip
            # one template, many items: said once
            sv.diag("BND003", msg, where, attr=attr, once=("BND003", "StringFormat", value))
        return None


# --------------------------------------------------------------------------- templated parent
UNEVALUATED = object()  # templated_value's answer for what needs code
_TEMPLATED = frozenset({"Path", "Property", "RelativeSource", "Converter", "ConverterParameter",
                        "StringFormat", "Mode", "FallbackValue", "TargetNullValue"})  # fmt: skip


def templated_value(sv, value: str, prop: str, parent_value, scopes: tuple, attr: str):
    """A template part's ``{Binding P, RelativeSource={RelativeSource TemplatedParent},
    Converter=..., StringFormat=...}`` (``{TemplateBinding P, Converter=...}``) as WPF
    evaluates it at load: the templated parent's value of ``P`` (``parent_value``: its
    ("text", str), or None for its default) through the framework's own converter
    (BooleanToVisibilityConverter, a resource found from the first of ``scopes``, the
    elements it is looked up from, that has it) and the StringFormat (a text target only).
    ("text", str); None (the default) when the format is refused (BND003); UNEVALUATED when
    it needs code (an application's converter) or is not text."""
    try:
        ext = parse(value)
    except MarkupSyntaxError:
        return UNEVALUATED
    if set(ext.named) - _TEMPLATED or (parent_value is not None and parent_value[0] != "text"):
        return UNEVALUATED
    text = parent_value[1] if parent_value is not None else None
    conv = ext.named.get("Converter")
    if conv is not None:
        if _framework_converter(sv, conv, *scopes) is None:
            return UNEVALUATED  # a converter class of the application: code
        # WPF's converter: a bool True is Visible, anything else (False, null, not a bool)
        # Collapsed; an unset bool property is its default, False
        flag = clr_of(prop) == "Boolean" and (text or "").strip().lower() == "true"
        return ("text", "Visible" if flag else "Collapsed")
    fmt = ext.named.get("StringFormat")
    if not isinstance(fmt, str) or text is None:
        return UNEVALUATED
    if not fmt or clr_of(attr) != "String":
        return ("text", text)
    number = clr_of(prop) in ("Double", "Int32")
    x = as_number(Value(text, "Double")) if number else None
    try:
        out = F.composite(fmt, x if x is not None else text, x is not None)
    except F.FormatError as exc:  # thrown in WPF when shown: the binding fails
        msg = (f"{attr}={value!r}: the binding fails in WPF too (StringFormat {fmt!r} is "
               f"refused by .NET: {exc}): the property keeps its default")  # fmt: skip
        sv.diag("BND003", msg, scopes[0], attr=attr, once=("BND003", "StringFormat", value))
        return None
    return ("text", "{}" + out if out.startswith("{") else out)


def _framework_converter(sv, conv, *scopes):
    """The BooleanToVisibilityConverter resource ``conv`` (``{StaticResource k}``) names, found
    from the first of ``scopes`` that has it; None for anything else (an application's)."""
    if isinstance(conv, str) or getattr(conv, "name", None) not in (
        "StaticResource", "DynamicResource"):  # fmt: skip
        return None
    key = conv.arg("ResourceKey")
    if not isinstance(key, str):
        return None
    for scope in scopes:
        entry = sv.find(key.strip(), scope) if scope is not None else None
        if entry is not None:
            return entry if sv.wpf_type(entry) == "BooleanToVisibilityConverter" else None
    return None
