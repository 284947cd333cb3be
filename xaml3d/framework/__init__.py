"""WPF's framework step: the element tree the markup describes turned into the tree WPF lays
out and draws (PresentationFramework's styles, templates, triggers, items and load-time
bindings), between reading and layout.

The step works in place on the document's element tree through the ElementTree interface of
its elements (``tag``, ``get``/``set``, children, ``makeelement``, copies) and through the
reader's services (``services.Services``: resource look-up, diagnostics); it imports neither
the reader nor lxml, nor layout, nor the renderer (import contracts in pyproject.toml). Its
passes, in WPF's order of evaluation at load:

0. ``null_content``: an ``<x:Null/>`` content or header written as ``{x:Null}``;
1. ``bindings``: load-time bindings that need no code, replaced by their values;
2. ``templates``: styles, control and data templates, triggers and items instantiated.

A document without any of them is left untouched (each pass looks before it works).
"""

from __future__ import annotations

from xaml3d.framework import bindings, null_content, templates
from xaml3d.framework.services import Services

__all__ = ["Services", "expand"]


def expand(root, services: Services) -> None:
    """Instantiate the framework's tree under ``root`` in place."""
    null_content.settle(root, services)
    contexts = bindings.evaluate(root, services)
    templates.instantiate(root, services)
    bindings.spend(contexts)
