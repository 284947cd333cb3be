"""The 2D layer: the scene's drawings drawn with skia (docs/layer2d.md).

``paint``: drawings and text onto a skia canvas, through ``paths`` (geometries), ``shaders``
(brushes: a DrawingBrush's drawing played through ``paint.PLAYER``, handed to them) and
``pens``; ``effects``: a visual's Effect as an image filter; ``surface``: a DrawingBrush
(VisualBrush, Viewport2DVisual3D content) rasterized as a texture for a 3D surface;
``picture``: a Viewport3D's own Opacity, OpacityMask, Clip, RenderTransform and Effect applied to
its rendered picture. skia is imported only through these modules, which are imported only when
a scene has 2D content: a scene without any renders without loading skia.
"""
