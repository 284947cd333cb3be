"""The ``xaml3d`` command line (click): a thin layer over the Python API."""

from __future__ import annotations

import click

from xaml3d import __version__


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="xaml3d")
def main() -> None:
    """Render and check WPF XAML 3D scenes (Viewport3D) headless."""
