"""Element names (``x:Name`` and the ``Name`` property) as WPF's XAML loader checks them.

A name must be an identifier (a letter or underscore, then letters, digits or underscores):
``x:Name="1"`` or ``Name="left cube"`` make the loader throw (XAML019). A name may be
registered once per namescope: two elements named alike in one scope make it throw "Cannot
register duplicate name" (XAML020). Name and x:Name on one WPF element set the same property
twice: the loader throws (XAML012). Styles, templates and resource dictionaries are namescopes
of their own, so names inside them are only checked against each other's scope.

``Name`` is the name property of WPF's own elements only: on a type of a clr-namespace it is an
ordinary property, so only x:Name is checked there. What WPF's loader never reads is not checked:
the content of ``x:XData`` (plain XML), elements of mc:Ignorable namespaces with their content,
and ``mc:AlternateContent`` (whose Choice and Fallback branches would name things alike).
"""

from __future__ import annotations

from xaml3d.xaml import vocabulary as voc
from xaml3d.xaml.context import ReadContext, ignorable_namespaces, is_presentation, qname, x_attr
from xaml3d.xaml.parser import MC_NS, XAML_NS

X_NAME = f"{{{XAML_NS}}}Name"
_SCOPES = {"Style", "ControlTemplate", "DataTemplate", "ItemsPanelTemplate",
           "HierarchicalDataTemplate", "ItemContainerTemplate", "ResourceDictionary"}  # fmt: skip
_UNREAD = {f"{{{XAML_NS}}}XData", f"{{{MC_NS}}}AlternateContent"}  # never checked for names


def check_names(ctx: ReadContext, root) -> None:
    """Report names that are not identifiers and names defined twice in one namescope."""
    stack = [(root, {})]
    while stack:
        el, scope = stack.pop()
        ns, local = qname(el.tag)
        if el.tag in _UNREAD or (ns is not None and ns in ignorable_namespaces(el)):
            continue
        framework = "." not in local and is_presentation(ns)  # Name is WPF's name property
        if framework and x_attr(el, "Name") is not None and el.get("Name") is not None:
            et = voc.lookup(local)
            if et is not None and (et.open or "Name" in et.properties):
                # Name is x:Name's property on this type: the loader refuses it set twice
                msg = (f"{local} has both Name and x:Name: they set one property, which WPF's "
                       "loader refuses to set twice (keep one)")  # fmt: skip
                ctx.diag("XAML012", msg, el, attr="Name")
        attr, name = (X_NAME, x_attr(el, "Name")) if x_attr(el, "Name") is not None else (
            "Name", el.get("Name") if framework else None)  # fmt: skip
        if name is not None:
            if not name.isidentifier():
                ctx.diag("XAML019", f"{name!r} is not a valid name: a name starts with a letter "
                         "or underscore and holds only letters, digits and underscores", el,
                         attr=attr)  # fmt: skip
            elif name in scope:
                line = ctx.locate(scope[name])[0]
                ctx.diag("XAML020", f"the name {name!r} is already used in this namescope "
                         f"(line {line}): WPF cannot register it twice", el, attr=attr)  # fmt: skip
            else:
                scope[name] = el
        inner = {} if local in _SCOPES or local.endswith(".Resources") else scope
        for child in reversed(el):
            if isinstance(child.tag, str):
                stack.append((child, inner))
