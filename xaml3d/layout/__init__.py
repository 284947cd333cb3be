"""Layout: WPF's measure/arrange of the panels around the viewports (architecture: panels ->
each viewport's rectangle). Pure numbers: the reader builds the element tree
(``xaml3d.scene.element_tree``), ``layout``
(engine.py, grid.py) sizes and places every element, measuring a TextBlock's text in the fonts
that draw it (text.py), ``gotchas`` says why a viewport came out
empty or hidden. Nothing here knows of XML or 3D."""

from xaml3d.layout.engine import LayoutResult, layout

__all__ = ["LayoutResult", "layout"]
