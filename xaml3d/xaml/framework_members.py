"""The members WPF's 2D framework types accept in markup, one table per level of WPF's class
hierarchy: UIElement, FrameworkElement, Control, ContentControl, ButtonBase, Button ...; panels,
decorators, shapes, text, items controls and their items, ContentElement and the text elements,
grid definitions, Application (the element types) and the Style vocabulary (Style, Setter,
EventSetter, Trigger, MultiTrigger, Condition, DataTrigger, MultiDataTrigger, the templates'
own attributes), and the 2D objects: geometries and their figures and segments, drawings,
pens, images and effects (brushes and 2D transforms are closed types of vocabulary.py).

A table lists the names a class declares itself: its dependency properties (read-only ones
included, as Triggers name them: ``IsMouseOver``), its CLR properties and its events (a
``+Name`` entry is the event and its tunnelling ``PreviewName`` twin), and the attached
properties it owns (``Grid``: Row, Column ...). A type accepts the names of its table and of its
bases' (``members``). The names follow WPF's own classes (dotnet/wpf); what is not listed here
keeps xaml3d's open behaviour (framework_check.py checks only types with a table).
"""

from __future__ import annotations

import functools

# class -> (its base class, or None at the top of what markup can set; the names it declares)
CLASSES: dict[str, tuple[str | None, str]] = {}


def _c(name: str, base: str | None, names: str = "") -> None:
    CLASSES[name] = (base, names)


_TOUCH_EVENTS = (
    "+TouchDown +TouchMove +TouchUp GotTouchCapture LostTouchCapture TouchEnter TouchLeave"
)
_INPUT_EVENTS = (
    "+MouseDown +MouseUp +MouseLeftButtonDown +MouseLeftButtonUp +MouseRightButtonDown "
    "+MouseRightButtonUp +MouseMove +MouseWheel MouseEnter MouseLeave GotMouseCapture "
    "LostMouseCapture QueryCursor +StylusDown +StylusUp +StylusMove +StylusInAirMove StylusEnter "
    "StylusLeave +StylusInRange +StylusOutOfRange +StylusSystemGesture GotStylusCapture "
    "LostStylusCapture +StylusButtonDown +StylusButtonUp +KeyDown +KeyUp +GotKeyboardFocus "
    "+LostKeyboardFocus +TextInput +QueryContinueDrag +GiveFeedback +DragEnter +DragOver "
    "+DragLeave +Drop GotFocus LostFocus IsMouseDirectlyOverChanged IsKeyboardFocusWithinChanged "
    "IsMouseCapturedChanged IsMouseCaptureWithinChanged IsStylusDirectlyOverChanged "
    "IsStylusCapturedChanged IsStylusCaptureWithinChanged IsKeyboardFocusedChanged "
    "IsEnabledChanged FocusableChanged " + _TOUCH_EVENTS
)
_INPUT_STATE = (
    "AllowDrop Focusable IsEnabled Uid CommandBindings InputBindings IsFocused IsKeyboardFocused "
    "IsKeyboardFocusWithin IsMouseCaptured IsMouseCaptureWithin IsMouseDirectlyOver IsMouseOver "
    "IsStylusCaptured IsStylusCaptureWithin IsStylusDirectlyOver IsStylusOver AreAnyTouchesOver "
    "AreAnyTouchesDirectlyOver AreAnyTouchesCaptured AreAnyTouchesCapturedWithin TouchesOver "
    "TouchesDirectlyOver TouchesCaptured TouchesCapturedWithin IsInputMethodEnabled "
    "HasAnimatedProperties "
)
_FRAMEWORK_COMMON = (
    "BindingGroup ContextMenu Cursor DataContext FocusVisualStyle ForceCursor InputScope "
    "IsInitialized IsLoaded Language Name OverridesDefaultStyle Parent Resources Style Tag "
    "TemplatedParent ToolTip ContextMenuClosing ContextMenuOpening DataContextChanged "
    "Initialized Loaded SourceUpdated TargetUpdated ToolTipClosing ToolTipOpening Unloaded"
)
_FONT = "FontFamily FontSize FontStretch FontStyle FontWeight Foreground"
_POPUP = (
    "CustomPopupPlacementCallback HasDropShadow HorizontalOffset IsOpen Placement "
    "PlacementRectangle PlacementTarget StaysOpen VerticalOffset Opened Closed"
)
_SCROLL_INFO = (
    "CanHorizontallyScroll CanVerticallyScroll ExtentHeight ExtentWidth HorizontalOffset "
    "ScrollOwner VerticalOffset ViewportHeight ViewportWidth"
)
_NAVIGATION = (
    "BackStack CanGoBack CanGoForward CurrentSource ForwardStack NavigationService "
    "SandboxExternalContent Source Navigating Navigated NavigationProgress NavigationFailed "
    "NavigationStopped LoadCompleted FragmentNavigation"
)
_HEADER = "Header HeaderStringFormat HeaderTemplate HeaderTemplateSelector HasHeader"
_COMMAND = "Command CommandParameter CommandTarget"
_TRIGGER_BASE = "EnterActions ExitActions"

# --------------------------------------------------------------------------- elements
_c(
    "UIElement",
    None,
    _INPUT_STATE
    + _INPUT_EVENTS
    + (
        " BitmapEffect BitmapEffectInput CacheMode Clip ClipToBounds Effect IsHitTestVisible "
        "IsManipulationEnabled Opacity OpacityMask RenderTransform RenderTransformOrigin "
        "SnapsToDevicePixels Visibility IsVisible DesiredSize RenderSize IsArrangeValid "
        "IsMeasureValid PersistId IsHitTestVisibleChanged IsVisibleChanged LayoutUpdated "
        "ManipulationStarting ManipulationStarted ManipulationDelta ManipulationInertiaStarting "
        "ManipulationBoundaryFeedback ManipulationCompleted"
    ),
)
_c(
    "FrameworkElement",
    "UIElement",
    _FRAMEWORK_COMMON
    + (
        " ActualHeight ActualWidth FlowDirection Height HorizontalAlignment LayoutTransform Margin "
        "MaxHeight MaxWidth MinHeight MinWidth Triggers UseLayoutRounding VerticalAlignment Width "
        "RequestBringIntoView SizeChanged"
    ),
)
_c(
    "Control",
    "FrameworkElement",
    _FONT
    + (
        " Background BorderBrush BorderThickness HorizontalContentAlignment IsTabStop Padding "
        "TabIndex Template VerticalContentAlignment +MouseDoubleClick"
    ),
)
_c(
    "ContentControl",
    "Control",
    "Content ContentStringFormat ContentTemplate ContentTemplateSelector HasContent",
)
_c("HeaderedContentControl", "ContentControl", _HEADER)
_c("ButtonBase", "ContentControl", f"ClickMode {_COMMAND} IsPressed Click")
_c("Button", "ButtonBase", "IsCancel IsDefault IsDefaulted")
_c("ToggleButton", "ButtonBase", "IsChecked IsThreeState Checked Unchecked Indeterminate")
_c("CheckBox", "ToggleButton")
_c("RadioButton", "ToggleButton", "GroupName")
_c("RepeatButton", "ButtonBase", "Delay Interval")
_c("Label", "ContentControl", "Target")
_c("ToolTip", "ContentControl", _POPUP + " ShowsToolTipOnKeyboardFocus")
_c("UserControl", "ContentControl")
_c(
    "Window",
    "ContentControl",
    (
        "AllowsTransparency DialogResult Icon IsActive Left Owner OwnedWindows ResizeMode "
        "RestoreBounds ShowActivated ShowInTaskbar SizeToContent TaskbarItemInfo ThemeMode Title "
        "Top Topmost WindowStartupLocation WindowState WindowStyle Activated Closed Closing "
        "ContentRendered Deactivated DpiChanged LocationChanged SourceInitialized StateChanged"
    ),
)
_c("NavigationWindow", "Window", _NAVIGATION + " ShowsNavigationUI")
_c(
    "Page",
    "FrameworkElement",
    (
        "Background Content KeepAlive ShowsNavigationUI Template Title WindowHeight WindowTitle "
        "WindowWidth NavigationService FontFamily FontSize Foreground"
    ),
)
_c(
    "Frame",
    "ContentControl",
    _NAVIGATION + " JournalOwnership NavigationUIVisibility ContentRendered",
)
_c(
    "ScrollViewer",
    "ContentControl",
    (
        "CanContentScroll ComputedHorizontalScrollBarVisibility "
        "ComputedVerticalScrollBarVisibility "
        "ContentHorizontalOffset ContentVerticalOffset ExtentHeight ExtentWidth HorizontalOffset "
        "HorizontalScrollBarVisibility IsDeferredScrollingEnabled PanningDeceleration PanningMode "
        "PanningRatio ScrollableHeight ScrollableWidth VerticalOffset VerticalScrollBarVisibility "
        "ViewportHeight ViewportWidth ScrollChanged"
    ),
)
_c("ListBoxItem", "ContentControl", "IsSelected Selected Unselected")
_c("ComboBoxItem", "ListBoxItem", "IsHighlighted")
_c("ListViewItem", "ListBoxItem")
_c("StatusBarItem", "ContentControl")
_c("GroupBox", "HeaderedContentControl")
_c("Expander", "HeaderedContentControl", "ExpandDirection IsExpanded Expanded Collapsed")
_c("TabItem", "HeaderedContentControl", "IsSelected TabStripPlacement Selected Unselected")

_c(
    "ItemsControl",
    "Control",
    (
        "AlternationCount AlternationIndex DisplayMemberPath GroupStyle GroupStyleSelector "
        "HasItems "
        "IsGrouping IsTextSearchCaseSensitive IsTextSearchEnabled ItemBindingGroup "
        "ItemContainerGenerator ItemContainerStyle ItemContainerStyleSelector Items ItemsPanel "
        "ItemsSource ItemStringFormat ItemTemplate ItemTemplateSelector"
    ),
)
_c(
    "Selector",
    "ItemsControl",
    (
        "IsSynchronizedWithCurrentItem SelectedIndex SelectedItem SelectedValue SelectedValuePath "
        "IsSelected IsSelectionActive SelectionChanged Selected Unselected"
    ),
)
_c("ListBox", "Selector", "SelectedItems SelectionMode AnchorItem")
_c("ListView", "ListBox", "View")
_c(
    "ComboBox",
    "Selector",
    (
        "IsDropDownOpen IsEditable IsReadOnly MaxDropDownHeight SelectionBoxItem "
        "SelectionBoxItemStringFormat SelectionBoxItemTemplate ShouldPreserveUserEnteredPrefix "
        "StaysOpenOnEdit Text IsSelectionBoxHighlighted DropDownOpened DropDownClosed"
    ),
)
_c(
    "TabControl",
    "Selector",
    (
        "ContentStringFormat ContentTemplate ContentTemplateSelector SelectedContent "
        "SelectedContentStringFormat SelectedContentTemplate SelectedContentTemplateSelector "
        "TabStripPlacement"
    ),
)
_c("HeaderedItemsControl", "ItemsControl", _HEADER)
_c("MenuBase", "ItemsControl", "ItemContainerTemplateSelector UsesItemContainerTemplate")
_c("Menu", "MenuBase", "IsMainMenu")
_c("ContextMenu", "MenuBase", _POPUP)
_c(
    "MenuItem",
    "HeaderedItemsControl",
    _COMMAND
    + (
        " Icon InputGestureText IsCheckable IsChecked IsHighlighted IsPressed IsSubmenuOpen "
        "IsSuspendingPopupAnimation ItemContainerTemplateSelector Role StaysOpenOnClick "
        "UsesItemContainerTemplate Click Checked Unchecked SubmenuOpened SubmenuClosed"
    ),
)
_c("TreeView", "ItemsControl", "SelectedItem SelectedValue SelectedValuePath SelectedItemChanged")
_c(
    "TreeViewItem",
    "HeaderedItemsControl",
    "IsExpanded IsSelected IsSelectionActive Expanded Collapsed Selected Unselected",
)
_c(
    "ToolBar",
    "HeaderedItemsControl",
    "Band BandIndex HasOverflowItems IsOverflowItem IsOverflowOpen Orientation OverflowMode",
)
_c("StatusBar", "ItemsControl", "ItemContainerTemplateSelector UsesItemContainerTemplate")

_c("RangeBase", "Control", "LargeChange Maximum Minimum SmallChange Value ValueChanged")
_c(
    "Slider",
    "RangeBase",
    (
        "AutoToolTipPlacement AutoToolTipPrecision Delay Interval IsDirectionReversed "
        "IsMoveToPointEnabled IsSelectionRangeEnabled IsSnapToTickEnabled Orientation SelectionEnd "
        "SelectionStart TickFrequency TickPlacement Ticks"
    ),
)
_c("ProgressBar", "RangeBase", "IsIndeterminate Orientation")
_c("ScrollBar", "RangeBase", "Orientation ViewportSize Track Scroll")
_c(
    "TextBoxBase",
    "Control",
    (
        "AcceptsReturn AcceptsTab AutoWordSelection CanRedo CanUndo CaretBrush ExtentHeight "
        "ExtentWidth HorizontalOffset HorizontalScrollBarVisibility "
        "IsInactiveSelectionHighlightEnabled IsReadOnly IsReadOnlyCaretVisible IsSelectionActive "
        "IsUndoEnabled SelectionBrush SelectionOpacity SelectionTextBrush UndoLimit VerticalOffset "
        "VerticalScrollBarVisibility ViewportHeight ViewportWidth TextChanged SelectionChanged"
    ),
)
_c(
    "TextBox",
    "TextBoxBase",
    (
        "CaretIndex CharacterCasing LineCount MaxLength MaxLines MinLines SelectedText "
        "SelectionLength SelectionStart Text TextAlignment TextDecorations TextWrapping Typography"
    ),
)
_c("RichTextBox", "TextBoxBase", "CaretPosition Document IsDocumentEnabled Selection")
_c(
    "PasswordBox",
    "Control",
    (
        "CaretBrush IsInactiveSelectionHighlightEnabled IsSelectionActive MaxLength Password "
        "PasswordChar SecurePassword SelectionBrush SelectionOpacity SelectionTextBrush "
        "PasswordChanged"
    ),
)
_c("Separator", "Control")
_c("ResizeGrip", "Control")
_c("Thumb", "Control", "IsDragging DragStarted DragDelta DragCompleted")
_c(
    "GridSplitter",
    "Thumb",
    ("DragIncrement KeyboardIncrement PreviewStyle ResizeBehavior ResizeDirection ShowsPreview"),
)

_c("Panel", "FrameworkElement", "Background Children IsItemsHost ZIndex")
_c(
    "Grid",
    "Panel",
    (
        "ColumnDefinitions RowDefinitions ShowGridLines Column ColumnSpan Row RowSpan "
        "IsSharedSizeScope"
    ),
)
_c("Canvas", "Panel", "Left Top Right Bottom")
_c("DockPanel", "Panel", "LastChildFill Dock")
_c("StackPanel", "Panel", _SCROLL_INFO + " Orientation")
_c("WrapPanel", "Panel", "ItemHeight ItemWidth Orientation")
_c("UniformGrid", "Panel", "Columns FirstColumn Rows")
_c(
    "VirtualizingPanel",
    "Panel",
    (
        "CacheLength CacheLengthUnit IsContainerVirtualizable IsVirtualizing "
        "IsVirtualizingWhenGrouping ScrollUnit VirtualizationMode"
    ),
)
_c(
    "VirtualizingStackPanel",
    "VirtualizingPanel",
    _SCROLL_INFO + " Orientation CleanUpVirtualizedItem",
)
_c("TabPanel", "Panel")
_c("ToolBarPanel", "StackPanel")
_c("ToolBarTray", "FrameworkElement", "Background IsLocked Orientation ToolBars")

_c("Decorator", "FrameworkElement", "Child")
_c("Border", "Decorator", "Background BorderBrush BorderThickness CornerRadius Padding")
_c("Viewbox", "Decorator", "Stretch StretchDirection")
_c("AdornerDecorator", "Decorator")
_c("Popup", "FrameworkElement", _POPUP + " AllowsTransparency Child PopupAnimation")
_c(
    "ContentPresenter",
    "FrameworkElement",
    (
        "Content ContentSource ContentStringFormat ContentTemplate ContentTemplateSelector "
        "RecognizesAccessKey"
    ),
)
_c("ItemsPresenter", "FrameworkElement")
_c(
    "Track",
    "FrameworkElement",
    (
        "DecreaseRepeatButton IncreaseRepeatButton IsDirectionReversed Maximum Minimum Orientation "
        "Thumb Value ViewportSize"
    ),
)

_c(
    "TextBlock",
    "FrameworkElement",
    _FONT
    + (
        " Background BaselineOffset ContentEnd ContentStart Inlines IsHyphenationEnabled "
        "LineHeight LineStackingStrategy Padding Text TextAlignment TextDecorations TextEffects "
        "TextTrimming TextWrapping Typography"
    ),
)
_c("Image", "FrameworkElement", "Source Stretch StretchDirection ImageFailed DpiChanged")
_c(
    "MediaElement",
    "FrameworkElement",
    (
        "Balance BufferingProgress CanPause Clock DownloadProgress HasAudio HasVideo IsBuffering "
        "IsMuted LoadedBehavior NaturalDuration NaturalVideoHeight NaturalVideoWidth Position "
        "ScrubbingEnabled Source SpeedRatio Stretch StretchDirection UnloadedBehavior Volume "
        "BufferingEnded BufferingStarted MediaEnded MediaFailed MediaOpened ScriptCommand"
    ),
)

_c(
    "Shape",
    "FrameworkElement",
    (
        "Fill GeometryTransform RenderedGeometry Stretch Stroke StrokeDashArray StrokeDashCap "
        "StrokeDashOffset StrokeEndLineCap StrokeLineJoin StrokeMiterLimit StrokeStartLineCap "
        "StrokeThickness"
    ),
)
_c("Rectangle", "Shape", "RadiusX RadiusY")
_c("Ellipse", "Shape")
_c("Path", "Shape", "Data")
_c("Line", "Shape", "X1 X2 Y1 Y2")
_c("Polygon", "Shape", "FillRule Points")
_c("Polyline", "Shape", "FillRule Points")

# ContentElement: the input members of UIElement without layout or rendering
_c("ContentElement", None, _INPUT_STATE + _INPUT_EVENTS)
_c("FrameworkContentElement", "ContentElement", _FRAMEWORK_COMMON)
_c("DefinitionBase", "FrameworkContentElement", "SharedSizeGroup")
_c("ColumnDefinition", "DefinitionBase", "Width MinWidth MaxWidth ActualWidth Offset")
_c("RowDefinition", "DefinitionBase", "Height MinHeight MaxHeight ActualHeight Offset")
_c(
    "TextElement",
    "FrameworkContentElement",
    _FONT + " Background ContentEnd ContentStart ElementEnd ElementStart TextEffects Typography",
)
_c(
    "Inline",
    "TextElement",
    ("BaselineAlignment FlowDirection TextDecorations NextInline PreviousInline SiblingInlines"),
)
_c("Run", "Inline", "Text")
_c("Span", "Inline", "Inlines")
_c("Bold", "Span")
_c("Italic", "Span")
_c("Underline", "Span")
_c("Hyperlink", "Span", _COMMAND + " NavigateUri TargetName Click RequestNavigate")
_c("LineBreak", "Inline")
_c("InlineUIContainer", "Inline", "Child")
_c(
    "Block",
    "TextElement",
    (
        "BorderBrush BorderThickness BreakColumnBefore BreakPageBefore ClearFloaters FlowDirection "
        "IsHyphenationEnabled LineHeight LineStackingStrategy Margin Padding TextAlignment "
        "SiblingBlocks NextBlock PreviousBlock"
    ),
)
_c(
    "Paragraph",
    "Block",
    ("Inlines KeepTogether KeepWithNext MinOrphanLines MinWidowLines TextDecorations TextIndent"),
)
_c(
    "FlowDocument",
    "FrameworkContentElement",
    _FONT
    + (
        " Background Blocks ColumnGap ColumnRuleBrush ColumnRuleWidth ColumnWidth ContentEnd "
        "ContentStart FlowDirection IsColumnWidthFlexible IsHyphenationEnabled "
        "IsOptimalParagraphEnabled LineHeight LineStackingStrategy MaxPageHeight MaxPageWidth "
        "MinPageHeight MinPageWidth PageHeight PagePadding PageWidth TextAlignment TextEffects "
        "Typography"
    ),
)

_c(
    "Application",
    None,
    (
        "MainWindow Properties Resources ShutdownMode StartupUri ThemeMode Activated Deactivated "
        "DispatcherUnhandledException Exit FragmentNavigation LoadCompleted Navigated Navigating "
        "NavigationFailed NavigationProgress NavigationStopped SessionEnding Startup"
    ),
)

# --------------------------------------------------------------------------- styles
_c("Style", None, "BasedOn Resources Setters TargetType Triggers")
_c("Setter", None, "Property TargetName Value")
_c("EventSetter", None, "Event Handler HandledEventsToo")
_c("TriggerBase", None, _TRIGGER_BASE)
_c("Trigger", "TriggerBase", "Property Setters SourceName Value")
_c("MultiTrigger", "TriggerBase", "Conditions Setters")
_c("DataTrigger", "TriggerBase", "Binding Setters Value")
_c("MultiDataTrigger", "TriggerBase", "Conditions Setters")
_c("Condition", None, "Binding Property SourceName Value")
_c("FrameworkTemplate", None, "Resources Template VisualTree")
_c("ControlTemplate", "FrameworkTemplate", "TargetType Triggers")
_c("ItemsPanelTemplate", "FrameworkTemplate")
_c("DataTemplate", "FrameworkTemplate", "DataTemplateKey DataType Triggers")
_c(
    "HierarchicalDataTemplate",
    "DataTemplate",
    (
        "AlternationCount ItemBindingGroup ItemContainerStyle ItemContainerStyleSelector "
        "ItemsSource "
        "ItemStringFormat ItemTemplate ItemTemplateSelector"
    ),
)

# --------------------------------------------------------------------------- 2D objects
_c("Freezable", None, "Changed")
_c("Geometry", "Freezable", "Transform Bounds")
_c("PathGeometry", "Geometry", "Figures FillRule")
_c("StreamGeometry", "Geometry", "FillRule")
_c("EllipseGeometry", "Geometry", "Center RadiusX RadiusY")
_c("RectangleGeometry", "Geometry", "RadiusX RadiusY Rect")
_c("LineGeometry", "Geometry", "EndPoint StartPoint")
_c("GeometryGroup", "Geometry", "Children FillRule")
_c("CombinedGeometry", "Geometry", "Geometry1 Geometry2 GeometryCombineMode")
_c("PathFigure", "Freezable", "IsClosed IsFilled Segments StartPoint")
_c("PathSegment", "Freezable", "IsSmoothJoin IsStroked")
_c("LineSegment", "PathSegment", "Point")
_c("BezierSegment", "PathSegment", "Point1 Point2 Point3")
_c("QuadraticBezierSegment", "PathSegment", "Point1 Point2")
_c("ArcSegment", "PathSegment", "IsLargeArc Point RotationAngle Size SweepDirection")
_c("PolyLineSegment", "PathSegment", "Points")
_c("PolyBezierSegment", "PathSegment", "Points")
_c("PolyQuadraticBezierSegment", "PathSegment", "Points")
_c("Drawing", "Freezable", "Bounds")
_c(
    "DrawingGroup",
    "Drawing",
    (
        "BitmapEffect BitmapEffectInput Children ClipGeometry GuidelineSet Opacity OpacityMask "
        "Transform"
    ),
)
_c("GeometryDrawing", "Drawing", "Brush Geometry Pen")
_c("ImageDrawing", "Drawing", "ImageSource Rect")
_c("GlyphRunDrawing", "Drawing", "ForegroundBrush GlyphRun")
_c("VideoDrawing", "Drawing", "Player Rect")
_c(
    "Pen",
    "Freezable",
    "Brush DashCap DashStyle EndLineCap LineJoin MiterLimit StartLineCap Thickness",
)
_c("DashStyle", "Freezable", "Dashes Offset")
_c("ImageSource", "Freezable", "Height Width Metadata")
_c("DrawingImage", "ImageSource", "Drawing")
_c(
    "BitmapSource",
    "ImageSource",
    (
        "DpiX DpiY Format Palette PixelHeight PixelWidth IsDownloading DecodeFailed "
        "DownloadCompleted DownloadFailed DownloadProgress"
    ),
)
_c(
    "BitmapImage",
    "BitmapSource",
    (
        "BaseUri CacheOption CreateOptions DecodePixelHeight DecodePixelWidth Rotation SourceRect "
        "StreamSource UriCachePolicy UriSource"
    ),
)
_c("BitmapCache", "Freezable", "EnableClearType RenderAtScale SnapsToDevicePixels")
_c("Effect", "Freezable")
_c("BlurEffect", "Effect", "KernelType Radius RenderingBias")
_c("DropShadowEffect", "Effect", "BlurRadius Color Direction Opacity RenderingBias ShadowDepth")
_c(
    "ShaderEffect",
    "Effect",
    ("PixelShader PaddingTop PaddingBottom PaddingLeft PaddingRight DdxUvDdyUvRegisterIndex"),
)
_c("BitmapEffect", "Freezable")
_c("BlurBitmapEffect", "BitmapEffect", "KernelType Radius")
_c("DropShadowBitmapEffect", "BitmapEffect", "Color Direction Noise Opacity ShadowDepth Softness")
_c("OuterGlowBitmapEffect", "BitmapEffect", "GlowColor GlowSize Noise Opacity")
_c("BevelBitmapEffect", "BitmapEffect", "BevelWidth EdgeProfile LightAngle Relief Smoothness")
_c("EmbossBitmapEffect", "BitmapEffect", "LightAngle Relief")
_c("BitmapEffectGroup", "BitmapEffect", "Children")


def _names(text: str) -> frozenset[str]:
    out: set[str] = set()
    for word in text.split():
        if word.startswith("+"):  # a bubbling event and its tunnelling twin
            out.update((word[1:], "Preview" + word[1:]))
        else:
            out.add(word)
    return frozenset(out)


@functools.cache
def bases(name: str) -> tuple[str, ...]:
    """``name`` and its base classes that have a table, nearest first (empty when unknown)."""
    out: list[str] = []
    while name in CLASSES:
        out.append(name)
        name = CLASSES[name][0]  # type: ignore[assignment]
    return tuple(out)


def derives(name: str, target: str) -> bool | None:
    """Whether a ``name`` element is a ``target`` (the type itself or a base class): None when
    WPF's class tree above ``name`` is not known here to its top, or ``target`` is no class
    with a table (DependencyObject, Visual...: not decided)."""
    chain = bases(name)
    if not chain or CLASSES[chain[-1]][0] is not None:
        return None
    if target in chain:
        return True
    return False if target in CLASSES else None


@functools.cache
def members(name: str) -> frozenset[str] | None:
    """Every member name ``name`` accepts in markup (its own and its bases'), or None when
    the type has no table (its vocabulary stays open)."""
    chain = bases(name)
    if not chain:
        return None
    return frozenset().union(*(_names(CLASSES[c][1]) for c in chain))
