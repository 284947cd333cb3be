"""Atomic output files: every image, animation, depth/id buffer and SVG the renderer writes.

A temporary file in the target's directory is written, fsynced and renamed over the target, so
a reader never sees a partial file and a failure (or Ctrl-C) leaves an existing file untouched.
Inside ``together()`` the renames wait: every file is written to its temporary first and all are
renamed at the end, or, on any failure, every temporary is removed (all or nothing for the
several files of one render: an image with its depth and id images, every viewport's image).

A temporary is named ``.<name>.<pid>-<random>.tmp``, the target's name cut so that the whole
fits in the file system's limit on a name (255 bytes on most): a temporary fits wherever its
target does. The process id in the name and a registry of this process's temporaries let
``remove_temporaries`` clean up after a run whose parent was killed (``xaml3d.render.workers``).

A target that exists and is not a regular file (a FIFO, a character device such as /dev/null,
a socket) is never renamed over: that would replace the device or pipe by a plain file. Its
bytes are still written to a temporary first (in the system's temporary folder, since the
target's folder may be /dev or read-only) and then copied into the target itself, opened for
writing as any other tool would (``place``): a reader of the pipe gets the whole file, and a
failure while drawing or encoding writes nothing into it.
"""

from __future__ import annotations

import os
import re
import shutil
import stat
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


_CREATED: set[str] = set()  # this process's temporaries not yet renamed or removed


def _name_max(directory: Path) -> int:
    try:
        return int(os.pathconf(directory, "PC_NAME_MAX"))
    except (OSError, ValueError, AttributeError):
        return 255


def temporary_name(directory: Path, name: str) -> str:
    """A fresh temporary name for the target ``name`` in ``directory`` (module docstring)."""
    # os.urandom is what secrets.token_hex reads; importing secrets loads hmac and OpenSSL's
    # hashlib (2-4 ms of every command's start) for these 8 hex digits
    tail = f".{os.getpid()}-{os.urandom(4).hex()}.tmp"
    room = _name_max(directory) - len(tail.encode()) - 1
    head = name.encode()[: max(0, room)].decode(errors="ignore")  # whole characters only
    return f".{head}{tail}"


def _create(directory: Path, name: str) -> tuple[int, str]:
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0)
    for _ in range(100):
        tmp = str(directory / temporary_name(directory, name))
        try:
            fd = os.open(tmp, flags, 0o600)
        except FileExistsError:
            continue
        _CREATED.add(tmp)
        return fd, tmp
    raise FileExistsError(f"no free temporary name beside {name}")


def _gone(tmp) -> None:
    _CREATED.discard(str(tmp))


def remove_temporaries(pid: int, folders=()) -> None:
    """Remove the temporaries of process ``pid``: this process's own from its registry, and
    in ``folders`` every file named as a temporary of ``pid``. Never raises."""
    if pid == os.getpid():
        for tmp in list(_CREATED):
            try:
                os.unlink(tmp)
            except OSError:
                pass
            _gone(tmp)
    mark = re.compile(rf"\..*\.{pid}-[0-9a-f]{{8}}\.tmp")
    for folder in folders:
        try:
            names = os.listdir(folder)
        except OSError:
            continue
        for n in names:
            if mark.fullmatch(n):
                try:
                    os.unlink(os.path.join(folder, n))
                except OSError:
                    pass


def special(path) -> bool:
    """True when ``path`` exists (through links) and is not a regular file or a folder: a
    FIFO, a device or a socket, which a write must go into, never replace."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return False
    return not (stat.S_ISREG(mode) or stat.S_ISDIR(mode))


def place(tmp, path) -> None:
    """Put the finished temporary ``tmp`` in place of ``path``: renamed over it, or, when
    ``path`` is a FIFO or a device (``special``), copied into it and removed. Raises OSError."""
    if not special(path):
        os.replace(tmp, path)
        _gone(tmp)
        return
    try:
        # no O_CREAT: should the node vanish meanwhile, fail rather than make a regular file
        fd = os.open(path, os.O_WRONLY | getattr(os, "O_CLOEXEC", 0))
        with open(tmp, "rb") as src, os.fdopen(fd, "wb") as dst:
            shutil.copyfileobj(src, dst, 1 << 20)
    finally:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        _gone(tmp)


class Staged:
    """The files written inside ``together()``: (temporary, target) pairs not yet renamed."""

    def __init__(self) -> None:
        self.pending: list[tuple[Path, Path]] = []

    def commit(self) -> None:
        """Put every temporary in place of its target (``place``), in the order written."""
        pending, self.pending = self.pending, []
        for i, (tmp, path) in enumerate(pending):
            try:
                place(tmp, path)
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
            _gone(tmp)
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
    removed. A FIFO or device ``path`` is written into, never replaced (``place``). RenderError
    RND007 when it cannot be written."""
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    if special(path):
        directory = Path(tempfile.gettempdir())
    if len(path.name.encode()) > _name_max(directory):
        raise RenderError(
            f"cannot write {path}: the name is {len(path.name.encode())} bytes long, over the "
            f"file system's limit of {_name_max(directory)}",
            code="RND007",
        )
    try:
        fd, tmp = _create(directory, path.name)
    except OSError as exc:
        raise _cannot(path, exc) from exc
    try:
        with os.fdopen(fd, "wb") as fh:
            write(fh)
            fh.flush()
            os.fsync(fh.fileno())
        # created 0600 (no one reads it half-written); give it the mode a plain open() would have
        os.chmod(tmp, 0o666 & ~_current_umask())
        staged = _STAGED.get()
        if staged is not None:
            staged.pending.append((Path(tmp), path))
            return
        place(tmp, path)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        _gone(tmp)
        if isinstance(exc, OSError):
            raise _cannot(path, exc) from exc
        raise
