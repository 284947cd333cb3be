"""The ``xaml3d`` command line (click): a thin layer over the Python API.

Commands live in their own modules: ``render`` (cli_render), ``validate`` (cli_validate),
``camera`` (cli_camera), ``info`` (cli_info), ``animate`` (cli_animate), ``export``
(cli_export), ``preview`` (cli_preview); shared helpers in
cli_common. Diagnostics go to stderr, data to stdout. Exit status: 0 success, 1 the input
could not be handled, 2 usage error.
"""

from __future__ import annotations

import os
import sys
import threading

import click

from xaml3d import __version__, native

# Each command's module is imported when the command runs (or its help is shown): ``info`` and
# ``validate`` never import the renderer, the exporters or the image encoders.
_COMMANDS = {
    "render": ("xaml3d.cli_render", "render_command"),
    "validate": ("xaml3d.cli_validate", "validate_command"),
    "camera": ("xaml3d.cli_camera", "camera_command"),
    "info": ("xaml3d.cli_info", "info_command"),
    "animate": ("xaml3d.cli_animate", "animate_command"),
    "export": ("xaml3d.cli_export", "export_command"),
    "preview": ("xaml3d.cli_preview", "preview_command"),
}


class _Commands(click.Group):
    """A group whose commands (``_COMMANDS``) are imported when first asked for."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted({*super().list_commands(ctx), *_COMMANDS})

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        found = super().get_command(ctx, cmd_name)
        if found is None and cmd_name in _COMMANDS:
            import importlib

            module, attr = _COMMANDS[cmd_name]
            found = getattr(importlib.import_module(module), attr)
            self.add_command(found, cmd_name)
        return found


HELP = """Render and check WPF XAML 3D scenes (Viewport3D) headless.

\b
Examples:
  xaml3d render scene.xaml -o scene.png
  xaml3d validate scene.xaml
  xaml3d camera scene.xaml --point 0,0,0
  xaml3d info scene.xaml --json
  xaml3d animate scene.xaml -o scene.gif
  xaml3d export scene.xaml -o scene.glb
  xaml3d preview scene.xaml --open

Run xaml3d COMMAND --help for each command's options.
"""


@click.group(cls=_Commands, context_settings={"help_option_names": ["-h", "--help"]}, help=HELP)
@click.version_option(__version__, prog_name="xaml3d")
@click.pass_context
def main(ctx: click.Context) -> None:
    # Numerical trouble in a scene is reported as diagnostics (CAM, MSH, RND codes): the math
    # handles extreme values itself, so no blanket numpy errstate hides what it would warn
    # (the test suite runs every command with numpy raising on each).
    # The first run on a machine compiles the kernels (seconds): say so when it happens.
    native.notify = _note


def _note(message: str) -> None:
    """A note on stderr, unless the running command was given -q (it prints errors only)."""
    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.params.get("quiet"):
        return
    click.echo(message, err=True)


def run() -> None:
    """The process's entry point (the ``xaml3d`` script, ``python -m xaml3d``): ``main``, then
    the process ends at once with its exit status, its output flushed.

    A normal interpreter shutdown tears down every module and object one by one: with a
    million-triangle scene and numba loaded that took 0.2-0.45 s (measured on a loaded 2-core
    machine) after the command had finished, longer than drawing the picture. Every file the
    commands write is closed before they return, so nothing is lost by skipping it. When a
    thread or a child process is still running (not the case after any command), or stdout
    cannot be flushed (a closed pipe), the usual shutdown runs instead, as before."""
    try:
        main()
    except SystemExit as exc:
        code = exc.code
    else:
        code = 0
    if code is None:
        code = 0
    if not isinstance(code, int) or threading.active_count() > 1 or _children():
        sys.exit(code)
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except OSError:
        sys.exit(code)
    os._exit(code)


def _children() -> bool:
    if "multiprocessing" not in sys.modules:
        return False
    import multiprocessing

    return bool(multiprocessing.active_children())
