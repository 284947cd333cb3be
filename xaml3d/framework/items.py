"""The items of ItemsControl, ListBox and ComboBox generated as WPF's ItemContainerGenerator
does at load: the items (inline, or ``ItemsSource="{StaticResource k}"``: an ``x:Array`` or
any collection element of the resources), each shown by the ``ItemTemplate`` (a DataTemplate
whose ``{Binding}`` / ``{Binding Path}`` read the item), else by an implicit DataTemplate of
the item's type (``DataType="{x:Type T}"``), else as the text of its ``DisplayMemberPath``
or itself; wrapped in the control's container (ListBoxItem, ComboBoxItem, a ContentPresenter
for an ItemsControl) styled by ``ItemContainerStyle``, in the ``ItemsPanel``'s panel (a
vertical StackPanel by default).

An item is ``("text", str, el)`` (a string: ``sys:String``, ``x:String``, any element of
another namespace holding text alone), ``("element", el, el)`` (a WPF element: its own
visual) or ``("data", el, el)`` (an object of another namespace whose properties are its
attributes).
"""

from __future__ import annotations

from xaml3d.framework import binding_data, markup, string_formats, xml_data
from xaml3d.framework.styles import Control, elements, local_name

CONTAINERS = {"ItemsControl": "ContentPresenter", "ListBox": "ListBoxItem",
              "ComboBox": "ComboBoxItem"}  # fmt: skip
_OWN_CONTAINERS = {"ListBoxItem", "ComboBoxItem"}
# the item properties the controls' own look reads: what the generator changes is drawn
_ITEM_PROPERTIES = (
    "ItemsSource",
    "ItemTemplate",
    "DisplayMemberPath",
    "ItemContainerStyle",
    "AlternationCount",
)


def generates(c: Control) -> bool:
    """Whether the generator has work for ``c`` beyond the items written inline as the
    theme's look of a ListBox or ComboBox shows them."""
    if c.type == "ItemsControl":
        return True
    return any(c.value(p) is not None for p in _ITEM_PROPERTIES)


def items_of(c: Control, sv):
    """(the items, whether they are the control's own elements to move), None when the
    ItemsSource is not known at load (a binding, a missing resource)."""
    source = c.value("ItemsSource")
    if source is not None:
        if source[0] == "element":
            holder = source[1]
        else:
            key = markup.resource_key(source[1])
            holder = sv.find(key, c.el) if key is not None else None
            if key is None and (markup.split(source[1]) or ("",))[0] == "Binding":
                return _bound_items(c, sv, source[1])
        if holder is None:
            return None
        kids = [k for k in elements(holder) if "." not in local_name(k.tag)]
        for k in elements(holder):  # <x:Array.Items>, <col:ArrayList.Items>...
            if local_name(k.tag).endswith(".Items"):
                kids.extend(elements(k))
        return [_item(k, sv) for k in kids], False
    kids = []
    for child in elements(c.el):
        local = local_name(child.tag)
        if "." not in local:
            kids.append(child)
        elif local.rpartition(".")[2] == "Items":
            kids.extend(elements(child))
    return [_item(k, sv) for k in kids], True


def _bound_items(c: Control, sv, text: str):
    """An ItemsSource binding's items (an XPath over XML data), or None."""
    from xaml3d.framework.binding_apply import bound_items  # a document that binds items only

    root = c.el
    while root.getparent() is not None:
        root = root.getparent()
    found = bound_items(root, sv, c.el, text)
    if found is None:
        return None
    # an attribute or text node: a string, its position the control's
    out = [_item(k, sv) if isinstance(getattr(k, "tag", None), str)
           else ("text", xml_data.text_of(k), c.el) for k in found]  # fmt: skip
    return out, False


def _item(el, sv):
    if sv.wpf_type(el) is not None:
        return ("element", el, el)
    own = [a for a in el.attrib if not a.startswith("{")]
    if not own and not elements(el):
        return ("text", el.text or "", el)
    return ("data", el, el)


def item_property(item, path: str) -> str | None:
    """The text of ``path`` (dotted) on an item: a data object's attribute or property element
    text; "" is the item itself (a string's text)."""
    kind, value, source = item
    if source is not None and kind != "element" and xml_data.is_data(source):
        return xml_data.item_text(source, path)  # an XML node's DisplayMemberPath: an XPath
    if path == "":
        return value if kind == "text" else None
    if kind == "text":
        return str(len(value)) if path == "Length" else None
    node = value
    for step in path.split("."):
        raw = node.get(step)
        if raw is not None:
            return raw
        for child in elements(node):
            if local_name(child.tag).rpartition(".")[2] == step and "." in local_name(child.tag):
                kids = elements(child)
                if not kids:
                    return (child.text or "").strip()
                node = kids[0]
                break
        else:
            return None
    return None


def data_template(c: Control, item, sv):
    """The DataTemplate that shows ``item``: the ItemTemplate, else (unless a
    DisplayMemberPath chooses the text) an implicit one of the item's type; None."""
    value = c.value("ItemTemplate")
    if value is not None:
        found = template_element(value, c.el, sv, "DataTemplate")
        if found is not None:
            return found
    if c.value("DisplayMemberPath") is not None:
        return None
    if item[0] == "data":
        return sv.implicit_data_template(local_name(item[1].tag), c.el)
    if item[0] == "text":
        return sv.implicit_data_template("String", c.el)
    return None


def template_element(value, where, sv, kind: str):
    """The template element a property value gives (written in place, or a resource)."""
    if value[0] == "element":
        el = value[1]
    else:
        key = markup.resource_key(value[1])
        el = sv.find(key, where) if key is not None else None
    return el if el is not None and local_name(el.tag) == kind else None


def shown(c: Control, item, sv):
    """What a container shows for a data or text item: ("visual", el) an instantiated
    DataTemplate, or ("text", str) (formatted by the ItemStringFormat)."""
    what, value = _shown(c, item, sv)
    fmt = c.value("ItemStringFormat")
    if what != "text" or fmt is None or fmt[0] != "text":
        return what, value
    found = string_formats.number_text(item[2]) if item[0] == "text" and item[2] is not None \
        else None  # fmt: skip
    number = found is not None and found[1]
    where = "ItemStringFormat" if c.el.get("ItemStringFormat") is not None else None
    return "text", string_formats.format_text(sv, fmt[1], value, number, c.el, where)


def _shown(c: Control, item, sv):
    template = data_template(c, item, sv)
    if template is not None:
        visual = [k for k in elements(template) if "." not in local_name(k.tag)]
        if visual:
            copy = sv.copy(visual[0])
            fill_data(copy, item, sv, c.el)
            return ("visual", copy)
    path = c.value("DisplayMemberPath")
    if path is not None and path[0] == "text" and markup.split(path[1]) is None:
        text = item_property(item, path[1].strip())
        return ("text", text or "")
    if item[0] == "text":
        return ("text", item[1])
    return ("text", local_name(item[1].tag))  # an object without a template: its type's name


def fill_data(root, item, sv=None, scope=None) -> None:
    """A DataTemplate's copy with its bindings to the data context replaced by the item's
    values (binding_data.py; a binding to nothing the item has is cleared: the property's
    default). ``sv``: where a refused StringFormat is said; ``scope``: the element showing the
    item, from which a Converter resource is looked up."""
    stack = [root]
    while stack:
        el = stack.pop()
        if not isinstance(el.tag, str):
            continue
        for attr, value in list(el.attrib.items()):
            if "{" not in value:
                continue
            text = binding_data.item_binding(value, item, item_property, sv, el, attr, scope)
            if text is binding_data.NOT_THE_ITEMS:
                continue
            if text is None:
                del el.attrib[attr]
            else:
                el.set(attr, "{}" + text if text.lstrip().startswith("{") else text)
        if local_name(el.tag) not in ("DataTemplate", "ControlTemplate", "Style"):
            stack.extend(elements(el))


def container_style(c: Control, sv):
    """The ``ItemContainerStyle`` element of ``c``, or None."""
    value = c.value("ItemContainerStyle")
    return None if value is None else template_element(value, c.el, sv, "Style")


def containers(c: Control, sv, on_item=None) -> list | None:
    """The containers of ``c``'s items, in order (None: the items are not known at load).
    ``on_item(container, item, instance)`` is told of each data or text item's container
    (``instance``: the DataTemplate's copy that shows it, or None)."""
    found = items_of(c, sv)
    if found is None:
        return None
    items, own = found
    kind = CONTAINERS[c.type]
    ns = c.el.tag.rpartition("}")[0]

    def make(local: str, where):
        el = c.el.makeelement(f"{ns}}}{local}" if ns else local, {})
        sv.made(el, where)
        return el

    out = []
    for item in items:
        source = item[2]
        if item[0] == "element":
            el = source if own else sv.copy(source)
            if local_name(el.tag) in _OWN_CONTAINERS or kind == "ContentPresenter":
                if own:
                    el.getparent().remove(el)
                el.tail = None
                out.append(el)
                continue
            box = make(kind, source)
            if own:
                el.getparent().remove(el)
            el.tail = None
            box.append(el)
        else:
            box = make(kind, source)
            what, value = shown(c, item, sv)
            if what == "visual":
                box.append(value)
            elif kind == "ContentPresenter":
                block = make("TextBlock", source)
                block.set("Text", "{}" + value if value.lstrip().startswith("{") else value)
                box.append(block)
            else:
                box.set("Content", "{}" + value if value.lstrip().startswith("{") else value)
            if own:
                source.getparent().remove(source)
            if on_item is not None:
                on_item(box, item, value if what == "visual" else None)
        out.append(box)
    count = c.value("AlternationCount")
    try:
        count = int(count[1]) if count is not None and count[0] == "text" else 0
    except ValueError:
        count = 0
    if count > 0:  # each container's ItemsControl.AlternationIndex, for its Style's triggers
        for i, box in enumerate(out):
            box.set("ItemsControl.AlternationIndex", str(i % count))
    if c.type != "ItemsControl":  # the selected item's container is IsSelected, as WPF sets it
        index = c.value("SelectedIndex")
        try:
            chosen = int(index[1]) if index is not None and index[0] == "text" else -1
        except ValueError:
            chosen = -1
        if 0 <= chosen < len(out) and out[chosen].get("IsSelected") is None:
            out[chosen].set("IsSelected", "True")
    # a bound ItemsSource is spent: its items are the containers now (the reader has
    # nothing left to evaluate)
    if (markup.split(c.el.get("ItemsSource")) or ("",))[0] == "Binding":
        del c.el.attrib["ItemsSource"]
    # the inline items' property element, emptied
    for child in elements(c.el):
        if local_name(child.tag).rpartition(".")[2] == "Items" and not elements(child):
            c.el.remove(child)
    return out


def items_panel(c: Control, sv, make_default):
    """A copy of the ItemsPanel's panel, else a new vertical StackPanel."""
    value = c.value("ItemsPanel")
    if value is not None:
        template = template_element(value, c.el, sv, "ItemsPanelTemplate")
        if template is not None:
            visual = [k for k in elements(template) if "." not in local_name(k.tag)]
            if visual:
                panel = sv.copy(visual[0])
                panel.attrib.pop("IsItemsHost", None)
                return panel
    return make_default()
