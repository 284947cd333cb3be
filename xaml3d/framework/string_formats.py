"""The string formats of content that is not an element: ``ContentStringFormat``
(ContentControl, ContentPresenter), ``HeaderStringFormat`` (headered controls) and
``ItemStringFormat`` (ItemsControl), applied as WPF's ContentPresenter applies them when it
shows the content as text: ``String.Format(format, content)`` (binding_format.py), a format
without braces being the content's own (``F2``). Text written in the markup is a String, which
takes no number format (``{0:F2}`` leaves ``3.14159`` as it is); a ``sys:Double`` (``x:Int32``)
resource or array item is a number.

A format .NET refuses (a brace out of place) throws in WPF when the content is shown: the
content is shown unformatted, said (TPL010)."""

from __future__ import annotations

from xaml3d.framework import binding_format as F
from xaml3d.framework import markup
from xaml3d.framework.binding_values import Value, as_number, primitive
from xaml3d.framework.markup_syntax import literal

_NUMBERS = ("Double", "Int32")


def number_text(el) -> tuple[str, bool] | None:
    """A primitive element's (text, is_number) (``<sys:Double>2.5</sys:Double>``), else None."""
    v = primitive(el)
    if v is None:
        return None
    return v.text or "", v.clr in _NUMBERS


def format_text(sv, fmt: str | None, text: str, is_number: bool, where, attr: str) -> str:
    """``text`` formatted by the format written ``fmt`` (None, or an extension not known at
    load: as it is); a refused format said at ``where``'s ``attr``."""
    if fmt is None or markup.split(fmt) is not None:
        return text
    fmt = literal(fmt)
    if not fmt:
        return text
    value: object = text
    if is_number:
        x = as_number(Value(text, "Double"))
        if x is None:
            is_number = False
        else:
            value = x
    try:
        return F.composite(fmt, value, is_number)
    except F.FormatError as exc:
        msg = f"{attr} {fmt!r} is refused by .NET ({exc}): the content is shown unformatted"
        sv.diag("TPL010", msg, where, attr=attr, once=("TPL010", id(where), attr))
        return text
