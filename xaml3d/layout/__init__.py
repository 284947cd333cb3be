"""Layout: WPF's measure/arrange of the panels around the viewports (architecture: panels ->
each viewport's rectangle). Pure numbers: the reader builds the tree (tree.py), ``layout``
(engine.py, grid.py) sizes and places every element, ``gotchas`` says why a viewport came out
empty or hidden. Nothing here knows of XML or 3D."""

from xaml3d.layout.engine import LayoutResult, layout
from xaml3d.layout.tree import Definition, Node

__all__ = ["Definition", "LayoutResult", "Node", "layout"]
