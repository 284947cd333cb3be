"""The package's theme dictionary (``xaml3d/data/themes/aero2.xaml``): WPF's Aero2 Styles and
ControlTemplates written as XAML, the lowest level of the framework step's value precedence
(the theme Style of a control, below any Style of the document's).

Read on the first control that asks for it and kept for the process: a document without
controls never reads it. Its Styles are looked up by type (implicit Styles only, as WPF finds a
theme Style by the control's DefaultStyleKey); ``BasedOn`` resolves within the theme.
"""

from __future__ import annotations

import functools
from importlib import resources

from xaml3d.xaml.context import qname, x_attr
from xaml3d.xaml.parser import parse_bytes
from xaml3d.xaml.resources import is_type_key, type_key

THEME_FILE = "aero2.xaml"
STYLE_DEPTH = 8  # the theme's BasedOn chains are short; this only stops a cycle


@functools.lru_cache(maxsize=1)
def theme_entries() -> dict:
    """The theme dictionary's entries, key -> element (implicit Styles under their
    ``{x:Type T}`` key); parsed once per process."""
    data = resources.files("xaml3d").joinpath("data", "themes", THEME_FILE).read_bytes()
    root = parse_bytes(data, f"xaml3d/data/themes/{THEME_FILE}")
    out: dict = {}
    for el in root:
        if not isinstance(el.tag, str):
            continue
        key = x_attr(el, "Key")
        if key is not None:
            out[type_key(key) if is_type_key(key) else key] = el
        elif qname(el.tag)[1] == "Style" and el.get("TargetType"):
            out[type_key(el.get("TargetType"))] = el
    return out


def theme_styles(type_name: str) -> list:
    """The theme's Style chain for a ``type_name`` control, base first (empty: the theme has
    no Style for it)."""
    entries = theme_entries()
    style = entries.get(type_key(type_name))
    chain: list = []
    while style is not None and len(chain) < STYLE_DEPTH:
        chain.append(style)
        based = (style.get("BasedOn") or "").strip()
        if not based:
            break
        body = based.strip("{}").split(None, 1)
        if len(body) != 2:
            break
        kind, ref = body[0], body[1].strip()
        if kind == "StaticResource":
            style = entries.get(ref)
        elif kind in ("x:Type", "Type"):
            style = entries.get(type_key(ref))
        else:
            break
        if style is not None and qname(style.tag)[1] != "Style":
            break
    return chain[::-1]
