"""The closed vocabulary of XAML element types xaml3d knows, and every reader diagnostic code.

Each known type lists its properties and their value kinds, its content property, whether xaml3d
supports it, and what kind of object it is. The 3D types, brushes, 2D transforms and animations
are CLOSED: a property not listed is reported (with the closest known name as a suggestion, so
``LookDirecton`` says "did you mean LookDirection?"). Framework types (Window, Grid, Button ...)
are OPEN here: xaml3d walks through them for Viewport3Ds, resources and triggers and reads no
value kinds for them; their member names are checked against the tables of WPF's class
hierarchy in framework_members.py (XAML024, framework_check.py). Known-but-unsupported types and
properties (VisualBrush content, DoubleAnimationUsingPath ...) are reported as such: this table is
documentation too.
"""

from __future__ import annotations

from dataclasses import dataclass

from xaml3d.codes.reader import READER_CODES  # noqa: F401 (the stage's table)


@dataclass(frozen=True)
class ElementType:
    name: str
    kind: str  # visual3d | model3d | light | geometry | camera | material | transform3d |
    # rotation3d | brush | transform2d | timeline | keyframe | trigger | action | collection |
    # resource | framework | other
    properties: dict[str, str]  # property name -> value kind
    content: str | None = None  # content property
    supported: bool = True
    open: bool = False  # framework element: properties not checked
    note: str = ""

    def property_kind(self, prop: str) -> str | None:
        return self.properties.get(prop)


_TYPES: dict[str, ElementType] = {}


def _t(name, kind, props=None, content=None, supported=True, open=False, note="", base=()):
    merged: dict[str, str] = {}
    for b in base:
        merged.update(b)
    merged.update(props or {})
    _TYPES[name] = ElementType(name, kind, merged, content, supported, open, note)


# --------------------------------------------------------------------------- property sets
_D, _B, _S = "double", "bool", "string"
_P3, _V3 = "point3d", "vector3d"
UI_PROPS = {
    "Width": _D, "Height": _D, "MinWidth": _D, "MinHeight": _D, "MaxWidth": _D,
    "MaxHeight": _D, "Margin": _S, "HorizontalAlignment": _S, "VerticalAlignment": _S,
    "ClipToBounds": _B, "Opacity": _D, "Visibility": _S, "IsHitTestVisible": _B,
    "Focusable": _B, "IsEnabled": _B, "Name": _S, "Resources": "resources",
    "Triggers": "triggers", "RenderTransform": "object", "RenderTransformOrigin": _S,
    "LayoutTransform": "object", "Clip": "object", "Effect": "object", "Style": "object",
    "Tag": "object", "ToolTip": "object", "Cursor": _S, "DataContext": "object",
    "FocusVisualStyle": "object", "SnapsToDevicePixels": _B, "UseLayoutRounding": _B,
    "FlowDirection": _S, "OpacityMask": "brush", "CacheMode": "object", "Uid": _S,
    "InputBindings": "object", "CommandBindings": "object", "ContextMenu": "object",
    "BitmapEffect": "object", "AllowDrop": _B, "ForceCursor": _B, "Language": _S,
    "OverridesDefaultStyle": _B, "Loaded": "event", "Unloaded": "event",
    "IsManipulationEnabled": _B, "BindingGroup": "object", "InputScope": "object",
}  # fmt: skip
_TRANSFORMABLE = {"Transform": "transform3d"}
_TIMELINE = {
    "BeginTime": "timespan", "Duration": "duration", "RepeatBehavior": "repeat",
    "AutoReverse": _B, "FillBehavior": _S, "SpeedRatio": _D, "AccelerationRatio": _D,
    "DecelerationRatio": _D, "Name": _S, "Completed": "event",
    "CurrentStateInvalidated": "event", "CurrentTimeInvalidated": "event",
    "CurrentGlobalSpeedInvalidated": "event", "RemoveRequested": "event",
}  # fmt: skip
_BRUSH = {"Opacity": _D, "Transform": "transform2d", "RelativeTransform": "transform2d"}
_GRADIENT = {
    "GradientStops": "gradientstop[]", "MappingMode": _S, "SpreadMethod": _S,
    "ColorInterpolationMode": _S,
}  # fmt: skip
_TILE = {
    "Viewport": "rect", "ViewportUnits": _S, "Viewbox": "rect", "ViewboxUnits": _S,
    "Stretch": _S, "TileMode": _S, "AlignmentX": _S, "AlignmentY": _S,
}  # fmt: skip
_LIGHT = {"Color": "color", "Transform": "transform3d"}
_POINTLIGHT = {
    "Position": _P3, "Range": _D, "ConstantAttenuation": _D, "LinearAttenuation": _D,
    "QuadraticAttenuation": _D,
}  # fmt: skip
_CAMERA = {
    "Position": _P3, "LookDirection": _V3, "UpDirection": _V3, "NearPlaneDistance": _D,
    "FarPlaneDistance": _D, "Transform": "transform3d",
}  # fmt: skip
_UI3D = {
    "Transform": "transform3d", "Visibility": _S, "IsHitTestVisible": _B, "IsEnabled": _B,
    "Focusable": _B, "Name": _S, "Uid": _S,
}  # fmt: skip
_CENTER3 = {"CenterX": _D, "CenterY": _D, "CenterZ": _D}
_CENTER2 = {"CenterX": _D, "CenterY": _D}

# --------------------------------------------------------------------------- 3D types
_t("Viewport3D", "viewport", {"Camera": "camera", "Children": "visual3d[]"}, "Children",
   base=(UI_PROPS,))  # fmt: skip
_t(
    "ModelVisual3D",
    "visual3d",
    {"Content": "model3d", "Children": "visual3d[]", "Transform": "transform3d"},
    "Children",
)
_t("ModelUIElement3D", "visual3d", {"Model": "model3d"}, "Model", base=(_UI3D,))
_t("ContainerUIElement3D", "visual3d", {"Children": "visual3d[]"}, "Children", base=(_UI3D,))
_t("Viewport2DVisual3D", "visual3d",
   {"Geometry": "geometry", "Material": "material", "Visual": "object", "CacheMode": "object"},
   "Visual", base=(_UI3D,), note="its Visual is drawn by the 2D layer")  # fmt: skip
_t("Model3DGroup", "model3d", {"Children": "model3d[]"}, "Children", base=(_TRANSFORMABLE,))
_t("GeometryModel3D", "model3d",
   {"Geometry": "geometry", "Material": "material", "BackMaterial": "material"},
   base=(_TRANSFORMABLE,))  # fmt: skip
_t("MeshGeometry3D", "geometry",
   {"Positions": "point3d[]", "Normals": "vector3d[]", "TextureCoordinates": "point[]",
    "TriangleIndices": "int[]"})  # fmt: skip
_t("AmbientLight", "light", base=(_LIGHT,))
_t("DirectionalLight", "light", {"Direction": _V3}, base=(_LIGHT,))
_t("PointLight", "light", base=(_LIGHT, _POINTLIGHT))
_t(
    "SpotLight",
    "light",
    {"Direction": _V3, "InnerConeAngle": _D, "OuterConeAngle": _D},
    base=(_LIGHT, _POINTLIGHT),
)
_t("PerspectiveCamera", "camera", {"FieldOfView": _D}, base=(_CAMERA,))
_t("OrthographicCamera", "camera", {"Width": _D}, base=(_CAMERA,))
_t(
    "MatrixCamera",
    "camera",
    {"ViewMatrix": "matrix3d", "ProjectionMatrix": "matrix3d", "Transform": "transform3d"},
)
_t("DiffuseMaterial", "material", {"Brush": "brush", "Color": "color", "AmbientColor": "color"})
_t("SpecularMaterial", "material", {"Brush": "brush", "Color": "color", "SpecularPower": _D})
_t("EmissiveMaterial", "material", {"Brush": "brush", "Color": "color"})
_t("MaterialGroup", "material", {"Children": "material[]"}, "Children")
_t("TranslateTransform3D", "transform3d", {"OffsetX": _D, "OffsetY": _D, "OffsetZ": _D})
_t("ScaleTransform3D", "transform3d", {"ScaleX": _D, "ScaleY": _D, "ScaleZ": _D}, base=(_CENTER3,))
_t("RotateTransform3D", "transform3d", {"Rotation": "rotation3d"}, base=(_CENTER3,))
_t("MatrixTransform3D", "transform3d", {"Matrix": "matrix3d"})
_t("Transform3DGroup", "transform3d", {"Children": "transform3d[]"}, "Children")
_t("AxisAngleRotation3D", "rotation3d", {"Axis": _V3, "Angle": _D})
_t("QuaternionRotation3D", "rotation3d", {"Quaternion": "quaternion"})
for _c in ("Model3DCollection", "Transform3DCollection", "MaterialCollection",
           "Visual3DCollection", "GradientStopCollection", "TransformCollection",
           "TimelineCollection", "TriggerActionCollection", "TriggerCollection",
           # the 2D ones (DrawingGroup.Children, GeometryGroup.Children, PathGeometry.Figures,
           # PathFigure.Segments): WPF takes the explicit element in each
           "DrawingCollection", "GeometryCollection", "PathFigureCollection",
           "PathSegmentCollection"):  # fmt: skip
    _t(_c, "collection", content="Children")
for _c in ("Point3DCollection", "Vector3DCollection", "PointCollection", "Int32Collection",
           "DoubleCollection"):  # fmt: skip
    _t(_c, "valuecollection", note="written as element text")

# --------------------------------------------------------------------------- brushes
_t("SolidColorBrush", "brush", {"Color": "color"}, base=(_BRUSH,))
_t("LinearGradientBrush", "brush", {"StartPoint": "point", "EndPoint": "point"},
   "GradientStops", base=(_BRUSH, _GRADIENT))  # fmt: skip
_t("RadialGradientBrush", "brush",
   {"Center": "point", "GradientOrigin": "point", "RadiusX": _D, "RadiusY": _D},
   "GradientStops", base=(_BRUSH, _GRADIENT))  # fmt: skip
_t("ImageBrush", "brush", {"ImageSource": "image"}, base=(_BRUSH, _TILE))
_t(
    "VisualBrush",
    "brush",
    {"Visual": "object", "AutoLayoutContent": _B},
    "Visual",
    base=(_BRUSH, _TILE),
    note="its Visual is drawn by the 2D layer (docs/layer2d.md)",
)
_t("DrawingBrush", "brush", {"Drawing": "object"}, "Drawing",
   base=(_BRUSH, _TILE), note="drawn by the 2D layer (docs/layer2d.md)")  # fmt: skip
_t(
    "BitmapCacheBrush",
    "brush",
    {"Target": "object", "BitmapCache": "object"},
    supported=False,
    base=(_BRUSH,),
    note="drawn as a placeholder",
)
_t("GradientStop", "gradientstop", {"Color": "color", "Offset": _D})
_t("TranslateTransform", "transform2d", {"X": _D, "Y": _D})
_t("ScaleTransform", "transform2d", {"ScaleX": _D, "ScaleY": _D}, base=(_CENTER2,))
_t("RotateTransform", "transform2d", {"Angle": _D}, base=(_CENTER2,))
_t("SkewTransform", "transform2d", {"AngleX": _D, "AngleY": _D}, base=(_CENTER2,))
_t("MatrixTransform", "transform2d", {"Matrix": "matrix"})
_t("TransformGroup", "transform2d", {"Children": "transform2d[]"}, "Children")

# --------------------------------------------------------------------------- animation
_STORY_ATTACHED = {"Storyboard.TargetName": _S, "Storyboard.TargetProperty": _S}
_t("Storyboard", "timeline", {"Children": "timeline[]"}, "Children", base=(_TIMELINE,))
_t("ParallelTimeline", "timeline", {"Children": "timeline[]"}, "Children", base=(_TIMELINE,))
_t(
    "BeginStoryboard",
    "action",
    {"Storyboard": "storyboard", "Name": _S, "HandoffBehavior": _S},
    "Storyboard",
)
for _c in ("PauseStoryboard", "ResumeStoryboard", "StopStoryboard", "RemoveStoryboard",
           "SkipStoryboardToFill", "SeekStoryboard", "SetStoryboardSpeedRatio"):  # fmt: skip
    _t(_c, "action", {"BeginStoryboardName": _S, "Offset": _S, "Origin": _S, "SpeedRatio": _D},
       note="interactive control: not evaluated")  # fmt: skip
_t(
    "EventTrigger",
    "trigger",
    {"RoutedEvent": _S, "SourceName": _S, "Actions": "action[]"},
    "Actions",
)
_ANIM_VALUE = {"Double": _D, "Point3D": _P3, "Vector3D": _V3, "Quaternion": "quaternion",
               "Rotation3D": "rotation3d", "Color": "color", "Point": "point",
               "Size": "size"}  # fmt: skip
_FROM_TO = {"IsAdditive": _B, "IsCumulative": _B, "EasingFunction": "object"}
for _v, _k in _ANIM_VALUE.items():
    _t(f"{_v}Animation", "animation",
       {"From": _k, "To": _k, "By": _k, "UseShortestPath": _B},
       base=(_TIMELINE, _FROM_TO))  # fmt: skip
    _t(f"{_v}AnimationUsingKeyFrames", "animation", {"KeyFrames": "keyframe[]"}, "KeyFrames",
       base=(_TIMELINE, _FROM_TO))  # fmt: skip
    for _kind in ("Linear", "Discrete", "Spline", "Easing"):
        _t(f"{_kind}{_v}KeyFrame", "keyframe",
           {"KeyTime": "keytime", "Value": _k, "KeySpline": "keyspline",
            "EasingFunction": "object"}, "Value")  # fmt: skip
for _c in ("DoubleAnimationUsingPath", "PointAnimationUsingPath"):
    _t(_c, "animation", {"PathGeometry": "object", "Source": _S}, base=(_TIMELINE, _FROM_TO))
_t(
    "MatrixAnimationUsingPath",
    "animation",
    {"PathGeometry": "object", "DoesRotateWithTangent": _B, "IsAngleCumulative": _B,
     "IsOffsetCumulative": _B},
    base=(_TIMELINE, _FROM_TO),
    supported=False,
    note="2D matrix path animations are not evaluated",
)  # fmt: skip
_EASINGS = {"Back": ("Amplitude",), "Bounce": ("Bounces", "Bounciness"), "Circle": (),
            "Cubic": (), "Elastic": ("Oscillations", "Springiness"), "Exponential": ("Exponent",),
            "Power": ("Power",), "Quadratic": (), "Quartic": (), "Quintic": (),
            "Sine": ()}  # fmt: skip
for _e, _ps in _EASINGS.items():
    _t(f"{_e}Ease", "easing", {"EasingMode": _S, **{_p: _D for _p in _ps}})
_KEYFRAME_COLLECTIONS = [f"{v}KeyFrameCollection" for v in _ANIM_VALUE]
for _c in _KEYFRAME_COLLECTIONS:
    _t(_c, "collection", content="Children")

# --------------------------------------------------------------------------- resources & markup
_t("ResourceDictionary", "resource", {"Source": _S, "MergedDictionaries": "object"})
_t("StaticResource", "reference", {"ResourceKey": _S})
_t("DynamicResource", "reference", {"ResourceKey": _S})

# --------------------------------------------------------------------------- framework (open)
_FRAMEWORK = """
Window Page UserControl Application Grid Border Canvas StackPanel DockPanel WrapPanel Viewbox
ScrollViewer Button TextBlock TextBox Label Slider CheckBox RadioButton ComboBox ComboBoxItem
ListBox ListBoxItem ListView ListViewItem Image Rectangle Ellipse Path Line Polygon Polyline
Frame ContentPresenter ContentControl AdornerDecorator Decorator ColumnDefinition RowDefinition
Style Setter ControlTemplate DataTemplate ItemsPanelTemplate HierarchicalDataTemplate Trigger
ItemContainerTemplate ItemContainerTemplateSelector
MultiTrigger Condition DataTrigger MultiDataTrigger EventSetter ToolTip Menu MenuItem Separator
Expander GroupBox TabControl TabItem ItemsControl ToggleButton RepeatButton ProgressBar InkCanvas
MediaElement KeyBinding MouseBinding BooleanToVisibilityConverter Run Span Bold Italic Underline
BorderGapMaskConverter
Hyperlink LineBreak Paragraph FlowDocument FlowDocumentScrollViewer RichTextBox PasswordBox
UniformGrid GridSplitter StatusBar StatusBarItem ToolBar ToolBarTray DocumentViewer Popup
Thumb Track ScrollBar ResizeGrip NavigationWindow HeaderedContentControl Calendar DatePicker
DataGrid TreeView TreeViewItem PathGeometry PathFigure
BezierSegment LineSegment ArcSegment PolyLineSegment PolyBezierSegment QuadraticBezierSegment
PolyQuadraticBezierSegment EllipseGeometry RectangleGeometry LineGeometry GeometryGroup
CombinedGeometry StreamGeometry DrawingGroup GeometryDrawing ImageDrawing GlyphRunDrawing
VideoDrawing DrawingImage BitmapImage Pen DashStyle DropShadowEffect BlurEffect VisualTarget
BlurBitmapEffect DropShadowBitmapEffect OuterGlowBitmapEffect BevelBitmapEffect EmbossBitmapEffect
BitmapEffectGroup ShaderEffect
ObjectDataProvider XmlDataProvider Binding MultiBinding RelativeSource ImageSource BitmapCache
Color Double Int32 String Boolean Point Point3D Vector3D Thickness CornerRadius FontFamily
FontWeight Array Null Static Type Key Code XData
"""
for _c in _FRAMEWORK.split():
    _t(_c, "framework", open=True)

# attached-property owners whose attributes are accepted anywhere ("Grid.Column" ...)
ATTACHED_OWNERS = frozenset(
    "Grid Canvas DockPanel Storyboard RenderOptions TextBlock TextElement ToolTipService "
    "KeyboardNavigation ScrollViewer Panel Validation FocusManager Selector AutomationProperties "
    "VirtualizingStackPanel InputMethod SpellCheck ContextMenuService Typography "
    "NumberSubstitution TextOptions Timeline Mouse Keyboard Stylus RadioButton Button "
    "ButtonBase ToggleButton Control UIElement FrameworkElement DesignerProperties "
    "Viewport3D Window Page".split()
)

# attachable members a type owns, which XAML also resolves when they are written on an element
# of that type without the owner prefix (<Storyboard TargetName="...">)
OWN_ATTACHED: dict[str, tuple[str, ...]] = {
    "Storyboard": ("TargetName", "TargetProperty", "Target"),
}

# event attributes: a handler name in code-behind (not evaluable)
EVENT_SUFFIXES = (
    "Loaded", "Unloaded", "Click", "Checked", "Unchecked", "Indeterminate", "Changed", "Down",
    "Up", "Move", "Enter", "Leave", "Wheel", "Completed", "Invalidated", "Rendered", "Startup",
    "Exit", "Closing", "Closed", "Activated", "Deactivated", "Initialized", "Opened", "Expanded",
    "Collapsed", "Selected", "Unselected", "Drop", "DragOver", "Tick", "Input", "Started",
    "Requested", "Navigated", "Navigating", "Scroll", "Focus", "Pressed", "Released",
)  # fmt: skip


def is_event_name(prop: str) -> bool:
    """Whether a property name looks like a routed/CLR event (handler attributes)."""
    name = prop.rsplit(".", 1)[-1]
    return name.endswith(EVENT_SUFFIXES) and not name.startswith(("Is", "Has"))


def lookup(name: str) -> ElementType | None:
    return _TYPES.get(name)


def known_types() -> list[str]:
    return sorted(_TYPES)


def closed_types() -> list[str]:
    """The types whose vocabulary is closed (3D, brushes, animations...): not framework ones."""
    return sorted(n for n, t in _TYPES.items() if not t.open)


def suggest(name: str, candidates) -> str | None:
    """The closest known name, compared without case (``lookdirection`` -> LookDirection:
    XAML names are case-sensitive, so a case slip is the likeliest typo), or None."""
    by_lower: dict[str, str] = {}
    for c in candidates:
        by_lower.setdefault(c.lower(), c)
    import difflib  # only for a misspelt name: a scene without one never needs it

    low = name.lower()
    found = difflib.get_close_matches(low, list(by_lower), n=1, cutoff=0.75)
    if found:
        return by_lower[found[0]]
    # two neighbouring letters swapped: in a short name (Rwo for Row) the ratio above is too
    # low, yet no slip is likelier
    swapped = [c for c in by_lower if _transposed(low, c)]
    return by_lower[swapped[0]] if swapped else None


def _transposed(a: str, b: str) -> bool:
    """Whether ``b`` is ``a`` with exactly two neighbouring characters swapped."""
    if len(a) != len(b) or a == b:
        return False
    diff = [i for i, (x, y) in enumerate(zip(a, b, strict=True)) if x != y]
    return len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]] and (
        a[diff[1]] == b[diff[0]])  # fmt: skip


def did_you_mean(name: str, candidates) -> str:
    s = suggest(name, candidates)
    return f" (did you mean {s}?)" if s else ""
