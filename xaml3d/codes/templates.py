"""The framework step's codes (TPL): control templates and triggers it cannot instantiate or
apply (xaml3d.framework).

Plain data at the ground of the package (``xaml3d.codes`` merges every table).
"""

from __future__ import annotations

from xaml3d.errors import ERROR, INFO, WARNING

TEMPLATE_CODES: dict[str, tuple[str, str]] = {
    "TPL001": (
        WARNING,
        "a user ControlTemplate of a control whose template xaml3d does not instantiate: "
        "drawn in the theme's look",
    ),
    "TPL002": (
        INFO,
        "a TemplateBinding with an application's converter (code): the property keeps its default",
    ),
    "TPL003": (
        INFO,
        "a trigger whose condition is not known at load: its Setters are not applied",
    ),
    "TPL004": (ERROR, "a template that holds itself (WPF overflows its stack): not drawn"),
    "TPL005": (ERROR, "a trigger Setter's TargetName names no part of the template"),
    "TPL006": (INFO, "an ItemsSource not known at load (a binding, a missing resource): no items"),
    "TPL007": (INFO, "a template selector is code: the items and content are shown without it"),
    "TPL008": (INFO, "the ItemsPanel of a ComboBox in the theme's look is not used"),
    "TPL009": (WARNING, "a trigger Condition's SourceName names no part of the template: skipped"),
    "TPL010": (WARNING, "a content, header or item string format .NET refuses: shown unformatted"),
    "TPL011": (
        WARNING,
        "templates nested deeper than xaml3d instantiates (16 deep, 1000 instances): the rest "
        "not instantiated",
    ),
    "TPL012": (ERROR, "a ControlTemplate whose TargetType does not match the control"),
    "BND004": (
        INFO,
        "an XmlDataProvider's Source file cannot be read: the bindings to it take their "
        "FallbackValue",
    ),
}
