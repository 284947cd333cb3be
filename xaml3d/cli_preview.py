"""``xaml3d preview``: a live page of a scene while its markup is edited.

Serves, on 127.0.0.1 at a free port (printed on stdout), a page with the picture ``render``
draws, the findings ``validate`` lists (with their source lines), the HTML export's interactive
view and the camera's matrices; the page updates after every save of the scene or of a file it
read (App.xaml, dictionaries, textures). While the markup is broken the last good picture stays,
with the new findings beside it. Ctrl-C (or SIGTERM) stops it, exit status 0.
"""

from __future__ import annotations

import os
import signal
import threading

import click

from xaml3d.cli_common import display_name, io_error, no_app_option, resources_option

HELP = """Show a scene on a local page that follows its file while you edit it.

The page (http://127.0.0.1:PORT/, printed when it is ready) shows the picture xaml3d renders,
the findings of xaml3d validate with their source lines, the interactive 3D view of the HTML
export and the camera's matrices. It updates within a second of each save of the scene or of a
file it reads (App.xaml, resource dictionaries, textures); while the markup has errors it keeps
the last good picture and shows the errors beside it. Only this machine can reach the page.

\b
Examples:
  xaml3d preview scene.xaml --open
  xaml3d preview scene.xaml --port 8030 -W 800
  xaml3d preview scene.xaml -r App.xaml --viewport 1

\b
Ctrl-C stops it (exit status 0); 1 when the file cannot be found, 2 for a usage error.
"""


@click.command("preview", help=HELP)
@click.argument("scene", metavar="SCENE")
@click.option(
    "--port",
    type=click.IntRange(0, 65535),
    default=0,
    show_default=True,
    help="The port on 127.0.0.1 (0: a free one).",
)
@click.option("--open", "open_browser", is_flag=True, help="Open the page in the web browser.")
@click.option("--viewport", metavar="INDEX|NAME", help="Which Viewport3D (default: the first).")
@click.option("-W", "--width", type=click.IntRange(min=1), help="Render at this width.")
@click.option("-H", "--height", type=click.IntRange(min=1), help="Render at this height.")
@resources_option
@no_app_option
def preview_command(scene, port, open_browser, viewport, width, height, resources, no_app):
    from xaml3d.cli_preview_server import PreviewServer, watch_inputs
    from xaml3d.cli_preview_state import PreviewState

    try:
        import watchfiles  # noqa: F401 (a dependency; imported here, before the first build)
    except ImportError:
        click.echo(
            "xaml3d: error PRV001 preview needs watchfiles: pip install watchfiles", err=True
        )
        click.get_current_context().exit(1)
    if scene == "-":
        raise click.UsageError("preview follows a file: stdin ('-') cannot be followed")
    if not os.path.isfile(scene):
        what = "is not a file" if os.path.exists(scene) else "No such file or directory"
        click.echo(io_error(display_name(scene), f"{what}: {scene}"), err=True)
        click.get_current_context().exit(1)
    state = PreviewState(
        scene, tuple(resources), discover_app=not no_app, viewport=viewport, width=width,
        height=height,
    )  # fmt: skip
    try:
        server = PreviewServer(state, port)
    except OSError as exc:
        click.echo(
            f"xaml3d: error IO001 cannot listen on 127.0.0.1:{port}: {exc.strerror}", err=True
        )
        click.get_current_context().exit(1)
    stop = threading.Event()
    # SIGTERM stops it as Ctrl-C does: the same clean end
    previous = signal.signal(signal.SIGTERM, _interrupt)
    watcher = threading.Thread(target=watch_inputs, args=(state, stop), daemon=True)
    try:
        state.rebuild()
        watcher.start()  # a save made before it watches is found by PreviewState.stale
        click.echo(f"xaml3d preview: {server.url} (Ctrl-C stops)")
        _summary(state)
        if open_browser:
            import webbrowser

            threading.Thread(target=webbrowser.open, args=(server.url,), daemon=True).start()
        server.serve_forever(poll_interval=0.2)
    except KeyboardInterrupt:
        pass
    finally:
        stop.set()
        server.stopping.set()
        with state.changed:
            state.changed.notify_all()  # event streams end
        server.server_close()
        watcher.join(timeout=2.0)
        signal.signal(signal.SIGTERM, previous)
    click.echo("xaml3d preview: stopped", err=True)


def _interrupt(signum, frame) -> None:
    raise KeyboardInterrupt


def _summary(state) -> None:
    data = state.data
    errors = sum(f["severity"] == "error" for f in data["findings"])
    warnings = sum(f["severity"] == "warning" for f in data["findings"])
    drawn = "rendered" if data["current"] else "not rendered"
    click.echo(
        f"xaml3d preview: {data['file']}: {drawn}, {errors} error(s), {warnings} warning(s); "
        "following " + ", ".join(data["inputs"]),
        err=True,
    )
