"""Styles, control templates, data templates, triggers and items, instantiated as WPF's
FrameworkElement.ApplyTemplate and ItemContainerGenerator build them at load."""

from __future__ import annotations


def instantiate(root, services) -> None:
    """Instantiate every template that applies under ``root`` (in place)."""
    return None
