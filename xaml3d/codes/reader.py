"""The reader's codes (XML, XAML, RES, SCN ...): parsing, names, resources, the scene's shape.

Plain data at the ground of the package (``xaml3d.codes`` merges every table): any stage
may read it, and it imports nothing but the severities.
"""

from __future__ import annotations

from xaml3d.errors import ERROR, INFO, WARNING

READER_CODES: dict[str, tuple[str, str]] = {
    "XML001": (ERROR, "not well-formed XML (fatal)"),
    "XML002": (ERROR, "DOCTYPE/ENTITY declaration refused (fatal)"),
    "XML003": (ERROR, "document larger than the size limit (fatal)"),
    "XML004": (ERROR, "more elements than the limit (fatal)"),
    "XML005": (ERROR, "elements nested deeper than the limit (fatal)"),
    "XML006": (ERROR, "file cannot be read (fatal)"),
    "XAML001": (INFO, "element from an unknown or clr-namespace namespace skipped"),
    "XAML002": (INFO, "attribute from an unknown or clr-namespace namespace ignored"),
    "XAML003": (ERROR, "unknown element type in the WPF namespace (closest known name suggested)"),
    "XAML004": (
        ERROR,
        "unknown property of a WPF type or unknown x: directive (closest known name suggested)",
    ),
    "XAML005": (WARNING, "known element type that xaml3d does not support"),
    "XAML006": (INFO, "known property that xaml3d does not use"),
    "XAML007": (INFO, "x:Class code-behind is not run"),
    "XAML008": (INFO, "event handler attribute ignored (code-behind is not run)"),
    "XAML009": (INFO, "{Binding} cannot be evaluated from markup: property keeps its default"),
    "XAML010": (INFO, "{x:Static} cannot be evaluated: property keeps its default"),
    "XAML011": (INFO, "markup extension not evaluated ({TemplateBinding}, {x:Type}...)"),
    "XAML012": (ERROR, "property set more than once (attribute and element forms)"),
    "XAML013": (
        ERROR,
        "value of the wrong type for this property (a Material where a Brush is expected)",
    ),
    "XAML014": (ERROR, "several values for a single-valued property"),
    "XAML015": (INFO, "Viewport3D inside a template or style is not instantiated"),
    "XAML016": (ERROR, "malformed markup extension"),
    "XAML017": (ERROR, "unknown element in WPF's presentation namespace (no WPF type)"),
    "XAML018": (ERROR, "namespace one edit away from WPF's presentation namespace (a typo)"),
    "XAML019": (ERROR, "x:Name or Name that is not a valid name (not an identifier)"),
    "XAML020": (ERROR, "the same name given to two elements of one namescope"),
    "XAML021": (ERROR, "element with no XML namespace (the xmlns declaration is missing)"),
    "XAML022": (ERROR, "a Style whose TargetType does not match the element it is set on"),
    "RES001": (ERROR, "StaticResource key not found"),
    "RES002": (ERROR, "StaticResource used before its definition"),
    "RES003": (ERROR, "resource reference cycle"),
    "RES004": (WARNING, "resource file outside the scene's folder tree refused"),
    "RES005": (ERROR, "merged resource dictionary missing or unreadable"),
    "RES006": (INFO, "application resources read from a file"),
    "RES007": (INFO, "resource entry without x:Key ignored"),
    "RES008": (ERROR, "resource of the wrong type for this property"),
    "RES010": (WARNING, "DynamicResource key not found: the property keeps its default"),
    "RES009": (ERROR, "resource file named by the user cannot be read (fatal)"),
    "RES011": (
        INFO,
        "system or theme resource (x:Static or type key): property keeps its default",
    ),
    "RES012": (WARNING, "merged dictionary from another assembly not available: its keys unknown"),
    "RES013": (
        WARNING,
        "resource key not found while a dictionary of another assembly is in scope",
    ),
    "RES014": (ERROR, "the same key twice in one resource dictionary"),
    "SCN001": (ERROR, "the document holds no Viewport3D: nothing to render"),
    "SCN013": (
        INFO,
        "a ResourceDictionary, Application or 3D-content file (a ModelVisual3D, model or mesh as "
        "the root): no scene to render",
    ),
    "SCN003": (INFO, "viewport size and how the layout derived it (docs/layout.md)"),
    "SCN004": (INFO, "no camera given: WPF's default PerspectiveCamera is used"),
    "SCN005": (WARNING, "GeometryModel3D without a Geometry skipped"),
    "SCN006": (WARNING, "geometry that is not a MeshGeometry3D skipped"),
    "SCN008": (ERROR, "element of the wrong kind in a 3D tree (a bare Model3D among Visual3Ds)"),
    "SCN009": (INFO, "Camera is {x:Null}: the viewport draws nothing"),
    "SCN010": (WARNING, "transform cannot be built: identity used"),
    "SCN011": (
        INFO,
        "GeometryModel3D without Material or BackMaterial: no longer reported (CHK005 says it)",
    ),
    "SCN012": (ERROR, "negative or infinite Width or Height (invalid in WPF): taken as 0"),
    "BRU001": (WARNING, "BitmapCacheBrush content drawn as a placeholder"),
    "BRU002": (WARNING, "image file not found: a grey checker stands in"),
    "BRU003": (WARNING, "image file cannot be decoded: a grey checker stands in"),
    "BRU004": (WARNING, "network image URI refused: a grey checker stands in"),
    "BRU005": (
        WARNING,
        "image path outside the scene's folder tree refused: a grey checker stands in",
    ),
    "BRU006": (WARNING, "unsupported brush or brush transform: ignored"),
    "ANI001": (
        WARNING,
        "animation not evaluated (MatrixAnimationUsingPath, a path without Figures, a "
        "Storyboard.Target xaml3d cannot follow)",
    ),
    "ANI002": (INFO, "storyboard control action (Pause/Stop/Seek...) ignored"),
    "ANI003": (INFO, "EasingFunction of a custom type ignored (linear timing used)"),
    "ANI004": (WARNING, "storyboard element of an unexpected kind ignored"),
    "XAML023": (ERROR, "text inside an element whose content is a collection of objects"),
    "XAML024": (
        ERROR,
        "unknown property of a WPF 2D framework type (attribute, property element, Style "
        "Setter or Trigger Property; closest known name suggested)",
    ),
    "XAML025": (ERROR, "a MultiTrigger or MultiDataTrigger without Conditions"),
    "BND001": (
        INFO,
        "binding that needs code or layout a load does not run: FallbackValue or the "
        "property's default (said once per kind)",
    ),
    "BND002": (WARNING, "binding cycle: the property keeps its FallbackValue or default"),
    "BND003": (
        INFO,
        "binding that fails in WPF too (no such element, path or conversion): FallbackValue "
        "or the property's default",
    ),
}
