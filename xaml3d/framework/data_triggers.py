"""Trigger conditions that read a binding or another element: ``DataTrigger`` and
``MultiDataTrigger`` (in Style.Triggers, ControlTemplate.Triggers and DataTemplate.Triggers) and
a template ``Trigger`` / ``Condition`` with ``SourceName`` (the named part's property).

A DataTrigger's Binding is evaluated as WPF evaluates it at load (binding_eval.py), on the
element WPF attaches it to: the styled element for a Style, the templated parent for a
ControlTemplate (``RelativeSource Self`` and ``TemplatedParent`` are both that control), the
ContentPresenter for a DataTemplate (its DataContext the item). The value is compared with
``Value`` as WPF's trigger compares them, the written value converted to the source value's
type: booleans case-insensitively, numbers as numbers, enumerations by name (case-insensitively,
as Enum.Parse reads them), strings as written; ``{x:Null}`` matches null. A value of a type of
the application's code (a data object's attribute) has no type the markup says: it is compared
as a boolean or a number when both read as one, else as a string.

A binding that needs code (a DataContext set by code-behind, a converter class) leaves the
trigger unfired, said once per kind (BND001); one WPF's binding fails on too (no such
element, no such property) leaves it unfired, said (BND003).
"""

from __future__ import annotations

import math

from xaml3d.framework import markup
from xaml3d.framework.binding_eval import Cycle, Evaluator
from xaml3d.framework.binding_sites import binding_element_extension
from xaml3d.framework.binding_tree import is_wpf, local, name_scope, object_parent
from xaml3d.framework.binding_values import (
    Unresolved,
    Value,
    as_bool,
    clr_of,
    default,
    display_text,
)
from xaml3d.framework.markup_syntax import (
    Extension,
    MarkupSyntaxError,
    is_extension,
    literal,
    parse,
)
from xaml3d.framework.styles import (
    X_NS,
    elements,
    local_name,
    property_name,
    setter_value,
    setters,
)

KINDS = ("DataTrigger", "MultiDataTrigger")
_NUMBERS = ("Double", "Int32")


def conditions(trigger) -> list:
    """A trigger's conditions: itself (Trigger, DataTrigger), or its ``<X.Conditions>``."""
    kind = local_name(trigger.tag)
    if kind in ("Trigger", "DataTrigger"):
        return [trigger]
    return [c for holder in elements(trigger)
            if local_name(holder.tag) == f"{kind}.Conditions"
            for c in elements(holder)]  # fmt: skip


def reads_other(trigger) -> bool:
    """Whether the trigger is one this module decides (a DataTrigger, or a condition with
    SourceName or Binding)."""
    if local_name(trigger.tag) in KINDS:
        return True
    return any(c.get("SourceName") is not None for c in conditions(trigger))


class Conditions:
    """The conditions of one document's triggers (``root``: the tree whose name scope
    ElementName reads; ``services``: the reader's)."""

    def __init__(self, root, services) -> None:
        self.root, self.sv = root, services
        self._names: dict | None = None
        self.contexts: dict[int, tuple] = {}  # id(el) -> (el, item Value): item containers

    def names(self) -> dict:
        if self._names is None:
            self._names = name_scope(self.root)
        return self._names

    def item_context(self, el, item) -> None:
        """``el`` (an item's container or template instance) has ``item`` as DataContext."""
        self.contexts[id(el)] = (el, item_value(item))

    # ----------------------------------------------------------------- a trigger
    def fires(self, trigger, el, control=None, parts: dict | None = None, item=None) -> bool | None:
        """Whether ``trigger`` fires on ``el`` at load: True, False, or None when a condition
        on a property is not known. ``control``: the styled control (styles.Control) whose
        properties a plain condition reads; ``parts``: its template's parts by name; ``item``:
        the data of a DataTemplate. A binding that needs code or fails: False, said here."""
        verdict: bool | None = True
        found = conditions(trigger)
        if not found:
            return False  # WPF refuses a MultiTrigger without conditions (XAML025)
        for c in found:
            wanted = c.get("Value")
            if wanted is None:
                wanted = _value_element_text(c)
            if wanted is None:
                return False
            m = markup.split(wanted)
            if m is not None and m[0] != "Null":
                verdict = None  # {x:Static}, a resource: a value of code xaml3d does not read
                continue
            binding = _binding(c)
            if binding is not None:
                v = self._binding_value(c, binding, el, item)
                if v is None:
                    return False
                held = matches(v, wanted)
            elif c.get("SourceName") is not None:
                held = self._source_holds(c, wanted, parts, control)
            else:
                prop = c.get("Property")
                if not prop or control is None:
                    return False if not prop else None
                held = control.holds(property_name(prop), wanted)
            if held is False:
                return False
            if held is None:
                verdict = None
        return verdict

    def _binding_value(self, cond, binding, el, item) -> Value | None:
        ev = _TriggerEvaluator(self, el, item)
        try:
            return ev.binding_value(el, "", binding)
        except Cycle:
            return None
        except Unresolved as u:
            self._say(u, cond)
            return None

    def _say(self, u: Unresolved, cond) -> None:
        if u.code == "BND001":
            msg = (f"this {local_name(cond.tag)}'s Binding needs code ({u.detail}): its Setters "
                   "are not applied (said once for every binding that needs this)")  # fmt: skip
            self.sv.diag("BND001", msg, cond, attr=_binding_attr(cond), once=("BND001", u.kind))
        elif u.code is not None:
            msg = (f"this {local_name(cond.tag)}'s Binding fails in WPF too ({u.detail}): its "
                   "Setters are not applied")  # fmt: skip
            self.sv.diag("BND003", msg, cond, attr=_binding_attr(cond), once=("BND003", id(cond)))

    def _source_holds(self, cond, wanted: str, parts: dict | None, control) -> bool | None:
        """A condition on the property of the template part ``SourceName`` names."""
        name = cond.get("SourceName", "").strip()
        if parts is None:
            return None  # a Style's trigger: SourceName names a template's part
        part = parts.get(name)
        prop = cond.get("Property")
        if part is None or not prop:
            if part is None:
                msg = f"SourceName {name!r} names no part of this template: the trigger is skipped"
                self.sv.diag("TPL009", msg, cond, attr="SourceName", once=("TPL009", id(cond)))
            return False
        prop = property_name(prop)
        raw = part.get(prop)
        ref = markup.templated_parent_property(raw)
        if ref is not None and control is not None and ref[1]:
            v = control.value(ref[0])  # a part not bound yet: the control's value
            raw = v[1] if v is not None and v[0] == "text" else None
            if v is not None and raw is None:
                return None
        if raw is not None and markup.split(raw) is not None:
            return None  # a binding or resource: not known here
        if raw is not None:
            return matches(Value(literal(raw), clr_of(prop)), wanted)
        t = self.sv.wpf_type(part) or local(part)
        d = default(t, prop)
        return None if d is None else matches(d, wanted)


class _TriggerEvaluator(Evaluator):
    """The evaluator with a trigger's context: ``TemplatedParent`` is the control the
    trigger's template styles (``el``), and the DataContext of an item's template is the
    item (``item``, or the nearest container the generator made)."""

    def __init__(self, conditions: Conditions, el, item) -> None:
        super().__init__(conditions.sv, conditions.names(), {})
        self.parent, self.item, self.ctx = el, item, conditions

    def _relative(self, el, rel) -> Value:
        if isinstance(rel, Extension) and rel.name in ("RelativeSource", "RelativeSourceExtension"):
            mode = rel.arg("Mode")
            if isinstance(mode, str) and mode.strip() == "TemplatedParent":
                return Value(el=self.parent, visual=True)
        return super()._relative(el, rel)

    def _data_context(self, el, prop: str) -> Value:
        if self.item is not None:
            return item_value(self.item)
        node = el
        while node is not None:
            if self._sets(node, "DataContext"):
                break
            hit = self.ctx.contexts.get(id(node))
            if hit is not None:
                return hit[1]
            node = object_parent(node)
        return super()._data_context(el, prop)


# --------------------------------------------------------------------------- comparison


def matches(v: Value, wanted: str) -> bool:
    """Whether the source value ``v`` equals the trigger's ``Value`` text converted to its
    type."""
    m = markup.split(wanted)
    if m is not None:
        return m[0].split(":")[-1] == "Null" and v.null
    wanted = literal(wanted)
    if v.null or v.el is not None or v.items is not None or v.text is None:
        return False  # null, or an object: a written value converts to no such object
    clr, text, w = v.clr, display_text(v), wanted.strip()
    if clr == "Boolean":
        return text.strip().lower() == w.lower()
    if clr in _NUMBERS:
        return _numbers_equal(text, w)
    if clr == "Brush":
        return False  # a brush compares by identity: a written one is another object
    if clr == "String":
        return text == wanted
    if clr == "Object":  # untyped (Tag) or a code type's property: read as what both are
        b1, b2 = as_bool(Value(text)), as_bool(Value(w))
        if b1 is not None and b2 is not None:
            return b1 == b2
        return text == wanted or _numbers_equal(text, w)
    return text.strip().lower() == w.lower()  # an enumeration: by name


def _numbers_equal(a: str, b: str) -> bool:
    """Double.Equals: NaN equals NaN."""
    try:
        x, y = float(a), float(b)
    except ValueError:
        return False
    return x == y or (math.isnan(x) and math.isnan(y))


def item_value(item) -> Value:
    """An item (items.py's tuple) as a binding's source value."""
    kind, value, _ = item
    if kind == "text":
        return Value(value, "String")
    return Value(el=value)


# --------------------------------------------------------------------------- the markup


def _binding(cond) -> Extension | None:
    """A condition's Binding (attribute or ``<X.Binding>`` element form), or None."""
    raw = cond.get("Binding")
    if raw is not None:
        if not is_extension(raw):
            return None
        try:
            return parse(raw)
        except MarkupSyntaxError:
            return None  # said by the reader (XAML016)
    for child in elements(cond):
        if local_name(child.tag).endswith(".Binding"):
            kids = elements(child)
            if len(kids) == 1 and is_wpf(kids[0]):
                try:
                    return binding_element_extension(kids[0])
                except MarkupSyntaxError:
                    return None
    return None


def _binding_attr(cond) -> str | None:
    return "Binding" if cond.get("Binding") is not None else None


def _value_element_text(cond) -> str | None:
    """``<DataTrigger.Value>text</DataTrigger.Value>`` (a primitive written as an element)."""
    for child in elements(cond):
        if local_name(child.tag).endswith(".Value"):
            kids = elements(child)
            if not kids:
                return (child.text or "").strip()
            if len(kids) == 1 and not elements(kids[0]):
                return (kids[0].text or "").strip()
    return None


# --------------------------------------------------------------------------- DataTemplate


def data_template_setters(conds: Conditions, template, instance, item, holder) -> list:
    """The Setters of ``template``'s DataTemplate.Triggers that fire for ``item``, shown by
    ``instance`` (the template's copy) in ``holder`` (the ContentPresenter or container that
    holds it): [(element, property, value)], each Setter's TargetName a named part of the
    instance, else the holder. Only DataTriggers and MultiDataTriggers are decided (a
    Trigger reads the presenter's state: not known, TPL003)."""
    out: list = []
    holder_type = conds.sv.wpf_type(holder) if holder is not None else None
    names: dict | None = None
    for trigger in _triggers(template):
        kind = local_name(trigger.tag)
        if kind == "EventTrigger":
            continue
        if kind not in KINDS:
            msg = (f"this {kind}'s condition is not known at load (the presenter's state): "
                   "its Setters are not applied")  # fmt: skip
            conds.sv.diag("TPL003", msg, trigger, once=("TPL003", id(trigger)))
            continue
        verdict = conds.fires(trigger, holder if holder is not None else instance, item=item)
        if verdict is None:
            msg = (f"this {kind}'s condition is not known at load (a Value of code): its "
                   "Setters are not applied")  # fmt: skip
            conds.sv.diag("TPL003", msg, trigger, once=("TPL003", id(trigger)))
        if not verdict:
            continue
        if names is None:
            names = _names(instance)
        for s in setters(trigger):
            prop, target, value = s.get("Property"), s.get("TargetName"), setter_value(s)
            if not prop or value is None:
                continue
            if target is None:
                if holder_type != "ContentPresenter":
                    msg = (f"a DataTemplate trigger's Setter without TargetName sets the "
                           f"presenter inside this {holder_type or 'container'}: not "
                           "applied")  # fmt: skip
                    conds.sv.diag("TPL003", msg, s, once=("TPL003", id(s)))
                    continue
                out.append((holder, property_name(prop), value))
                continue
            part = names.get(target.strip())
            if part is None:
                unknown_target(conds.sv, s, target, names)
                continue
            out.append((part, property_name(prop), value))
    return out


def unknown_target(sv, setter, target: str, names) -> None:
    """TPL005: a trigger Setter's TargetName that names no part of the template (WPF throws
    at load: "Cannot find the Trigger target"), with the closest part name."""
    import difflib  # only for a name that is wrong

    near = difflib.get_close_matches(target.strip(), sorted(names), 1, 0.7)
    hint = f" (did you mean {near[0]}?)" if near else ""
    msg = f"TargetName {target!r} names no part of this template{hint}: WPF refuses the file"
    sv.diag("TPL005", msg, setter, attr="TargetName", once=("TPL005", id(setter)))


def _triggers(template) -> list:
    return [t for holder in elements(template)
            if local_name(holder.tag) == "DataTemplate.Triggers"
            for t in elements(holder)]  # fmt: skip


def _names(instance) -> dict:
    """The named elements of a template's copy (its name scope)."""
    out: dict = {}
    for el in instance.iter():
        if not isinstance(el.tag, str):
            continue
        for attr in (f"{{{X_NS}}}Name", "Name"):
            name = el.get(attr)
            if name is not None:
                out.setdefault(name.strip(), el)
    return out
