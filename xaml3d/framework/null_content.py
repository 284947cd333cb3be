"""``<x:Null/>`` written as an object element of a content or header property
(``<Button.Content><x:Null/></Button.Content>``, ``<Label><x:Null/></Label>``,
``<GroupBox.Header><x:Null/></GroupBox.Header>``): the property is null, as WPF's loader sets
it, so the control shows no content. Rewritten as the attribute ``{x:Null}`` before the other
passes, which read it as written so (an element named Null is not content to show)."""

from __future__ import annotations

from xaml3d.framework.binding_tree import children, is_property_element, is_wpf, local

X_NULL = "{http://schemas.microsoft.com/winfx/2006/xaml}Null"
_PROPERTIES = ("Content", "Header")


def settle(root, services) -> None:
    """Each null content or header under ``root`` made the attribute ``{x:Null}``."""
    pinned = False
    for null in list(root.iter(X_NULL)):
        holder = null.getparent()
        if holder is None or len(children(holder)) != 1 or (holder.text or "").strip():
            continue
        if is_property_element(holder):
            el, prop = holder.getparent(), local(holder).rpartition(".")[2]
            gone = holder
        else:
            # the property tables, for a document that writes x:Null only
            from xaml3d.framework.binding_props import content_property

            el, prop, gone = holder, content_property(holder), null
        if el is None or not is_wpf(el) or prop not in _PROPERTIES or el.get(prop) is not None:
            continue
        if not pinned:
            services.pin(root)  # the tree changes shape: positions first
            pinned = True
        el.remove(gone)
        el.set(prop, "{x:Null}")
