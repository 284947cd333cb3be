"""The element tree as a binding sees it: element types and namespaces, the object parent
(property elements are not objects), name scopes (a template's names are its own), the
ancestors FindAncestor walks and the WPF base classes its AncestorType matches, through the
ElementTree interface of the document's elements."""

from __future__ import annotations

PRESENTATION = frozenset(
    {
        "http://schemas.microsoft.com/winfx/2006/xaml/presentation",
        "http://schemas.microsoft.com/netfx/2007/xaml/presentation",
    }
)
XAML = "http://schemas.microsoft.com/winfx/2006/xaml"
# the markup extensions of a binding (their element forms too)
BINDINGS = ("Binding", "MultiBinding", "PriorityBinding")
# the bodies instantiated later, each with its own name scope and its templated parent: the
# templates pass evaluates the bindings in them
TEMPLATES = frozenset(
    {
        "Style",
        "ControlTemplate",
        "DataTemplate",
        "ItemsPanelTemplate",
        "HierarchicalDataTemplate",
        "ItemContainerTemplate",
    }  # fmt: skip
)


def qname(el) -> tuple[str | None, str]:
    """(namespace, local name) of an element's tag."""
    tag = el.tag
    if tag.startswith("{"):
        ns, _, local = tag[1:].partition("}")
        return ns, local
    return None, tag


def local(el) -> str:
    return qname(el)[1]


def is_wpf(el) -> bool:
    return qname(el)[0] in PRESENTATION


def is_element(node) -> bool:
    return isinstance(node.tag, str)


def x_attr(el, name: str) -> str | None:
    return el.get(f"{{{XAML}}}{name}")


def name_of(el) -> str | None:
    """x:Name, or the Name property."""
    return x_attr(el, "Name") or el.get("Name")


def is_property_element(el) -> bool:
    return "." in local(el)


def children(el) -> list:
    """The element children (no comments or processing instructions)."""
    return [k for k in el if is_element(k)]


def object_parent(el):
    """The object that holds ``el`` (its property element skipped), None at the root."""
    up = el.getparent()
    while up is not None and is_property_element(up):
        up = up.getparent()
    return up


def object_ancestors(el):
    """The objects above ``el``, nearest first."""
    up = object_parent(el)
    while up is not None:
        yield up
        up = object_parent(up)


def in_template(el) -> bool:
    """Whether ``el`` is inside a Style or template body."""
    return any(is_wpf(a) and local(a) in TEMPLATES for a in el.iterancestors())


def in_resources(el) -> bool:
    """Whether ``el`` is inside a resource dictionary (a shared object, not the tree's)."""
    for a in el.iterancestors():
        name = local(a)
        if name == "ResourceDictionary" or name.endswith(".Resources"):
            return True
    return False


def name_scope(root) -> dict[str, object]:
    """The root name scope: name -> element, outside templates (first of a repeated name)."""
    names: dict[str, object] = {}
    stack = [root]
    while stack:
        el = stack.pop()
        if is_wpf(el) and local(el) in TEMPLATES:
            continue
        n = name_of(el)
        if n and n not in names:
            names[n] = el
        stack.extend(reversed(children(el)))
    return names


# WPF's classes above the common controls, for FindAncestor's AncestorType (a type matches
# itself and each class it derives from)
_BASES = {
    "FrameworkElement": "UIElement", "UIElement": "Visual", "Visual": "DependencyObject",
    "Control": "FrameworkElement", "Panel": "FrameworkElement", "Decorator": "FrameworkElement",
    "Shape": "FrameworkElement", "ContentControl": "Control", "ItemsControl": "Control",
    "HeaderedContentControl": "ContentControl", "HeaderedItemsControl": "ItemsControl",
    "Selector": "ItemsControl", "ButtonBase": "ContentControl", "ToggleButton": "ButtonBase",
    "RangeBase": "Control", "TextBoxBase": "Control", "Window": "ContentControl",
    "UserControl": "ContentControl", "Page": "FrameworkElement",
    "Grid": "Panel", "StackPanel": "Panel", "DockPanel": "Panel", "Canvas": "Panel",
    "WrapPanel": "Panel", "UniformGrid": "Panel", "VirtualizingPanel": "Panel",
    "VirtualizingStackPanel": "VirtualizingPanel", "TabPanel": "Panel",
    "ToolBarPanel": "StackPanel",
    "Border": "Decorator", "Viewbox": "Decorator", "AdornerDecorator": "Decorator",
    "Rectangle": "Shape", "Ellipse": "Shape", "Line": "Shape", "Path": "Shape",
    "Polygon": "Shape", "Polyline": "Shape",
    "Button": "ButtonBase", "RepeatButton": "ButtonBase", "CheckBox": "ToggleButton",
    "RadioButton": "ToggleButton", "Label": "ContentControl", "ScrollViewer": "ContentControl",
    "ListBoxItem": "ContentControl", "ComboBoxItem": "ListBoxItem", "ListViewItem": "ListBoxItem",
    "ToolTip": "ContentControl", "Frame": "ContentControl",
    "GroupBox": "HeaderedContentControl", "Expander": "HeaderedContentControl",
    "TabItem": "HeaderedContentControl", "MenuItem": "HeaderedItemsControl",
    "TreeViewItem": "HeaderedItemsControl", "ToolBar": "HeaderedItemsControl",
    "ListBox": "Selector", "ComboBox": "Selector", "TabControl": "Selector",
    "ListView": "ListBox", "Menu": "ItemsControl", "TreeView": "ItemsControl",
    "StatusBar": "ItemsControl", "Slider": "RangeBase", "ProgressBar": "RangeBase",
    "ScrollBar": "RangeBase", "TextBox": "TextBoxBase", "RichTextBox": "TextBoxBase",
    "PasswordBox": "Control", "TextBlock": "FrameworkElement", "Image": "FrameworkElement",
    "Viewport3D": "FrameworkElement", "ContentPresenter": "FrameworkElement",
    "ItemsPresenter": "FrameworkElement", "AccessText": "FrameworkElement",
}  # fmt: skip


def type_matches(el, type_name: str) -> bool:
    """Whether ``el`` is of type ``type_name`` or derives from it (WPF's own classes; another
    assembly's type matches by its name)."""
    want = type_name.split(":")[-1].strip()
    name = local(el)
    if not is_wpf(el):
        return name == want or want in ("Object", "DependencyObject", "Visual", "UIElement",
                                        "FrameworkElement")  # fmt: skip
    if want == "Object":
        return True
    seen = 0
    t: str | None = name
    while t is not None and seen < 16:
        if t == want:
            return True
        t = _BASES.get(t)
        seen += 1
    return False


def type_argument(value) -> str | None:
    """The type an ``{x:Type T}`` (or a plain type name) names, without its prefix."""
    if isinstance(value, str):
        return value.split(":")[-1].strip() or None
    if value is not None and value.name in ("Type", "TypeExtension"):
        arg = value.arg("TypeName")
        return arg.split(":")[-1].strip() if isinstance(arg, str) else None
    return None
