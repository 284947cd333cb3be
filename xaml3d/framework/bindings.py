"""Load-time bindings: ``{Binding}`` values WPF evaluates without code (ElementName,
RelativeSource, Source={StaticResource}, the framework's own converters), replaced by their
values before templates are instantiated.

Every ``{Binding}`` attribute, and every property element holding a ``<Binding>`` (or a
``<MultiBinding>`` with a StringFormat, a ``<PriorityBinding>``), outside Style and template
bodies (the templates pass evaluates those once instantiated) and outside resource dictionaries
(shared objects, not the tree's) is evaluated (binding_eval.py) and replaced by its value as
attribute text the reader then parses as if written so. Three other outcomes:

- the value is an element of the tree (``Visual="{Binding ElementName=panel}"``,
  ``Storyboard.Target``): the binding stays, for the reader, which follows it itself;
- the binding needs what a load does not run (a DataContext set by code, an application's
  converter, ``x:Static``, a layout result): FallbackValue, else the property keeps its
  default; said once per kind (BND001);
- WPF's binding fails too (no element of that name, a path the source does not have, a value
  the target cannot take): FallbackValue, else the default (BND003).

A chain of bindings that comes back to itself, and a VisualBrush whose Visual contains the
brush, are reported (BND002) and cut, never followed forever.

A second ``evaluate`` over the same tree changes nothing and says nothing more, so a pass that
instantiates templates can call it again for the bindings their instances bring (no longer
inside a template body).
"""

from __future__ import annotations

from xaml3d.framework.binding_sites import collect


def evaluate(root, services) -> list:
    """Replace every evaluable binding under ``root`` by its value (in place). Returns the
    DataContext bindings to XML data kept for the items pass, for ``spend``."""
    sites = collect(root, services)
    if not sites:
        return []
    # the evaluator is imported for a document that has bindings only (most have none)
    from xaml3d.framework.binding_apply import apply

    return apply(root, services, sites)


def spend(contexts: list) -> None:
    """After the items are made: the DataContext bindings ``evaluate`` kept for them removed
    (evaluated: nothing is left for the reader)."""
    if contexts:
        from xaml3d.framework.binding_apply import spend as remove

        remove(contexts)


def value_text(root, services, el, text: str, prop: str = "") -> str | None:
    """The value WPF gives the binding ``text`` (``{Binding ...}``) set on ``el`` at load, as
    attribute text (a DataTrigger's condition compares it), or None when it needs code, fails,
    or is an object; nothing is said. ``root``: the tree whose name scope ``ElementName``
    names."""
    from xaml3d.framework.binding_apply import value_text as evaluate_text

    return evaluate_text(root, services, el, text, prop)
