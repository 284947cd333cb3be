"""The names of WPF's public types that the presentation namespace maps (System.Windows and its
Controls, Controls.Primitives, Controls.Ribbon, Documents, Shapes, Data, Input, Navigation,
Media, Media.Animation, Media.Effects, Media.Imaging, Media.Media3D, Ink and Markup
namespaces), beyond the vocabulary xaml3d reads (vocabulary.py).

An element of the presentation namespace whose name is neither here nor in the vocabulary is
no WPF type: WPF's loader refuses it (XAML017). One named here is walked through as any
framework element: its Viewport3Ds, resources and triggers are read.
"""

from __future__ import annotations

_NAMES = """
Application Window NavigationWindow Page PageFunctionBase UserControl ResourceDictionary
FrameworkElement FrameworkContentElement UIElement ContentElement UIElement3D Visual Visual3D
Style Setter EventSetter Trigger MultiTrigger DataTrigger MultiDataTrigger EventTrigger Condition
FrameworkTemplate ControlTemplate DataTemplate HierarchicalDataTemplate ItemsPanelTemplate
DataTemplateKey ComponentResourceKey TemplateBindingExtension DynamicResourceExtension
StaticResourceExtension ThemeDictionaryExtension ColorConvertedBitmapExtension
VisualStateManager VisualStateGroup VisualState VisualTransition PropertyPath
Thickness CornerRadius Point Size Rect Vector Int32Rect Duration GridLength FigureLength
FontWeight FontStyle FontStretch TextDecoration TextDecorationCollection SystemColors
SystemFonts SystemParameters DependencyObject Freezable TriggerAction Localization
AccessText AdornedElementPlaceholder Border BorderGapMaskConverter Button Calendar Canvas
CheckBox ColumnDefinition ComboBox ComboBoxItem ContentControl ContentPresenter ContextMenu
ContextMenuService Control DataGrid DataGridCheckBoxColumn DataGridComboBoxColumn
DataGridHyperlinkColumn DataGridTemplateColumn DataGridTextColumn DataGridRow DataGridCell
DataGridLength DatePicker Decorator DockPanel DocumentViewer
Expander FlowDocumentPageViewer FlowDocumentReader FlowDocumentScrollViewer Frame Grid
GridSplitter GridView GridViewColumn GridViewColumnHeader GridViewHeaderRowPresenter
GridViewRowPresenter GroupBox GroupItem GroupStyle HeaderedContentControl HeaderedItemsControl
Image InkCanvas InkPresenter ItemContainerTemplate ItemContainerTemplateSelector ItemsControl
ItemsPresenter Label ListBox ListBoxItem ListView ListViewItem MediaElement Menu MenuItem Panel
PasswordBox ProgressBar RadioButton RichTextBox RowDefinition ScrollContentPresenter
ScrollViewer Separator Slider SpellCheck StackPanel StickyNoteControl TabControl TabItem
TextBlock TextBox ToolBar ToolBarTray ToolTip ToolTipService TreeView TreeViewItem Validation
ExceptionValidationRule DataErrorValidationRule NotifyDataErrorValidationRule Viewbox
VirtualizingStackPanel VirtualizingPanel WrapPanel BooleanToVisibilityConverter
AlternationConverter MenuScrollingVisibilityConverter DataTemplateSelector StyleSelector
TextSearch UniformGrid WebBrowser DocumentPageView ViewBase
ToggleButton RepeatButton Thumb Track ScrollBar ResizeGrip Popup TabPanel ToolBarPanel
ToolBarOverflowPanel StatusBar StatusBarItem BulletDecorator TickBar SelectiveScrollingGrid
DataGridCellsPresenter DataGridColumnHeader DataGridColumnHeadersPresenter
DataGridDetailsPresenter DataGridRowHeader DataGridRowsPresenter DataGridCellsPanel
DatePickerTextBox CalendarItem CalendarButton CalendarDayButton
ButtonBase Selector MultiSelector RangeBase TextBoxBase DocumentViewerBase LayoutInformation
Ribbon RibbonWindow RibbonTab RibbonGroup RibbonButton RibbonToggleButton RibbonCheckBox
RibbonRadioButton RibbonComboBox RibbonTextBox RibbonMenuButton RibbonMenuItem RibbonSplitButton
RibbonSplitMenuItem RibbonApplicationMenu RibbonApplicationMenuItem
RibbonApplicationSplitMenuItem RibbonGallery RibbonGalleryCategory RibbonGalleryItem
RibbonQuickAccessToolBar RibbonSeparator RibbonContextualTabGroup RibbonTwoLineText
RibbonControlGroup RibbonControl RibbonToolTip RibbonFilterMenuButton
FlowDocument Paragraph Run Span Bold Italic Underline Hyperlink LineBreak InlineUIContainer
BlockUIContainer List ListItem Table TableColumn TableRowGroup TableRow TableCell Section Figure
Floater FixedDocument FixedPage PageContent FixedDocumentSequence DocumentReference TextEffect
Glyphs AdornerDecorator AdornerLayer Adorner Typography TextElement Inline Block
Rectangle Ellipse Line Path Polygon Polyline Shape
Binding MultiBinding PriorityBinding CollectionViewSource ObjectDataProvider XmlDataProvider
XmlNamespaceMapping XmlNamespaceMappingCollection CompositeCollection CollectionContainer
RelativeSource BindingGroup PropertyGroupDescription
KeyBinding MouseBinding InputBinding KeyGesture MouseGesture CommandBinding RoutedCommand
RoutedUICommand Cursor InputScope InputScopeName FocusManager KeyboardNavigation InputMethod
Color Colors Brushes FontFamily Typeface GradientStop GradientStopCollection Pen DashStyle
DashStyles DoubleCollection PointCollection Int32Collection VectorCollection
Geometry PathGeometry PathFigure PathFigureCollection PathSegmentCollection PathSegment
BezierSegment LineSegment ArcSegment PolyLineSegment PolyBezierSegment QuadraticBezierSegment
PolyQuadraticBezierSegment EllipseGeometry RectangleGeometry LineGeometry GeometryGroup
CombinedGeometry StreamGeometry GeometryCollection DrawingGroup GeometryDrawing ImageDrawing
GlyphRunDrawing VideoDrawing DrawingVisual DrawingImage DrawingCollection GlyphRun Matrix
MediaPlayer MediaTimeline RenderOptions TextOptions VisualTarget BitmapCache BitmapCacheBrush
GuidelineSet ContainerVisual HostVisual NumberSubstitution ImageSource Drawing Brush
BitmapImage CroppedBitmap FormatConvertedBitmap TransformedBitmap CachedBitmap
RenderTargetBitmap WriteableBitmap ColorConvertedBitmap BitmapSource BitmapFrame
DropShadowEffect BlurEffect ShaderEffect PixelShader Effect BlurBitmapEffect
DropShadowBitmapEffect OuterGlowBitmapEffect BevelBitmapEffect EmbossBitmapEffect
BitmapEffectGroup BitmapEffectInput
Storyboard BeginStoryboard PauseStoryboard ResumeStoryboard StopStoryboard RemoveStoryboard
SeekStoryboard SetStoryboardSpeedRatio SkipStoryboardToFill ParallelTimeline TimelineGroup
Timeline KeySpline KeyTime RepeatBehavior SoundPlayerAction
BackEase BounceEase CircleEase CubicEase ElasticEase ExponentialEase PowerEase QuadraticEase
QuarticEase QuinticEase SineEase
Viewport2DVisual3D ModelUIElement3D ContainerUIElement3D Matrix3D Quaternion Size3D Rect3D
Point4D Model3D Light Camera ProjectionCamera Material Transform3D Rotation3D
StrokeCollection DrawingAttributes
"""

# the animation types of each animatable value type (System.Windows.Media.Animation)
_ANIMATED = (
    "Boolean Byte Char Color Decimal Double Int16 Int32 Int64 Matrix Object Point Point3D "
    "Quaternion Rect Rotation3D Single Size String Thickness Vector Vector3D"
).split()
_INTERPOLATED = set(_ANIMATED) - {"Boolean", "Char", "Matrix", "Object", "String"}

NAMES: frozenset[str] = frozenset(
    _NAMES.split()
    + [f"{t}AnimationUsingKeyFrames" for t in _ANIMATED]
    + [f"Discrete{t}KeyFrame" for t in _ANIMATED]
    + [f"{t}KeyFrameCollection" for t in _ANIMATED]
    + [f"{t}Animation" for t in _INTERPOLATED]
    + [f"{kind}{t}KeyFrame" for t in _INTERPOLATED for kind in ("Linear", "Spline", "Easing")]
    + [f"{t}AnimationUsingPath" for t in ("Double", "Point", "Matrix")]
)
