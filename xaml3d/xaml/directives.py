"""The XAML language namespace's directives (``x:Name``, ``x:Key`` ...) as WPF's loader checks
them, wherever they are in the document.

An ``x:`` attribute must name a directive of the XAML 2006 language namespace
(``http://schemas.microsoft.com/winfx/2006/xaml``, System.Xaml's XamlLanguage): anything else
makes WPF's loader throw "The property 'Nmae' does not exist in XML namespace
'http://schemas.microsoft.com/winfx/2006/xaml'". Such a typo is no mere unused attribute (it
loses the name or key it meant to give), so it is reported as an error (XAML004) at the
attribute, with the closest directive. ``x:Type``, ``x:Null``, ``x:Static`` ... are types (markup
extensions), written as ``{x:Null}`` or as elements, never as attributes.

What WPF's loader never reads is not checked: the content of ``x:XData`` (plain XML),
``mc:AlternateContent`` and elements of mc:Ignorable namespaces.
"""

from __future__ import annotations

from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.context import ReadContext, ignorable_namespaces, qname
from xaml3d.xaml.parser import MC_NS, XAML_NS

# the directives of XamlLanguage's 2006 namespace that may be written as attributes (Code,
# Items, Initialization, PositionalParameters, Members... are there too: listed so that no
# legal member is ever refused)
X_DIRECTIVES = frozenset({
    "Name", "Key", "Class", "ClassModifier", "FieldModifier", "Uid", "Shared", "Subclass",
    "TypeArguments", "Arguments", "FactoryMethod", "ConnectionId", "Code", "Items",
    "Initialization", "PositionalParameters", "Members", "ClassAttributes", "AsyncRecords",
    "SynchronousMode", "UnknownContent",
})  # fmt: skip
_UNREAD = {f"{{{XAML_NS}}}XData", f"{{{MC_NS}}}AlternateContent"}


def unknown_directive(local: str) -> str:
    """The message for ``x:local``, a name the XAML language namespace does not have."""
    meant = voc.suggest(local, X_DIRECTIVES)
    hint = f" (did you mean x:{meant}?)" if meant else ""
    return (f"x:{local} is not a directive of the XAML language namespace{hint}: WPF's loader "
            f"refuses it (\"The property '{local}' does not exist in XML namespace "
            f"'{XAML_NS}'\")")  # fmt: skip


def _unread(el) -> bool:
    """Whether WPF's loader never reads ``el`` as XAML (inside x:XData, mc:AlternateContent,
    or an element of an mc:Ignorable namespace)."""
    ignorable = None
    node = el
    while node is not None:
        if node.tag in _UNREAD:
            return True
        ns = qname(node.tag)[0]
        if ns is not None:
            ignorable = ignorable if ignorable is not None else ignorable_namespaces(el)
            if ns in ignorable:
                return True
        node = node.getparent()
    return False


def check_directives(ctx: ReadContext, root) -> None:
    """Report every ``x:`` attribute that names no directive (module docstring)."""
    # libxml2 finds the few elements with an x: attribute: a document of a million elements
    # holds a handful
    found = root.xpath("descendant-or-self::*[@x:*]", namespaces={"x": XAML_NS})
    for el in found:
        for key in el.attrib:
            ns, local = qname(key)
            if ns == XAML_NS and local not in X_DIRECTIVES:
                if _unread(el):
                    break
                ctx.diag("XAML004", unknown_directive(local), el, attr=key)
