"""Styles' control templates and triggers, instantiated as WPF's FrameworkElement.ApplyTemplate
builds them at load (``ControlTemplate`` from the control's ``Template`` attribute or
``<X.Template>`` property element, a Style Setter of a keyed or implicit Style and its
``BasedOn`` chain, a merged or application dictionary's Style).

A templated control stays in the tree with its own layout properties (size, margin,
alignment, attached properties, visibility, opacity, transforms) and the template's visual
tree, copied, as its only child (the reader lays it out and draws it as a plain container:
``Services.templated``). In the copy:

- ``{TemplateBinding P}`` and ``{Binding P, RelativeSource={RelativeSource TemplatedParent}}``
  become the control's effective value of P (``styles.Control.value``);
- a ``ContentPresenter`` holds the control's content (its ``ContentSource``, ``Content`` by
  default; ``Header`` for a header's presenter): string content as a TextBlock (AccessText's
  access key hidden when ``RecognizesAccessKey``), element content moved in, a
  ``ContentTemplate`` (DataTemplate) instantiated with the content as its data;
- names (``x:Name``) belong to the template's name scope: they are taken off the copies (the
  window's names and storyboard targets never see them) and serve the triggers' TargetName;
- triggers whose condition is known at load (``Trigger`` and ``MultiTrigger`` on a property
  the control sets, its Style sets, or a state a picture shows: enabled, not checked, not
  selected, no mouse, no focus; on a named part's property with ``SourceName``;
  ``DataTrigger`` and ``MultiDataTrigger`` on a binding evaluated at load: data_triggers.py)
  apply their Setters: a ControlTemplate trigger's to its TargetName part (above the part's
  own values) or to the control, a Style trigger's to the control (below its local values), a
  DataTemplate trigger's to its named part or the ContentPresenter holding the item;
- ``ContentStringFormat`` / ``HeaderStringFormat`` / ``ItemStringFormat`` format content that
  is not an element (string_formats.py).

What WPF refuses at load is an error here: a template that holds itself, directly or through
a Style, ContentTemplate or ItemTemplate (TPL004: the outermost control of the cycle draws
nothing; WPF recurses until its stack overflows), a ControlTemplate whose TargetType is not the
control's type or a base class (TPL012: the theme's look stands), a trigger Setter's TargetName
that names no part (TPL005, for every trigger of the template, fired at load or not).

Button, ToggleButton and RepeatButton without a template of their own (nor their Style's)
take the theme Style's (``THEMED``), instantiated the same way, as do CheckBox and RadioButton
(their triggers on HasContent and on IsChecked's ``{x:Null}`` included), Label, TextBox and
PasswordBox (a TextBox's or PasswordBox's ``PART_ContentHost`` holds its text view,
text_host.py, in the theme's template or a user's), ListBox and ListBoxItem, and ComboBox (its
SelectionBoxItem filled at load with the selected item's content); GroupBox and Expander take
the theme's too (a GroupBox's frame masked by BorderGapMaskConverter: gap_mask.py); the other
controls without a user template are left to the reader's theme drawing.
"""

from __future__ import annotations

import math
import re

from xaml3d.access_text import access_text
from xaml3d.framework import (
    binding_data,
    binding_tree,
    data_triggers,
    gap_mask,
    items,
    markup,
    string_formats,
    text_host,
)
from xaml3d.framework.styles import (
    X_NS,
    Control,
    elements,
    local_name,
    property_name,
    setter_value,
    setters,
    triggers,
)

# controls whose user template is instantiated: content controls and plain Controls
CONTENT_CONTROLS = {
    "Button", "ToggleButton", "RepeatButton", "CheckBox", "RadioButton", "Label",
    "ContentControl", "UserControl", "ListBoxItem", "ComboBoxItem", "ListViewItem",
    "StatusBarItem", "ToolTip", "Frame",
}  # fmt: skip
# controls whose template, when neither they nor their Style set one, is the theme's
# (``Services.theme_styles``: the package's theme dictionary)
THEMED = {"Button", "ToggleButton", "RepeatButton"}
THEMED |= {"CheckBox", "RadioButton"}
THEMED |= {"Label", "TextBox", "PasswordBox"}
# themed controls a ToolBar draws in the theme's template (its TextBox Style, ToolBar.
# TextBoxStyleKey, is a Border around PART_ContentHost as the theme's; its ComboBox shows
# the closed ComboBox's face)
_OWN_ON_TOOL_BAR = {"Label", "TextBox", "PasswordBox", "ComboBox"}
THEMED |= {"ListBox", "ListBoxItem"}
THEMED |= {"ComboBox"}
THEMED |= {"GroupBox"}
THEMED |= {"Expander"}
THEMED |= {"Separator", "GridSplitter"}
THEMED |= {"ProgressBar"}
HEADERED = {"GroupBox", "HeaderedContentControl", "Expander", "TabItem"}
PLAIN_CONTROLS = {"Control", "Separator", "GridSplitter", "ProgressBar"}
# items controls whose template's presenter shows the selected item (SelectionBoxItem)
SELECTION_BOXES = {"ComboBox"}
ITEMS_CONTROLS = {"ItemsControl", "ListBox"}  # their items placed by ItemsPresenter/IsItemsHost
# controls whose template's PART_ContentHost shows their text (text_host.py)
TEXT_HOSTS = set(text_host.HOSTS)
SUPPORTED = CONTENT_CONTROLS | HEADERED | PLAIN_CONTROLS | ITEMS_CONTROLS | TEXT_HOSTS
SUPPORTED |= SELECTION_BOXES
# controls whose templates place parts xaml3d does not generate (items, text hosts, tracks)
UNSUPPORTED = {
    "ListView", "TabControl", "Menu", "MenuItem",
    "ToolBar", "StatusBar", "TreeView", "TreeViewItem", "DataGrid",
    "RichTextBox", "Slider", "ScrollBar", "ScrollViewer", "Calendar",
    "DatePicker", "DocumentViewer", "FlowDocumentScrollViewer",
}  # fmt: skip
# the control's own layout properties a theme Style may set (the reader reads them there)
_THEME_LAYOUT = ("Margin", "Width", "Height", "MinWidth", "MinHeight", "HorizontalAlignment",
                 "VerticalAlignment")  # fmt: skip
# elements whose content is not part of the visual tree where they are written
_NOT_VISUAL = {"Style", "ControlTemplate", "DataTemplate", "ItemsPanelTemplate",
               "HierarchicalDataTemplate", "ItemContainerTemplate",
               "ResourceDictionary"}  # fmt: skip
_NOT_VISUAL_PROPERTIES = ("Resources", "Style", "Template", "ContentTemplate", "ItemTemplate",
                          "ItemsPanel", "ItemContainerStyle", "Triggers", "ToolTip",
                          "ContextMenu", "HeaderTemplate", "FocusVisualStyle")  # fmt: skip
# the presenter's own properties, consumed where its content is placed
_PRESENTER_PROPS = ("Content", "ContentSource", "ContentTemplate", "ContentTemplateSelector",
                    "ContentStringFormat", "RecognizesAccessKey")  # fmt: skip
THEME = "<theme>"  # template_of's answer for a template the theme gives (no attribute names it)
MAX_DEPTH = 16  # templates inside templates deeper than this: a template that holds itself
MAX_INSTANCES = 1000  # instances in one document: past this, a template that multiplies itself


# the controls' tags in any namespace: the one look a document without controls costs
TAGS = tuple(f"{{*}}{t}" for t in sorted(SUPPORTED | UNSUPPORTED))


def instantiate(root, services) -> None:
    """Instantiate every user control template that applies under ``root`` (in place); then
    apply the Style triggers of the other elements when the document writes any."""
    controls = next(root.iter(*TAGS), None) is not None
    styled = next(root.iter("{*}Style.Triggers"), None) is not None
    if not controls and not styled:
        return
    run = _Instantiation(root, services, TAGS)
    if controls:
        run.run()
    if styled:
        run.styled()


class _Instantiation:
    def __init__(self, root, services, tags) -> None:
        self.root, self.sv, self.tags = root, services, tags
        self.done: set[int] = set()
        self.keep: list = []  # the elements whose ids are in ``done``
        self.pinned = False
        self.count = 0  # the templates instantiated
        self.conditions = data_triggers.Conditions(root, services)
        self.cyclic: list = []  # the controls whose template holds itself (TPL004)
        self.selection: dict[int, object] = {}  # a ComboBox's selection box content, by id

    def run(self) -> None:
        for el in list(self.root.iter(*self.tags)):
            self.control(el, 0, ())
        for owner in self.cyclic:  # WPF overflows its stack: nothing of it is drawn
            for k in list(owner):
                owner.remove(k)
            owner.text = None

    def styled(self) -> None:
        """The elements that are not controls (a TextBlock, a Border, a panel) whose Style
        has triggers: those that fire at load set the element's values where it has none of
        its own, as a control's in the theme's look (instances of templates included)."""
        for el in list(self.root.iter()):
            if not isinstance(el.tag, str) or id(el) in self.done:
                continue
            t = self.sv.wpf_type(el)
            if t is None or "." in t or t in SUPPORTED or t in UNSUPPORTED or t in _NOT_VISUAL:
                continue
            if _visual(el, self.sv):
                self.themed_triggers(Control(el, t, self.sv))

    # ----------------------------------------------------------------- one control
    def control(self, el, depth: int, chain: tuple) -> None:
        """Instantiate ``el``'s template; ``chain`` holds the (template, control) pairs of
        the instances it is inside."""
        if id(el) in self.done:
            return
        self.done.add(id(el))
        self.keep.append(el)
        t = self.sv.wpf_type(el)
        if t is None or not _visual(el, self.sv):
            return
        c = Control(el, t, self.sv)
        found = self.template_of(c)
        if found is None:
            self.themed_triggers(c)
            self.themed_format(c)
            if t == "ContentControl" and c.value("ContentTemplate") is not None:
                shown = items.template_element(c.value("ContentTemplate"), el, self.sv,
                                               "DataTemplate")  # fmt: skip
                if self.holds_itself(c, shown, chain):
                    return
                if self.room(el, depth):
                    self.presented(c)
                    self.below(el, depth, (*chain, (shown, el)))
            elif t in items.CONTAINERS and items.generates(c):
                shown = _item_template(c, self.sv)
                if self.holds_itself(c, shown, chain):
                    return
                if self.room(el, depth):
                    for sub in self.themed_items(c):
                        self.below(sub, depth, (*chain, (shown, el)))
            return
        template, where = found
        target = template.get("TargetType") if where is not THEME else None
        if target and self.sv.derives(t, target) is False:
            shown = target.strip().strip("{}").split()[-1]  # {x:Type T}: T
            msg = (f"the ControlTemplate's TargetType {shown} does not match this {t}: WPF "
                   "refuses to apply it")  # fmt: skip
            self.sv.diag("TPL012", msg, el, attr=where)
            value = c.theme_setters().get("Template") if t in THEMED else None
            if value is None or value[0] != "element" or not _is_template(value[1]):
                return
            template, where = value[1], THEME  # --lenient: the theme's look
        if t not in SUPPORTED:
            msg = (f"the ControlTemplate of this {t} is not instantiated (xaml3d instantiates "
                   "the templates of content controls): it is drawn in the theme's "
                   "look")  # fmt: skip
            self.sv.diag("TPL001", msg, el, attr=where)
            return
        shown = _item_template(c, self.sv) if t in ITEMS_CONTROLS else None
        if self.holds_itself(c, template, chain) or self.holds_itself(c, shown, chain):
            return
        if self.room(el, depth):
            instance = self.apply(c, template, themed=where is THEME)
            if instance is not None:
                self.below(instance, depth, (*chain, (template, el), (shown, el)))

    def holds_itself(self, c: Control, template, chain: tuple) -> bool:
        """Whether ``template`` is being instantiated already around ``c`` (WPF recurses until
        its stack overflows): TPL004 at the outermost control it draws, which draws nothing."""
        outer = next((owner for t, owner in chain if t is template), None)
        if template is None or outer is None:
            return False
        if all(k is not outer for k in self.cyclic):
            self.cyclic.append(outer)
            what = local_name(template.tag)
            msg = (f"this {self.sv.wpf_type(outer)}'s {what} holds a {c.type} with the same "
                   f"{what}: WPF instantiates it without end (its stack overflows): not "
                   "drawn")  # fmt: skip
            self.sv.diag("TPL004", msg, outer, once=("TPL004", id(template)))
        return True

    def room(self, el, depth: int) -> bool:
        """Whether another instance may be made at ``depth`` (counted, and the tree pinned
        before its first change), else TPL011."""
        if depth >= MAX_DEPTH or (depth and self.count >= MAX_INSTANCES):
            msg = (f"templates nested {MAX_DEPTH} deep or {MAX_INSTANCES} instances (xaml3d's "
                   "limit): not instantiated")  # fmt: skip
            self.sv.diag("TPL011", msg, el, once="depth")
            return False
        self.count += depth > 0  # the document's own controls are as many as it writes
        self.pin()
        return True

    def below(self, el, depth: int, chain: tuple) -> None:
        """The controls in what was made under ``el``."""
        for k in list(el.iter(*self.tags)):
            self.control(k, depth + 1, chain)

    def pin(self) -> None:
        if not self.pinned:
            self.sv.pin(self.root)
            self.pinned = True

    def boxes(self, c: Control) -> list:
        """The item containers of an items control (none, said, when its items are not known
        at load)."""
        self.selector(c, "ItemTemplateSelector")
        out = items.containers(c, self.sv, lambda box, item, shown: self.item_shown(
            c, box, item, shown))  # fmt: skip
        style = items.container_style(c, self.sv)
        if style is not None:
            for box in out or ():
                self.container_style(box, style)
        if out is None:
            msg = (f"this {c.type}'s ItemsSource is not known at load (a binding or a missing "
                   "resource): it shows no items")  # fmt: skip
            self.sv.diag("TPL006", msg, c.el, attr="ItemsSource" if c.el.get("ItemsSource")
                         else None)  # fmt: skip
            return []
        return out

    def themed_format(self, c: Control) -> None:
        """A content or headered control in the theme's look: its ContentStringFormat
        (HeaderStringFormat) applied to text content, which the reader then draws."""
        el = c.el
        for source in ("Content", "Header"):
            fmt = c.value(f"{source}StringFormat")
            if fmt is None or fmt[0] != "text" or c.type not in CONTENT_CONTROLS | HEADERED:
                continue
            if source == "Header" and c.type not in HEADERED:
                continue
            if c.value(f"{source}Template") is not None:
                continue  # a DataTemplate shows the content: no format (WPF's)
            shown = _content(c, source)
            if shown is None or shown[0] == "elements" and (
                    len(shown[1]) != 1 or self.sv.wpf_type(shown[1][0]) is not None):  # fmt: skip
                continue  # an element: its own visual, no format
            kind, value = shown
            if kind == "elements":
                kind, value = "element", value[0]
            number = False
            if kind == "element":
                found = string_formats.number_text(value)
                if found is None:
                    continue  # an object: shown by its DataTemplate or type name by the reader
                value, number = found
            where = f"{source}StringFormat" if el.get(f"{source}StringFormat") else None
            text = string_formats.format_text(self.sv, fmt[1], value, number, el, where)
            self.pin()
            put(self.sv, el, source, ("text", _literal(text)))
            if source == "Content":
                for k in _content_elements(el):
                    k.getparent().remove(k)
                el.text = None
                for k in el:
                    k.tail = None
            el.attrib.pop(f"{source}StringFormat", None)

    def item_shown(self, c: Control, box, item, instance) -> None:
        """An item's container: its DataContext the item (the triggers of its Style and of
        the controls inside read it), its DataTemplate's triggers applied."""
        self.conditions.item_context(box, item)
        if instance is not None:
            template = items.data_template(c, item, self.sv)
            if template is not None:
                self.data_template_triggers(template, instance, item, box)

    def data_template_triggers(self, template, instance, item, holder) -> None:
        found = data_triggers.data_template_setters(
            self.conditions, template, instance, item, holder
        )
        if found:
            self.pin()
        for el, prop, value in found:
            put(self.sv, el, prop, value)

    def themed_triggers(self, c: Control) -> None:
        """A control in the theme's look: its Style's triggers that fire at load set its
        values where it has none of its own (the reader draws them as local values)."""
        if not any(True for style in c.styles for _ in triggers(style, "Style")):
            return
        self.style_triggers(c)
        if c.triggered:
            self.pin()
            for prop, value in c.triggered.items():
                if c.local(prop) is None:
                    put(self.sv, c.el, prop, value)

    def container_style(self, box, style) -> None:
        """``ItemContainerStyle`` on a container: its Setters and the triggers it fires at load
        (IsSelected of the selected item...) as the container's values where it has none of
        its own (its template, a Setter too, is instantiated when the container is)."""
        t = self.sv.wpf_type(box) or ""
        k = Control(box, t, self.sv)
        k.styles = [style]
        k.setters = {}
        for s in setters(style):
            prop, value = s.get("Property"), setter_value(s)
            if prop and value is not None and not s.get("TargetName"):
                k.setters[property_name(prop)] = value
        self.style_triggers(k)
        for prop in (*k.setters, *k.triggered):
            if k.local(prop) is None:
                put(self.sv, box, prop, k.triggered.get(prop, k.setters.get(prop)))

    def selector(self, c: Control, prop: str) -> None:
        """A template selector is a class of the application's code: said, not run."""
        if c.value(prop) is not None:
            msg = (f"{prop} is code xaml3d does not run: the items and content are shown "
                   "without it")  # fmt: skip
            where = prop if c.el.get(prop) is not None else None
            self.sv.diag("TPL007", msg, c.el, attr=where, once=("TPL007", id(c.el)))

    def themed_items(self, c: Control) -> list:
        """The items of a control drawn in the theme's look: a ComboBox's containers as its
        children (a ListBox's go to its theme template's ItemsPresenter); an ItemsControl's
        panel in the Border of its default template (WPF's: Background, BorderBrush,
        BorderThickness and Padding bound)."""
        sv, el = self.sv, c.el
        boxes = self.boxes(c)
        if c.type != "ItemsControl":
            if c.value("ItemsPanel") is not None:
                msg = (f"the ItemsPanel of this {c.type} is not used: the theme's look stacks "
                       "its items")  # fmt: skip
                where = "ItemsPanel" if el.get("ItemsPanel") is not None else None
                sv.diag("TPL008", msg, el, attr=where)
            for k in boxes:
                el.append(k)
            return boxes
        border = self.make(el, "Border", el)
        for prop in ("Background", "BorderBrush", "BorderThickness", "Padding"):
            put(sv, border, prop, c.value(prop))
        panel = items.items_panel(c, sv, lambda: self.make(el, "StackPanel", el))
        for k in boxes:
            panel.append(k)
        border.append(panel)
        for child in _content_elements(el):
            child.getparent().remove(child)
        el.text = None
        el.append(border)
        sv.templated(el, None)
        return [border]

    def make(self, near, local: str, where):
        el = near.makeelement(_same_ns(near, local), {})
        self.sv.made(el, where)
        return el

    def template_of(self, c: Control):
        """(the ControlTemplate element, the attribute naming it or None) of a user template,
        else of the theme's (``THEME``) for the controls it draws."""
        el, sv = c.el, self.sv
        ref = el.get("Template")
        if ref is not None:
            key = markup.resource_key(ref)
            entry = sv.find(key, el) if key is not None else None
            return (entry, "Template") if _is_template(entry) else None
        for child in elements(el):
            if local_name(child.tag).endswith(".Template") and "." in local_name(child.tag):
                entry = next(iter(elements(child)), None)
                return (entry, None) if _is_template(entry) else None
        value = c.setters.get("Template")
        if value is None:
            if c.type not in THEMED or (c.type not in _OWN_ON_TOOL_BAR and _on_tool_bar(el, sv)):
                return None
            self.theme_triggers(c)
            value = c.theme_setters().get("Template")
            if value is None or value[0] != "element" or not _is_template(value[1]):
                return None  # OverridesDefaultStyle without a template of its own
            return value[1], THEME
        if value[0] == "element":
            entry = value[1]
        else:
            key = markup.resource_key(value[1])
            entry = sv.find(key, c.styles[-1]) if key is not None else None
        if not _is_template(entry):
            return None
        return entry, ("Style" if el.get("Style") is not None else None)

    def theme_triggers(self, c: Control) -> None:
        """The theme Style's triggers that fire at load (a ComboBox's IsEditable choosing the
        editable template and Padding) set theme values above the theme's Setters, below the
        control's own Style (WPF's precedence for a default Style's triggers)."""
        found = c.theme_setters()
        if not found:
            return  # OverridesDefaultStyle: no theme Style
        for style in self.sv.theme_styles(c.type):
            for trigger in triggers(style, "Style"):
                if c.fires(trigger):
                    for s in setters(trigger):
                        prop, value = s.get("Property"), setter_value(s)
                        if prop and value is not None and not s.get("TargetName"):
                            found[property_name(prop)] = value

    def selection_box(self, c: Control, themed: bool):
        """A ComboBox's items generated (its containers, as its drop-down would hold them) and
        what its selection box shows: the content of the selected container (SelectedIndex,
        an item's IsSelected, SelectedItem from a resource), shown through the ItemTemplate
        or DisplayMemberPath as the container shows it; an editable ComboBox without Text
        takes the selected item's. WPF sets SelectionBoxItem in code; here at load. Returns
        the containers."""
        picked = self.selected_item(c)
        boxes = self.boxes(c)
        if picked is not None and picked < len(boxes) and not any(
                (b.get("IsSelected") or "").strip().lower() == "true" for b in boxes):  # fmt: skip
            boxes[picked].set("IsSelected", "True")
        if themed and c.value("ItemsPanel") is not None:
            msg = (f"the ItemsPanel of this {c.type} is not used: the theme's look shows its "
                   "selected item alone (its list is a drop-down window)")  # fmt: skip
            where = "ItemsPanel" if c.el.get("ItemsPanel") is not None else None
            self.sv.diag("TPL008", msg, c.el, attr=where)
        chosen = next((b for b in boxes
                       if (b.get("IsSelected") or "").strip().lower() == "true"), None)  # fmt: skip
        shown = None
        if chosen is not None:
            shown = _content(Control(chosen, self.sv.wpf_type(chosen) or "", self.sv), "Content")
        editable = (c.value_of_own("IsEditable") or "").strip().lower() == "true"
        if editable and c.local("Text") is None and shown is not None and shown[0] == "text":
            put(self.sv, c.el, "Text", ("text", _literal(shown[1])))
        self.selection[id(c.el)] = shown
        return boxes

    def selected_item(self, c: Control) -> int | None:
        """The index of the item ``SelectedItem="{StaticResource k}"`` names (the resource
        itself, or a string equal to it: WPF compares items with Equals), else None."""
        value = c.value("SelectedItem")
        key = markup.resource_key(value[1]) if value is not None and value[0] == "text" else None
        entry = self.sv.find(key, c.el) if key is not None else None
        found = items.items_of(c, self.sv) if entry is not None else None
        if found is None:
            return None
        text = None if elements(entry) or self.sv.wpf_type(entry) else (entry.text or "")
        for i, (kind, shown, source) in enumerate(found[0]):
            if source is entry or (kind == "text" and text is not None and shown == text):
                return i
        return None

    # ----------------------------------------------------------------- instantiation
    def apply(self, c: Control, template, themed: bool = False):
        sv = self.sv
        self.style_triggers(c)
        visual = [k for k in elements(template) if "." not in local_name(k.tag)]
        instance = sv.copy(visual[0]) if visual else None
        if instance is not None and themed:
            # the theme's parts are the control's own, in the document's text
            for part in instance.iter():
                sv.made(part, c.el)
        if instance is not None:
            gap_mask.mark(sv, instance)
        if themed:
            self.theme_layout(c)
        names: dict[str, object] = {}
        parts = _parts(instance) if instance is not None else []
        for part in parts:
            for attr in (f"{{{X_NS}}}Name", "Name"):
                name = part.get(attr)
                if name is not None:
                    names.setdefault(name, part)
                    del part.attrib[attr]
        self.template_triggers_on_control(c, template, names)
        boxes = self.selection_box(c, themed) if c.type in SELECTION_BOXES else None
        if instance is not None:
            for part in parts:
                self.bind(c, part)
            for part in parts:
                if sv.wpf_type(part) == "ContentPresenter":
                    self.present(c, part)
            if c.type in ITEMS_CONTROLS | SELECTION_BOXES:
                self.host_items(c, parts, boxes)
            if c.type in TEXT_HOSTS:
                text_host.fill(sv, c, names.get(text_host.PART), _literal)
            self.template_triggers_on_parts(c, template, names)
            if c.type == "ProgressBar" and names.get("PART_Indicator") is not None:
                self.sv.indicator(names["PART_Indicator"], _progress_share(c))
        self.finish(c, instance, template)
        return instance

    def theme_layout(self, c: Control) -> None:
        """The theme Style's layout values (a Separator's Margin 0,2,0,2) on the control where
        neither it nor its Style sets them: the reader lays the control out from its own."""
        theme = c.theme_setters()
        for prop in _THEME_LAYOUT:
            value = theme.get(prop)
            if value is not None and c.local(prop) is None and prop not in c.setters:
                put(self.sv, c.el, prop, value)

    def presented(self, c: Control) -> None:
        """A ContentControl with a ContentTemplate and no template of the user's: its default
        template, a ContentPresenter, holding the content its ContentTemplate shows."""
        presenter = self.make(c.el, "ContentPresenter", c.el)
        self.present(c, presenter)
        self.finish(c, presenter, None)

    def finish(self, c: Control, instance, template) -> None:
        """The control's content taken out (what a presenter did not place is not shown) and
        the instance made its only child."""
        sv, el = self.sv, c.el
        content = _content_elements(el)
        for k in content:  # element content not placed by a presenter: not shown
            if k.getparent() is el or _is_content_property(k.getparent()):
                k.getparent().remove(k)
        for child in elements(el):
            if _is_content_property(child) and not elements(child):
                el.remove(child)
        el.text = None
        for child in el:
            child.tail = None
        if instance is not None:
            instance.tail = None
            el.append(instance)
        sv.templated(el, template)

    def host_items(self, c: Control, parts: list, boxes=None) -> None:
        """The items in the template's ItemsPresenter (the ItemsPanel's panel inside it) or
        in its panel marked IsItemsHost (``boxes``: the containers already generated)."""
        sv = self.sv
        hosts = [p for p in parts if sv.wpf_type(p) == "ItemsPresenter"
                 or (p.get("IsItemsHost") or "").strip().lower() == "true"]  # fmt: skip
        boxes = self.boxes(c) if boxes is None else boxes
        if not hosts:
            return
        host = hosts[0]
        if sv.wpf_type(host) == "ItemsPresenter":
            # laid out as the presenter it is: a plain holder of the panel
            host.tag = _same_ns(host, "ContentPresenter")
            panel = items.items_panel(c, sv, lambda: self.make(host, "StackPanel", host))
            host.append(panel)
        else:
            host.attrib.pop("IsItemsHost", None)
            panel = host
        for k in boxes:
            panel.append(k)

    def bind(self, c: Control, part) -> None:
        """The part's references to the templated parent replaced by the control's values."""
        for attr, value in list(part.attrib.items()):
            ref = markup.templated_parent_property(value)
            if ref is None:
                continue
            prop, plain = ref
            shown = ("Content", "ContentTemplate")
            if (prop in shown or attr in shown) and self.sv.wpf_type(part) == "ContentPresenter":
                continue  # placed by present()
            found = binding_data.UNEVALUATED
            if not plain:  # the framework's own converters, a StringFormat
                found = binding_data.templated_value(
                    self.sv, value, prop, c.value(prop), (part, c.el), attr
                )
            if found is not binding_data.UNEVALUATED:
                put(self.sv, part, attr, found)
                continue
            if not plain:
                msg = (f"{attr} binds the templated parent's {prop} through a converter of "
                       "the application (code): the property keeps its default")  # fmt: skip
                self.sv.diag("TPL002", msg, part, attr=attr, once=("TPL002", id(part), attr))
                del part.attrib[attr]
                continue
            value = self.from_ancestor(c, c.value(prop))
            put(self.sv, part, attr, self.in_control_scope(c, part, value))

    def from_ancestor(self, c: Control, value):
        """A Setter's binding to an ancestor's property (the theme's ListBoxItem takes its
        content alignments from ``{Binding P, RelativeSource={RelativeSource AncestorType=
        {x:Type ItemsControl}}}``): the nearest such ancestor's value of P, else None (the
        property's default, as a binding that finds no source gives)."""
        found = _ancestor_binding(value)
        if found is None:
            return value
        prop, type_name = found
        node = c.el.getparent()
        while node is not None:
            t = self.sv.wpf_type(node)
            if t is not None and binding_tree.type_matches(node, type_name):
                return Control(node, t, self.sv).value(prop)
            node = node.getparent()
        return None

    def in_control_scope(self, c: Control, part, value):
        """A resource reference in the control's value resolved where the control is: the
        part, a copy, looks resources up in its template's scope, which does not hold the
        control's resources when the template comes from another dictionary (a merged
        dictionary's file, the application's). Left as written when the part finds the key
        itself or the control does not (the reader then reports it)."""
        if value is None or value[0] != "text":
            return value
        key = markup.resource_key(value[1])
        if key is None or self.sv.find(key, part) is not None:
            return value
        entry = self.sv.find(key, c.el)
        return value if entry is None else ("element", entry)

    def present(self, c: Control, presenter) -> None:
        """A ContentPresenter filled with the control's content (or its own Content)."""
        sv = self.sv
        self.selector(c, "ContentTemplateSelector")
        source = presenter.get("ContentSource", "Content").strip()
        own = presenter.get("Content")
        template = presenter.get("ContentTemplate")
        own_format = presenter.get("ContentStringFormat")
        access = (presenter.get("RecognizesAccessKey") or "").strip().lower() == "true"
        for attr in _PRESENTER_PROPS:
            presenter.attrib.pop(attr, None)
        if own is not None:
            ref = markup.templated_parent_property(own)
            if ref is not None and ref[0] == "SelectionBoxItem" and id(c.el) in self.selection:
                source = ref[0]
                content = self.selection[id(c.el)]
            elif ref is not None:
                source = ref[0]
                content = _content(c, source)
            elif markup.split(own) is None:
                content = ("text", own)
            else:
                content = None
        else:
            content = _content(c, source)
        if template is not None:
            ref = markup.templated_parent_property(template)
            data_template = c.value(ref[0]) if ref is not None else ("text", template)
        elif source in ("Content", "Header"):
            data_template = c.value(f"{source}Template")
        else:
            data_template = None
        data_template = self.resolve_template(data_template, c.el)
        if content is None:
            return
        kind, value = content
        if kind == "elements" and len(value) == 1 and sv.wpf_type(value[0]) is None:
            kind, value = "element", value[0]  # a data object: shown by a DataTemplate
        if kind == "elements":
            for k in value:
                k.tail = None
                presenter.append(k)  # moved: an element is its own visual
            return
        data = sv.wpf_type(value) is None if kind == "element" else True
        if kind == "element" and not data:  # a WPF object from a property element or resource
            presenter.append(sv.copy(value))
            return
        item = ("text", value, None) if kind == "text" else ("data", value, value)
        if data_template is None and kind == "element":
            data_template = sv.implicit_data_template(local_name(value.tag), c.el)
        if data_template is not None:
            visual = [k for k in elements(data_template) if "." not in local_name(k.tag)]
            if visual:
                shown = sv.copy(visual[0])
                items.fill_data(shown, item, sv, c.el)
                presenter.append(shown)
                self.conditions.item_context(presenter, item)
                self.data_template_triggers(data_template, shown, item, presenter)
                return
        number = False
        if kind == "element":  # a number, or an object without a template: its type's name
            found = string_formats.number_text(value)
            value, number = found if found is not None else (local_name(value.tag), False)
        fmt = self.content_format(c, own_format, own is None, source)
        if fmt is not None:
            value = string_formats.format_text(self.sv, fmt, value, number, presenter,
                                               "ContentStringFormat")  # fmt: skip
        text = access_text(value) if access else value
        # the presenter's own TextBlock: only the application's implicit TextBlock Style
        # reaches it (WPF's look-up stops at the templated parent: resources.find_implicit)
        block = presenter.makeelement(_same_ns(presenter, "TextBlock"), {"Text": _literal(text)})
        sv.made(block, presenter)
        presenter.append(block)

    def content_format(self, c: Control, own: str | None, from_control: bool, source: str):
        """The format a presenter applies: its own ContentStringFormat (a TemplateBinding
        read on the control), else the control's ``{source}StringFormat`` when it shows the
        control's property."""
        if own is not None:
            ref = markup.templated_parent_property(own)
            if ref is None:
                return own
            v = c.value(ref[0])
        elif from_control and source in ("Content", "Header"):
            v = c.value(f"{source}StringFormat")
        else:
            return None
        return v[1] if v is not None and v[0] == "text" else None

    def resolve_template(self, value, where):
        if value is None:
            return None
        if value[0] == "element":
            return value[1] if local_name(value[1].tag) == "DataTemplate" else None
        key = markup.resource_key(value[1])
        entry = self.sv.find(key, where) if key is not None else None
        return entry if entry is not None and local_name(entry.tag) == "DataTemplate" else None

    # ----------------------------------------------------------------- triggers
    def _fired(self, c: Control, trigger, parts: dict | None = None) -> bool:
        """Whether ``trigger`` fires on ``c`` at load (``parts``: its template's named parts,
        which a SourceName reads)."""
        kind = local_name(trigger.tag)
        if kind == "EventTrigger":
            return False  # storyboards: the animation reader's
        if data_triggers.reads_other(trigger):
            verdict = self.conditions.fires(trigger, c.el, c, parts)
        else:
            verdict = c.fires(trigger)
        if verdict is None:
            msg = (f"this {kind}'s condition is not known at load (a binding, another "
                   "element's property or code): its Setters are not applied")  # fmt: skip
            self.sv.diag("TPL003", msg, trigger, once=("TPL003", id(trigger)))
            return False
        return verdict

    def style_triggers(self, c: Control) -> None:
        for style in c.styles:
            for trigger in triggers(style, "Style"):
                if self._fired(c, trigger):
                    for s in setters(trigger):
                        prop, value = s.get("Property"), setter_value(s)
                        if prop and value is not None:
                            c.triggered[property_name(prop)] = value

    def template_triggers_on_control(self, c: Control, template, names: dict) -> None:
        for trigger in triggers(template, "ControlTemplate"):
            if self._fired(c, trigger, names):
                for s in setters(trigger):
                    prop, value = s.get("Property"), setter_value(s)
                    # below the Style's triggers: only what they leave unset
                    if prop and value is not None and not s.get("TargetName"):
                        c.triggered.setdefault(property_name(prop), value)
        for prop, value in c.triggered.items():
            if c.local(prop) is None:  # the control's value at load, seen by the reader
                put(self.sv, c.el, prop, value)

    def template_triggers_on_parts(self, c: Control, template, names: dict) -> None:
        for trigger in triggers(template, "ControlTemplate"):
            fired = self._fired(c, trigger, names)
            for s in setters(trigger):
                prop, target, value = s.get("Property"), s.get("TargetName"), setter_value(s)
                if not prop or not target or value is None:
                    continue
                part = names.get(target)
                if part is None:  # WPF checks every trigger's targets when it seals
                    data_triggers.unknown_target(self.sv, s, target, names)
                    continue
                if fired:
                    put(self.sv, part, property_name(prop), value)


# --------------------------------------------------------------------------- helpers


def _item_template(c: Control, sv):
    """The DataTemplate element an items control's ItemTemplate names, or None."""
    value = c.value("ItemTemplate")
    return None if value is None else items.template_element(value, c.el, sv, "DataTemplate")


# a property's name, or an attached one's Owner.Name: what a Setter may name
_MEMBER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)?\Z")


def put(sv, el, prop: str, value) -> None:
    """Set ``el``'s property ``prop`` to ``value`` (text, or an element copied into a property
    element), replacing how it was written before; None clears it (the default stands). A
    name that is no property name (``Background,``) is not set: the reader's checks refuse it."""
    if not _MEMBER.match(prop):
        return
    el.attrib.pop(prop, None)
    for child in elements(el):
        local = local_name(child.tag)
        if "." in local and property_name(local) == property_name(prop):
            el.remove(child)
    if value is None:
        return
    kind, v = value
    if kind == "text":
        el.set(prop, v)
        return
    owner = prop if "." in prop else f"{local_name(el.tag)}.{prop}"
    holder = el.makeelement(_same_ns(el, owner), {})
    sv.made(holder, el)
    made = sv.copy(v)
    made.attrib.pop(f"{{{X_NS}}}Key", None)  # a resource entry's copy, now a property value
    holder.append(made)
    el.insert(0, holder)


def _progress_share(c: Control) -> float:
    """The share of PART_Track's width a ProgressBar's PART_Indicator takes, as WPF's
    ProgressBar sets it in code: 1 when IsIndeterminate or Maximum <= Minimum, else Value's
    place in Minimum..Maximum (Value coerced into that range, as RangeBase does)."""

    def number(prop: str, default: float) -> float:
        hit = c.value(prop)
        try:
            x = float(hit[1]) if hit is not None and hit[0] == "text" else default
        except ValueError:
            return default  # a binding or resource: the property's default
        return x if math.isfinite(x) else default

    indeterminate = c.value("IsIndeterminate")
    lo, hi = number("Minimum", 0.0), number("Maximum", 100.0)
    hi = max(hi, lo)  # RangeBase coerces Maximum up to Minimum
    if (indeterminate is not None and indeterminate[0] == "text"
            and indeterminate[1].strip().lower() == "true") or hi <= lo:  # fmt: skip
        return 1.0
    return (min(hi, max(lo, number("Value", 0.0))) - lo) / (hi - lo)


def _ancestor_binding(value) -> tuple[str, str] | None:
    """(property, ancestor type) of ``{Binding P, RelativeSource={RelativeSource
    AncestorType={x:Type T}}}`` (FindAncestor, the first such ancestor), else None."""
    if value is None or value[0] != "text":
        return None
    m = markup.split(value[1])
    if m is None or m[0] != "Binding":
        return None
    positional, named = markup.arguments(m[1])
    rs = markup.split(named.get("RelativeSource"))
    if rs is None or rs[0] != "RelativeSource" or named.keys() - {"Path", "RelativeSource"}:
        return None
    rpos, rnamed = markup.arguments(rs[1])
    mode = rnamed.get("Mode", rpos[0] if rpos else "FindAncestor")
    raw = rnamed.get("AncestorType") or ""
    kind = markup.split(raw)  # {x:Type T}, or T written plainly (its type converter)
    type_name = kind[1] if kind is not None and kind[0] == "Type" else None
    if kind is None and raw.strip() and "{" not in raw:
        type_name = raw
    if mode != "FindAncestor" or not type_name or "AncestorLevel" in rnamed:
        return None
    prop = named.get("Path", positional[0] if positional else "").strip()
    if not prop or "." in prop or "[" in prop:
        return None
    return prop, type_name.split(":")[-1].strip()


def _same_ns(el, local: str) -> str:
    ns = el.tag.rpartition("}")[0]
    return f"{ns}}}{local}" if ns else local


def _literal(text: str) -> str:
    """Text set as an attribute value: a leading brace escaped (not a markup extension)."""
    return "{}" + text if text.lstrip().startswith("{") else text


def _on_tool_bar(el, sv) -> bool:
    """Whether ``el`` is an item of a ToolBar, which gives its buttons a Style of its own
    (ToolBar.ButtonStyleKey: drawn by the reader's ToolBar) instead of the theme's."""
    node = el.getparent()
    if node is not None and local_name(node.tag) == "ToolBar.Items":
        node = node.getparent()
    return node is not None and sv.wpf_type(node) == "ToolBar"


def _is_template(el) -> bool:
    return el is not None and isinstance(el.tag, str) and local_name(el.tag) == "ControlTemplate"


def _visual(el, sv) -> bool:
    """Whether ``el`` is in the visual tree (not inside a Style, template or dictionary, nor in
    a property element whose value is not laid out)."""
    node = el.getparent()
    while node is not None:
        local = local_name(node.tag)
        owned = local.rpartition(".")[2] if "." in local else None
        if local in _NOT_VISUAL or owned in _NOT_VISUAL_PROPERTIES:
            return False
        node = node.getparent()
    return True


def _parts(instance) -> list:
    """The instance's elements that belong to the template (not inside a nested template or
    Style, whose content is built when that is applied)."""
    out = []
    stack = [instance]
    while stack:
        el = stack.pop()
        if not isinstance(el.tag, str):
            continue
        out.append(el)
        if local_name(el.tag) not in _NOT_VISUAL:
            stack.extend(reversed(elements(el)))
    return out


def _is_content_property(el) -> bool:
    if el is None:
        return False
    local = local_name(el.tag)
    return "." in local and local.rpartition(".")[2] in ("Content", "Header")


def _content_elements(el) -> list:
    """The control's content elements: children that are not property elements, and those of
    ``<X.Content>``."""
    out = []
    for child in elements(el):
        local = local_name(child.tag)
        if "." not in local:
            out.append(child)
        elif local.rpartition(".")[2] == "Content":
            out.extend(elements(child))
    return out


def _content(c: Control, source: str):
    """The control's ``source`` property (Content, Header) as a presenter shows it:
    ("text", str), ("elements", [el...]) to move, ("element", el) to copy, or None."""
    el = c.el
    if source == "Content":
        kids = _content_elements(el)
        if kids:
            return ("elements", kids)
        raw = el.get("Content")
        if raw is None:
            for child in elements(el):
                if local_name(child.tag).rpartition(".")[2] == "Content" and "." in local_name(
                    child.tag
                ):
                    text = (child.text or "").strip()
                    return ("text", text) if text else None
            text = _text_content(el)
            if text:
                return ("text", text)
            value = c.value("Content")
            return _shown(c, value)
        return _shown(c, ("text", raw))
    value = c.value(source)
    return _shown(c, value)


def _text_content(el) -> str:
    """The text an element holds as its content (around its property elements), its white
    space collapsed as XAML's is."""
    parts = [el.text or "", *(k.tail or "" for k in el)]
    return " ".join("".join(parts).split())


def _shown(c: Control, value):
    if value is None:
        return None
    kind, v = value
    if kind == "element":
        return ("element", v)
    key = markup.resource_key(v)
    if key is not None:
        entry = c.services.find(key, c.el)
        if entry is None:
            return None
        if local_name(entry.tag) == "String":
            return ("text", entry.text or "")
        return ("element", entry)
    if markup.split(v) is not None:
        return None  # a binding or extension the bindings step left: nothing to show
    return ("text", v)
