"""Atomic output files: every image, animation, depth/id buffer and SVG the renderer writes.

A temporary file in the target's directory is written, fsynced and renamed over the target, so
a reader never sees a partial file and a failure (or Ctrl-C) leaves an existing file untouched.
Inside ``together()`` the renames wait: every file is written to its temporary first and all are
renamed at the end, or, on any failure, every temporary is removed (all or nothing for the
several files of one render: an image with its depth and id images, every viewport's image).
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from pathlib import Path
from typing import BinaryIO

from xaml3d.errors import RenderError


def _current_umask() -> int:
    mask = os.umask(0o022)  # reading the umask means setting it; put it straight back
    os.umask(mask)
    return mask


def _cannot(path: Path, exc: OSError) -> RenderError:
    return RenderError(f"cannot write {path}: {exc.strerror or exc}", code="RND007")


class Staged:
    """The files written inside ``together()``: (temporary, target) pairs not yet renamed."""

    def __init__(self) -> None:
        self.pending: list[tuple[Path, Path]] = []

    def commit(self) -> None:
        """Rename every temporary over its target, in the order written."""
        pending, self.pending = self.pending, []
        for i, (tmp, path) in enumerate(pending):
            try:
                os.replace(tmp, path)
            except OSError as exc:
                self.pending = pending[i + 1 :]
                self.discard()
                raise _cannot(path, exc) from exc

    def discard(self) -> None:
        """Remove every temporary not yet renamed."""
        for tmp, _ in self.pending:
            try:
                os.unlink(tmp)
            except OSError:
                pass
        self.pending = []


_STAGED: ContextVar[Staged | None] = ContextVar("xaml3d_staged", default=None)


@contextmanager
def together(commit: bool = True) -> Iterator[Staged]:
    """Every ``write_atomically`` inside the block writes its temporary file only; when the block
    ends without an exception they are all renamed into place (``commit=False``: left to the
    caller, as ``Staged.pending``), and on an exception every temporary is removed, so no
    target is touched."""
    staged = Staged()
    token = _STAGED.set(staged)
    try:
        yield staged
    except BaseException:
        staged.discard()
        raise
    finally:
        _STAGED.reset(token)
    if commit:
        staged.commit()


def write_atomically(path, write: Callable[[BinaryIO], object]) -> None:
    """Call ``write(file)`` on a temporary file beside ``path``, then rename it over ``path``
    (inside ``together()``: at the end of the block); on any failure the temporary file is
    removed. RenderError RND007 when it cannot be written."""
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
        staged = _STAGED.get()
        if staged is not None:
            staged.pending.append((Path(tmp), path))
            return
        os.replace(tmp, path)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(exc, OSError):
            raise _cannot(path, exc) from exc
        raise
