"""The text an element's content holds, as WPF's XAML reader hands it over (visual_text,
inline_text, templates: the text of TextBlock, TextBox, the content controls and the headers).

- A property given as a property element (``<TextBlock.Text>Hello</TextBlock.Text>``,
  ``<Button.Content>OK</Button.Content>``, ``<ContentControl.Content>`` on a Button) holds the
  same text as the attribute form: ``property_element`` finds it, whatever type names it.
- White space in element content is XAML's: runs of spaces, tabs and line feeds become one
  space, none is kept at the start and the end (``xaml_text``); only those four characters are
  white space (a no-break space stays). ``xml:space="preserve"`` on the element or an ancestor
  keeps the text as written, line feeds included (``preserves_space``).
- AccessText (``xaml3d.access_text``, shared with the framework step): the text of a
  control whose template's ContentPresenter has RecognizesAccessKey="True" (Aero2: Label,
  Button, ToggleButton, RepeatButton, CheckBox, RadioButton; the headers of GroupBox, Expander,
  TabItem and MenuItem) loses its first lone underscore, the access-key marker; ``__`` shows
  one underscore. The access key is underlined only while Alt is held, so never in a still
  picture.
"""

from __future__ import annotations

import re

from xaml3d.xaml.context import qname

XML_SPACE = "{http://www.w3.org/XML/1998/namespace}space"
# XAML's white space: what the XML reader leaves of CR LF is LF; a no-break space is text
_WHITE = re.compile(r"[ \t\r\n]+")
# the controls whose Aero2 template shows string content through AccessText (their
# ContentPresenter's RecognizesAccessKey="True"); a TextBlock, a TextBox, a ListBoxItem and a
# ComboBoxItem show an underscore as it is
ACCESS_KEY_CONTROLS = frozenset(
    {"Label", "Button", "ToggleButton", "RepeatButton", "CheckBox", "RadioButton"}
)


def preserves_space(el) -> bool:
    """Whether ``xml:space="preserve"`` is in effect at ``el``: the nearest xml:space, on the
    element or an ancestor, decides (XML scopes it so)."""
    node = el
    while node is not None:
        if isinstance(node.tag, str):
            mode = node.get(XML_SPACE)
            if mode is not None:
                return mode == "preserve"
        node = node.getparent()
    return False


def xaml_text(text: str, preserve: bool = False) -> str:
    """Element content as XAML reads it: white space runs collapsed to one space and none at
    either end, unless ``preserve`` (xml:space="preserve")."""
    if preserve:
        return text
    return _WHITE.sub(" ", text).strip(" ")


def split_words(text: str) -> list[str]:
    """``text`` cut at XAML white space (``str.split`` would cut at a no-break space too)."""
    return [w for w in _WHITE.split(text) if w]


def is_white(c: str) -> bool:
    return c in " \t\r\n"


def property_element(el, prop: str):
    """The property element that sets ``prop`` on ``el`` (``<Owner.prop>``, whichever type
    owns it: ``ContentControl.Content`` sets a Button's Content), or None."""
    for child in el:
        if isinstance(child.tag, str):
            local = qname(child.tag)[1]
            if "." in local and local.rpartition(".")[2] == prop:
                return child
    return None


def holder_text(holder) -> str | None:
    """The text a property element holds, as XAML reads it; None when it holds an element (a
    TextBlock, a markup extension element...): that is not text."""
    if any(isinstance(k.tag, str) for k in holder):
        return None
    return xaml_text(holder.text or "", preserves_space(holder))


def content_text(el) -> str:
    """The text of an element's content: its own text, inline elements' text (Run, Bold ...)
    and the text after property elements, white space as XAML reads it (``xml:space``)."""
    parts = [el.text or ""]
    for child in el:
        local = qname(child.tag)[1] if isinstance(child.tag, str) else "."
        if local == "Run" and child.get("Text") is not None:  # a Run's text as an attribute
            parts.append(child.get("Text"))
        elif local == "LineBreak":
            parts.append("\n" if preserves_space(el) else " ")
        elif "." not in local:
            parts.append("".join(child.itertext()))
        parts.append(child.tail or "")
    return xaml_text("".join(parts), preserves_space(el))
