"""The theme's values for the controls' properties: what a ``{TemplateBinding P}`` reads when
neither the control, its Style nor the theme dictionary's Style (``xaml3d/data/themes/aero2.xaml``:
Button, ToggleButton, RepeatButton, CheckBox, RadioButton, Label, TextBox, PasswordBox, ListBox,
ListBoxItem) sets P (WPF's default Style of the Aero2 theme, from the [[Aero2.NormalColor]]
values of dotnet/wpf's theme files, for the controls whose Style is not yet written in the theme
dictionary; then the properties' own defaults).

A user's Style does not replace the theme's: WPF applies both (the theme Style sits below the
user's Style in value precedence), unless ``OverridesDefaultStyle`` is set.
"""

from __future__ import annotations

THEME: dict[str, dict[str, str]] = {
    "Label": {
        "Foreground": "#FF000000",
        "Background": "Transparent",
        "Padding": "5",
        "HorizontalContentAlignment": "Left",
        "VerticalContentAlignment": "Top",
    },
}

# Control's own defaults (the dependency properties' default values); Background, BorderBrush
# and Foreground's are null or inherited: no value to write
DEFAULTS: dict[str, str] = {
    "BorderThickness": "0",
    "Padding": "0",
    "HorizontalContentAlignment": "Left",
    "VerticalContentAlignment": "Top",
    # the states a picture shows: enabled, nothing pressed, hovered, focused, checked or selected
    "IsEnabled": "True",
    "IsChecked": "False",
    "IsSelected": "False",
    "IsExpanded": "False",
    "IsMouseOver": "False",
    "IsPressed": "False",
    "IsFocused": "False",
    "IsKeyboardFocused": "False",
    "IsKeyboardFocusWithin": "False",
    "IsSelectionActive": "False",  # Selector.IsSelectionActive: no keyboard focus either
    "IsDefaulted": "False",
    "IsDefault": "False",
    "IsCancel": "False",
    "IsThreeState": "False",
    "Visibility": "Visible",
}


def theme_value(type_name: str, prop: str) -> str | None:
    """The theme's value of ``prop`` for a ``type_name`` control, else the property's default
    (None when it has none to write: null, or inherited)."""
    hit = THEME.get(type_name, {}).get(prop)
    return hit if hit is not None else DEFAULTS.get(prop)
