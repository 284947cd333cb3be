"""BorderGapMaskConverter: the OpacityMask that breaks a GroupBox frame's top line under its
header (Aero2's GroupBox template; a user's template may use it the same way).

WPF's converter takes, through a ``MultiBinding``, the header part's ActualWidth (``ElementName``),
the masked element's ActualWidth and ActualHeight and the line's offset (ConverterParameter) and
returns a mask opaque everywhere but over the rectangle from the offset, the header's width wide,
over the element's top half. Those sizes exist only after layout: at instantiation the framework
takes the ``MultiBinding`` off the part and hands the reader the masked element, the header
part and the offset (``Services.gap_masked``); the layout step cuts the element's layer there.
"""

from __future__ import annotations

import re

from xaml3d.framework.styles import X_NS, elements, local_name

CONVERTER = "BorderGapMaskConverter"
_RESOURCE = re.compile(r"\{\s*(?:StaticResource|DynamicResource)\s+(?:ResourceKey=)?([^\s}]+)\s*\}")


def mark(sv, instance) -> None:
    """Take every BorderGapMaskConverter mask off the parts of ``instance`` (a template's copy)
    and report it to the reader, with its header part."""
    masks = [
        p for p in instance.iter()
        if isinstance(p.tag, str) and local_name(p.tag).endswith(".OpacityMask")
    ]  # fmt: skip
    for prop in masks:
        found = _gap_binding(sv, prop)
        if found is None:
            continue
        header_name, offset = found
        header = _named(instance, header_name)
        if header is None:
            continue  # the binding names no part: the mask stays for the reader to report
        owner = prop.getparent()
        owner.remove(prop)
        sv.gap_masked(owner, header, offset)


def _gap_binding(sv, prop) -> tuple[str, float] | None:
    """(the header part's name, the offset) of a MultiBinding through the converter."""
    kids = elements(prop)
    if len(kids) != 1 or sv.wpf_type(kids[0]) != "MultiBinding":
        return None
    multi = kids[0]
    if not _is_gap_converter(sv, multi):
        return None
    bindings = [b for b in elements(multi) if sv.wpf_type(b) == "Binding"]
    if not bindings or not bindings[0].get("ElementName"):
        return None
    try:
        offset = float(multi.get("ConverterParameter") or "0")
    except ValueError:
        return None
    return bindings[0].get("ElementName").strip(), offset


def _is_gap_converter(sv, multi) -> bool:
    """Whether the MultiBinding's Converter is a BorderGapMaskConverter resource (the theme's
    is keyed by its type's name, found in the theme dictionary rather than the document)."""
    m = _RESOURCE.fullmatch((multi.get("Converter") or "").strip())
    if m is None:
        return False
    entry = sv.find(m.group(1), multi)
    if entry is not None:
        return sv.wpf_type(entry) == CONVERTER
    return m.group(1) == CONVERTER


def _named(instance, name: str):
    for el in instance.iter():
        if isinstance(el.tag, str) and name in (el.get(f"{{{X_NS}}}Name"), el.get("Name")):
            return el
    return None
