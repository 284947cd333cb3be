"""``xaml3d preview``'s state: what the page shows of the scene file as it is now.

One ``PreviewState`` per command. ``rebuild()`` reads the scene again (its App.xaml and -r
dictionaries, its textures), lists its findings as ``xaml3d validate`` does, and, when they
hold no error, renders the picture (``xaml3d render``'s, WPF's first frame), builds the HTML
export's interactive page and the camera's matrices (``xaml3d camera --json``'s data). While
the markup is broken (a fatal reading error, or findings with an error, which ``render``
refuses), the last good picture and page are kept and the new findings are shown beside them.
Each rebuild gets a new version number; the server's event stream waits on ``changed``.
"""

from __future__ import annotations

import io
import os
import threading
import time
from pathlib import Path

from xaml3d.animation.moment import scene_at
from xaml3d.cli_camera import camera_report
from xaml3d.cli_common import describe_os_error, load_scene, render_size
from xaml3d.errors import ERROR, INFO, WARNING, Diagnostic, XamlError
from xaml3d.findings import scene_findings
from xaml3d.scene.types import ImageBrush, Scene


class PreviewState:
    """The page's data for one scene file (see the module docstring)."""

    def __init__(
        self,
        source: str,
        resources: tuple[str, ...] = (),
        *,
        discover_app: bool = True,
        viewport: str | None = None,
        width: int | None = None,
        height: int | None = None,
    ) -> None:
        self.source = source
        self.resources = tuple(resources)
        self.discover_app = discover_app
        self.viewport = viewport
        self.width = width
        self.height = height
        self.changed = threading.Condition()  # notified after every rebuild
        self.version = 0
        self.data: dict = {}
        self.picture: bytes | None = None  # the last good picture (PNG)
        self.view: bytes | None = None  # the last good interactive page (HTML)
        self._good: dict | None = None  # what the last good build showed: version, time, size
        self._inputs: frozenset[str] = self._own_files()
        self._stamps: dict[str, tuple | None] = {}  # each input as the last build found it
        self._building = threading.Lock()  # one rebuild at a time

    def _own_files(self) -> frozenset[str]:
        return frozenset(os.path.realpath(f) for f in (self.source, *self.resources))

    def inputs(self) -> frozenset[str]:
        """Every file the preview follows (real paths): the scene, the -r dictionaries, and
        what the last good read of the scene read (App.xaml, merged dictionaries, images) or
        missed (an image not found)."""
        return self._inputs

    def stale(self) -> bool:
        """Whether an input changed since the last build read it: for the moments the watcher
        is not yet watching (its start, a new folder), which a save may fall into."""
        return any(_stamp(f) != stamp for f, stamp in self._stamps.items())

    def rebuild(self) -> None:
        with self._building:
            started = time.monotonic()
            stamps = {f: _stamp(f) for f in self._inputs}  # before reading: a save during it
            try:
                data, picture, view, files = self._build()
            except Exception as exc:  # a fault of xaml3d's: shown, and the preview goes on
                fault = Diagnostic("PRV001", ERROR, f"{type(exc).__name__}: {exc}", self.source)
                data = {"file": self.source, "findings": _findings_data([fault])}
                data.update(camera=None, size=None)
                picture = view = None
                files = frozenset()
            data["seconds"] = round(time.monotonic() - started, 3)
            with self.changed:
                self.version += 1
                data["version"] = self.version
                data["time"] = time.strftime("%H:%M:%S")
                if picture is not None:
                    self.picture, self.view = picture, view
                    self._good = {
                        "version": self.version,
                        "time": data["time"],
                        "width": data["size"][0],
                        "height": data["size"][1],
                    }
                    self._inputs = self._own_files() | files
                stamps.update((f, _stamp(f)) for f in self._inputs if f not in stamps)
                self._stamps = stamps
                data["picture"] = self._good
                data["current"] = picture is not None
                data["inputs"] = sorted(self._inputs)
                self.data = data
                self.changed.notify_all()

    def _build(self) -> tuple[dict, bytes | None, bytes | None, frozenset[str]]:
        name = self.source
        data: dict = {"file": name, "findings": [], "camera": None, "size": None}
        try:
            loaded = load_scene(name, self.resources, discover_app=self.discover_app, collect=False)
            scene = scene_at(loaded, 0.0)  # WPF's first frame, as `render` draws it
            vp = scene.viewport(self.viewport)
            w, h = render_size(vp, self.width, self.height)
        except XamlError as exc:
            exc.with_location(file=name)
            data["findings"] = _findings_data([exc.as_diagnostic()])
            return data, None, None, frozenset()
        except (OSError, ValueError) as exc:
            fatal = Diagnostic("IO001", ERROR, describe_os_error(exc), name)
            data["findings"] = _findings_data([fatal])
            return data, None, None, frozenset()
        read = (*loaded.input_files, *_missing_images(loaded))
        files = frozenset(os.path.realpath(f) for f in read)

        def size_of(v):
            return render_size(v, self.width, self.height) if v is vp else (v.width, v.height)

        findings = scene_findings(scene, size_of, name)
        data["size"] = [w, h]
        data["camera"], _, _ = camera_report(vp, w, h, scene.file or name)
        picture = view = None
        if not any(d.severity == ERROR for d in findings):
            try:
                picture, view = self._draw(scene, vp, w, h)
            except XamlError as exc:  # what only drawing finds (RND001 size limits...)
                findings = [*findings, exc.with_location(file=name).as_diagnostic()]
        data["findings"] = _findings_data(findings)
        return data, picture, view, files

    def _draw(self, scene, vp, w: int, h: int) -> tuple[bytes, bytes]:
        from xaml3d.api import render  # the renderer and the exporters: on the first picture
        from xaml3d.export import export_bytes

        image = render(scene, w, h, viewport=vp.index)
        out = io.BytesIO()
        image.save(out, format="PNG", compress_level=1)
        files, _ = export_bytes(scene, "html", viewport=vp.index)
        return out.getvalue(), files[""]


def _findings_data(findings) -> list[dict]:
    """Each finding as the page shows it: ``validate --format json``'s fields, its text line
    and the source line it points at (when the file and line are known)."""
    texts: dict[str, list[str] | None] = {}
    rows = []
    for d in findings:
        row = d.to_dict()
        row["text"] = d.format()
        row["source"] = None
        if d.file and d.line:
            if d.file not in texts:
                texts[d.file] = _lines_of(d.file)
            lines = texts[d.file]
            if lines is not None and 0 < d.line <= len(lines):
                row["source"] = lines[d.line - 1][:400]
        rows.append(row)
    order = {ERROR: 0, WARNING: 1, INFO: 2}
    rows.sort(key=lambda r: order.get(r["severity"], 3))  # stable: by position within each
    return rows


def _missing_images(scene: Scene) -> set[str]:
    """The files of the textures the scene names but could not read (BRU002: a checker stands
    in): followed too, so that saving the image shows it."""
    found = set()
    for vp in scene.viewports:
        for model in vp.models:
            for material in (*model.material, *model.back_material):
                brush = material.brush
                if isinstance(brush, ImageBrush) and brush.is_placeholder and brush.path:
                    found.add(brush.path)
    return found


def _stamp(file: str) -> tuple | None:
    """What tells a file's versions apart: its inode, size and modification time (None: it
    is missing)."""
    try:
        st = os.stat(file)
    except OSError:
        return None
    return (st.st_ino, st.st_size, st.st_mtime_ns)


def _lines_of(file: str) -> list[str] | None:
    try:
        return Path(file).read_text("utf-8", errors="replace").splitlines()
    except OSError:
        return None
