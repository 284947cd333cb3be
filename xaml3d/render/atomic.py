"""Atomic output files: every image, animation, depth/id buffer and SVG the renderer writes.

A temporary file in the target's directory is written, fsynced and renamed over the target, so
a reader never sees a partial file and a failure (or Ctrl-C) leaves an existing file untouched.
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import BinaryIO

from xaml3d.errors import RenderError


def _current_umask() -> int:
    mask = os.umask(0o022)  # reading the umask means setting it; put it straight back
    os.umask(mask)
    return mask


def _cannot(path: Path, exc: OSError) -> RenderError:
    return RenderError(f"cannot write {path}: {exc.strerror or exc}", code="RND007")


def write_atomically(path, write: Callable[[BinaryIO], object]) -> None:
    """Call ``write(file)`` on a temporary file beside ``path``, then rename it over ``path``;
    on any failure the temporary file is removed. RenderError RND007 when it cannot be written."""
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=directory)
    except OSError as exc:
        raise _cannot(path, exc) from exc
    try:
        with os.fdopen(fd, "wb") as fh:
            write(fh)
            fh.flush()
            os.fsync(fh.fileno())
        # mkstemp creates the file 0600; give it the mode a plain open() would have.
        os.chmod(tmp, 0o666 & ~_current_umask())
        os.replace(tmp, path)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(exc, OSError):
            raise _cannot(path, exc) from exc
        raise
