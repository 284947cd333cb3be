"""Markup extensions as the framework step reads them: ``{TemplateBinding P}`` and
``{Binding P, RelativeSource={RelativeSource TemplatedParent}}`` (a templated parent's
property), ``{Binding}`` / ``{Binding Path}`` (a DataTemplate's data) and
``{StaticResource k}``; split without evaluating anything else."""

from __future__ import annotations

# attached properties keep their owner's name (Grid.Row); others are named without it
ATTACHED_OWNERS = {"Grid", "DockPanel", "Canvas", "ScrollViewer", "TextElement", "Panel",
                   "KeyboardNavigation", "ToolTipService", "RenderOptions"}  # fmt: skip


def split(value: str | None) -> tuple[str, str] | None:
    """``{Name args}`` -> (Name without prefix, args); None when not a markup extension (a
    leading ``{}`` escapes a literal brace)."""
    if value is None:
        return None
    v = value.strip()
    if not v.startswith("{") or v.startswith("{}") or not v.endswith("}"):
        return None
    body = v[1:-1].strip()
    name, _, args = body.partition(" ")
    if "," in name:
        name, _, rest = name.partition(",")
        args = rest + args
    return name.split(":")[-1], args.strip()


def arguments(args: str) -> tuple[list[str], dict[str, str]]:
    """(positional, named) arguments of an extension's text, split at the commas outside
    nested braces."""
    parts, depth, start = [], 0, 0
    for i, c in enumerate(args):
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(args[start:i])
            start = i + 1
    parts.append(args[start:])
    positional, named = [], {}
    for part in (p.strip() for p in parts):
        if not part:
            continue
        key, eq, value = part.partition("=")
        if eq and "{" not in key:
            named[key.strip()] = value.strip()
        else:
            positional.append(part)
    return positional, named


def resource_key(value: str | None) -> str | None:
    """The key of ``{StaticResource k}`` / ``{DynamicResource k}``, else None."""
    m = split(value)
    if m is None or m[0] not in ("StaticResource", "DynamicResource"):
        return None
    positional, named = arguments(m[1])
    key = named.get("ResourceKey", positional[0] if positional else None)
    return None if key is None else key.strip().strip("'\"")


def templated_parent_property(value: str | None) -> tuple[str, bool] | None:
    """(property, plain) of a reference to the templated parent's property:
    ``{TemplateBinding P}`` or ``{Binding P, RelativeSource={RelativeSource TemplatedParent}}``;
    ``plain`` is False when a Converter or StringFormat changes the value. None otherwise."""
    m = split(value)
    if m is None:
        return None
    positional, named = arguments(m[1])
    if m[0] == "TemplateBinding":
        prop = named.get("Property", positional[0] if positional else None)
        plain = "Converter" not in named
    elif m[0] == "Binding":
        rs = split(named.get("RelativeSource"))
        if rs is None or rs[0] != "RelativeSource":
            return None
        rpos, rnamed = arguments(rs[1])
        if rnamed.get("Mode", rpos[0] if rpos else None) != "TemplatedParent":
            return None
        prop = named.get("Path", positional[0] if positional else None)
        plain = not ({"Converter", "StringFormat"} & named.keys())
    else:
        return None
    if not prop:
        return None
    prop = prop.strip().strip("()")
    owner, _, short = prop.rpartition(".")
    # an attached property keeps its owner, as the Setters that set it name it
    attached = owner.split(":")[-1] in ATTACHED_OWNERS
    return (f"{owner.split(':')[-1]}.{short}" if attached else short), plain


def data_binding(value: str | None) -> str | None:
    """The path of a binding to the data context (``{Binding}`` -> "", ``{Binding Name}`` /
    ``{Binding Path=Name}`` -> "Name"), None for anything else (a source, a converter...)."""
    m = split(value)
    if m is None or m[0] != "Binding":
        return None
    positional, named = arguments(m[1])
    if named.keys() - {"Path", "Mode"}:
        return None
    path = named.get("Path", positional[0] if positional else "")
    return path.strip()
