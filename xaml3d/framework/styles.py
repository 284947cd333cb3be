"""A control's Style and its property values as WPF's value precedence gives them at load:
local value, then Style triggers, then template triggers (those of the control's template
without TargetName), then Style setters (``BasedOn`` chains: the derived Style's win), then
the theme Style's setters (the package's theme dictionary, ``Services.theme_styles``), then
the theme's values not yet written as XAML and the properties' defaults (``aero2``).

A value is ``("text", str)`` (an attribute's text, markup extensions kept for the reader) or
``("element", el)`` (an object written as an element: a brush, a template).
"""

from __future__ import annotations

from xaml3d.framework import markup
from xaml3d.framework.aero2 import theme_value

STYLE_DEPTH = 16  # BasedOn chains longer than this are cut (a cycle, or hostile markup)
X_NS = "http://schemas.microsoft.com/winfx/2006/xaml"
# attached properties keep their owner (markup.ATTACHED_OWNERS); others are named without it
# (Button.Background)
ATTACHED_OWNERS = markup.ATTACHED_OWNERS
# attached properties whose owner also has properties of its own
ATTACHED = {"ItemsControl.AlternationIndex"}


def local_name(tag) -> str:
    return tag.rpartition("}")[2] if isinstance(tag, str) else ""


def elements(el) -> list:
    return [k for k in el if isinstance(k.tag, str)]


def property_name(prop: str) -> str:
    """A Setter's or Trigger's Property without its owner, unless it is attached."""
    owner, _, short = prop.strip().rpartition(".")
    owner = owner.split(":")[-1]
    attached = owner in ATTACHED_OWNERS or f"{owner}.{short}" in ATTACHED
    return f"{owner}.{short}" if attached else short


def setter_value(setter):
    """A Setter's value: its Value attribute, or what its ``<Setter.Value>`` holds (one
    element, or text); None when it has none."""
    value = setter.get("Value")
    if value is not None:
        return ("text", value)
    for child in elements(setter):
        if local_name(child.tag) == "Setter.Value":
            kids = elements(child)
            if kids:
                return ("element", kids[0])
            text = (child.text or "").strip()
            return ("text", text) if text else None
    return None


def setters(holder):
    """The Setters of a Style, Trigger or MultiTrigger (direct, or in ``<X.Setters>``)."""
    for child in elements(holder):
        local = local_name(child.tag)
        if local == "Setter":
            yield child
        elif local.endswith(".Setters"):
            yield from (k for k in elements(child) if local_name(k.tag) == "Setter")


def triggers(holder, owner: str):
    """The triggers of a Style or ControlTemplate (``<owner.Triggers>``)."""
    for child in elements(holder):
        if local_name(child.tag) == f"{owner}.Triggers":
            yield from elements(child)


class Control:
    """One control's Style chain and effective values (``services``: the reader's)."""

    def __init__(self, el, type_name: str, services) -> None:
        self.el, self.type, self.services = el, type_name, services
        self.styles = self._style_chain()  # base first
        self.setters: dict[str, tuple] = {}
        for style in self.styles:
            for s in setters(style):
                prop, value = s.get("Property"), setter_value(s)
                if prop and value is not None and not s.get("TargetName"):
                    self.setters[property_name(prop)] = value
        self.triggered: dict[str, tuple] = {}  # Style triggers' and template triggers' values
        self._theme: dict[str, tuple] | None = None  # read on first use: theme_setters()

    # ----------------------------------------------------------------- the Style
    def _style_chain(self) -> list:
        sv, el = self.services, self.el
        ref = el.get("Style")
        style = None
        given = True  # a Style the element names (an implicit one is keyed by its very type)
        if ref is not None:
            key = markup.resource_key(ref)
            style = sv.find(key, el) if key is not None else None
        else:
            for child in elements(el):
                if local_name(child.tag).endswith(".Style"):
                    style = next(iter(elements(child)), None)
                    break
            else:
                style, given = sv.implicit_style(self.type, el), False
        target = style.get("TargetType") if given and style is not None else None
        if target and sv.derives(self.type, target) is False:
            return []  # WPF refuses a Style of another type (the reader says it: XAML022)
        chain = []
        while style is not None and local_name(style.tag) == "Style" and len(chain) < STYLE_DEPTH:
            chain.append(style)
            based = style.get("BasedOn")
            m = markup.split(based)
            if m is None:
                break
            if m[0] == "Type":
                style = sv.implicit_style(m[1].split(":")[-1].strip(), style)
            else:
                key = markup.resource_key(based)
                style = sv.find(key, style) if key is not None else None
        return chain[::-1]

    def theme_setters(self) -> dict[str, tuple]:
        """The Setters of the control's theme Style chain (the lowest Style precedence: WPF
        applies it beside the user's Style, unless OverridesDefaultStyle), read on first use."""
        if self._theme is None:
            self._theme = {}
            if (self.value_of_own("OverridesDefaultStyle") or "").strip().lower() != "true":
                for style in self.services.theme_styles(self.type):
                    for s in setters(style):
                        prop, value = s.get("Property"), setter_value(s)
                        if prop and value is not None and not s.get("TargetName"):
                            self._theme[property_name(prop)] = value
        return self._theme

    def value_of_own(self, prop: str) -> str | None:
        """``prop`` as the control or its Style writes it (text), else None."""
        hit = self.local(prop) or self.setters.get(prop)
        return hit[1] if hit is not None and hit[0] == "text" else None

    # ----------------------------------------------------------------- values
    def local(self, prop: str):
        """The control's local value of ``prop`` (attribute or property element), or None."""
        el = self.el
        raw = el.get(prop)
        if raw is not None:
            return ("text", raw)
        for child in elements(el):
            local = local_name(child.tag)
            if "." in local and property_name(local) == prop:
                kids = elements(child)
                if kids:
                    return ("element", kids[0])
                text = (child.text or "").strip()
                return ("text", text) if text else None
        return None

    def value(self, prop: str, triggered: bool = True):
        """The effective value of ``prop`` (``triggered``: the triggers' values included)."""
        hit = self.local(prop)
        if hit is None and triggered:
            hit = self.triggered.get(prop)
        if hit is None:
            hit = self.setters.get(prop)
        if hit is None:
            hit = self.theme_setters().get(prop)
        if hit is None:
            text = theme_value(self.type, prop)
            hit = None if text is None else ("text", text)
        return hit

    def holds(self, prop: str, wanted: str) -> bool | None:
        """Whether ``prop``'s value at load (triggers aside) is ``wanted``; None when it is not
        known without running code (a binding, a resource)."""
        if prop == "IsEnabled" and wanted.strip().lower() in ("true", "false"):
            # WPF coerces IsEnabled to false below a disabled element: an ancestor's counts
            disabled = self.disabled_above()
            if disabled:
                return wanted.strip().lower() == "false"
        if prop == "IsDefaulted" and self.type == "Button":
            # a default Button is defaulted at load (the window's focus is on no other button)
            prop = "IsDefault"
        if prop == "HasContent":
            return self.has_content() == (wanted.strip().lower() == "true")
        null = _is_null(wanted)  # Value="{x:Null}": IsChecked's third state, an unset value
        v = self.value(prop, triggered=False)
        if v is None or v[0] != "text":
            return None if v is not None else null
        text = v[1].strip()
        if _is_null(text):
            return null
        if null:
            return False if markup.split(text) is None else None
        if markup.split(text) is not None:
            return None
        return text.lower() == wanted.strip().lower()

    def has_content(self) -> bool:
        """ContentControl.HasContent: whether the control's Content (an attribute, element
        or text content, ``<X.Content>``, a Style's Setter) is set and not null."""
        el = self.el
        if (el.text or "").strip() or any((k.tail or "").strip() for k in el):
            return True
        for child in elements(el):
            local = local_name(child.tag)
            if "." not in local or (local.rpartition(".")[2] == "Content" and (
                    elements(child) or (child.text or "").strip())):  # fmt: skip
                return True
        v = self.local("Content") or self.setters.get("Content")
        return v is not None and not (v[0] == "text" and _is_null(v[1]))

    def disabled_above(self) -> bool:
        """Whether an ancestor of the control (in the tree as instantiated so far: a template's
        part sees its templated parent) is written disabled (``IsEnabled="False"``)."""
        node = self.el.getparent()
        while node is not None:
            if (node.get("IsEnabled") or "").strip().lower() == "false":
                return True
            node = node.getparent()
        return False

    def fires(self, trigger) -> bool | None:
        """Whether a Trigger or MultiTrigger's condition holds at load (None: not known)."""
        kind = local_name(trigger.tag)
        if kind == "Trigger":
            conditions = [trigger]
        elif kind == "MultiTrigger":
            conditions = [c for holder in elements(trigger)
                          if local_name(holder.tag) == "MultiTrigger.Conditions"
                          for c in elements(holder)]  # fmt: skip
        else:
            return None
        if not conditions:
            return False  # WPF refuses a MultiTrigger without conditions (XAML025)
        verdict: bool | None = True
        for c in conditions:
            prop, wanted = c.get("Property"), c.get("Value")
            if not prop or wanted is None or c.get("SourceName"):
                return None
            held = self.holds(property_name(prop), wanted)
            if held is False:
                return False
            if held is None:
                verdict = None
        return verdict


def _is_null(text: str) -> bool:
    m = markup.split(text)
    return m is not None and m[0] == "Null"
