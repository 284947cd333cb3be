"""Where a kernel module's native objects live, and when they are still valid.

One folder per kernel module and key under numba's cache folder (``numba_env.set_cache_dir``):
``native/<module>-<key>/`` holds ``manifest.json`` (per kernel: its compiled versions, the
symbol of each one's trampoline, the object files, their undefined symbols; the module's
integer and float constants) and the object files. The key changes with anything that changes
the machine code: the kernel module's source, numba's and llvmlite's builds (the identity of
their compiled libraries), Python's version, and this processor's name and features. Computing
it needs no numba: a few ``os.stat`` calls and the processor's features from llvmlite.

Writers make each file under a temporary name and rename it into place, so a reader sees a
whole manifest or the previous one; two processes adding kernels at once may lose one's
addition, which is then made again the next time it is used.
"""

from __future__ import annotations

import hashlib
import importlib.machinery
import importlib.util
import json
import os
import sys
from pathlib import Path

from xaml3d.numba_env import set_cache_dir

FORMAT = 3  # of the manifest


def package_file(package: str, relative: str, extension: bool = False) -> Path:
    """A file of an installed package found without importing the package: ``relative``
    (with one of Python's C-extension suffixes when ``extension``); ImportError if absent."""
    spec = importlib.util.find_spec(package)
    if spec is None or not spec.submodule_search_locations:
        raise ImportError(package)
    folder = Path(next(iter(spec.submodule_search_locations)))
    suffixes = importlib.machinery.EXTENSION_SUFFIXES if extension else [""]
    for suffix in suffixes:
        path = folder / (relative + suffix)
        if path.is_file():
            return path
    raise ImportError(f"{package}/{relative}")


def _library_identity(package: str, relative: str, extension: bool) -> str:
    path = package_file(package, relative, extension)
    st = path.stat()
    return f"{path}:{st.st_size}:{st.st_mtime_ns}"


def key(source: Path, cpu_name: str, cpu_features: str) -> str:
    """The key of a kernel module's native objects (ImportError without numba/llvmlite)."""
    h = hashlib.sha256()
    h.update(source.read_bytes())
    for part in (
        str(FORMAT),
        sys.version,
        _library_identity("numba", "_helperlib", True),
        _library_identity("llvmlite", "binding/libllvmlite.so", False),
        cpu_name,
        cpu_features,
    ):
        h.update(b"\0" + part.encode())
    return h.hexdigest()[:24]


def folder(module: str, k: str) -> Path:
    return Path(set_cache_dir()) / "native" / f"{module}-{k}"


def read_manifest(where: Path) -> dict | None:
    try:
        data = json.loads((where / "manifest.json").read_text())
    except (OSError, ValueError):
        return None
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        return None
    return data


def write_atomically(path: Path, data: bytes) -> None:
    import tempfile  # writers only

    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.name + ".", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


# Folders of other keys kept per module: other installs on the machine (a second virtual
# environment, another Python) share the cache and each needs its own; the oldest go.
KEEP_OTHERS = 7


def prune(module: str, k: str) -> None:
    """Remove the module's folders of other keys beyond the KEEP_OTHERS last used (a loader
    touches its manifest): older sources, another numba, processor or install. Best effort: a
    folder another process still reads loses only speed there (its manifest or objects are
    gone, so it runs those kernels through numba, and keeps them again)."""
    parent = folder(module, k).parent
    others = []
    for other in parent.glob(f"{module}-*"):
        if other.name != f"{module}-{k}" and other.is_dir():
            try:
                others.append(((other / "manifest.json").stat().st_mtime, other))
            except OSError:
                others.append((0.0, other))
    others.sort(reverse=True)
    for _, other in others[KEEP_OTHERS:]:
        for f in other.iterdir():
            try:
                f.unlink()
            except OSError:
                pass
        try:
            other.rmdir()
        except OSError:
            pass


def touch(where: Path) -> None:
    """Mark a folder's manifest as used now (``prune`` keeps the last used)."""
    try:
        os.utime(where / "manifest.json")
    except OSError:
        pass
