"""``xaml3d preview``'s local server and file watcher.

The server is the standard library's threaded HTTP server, bound to 127.0.0.1 only (and
refusing requests whose Host is not this machine's loopback, so no other site can reach it
through a rebound DNS name). It serves the page (``cli_preview_page``), ``/state.json``, the
event stream ``/events`` (server-sent events: the state's data after each rebuild),
``/picture.png`` and ``/view.html`` (the last good picture and HTML export page).

The watcher is watchfiles (the Rust ``notify`` crate: inotify, FSEvents, ReadDirectoryChangesW,
polling only where the system has nothing better), imported when the command runs: it follows
the folders of every file the scene read, so an editor that saves by writing a new file and
renaming it over the old one is followed as well as one that writes in place, and it reports
a save within a few tens of milliseconds, grouping the writes of one save into one change.
"""

from __future__ import annotations

import json
import math
import os
import threading
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

from xaml3d.cli_preview_page import PAGE
from xaml3d.cli_preview_state import PreviewState

HOST = "127.0.0.1"
KEEPALIVE = 10.0  # seconds between comments on an idle event stream (a closed page is noticed)
STEP_MS = 50  # a change is reported once the folder has been quiet this long
CHECK_MS = 300  # the watcher looks at the set of followed files at least this often


def _plain(value):
    """``value`` for JSON.parse: non-finite floats as their names ("inf"), as ``camera --json``
    writes an infinite far plane."""
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value


def state_json(state: PreviewState) -> bytes:
    with state.changed:
        data = state.data
    return json.dumps(_plain(data), allow_nan=False).encode("utf-8")


class PreviewServer(ThreadingHTTPServer):
    daemon_threads = True  # an open event stream never holds the command at Ctrl-C

    def __init__(self, state: PreviewState, port: int = 0) -> None:
        self.state = state
        self.stopping = threading.Event()
        super().__init__((HOST, port), PreviewHandler)

    @property
    def url(self) -> str:
        return f"http://{HOST}:{self.server_address[1]}/"


class PreviewHandler(BaseHTTPRequestHandler):
    server: PreviewServer
    protocol_version = "HTTP/1.1"

    def log_message(self, format, *args) -> None:  # noqa: A002 (the base class's name)
        pass  # the command prints its own lines, not one per request

    def _send(self, body: bytes, kind: str, status=HTTPStatus.OK) -> None:
        self.send_response(status)
        self.send_header("Content-Type", kind)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.end_headers()
        if self.command != "HEAD":
            self.wfile.write(body)

    def _local(self) -> bool:
        host = (self.headers.get("Host") or "").rsplit(":", 1)[0]
        return host in (HOST, "localhost")

    def do_HEAD(self) -> None:
        self.do_GET()

    def do_GET(self) -> None:
        if not self._local():
            self._send(b"xaml3d preview answers 127.0.0.1 only\n", "text/plain", 403)
            return
        path = self.path.split("?", 1)[0]
        state = self.server.state
        if path == "/":
            self._send(PAGE.encode("utf-8"), "text/html; charset=utf-8")
        elif path == "/state.json":
            self._send(state_json(state), "application/json")
        elif path == "/events":
            self._events()
        elif path in ("/picture.png", "/view.html"):
            with state.changed:
                body = state.picture if path == "/picture.png" else state.view
            if body is None:
                self._send(b"no good build yet\n", "text/plain", HTTPStatus.NOT_FOUND)
            elif path == "/picture.png":
                self._send(body, "image/png")
            else:
                self._send(body, "text/html; charset=utf-8")
        else:
            self._send(b"not found\n", "text/plain", HTTPStatus.NOT_FOUND)

    def _events(self) -> None:
        """Server-sent events: the state now, then after each rebuild."""
        state = self.server.state
        self.close_connection = True
        self.send_response(HTTPStatus.OK)
        self.send_header("Content-Type", "text/event-stream")
        self.send_header("Cache-Control", "no-store")
        self.end_headers()
        seen = -1
        try:
            while not self.server.stopping.is_set():
                with state.changed:
                    state.changed.wait_for(
                        lambda seen=seen: state.version != seen or self.server.stopping.is_set(),
                        timeout=KEEPALIVE,
                    )
                    version = state.version
                if version != seen:
                    seen = version
                    self.wfile.write(b"data: " + state_json(state) + b"\n\n")
                else:
                    self.wfile.write(b": idle\n\n")
                self.wfile.flush()
        except (BrokenPipeError, ConnectionResetError, ConnectionAbortedError):
            pass  # the page was closed or reloaded


def watch_inputs(state: PreviewState, stop: threading.Event) -> None:
    """Rebuild ``state`` whenever one of its input files changes, until ``stop`` is set. The
    folders watched follow the inputs: a texture or dictionary the scene starts reading is
    followed from its next good build on."""
    from watchfiles import watch  # the command's own dependency, imported when it runs

    while not stop.is_set():
        files = state.inputs()
        folders = _folders(files)
        if not folders:
            stop.wait(CHECK_MS / 1000)
            continue

        def ours(change, path: str, files=files) -> bool:
            return os.path.realpath(path) in files

        first = True
        for changes in watch(
            *folders,
            watch_filter=ours,
            stop_event=stop,
            step=STEP_MS,
            rust_timeout=CHECK_MS,
            yield_on_timeout=True,
            recursive=False,
            ignore_permission_denied=True,
        ):
            # the first report (a change, or none within CHECK_MS) comes once the folders
            # are watched: a save made before that is found by comparing the files
            if changes or (first and state.stale()):
                state.rebuild()
            first = False
            if state.inputs() != files or _folders(files) != folders:
                break  # follow the new set of files, or a folder made or removed


def _folders(files) -> list[str]:
    """The folders of ``files`` that exist (a missing texture's folder may be made later)."""
    return sorted({os.path.dirname(f) for f in files if os.path.isdir(os.path.dirname(f))})
