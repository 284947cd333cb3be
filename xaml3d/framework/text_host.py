"""The text view of TextBox and PasswordBox: what WPF's TextBoxBase puts in its template's
``PART_ContentHost`` in code (``OnApplyTemplate``), built here at load.

WPF makes the host's content a TextBoxView that draws the text 2 px in from its left and
right edges and scrolls itself (the ScrollViewer offers it its own viewport: no infinite
width to wrap against). Here the host becomes a plain holder (laid out and drawn as a
ContentPresenter: the scroll bars a TextBox's template hides never show) of a TextBlock with
Margin 2,0,2,0 (plus the control's Padding, where WPF's ScrollViewer places its content)
showing the control's ``Text`` (a TextBox's, with its TextWrapping and TextAlignment) or its
``PasswordChar`` once per character of ``Password`` (a PasswordBox's: usually empty, an empty
box a line high).
"""

from __future__ import annotations

from xaml3d.framework import markup
from xaml3d.framework.styles import elements, local_name

PART = "PART_ContentHost"
HOSTS = ("TextBox", "PasswordBox")
INSET = "2,0,2,0"  # TextBoxView's text margin: 2 px in from each side, none above or below
DEFAULT_PASSWORD_CHAR = "\u25cf"  # PasswordBox.PasswordChar's default
# the text's own properties a TextBox passes to its view
_TEXT_PROPS = ("TextWrapping", "TextAlignment")
# the ScrollViewer's own properties, meaningless on the plain holder it becomes
_SCROLL_PROPS = ("HorizontalScrollBarVisibility", "VerticalScrollBarVisibility",
                 "CanContentScroll", "IsDeferredScrollingEnabled", "PanningMode",
                 "Padding", "Content", "ContentTemplate")  # fmt: skip


def fill(sv, c, host, literal) -> None:
    """Fill ``host`` (the instance's PART_ContentHost part, or None: a template without one
    shows no text, as in WPF) with the text view of the control ``c``; ``literal`` escapes a
    text for an attribute."""
    if host is None:
        return
    ns = host.tag.rpartition("}")[0]
    host.tag = f"{ns}}}ContentPresenter" if ns else "ContentPresenter"
    for attr in list(host.attrib):
        if attr in _SCROLL_PROPS or attr.startswith("ScrollViewer."):
            del host.attrib[attr]
    for k in elements(host):
        host.remove(k)  # a ScrollViewer's content written in the template: replaced
    host.text = None
    # not a TextBlock in WPF: no TextBlock Style of the document's applies to it
    attrs = {"Text": literal(shown_text(c)), "Margin": _margin(c), "Style": "{x:Null}"}
    if c.type == "TextBox":
        for prop in _TEXT_PROPS:
            v = c.value(prop)
            if v is not None and v[0] == "text" and markup.split(v[1]) is None:
                attrs[prop] = v[1]
    block = host.makeelement(f"{ns}}}TextBlock" if ns else "TextBlock", attrs)
    sv.made(block, host)
    host.append(block)


def _margin(c) -> str:
    """The text view's margin in the host: the control's Padding (WPF's ScrollViewer places
    its content at it) and the view's 2 px each side. A Padding not known at load (markup)
    leaves the 2 px alone; one that is no Thickness is passed on as written, for the reader to
    report where it is written."""
    v = c.value("Padding")
    text = v[1] if v is not None and v[0] == "text" else ""
    if not text.strip() or markup.split(text) is not None:
        return INSET
    try:
        nums = [float(p) for p in text.replace(",", " ").split()]
    except ValueError:
        return text
    if len(nums) in (1, 2):
        nums *= 4 // len(nums)
    if len(nums) != 4 or not all(abs(n) < 1e9 for n in nums):
        return text
    left, top, right, bottom = nums
    return f"{left + 2:g},{top:g},{right + 2:g},{bottom:g}"


def shown_text(c) -> str:
    """The text the control shows: a TextBox's Text (attribute, property element, Style or
    its content text), a PasswordBox's PasswordChar for each character of its Password; a
    value not known at load (an unevaluated binding) shows nothing."""
    if c.type == "PasswordBox":
        password = _plain(c.value("Password"))
        mark = _plain(c.value("PasswordChar")) or DEFAULT_PASSWORD_CHAR
        return mark[0] * len(password)
    if c.local("Text") is None:
        own = _content_text(c.el)
        if own:
            return own
    return _plain(c.value("Text"))


def _plain(value) -> str:
    if value is None or value[0] != "text":
        return ""
    text = value[1]
    if text.startswith("{}"):
        return text[2:]
    return "" if markup.split(text) is not None else text


def _content_text(el) -> str:
    """A TextBox's text written as its content (``<TextBox>text</TextBox>``), its white space
    collapsed as XAML's is."""
    if any("." not in local_name(k.tag) for k in elements(el)):
        return ""
    parts = [el.text or "", *(k.tail or "" for k in el)]
    return " ".join("".join(parts).split())
