"""Load-time bindings: ``{Binding}`` values WPF evaluates without code (ElementName,
RelativeSource, Source={StaticResource}, the framework's own converters), replaced by their
values before templates are instantiated."""

from __future__ import annotations


def evaluate(root, services) -> None:
    """Replace every evaluable binding under ``root`` by its value (in place)."""
    return None
